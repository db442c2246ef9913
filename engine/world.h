// The 2D and 3D worlds: bodies advanced from impact to impact at the exact instant of contact.
// One algorithm serves both dimensions (World<2>, World<3>); what differs comes from Space<D>
// (engine/space.h). Between events bodies move freely (ballistic, torque-free turning); each
// impact is found by time of impact and resolved by the scene's policy and model; resting
// contacts form islands with constant forces, islands at rest sleep, persistent contacts are
// stepped in time steps, and the stick model welds bodies together.
//
// How a scene is stepped, in full: docs/stepping.md. Its sections ("Motion between events",
// "Time of impact", "At an impact", "Resting contact", "Sleeping islands", "Stepped islands",
// "Stuck bodies", "The page's listing as written", "Known limits") are what this code's
// comments refer to. The state below is grouped by the concern that owns it, each in its file.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "engine/broad_phase.h"
#include "engine/contact_solver.h"
#include "engine/island_step.h"
#include "engine/run_count.h"
#include "engine/scene.h"
#include "engine/space.h"
#include "engine/weld.h"

namespace collide {

// One collision of one pair of bodies at one instant (all its contact points together).
template <int D>
struct Event {
    using Vec = typename Space<D>::Vec;
    using Spin = typename Space<D>::Spin;
    struct Velocity {
        Vec v;   // m/s
        Spin w;  // rad/s
    };
    double t = 0.0;            // s
    std::size_t a = 0, b = 0;  // body indices (a < b, or b the dynamic one against a static a)
    Vec point;                 // m: where the resultant impulse acts (impulse-weighted points)
    Vec normal;                // unit, from a into b
    Vec impulse;               // N s on b (a receives -impulse)
    Velocity before_a, before_b, after_a, after_b;
    // Where the two bodies are at the instant (centre of mass and orientation): with the
    // scene's masses, shapes and the velocities above, the collision can be rebuilt from the
    // event alone (teach/event_problem.h). (A welded body's pose is its own, not its compound's.)
    typename Space<D>::Pose pose_a, pose_b;
    // The model's answer was an approximation (Response3::approximate: Routh's integration
    // could not be finished as specified); `collide step --events` says so.
    bool approximate = false;
};

// Where, when and how hard one collision struck, in 3D form whatever its dimension (as
// BodyState is for a body): what the renderer marks and the teaching code rebuilds from.
struct LiftedEvent {
    double t = 0.0;               // s
    std::size_t a = 0, b = 0;     // body indices; the normal points from a into b
    Vec3 point = Vec3::Zero();    // m
    Vec3 normal = Vec3::UnitX();  // unit
    Vec3 impulse = Vec3::Zero();  // N s on b
};
template <int D>
LiftedEvent lifted(const Event<D>& e) {
    return {e.t, e.a, e.b, lift(e.point), lift(e.normal), lift(e.impulse)};
}

template <int D>
class World {
public:
    using Vec = typename Space<D>::Vec;
    using Spin = typename Space<D>::Spin;
    using Body = typename Space<D>::Body;
    using Shape = typename Space<D>::Shape;
    using Manifold = typename Space<D>::Manifold;

    explicit World(const Scene& scene);  // throws std::invalid_argument for a wrong dimension

    double time() const { return loop_.time; }
    const Scene& scene() const { return scene_; }
    // Every body's state at time().
    const std::vector<Body>& bodies() const { return loop_.open ? loop_.bodies_now : bodies_; }

    // Called during advance_to each time an impact was resolved and its events appended, with
    // its instant; bodies_at(t) then gives every body there, after the impulses.
    using ImpactHook = std::function<void(double t)>;

