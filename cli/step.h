// `collide step`: runs a scenario and prints its states at each output step, or its collision
// events, in 1D, 2D and 3D. Formats: README.md. The pieces the interactive mode shares (output
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

// The output instants t = k output_dt, k = 0 .. K, with the last one at the duration exactly.
std::vector<double> output_times(const Scene& scene);

// One state or one event, as `collide step` prints them; `only` limits a state to one body.
constexpr std::size_t kAllBodies = static_cast<std::size_t>(-1);
std::string state_json(const Scene& s, double t, const std::vector<Body1>& bodies,
                       std::size_t only = kAllBodies);
std::string state_json(const Scene& s, double t, const std::vector<Body2>& bodies,
                       std::size_t only = kAllBodies);
std::string state_json(const Scene& s, double t, const std::vector<Body3>& bodies,
                       std::size_t only = kAllBodies);
std::string event_json(const Scene& s, const Event1& e);
std::string event_json(const Scene& s, const Event2& e);
std::string event_json(const Scene& s, const Event3& e);
std::string event_text(const Scene& s, const Event1& e);  // one line, no newline
std::string event_text(const Scene& s, const Event2& e);
std::string event_text(const Scene& s, const Event3& e);
// A state as lines for a reader: the time, one line per body, the totals (all bodies only).
std::string state_text(const Scene& s, double t, const std::vector<Body1>& bodies,
                       std::size_t only = kAllBodies);
std::string state_text(const Scene& s, double t, const std::vector<Body2>& bodies,
                       std::size_t only = kAllBodies);
std::string state_text(const Scene& s, double t, const std::vector<Body3>& bodies,
                       std::size_t only = kAllBodies);

}  // namespace collide
