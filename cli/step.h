// `collide step`: runs a scenario and prints its states at each output step, or its collision
// events, in 1D, 2D and 3D. Formats: README.md. The pieces the interactive mode shares (output
// instants, one state, one event) are declared here too.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "engine/scene.h"
#include "engine/world.h"
#include "engine/world1d.h"

namespace collide {

struct StepOptions {
    bool json = false;    // one JSON object per line instead of the aligned table
    bool events = false;  // only the collision events
};

// Writes the run of `scene` to out. Throws std::runtime_error when the world fails.
void write_steps(const Scene& scene, const StepOptions& options, std::ostream& out);

// The output instants t = k output_dt, k = 0 .. K, with the last one at the duration exactly.
std::vector<double> output_times(const Scene& scene);

// World1 with set_body, as World<2> and World<3> have. World1 has no setter, so set_body
// restarts it from a scene holding every body's current state; its clock then starts at 0
// again, and the time it restarted at is kept here as an offset.
class SettableWorld1 {
public:
    explicit SettableWorld1(const Scene& scene) : world_(scene) {}

    double time() const { return start_ + world_.time(); }
    const Scene& scene() const { return world_.scene(); }
    const std::vector<Body1>& bodies() const { return world_.bodies(); }
    void advance_to(double t, std::vector<Event1>* events);
    void set_body(std::size_t i, const Body1& body);

private:
    World1 world_;
    double start_ = 0.0;  // s: when world_ started
};

// The world and event types of each dimension.
template <int D> struct Stepping {
    using World = collide::World<D>;
    using Event = collide::Event<D>;
};
template <> struct Stepping<1> {
    using World = SettableWorld1;
    using Event = Event1;
};

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