    // Moves to time t (>= time()), resolving every impact on the way; appends the events in
    // time order. Throws std::runtime_error if more than kMaxEventsPerAdvance happen, RunError
    // (engine/run_error.h) if a body's state is no longer finite.
    // Where advance_to is asked to stop does not shape the run: substeps are chosen from the
    // bodies alone, and an advance that ends inside one pauses there (bodies() is then each
    // body's state at t along its motion, the substep's predictions and forces kept), so a
    // run sampled at other instants is the same run, event for event and bit for bit.
    void advance_to(double t, std::vector<Event<D>>* events, const ImpactHook& on_impact = nullptr);

    // Every body at time t along its current motion, the world itself unchanged: valid from
    // the last instant the world handled up to its next impact (inside ImpactHook: the
    // impact's own instant). Between advances, bodies_at(time()) == bodies().
    std::vector<Body> bodies_at(double t) const;

    // Replaces a body's state (position, orientation, velocities) at time(); e.g. the
    // interactive `set` command. Contacts and predictions are recomputed.
    void set_body(std::size_t i, const Body& body);

    // True while body i is held by a resting contact (an island).
    bool resting(std::size_t i) const { return islands_.of[i] != 0; }
    // True while body i's island sleeps: at rest, in balance, costing nothing until woken.
    bool asleep(std::size_t i) const { return islands_.asleep[i] != 0; }
    // True while body i is stuck to other bodies (see "Stuck bodies").
    bool welded(std::size_t i) const { return welds_.of[i] >= 0; }
    // True while body i advances by time steps (see "Stepped islands").
    bool stepped(std::size_t i) const { return steps_.stepped[i] != 0; }

    struct Counters {
        std::uint64_t events = 0;       // pair collisions recorded
        std::uint64_t predictions = 0;  // time-of-impact computations
        std::uint64_t substeps = 0;
        std::uint64_t island_solves = 0;
        std::uint64_t sleeps = 0;  // islands put to sleep
        std::uint64_t welds = 0;   // pairs stuck together (the stick model)
        std::uint64_t steps = 0;   // time steps of the stepped islands
        std::uint64_t joined = 0;  // bodies that became stepped
    };
    const Counters& counters() const { return counters_; }

    // The work done so far, in the units of Scene::work_budget (engine/scene.h): each moving
    // body's share of each substep, each free-rotation step, each time-of-impact prediction,
    // each collision. The world refuses (RunError) to start a scene whose estimate
    // (work_estimate(): its free motion alone, without gravity, over its duration) is beyond
    // the budget, and stops a run whose work passes it.
    std::uint64_t work_done() const;
    double work_estimate() const { return estimate_; }

