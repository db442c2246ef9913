// Dear ImGui, headless: its draw lists (anti-aliased lines, filled shapes, text) drawn into the
// current render target by a small OpenGL 3.3 renderer of ImDrawData of our own (Debian's
// prebuilt opengl3 backend cannot load GL from OSMesa; see ../shared/STACK.md).
//
// There is no platform layer: no window, no input. Each frame is begin() ... end(); the views
// draw on the frame-wide draw list (draw_list()) in pixels, origin at the top left, y down.
//
// Fonts: DejaVu Sans (Debian's fonts-dejavu-core) rasterised by FreeType, with the glyph ranges
// the labels need built by hand (Debian's ImGui 1.86 has no Greek ranges): Latin-1, Greek,
// the phonetic subscripts (U+1D62-1D6A: i r u v beta gamma rho phi chi), super- and subscripts
// (U+2070-209F), arrows and mathematical operators.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "render/gl.h"

struct ImDrawList;
struct ImFont;
struct ImGuiContext;

namespace collide::render {

struct FontSet {
    ImFont* text = nullptr;   // labels
    ImFont* small = nullptr;  // sub- and superscripts, legend notes
    ImFont* bold = nullptr;   // titles, table headers
    ImFont* table = nullptr;  // the data table
    float text_px = 0, small_px = 0, bold_px = 0, table_px = 0;
};

// Font sizes in pixels for a frame `height` pixels tall (18 px labels at 720p, never below 9).
struct FontSizes {
    float text, small, bold, table;
    static FontSizes for_height(int height);
};

class ImGuiLayer {
public:
    // Needs a current GL context. Throws std::runtime_error if a font file is missing.
    ImGuiLayer(const Gl& gl, int width, int height, const FontSizes& sizes,
               const std::string& font_dir = "/usr/share/fonts/truetype/dejavu");
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    // Starts a frame; `anti_aliased` switches ImGui's own edge anti-aliasing (feathered edges).
    void begin(bool anti_aliased = true);
    ImDrawList* draw_list();  // the frame-wide (background) draw list
    // Ends the frame and draws it into the bound framebuffer (blending over what is there).
    void end();

    const FontSet& fonts() const { return fonts_; }
    int width() const { return width_; }
    int height() const { return height_; }

    // True if every code point of `utf8` has a glyph in the text font (tests, diagnostics).
    bool has_glyphs(const std::string& utf8) const;

private:
    void render_draw_data();

    const Gl& gl_;
    int width_, height_;
    ImGuiContext* context_ = nullptr;
    FontSet fonts_;
    std::vector<std::vector<char>> font_files_;  // kept alive: the atlas does not own them
    GLuint program_ = 0, vao_ = 0, vbo_ = 0, ibo_ = 0, font_texture_ = 0;
    GLint proj_location_ = -1, tex_location_ = -1;
};

// Shared by the views: compile and link a GLSL program; throws with the driver's log.
GLuint build_program(const Gl& gl, const char* vertex_source, const char* fragment_source,
                     const std::vector<std::pair<GLuint, const char*>>& attributes);

}  // namespace collide::render
