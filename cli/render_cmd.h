// `collide render SCENARIO -o DIR`: runs a scenario and writes its pictures (README.md,
// "collide render"):
//   DIR/frames/frame_00000.png ...   the animation, one PNG per frame (fps frames per simulated s)
//   DIR/before.png, at.png, after.png  the first collision: a moment before, the exact instant
//                                      (impulse, normal, r vectors), a moment after
//   DIR/figure.png                   those three side by side with captions
//   DIR/data.csv, DIR/data.json      the sampled states (as `collide step --json`) and events
//   DIR/events.csv                   the collision events
//   DIR/worked-example.md            the first collision worked out (as `collide solve`)
//   DIR/lesson.md                    for a lesson: its text, questions and computed answers
//   DIR/variants.png                 for a lesson with variants: a row of panels for each
//   DIR/animation.mp4 or .gif        with --format mp4 or gif (needs ffmpeg)
#pragma once

#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "teach/answers.h"
#include "teach/lesson_penalty.h"
#include "cli/scene_run.h"
#include "teach/solve.h"
#include "render/frame_state.h"
#include "render/renderer.h"

namespace collide {

struct RenderOptions {
    std::string scenario;          // a scenario file, a lesson file or a lesson id
    std::string out_dir;           // -o DIR
    std::string size = "720p";     // --size: WxH, or 480p, 720p, 1080p, 1440p
    double fps = 30.0;             // --fps: frames per simulated second
    // --quality: low: no anti-aliasing; medium: anti-aliased (2D: Dear ImGui's edges; 3D: 4x
    // MSAA), fast PNGs (zlib level 1, no filter); high: as medium, PNGs about 10-20% smaller
    // (level 6, adaptive filters) and 4x slower to encode (two encoder threads).
    std::string quality = "medium";
    std::string view;              // --view: 2d or 3d; empty: 2d for 1D and 2D scenes, 3d for 3D
    std::string format = "png";    // --format: png (frames only), mp4 or gif (also
                                   // DIR/animation.mp4 or .gif, through ffmpeg)
    bool quiet = false;            // --quiet: no progress bar, no summary
    bool force = false;            // --force: write into a non-empty DIR (replacing our files)
    std::string backend = "osmesa";  // OpenGL context: osmesa or egl
};

// What a render made and computed, for the summary line and for `collide material`.
struct RenderReport {
    Scene scene;
    SceneView view;
    std::optional<Lesson> lesson;
    std::vector<LessonAnswer> answers;         // a lesson's questions, in order
    std::optional<SolveProblem> problem;       // the first collision's worked example
    std::optional<Solution> solution;
    std::optional<CollisionInstant> first_collision;
    std::string world_note;  // when the world resolved several points there (the formula box's note)
    std::vector<double> collision_times;       // s, every collision of the run
    // A lesson's scene and its variants side by side (variants.png): the first collision of
    // each (none when it has none).
    struct Variant {
        std::string label;
        std::optional<CollisionInstant> first;
        double ke_before = 0.0, ke_after = 0.0;  // J, the two bodies of that collision
    };
    std::vector<Variant> variants;
    std::optional<PenaltyStudy> penalty;       // a lesson's [penalty] (penalty.svg, penalty.csv)
    std::vector<double> t;                     // every frame's time (s)
    std::vector<render::FrameTotals> totals;   // and its energies and momentum
    long frames = 0;
    int width = 0, height = 0;
    double seconds = 0.0;                      // rendering and writing the frames
    std::string video;                         // "animation.mp4" / ".gif", or ""
};

// Thrown when SIGINT or SIGTERM stopped a render between frames: every file written is
// complete (the frames handed to the encoder were finished first).
struct Interrupted : std::runtime_error {
    explicit Interrupted(long frames_written)
        : std::runtime_error("interrupted"), frames(frames_written) {}
    long frames;
};

// Renders `options.scenario` into options.out_dir as the command does, without the summary.
// Throws InputError (bad input: nothing written), Interrupted, or std::runtime_error.
RenderReport render_scenario(const RenderOptions& options, std::ostream& err);

// Runs the command. Returns the exit code: 0 done, 130 interrupted (SIGINT / SIGTERM: the
// files written are complete), 2 bad input (one "collide: error: ..."
// line on err: the scenario file, an option, or an output directory that is not empty),
// 1 any other failure. Progress goes to err when it is the process's stderr and a terminal.
int run_render(const RenderOptions& options, std::ostream& out, std::ostream& err);

// What `collide gui` shares with the frames of `collide render`:
// the frames' settings for the options' size, quality, fps and view (and the first collision's
// formula, when given);
render::RenderSettings frame_settings(const RenderOptions& o, const Scene& scene, const SceneView& view,
                                      const render::FormulaText* formula);
// the first collision's formula overlay, and its before / at / after figure (figure.png), of
// the scene's run (run_scene at the frame rate); nullopt when the run has no collision.
std::optional<render::FormulaText> first_collision_formula(const Scene& scene, const SceneRun& run);
std::optional<render::Image> first_collision_figure(render::GlContext& context, const Scene& scene,
                                                    const SceneView& view, const render::RenderSettings& settings,
                                                    const SceneRun& run);

// "1280x720" or a preset (480p: 854x480, 720p: 1280x720, 1080p: 1920x1080, 1440p: 2560x1440);
// false for anything else, or sizes outside 16..8192.
bool parse_render_size(const std::string& text, int* width, int* height);
// The same for the --size option: throws InputError naming --size and what it accepts.
void read_render_size(const std::string& text, int* width, int* height);

}  // namespace collide