    static constexpr double kTouch = 1e-10;     // m: a gap this small is contact
    static constexpr double kZenoTime = 1e-12;  // s: see "Resting contact"
    static constexpr double kRestStep = 1e-3;   // s: longest substep while anything rests
    // Substeps (free_substep(); docs/stepping.md, "Motion between events"): about four radii
    // of motion each (the bodies' speeds counted as |v| + |a| kSpeedSpan), at most
    // kLongestSubstep and at least kShortestSubstep (a body at an absurd speed cannot make a
    // run millions of grid rebuilds; longer substeps only widen the swept boxes). Free motion in
    // closed form (ballistic; a 2D turn; a sphere's or a symmetric top's turn) is exact for any
    // length. A turn integrated in steps (turns_in_steps()) is integrated from the substep's
    // start to a sample or a time-of-impact guess, and in other pieces by the run's events: while
    // one exists no body turns more than kTurnPerSubstep in a substep, where such pieces agree
    // to 1e-11 m per metre of reach (10x under kTouch; measured: 2e-12 at up to 1 rad, 6e-10 at
    // 5 rad, and near the middle axis, whose motion is unstable, 2e-2 at 50 rad); yet never
    // shorter than kRestStep, whatever the spin (over 500 rad/s: a turn beyond the work budget
    // is still refused before it is taken, not after the budget is spent in short substeps). Each
    // substep's start takes gaps under kTouch for contact, so two bodies closing at speed u meet
    // within kTouch / u of the exact instant.
    static constexpr double kLongestSubstep = 1.0;
    static constexpr double kSpeedSpan = 0.01;      // s
    static constexpr double kTurnPerSubstep = 0.5;  // rad
    static constexpr double kShortestSubstep = 1e-5;
    static constexpr std::size_t kMaxEventsPerAdvance = 20000000;
    static constexpr std::uint64_t kMaxWorkPerInstant = 100000;  // predictions popped at one t
    // Stepped islands (docs/stepping.md).
    static constexpr double kIslandStep = 1.0 / 600.0;  // s
    static constexpr int kPersistImpacts = 16;
    static constexpr double kPersistWindow = 0.1;    // s
    static constexpr double kSpeculative = 1e-3;     // m
    static constexpr double kStepSleepSpeed = 2e-3;  // m/s
    static constexpr double kStepSleepTime = 0.5;    // s

private:
    // advance_to's start of a substep at loop_.time: its length, the grid, resting forces, the stepped
    // islands' step, every prediction.
    void begin_substep(std::vector<Event<D>>* events, const ImpactHook& on_impact);
    struct Track {                  // per body: its own clock and current free motion
        double t = 0.0;             // s: the time bodies_[i] is at
        Vec a;                      // m/s^2 (gravity plus resting forces)
        Spin alpha;                 // rad/s^2 (resting forces)
        std::uint32_t version = 0;  // bumped whenever the motion changes
    };
    struct Pending {  // a predicted impact of bodies i and j
        double t;
        std::uint32_t i, j, vi, vj;  // vi, vj: the versions it was predicted from
        bool operator>(const Pending& o) const { return t != o.t ? t > o.t : (i != o.i ? i > o.i : j > o.j); }
    };
    using Contact = collide::Contact<D>;      // one touching pair (engine/contact_solver.h)
    using PointGoal = collide::PointGoal<D>;  // what the contact solver aims at for one point
    using Weld = collide::Weld<D>;            // bodies stuck together (engine/weld.h)
    // A body's motion for conservative advancement: a copy of it and, when welded, of its weld.
    struct Mover {
        std::size_t i = 0;
        Body body, compound;
    };

    // Every body's state finite at t (the end of a substep, or where an advance pauses);
    // else throws RunError naming the first body that is not and the instant.
    void check_finite(const std::vector<Body>& bodies, double t) const;

    // The work budget (see work_done()).
    std::uint64_t work_budget() const;
    double estimate_work() const;
    [[noreturn]] void refuse_work(double t) const;

    // Motion.
    double free_substep() const;               // the substep free motion allows (see kLongestSubstep)
    bool turns_in_steps(std::size_t i) const;  // its free turn is integrated in steps (rotation.h)
    void move(Body* b, const Track& k, double dt) const;
    Mover mover(std::size_t i) const;
    void step(Mover* m, double dt) const;
    void drift(std::size_t i, double t);  // bodies_[i] to time t along its motion
    void set_free(std::size_t i);         // gravity only
    Vec gravity() const;

    // Broad phase (engine/broad_phase.h: a uniform grid rebuilt each substep; bodies
    // re-inserted after events).
    void build_grid(double t0, double t1);
    void insert(std::size_t i, double t0, double t1);
    void swept_box(std::size_t i, double t0, double t1, Vec* lo, Vec* hi) const;
    template <class F>
    void for_each_neighbour(std::size_t i, double t, F&& f) {
        grid_.for_each_neighbour(
            i, [&](Vec* lo, Vec* hi) { swept_box(i, t, loop_.substep_end, lo, hi); }, f);
    }

    // Narrow phase.
    Manifold manifold(std::size_t a, std::size_t b) const;  // both at the same time
    double normal_speed(std::size_t a, std::size_t b, const Vec& p, const Vec& n) const;
    double rest_speed(std::size_t i, std::size_t j) const;
    bool passed(std::size_t i, std::size_t j) const;  // let through by the page's listing
    // Their bounding circles (spheres), or one's and a plane, further apart than gap: they do
    // not touch within it. (Never for two planes.)
    bool apart(std::size_t a, std::size_t b, double gap) const;
    double friction_limit(std::size_t a, std::size_t b) const;

