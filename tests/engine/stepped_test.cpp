// Stepped islands (engine/world.h, "Stepped islands"; engine/island_step.h): resting stacks
// that stay put, a pyramid that stands, a bin whose boxes do not sink into each other, a
// collision between stepped bodies that follows Newton's law, and impacts outside the stepped
// islands still resolved at their exact instants.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/world.h"
#include "tests/scenes/world_scenes.h"

namespace {

using namespace collide;
using namespace collide::scenes;

constexpr double kG = 9.81;

Scene stacked_scene(int dimension, int n, StepMode mode) {
    Scene s = empty_scene(dimension, Policy::simultaneous, 0.2);
    s.gravity = Vec3(0.0, -kG, 0.0);
    s.model = Model::coulomb;
    s.friction = 0.5;
    s.stepping = mode;
    if (dimension == 2) {
        s.bodies.push_back(half_plane("ground", Vec2(0.0, 1.0), 0.0));
        for (int i = 0; i < n; ++i)
            s.bodies.push_back(rectangle("b" + std::to_string(i), 0.4, 0.2, 1.0, Vec2(0.0, 0.1 + 0.2 * i)));
    } else {
        s.bodies.push_back(half_space("ground", Vec3(0.0, 1.0, 0.0), 0.0));
        for (int i = 0; i < n; ++i)
            s.bodies.push_back(box("b" + std::to_string(i), Vec3(0.2, 0.1, 0.15), 1.0, Vec3(0.0, 0.1 + 0.2 * i, 0.0)));
    }
    return s;
}

template <int D>
double energy(const World<D>& w) {
    return kinetic_energy(w.bodies()) + potential_energy(w.bodies(), w.scene().gravity);
}

// A column of boxes resting exactly on each other, stepped from the start (stepping = always),
// watched for 10 s. Closed form: nothing moves. Allowed: the split impulse leaves penetrations
// of up to kSlop (5e-5 m) alone, so each box may settle by that much per contact below it;
// 1e-4 m per box is asserted. Energy may only be lost (a settling of 1e-4 m is 1e-3 J per kg):
// no gain beyond 1e-12 of E0 (round-off).
template <int D>
void resting_column() {
    const int n = 6;
    const Scene s = stacked_scene(D, n, StepMode::always);
    World<D> w(s);
    const std::vector<typename World<D>::Body> start = w.bodies();
    const double E0 = energy(w);
    double worst_drift = 0.0, worst_gain = -1e300;
    for (int k = 1; k <= 100; ++k) {
        w.advance_to(0.1 * k, nullptr);
        for (int i = 1; i <= n; ++i)
            worst_drift = std::max(worst_drift, (w.bodies()[i].position - start[i].position).norm());
        worst_gain = std::max(worst_gain, energy(w) - E0);
    }
    EXPECT_GT(w.counters().steps, 0u) << "the column was never stepped";
    EXPECT_LE(worst_drift, 1e-4 * n) << "a resting box moved by " << worst_drift << " m";
    EXPECT_LE(worst_gain, 1e-12 * std::abs(E0)) << "energy gained at rest: " << worst_gain << " J";
    for (int i = 1; i <= n; ++i) EXPECT_TRUE(w.asleep(i)) << "box " << i << " still awake after 10 s";
    EXPECT_LE(deepest_overlap(s, w.bodies()), IslandStepper<D>::kSlop * 2) << "boxes sank into each other";
}

TEST(Stepped, RestingColumn2dStaysPutFor10s) { resting_column<2>(); }
TEST(Stepped, RestingColumn3dStaysPutFor10s) { resting_column<3>(); }

// Box2D's pyramid of 20 rows (210 boxes, Coulomb 0.6, e = 0) stepped from the start: it must
// stand. Every box stays within 1 mm of where it was built, nothing sinks deeper than 0.5 mm,
// and the pyramid falls asleep.
TEST(Stepped, PyramidOf20RowsStands) {
    Scene s = pyramid({});
    s.stepping = StepMode::always;
    World2 w(s);
    const std::vector<Body2> start = w.bodies();
    double worst_drift = 0.0, worst_overlap = 0.0;
    for (int k = 1; k <= 30; ++k) {
        w.advance_to(0.1 * k, nullptr);
        worst_overlap = std::max(worst_overlap, deepest_overlap(s, w.bodies()));
        for (std::size_t i = 0; i < start.size(); ++i)
            worst_drift = std::max(worst_drift, (w.bodies()[i].position - start[i].position).norm());
    }
    EXPECT_LE(worst_drift, 1e-3) << "a box of the pyramid moved " << worst_drift << " m";
    EXPECT_LE(worst_overlap, 5e-4);
    std::size_t awake = 0;
    for (std::size_t i = 0; i < start.size(); ++i) awake += !start[i].is_static && !w.asleep(i);
    EXPECT_EQ(awake, 0u) << "boxes still awake after 3 s";
}

// Boxes dropped into a bin (tests/scenes/world_scenes.h, 40 of them here to keep the test
// short; the benchmarks run 100 and 400) with the default stepping = auto: the piles become
// stepped, no two bodies overlap by more than 0.5 mm at any 1/60 s, every box stays inside
// the bin, and the heap comes to rest.
TEST(Stepped, BinOfBoxesPenetratesLessThanHalfAMillimetre) {
    BinSpec b;
    b.n = 40;
    const Scene s = bin(2, b);
    World2 w(s);
    const double W = bin_width(2, b);
    double worst = 0.0, worst_t = 0.0;
    for (int k = 1; k <= 240; ++k) {
        w.advance_to(k / 60.0, nullptr);
        const double d = deepest_overlap(s, w.bodies());
        if (d > worst) {
            worst = d;
            worst_t = w.time();
        }
    }
    EXPECT_GT(w.counters().joined, 0u) << "nothing was stepped";
    EXPECT_LE(worst, 5e-4) << "overlap of " << worst << " m at t = " << worst_t << " s";
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        if (s.bodies[i].is_static()) continue;
        const Vec2 x = w.bodies()[i].position;
        EXPECT_GT(x.x(), 0.0) << s.bodies[i].name;
        EXPECT_LT(x.x(), W) << s.bodies[i].name;
        EXPECT_GT(x.y(), 0.0) << s.bodies[i].name;
    }
    EXPECT_LE(fastest_surface_speed(s, w.bodies()), 0.05) << "the heap is still moving after 4 s";
}

