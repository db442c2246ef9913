// `collide step`'s output: runs a scenario and prints its states at each output step, or its
// collision events, in 1D, 2D and 3D. Formats: docs/commands/step.md. Render-free, in teach/ so that the
// command, the Python module and the WebAssembly module (wasm/) call this one implementation. The pieces the interactive mode shares (output
// instants, one state, one event) are declared here too.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "engine/record.h"
#include "engine/scene.h"

namespace collide {

struct StepOptions {
    bool json = false;    // one JSON object per line instead of the aligned table
    bool events = false;  // only the collision events
};

// Writes the run of `scene` to out. Throws std::runtime_error when the world fails.
void write_steps(const Scene& scene, const StepOptions& options, std::ostream& out);

// The lines of `collide step --json` (one state per output instant) and of
// `collide step --events --json` (one per collision), from one run of `scene` (the Python
// module's collide.run). Throws std::runtime_error when the world fails.
struct StepJson {
    std::vector<std::string> states, events;
};
StepJson step_json(const Scene& scene);

// The output instants t = k output_dt, k = 0 .. K, with the last one at the duration exactly.
std::vector<double> output_times(const Scene& scene);

// One state or one event, as `collide step` prints them; `only` limits a state to one body.
constexpr std::size_t kAllBodies = static_cast<std::size_t>(-1);
// (Body: Body1, Body2 or Body3.)
template <class Body>
std::string state_json(const Scene& s, double t, const std::vector<Body>& bodies, std::size_t only = kAllBodies);
// `energy_gain`: the event's instant left its bodies with more kinetic energy than before
// (energy_gains): JSON "energy_gain": true, the text line ends with a warning.
std::string event_json(const Scene& s, const Event1& e, bool energy_gain);
std::string event_json(const Scene& s, const Event2& e, bool energy_gain);
std::string event_json(const Scene& s, const Event3& e, bool energy_gain);
std::string event_text(const Scene& s, const Event1& e, bool energy_gain);  // one line, no newline
std::string event_text(const Scene& s, const Event2& e, bool energy_gain);
std::string event_text(const Scene& s, const Event3& e, bool energy_gain);
// For each event, whether its instant (the events of its time, in order: `events` holds whole
// instants) left their bodies with more kinetic energy than before (engine/diagnostics.h
// gains_energy, on teach/event_problem.h instant_kinetic_energy): no passive impact can;
// a one-step friction model with Newton's restitution can (Kane's paradox).
std::vector<bool> energy_gains(const Scene& s, const std::vector<Event1>& events);
std::vector<bool> energy_gains(const Scene& s, const std::vector<Event2>& events);
std::vector<bool> energy_gains(const Scene& s, const std::vector<Event3>& events);
// A state as lines for a reader: the time, one line per body, the totals (all bodies only).
template <class Body>
std::string state_text(const Scene& s, double t, const std::vector<Body>& bodies, std::size_t only = kAllBodies);

}  // namespace collide