    // Prediction (the time of impact: engine/toi.h).
    double predict_pair(std::size_t i, std::size_t j, double t, double t1);
    void predict(std::size_t i, double t);

    // Welds (engine/weld.cpp).
    bool same_weld(std::size_t i, std::size_t j) const;
    void weld(std::size_t a, std::size_t b, double t);
    void unweld(std::size_t i);
    void weld_to(Weld* w, double t) const;  // its compound to time t
    void place(std::size_t i);              // bodies_[i] from its weld's compound
    Body* mobile(std::size_t i);            // what an impulse on body i moves: it or its compound
    void moved(std::size_t i);              // after mobile(i) changed: its members placed again

    // Contacts at one instant.
    void contacts_of(std::size_t i, double t, std::vector<Contact>* out);
    static std::uint32_t fresh(std::vector<std::uint32_t>* marks, std::uint32_t* counter);
    bool resolve(std::size_t i, std::size_t j, double t, std::vector<Event<D>>* events);  // true: an impact
    bool resolve_point(Contact* c, int k);
    void resolve_simultaneous(std::vector<Contact>* contacts);
    // An event of bodies a and b at t: their velocities now are its "after".
    void record(std::size_t a, std::size_t b, double t, const Vec& normal, const Vec& impulse, const Vec& point,
                const typename Event<D>::Velocity& before_a, const typename Event<D>::Velocity& before_b,
                std::vector<Event<D>>* events);
    void solve_points(std::vector<Contact>* contacts, const std::vector<PointGoal>& goals,
                      std::vector<Body>* state);  // the contact solver, on bodies not welded

    // Islands and sleeping (engine/islands.cpp).
    bool same_island(std::size_t i, std::size_t j) const;
    void settle(const std::vector<std::size_t>& reached, double t);
    void solve_island(std::vector<Contact>* contacts, const std::vector<std::size_t>& members, double t);

    // Stepped islands (engine/stepped.cpp).
    bool may_step(std::size_t i) const;
    // i and j meet only at steps: both stepped, or one stepped and one static.
    bool meet_at_steps(std::size_t i, std::size_t j) const {
        return (steps_.stepped[i] || steps_.stepped[j]) && (steps_.stepped[i] || bodies_[i].is_static) &&
               (steps_.stepped[j] || bodies_[j].is_static);
    }
    void join(std::size_t i, double t);                         // body i is stepped from t on (a step is taken at t)
    void wake(std::size_t i);                                   // a sleeping stepped body moves again (a step is taken)
    void count_impact(std::size_t a, std::size_t b, double t);  // stepping = auto's rule
    double surface_speed(std::size_t i) const;                  // |v| + |w| R
    // A step from t of every stepped body awake (all), or (a step taken again between two
    // steps, `within` a substep) of the islands of the bodies in steps_.reseed, predicted again.
    void step_islands(double t, std::vector<Event<D>>* events, bool within);

    RunCount runs_;  // counts this world among every run (run_count.h)
    Scene scene_;
    // Work beyond the counters (work_done()): bodies times substeps, rotation steps (turned in
    // const functions too: bodies_at(), the time of impact's copies).
    struct Work {
        std::uint64_t body_substeps = 0, rotation_steps = 0;
    };
    mutable Work work_;
    double estimate_ = 0.0;
    std::vector<Body> bodies_;
    std::vector<Track> track_;
    Counters counters_;

    // The bodies' shapes and what follows from them, fixed for the run (world.cpp: the narrow
    // phase and the motion bounds).
    struct Shapes {
        std::vector<Shape> of;
        std::vector<double> radius;          // bounding radius (m); 0 for planes
        std::vector<double> inv_min_moment;  // 1 / the smallest principal moment (spin bound)
        std::vector<bool> round;             // disc or sphere: turning does not move the surface
        std::vector<bool> plane;
    } shapes_;

