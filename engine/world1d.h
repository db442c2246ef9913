// The 1D world: blocks on a line, advanced from event to event with exact impact times.
//
// Between impacts every block moves freely: x(t) = x + v t + g t^2/2 (g: the scene's gravity
// along x for dynamic blocks). The gap between two blocks is then a quadratic in t, so the
// first contact time is its smallest root, found in closed form (no step size, no overlap).
// At an impact instant every touching pair that approaches is resolved by the scene's policy
// (docs/conventions.md: n from A, the left block, into B, the right one):
//   sequential:   one contact at a time, the leftmost approaching pair first, until no touching
//                 pair approaches (Newton's cradle: (v, 0, 0) -> (0, 0, v)); a sequence that
//                 would go on for ever is finished by one simultaneous step (resolve_contacts);
//   simultaneous: all touching pairs of the instant together: impulses P >= 0 with
//                 K P = -(1 + e) u on the pairs that receive one (a small LCP solved by active
//                 sets, as Box2D's block solver does for two points); the cradle gives
//                 (-v/3, 2v/3, 2v/3).
// Resting contact under gravity: a block touching a support (a static block, or a block that
// itself rests) with no speed away from it rests: gravity is balanced and it stays put until
// something hits it. A bouncing block whose remaining bounce series would last less than
// kZenoTime (the series 2u/(g(1 - e)) sums the flights after a bounce at speed u) is set to
// rest there: the infinitely many bounces of e < 1 accumulate at a finite time, and this
// merges at most kZenoTime of them. It is a time tolerance, not a restitution threshold:
// e = 1 bounces forever, and every bounce longer than kZenoTime is simulated exactly.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "engine/run_count.h"
#include "engine/scene.h"

namespace collide {

struct Event1 {
    double t = 0.0;            // s
    std::size_t a = 0, b = 0;  // the left and the right block (indices into the scene)
    double point = 0.0;        // m, where they touch
    double impulse = 0.0;      // N s on b along +x (a receives the opposite)
    double va_before = 0.0, vb_before = 0.0, va_after = 0.0, vb_after = 0.0;  // m/s
    double xa = 0.0, xb = 0.0;                                                // m: the blocks' centres at the instant
};

class World1 {
public:
    explicit World1(const Scene& scene);

    double time() const { return time_; }
    const std::vector<Body1>& bodies() const { return bodies_; }
    const Scene& scene() const { return scene_; }

    // Called during advance_to each time impacts were resolved and their events appended, with
    // their instant (= time(); bodies() are there, after the impulses).
    using ImpactHook = std::function<void(double t)>;

    // Moves to time t (>= time()), resolving every impact on the way; appends the events.
    // (An impact exactly at t is resolved by the next advance, at its start.)
    void advance_to(double t, std::vector<Event1>* events, const ImpactHook& on_impact = nullptr);

    // Every block moves together here: the state at time() (as World<D>::bodies_at).
    std::vector<Body1> bodies_at(double t) const;

    // Replaces block i's state at time() (the interactive `set` command); supports are found
    // again at the next advance.
    void set_body(std::size_t i, const Body1& body);

    static constexpr double kTouch = 1e-12;     // m: a gap this small is contact
    static constexpr double kZenoTime = 1e-12;  // s: a bounce series this short is rest

    bool resting(std::size_t i) const { return supported_[i]; }

    // The work done so far (Scene::work_budget, engine/scene.h): each motion between events
    // and each event. A run whose work passes the budget is stopped (RunError).
    std::uint64_t work_done() const { return work_; }

private:
    double right_face(std::size_t i) const;          // m: where a block meets its right neighbour
    double gap(std::size_t i, std::size_t j) const;  // right i's face to left j's face
    double first_contact(std::size_t i, std::size_t j, double horizon) const;
    void drift(double dt);
    void check_finite() const;  // every body finite at time_; else RunError
    [[noreturn]] void refuse_work() const;
    std::uint64_t work_ = 0;
    void update_support();                           // sets supported_ (see above)
    double acceleration(std::size_t i) const;        // m/s^2 along x
    std::vector<std::size_t> left_to_right() const;  // block indices by position
    void resolve_contacts(std::vector<Event1>* events);
    bool resolve_sequential(std::vector<Event1>* events);
    bool resolve_simultaneous(std::vector<Event1>* events);

    RunCount runs_;  // counts this world among every run (run_count.h)
    Scene scene_;
    std::vector<Body1> bodies_;
    std::vector<bool> supported_;  // resting on a support under gravity
    double time_ = 0.0;
};

}  // namespace collide