// Two stepped boxes on a frictionless floor (stepping = always: both rest on it), the one
// sliding at 1 m/s into the other at rest, e = 0.5, equal masses. Their collision happens at a
// step's start with Newton's law on the approach speed: afterwards v = (0.25, 0.75) m/s
// (momentum kept, relative speed times e). Twelve Gauss-Seidel sweeps (island_step.h) leave
// 1e-5 m/s of the split between the two; 1e-4 m/s is asserted.
TEST(Stepped, CollisionBetweenSteppedBodiesFollowsNewtonsLaw) {
    Scene s = empty_scene(2, Policy::simultaneous, 0.5);
    s.gravity = Vec3(0.0, -kG, 0.0);
    s.model = Model::frictionless;
    s.stepping = StepMode::always;
    s.bodies.push_back(half_plane("floor", Vec2(0.0, 1.0), 0.0));
    s.bodies.push_back(rectangle("A", 0.2, 0.2, 1.0, Vec2(0.0, 0.1), 0.0, Vec2(1.0, 0.0)));
    s.bodies.push_back(rectangle("B", 0.2, 0.2, 1.0, Vec2(0.5, 0.1)));
    World2 w(s);
    w.advance_to(0.5, nullptr);
    ASSERT_TRUE(w.stepped(1) && w.stepped(2)) << "both boxes rest on the floor: stepped";
    const Body2& A = w.bodies()[1];
    const Body2& B = w.bodies()[2];
    EXPECT_NEAR(A.v.x() + B.v.x(), 1.0, 1e-12) << "momentum along the floor";
    EXPECT_NEAR(A.v.x(), 0.25, 1e-4);
    EXPECT_NEAR(B.v.x(), 0.75, 1e-4);
}

// An isolated impact in a scene with a stepped island is still found at its exact instant: a
// column of boxes is stepped (stepping = always) while two discs far away fly at each other
// (both fall alike, so their relative motion is uniform): they touch when their gap of
// 0.5002 m has closed at 2 m/s, at t = 0.2501 s, and leave with -e times the approach speed.
TEST(Stepped, IsolatedImpactBesideASteppedIslandIsExact) {
    Scene s = stacked_scene(2, 4, StepMode::always);
    s.model = Model::frictionless;
    s.bodies.push_back(disc("L", 0.1, 1.0, Vec2(5.0, 3.0), Vec2(1.0, 0.0)));
    s.bodies.push_back(disc("R", 0.1, 1.0, Vec2(5.7002, 3.0), Vec2(-1.0, 0.0)));
    World2 w(s);
    std::vector<Event2> events;
    bool stepped_then = false;
    w.advance_to(0.5, &events, [&](double t) {
        if (std::abs(t - 0.2501) < 1e-6) stepped_then = w.stepped(1) && w.stepped(4);
    });
    const std::size_t L = s.bodies.size() - 2, R = L + 1;
    const auto it = std::find_if(events.begin(), events.end(), [&](const Event2& e) { return e.a == L && e.b == R; });
    ASSERT_NE(it, events.end()) << "the discs never met";
    EXPECT_NEAR(it->t, 0.2501, 1e-12);
    EXPECT_NEAR(it->after_a.v.x(), -0.2, 1e-12);
    EXPECT_NEAR(it->after_b.v.x(), 0.2, 1e-12);
    EXPECT_TRUE(stepped_then) << "the column was not stepped at the discs' impact";
    EXPECT_GT(w.counters().steps, 0u);
}

