// The 2D world (engine/world.h) against closed forms and conservation laws: free flight, impact
// times, velocity exchange, bounce series and their accumulation time, Newton's cradle under
// both policies, resting and landing rectangles, determinism, an elastic gas in a walled box.
//
// Every tolerance is stated where it is used. Two recurring ones:
//   round-off (1e-12 relative): closed-form motion and single impulses, a few operations deep;
//   1e-9 s / 1e-9 m: impact times and positions, which the world finds to kTouch = 1e-10 m
//     (for discs in closed form, for polygons by conservative advancement: a gap of at most
//     1e-10 m at speeds of order 1 m/s is 1e-10 s).
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/world.h"
#include "tests/scenes/world_scenes.h"

namespace collide {
namespace {

using namespace scenes;

constexpr double kG = 9.81;

Scene plane_scene(Policy policy, double e, double g = kG) {
    Scene s = empty_scene(2, policy, e, Vec3(0.0, -g, 0.0));
    s.bodies.push_back(half_plane("ground", Vec2(0, 1), 0.0));
    return s;
}

// ---- 1. Projectile ----------------------------------------------------------------------------

// A disc alone under gravity: x(t) = x0 + v0 t + g t^2/2, v(t) = v0 + g t, angle0 + w t, w kept.
// Tolerance 1e-12 relative to the size of the terms (round-off of a closed-form evaluation).
TEST(World2d, ProjectileFollowsTheParabola) {
    const Vec2 g(0.0, -kG), x0(1.5, 2.0), v0(3.0, 4.0);
    const double w0 = 2.5, angle0 = 0.3;
    Scene s = empty_scene(2, Policy::sequential, 1.0, Vec3(g.x(), g.y(), 0.0));
    s.bodies.push_back(disc("ball", 0.1, 2.0, x0, v0, w0, angle0));
    World2 w(s);
    std::vector<Event2> events;
    for (int k = 1; k <= 20; ++k) {
        const double t = 0.1 * k;
        w.advance_to(t, &events);
        const Body2& b = w.bodies()[0];
        const double scale = x0.norm() + v0.norm() * t + 0.5 * g.norm() * t * t;
        EXPECT_LE((b.position - (x0 + v0 * t + 0.5 * g * t * t)).norm(), 1e-12 * scale) << t;
        EXPECT_LE((b.v - (v0 + g * t)).norm(), 1e-12 * (v0.norm() + g.norm() * t)) << t;
        EXPECT_NEAR(b.angle, angle0 + w0 * t, 1e-12 * (angle0 + w0 * t)) << t;
        EXPECT_EQ(b.w, w0);
    }
    EXPECT_TRUE(events.empty());
    EXPECT_DOUBLE_EQ(w.time(), 2.0);
}

// ---- 4. Impact times and the elastic exchange ----------------------------------------------------

// Two equal discs on the line through their centres (direction n), gap d, closing speed u:
// contact at t = d/u exactly; e = 1, equal masses: the normal velocities are exchanged, the
// impulse on B is m u n (j = -(1 + e) un / (2/m), un = -u), spins (frictionless, central) kept.
TEST(World2d, TwoDiscsMeetAtGapOverSpeedAndExchange) {
    const double r = 0.1, m = 1.5, d = 0.7;
    const Vec2 n(std::cos(0.6), std::sin(0.6));
    const Vec2 va = 1.25 * n, vb = -0.5 * n;  // u = 1.75 m/s
    const double u = 1.75, t_hit = d / u;
    Scene s = empty_scene(2, Policy::sequential, 1.0);
    s.bodies.push_back(disc("a", r, m, Vec2::Zero(), va, 1.0));
    s.bodies.push_back(disc("b", r, m, (2 * r + d) * n, vb, -2.0));
    World2 w(s);
    const Totals2 before = totals(w.bodies());
    std::vector<Event2> events;
    w.advance_to(2.0, &events);
    ASSERT_EQ(events.size(), 1u);
    const Event2& ev = events[0];
    EXPECT_NEAR(ev.t, t_hit, 1e-9);  // s
    EXPECT_EQ(ev.a, 0u);
    EXPECT_EQ(ev.b, 1u);
    EXPECT_LE((ev.normal - n).norm(), 1e-12);
    EXPECT_LE((ev.point - (va * t_hit + r * n)).norm(), 1e-9);  // m: where the surfaces meet
    EXPECT_LE((ev.impulse - m * u * n).norm(), 1e-12 * m * u);  // N s, round-off
    EXPECT_LE((ev.after_a.v - vb).norm(), 1e-12 * u);
    EXPECT_LE((ev.after_b.v - va).norm(), 1e-12 * u);
    EXPECT_NEAR(ev.after_a.w, 1.0, 1e-12);  // frictionless, central: spins kept (round-off)
    EXPECT_NEAR(ev.after_b.w, -2.0, 1e-12);
    EXPECT_LE((w.bodies()[0].v - vb).norm(), 1e-12 * u);
    EXPECT_LE((w.bodies()[1].v - va).norm(), 1e-12 * u);
    // Momentum and energy: 1e-12 relative (one impulse, round-off).
    const Totals2 after = totals(w.bodies());
    EXPECT_LE((after.momentum - before.momentum).norm(), 1e-12 * m * u);
    EXPECT_NEAR(after.kinetic_energy, before.kinetic_energy, 1e-12 * before.kinetic_energy);
}

// A disc dropped from rest with its lowest point H above the ground: it lands at T = sqrt(2H/g)
// at speed U = g T. With restitution e a bounce leaves at e^k U and returns 2 e^k U / g = 2 e^k T
// later: t_k = T (1 + 2e + ... + 2e^(k-1)), landing speeds e^(k-1) U. e = 1: T (1, 3, 5, ...).
// Times to 1e-9 s, speeds to 1e-9 m/s (closed-form roots; round-off accumulates over bounces).
void expect_bounce_series(double e, int bounces) {
    const double H = 1.0, r = 0.1, T = std::sqrt(2 * H / kG), U = kG * T;
    Scene s = plane_scene(Policy::sequential, e);
    s.bodies.push_back(disc("ball", r, 1.0, Vec2(0.3, H + r), Vec2::Zero(), 0.7));
    World2 w(s);
    std::vector<double> t(bounces), speed(bounces);
    double tk = T, uk = U;
    for (int k = 0; k < bounces; ++k) {
        t[k] = tk;
        speed[k] = uk;
        uk *= e;
        tk += 2 * uk / kG;
    }
    std::vector<Event2> events;
    w.advance_to(t.back() + 0.5 * uk / kG, &events);  // half way up after the last bounce
    ASSERT_EQ(events.size(), static_cast<std::size_t>(bounces)) << "e = " << e;
    for (int k = 0; k < bounces; ++k) {
        const Event2& ev = events[k];
        EXPECT_NEAR(ev.t, t[k], 1e-9) << "e = " << e << ", bounce " << k;
        EXPECT_EQ(ev.a, 0u);
        EXPECT_EQ(ev.b, 1u);
        EXPECT_LE((ev.normal - Vec2(0, 1)).norm(), 1e-12);
        EXPECT_NEAR(ev.before_b.v.y(), -speed[k], 1e-9) << "bounce " << k;
        EXPECT_NEAR(ev.after_b.v.y(), e * speed[k], 1e-9) << "bounce " << k;
        EXPECT_NEAR(ev.after_b.v.x(), 0.0, 1e-12);
        EXPECT_NEAR(ev.after_b.w, 0.7, 1e-12);  // frictionless, central: the spin is kept
        // Impulse on the ball: (1 + e) m (landing speed), up (round-off of one formula).
        EXPECT_NEAR(ev.impulse.y(), -(1 + e) * ev.before_b.v.y(), 1e-12 * speed[0]);
    }
}

TEST(World2d, ElasticBounceTimesAreOddMultiples) { expect_bounce_series(1.0, 6); }
TEST(World2d, InelasticBounceTimesFollowTheGeometricSeries) { expect_bounce_series(0.5, 8); }

// ---- 5. The bounce series accumulates: the ball rests ---------------------------------------------

// The landings t_k = T (1 + 2e + ... + 2e^(k-1)) accumulate at T (1 + e)/(1 - e). The world
// merges the bounces that would land within kZenoTime (1e-12 s), so the last event lies within
// 1e-9 s of the accumulation time; from then on the ball lies on the ground (centre r above it,
// 1e-9 m), at rest (1e-9 m/s), held by a resting contact, with no further events.
TEST(World2d, BouncingBallRestsAtTheAccumulationTime) {
    for (double e : {0.5, 0.8}) {
        const double H = 1.0, r = 0.1, T = std::sqrt(2 * H / kG);
        const double t_rest = T * (1 + e) / (1 - e);
        Scene s = plane_scene(Policy::sequential, e);
        s.bodies.push_back(disc("ball", r, 1.0, Vec2(0.3, H + r)));
        World2 w(s);
        std::vector<Event2> events;
        w.advance_to(t_rest + 0.01, &events);
        ASSERT_FALSE(events.empty());
        EXPECT_NEAR(events.back().t, t_rest, 1e-9) << "e = " << e;
        const std::size_t n = events.size();
        for (int k = 1; k <= 200; ++k) {  // 2 s more, checked every 0.01 s
            w.advance_to(t_rest + 0.01 + 0.01 * k, &events);
            const Body2& b = w.bodies()[1];
            ASSERT_NEAR(b.position.y(), r, 1e-9) << "e = " << e << ", t = " << w.time();
            ASSERT_NEAR(b.position.x(), 0.3, 1e-12);
            ASSERT_LE(b.v.norm(), 1e-9) << "e = " << e << ", t = " << w.time();
        }
        EXPECT_EQ(events.size(), n) << "e = " << e << ": events after the ball came to rest";
        EXPECT_TRUE(w.resting(1)) << "e = " << e;
    }
}

// ---- 6. Newton's cradle ------------------------------------------------------------------------

// Ball 1 arrives at v on balls 2 and 3, which touch; equal masses, e = 1, no gravity.
// Sequential (pair 1-2, then 2-3): (0, 0, v). Simultaneous: K = [[2, -1], [-1, 2]]/m and
// K P = (2v, 0) (contact 1-2 leaves at v, 2-3 at 0) give P = (4v/3, 2v/3) m, velocities
// (-v/3, 2v/3, 2v/3). Both conserve momentum
// and energy. Radii and positions are binary fractions, so 2 and 3 touch exactly.
// Tolerance 1e-12 v (round-off of the impulses; the simultaneous solve converges to round-off).
Scene cradle2(Policy policy, double v) {
    const double r = 0.125;
    Scene s = empty_scene(2, policy, 1.0);
    s.bodies.push_back(disc("1", r, 1.0, Vec2(-0.5, 0.0), Vec2(v, 0.0)));
    s.bodies.push_back(disc("2", r, 1.0, Vec2(0.0, 0.0)));
    s.bodies.push_back(disc("3", r, 1.0, Vec2(2 * r, 0.0)));
    return s;
}

void expect_cradle2(Policy policy, const Vec3& expected_over_v) {
    const double v = 2.0;
    World2 w(cradle2(policy, v));
    const Totals2 before = totals(w.bodies());
    std::vector<Event2> events;
    w.advance_to(0.3, &events);  // contact at (0.5 - 0.25)/v = 0.125 s
    ASSERT_FALSE(events.empty());
    EXPECT_NEAR(events.front().t, 0.125, 1e-9);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(w.bodies()[i].v.x(), expected_over_v[i] * v, 1e-12 * v)
            << policy_name(policy) << ", ball " << i + 1;
        EXPECT_NEAR(w.bodies()[i].v.y(), 0.0, 1e-12 * v);
    }
    const Totals2 after = totals(w.bodies());
    EXPECT_LE((after.momentum - before.momentum).norm(), 1e-12 * v);
    EXPECT_NEAR(after.kinetic_energy, before.kinetic_energy, 1e-12 * before.kinetic_energy);
}

TEST(World2d, NewtonsCradleSequential) { expect_cradle2(Policy::sequential, Vec3(0, 0, 1)); }
TEST(World2d, NewtonsCradleSimultaneous) {
    expect_cradle2(Policy::simultaneous, Vec3(-1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0));
}

// ---- 7. A rectangle resting on the ground ------------------------------------------------------

// Placed exactly on the ground (bottom edge on y = 0), at rest, under gravity, for 2 s: it does
// not move at all (the resting contact carries exactly m g): position and angle unchanged to
// 1e-12 m / rad, velocities 0 to 1e-12, no event with a non-zero impulse (1e-12 N s), resting.
TEST(World2d, RectangleOnTheGroundStays) {
    for (Policy policy : {Policy::sequential, Policy::simultaneous}) {
        const double width = 0.4, height = 0.2;
        Scene s = plane_scene(policy, 0.5);
        s.bodies.push_back(rectangle("box", width, height, 3.0, Vec2(0.7, 0.5 * height)));
        World2 w(s);
        std::vector<Event2> events;
        for (int k = 1; k <= 200; ++k) {
            w.advance_to(0.01 * k, &events);
            const Body2& b = w.bodies()[1];
            ASSERT_LE((b.position - Vec2(0.7, 0.5 * height)).norm(), 1e-12)
                << policy_name(policy) << ", t = " << w.time();
            ASSERT_NEAR(b.angle, 0.0, 1e-12) << policy_name(policy) << ", t = " << w.time();
            ASSERT_LE(b.v.norm(), 1e-12) << policy_name(policy) << ", t = " << w.time();
            ASSERT_NEAR(b.w, 0.0, 1e-12) << policy_name(policy) << ", t = " << w.time();
        }
        for (const Event2& ev : events) EXPECT_LE(ev.impulse.norm(), 1e-12) << ev.t;
        EXPECT_TRUE(w.resting(1)) << policy_name(policy);
    }
}

// Dropped flat from h = 0.5 m with e = 0, simultaneous: both bottom corners land together and
// the LCP (un+ >= 0, equality where P > 0) stops the body without turning it (the symmetric
// solution is the only one). It lands at sqrt(2h/g) (1e-9 s) and then lies flat: angle and spin
// 0 to 1e-12, height to 1e-9 m (the landing is detected at a gap of up to kTouch = 1e-10 m),
// speed 1e-9 m/s, resting.
TEST(World2d, RectangleDroppedFlatWithoutBounceRestsFlat) {
    const double width = 0.4, height = 0.2, h = 0.5;
    Scene s = plane_scene(Policy::simultaneous, 0.0);
    s.bodies.push_back(rectangle("box", width, height, 3.0, Vec2(0.7, h + 0.5 * height)));
    World2 w(s);
    std::vector<Event2> events;
    w.advance_to(2.0, &events);
    ASSERT_FALSE(events.empty());
    EXPECT_NEAR(events.front().t, std::sqrt(2 * h / kG), 1e-9);
    const Body2& b = w.bodies()[1];
    EXPECT_NEAR(b.position.y(), 0.5 * height, 1e-9);
    EXPECT_NEAR(b.position.x(), 0.7, 1e-12);
    EXPECT_NEAR(b.angle, 0.0, 1e-12);
    EXPECT_NEAR(b.w, 0.0, 1e-12);
    EXPECT_LE(b.v.norm(), 1e-9);
    EXPECT_TRUE(w.resting(1));
}

// ---- 7b. Sleeping islands ------------------------------------------------------------------------

// Box2D's pyramid (tests/scenes/world_scenes.h): 20 rows, 210 unit boxes exactly touching,
// Coulomb mu = 0.6, e = 0, at rest on the ground. Vertical forces alone hold it (every box's
// load lies over its supports), so nothing may move at all: for 1 s every box keeps its
// position and angle to 1e-12 m / rad and has no velocity (1e-12), no event happens, and the
// whole pyramid is resting and asleep (its contact forces found once, to kPolishTolerance).
TEST(World2d, PyramidOfBoxesStaysStillAndSleeps) {
    PyramidSpec p;
    const Scene s = pyramid(p);
    ASSERT_EQ(s.bodies.size(), 1u + 210u);
    World2 w(s);
    std::vector<Event2> events;
    for (int k = 1; k <= 10; ++k) {
        w.advance_to(0.1 * k, &events);
        for (std::size_t i = 1; i < s.bodies.size(); ++i) {
            const Body2& b = w.bodies()[i];
            ASSERT_LE((b.position - s.bodies[i].body2.position).norm(), 1e-12) << i << ", t = " << w.time();
            ASSERT_NEAR(b.angle, 0.0, 1e-12) << i;
            ASSERT_LE(b.v.norm(), 1e-12) << i;
            ASSERT_NEAR(b.w, 0.0, 1e-12) << i;
            ASSERT_TRUE(w.resting(i) && w.asleep(i)) << i << ", t = " << w.time();
        }
    }
    EXPECT_TRUE(events.empty());
}

// A rectangle (w x h) lies asleep on the ground; a disc dropped from rest with its lowest point
// H above the rectangle's top, over its centre, lands at T = sqrt(2H/g) (1e-9 s: the sleeper
// is found by the disc's prediction and has not moved). e = 0, frictionless, sequential: the
// disc stops on the rectangle (its landing impulse m U = m g T up, less at most m v_rest) and the
// rectangle, hit through its centre and held by the ground, does not move (1e-12 m, rad).
// Afterwards both rest and, still, fall asleep again: disc centre r above the top (1e-9 m).
TEST(World2d, ASleeperIsWokenByAnImpactAndSleepsAgain) {
    const double width = 0.4, height = 0.2, r = 0.05, m = 0.5, H = 0.3;
    Scene s = plane_scene(Policy::sequential, 0.0);
    s.bodies.push_back(rectangle("box", width, height, 3.0, Vec2(0.7, 0.5 * height)));
    const Vec2 top(0.7, height);
    s.bodies.push_back(disc("ball", r, m, top + Vec2(0.0, H + r)));
    // The disc is far above at first: let the rectangle fall asleep before anything arrives.
    World2 w(s);
    std::vector<Event2> events;
    w.advance_to(0.01, &events);
    ASSERT_TRUE(w.asleep(1));
    ASSERT_FALSE(w.asleep(2));
    const double T = std::sqrt(2 * H / kG);
    w.advance_to(T + 0.05, &events);
    const auto hit =
        std::find_if(events.begin(), events.end(), [](const Event2& ev) { return ev.a == 1 && ev.b == 2; });
    ASSERT_NE(hit, events.end());
    EXPECT_NEAR(hit->t, T, 1e-9);
    // The passes of the sequential policy stop once the disc approaches slower than the resting
    // speed of a cornered pair, sqrt(4 g kTouch) (engine/world.h); the rest is the resting
    // contact's.
    const double v_rest = std::sqrt(4 * kG * World2::kTouch);
    EXPECT_LE(hit->impulse.y(), m * kG * T * (1 + 1e-9));  // on the disc: up
    EXPECT_GE(hit->impulse.y(), m * (kG * T - v_rest) * (1 - 1e-9));
    w.advance_to(1.0, &events);
    const Body2& box = w.bodies()[1];
    const Body2& ball = w.bodies()[2];
    EXPECT_LE((box.position - Vec2(0.7, 0.5 * height)).norm(), 1e-12);
    EXPECT_NEAR(box.angle, 0.0, 1e-12);
    EXPECT_NEAR(ball.position.y(), height + r, 1e-9);
    EXPECT_NEAR(ball.position.x(), 0.7, 1e-12);
    EXPECT_TRUE(w.asleep(1) && w.asleep(2));
    EXPECT_EQ(box.v.norm() + std::abs(box.w) + ball.v.norm(), 0.0);  // asleep: exactly still
}

// ---- 10. Two-point contact: policy decides the spin ---------------------------------------------

// The velocities right after a flat rectangle (w x h, mass m, I = m (w^2 + h^2)/12) lands on
// the ground at (0, -U), resolved one corner at a time in the given order with the frictionless
// formula on each corner's current approach, passes repeated until no corner approaches (the
// world's sequential policy). n = +y, so a corner at r has r x n = rx and approach
// un = vy + w rx.
Event2::Velocity sequential_landing(Event2::Velocity s, const std::vector<double>& rx, double m, double I, double e) {
    for (int pass = 0; pass < 64; ++pass) {
        bool any = false;
        for (double x : rx) {
            const double un = s.v.y() + s.w * x;
            if (un >= 0) continue;
            any = true;
            const double j = -(1 + e) * un / (1 / m + x * x / I);
            s.v.y() += j / m;
            s.w += j * x / I;
        }
        if (!any) break;
    }
    return s;
}

// e = 0.5, dropped flat from h = 0.5 m: it lands at U = sqrt(2 g h) (1e-9 m/s, the landing is
// found at a gap <= kTouch). Simultaneous: both corners get the same impulse, the rectangle
// leaves at e U without spin (1e-12 relative). Sequential: one corner first; the result is the
// closed-form sequence above for one of the two orders (mirror images: the same rebound, spins
// of opposite sign), for this shape a spin of 0.627 rad/s per m/s of U, to 1e-12 relative.
TEST(World2d, FlatLandingSimultaneousHasNoSpinSequentialSpins) {
    const double width = 0.4, height = 0.2, h = 0.5, m = 1.0, e = 0.5;
    const double I = m * (width * width + height * height) / 12;
    const double U = std::sqrt(2 * kG * h);
    for (Policy policy : {Policy::simultaneous, Policy::sequential}) {
        Scene s = plane_scene(policy, e);
        s.bodies.push_back(rectangle("box", width, height, m, Vec2(0.0, h + 0.5 * height)));
        World2 w(s);
        std::vector<Event2> events;
        w.advance_to(std::sqrt(2 * h / kG) + 1e-3, &events);
        ASSERT_EQ(events.size(), 1u) << policy_name(policy);
        const Event2& ev = events[0];
        const double u = -ev.before_b.v.y();
        EXPECT_NEAR(u, U, 1e-9) << policy_name(policy);
        EXPECT_NEAR(ev.before_b.w, 0.0, 1e-15);
        EXPECT_NEAR(ev.after_b.v.x(), 0.0, 1e-12 * u);  // frictionless: no horizontal impulse
        if (policy == Policy::simultaneous) {
            EXPECT_NEAR(ev.after_b.v.y(), e * u, 1e-12 * u);
            EXPECT_NEAR(ev.after_b.w, 0.0, 1e-12 * u / (0.5 * width));
        } else {
            const Event2::Velocity right = sequential_landing(ev.before_b, {0.5 * width, -0.5 * width}, m, I, e);
            const Event2::Velocity left = sequential_landing(ev.before_b, {-0.5 * width, 0.5 * width}, m, I, e);
            const Event2::Velocity& expected = ev.after_b.w < 0 ? right : left;
            EXPECT_GT(std::abs(expected.w), 0.5 * u);  // a real spin: 0.627 rad/s per m/s of u
            EXPECT_NEAR(ev.after_b.v.y(), expected.v.y(), 1e-12 * u);
            EXPECT_NEAR(ev.after_b.w, expected.w, 1e-12 * std::abs(expected.w));
        }
    }
}

// ---- 8. Determinism ----------------------------------------------------------------------------

// Bit-identical histories: events (time, pair, impulse, point, velocities) and final states.
void expect_identical(const World2& x, const World2& y, const std::vector<Event2>& ex, const std::vector<Event2>& ey) {
    ASSERT_EQ(ex.size(), ey.size());
    for (std::size_t k = 0; k < ex.size(); ++k) {
        ASSERT_EQ(ex[k].t, ey[k].t) << k;
        ASSERT_EQ(ex[k].a, ey[k].a) << k;
        ASSERT_EQ(ex[k].b, ey[k].b) << k;
        ASSERT_EQ(ex[k].impulse, ey[k].impulse) << k;
        ASSERT_EQ(ex[k].point, ey[k].point) << k;
        ASSERT_EQ(ex[k].after_a.v, ey[k].after_a.v) << k;
        ASSERT_EQ(ex[k].after_b.v, ey[k].after_b.v) << k;
        ASSERT_EQ(ex[k].after_a.w, ey[k].after_a.w) << k;
        ASSERT_EQ(ex[k].after_b.w, ey[k].after_b.w) << k;
    }
    ASSERT_EQ(x.bodies().size(), y.bodies().size());
    for (std::size_t i = 0; i < x.bodies().size(); ++i) {
        const Body2 &a = x.bodies()[i], &b = y.bodies()[i];
        ASSERT_EQ(a.position, b.position) << i;
        ASSERT_EQ(a.angle, b.angle) << i;
        ASSERT_EQ(a.v, b.v) << i;
        ASSERT_EQ(a.w, b.w) << i;
    }
}

// 50 discs in a walled square with random velocities (fixed seed), e = 1, 2 s: the same scene
// run twice, and a copy of a world taken before running (as the benchmarks use), give
// bit-identical states and events.
TEST(World2d, SameSceneSameHistory) {
    GasSpec g;
    g.n = 50;
    g.seed = 11;
    g.speed = 2.0;
    const Scene s = gas(2, g);
    World2 one(s), two(s);
    const World2 copy = one;
    World2 three = copy;
    std::vector<Event2> e1, e2, e3;
    for (int k = 1; k <= 100; ++k) {
        one.advance_to(0.02 * k, &e1);
        two.advance_to(0.02 * k, &e2);
        three.advance_to(0.02 * k, &e3);
    }
    EXPECT_GT(e1.size(), 50u);  // the history is not trivial
    expect_identical(one, two, e1, e2);
    expect_identical(one, three, e1, e3);
}

// ---- 9. An elastic gas -------------------------------------------------------------------------

// 200 discs at 5% area fraction in a walled square, e = 1, frictionless, no gravity, 1 s.
// Kinetic energy conserved to 1e-9 relative (every impulse keeps it to round-off); at every
// output time (0.01 s) no disc pokes through a wall nor overlaps another by more than 1e-9 m
// (impacts are found at a gap <= kTouch = 1e-10 m).
TEST(World2d, ElasticGasKeepsEnergyAndNoOverlap) {
    GasSpec g;
    g.n = 200;
    g.seed = 3;
    const Scene s = gas(2, g);
    const double L = gas_box_size(2, g), r = g.radius;
    const std::size_t first = 4;  // the walls come first
    World2 w(s);
    const double e0 = kinetic_energy(w.bodies());
    std::vector<Event2> events;
    for (int k = 1; k <= 100; ++k) {
        w.advance_to(0.01 * k, &events);
        const auto& b = w.bodies();
        for (std::size_t i = first; i < b.size(); ++i) {
            for (int c = 0; c < 2; ++c) {
                ASSERT_GE(b[i].position[c], r - 1e-9) << "body " << i << ", t = " << w.time();
                ASSERT_LE(b[i].position[c], L - r + 1e-9) << "body " << i << ", t = " << w.time();
            }
            for (std::size_t j = i + 1; j < b.size(); ++j)
                ASSERT_GE((b[i].position - b[j].position).norm(), 2 * r - 1e-9)
                    << "bodies " << i << ", " << j << ", t = " << w.time();
        }
        ASSERT_NEAR(kinetic_energy(b), e0, 1e-9 * e0) << "t = " << w.time();
    }
    // The run is not vacuous: discs hit each other and the walls.
    const auto pairs = std::count_if(events.begin(), events.end(), [&](const Event2& ev) { return ev.a >= first; });
    EXPECT_GT(pairs, 0);
    EXPECT_GT(static_cast<long>(events.size()) - pairs, 0);
}

// ---- 11. A disc sliding off a disc that lies on the ground ---------------------------------------

// Ground y = 0; disc A (r = 0.05 m, 1 kg) lies on it at rest; disc B (the same) rests on A,
// touching it, its centre 0.3 r to the side (+x) of A's. Gravity, frictionless, sequential.
// B slides down A's side and pushes A away along the ground. What every frictionless model
// must give: the horizontal momentum stays 0 (no horizontal external force; 1e-12 kg m/s);
// the total energy never grows (1e-12 relative); no overlap: at every output time (2 ms, for
// 0.1 s) the two are at least -1e-9 m apart and neither is below the ground by more than 1e-9 m
// (contact is found at kTouch = 1e-10 m).
struct SlideResult {
    double worst_gap = 0.0, worst_gap_t = 0.0, worst_floor = 0.0;
    double worst_px = 0.0, worst_gain = -1e300, worst_change = 0.0, E0 = 0.0;
    std::size_t events = 0;
};

SlideResult slide_off(double e) {
    const double r = 0.05, m = 1.0;
    const double h = std::sqrt(4 * r * r - 0.09 * r * r);  // B's centre above A's
    Scene s = plane_scene(Policy::sequential, e);
    s.bodies.push_back(disc("A", r, m, Vec2(0.0, r)));
    s.bodies.push_back(disc("B", r, m, Vec2(0.3 * r, r + h)));
    s.stepping = StepMode::never;  // the exact world's resting contact, not stepped islands
    World2 w(s);
    std::vector<Event2> events;
    auto energy = [&] { return kinetic_energy(w.bodies()) + potential_energy(w.bodies(), s.gravity); };
    SlideResult out;
    out.E0 = energy();
    for (int k = 1; k <= 50; ++k) {
        w.advance_to(0.002 * k, &events);
        const auto& b = w.bodies();
        const double gap = (b[2].position - b[1].position).norm() - 2 * r;
        if (gap < out.worst_gap) {
            out.worst_gap = gap;
            out.worst_gap_t = w.time();
        }
        out.worst_floor = std::min({out.worst_floor, b[1].position.y() - r, b[2].position.y() - r});
        out.worst_px = std::max(out.worst_px, std::abs(m * (b[1].v.x() + b[2].v.x())));
        out.worst_gain = std::max(out.worst_gain, energy() - out.E0);
        out.worst_change = std::max(out.worst_change, std::abs(energy() - out.E0));
    }
    out.events = events.size();
    return out;
}

TEST(World2d, DiscSlidingOffADiscOnTheGroundNeverOverlaps) {
    for (double e : {1.0, 0.8, 0.5}) {
        const SlideResult x = slide_off(e);
        // Resting contact is integrated with constant forces per substep (engine/world.h,
        // "Known limits"): sliding over a curved partner, the contact chatters. With e = 1 the
        // tiny impacts are elastic and nothing overlaps; with e < 1 overlaps of up to a few
        // 1e-5 m (measured 2.3e-5) are the documented limit, asserted so it cannot grow.
        const double allowed = e == 1.0 ? 1e-9 : 5e-5;
        EXPECT_GE(x.worst_gap, -allowed) << "e = " << e << ": A and B overlap by " << -x.worst_gap
                                         << " m at t = " << x.worst_gap_t << " s (" << x.events << " events in 0.1 s)";
        EXPECT_GE(x.worst_floor, -1e-9) << "e = " << e;
        EXPECT_LE(x.worst_px, 1e-12) << "e = " << e;
        EXPECT_LE(x.worst_gain, 1e-12 * x.E0) << "e = " << e;
    }
}

// The same with e = 1: the contact force of an ideal frictionless contact does no work. The
// constant forces of a resting substep follow the curved contact to third order (the
// centripetal term of solve_island), so the energy is kept to 1e-7 relative (measured 1e-8
// in 2D, 4e-8 in 3D), not to round-off: the documented limit of resting contact.
TEST(World2d, DiscSlidingOffADiscElasticKeepsEnergy) {
    const SlideResult x = slide_off(1.0);
    EXPECT_LE(x.worst_change, 1e-7 * x.E0) << "largest |E - E0| = " << x.worst_change << " J of E0 = " << x.E0 << " J";
}

// Without gravity the resting speeds are zero: a contact left at u_n = 0 by an e = 0 hit, whose
// normal speed then reads -1e-18 m/s from round-off, used to be answered again and again at
// one instant until the world gave up ("stuck"). A disc hits a free bar near its end with e = 0;
// the turning bar then sweeps it along. Stepped in 1/60 s chunks (as a 60 frames/s render
// does) the run finishes; momentum is kept (the impulses are internal) and no energy appears.
TEST(World2d, ZeroRestitutionWithoutGravityIsNotAnsweredForever) {
    Scene s = empty_scene(2, Policy::sequential, 0.0);
    s.bodies.push_back(disc("clay", 0.05, 0.5, Vec2(0.45, -0.6), Vec2(0.0, 3.0)));
    s.bodies.push_back(rectangle("rod", 1.0, 0.05, 2.0, Vec2(0.0, 0.0)));
    World2 world(s);
    const Totals2 start = totals(world.bodies());
    std::vector<Event2> events;
    for (int k = 1; k <= 30; ++k) ASSERT_NO_THROW(world.advance_to(k / 60.0, &events));
    ASSERT_GE(events.size(), 1u);
    const Totals2 end = totals(world.bodies());
    EXPECT_NEAR((end.momentum - start.momentum).norm(), 0.0, 1e-12 * start.momentum.norm());
    EXPECT_LE(end.kinetic_energy, start.kinetic_energy * (1 + 1e-12));
}

}  // namespace
}  // namespace collide
