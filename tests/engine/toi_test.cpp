// Time of impact against closed forms: constant closing speed, oblique approach, a fall under
// gravity, a spinning box landing (root of its analytic lowest-point height), a near miss, and
// a fast disc against a thin plate (no tunnelling); the worlds' closed forms for round bodies.
// (The worlds' conservative advancement is tested through the worlds: tests/engine/world*.)
#include <cmath>

#include <gtest/gtest.h>

#include "engine/toi.h"

namespace collide {
namespace {

Shape2 disc(double r) { return Shape2::disc(r); }
Shape2 rect(double w, double h) { return Shape2::rectangle(w, h); }
Shape2 ground() { return Shape2::half_plane(Vec2(0, 1), 0.0); }
Motion2 moving(Vec2 x, Vec2 v, double angle = 0, double w = 0, Vec2 g = Vec2::Zero()) {
    return Motion2{x, v, g, angle, w};
}

// Gap 1 m closing at 3 m/s: t = 1/3 s. The tolerance 1e-10 m is 3.3e-11 s at 3 m/s.
TEST(Toi2d, HeadOnDiscs) {
    const TimeOfImpact r = time_of_impact(disc(0.5), moving({0, 0}, {1, 0}), disc(0.5), moving({2, 0}, {-2, 0}), 10.0);
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.t, 1.0 / 3.0, 1e-10);
    EXPECT_LE(r.manifold.separation, 1e-10);
    EXPECT_GE(r.manifold.separation, -1e-12);
    EXPECT_LE((r.manifold.normal - Vec2(1, 0)).norm(), 1e-12);
    ASSERT_EQ(r.manifold.count, 1);
}

// A at the origin moving +x at 1 m/s, B resting at (3, 0.6), radii 0.5: contact when
// (3 - t)^2 + 0.36 = 1, t = 2.2 s; the normal then points along (0.8, 0.6).
TEST(Toi2d, ObliqueApproach) {
    const TimeOfImpact r = time_of_impact(disc(0.5), moving({0, 0}, {1, 0}), disc(0.5), moving({3, 0.6}, {0, 0}), 10.0);
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.t, 2.2, 1e-9);
    EXPECT_LE((r.manifold.normal - Vec2(0.8, 0.6)).norm(), 1e-9);
}

// A disc dropped from rest with its lowest point h above the ground: t = sqrt(2 h / g).
TEST(Toi2d, FallUnderGravity) {
    const double g = 9.81, h = 1.25, R = 0.1;
    const TimeOfImpact r =
        time_of_impact(ground(), moving({0, 0}, {0, 0}), disc(R), moving({0, h + R}, {0.3, 0}, 0, 0, {0, -g}), 10.0);
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.t, std::sqrt(2 * h / g), 1e-9);
    EXPECT_LE((r.manifold.points[0] - Vec2(0.3 * r.t, 0)).norm(), 1e-9);
}

// A w x h box spinning at w0 while it descends at speed s: its lowest point is
// (w/2)|sin th| + (h/2)|cos th| below the centre, so the gap is
// f(t) = y0 - s t - (w/2)|sin(w0 t)| - (h/2)|cos(w0 t)|. The first root of f, found by dense
// sampling and bisection, is the time of impact.
TEST(Toi2d, SpinningBoxLands) {
    const double W = 1.0, H = 0.3, y0 = 2.0, s = 0.7, w0 = 5.0;
    auto f = [&](double t) {
        return y0 - s * t - 0.5 * W * std::abs(std::sin(w0 * t)) - 0.5 * H * std::abs(std::cos(w0 * t));
    };
    double lo = 0, hi = 0;
    for (double t = 0; t < 10; t += 1e-4)
        if (f(t) <= 0) {
            hi = t;
            lo = t - 1e-4;
            break;
        }
    ASSERT_GT(hi, 0);
    for (int i = 0; i < 200; ++i) (f(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
    const TimeOfImpact r =
        time_of_impact(ground(), moving({0, 0}, {0, 0}), rect(W, H), moving({0, y0}, {0, -s}, 0, w0), 10.0);
    ASSERT_TRUE(r.hit);
    ASSERT_TRUE(r.converged);
    EXPECT_NEAR(r.t, lo, 1e-9);
}

// Closest approach 0.05 m beyond contact: no hit, and the answer comes back.
TEST(Toi2d, NearMiss) {
    const TimeOfImpact r =
        time_of_impact(disc(0.5), moving({0, 0}, {1, 0}), disc(0.5), moving({3, 1.05}, {0, 0}), 10.0);
    EXPECT_FALSE(r.hit);
    EXPECT_TRUE(r.converged);
}

// 1000 m/s against a 1 mm plate 1 m away: contact at (1 - 0.0005 - 0.01) / 1000 s, before any
// overlap (a fixed step of 1/60 s would jump 16 m past it).
TEST(Toi2d, FastDiscDoesNotTunnel) {
    const TimeOfImpact r =
        time_of_impact(disc(0.01), moving({0, 0}, {1000, 0}), rect(0.001, 1), moving({1, 0}, {0, 0}), 1.0 / 60.0);
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.t, (1 - 0.0005 - 0.01) / 1000.0, 1e-12);
    EXPECT_GE(r.manifold.separation, -1e-12);
}

// Bodies that already overlap at t = 0 are reported at t = 0 with their depth.
TEST(Toi2d, InitialOverlapIsImmediate) {
    const TimeOfImpact r = time_of_impact(disc(0.5), moving({0, 0}, {0, 0}), disc(0.5), moving({0.9, 0}, {0, 0}), 1.0);
    ASSERT_TRUE(r.hit);
    EXPECT_EQ(r.t, 0.0);
    EXPECT_NEAR(r.manifold.separation, -0.1, 1e-12);
}

// The worlds' closed forms. A ball whose lowest point is h above the ground, moving sideways:
// t = sqrt(2 h / g); one touching it and leaving at 2 m/s is back after 2 v / g.
TEST(Toi, RoundOnPlane) {
    const double g = 9.81, h = 1.25;
    const Vec3 n(0, 1, 0), a(0, -g, 0);
    EXPECT_NEAR(plane_contact_time(n, Vec3(0.3, 0, 0), a, h, false), std::sqrt(2 * h / g), 1e-12);
    EXPECT_NEAR(plane_contact_time(n, Vec3(0, 2, 0), a, 0.0, true), 4.0 / g, 1e-12);
    EXPECT_TRUE(std::isinf(plane_contact_time(Vec2(0, 1), Vec2(0, 1), Vec2::Zero(), h, false)));
}

// Two discs, radii summing to 1 m, centres 2 m apart closing at 3 m/s: t = 1/3 s; parting or
// touching: never.
TEST(Toi, RoundPair) {
    EXPECT_NEAR(round_contact_time(Vec2(2, 0), Vec2(-3, 0), 1.0, false), 1.0 / 3.0, 1e-12);
    EXPECT_TRUE(std::isinf(round_contact_time(Vec2(2, 0), Vec2(3, 0), 1.0, false)));
    EXPECT_TRUE(std::isinf(round_contact_time(Vec3(1, 0, 0), Vec3(-3, 0, 0), 1.0, true)));
}

}  // namespace
}  // namespace collide
