// A render over one typed request (`collide render SCENARIO -o DIR`, each lesson of `collide
// material`), in stages: load, run, analyse, write. It writes into request.out_dir
// (docs/commands/render.md):
//   DIR/frames/frame_00000.png ...   the animation, one PNG per frame (fps frames per simulated s)
//   DIR/before.png, at.png, after.png  the first collision: a moment before, the exact instant
//                                      (impulse, normal, r vectors), a moment after
//   DIR/figure.png                   those three side by side with captions
//   DIR/data.csv, DIR/data.json      the sampled states (as `collide step --json`) and events
//   DIR/events.csv                   the collision events
//   DIR/worked-example.md            the first collision worked out (as `collide solve`)
//   DIR/lesson.md                    for a lesson: its text, questions and computed answers
//   DIR/variants.png                 for a lesson with variants: a row of panels for each
//   DIR/animation.mp4 or .gif        with a video request (ffmpeg)
// and returns a typed report of what it made and computed.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "present/frame_spec.h"
#include "present/lesson_plots.h"
#include "present/scene_run.h"
#include "present/stop.h"
#include "render/frame_state.h"
#include "render/renderer.h"
#include "teach/answers.h"
#include "teach/lesson_penalty.h"
#include "teach/solve.h"

namespace collide {

// A render, every option read and checked.
struct RenderRequest {
    std::string scenario;  // a scenario file, a lesson file or a lesson id (load_scenario reads it)
    std::string out_dir;
    FrameSpec frame;
    std::optional<VideoRequest> video;  // unset: the frames alone
    render::GlBackend backend = render::GlBackend::osmesa;
    bool quiet = false;  // no progress on err (the command: also when err is not a terminal)
    bool force = false;  // write into a directory that is not empty
};

// What a render made and computed, for the summary line and for `collide material`.
struct RenderReport {
    Scene scene;
    SceneView view;
    std::optional<Lesson> lesson;
    std::vector<LessonAnswer> answers;    // a lesson's questions, in order
    std::optional<SolveProblem> problem;  // the first collision's worked example
    std::optional<Solution> solution;
    std::optional<CollisionInstant> first_collision;
    std::string world_note;               // when the world resolved several points there (the formula box's note)
    std::vector<double> collision_times;  // s, every collision of the run
    // The run's collisions the figures do not show (at most kLaterCollisions), each worked
    // out as those are: the site explains them below them.
    struct Later {
        CollisionInstant instant;
        SolveProblem problem;
        Solution solution;
        std::string world_note;
    };
    static constexpr std::size_t kLaterCollisions = 8;
    std::vector<Later> later;  // the run's other collisions, in time order
    // The collisions the figures show, each worked out: figure.png's (the first collision,
    // or a lesson's first [[figure]]), then a lesson's next [[figure]] entries (figure-2.png, ...).
    struct Shown {
        CollisionInstant instant;
        SolveProblem problem;
        Solution solution;
        std::string world_note;
        std::string caption;  // the [[figure]]'s, or ""
        std::string file;     // "figure.png", "figure-2.png", ...
    };
    std::vector<Shown> figures;
    // A lesson's scene and its variants side by side (variants.png): the first collision of
    // each (none when it has none).
    struct Variant {
        std::string label;
        std::optional<CollisionInstant> first;
        double ke_before = 0.0, ke_after = 0.0;  // J, the two bodies of that collision
    };
    std::vector<Variant> variants;
    std::optional<PenaltyStudy> penalty;      // a lesson's [penalty] (penalty.svg, penalty.csv)
    std::vector<double> t;                    // every frame's time (s)
    std::vector<render::FrameTotals> totals;  // and its energies and momentum
    // For the plots: the frames' totals with the exact ones just before and just after each
    // recorded collision instant inserted (two points at its time), in time order.
    std::vector<double> plot_t;
    std::vector<render::FrameTotals> plot_totals;
    std::vector<PlotData> plots;  // a lesson's [[plot]] entries, on this run
    long frames = 0;
    int width = 0, height = 0;
    double seconds = 0.0;  // rendering and writing the frames
    std::string video;     // "animation.mp4" / ".gif", or ""
};

// Renders `request.scenario` into request.out_dir as the command does, without the summary:
// load (the scene, its [view], its lesson), run (the scene once; a lesson's answers and
// penalty study), analyse (the first collision's moments, its worked example, a lesson's
// variants), write (the data files, worked-example.md, the frames, the stills, the figure,
// variants.png, lesson.md, the video).
// Throws InputError (bad input: nothing written), Interrupted, or std::runtime_error.
// Progress and notes (no collision) go to err.
RenderReport render_scenario(const RenderRequest& request, std::ostream& err, const StopRequested& stop = nullptr);

// What a render draws: a scene, its [view] table and its lesson, if it is one.
struct RenderSource {
    Scene scene;
    SceneView view;
    std::optional<Lesson> lesson;
};
// Read from a scenario file, a lesson file or a lesson id (load_scenario). Throws InputError.
RenderSource load_render_source(const std::string& scenario);

// figure.png alone, as render_scenario writes it for a request with `frame` and `backend` (the
// same run and the same collision; no frames and no other file), drawn from `source` (the
// Python module's collide.render_figure, whose scene may be a table in memory): the PNG's
// bytes, or nullopt when the run has no collision. Throws InputError or std::runtime_error.
std::optional<std::vector<std::uint8_t>> figure_png(const FrameSpec& frame, render::GlBackend backend,
                                                    RenderSource source);

// A variant's "kinetic energy lost" cell: the loss, or the gain marked as such (no passive
// impact gains energy: engine/diagnostics.h gains_energy).
std::string energy_lost_text(double before, double after);

// The first collision's formula overlay of the scene's run (run_scene at the frame rate), as
// the frames show it (`collide gui` draws it too); nullopt when the run has no collision.
std::optional<render::FormulaText> first_collision_formula(const Scene& scene, const SceneRun& run);

}  // namespace collide
