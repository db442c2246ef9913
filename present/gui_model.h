// What `collide gui` shows and changes, without the window: the scene as loaded and as edited,
// its run sampled at the frame rate (exactly as `collide render` samples it, so a frame of the
// window is a frame of the offscreen render), the playback position and speed, and the text
// script that drives it in tests and demonstrations (`collide gui --script FILE`).
//
// Every change re-runs the edited scene from its start: the run is deterministic, so the same
// settings give the same frames. The re-run happens on a worker thread (present/background_run.h):
// in the window (Rerun::background) an edit returns at once, the frames stay those of the last
// complete run while the new one runs, and a newer edit cancels an older run; elsewhere
// (Rerun::wait, the default: tests, scripts) an edit returns once its run has finished.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "present/background_run.h"
#include "present/scene_run.h"
#include "engine/scene.h"
#include "render/diagram_view.h"
#include "render/frame_state.h"

namespace collide {

// How an edit's re-run is waited for.
enum class Rerun {
    wait,        // the edit returns once the run has finished (its frames or error are there)
    background,  // the edit returns at once; poll() takes the run when it has finished
};

class GuiModel {
public:
    // Runs `scene` at `fps` frames per simulated second (this first run always waits). Throws
    // std::runtime_error if the world cannot run it (the message says why).
    GuiModel(Scene scene, double fps, Rerun mode = Rerun::wait);

    const Scene& original() const { return original_; }
    const Scene& scene() const { return scene_; }  // as edited: what the controls show
    // The scene of the frames (run()): scene() once its re-run has finished, until then the
    // scene of the previous complete run. Draw with this one.
    const Scene& shown_scene() const { return shown_; }

    // Edits; each re-runs the scene from t = 0 and keeps the playback time. A run the world
    // refuses leaves the previous frames and sets error(). Restitution and friction set the
    // scene's value for every pair (bodies' own values are cleared).
    void set_restitution(double e);
    void set_friction(double mu);
    void set_model(Model m);
    void set_policy(Policy p);
    void set_mass(std::size_t body, double mass);        // the inertia scales with it
    void set_velocity(std::size_t body, const Vec3& v);  // 1D: x; 2D: x, y
    void set_spin(std::size_t body, const Vec3& w);      // 2D: z; 3D: the vector (rad/s)
    // The body's shape scaled by `factor` about its centre (mass kept, inertia x factor^2).
    // Refused (error(), nothing changed) when it would then overlap another body.
    void scale_size(std::size_t body, double factor);
    void reset();  // back to the scene as loaded
    const std::string& error() const { return error_; }

    // The re-run under way (Rerun::background). running(): an edit's run has not finished, or
    // not been taken by poll(); the frames are still the previous run's.
    bool running() const { return runs_.busy(); }
    double run_progress() const { return runs_.progress(); }  // 0 to 1: simulated time reached / duration
    // Takes the newest run once it has finished: its frames (the playback time kept) or its
    // error. True when either changed (the window then redraws from shown_scene() and run()).
    bool poll();
    // Waits for the run under way and takes it (as poll()); at once when there is none.
    void finish();

    // The run: one frame per 1/fps s from 0 to the duration, and every collision.
    double fps() const { return fps_; }
    const std::vector<render::FrameState>& frames() const { return run_.frames; }
    const std::vector<render::ImpactMark>& impacts() const { return run_.impacts; }
    const SceneRun& run() const { return run_; }  // the one run the frames and figure read

    // Playback: the frame shown.
    std::size_t index() const { return index_; }
    double time() const { return run_.frames[index_].t; }
    void seek_index(std::size_t k);
    void seek_time(double t);  // the last frame at or before t
    void step(long frames);    // forward (or back, when negative), stopping at the ends
    bool next_collision();     // the first frame at or after the next collision; false if none
    // Playing: advances by `wall_seconds` x speed of simulated time; stops at the end.
    bool playing = false;
    double speed = 1.0;  // 1: real time; 0.25: slow motion
    void advance(double wall_seconds);

    // The frame as drawn: trails, and the collisions since the previous frame (as the
    // offscreen render shows them).
    render::FrameState display_frame() const;

private:
    struct Run {
        Scene scene;  // the scene the run is of
        SceneRun run;
    };
    void rerun();  // starts the run of scene_ (and waits for it under Rerun::wait)

    Scene original_, scene_, shown_;
    double fps_;
    Rerun mode_;
    SceneRun run_;
    std::size_t index_ = 0;
    double clock_ = 0.0;  // simulated time while playing (between frames)
    std::string error_;
    BackgroundRun<Run> runs_;  // last: its worker stops before the rest goes
};

// The view switches of the window (and the script's `toggle`).
struct GuiToggles {
    render::Decor decor;  // velocities, impacts, trails, labels, com, directions
    bool header = true, table = true, plots = true, timeline = true;
    // Names as in the script: velocities impacts trails labels com directions header table
    // plots timeline. False if unknown.
    bool toggle(const std::string& name);
};

// One line of a script. Window actions (open, screenshot, save-frame, save-figure, wait, orbit,
// zoom, quit) are carried out by the window; the others by run_script_action.
struct GuiAction {
    int line = 0;
    std::string verb;               // set, play, pause, step, back, next-collision, time, slow,
                                    // toggle, reset, screenshot, save-frame, save-figure, wait,
                                    // open, orbit, zoom, quit
    std::vector<std::string> args;  // as written
};

// Reads a script (one action a line; '#' starts a comment). Throws InputError naming the
// file, line and word for an unknown verb or a wrong argument.
std::vector<GuiAction> parse_gui_script(const std::string& path);
// The same from text (`name` for messages).
std::vector<GuiAction> parse_gui_script_text(const std::string& text, const std::string& name);

// Carries out a model or toggle action; false for a window action (left to the caller).
// Throws InputError (file, line) for a body that does not exist or a run the world refuses.
bool run_script_action(const GuiAction& a, const std::string& file, GuiModel* model, GuiToggles* toggles);

}  // namespace collide
