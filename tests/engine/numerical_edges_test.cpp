// Numerical edges: near-zero approach speeds, grazing contacts, mass ratios from 1e-6 to 1e6, a
// thin rod with near-singular inertia, huge and tiny scales, far from the origin. Each ends in a
// finite result that matches the closed form (or the same collision at scale 1) within the
// stated tolerance; the limits are documented in docs/tests.md ("Numerical limits").
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/rotation.h"
#include "engine/run_error.h"
#include "engine/world.h"
#include "engine/world1d.h"
#include "tests/scenes/world_scenes.h"

namespace collide {
namespace {

using scenes::disc;
using scenes::empty_scene;

template <int D>
std::vector<Event<D>> run(const Scene& s, double t) {
    World<D> w(s);
    std::vector<Event<D>> events;
    w.advance_to(t, &events);
    for (const auto& b : w.bodies()) {
        EXPECT_TRUE(b.position.allFinite());
        EXPECT_TRUE(b.v.allFinite());
    }
    return events;
}

// ---- Mass ratios ---------------------------------------------------------------------------

// Head-on, e = 1, B at rest: va' = (ma - mb) / (ma + mb) va, vb' = 2 ma / (ma + mb) va. Both
// worlds, every ratio from 1e-6 to 1e6; momentum and energy kept to 1e-12 of their size.
TEST(NumericalEdges, MassRatiosFromOneMillionthToOneMillion) {
    for (double ratio : {1e-6, 1e-3, 1.0, 1e3, 1e6}) {
        SCOPED_TRACE(ratio);
        const double ma = ratio, mb = 1.0, va = 2.0;
        const double va_after = (ma - mb) / (ma + mb) * va, vb_after = 2 * ma / (ma + mb) * va;
        Scene line;
        line.dimension = 1;
        line.restitution = 1.0;
        SceneBody a, b;
        a.name = "a";
        a.shape = b.shape = "block";
        a.length = b.length = 0.2;
        a.body1 = Body1{ma, false, 0.0, va};
        b.name = "b";
        b.body1 = Body1{mb, false, 0.5, 0.0};
        line.bodies = {a, b};
        World1 w1(line);
        std::vector<Event1> e1;
        w1.advance_to(1.0, &e1);
        ASSERT_EQ(e1.size(), 1u);
        EXPECT_NEAR(e1[0].va_after, va_after, 1e-12 * va);
        EXPECT_NEAR(e1[0].vb_after, vb_after, 1e-12 * va);

        Scene s = empty_scene(2);
        s.bodies = {disc("a", 0.1, ma, Vec2(0, 0), Vec2(va, 0)), disc("b", 0.1, mb, Vec2(0.5, 0))};
        const auto e2 = run<2>(s, 1.0);
        ASSERT_EQ(e2.size(), 1u);
        EXPECT_NEAR(e2[0].after_a.v.x(), va_after, 1e-12 * va);
        EXPECT_NEAR(e2[0].after_b.v.x(), vb_after, 1e-12 * va);
        const double p0 = ma * va, e0 = 0.5 * ma * va * va;
        const double p1 = ma * e2[0].after_a.v.x() + mb * e2[0].after_b.v.x();
        const double k1 = 0.5 * ma * e2[0].after_a.v.squaredNorm() + 0.5 * mb * e2[0].after_b.v.squaredNorm();
        EXPECT_NEAR(p1, p0, 1e-12 * std::max(p0, mb * va));
        EXPECT_NEAR(k1, e0, 1e-12 * std::max(e0, mb * va * va));
    }
}

// ---- Near-zero approach speed and grazing contacts -------------------------------------------

// Discs closing at 1e-9 m/s over a 1e-9 m gap: they meet at t = 1 s (within kTouch / 1e-9 m/s
// = 0.1 s: a substep that starts with them closer than kTouch takes them for touching) and,
// equal masses and e = 1, exchange velocities exactly. Rectangles face to face closing at 1e-7 m/s (e = 0.5,
// both corners at once): no spin, and the centres part at u_n' = -e u_n to 1e-12 of it.
TEST(NumericalEdges, NearZeroApproachSpeed) {
    Scene s = empty_scene(2);
    s.bodies = {disc("a", 0.1, 1.0, Vec2(0, 0), Vec2(1e-9, 0)), disc("b", 0.1, 1.0, Vec2(0.2 + 1e-9, 0))};
    const auto e = run<2>(s, 2.0);
    ASSERT_EQ(e.size(), 1u);
    EXPECT_NEAR(e[0].t, 1.0, World2::kTouch / 1e-9);
    EXPECT_NEAR(e[0].after_a.v.x(), 0.0, 1e-21);
    EXPECT_NEAR(e[0].after_b.v.x(), 1e-9, 1e-21);

    Scene r = empty_scene(2, Policy::simultaneous, 0.5);  // both points of the faces at once
    r.bodies = {scenes::rectangle("a", 0.2, 0.1, 1.0, Vec2(0, 0), 0.0, Vec2(1e-7, 0)),
                scenes::rectangle("b", 0.2, 0.1, 2.0, Vec2(0.2 + 1e-8, 0.0))};
    const auto f = run<2>(r, 1.0);
    ASSERT_GE(f.size(), 1u);
    const double un_before = f[0].before_b.v.dot(f[0].normal) - f[0].before_a.v.dot(f[0].normal);
    const double un_after = f[0].after_b.v.dot(f[0].normal) - f[0].after_a.v.dot(f[0].normal);
    EXPECT_NEAR(un_before, -1e-7, 1e-19);  // face to face: no lever arm, no spin
    EXPECT_NEAR(un_after, 0.5e-7, 1e-19);
}

// Discs passing with centre offset 2r (1 - 1e-9): they just touch, the normal nearly at right
// angles to the motion. Closed form (equal masses, e = 1, b at rest): the normal
// n = (dx, dy) / 2r at contact, b leaves with (v . n) n and a keeps the rest; energy kept.
// With offset 2r (1 + 1e-9) they miss.
TEST(NumericalEdges, GrazingContactTouchesOrMissesByOnePartInABillion) {
    const double r = 0.1, v = 1.0;
    for (double sign : {-1.0, 1.0}) {
        const double offset = 2 * r * (1 + sign * 1e-9);
        Scene s = empty_scene(2);
        s.bodies = {disc("a", r, 1.0, Vec2(0, 0), Vec2(v, 0)), disc("b", r, 1.0, Vec2(1.0, offset))};
        const auto e = run<2>(s, 2.0);
        if (sign > 0) {
            EXPECT_TRUE(e.empty());
            continue;
        }
        ASSERT_EQ(e.size(), 1u);
        const double dy = offset, dx = std::sqrt(4 * r * r - dy * dy);
        const Vec2 n(dx / (2 * r), dy / (2 * r));
        EXPECT_NEAR((e[0].normal - n).norm(), 0.0, 1e-6);  // n.x = 4.5e-5: the contact found to 1e-10 m
        const Vec2 vb = v * n.x() * n;
        EXPECT_NEAR((e[0].after_b.v - vb).norm(), 0.0, 1e-9);
        EXPECT_NEAR((e[0].after_a.v - (Vec2(v, 0) - vb)).norm(), 0.0, 1e-9);
        EXPECT_NEAR(e[0].after_a.v.squaredNorm() + e[0].after_b.v.squaredNorm(), v * v, 1e-12);
    }
}

// ---- Thin rod ------------------------------------------------------------------------------

// A rod 1 m long and 2 um thick: its inertia about its own axis is 4e-12 of the others
// (near-singular), hit across its top face by a sphere 0.4 m from its centre, e = 1. Closed
// form: j = (1 + e) u / (1/m_s + 1/m_r + arm^2 / I_zz), I_zz = m (L^2 + t^2) / 12; the arm has
// no part along the rod, so the inverse of the tiny axial inertia must bring nothing (no NaN,
// no spin about the axis); energy kept to 1e-12.
TEST(NumericalEdges, ThinRodWithNearSingularInertia) {
    const double L = 1.0, t = 2e-6, mr = 1.0, ms = 0.5, u = 1.0;
    Scene s = empty_scene(3);
    s.bodies.push_back(scenes::box("rod", Vec3(L / 2, t / 2, t / 2), mr, Vec3(0, 0, 0)));
    s.bodies.push_back(scenes::sphere("ball", 0.05, ms, Vec3(0.4, 0.3, 0), Vec3(0, -u, 0)));
    World<3> w(s);
    const double e0 = totals(w.bodies()).kinetic_energy;
    std::vector<Event<3>> events;
    w.advance_to(0.5, &events);
    ASSERT_GE(events.size(), 1u);
    const double Izz = mr * (L * L + t * t) / 12, arm = 0.4;
    const double j = 2 * u / (1 / ms + 1 / mr + arm * arm / Izz);
    EXPECT_NEAR(events[0].impulse.norm(), j, 1e-9 * j);
    EXPECT_NEAR(events[0].after_a.w.x(), 0.0, 1e-9);  // the rod (body 0): no spin about its axis
    EXPECT_NEAR(totals(w.bodies()).kinetic_energy, e0, 1e-12 * e0);
}

// The same rod 0.2 mm thick and turned 0.3 rad about its axis: the sphere now strikes an edge
// of its square section, 0.1 mm off the axis, and that lever about the tiny axial inertia spins
// it at thousands of rad/s: the physics of a rigid thin bar, not an error. The impulse is the
// closed form with the event's own contact point and the full inverse inertia tensor,
// j = (1 + e) u_n / (1/m_s + 1/m_r + (r x n) . I^-1 (r x n)), and the fast spin is turned in
// substeps of 0.005 rad with its energy kept to 1e-9 over the 0.5 s (about 4 x 10^5 substeps).
TEST(NumericalEdges, ThinRodStruckOnAnEdgeSpinsFastAboutItsAxis) {
    const double L = 1.0, t = 2e-4, mr = 1.0, ms = 0.5, u = 1.0;
    Scene s = empty_scene(3);
    const Quat q(Eigen::AngleAxisd(0.3, Vec3::UnitX()));
    s.bodies.push_back(scenes::box("rod", Vec3(L / 2, t / 2, t / 2), mr, Vec3(0, 0, 0), q));
    s.bodies.push_back(scenes::sphere("ball", 0.05, ms, Vec3(0.4, 0.3, 0), Vec3(0, -u, 0)));
    World<3> w(s);
    const Body3 rod0 = w.bodies()[0];
    const double e0 = totals(w.bodies()).kinetic_energy;
    std::vector<Event<3>> events;
    w.advance_to(0.5, &events);
    ASSERT_GE(events.size(), 1u);
    const Event<3>& ev = events[0];
    const Vec3 n = ev.normal;                 // from a (the rod) into b (the ball)
    const Vec3 r = ev.point - rod0.position;  // the rod sat still until then
    const Vec3 rn = r.cross(n);
    const double un = -ev.before_b.v.dot(n);  // the ball's approach along n (the rod at rest)
    const double j = 2 * un / (1 / ms + 1 / mr + rn.dot(rod0.inv_inertia_world() * rn));
    EXPECT_NEAR(ev.impulse.norm(), j, 1e-9 * j);
    const double axial = ev.after_a.w.dot(q * Vec3::UnitX());
    EXPECT_GT(std::abs(axial), 1e3);  // rad/s
    EXPECT_TRUE(std::isfinite(axial));
    for (const Body3& b : w.bodies()) EXPECT_TRUE(b.orientation.coeffs().allFinite());
    EXPECT_NEAR(totals(w.bodies()).kinetic_energy, e0, 1e-9 * e0);
    RecordProperty("axial_spin_rad_per_s", std::to_string(axial));
}

// ---- Scales and distance from the origin -----------------------------------------------------

// Two turned rectangles, one spinning, colliding (e = 1): the same collision in units scaled
// by s gives t the same and impulse, point and speeds scaled by s. The contact is found to an
// absolute 1e-10 m, so the agreement is about 1e-10 m / size: 1e-6 relative for bodies of
// 0.1 mm and up; bodies of 1 um (the smallest a scenario file accepts) still agree to 1e-3.
struct Hit {
    double t;
    Vec2 impulse, point;
};

Hit box_pair(double s, double far = 0.0) {
    Scene sc = empty_scene(2);
    sc.bodies.push_back(scenes::rectangle("a", 0.2 * s, 0.1 * s, 1.0, Vec2(far, 0), 0.3, Vec2(s, 0), 0.5));
    sc.bodies.push_back(scenes::rectangle("b", 0.2 * s, 0.1 * s, 2.0, Vec2(far + 0.6 * s, 0.02 * s), -0.2));
    const auto e = run<2>(sc, 1.0);
    EXPECT_GE(e.size(), 1u);
    if (e.empty()) return {0, Vec2::Zero(), Vec2::Zero()};
    return {e[0].t, e[0].impulse / s, (e[0].point - Vec2(far, 0)) / s};
}

TEST(NumericalEdges, HugeAndTinyScalesGiveTheSameCollision) {
    const Hit one = box_pair(1.0);
    for (double s : {1e-5, 1e-3, 1e3, 1e6, 1e9, 1e12}) {
        SCOPED_TRACE(s);
        const Hit h = box_pair(s);
        const double tol = s < 1e-4 ? 1e-3 : 1e-6;
        EXPECT_NEAR(h.t, one.t, tol * one.t);
        EXPECT_NEAR((h.impulse - one.impulse).norm(), 0.0, tol * one.impulse.norm());
        EXPECT_NEAR((h.point - one.point).norm(), 0.0, tol * 0.2);
    }
}

// Far from the origin a position keeps fewer digits (its last bit is 1.2e-7 m at 1e9 m, 1.2e-4 m
// at 1e12 m, the largest a file accepts): the result degrades by about that / the body's size,
// never to NaN.
TEST(NumericalEdges, FarFromTheOriginTheCollisionDegradesGracefully) {
    const Hit one = box_pair(1.0);
    for (double far : {1e6, 1e9, 1e12}) {
        SCOPED_TRACE(far);
        const Hit h = box_pair(1.0, far);
        const double tol = 1e4 * far * 1e-16 / 0.1;  // 10^4 ulps of the position, per body size
        EXPECT_NEAR(h.t, one.t, tol * one.t);
        EXPECT_NEAR((h.impulse - one.impulse).norm(), 0.0, tol * one.impulse.norm());
    }
}

// ---- No state that is not finite leaves a world ---------------------------------------------

// Checks that f throws RunError whose message holds every piece of `names`.
template <class F>
void expect_run_error(F f, const std::vector<std::string>& names) {
    try {
        f();
        ADD_FAILURE() << "no RunError";
    } catch (const RunError& e) {
        for (const std::string& n : names) EXPECT_NE(std::string(e.what()).find(n), std::string::npos) << e.what();
    }
}

// A body flying at 1e308 m/s from 1.79e308 m leaves the doubles (DBL_MAX = 1.798e308) within
// its first 0.01 s (1000 substeps of 1e-5 s, each 1e303 m further): each world stops there with
// RunError naming the body and the instant (2D, 3D: when its swept box leaves the doubles, a
// substep before its state would), instead of returning an infinite state or sizing a grid
// without end.
TEST(NumericalEdges, AStateThatOverflowsStopsTheRunNamingBodyAndInstant) {
    {
        Scene s = empty_scene(2);
        s.bodies.push_back(disc("runaway", 0.1, 1.0, Vec2(1.79e308, 0.0), Vec2(1e308, 0.0)));
        World2 w(s);
        std::vector<Event2> events;
        expect_run_error([&] { w.advance_to(0.01, &events); }, {"'runaway'", "t = "});
    }
    {
        Scene s = empty_scene(3);
        s.bodies.push_back(scenes::sphere("runaway", 0.1, 1.0, Vec3(1.79e308, 0, 0), Vec3(1e308, 0, 0)));
        World3 w(s);
        std::vector<Event3> events;
        expect_run_error([&] { w.advance_to(0.01, &events); }, {"'runaway'", "t = "});
    }
    {
        Scene s = empty_scene(1);
        SceneBody b;
        b.name = "runaway";
        b.shape = "block";
        b.length = 0.1;
        b.body1 = Body1{1.0, false, 1.79e308, 1e308};
        s.bodies.push_back(b);
        World1 w(s);
        std::vector<Event1> events;
        expect_run_error([&] { w.advance_to(1.0, &events); }, {"'runaway'", "no longer finite"});
    }
}

// A free rotation's step count is a 64-bit count: one of more than 2^31 steps (a 3D spin of
// 1.07e9 rad/s over a 0.01 s substep) overflowed an int and became one giant step, NaN.
// Beyond 2^53 steps (here 1e12 rad/s for 1000 s at 1e-6 rad a step: 1e21) it is refused.
TEST(NumericalEdges, AFreeRotationOfTooManyStepsIsRefusedNotNaN) {
    Body3 b;
    b.inertia = Vec3(1.0, 2.0, 3.0).asDiagonal();
    b.w = Vec3(1e12, 1.0, 0.0);
    RotationSettings fine;
    fine.max_angle_per_step = 1e-6;
    expect_run_error([&] { rotate_free(&b, 1000.0, fine); }, {"steps"});
    // Below that, the count it reports is the turn over the step length: 2048 rad at 2^-7 rad.
    Body3 c = b;
    c.w = Vec3(2048.0, 0.0, 0.0);
    RotationSettings coarse;
    coarse.max_angle_per_step = 0x1p-7;
    EXPECT_EQ(rotate_free(&c, 1.0, coarse), 262144u);
    EXPECT_TRUE(c.state_finite());
}

// ---- Runs without end are refused: the work budget -------------------------------------------

// A free box spinning at 2.2e9 rad/s (the spin that once printed NaN) and one at 1e6 rad/s for
// 1 s (92 s of work): each world refuses before it starts, from its estimate. Free rotation
// keeps E and L, so |w| >= 2E/|L|; at 0.005 rad a step the estimate for the second is 2e8.
TEST(NumericalEdges, AFreeSpinBeyondTheWorkBudgetIsRefusedBeforeItStarts) {
    Scene s = empty_scene(3);
    s.duration = 0.01;
    s.bodies.push_back(scenes::box("box", Vec3(0.5, 1.0, 1.5), 1.0, Vec3::Zero(), Quat::Identity(), Vec3::Zero(),
                                   Vec3(2e9, 1e9, 0.0)));
    expect_run_error([&] { World3 w(s); }, {"units of work", "budget of 1e+08", "--max-work"});
    s.duration = 1.0;
    s.bodies[0].body3.w = Vec3(1e6, 1.0, 0.0);
    expect_run_error([&] { World3 w(s); }, {"about 2e+08 units of work"});
    s.work_budget = 1e9;
    const World3 allowed(s);
    // (and 1000 substeps of 1 ms, the shortest a spin makes: 1000 more)
    EXPECT_NEAR(allowed.work_estimate(), 2e8 + 1e3, 1e-6 * 2e8);
}

// A ball bouncing for ever (e = 1) under gravity may not be estimated before it runs (under
// gravity bodies may come to rest and cost nothing): each world counts its work and stops the
// run once it passes the budget, naming the instant and the rate. 2D, 3D and 1D; the budget
// is passed by at most one substep's work.
TEST(NumericalEdges, ABounceWithoutEndIsStoppedAtItsWorkBudget) {
    const Vec3 g(0.0, -9.81, 0.0);
    {
        Scene s = empty_scene(2, Policy::sequential, 1.0, g);
        s.duration = 1e9;
        s.work_budget = 1e5;
        s.bodies.push_back(scenes::half_plane("ground", Vec2(0, 1), 0.0));
        s.bodies.push_back(disc("ball", 0.1, 1.0, Vec2(0.0, 1.0)));
        World2 w(s);
        std::vector<Event2> events;
        expect_run_error([&] { w.advance_to(s.duration, &events); }, {"units of work by t = ", "budget of 100000"});
        EXPECT_LE(w.work_done(), 100010u);
        EXPECT_GT(events.size(), 30u);  // it did bounce (every 0.9 s; about 2 units a 1 ms substep)
    }
    {
        Scene s = empty_scene(3, Policy::sequential, 1.0, g);
        s.duration = 1e9;
        s.work_budget = 1e5;
        s.bodies.push_back(scenes::half_space("ground", Vec3(0, 1, 0), 0.0));
        s.bodies.push_back(scenes::sphere("ball", 0.1, 1.0, Vec3(0.0, 1.0, 0.0)));
        World3 w(s);
        std::vector<Event3> events;
        expect_run_error([&] { w.advance_to(s.duration, &events); }, {"units of work by t = "});
        EXPECT_LE(w.work_done(), 100010u);
    }
    {
        Scene s = empty_scene(1, Policy::sequential, 1.0, Vec3(-9.81, 0.0, 0.0));  // 1D: along x
        s.duration = 1e9;
        s.work_budget = 1e4;
        SceneBody ground, ball;
        ground.name = "ground", ball.name = "ball";
        ground.shape = ball.shape = "block";
        ground.length = 1.0, ball.length = 0.2;
        ground.body1 = Body1{1.0, true, -0.5, 0.0};
        ball.body1 = Body1{1.0, false, 1.0, 0.0};
        s.bodies = {ground, ball};
        World1 w(s);
        std::vector<Event1> events;
        expect_run_error([&] { w.advance_to(s.duration, &events); }, {"units of work by t = "});
        EXPECT_LE(w.work_done(), 10001u + 2u);
    }
}

// Under gravity the estimate is not made; a spin of 3e9 rad/s would turn 6e8 steps in its
// first millisecond substep: refused before the first of them, not after minutes.
TEST(NumericalEdges, ATurnBeyondWhatTheBudgetHasLeftIsRefusedBeforeItIsTaken) {
    Scene s = empty_scene(3, Policy::sequential, 1.0, Vec3(0.0, -9.81, 0.0));
    s.file = "spin.toml";
    s.bodies.push_back(scenes::box("box", Vec3(0.5, 1.0, 1.5), 1.0, Vec3::Zero(), Quat::Identity(), Vec3::Zero(),
                                   Vec3(3e9, 0.0, 1.0)));
    World3 w(s);
    EXPECT_EQ(w.work_estimate(), 0.0);
    std::vector<Event3> events;
    expect_run_error([&] { w.advance_to(0.1, &events); }, {"spin.toml: ", "work budget"});
    EXPECT_LT(w.work_done(), 1000u);
}

}  // namespace
}  // namespace collide
