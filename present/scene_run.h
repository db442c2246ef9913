// A scene run once (engine/record.h) and what the pictures and data files take from it:
// every sampled state lifted to 3D for the renderer, every collision as a mark, the data
// files' text, and the moments of a collision (before / at / after) for its figure.
// `collide render`, `collide material` and `collide gui` read one SceneRun per scene.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "present/shown_collision.h"
#include "teach/event_problem.h"
#include "engine/record.h"
#include "render/frame_state.h"

namespace collide {

struct SceneRun {
    AnyRecording record;
    std::vector<render::FrameState> frames;   // every sampled instant, in order
    std::vector<render::ImpactMark> impacts;  // every collision, in time order
};

// Runs `scene` once, sampled at `times` (output_times of the scene at the frame rate).
// `on_sample`, if given, is called after each sample with its time (RecordOptions::on_sample:
// progress, and a throw stops the run). `keep`: collisions whose instants the record keeps
// wherever they fall (RecordOptions::keep: a lesson's figures), besides the first 16.
SceneRun run_scene(const Scene& scene, const std::vector<double>& times,
                   const std::function<void(double t)>& on_sample = nullptr,
                   const std::vector<RecordOptions::Keep>& keep = {});

// The data files of a run (docs/commands/render.md): data.csv, events.csv, and the
// frames and events of data.json (state_json / event_json objects joined by ",\n").
struct DataFiles {
    std::string csv, events_csv, json_frames, json_events;
};
DataFiles data_files(const Scene& scene, const SceneRun& run);

// The three moments of a run's first collision: a recorded state a moment before it (the
// last sample at or before te - dt), the bodies at the instant after its impulses, and a
// recorded state a moment after (the first sample at or after te + dt, short of the next
// collision of the same bodies; the instant itself when no sample lies between). dt: the
// time to close half the smaller body's size at the approach speed (at most a quarter of
// the run). The before and after states keep those samples' poses but carry the velocities
// just before and just after the impacts, so that the figure's numbers are the instant's.
struct Moments {
    double before = 0, at = 0, after = 0;  // s
    render::FrameState states[3];          // at those times; states[1] has the instant's impacts
    CollisionInstant instant;              // the collision, the bodies where they touch
    std::size_t event = 0;                 // its (first) event's index in the run
    std::vector<std::size_t> focus;        // a picked pair's two bodies (their arrows only);
                                           // empty for a whole instant (every body's)
};
std::optional<Moments> first_moments(const Scene& scene, const SceneRun& run);

// Its moments, as first_moments gives the first collision's; the "at" state holds only this
// pair's impacts, and before / after carry the velocities just before and just after them
// (in an instant resolved one contact after another, the earlier contacts have acted).
// nullopt when the run has no such collision among its recorded instants.
std::optional<Moments> collision_moments(const Scene& scene, const SceneRun& run, const CollisionPick& pick);
// The moments of the collision a page works out first (present/shown_collision.h page_pick):
// the first of `picks`, else the run's first collision.
std::optional<Moments> page_moments(const Scene& scene, const SceneRun& run, const std::vector<CollisionPick>& picks);

// How many recorded instants of the run have a collision of bodies a and b.
int pair_collisions(const SceneRun& run, std::size_t a, std::size_t b);

// An impact drawn with the roles given (with_roles for the mark): the same impulse and normal
// with a and b swapped when the engine found them the other way round.
render::ImpactMark with_roles(const render::ImpactMark& mark, std::size_t a, std::size_t b);

// The totals (energies, momentum) just before and just after each recorded collision instant
// (the first RecordOptions::instants of the run), exact: plots step there instead of
// sloping between the samples around it.
struct InstantTotals {
    double t = 0;  // s
    render::FrameTotals before, after;
};
std::vector<InstantTotals> instant_totals(const Scene& scene, const SceneRun& run);

// The run's totals for plots: every sample's, and at each recorded collision instant the two
// of instant_totals (a sample at that very instant left out: which side it shows depends on
// the world's order of work), so that a plot steps at the instant. The site's plots and the
// frames' use these.
struct PlotTotals {
    std::vector<double> t;  // s, not decreasing (an instant twice)
    std::vector<render::FrameTotals> totals;
};
PlotTotals plot_totals(const Scene& scene, const SceneRun& run);

// The same instants as plot_totals, with the bodies (no impacts, no trails): every sample, and
// at each recorded collision instant the bodies just before and just after its impulses (a
// lesson's per-sample [[plot]], present/lesson_plots.h).
std::vector<render::FrameState> plot_states(const Scene& scene, const SceneRun& run);

}  // namespace collide
