// The pictures of a run's first collision that `collide render` writes beside the frames
// (docs/commands/render.md), and the figure `collide gui` saves:
//   before.png, at.png, after.png   a moment before, the instant, a moment after, at the frame size
//   figure.png, thumb.png           those three moments side by side with captions; its middle panel
//   variants.png                    a lesson's scene and its variants, a row of panels each
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "present/scene_run.h"
#include "render/png.h"
#include "render/renderer.h"
#include "scenario/scene_file.h"

namespace collide {

// The trails behind the bodies (s) in the frames and in the stills.
double trail_seconds(const Scene& scene);

// A scene's [[mark]] points as the diagrams draw them (render::Decor::points).
std::vector<render::PointMark> points_of(const SceneView& view);

// What a collision's pictures are drawn from: a scene, its [view] table, its run, and the
// moments of its first collision in that run.
struct CollisionShots {
    const Scene& scene;
    const SceneView& view;
    const SceneRun& run;
    const Moments& moments;
};

// Where pictures are written, and how they are encoded.
struct PictureOut {
    std::string dir;
    render::PngOptions png;
};

// The widths (pixels) the site shows a figure at (assets/site/style.css): its text column,
// and the wider box of a figure whose panels stand side by side. A figure is laid out for them
// (at 720p fonts; other sizes scale): wide strips (1D) are stacked to the column's width,
// others stand side by side in the wide box. So its smallest label (13 px) shows at least
// 12 px tall.
constexpr int kColumnWidth = 944;
constexpr int kWideFigureWidth = 1200;

// The before / at / after panels framed on the moments without the table, and the figure of
// the three with their captions.
struct Figure {
    std::vector<render::Image> panels;
    std::vector<render::Annotations> annotations;  // what each panel drew
    double times[3] = {0, 0, 0};                   // s: the panels' moments
    render::Image figure;
    render::RenderSettings panel;           // the panels' settings (variants.png uses them too)
    bool stacked = false;                   // the panels one above the other (variants.png too)
    std::vector<render::PointMark> points;  // the scene's marked points (variants.png too)
};

// One row of variants.png: a scene (the lesson's own or a variant) and its first collision.
struct VariantRow {
    std::string label;
    const Scene* scene = nullptr;
    Moments moments;
};

// The figure of a collision (figure.png's image), and its panels; write_figure writes it.
Figure make_figure(render::GlContext& context, const CollisionShots& shots, const render::RenderSettings& settings);

// before.png, at.png and after.png: the moments as the frames' renderer draws them (with the
// trails up to then; at the instant the impulse instead of the velocities).
void write_stills(render::Renderer& frames, const CollisionShots& shots, const PictureOut& out);
// annotations.json: what the figure's three panels draw (render/annotation.h), as
//   {"dimension": D, "view": "2d" or "3d", "panel_size": [w, h],
//    "times": {"before": t, "at": t, "after": t},
//    "panels": {"before": [items], "at": [items], "after": [items]}}
// ("panels": {} when there is no figure: `figure` null, the run has no collision).
std::string annotations_json(const Scene& scene, const Figure* figure);
// figure.png, thumb.png (the collision panel, 480 pixels wide) and annotations.json; returns
// the figure. A lesson's next figures are number 2, 3, ...: figure-K.png and annotations-K.json.
Figure write_figure(render::GlContext& context, const CollisionShots& shots, const render::RenderSettings& settings,
                    const PictureOut& out, int number = 1);
// variants.png: the same three moments of each row, framed alike with `figure`'s panels.
void write_variants(render::GlContext& context, const std::vector<VariantRow>& rows,
                    const render::RenderSettings& settings, const Figure& figure, const PictureOut& out);

// The first collision's before / at / after figure (figure.png) of the scene's run (run_scene
// at the frame rate), drawn with the frames' settings; nullopt when the run has no collision.
std::optional<render::Image> first_collision_figure(render::GlContext& context, const Scene& scene,
                                                    const SceneView& view, const render::RenderSettings& settings,
                                                    const SceneRun& run);

}  // namespace collide
