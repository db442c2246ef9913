// Bodies (engine/body.h) and the math vocabulary (engine/math.h): inverse masses, static bodies,
// the contact view r = p - x, point velocities v + w x r, the cross-product helpers.
#include <gtest/gtest.h>

#include "engine/body.h"
#include "engine/math.h"
#include "tests/engine/random_bodies.h"

namespace {

using namespace collide;

constexpr double kAtol = 1e-14;
constexpr double kRtol = 1e-14;

// [r]x a = r x a. r = (1, 2, 3), a = (4, 5, 6):
// r x a = (2*6 - 3*5, 3*4 - 1*6, 1*5 - 2*4) = (-3, 6, -3). [r]x is antisymmetric.
TEST(MathSkew, IsTheCrossProductMatrix) {
    const Vec3 r(1, 2, 3), a(4, 5, 6);
    EXPECT_NEAR_ABS_REL(Vec3(skew(r) * a), Vec3(-3, 6, -3), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(Mat3(skew(r).transpose()), Mat3(-skew(r)), 0.0, 0.0);
}

// 2D scalar cross product: (1, 2) x (3, 4) = 1*4 - 2*3 = -2.
// w x r for w = 2 (counter-clockwise) at r = (1, 0) is (0, 2); at r = (0, 1) it is (-2, 0).
// perp(1, 2) = (-2, 1), and r x P = perp(r).P: (1, 2) x (3, 4) = (-2, 1).(3, 4) = -2.
TEST(MathCross2D, HandValues) {
    EXPECT_EQ(cross(Vec2(1, 2), Vec2(3, 4)), -2.0);
    EXPECT_NEAR_ABS_REL(cross(2.0, Vec2(1, 0)), Vec2(0, 2), 0.0, 0.0);
    EXPECT_NEAR_ABS_REL(cross(2.0, Vec2(0, 1)), Vec2(-2, 0), 0.0, 0.0);
    EXPECT_NEAR_ABS_REL(perp(Vec2(1, 2)), Vec2(-2, 1), 0.0, 0.0);
    EXPECT_EQ(perp(Vec2(1, 2)).dot(Vec2(3, 4)), cross(Vec2(1, 2), Vec2(3, 4)));
}

// The 2D helpers are the 3D cross products in the plane z = 0.
TEST(MathCross2D, AreThe3DProductsInThePlane) {
    collide_test::Random rng(201);
    for (int i = 0; i < 100; ++i) {
        const Vec2 a = rng.vec2(-2, 2), b = rng.vec2(-2, 2);
        const double w = rng.uniform(-3, 3);
        const Vec3 a3(a.x(), a.y(), 0), b3(b.x(), b.y(), 0);
        EXPECT_NEAR_ABS_REL(cross(a, b), a3.cross(b3).z(), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(cross(w, a), Vec2(Vec3(0, 0, w).cross(a3).head<2>()), kAtol, kRtol);
    }
}

// Inverse mass 1/m; a static body has zero inverse mass, inverse inertia and world inertia.
TEST(Body, InverseMassAndStatic) {
    Body1 b1;
    b1.mass = 4.0;
    EXPECT_EQ(b1.inv_mass(), 0.25);
    b1.is_static = true;
    EXPECT_EQ(b1.inv_mass(), 0.0);

    Body2 b2;
    b2.mass = 2.0;
    b2.inertia = 0.5;
    EXPECT_EQ(b2.inv_mass(), 0.5);
    EXPECT_EQ(b2.inv_inertia(), 2.0);
    b2.is_static = true;
    EXPECT_EQ(b2.inv_mass(), 0.0);
    EXPECT_EQ(b2.inv_inertia(), 0.0);

    Body3 b3;
    b3.mass = 8.0;
    b3.inertia = Vec3(1, 2, 4).asDiagonal();
    EXPECT_EQ(b3.inv_mass(), 0.125);
    EXPECT_NEAR_ABS_REL(b3.inv_inertia_world(), Mat3(Vec3(1, 0.5, 0.25).asDiagonal()), kAtol, kRtol);
    b3.is_static = true;
    EXPECT_EQ(b3.inv_mass(), 0.0);
    EXPECT_EQ(b3.inertia_world(), Mat3::Zero());
    EXPECT_EQ(b3.inv_inertia_world(), Mat3::Zero());
}

// at_contact: r = p - x (from the centre of mass to the contact), velocities copied, world
// inertia and its inverse. Point velocity v + w x r: v = (1, 0, 0), w = (0, 0, 2),
// x = (1, 1, 0), p = (2, 1, 0): r = (1, 0, 0), w x r = (0, 2, 0), vp = (1, 2, 0).
TEST(Body, AtContact3D) {
    Body3 b;
    b.mass = 2.0;
    b.inertia = Vec3(1, 2, 3).asDiagonal();
    b.orientation = Quat(Eigen::AngleAxisd(collide_test::kPi / 2, Vec3::UnitZ()));
    b.position = Vec3(1, 1, 0);
    b.v = Vec3(1, 0, 0);
    b.w = Vec3(0, 0, 2);
    const ImpactBody3 c = at_contact(b, Vec3(2, 1, 0));
    EXPECT_EQ(c.inv_m, 0.5);
    EXPECT_NEAR_ABS_REL(c.r, Vec3(1, 0, 0), kAtol, kRtol);
    // Turned 90 degrees about z: world diag(2, 1, 3).
    EXPECT_NEAR_ABS_REL(c.I, Mat3(Vec3(2, 1, 3).asDiagonal()), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(c.inv_I, Mat3(Vec3(0.5, 1, 1.0 / 3).asDiagonal()), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(point_velocity(c), Vec3(1, 2, 0), kAtol, kRtol);
    EXPECT_FALSE(c.is_static());
    b.is_static = true;
    EXPECT_TRUE(at_contact(b, Vec3(2, 1, 0)).is_static());
}

// 2D: v = (1, 0), w = 2, x = (0, 1), p = (0, 0): r = (0, -1), w x r = 2 (1, 0) = (2, 0),
// vp = (3, 0).
TEST(Body, AtContact2D) {
    Body2 b;
    b.mass = 4.0;
    b.inertia = 0.25;
    b.position = Vec2(0, 1);
    b.v = Vec2(1, 0);
    b.w = 2.0;
    const ImpactBody2 c = at_contact(b, Vec2(0, 0));
    EXPECT_EQ(c.inv_m, 0.25);
    EXPECT_EQ(c.inv_I, 4.0);
    EXPECT_EQ(c.I, 0.25);
    EXPECT_NEAR_ABS_REL(c.r, Vec2(0, -1), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(point_velocity(c), Vec2(3, 0), kAtol, kRtol);
    b.is_static = true;
    const ImpactBody2 s = at_contact(b, Vec2(0, 0));
    EXPECT_TRUE(s.is_static());
    EXPECT_EQ(s.inv_I, 0.0);
    EXPECT_EQ(s.I, 0.0);
}

TEST(Body, AtContact1D) {
    Body1 b;
    b.mass = 5.0;
    b.v = -1.5;
    const ImpactBody1 c = at_contact(b);
    EXPECT_EQ(c.inv_m, 0.2);
    EXPECT_EQ(c.v, -1.5);
    b.is_static = true;
    EXPECT_TRUE(at_contact(b).is_static());
}

}  // namespace
