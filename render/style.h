// The look of the diagrams: colours and sizes, in one place. Sizes are in pixels at 720p and
// scale with the frame height (Style::for_height).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

namespace collide::render {

// 0xAABBGGRR, Dear ImGui's packed colour (IM_COL32 order).
using Colour = std::uint32_t;
constexpr Colour rgb(unsigned r, unsigned g, unsigned b, unsigned a = 255) {
    return (a << 24) | (b << 16) | (g << 8) | r;
}
constexpr Colour with_alpha(Colour c, float a) {
    return (c & 0x00FFFFFFu) | (static_cast<std::uint32_t>(a * 255.0f + 0.5f) << 24);
}

// A colour as CSS writes it, "#rrggbb" (the alpha left out): the site's and the worksheets' figures.
inline std::string css_colour(Colour c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c & 0xFFu, (c >> 8) & 0xFFu, (c >> 16) & 0xFFu);
    return buf;
}

struct Palette {
    Colour background = rgb(251, 251, 248);  // paper
    Colour ink = rgb(28, 28, 30);            // outlines, text
    Colour muted = rgb(110, 112, 118);       // secondary text, axes
    Colour grid = rgb(222, 222, 218);
    Colour static_fill = rgb(214, 214, 210);  // ground, walls, static bodies
    Colour hatch = rgb(90, 90, 92);
    // The arrows' colours stay apart for readers with colour blindness too: each pair differs
    // by at least 15 (CIELAB ΔE) in normal vision and in deuteranopia, protanopia and
    // tritanopia as simulated (tests/render/palette_test.cpp). (A violet spin was 6.6 from
    // the blue velocity for deuteranopes.)
    Colour velocity = rgb(29, 78, 216);      // blue
    Colour spin = rgb(200, 110, 0);          // amber
    Colour impulse = rgb(206, 32, 41);       // red
    Colour normal = rgb(15, 118, 110);       // dark teal
    Colour lever = rgb(40, 40, 44);          // r vectors (dashed): near the ink
    Colour panel = rgb(255, 255, 255, 236);  // table and legend backgrounds
    Colour panel_border = rgb(200, 200, 196);
    // Flat body fills, in scene order (cycled). The first two, the pair of most figures, stay
    // apart from every arrow colour, flat and shaded (80 %), by ΔE 15 in normal vision and in
    // deuteranopia, protanopia and tritanopia as simulated (tests/render/palette_test.cpp): B
    // is sand, not orange (an orange B's shaded faces were the amber spin's colour).
    static constexpr int kFills = 6;
    Colour fills[kFills] = {rgb(141, 179, 226), rgb(240, 210, 150), rgb(155, 211, 155),
                            rgb(212, 166, 224), rgb(242, 142, 142), rgb(158, 219, 215)};
    // The same hues, darker: trails and 3D outlines.
    Colour darks[kFills] = {rgb(46, 94, 160),  rgb(148, 130, 93), rgb(52, 128, 52),
                            rgb(128, 68, 150), rgb(170, 52, 52),  rgb(38, 130, 124)};
};

struct Style {
    Palette colours;
    float scale = 1.0f;  // frame height / 720
    // Pixels at 720p (multiply by scale).
    float outline = 2.0f;       // body outlines
    float arrow = 3.0f;         // arrow shafts
    float head_length = 15.0f;  // arrow heads
    float head_width = 12.0f;
    float thin = 1.5f;            // r vectors, radius lines, trails
    float com = 6.0f;             // centre-of-mass marker radius
    float margin = 24.0f;         // between the frame's edge and its content
    float normal_length = 70.0f;  // the unit normal's arrow
    float hatch_depth = 14.0f;    // ground hatching
    float hatch_step = 11.0f;

    float px(float at720) const { return at720 * scale; }
    // Line widths and arrow heads: they scale too, but stay visible in small frames.
    float lw(float at720) const { return at720 * (scale > 0.5f ? scale : 0.5f); }
    static Style for_height(int height) {
        Style s;
        s.scale = static_cast<float>(height) / 720.0f;
        return s;
    }
};

}  // namespace collide::render
