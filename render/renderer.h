// The renderer: one frame of a scene, drawn offscreen and read back as RGBA.
//
//   Renderer r(context, scene, settings);
//   r.prepare(samples, impacts);          // frames the camera and lays out the overlays
//   r.render(frame, decor, rgba);         // as often as needed, any frame of the run
//
// A frame is drawn into a render target (4x MSAA unless anti-aliasing is off): the 3D view's
// shaded bodies first (when the view is 3D), then everything 2D through Dear ImGui: the
// diagram (2D view) or the 3D view's labels, the header (title, time, legends) and the data
// table; along the bottom the plots of energy and momentum, the formula of the first collision
// and the time line. Layout: header at the top left, table at the top right, the strip at the
// bottom, and the view between them or beside the header and table, whichever leaves the
// scene larger.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/scene.h"
#include "render/context.h"
#include "render/diagram_view.h"
#include "render/frame_state.h"
#include "render/overlay.h"
#include "render/scene3d_view.h"
#include "render/png.h"

namespace collide::render {

enum class ViewKind { diagram, perspective };  // 2D textbook diagram, 3D shaded

struct RenderSettings {
    int width = 1280, height = 720;  // pixels
    int samples = 4;                 // MSAA samples; 0: off
    // 3D with samples: multisample only the rectangle the bodies and arrows cover, the ground
    // around it drawn once without (Scene3dView::above_bounds). Off: the whole frame.
    bool msaa_region = true;
    bool smooth = true;  // Dear ImGui's edge anti-aliasing (lines, fills, text)
    ViewKind view = ViewKind::diagram;
    bool header = true;       // title, time, arrow legends
    bool table = true;        // the data table
    bool plots = true;        // energy and momentum against time (bottom)
    bool timeline = true;     // the run's time line with its collisions (bottom)
    FormulaText formula;      // the first collision's formula with numbers (bottom)
    CameraRequest camera;     // the 3D view's camera, where the scenario sets it
    bool directions = false;  // the 2D view's positive-direction arrows (Decor::directions)
    // When not empty, the 2D view frames these bodies only (scene indices): a figure about one
    // pair of a busy scene is drawn at that pair's size (DiagramView::frame_only).
    std::vector<std::size_t> frame_bodies;
    // Marked points whose velocity arrows the frames draw: counted in the framing and the
    // arrow scale (DiagramView::frame_points).
    std::vector<PointMark> points;
    int time_decimals = 3;  // "t = 0.350 s"
    // Font sizes: by default for the frame height; figure panels use the frame's.
    int font_height = 0;  // 0: height
    std::string font_dir = "/usr/share/fonts/truetype/dejavu";
};

class ImGuiLayer;
class RenderTarget;

class Renderer {
public:
    // Needs `context` current on the calling thread, now and for every call.
    Renderer(GlContext& context, const Scene& scene, const RenderSettings& settings);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Frames the view over the run (`samples`: states spread over it) and sets the arrow
    // scales (impulses from `impacts`).
    void prepare(const std::vector<FrameState>& samples, const std::vector<ImpactMark>& impacts);
    // The plots' points (times not decreasing; an instant twice: just before and just after
    // it), instead of the samples' totals; call before prepare().
    void set_plot_totals(std::vector<double> t, std::vector<FrameTotals> totals) {
        plot_t_ = std::move(t);
        plot_totals_ = std::move(totals);
    }

    // The 3D view's camera (collide gui's orbit and zoom); call prepare() again after it.
    void set_camera(const CameraRequest& camera);

    // Draws one frame into `rgba` (width * height * 4 bytes, top row first).
    void render(const FrameState& frame, const Decor& decor, std::uint8_t* rgba);
    Image render(const FrameState& frame, const Decor& decor);

    int width() const { return settings_.width; }
    int height() const { return settings_.height; }
    const RenderSettings& settings() const { return settings_; }
    // World to pixels, for tests and annotations.
    ImVec2 to_screen(const Vec3& world) const;
    // The 2D view (its arrow scales, its framing); null in the 3D view.
    const DiagramView* diagram() const { return view3d_ ? nullptr : diagram_.get(); }
    // What the last render() drew in the view (render/annotation.h).
    const Annotations& annotations() const { return annotations_; }
    // Whether each glyph of `utf8` is in the label font.
    bool has_glyphs(const std::string& utf8) const;

private:
    void draw(const FrameState& frame, const Decor& decor);

    GlContext& context_;
    const Scene& scene_;
    RenderSettings settings_;
    Style style_;
    std::unique_ptr<RenderTarget> target_;
    std::unique_ptr<ImGuiLayer> imgui_;
    std::unique_ptr<DiagramView> diagram_;
    std::unique_ptr<Scene3dView> view3d_;
    std::unique_ptr<DataTable> table_;
    std::unique_ptr<Header> header_;
    std::unique_ptr<FormulaBox> formula_;
    std::unique_ptr<Plot> energy_plot_, momentum_plot_;
    std::unique_ptr<TimeLine> timeline_;
    ImVec2 header_at_{0, 0}, table_at_{0, 0};
    ImVec2 formula_at_{0, 0}, energy_at_{0, 0}, momentum_at_{0, 0}, timeline_at_{0, 0};
    ImVec4 view_rect_{0, 0, 0, 0};
    Annotations annotations_;
    std::vector<double> plot_t_;
    std::vector<FrameTotals> plot_totals_;
};

// One figure of panels side by side with a caption under each (e.g. before / at collision /
// after), on the diagrams' paper; `stacked`: one above the other (wide strips, so that the
// figure fits a page's width). All panels must have the same size.
Image compose_figure(GlContext& context, const std::vector<Image>& panels, const std::vector<std::string>& captions,
                     const std::vector<std::string>& notes, int font_height, bool stacked = false,
                     const std::string& font_dir = "/usr/share/fonts/truetype/dejavu");

}  // namespace collide::render