// The tower of six boxes knocked by a ball (3D, stepping = auto). The ball's first impact is
// exact: the tower rests asleep, the ball flies ballistically and meets the fourth box's face
// x = -0.1 m when its centre reaches x = -0.18 m, at t = 0.62 / 4 = 0.155 s. Then the tower is
// stepped; nothing sinks deeper than 0.5 mm, no energy appears, and it comes to rest.
TEST(Stepped, TowerKnockedByABall) {
    const Scene s = tower3d({});
    World3 w(s);
    const double E0 = energy(w);
    std::vector<Event3> events;
    double worst_overlap = 0.0, worst_gain = -1e300;
    for (int k = 1; k <= 180; ++k) {
        w.advance_to(k / 60.0, &events);
        worst_overlap = std::max(worst_overlap, deepest_overlap(s, w.bodies()));
        worst_gain = std::max(worst_gain, energy(w) - E0);
    }
    const std::size_t ball = s.bodies.size() - 1;
    const auto first = std::find_if(events.begin(), events.end(), [&](const Event3& e) { return e.b == ball; });
    ASSERT_NE(first, events.end()) << "the ball never hit";
    EXPECT_EQ(first->a, 4u) << "the fourth box (0.3 to 0.4 m up) is body 4";
    EXPECT_NEAR(first->t, 0.155, 1e-9);
    EXPECT_GT(w.counters().joined, 0u);
    EXPECT_LE(worst_overlap, 5e-4);
    EXPECT_LE(worst_gain, 1e-9 * E0) << "energy appeared";
    std::vector<Body3> boxes = w.bodies();
    boxes.pop_back();  // the ball rolls on (no rolling resistance)
    Scene tower_only = s;
    tower_only.bodies.pop_back();
    EXPECT_LE(fastest_surface_speed(tower_only, boxes), 0.05) << "the boxes still move after 3 s";
}

// Where a run is sampled does not change it (engine/world.h, advance_to): the 3D tower and a
// 2D bin of 25 boxes (both stepped after their first impacts, both chaotic once they
// collapse: any difference grows), advanced to 1.5 s through samples every 0.01 s, every
// 1/30 s, and in one call, give the same events and the same final state, bit for bit.
template <int D>
void same_run_whatever_the_samples(const Scene& s) {
    using W = World<D>;
    const auto run = [&](double dt, std::vector<Event<D>>* events) {
        W w(s);
        const int n = dt > 0 ? static_cast<int>(std::lround(1.5 / dt)) : 1;
        for (int k = 1; k <= n; ++k) w.advance_to(k == n ? 1.5 : k * dt, events);
        EXPECT_GT(w.counters().joined, 0u) << "nothing was stepped";
        return w.bodies();
    };
    std::vector<Event<D>> e1, e2, e3;
    const auto b1 = run(0.01, &e1), b2 = run(1.0 / 30.0, &e2), b3 = run(0.0, &e3);
    ASSERT_GT(e1.size(), 10u);
    for (const auto* other : {&e2, &e3}) {
        ASSERT_EQ(e1.size(), other->size());
        for (std::size_t k = 0; k < e1.size(); ++k) {
            const Event<D>& a = e1[k];
            const Event<D>& b = (*other)[k];
            ASSERT_EQ(a.t, b.t) << "event " << k;
            ASSERT_EQ(a.a, b.a) << "event " << k;
            ASSERT_EQ(a.b, b.b) << "event " << k;
            ASSERT_EQ(a.impulse, b.impulse) << "event " << k << " at t = " << a.t;
        }
    }
    for (const auto* other : {&b2, &b3})
        for (std::size_t i = 0; i < b1.size(); ++i) {
            EXPECT_EQ(b1[i].position, (*other)[i].position) << s.bodies[i].name;
            EXPECT_EQ(b1[i].v, (*other)[i].v) << s.bodies[i].name;
            EXPECT_EQ(b1[i].w, (*other)[i].w) << s.bodies[i].name;
        }
}

TEST(Stepped, TheTowerIsTheSameRunWhateverItsSamples) { same_run_whatever_the_samples<3>(tower3d({})); }

TEST(Stepped, TheBinIsTheSameRunWhateverItsSamples) {
    BinSpec b;
    b.n = 25;
    same_run_whatever_the_samples<2>(bin(2, b));
}

}  // namespace
