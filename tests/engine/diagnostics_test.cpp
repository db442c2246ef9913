// Conservation checks (engine/diagnostics.h) on hand-computed bodies: the other suites rely on
// totals(), so it is checked here against numbers worked out by hand.
#include <gtest/gtest.h>

#include <vector>

#include "engine/diagnostics.h"
#include "tests/engine/random_bodies.h"

namespace {

using namespace collide;

constexpr double kAtol = 1e-14;
constexpr double kRtol = 1e-14;

// 1D: m = 2 kg at 3 m/s and m = 1 kg at -4 m/s, plus a static wall (left out):
// p = 6 - 4 = 2 kg m/s, KE = 1/2 2 9 + 1/2 1 16 = 9 + 8 = 17 J.
TEST(Totals, OneD) {
    std::vector<Body1> bodies(3);
    bodies[0].mass = 2.0;
    bodies[0].v = 3.0;
    bodies[1].mass = 1.0;
    bodies[1].v = -4.0;
    bodies[2].is_static = true;
    bodies[2].v = 10.0;
    const Totals1 t = totals(bodies);
    EXPECT_NEAR_ABS_REL(t.momentum, 2.0, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(t.kinetic_energy, 17.0, kAtol, kRtol);
}

// 2D: m = 2 kg at x = (1, 0), v = (0, 3), I = 0.5, w = 2:
// p = (0, 6); L about 0 = I w + m x x v = 1 + 2 (1*3 - 0*0) = 7; KE = 1/2 2 9 + 1/2 0.5 4 = 10.
// About o = (0, 1): x - o = (1, -1), (x - o) x v = 1*3 - (-1)*0 = 3: L = 1 + 6 = 7 as well
// (L_o = L_0 - o x p, o x p = 0*6 - 1*0 = 0). About o = (1, 0): L = 1 + 0 = 1 (= 7 - (1*6)).
TEST(Totals, TwoD) {
    std::vector<Body2> bodies(2);
    bodies[0].mass = 2.0;
    bodies[0].position = Vec2(1, 0);
    bodies[0].v = Vec2(0, 3);
    bodies[0].inertia = 0.5;
    bodies[0].w = 2.0;
    bodies[1].is_static = true;
    bodies[1].v = Vec2(5, 5);
    bodies[1].w = 1.0;
    const Totals2 t = totals(bodies);
    EXPECT_NEAR_ABS_REL(t.momentum, Vec2(0, 6), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(t.angular_momentum, 7.0, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(t.kinetic_energy, 10.0, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(totals(bodies, Vec2(0, 1)).angular_momentum, 7.0, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(totals(bodies, Vec2(1, 0)).angular_momentum, 1.0, kAtol, kRtol);
}

// 3D, body 1: m = 2 kg at x = (1, 0, 0), v = (0, 3, 0), Ibody = diag(1, 2, 3), identity
// orientation, w = (0, 0, 1): p = (0, 6, 0), L = (0, 0, 3) + 2 (1,0,0)x(0,3,0) = (0, 0, 3 + 6),
// KE = 9 + 1/2 3 = 10.5.
// Body 2: m = 1 kg at the origin at rest, Ibody = diag(1, 2, 3) turned 45 degrees about z:
// Iworld = [[1.5, -0.5, 0], [-0.5, 1.5, 0], [0, 0, 3]]; w = (1, 1, 0): I w = (1, 1, 0),
// KE = 1/2 (1 + 1) = 1 (the diagonal alone would give 1.5: the product of inertia counts).
// Totals: p = (0, 6, 0), L = (1, 1, 9), KE = 11.5.
TEST(Totals, ThreeDWithProductsOfInertia) {
    std::vector<Body3> bodies(3);
    bodies[0].mass = 2.0;
    bodies[0].position = Vec3(1, 0, 0);
    bodies[0].v = Vec3(0, 3, 0);
    bodies[0].inertia = Vec3(1, 2, 3).asDiagonal();
    bodies[0].w = Vec3(0, 0, 1);
    bodies[1].mass = 1.0;
    bodies[1].inertia = Vec3(1, 2, 3).asDiagonal();
    bodies[1].orientation = Quat(Eigen::AngleAxisd(collide_test::kPi / 4, Vec3::UnitZ()));
    bodies[1].w = Vec3(1, 1, 0);
    bodies[2].is_static = true;
    bodies[2].v = Vec3(1, 2, 3);
    const Totals3 t = totals(bodies);
    EXPECT_NEAR_ABS_REL(t.momentum, Vec3(0, 6, 0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(t.angular_momentum, Vec3(1, 1, 9), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(t.kinetic_energy, 11.5, kAtol, kRtol);
    // About o = (0, 0, 2): L_o = L_0 - o x p = (1, 1, 9) - (0,0,2)x(0,6,0) = (1, 1, 9) - (-12, 0, 0).
    EXPECT_NEAR_ABS_REL(totals(bodies, Vec3(0, 0, 2)).angular_momentum, Vec3(13, 1, 9), kAtol, kRtol);
}

}  // namespace