    // The narrow phase's rules for a touching pair (world.cpp).
    struct Narrow {
        double rest_smooth = 0.0, rest_cornered = 0.0;  // m/s: rest_speed() of the two kinds
        std::unordered_set<std::uint64_t> passed;       // pairs (a << 32 | b, a < b) the listing answered
    } narrow_;

    BroadPhase<D> grid_;       // broad phase (broad_phase.h)
    ContactSolver<D> solver_;  // contact solver (contact_solver.h)

    // The event loop (advance.cpp): the substep, its predicted impacts, and an advance paused
    // inside it. An advance that ended inside a substep (time < substep_end) goes on with its
    // predictions (heap) from the event loop's instant `now`; bodies_now is every body at time
    // (bodies_ stay where the substep's events left each of them).
    struct EventLoop {
        double time = 0.0;
        double substep_end = 0.0;
        bool open = false;
        double now = 0.0;
        std::uint64_t pops_at_now = 0;
        std::vector<Body> bodies_now;
        std::vector<Pending> heap;
        double stall_time = -1.0;  // see advance_to()
        std::unordered_map<std::uint64_t, int> stalls;
        std::unordered_set<std::uint64_t> stalled;
    } loop_;

    // Per-body scratch of one instant's searches (resolve(), settle(), step_islands()), valid
    // where the stamp is current (fresh()).
    struct Scratch {
        std::vector<std::uint32_t> mark;  // reached / in the group / island member
        std::uint32_t mark_id = 0;
        std::vector<std::uint32_t> searched;  // contacts_of() ran for it in this search
        std::uint32_t search = 0;
        std::vector<std::size_t> parent;                  // union-find of settle() and step_islands()
        std::vector<typename Event<D>::Velocity> before;  // resolve(): velocities before
    } scratch_;

    // Islands and sleeping (islands.cpp).
    struct Islands {
        std::vector<std::uint32_t> of;  // per body: 0 free; else the id of its island solve
        std::vector<char> asleep;       // 1: its island sleeps (v, w, a, alpha exactly 0)
        std::unordered_map<std::uint32_t, std::vector<std::size_t>> members;
        std::uint32_t next_id = 1;
        std::vector<Body> later;  // solve_island's scratch: an island's bodies a step later
    } islands_;

    // Stuck bodies (weld.cpp).
    struct Welds {
        std::vector<Weld> all;  // (dissolved welds stay, with no members)
        std::vector<int> of;    // per body: index into all; -1: not welded
    } welds_;

    // Stepped islands (stepped.cpp).
    struct SteppedIslands {
        std::vector<char> stepped;  // 1: advances by time steps
        // 1: its motion is the last step's (a step taken again before its end gives back the
        // gravity impulse of the time left, see "Stepped islands").
        std::vector<char> solved;
        std::vector<double> until;  // s: the end of a solved body's step
        // Some body moves by exact events (not static, not stepped; awake or asleep): only then
        // do stepped bodies predict impacts (with those bodies: they meet the rest at their
        // steps). Set at each substep's start, and when a stepped body leaves its island.
        bool exact_bodies = true;
        bool restep = false;              // something joined, woke or was pushed: a step is taken now
        std::vector<std::size_t> reseed;  // ... these bodies: their islands are stepped again
        std::vector<double> still;        // s a stepped body has been slower than kStepSleepSpeed
        struct Rate {                     // a pair's recent collisions (count_impact)
            double since = 0.0;
            int count = 0;
        };
        std::unordered_map<std::uint64_t, Rate> rates;
        double end = -std::numeric_limits<double>::infinity();  // the present step's end
        IslandStepper<D> stepper;
    } steps_;
};

using World2 = World<2>;
using World3 = World<3>;
using Event2 = Event<2>;
using Event3 = Event<3>;

}  // namespace collide
