// Drawing helpers on a Dear ImGui draw list, in pixels (origin top left, y down): arrows,
// curved arrows, dashed lines, hatched ground, centre-of-mass markers, and labels.
//
// Labels are "rich text": `_{...}` sets what is inside as a subscript and `^{...}` as a
// superscript, in the small font (e.g. "r_{a}", "v_{b}'"); Unicode super- and subscript glyphs
// ("m s⁻¹") are ordinary characters of the text font.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <imgui.h>

#include "render/imgui_layer.h"
#include "render/style.h"

namespace collide::render {

// An arrow from `from` to `to` (the tip). The head shrinks on arrows shorter than 1.5 heads;
// nothing is drawn for arrows under half a pixel.
void draw_arrow(ImDrawList* dl, ImVec2 from, ImVec2 to, Colour colour, float thickness, float head_length,
                float head_width);
// An arc of radius r about c from angle a0 to a1 (radians, counter-clockwise on screen as
// seen by the reader: the angles are those of the world, y up), with the head at a1.
void draw_curved_arrow(ImDrawList* dl, ImVec2 c, float r, float a0, float a1, Colour colour, float thickness,
                       float head_length, float head_width);
void draw_dashed_line(ImDrawList* dl, ImVec2 a, ImVec2 b, Colour colour, float thickness, float dash, float gap);
// The screen box (x0, y0, x1, y1) around a polygon's points; inverted (x0 > x1) when empty.
ImVec4 bounds_of(const std::vector<ImVec2>& poly);

// The classic centre-of-mass symbol: a circle with two opposite quarters filled.
void draw_com_marker(ImDrawList* dl, ImVec2 c, float r, Colour ink, Colour paper, float angle);

// Rich text (see above).
ImVec2 rich_text_size(const FontSet& fonts, ImFont* font, const std::string& text);
void draw_rich_text(ImDrawList* dl, const FontSet& fonts, ImFont* font, ImVec2 top_left, Colour colour,
                    const std::string& text);

// Numbers for labels: `digits` significant digits, a true minus sign (U+2212), no "-0".
std::string format_number(double x, int digits = 3);
// As format_number, without trailing zeros: legend values ("1", "0.5", "2.5").
std::string format_compact(double x);
// Fixed decimals, true minus sign, no "-0.00".
std::string format_fixed(double x, int decimals);

// Places labels without overlapping each other or the reserved areas, inside the bounds.
class LabelPlacer {
public:
    explicit LabelPlacer(ImVec4 bounds) : bounds_(bounds) {}
    void reserve(ImVec4 rect) { taken_.push_back(rect); }  // (x0, y0, x1, y1)
    // Areas labels should rather not cover (bodies: convex polygons, screen points); a label
    // goes over one only when no free place is near.
    void avoid(std::vector<ImVec2> convex) { soft_.push_back(std::move(convex)); }
    // The top-left corner for a box of `size` near `anchor`, preferably in `direction`
    // (a unit vector, screen coordinates), `gap` pixels away; tries other sides and larger
    // distances when that spot is taken, and reserves the result. When no free spot is near,
    // it returns the preferred spot without reserving it and last_free() is false: callers
    // then leave the label out, so that labels never overlap (the most important are placed
    // first).
    ImVec2 place(ImVec2 anchor, ImVec2 size, ImVec2 direction, float gap);
    bool last_free() const { return last_free_; }
    // A further test every place() result must pass (e.g. "nearer its own body than any
    // other"); none by default. place() falls back to a spot that fails it only as it does to
    // a taken one: unreserved, with last_free() false.
    void require(std::function<bool(const ImVec4&)> acceptable) { acceptable_ = std::move(acceptable); }

private:
    bool free(const ImVec4& r, bool strict) const;
    ImVec4 bounds_;
    std::vector<ImVec4> taken_;
    std::vector<std::vector<ImVec2>> soft_;
    bool last_free_ = true;
    std::function<bool(const ImVec4&)> acceptable_;
};

// A label with a soft paper-coloured backing so that it reads over lines and fills.
void draw_label(ImDrawList* dl, const FontSet& fonts, ImFont* font, ImVec2 top_left, const std::string& text,
                Colour colour, Colour backing, float pad);

// A label's box (pixels: x0, y0, x1, y1, its padding included) placed for `anchor` (see
// LabelPlacer::place), and the label drawn in that box; a label that had to move away from
// its anchor gets a thin leader line back to it.
ImVec4 place_label_box(const FontSet& fonts, LabelPlacer* placer, ImFont* font, ImVec2 anchor, ImVec2 direction,
                       const std::string& text, float pad, float gap);
void draw_placed_label(ImDrawList* dl, const FontSet& fonts, ImFont* font, ImVec4 box, ImVec2 anchor,
                       const std::string& text, Colour colour, Colour backing, float pad, float gap);
// Both at once.
void place_label(ImDrawList* dl, const FontSet& fonts, LabelPlacer* placer, ImFont* font, ImVec2 anchor,
                 ImVec2 direction, const std::string& text, Colour colour, Colour backing, float pad, float gap);

}  // namespace collide::render
