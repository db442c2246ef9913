// A scene run once (engine/record.h) and what the pictures and data files take from it:
// every sampled state lifted to 3D for the renderer, every collision as a mark, the data
// files' text, and the moments of a collision (before / at / after) for its figure.
// `collide render`, `collide material` and `collide gui` read one SceneRun per scene.
#pragma once

#include <optional>
#include <string>
#include <vector>

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
SceneRun run_scene(const Scene& scene, const std::vector<double>& times);

// The data files of a run (README.md, "collide render"): data.csv, events.csv, and the
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
    double before = 0, at = 0, after = 0;   // s
    render::FrameState states[3];           // at those times; states[1] has the instant's impacts
    CollisionInstant instant;               // the first collision, the bodies where they touch
};
std::optional<Moments> first_moments(const Scene& scene, const SceneRun& run);

// The totals (energies, momentum) just before and just after each recorded collision instant
// (the first RecordOptions::instants of the run), exact: plots step there instead of
// sloping between the samples around it.
struct InstantTotals {
    double t = 0;  // s
    render::FrameTotals before, after;
};
std::vector<InstantTotals> instant_totals(const Scene& scene, const SceneRun& run);

}  // namespace collide
