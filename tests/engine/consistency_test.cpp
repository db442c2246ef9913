// Consistency between the models and dimensions:
//  - swapping A and B (and n -> -n) describes the same collision: same motion, impulse -P;
//  - 2D equals 3D restricted to the plane (z = 0, w along z, inertia Izz);
//  - 1D equals 2D and 3D with r = 0;
//  - rotating the whole scene rotates the result; adding a common velocity (Galilean boost)
//    adds it to the result and leaves the impulse alone.
#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "engine/response.h"
#include "tests/engine/random_bodies.h"

namespace {

using namespace collide;

constexpr double kAtol = 1e-13;
constexpr double kRtol = 1e-11;
constexpr int kDraws = 2000;

using Solver3 = std::function<Response3(const ImpactBody3&, const ImpactBody3&, const Vec3&)>;
using Solver2 = std::function<Response2(const ImpactBody2&, const ImpactBody2&, const Vec2&)>;

struct Named3 {
    const char* name;
    Solver3 solve;
};
struct Named2 {
    const char* name;
    Solver2 solve;
};

// Every model with fixed e = 0.6, mu = 0.4 (the coulomb draws then both stick and slide).
std::vector<Named3> solvers3() {
    return {
        {"frictionless", [](auto& a, auto& b, auto& n) { return frictionless(a, b, n, 0.6); }},
        {"coulomb", [](auto& a, auto& b, auto& n) { return coulomb(a, b, n, 0.6, 0.4); }},
        {"matrix", [](auto& a, auto& b, auto& n) { return matrix(a, b, n, 0.6); }},
        {"stick", [](auto& a, auto& b, auto& n) { return stick(a, b, n); }},
        {"stick_newton_euler", [](auto& a, auto& b, auto& n) { return stick_newton_euler(a, b, n); }},
    };
}
std::vector<Named2> solvers2() {
    return {
        {"frictionless", [](auto& a, auto& b, auto& n) { return frictionless(a, b, n, 0.6); }},
        {"coulomb", [](auto& a, auto& b, auto& n) { return coulomb(a, b, n, 0.6, 0.4); }},
        {"matrix", [](auto& a, auto& b, auto& n) { return matrix(a, b, n, 0.6); }},
        {"stick", [](auto& a, auto& b, auto& n) { return stick(a, b, n); }},
    };
}

void expect_same3(const Response3& x, const Response3& y) {
    EXPECT_NEAR_ABS_REL(x.P, y.P, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(x.couple, y.couple, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(x.va, y.va, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(x.vb, y.vb, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(x.wa, y.wa, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(x.wb, y.wb, kAtol, kRtol);
    EXPECT_EQ(x.separating, y.separating);
    EXPECT_EQ(x.sliding, y.sliding);
}

// Swap: B becomes A and the normal (from A into B) flips. u -> -u, un = u.n unchanged, K
// unchanged, so every model's impulse on the new B (old A) is -P, and each body's motion is
// the same. Random approaching 3D pairs, one static body in every fifth draw.
TEST(ConsistencySwap, SameMotion3D) {
    collide_test::Random rng(1001);
    for (const Named3& s : solvers3()) {
        SCOPED_TRACE(s.name);
        for (int i = 0; i < kDraws; ++i) {
            Body3 A = rng.body3(), B = rng.body3();
            if (i % 5 == 1) A.is_static = true;
            if (i % 5 == 2) B.is_static = true;
            const Vec3 p = rng.vec3(-1, 1);
            const ImpactBody3 a = at_contact(A, p), b = at_contact(B, p);
            Vec3 n = rng.unit3();
            if (relative_velocity(a, b).dot(n) > 0) n = -n;
            const Response3 r = s.solve(a, b, n), q = s.solve(b, a, -n);
            Response3 swapped = q;
            swapped.P = -q.P;
            swapped.couple = -q.couple;
            swapped.va = q.vb, swapped.wa = q.wb, swapped.vb = q.va, swapped.wb = q.wa;
            expect_same3(r, swapped);
        }
    }
}

TEST(ConsistencySwap, SameMotion2D) {
    collide_test::Random rng(1002);
    for (const Named2& s : solvers2()) {
        SCOPED_TRACE(s.name);
        for (int i = 0; i < kDraws; ++i) {
            Body2 A = rng.body2(), B = rng.body2();
            if (i % 5 == 1) A.is_static = true;
            if (i % 5 == 2) B.is_static = true;
            const Vec2 p = rng.vec2(-1, 1);
            const ImpactBody2 a = at_contact(A, p), b = at_contact(B, p);
            Vec2 n = rng.unit2();
            if (relative_velocity(a, b).dot(n) > 0) n = -n;
            const Response2 r = s.solve(a, b, n), q = s.solve(b, a, -n);
            EXPECT_NEAR_ABS_REL(r.P, Vec2(-q.P), kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(r.couple, -q.couple, kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(r.va, q.vb, kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(r.vb, q.va, kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(r.wa, q.wb, kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(r.wb, q.wa, kAtol, kRtol);
            EXPECT_EQ(r.sliding, q.sliding);
        }
    }
}

// A 2D body embedded in 3D: position, velocity, normal and contact point in z = 0, w = (0, 0, w),
// a body-frame tensor with Izz = the 2D inertia and the other moments from physical extents
// (Izz = m (a + b), Ixx = m (b + c), Iyy = m (a + c)), turned about z by the body's angle.
// The 3D collision matrix is then block-diagonal (in-plane block = the 2D K), so every model's
// 3D answer stays in the plane and equals the 2D one.
Body3 embed(const Body2& b, double c_extent) {
    Body3 e;
    e.mass = b.mass;
    e.is_static = b.is_static;
    const double k2 = b.inertia / b.mass;  // a + b
    const double ax = 0.3 * k2, by = 0.7 * k2;
    e.inertia = b.mass * Vec3(by + c_extent, ax + c_extent, ax + by).asDiagonal();
    e.orientation = Quat(Eigen::AngleAxisd(b.angle, Vec3::UnitZ()));
    e.position = Vec3(b.position.x(), b.position.y(), 0);
    e.v = Vec3(b.v.x(), b.v.y(), 0);
    e.w = Vec3(0, 0, b.w);
    return e;
}
Vec3 in3(const Vec2& v) { return Vec3(v.x(), v.y(), 0); }

TEST(ConsistencyDimensions, TwoDEqualsThreeDInThePlane) {
    collide_test::Random rng(1003);
    const std::vector<Named2> s2 = solvers2();
    const std::vector<Named3> s3 = solvers3();
    for (std::size_t k = 0; k < s2.size(); ++k) {
        SCOPED_TRACE(s2[k].name);
        for (int i = 0; i < kDraws; ++i) {
            Body2 A = rng.body2(), B = rng.body2();
            if (i % 5 == 1) A.is_static = true;
            if (i % 5 == 2) B.is_static = true;
            const Vec2 p = rng.vec2(-1, 1);
            Vec2 n = rng.unit2();
            const ImpactBody2 a = at_contact(A, p), b = at_contact(B, p);
            if (relative_velocity(a, b).dot(n) > 0) n = -n;
            const Response2 r2 = s2[k].solve(a, b, n);
            const Body3 A3 = embed(A, rng.log_uniform(0.005, 0.5)), B3 = embed(B, rng.log_uniform(0.005, 0.5));
            const Response3 r3 = s3[k].solve(at_contact(A3, in3(p)), at_contact(B3, in3(p)), in3(n));
            EXPECT_NEAR_ABS_REL(r3.P, in3(r2.P), kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(r3.va, in3(r2.va), kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(r3.vb, in3(r2.vb), kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(r3.wa, Vec3(0, 0, r2.wa), kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(r3.wb, Vec3(0, 0, r2.wb), kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(r3.couple, Vec3(0, 0, r2.couple), kAtol, kRtol);
            EXPECT_EQ(r3.separating, r2.separating);
            EXPECT_EQ(r3.sliding, r2.sliding);
        }
    }
}

// 1D = 2D = 3D with r = 0 (both centres at the contact point), velocities along the line
// n = +-x, no spin: frictionless and stick give the same velocities and impulse.
TEST(ConsistencyDimensions, OneDEqualsTwoDAndThreeDWithZeroLever) {
    collide_test::Random rng(1004);
    for (int i = 0; i < kDraws; ++i) {
        const double ma = rng.mass(), mb = rng.mass(), e = rng.uniform(0, 1);
        const double va = rng.uniform(-3, 3), vb = rng.uniform(-3, 3);
        const double n = (vb - va) < 0 ? 1.0 : -1.0;  // approaching
        ImpactBody1 a1, b1;
        a1.inv_m = 1 / ma, a1.v = va;
        b1.inv_m = 1 / mb, b1.v = vb;
        if (i % 7 == 3) a1.inv_m = 0;  // a wall
        ImpactBody2 a2, b2;
        a2.inv_m = a1.inv_m, a2.v = Vec2(va, 0);
        b2.inv_m = b1.inv_m, b2.v = Vec2(vb, 0);
        a2.I = a1.inv_m > 0 ? ma * 0.1 : 0, a2.inv_I = a1.inv_m > 0 ? 1 / a2.I : 0;
        b2.I = mb * 0.2, b2.inv_I = 1 / b2.I;
        ImpactBody3 a3, b3;
        a3.inv_m = a1.inv_m, a3.v = Vec3(va, 0, 0);
        b3.inv_m = b1.inv_m, b3.v = Vec3(vb, 0, 0);
        a3.I = a1.inv_m > 0 ? Mat3(rng.inertia_body(ma)) : Mat3::Zero();
        a3.inv_I = a1.inv_m > 0 ? Mat3(a3.I.inverse()) : Mat3::Zero();
        b3.I = rng.inertia_body(mb), b3.inv_I = b3.I.inverse();

        const Response1 f1 = frictionless(a1, b1, n, e);
        const Response2 f2 = frictionless(a2, b2, Vec2(n, 0), e);
        const Response3 f3 = frictionless(a3, b3, Vec3(n, 0, 0), e);
        EXPECT_NEAR_ABS_REL(f2.P, Vec2(f1.P, 0), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(f3.P, Vec3(f1.P, 0, 0), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(f2.va, Vec2(f1.va, 0), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(f2.vb, Vec2(f1.vb, 0), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(f3.va, Vec3(f1.va, 0, 0), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(f3.vb, Vec3(f1.vb, 0, 0), kAtol, kRtol);
        EXPECT_EQ(f2.wb, 0.0);
        EXPECT_EQ(f3.wb, Vec3::Zero());

        const Response1 s1 = stick(a1, b1, n);
        const Response2 s2 = stick(a2, b2, Vec2(n, 0));
        const Response3 s3 = stick(a3, b3, Vec3(n, 0, 0));
        EXPECT_NEAR_ABS_REL(s2.va, Vec2(s1.va, 0), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(s2.vb, Vec2(s1.vb, 0), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(s3.va, Vec3(s1.va, 0, 0), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(s3.vb, Vec3(s1.vb, 0, 0), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(s2.wb, 0.0, kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(s3.wb, Vec3(Vec3::Zero()), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(s1.P, f1.P * 1.0 / (1 + e), kAtol, kRtol);  // stick = e 0 on a line
    }
}

// Rotating the whole scene by Q (positions, velocities, spins, tensors Q I Q^T, normal) rotates
// every model's answer: P -> Q P, v -> Q v, w -> Q w. Adding a common velocity V to both
// bodies (static ones too) leaves u, K and so the impulse unchanged and adds V to both
// velocities.
TEST(ConsistencyFrames, RotationAndGalileanBoost) {
    collide_test::Random rng(1005);
    for (const Named3& s : solvers3()) {
        SCOPED_TRACE(s.name);
        for (int i = 0; i < kDraws; ++i) {
            Body3 A = rng.body3(), B = rng.body3();
            if (i % 5 == 1) A.is_static = true;
            const Vec3 p = rng.vec3(-1, 1);
            Vec3 n = rng.unit3();
            if (relative_velocity(at_contact(A, p), at_contact(B, p)).dot(n) > 0) n = -n;
            const Response3 r = s.solve(at_contact(A, p), at_contact(B, p), n);

            const Quat Q = rng.rotation();
            auto turn = [&](Body3 b) {
                b.orientation = Q * b.orientation;
                b.position = Q * b.position;
                b.v = Q * b.v;
                b.w = Q * b.w;
                return b;
            };
            const Response3 t = s.solve(at_contact(turn(A), Q * p), at_contact(turn(B), Q * p), Q * n);
            Response3 expected = r;
            expected.P = Q * r.P;
            expected.couple = Q * r.couple;
            expected.va = Q * r.va, expected.vb = Q * r.vb;
            expected.wa = Q * r.wa, expected.wb = Q * r.wb;
            expect_same3(t, expected);

            const Vec3 V = rng.vec3(-2, 2);
            Body3 A2 = A, B2 = B;
            A2.v += V;
            B2.v += V;
            const Response3 g = s.solve(at_contact(A2, p), at_contact(B2, p), n);
            Response3 boosted = r;
            boosted.va += V;
            boosted.vb += V;
            expect_same3(g, boosted);
        }
    }
}

}  // namespace
