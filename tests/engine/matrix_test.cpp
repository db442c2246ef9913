// The collision matrix K and the page's matrix model (P = -(1 + e) K^-1 u).
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>

#include "engine/mass.h"
#include "engine/page.h"
#include "engine/response.h"
#include "tests/engine/random_bodies.h"

namespace {

using namespace collide;

constexpr double kAtol = 1e-13;
constexpr double kRtol = 1e-12;

// Relative contact velocity after a response, recomputed from its velocities.
Vec3 u_after(ImpactBody3 a, ImpactBody3 b, const Response3& r) {
    a.v = r.va, a.w = r.wa, b.v = r.vb, b.w = r.wb;
    return relative_velocity(a, b);
}
Vec2 u_after(ImpactBody2 a, ImpactBody2 b, const Response2& r) {
    a.v = r.va, a.w = r.wa, b.v = r.vb, b.w = r.wb;
    return relative_velocity(a, b);
}

// K is symmetric positive definite: K = (1/ma + 1/mb) E + [ra]x^T Ia^-1 [ra]x + ..., the sum of
// a positive multiple of E and positive semi-definite terms. Also with one static body
// (its terms vanish) and for a thin rod (singular inertia, pseudo-inverse).
TEST(CollisionMatrix, SymmetricPositiveDefinite) {
    collide_test::Random rng(601);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p = rng.vec3(-1, 1);
        Body3 A = rng.body3(), B = rng.body3();
        if (i % 4 == 1) A.is_static = true;
        if (i % 4 == 2) B.inertia = rod_inertia(B.mass, rng.uniform(0.2, 2.0));
        const Mat3 K = collision_matrix(at_contact(A, p), at_contact(B, p));
        EXPECT_NEAR_ABS_REL(K, Mat3(K.transpose()), 0.0, 1e-14);
        Eigen::SelfAdjointEigenSolver<Mat3> eig(K);
        // Every eigenvalue is at least 1/ma + 1/mb (the other terms are semi-definite).
        EXPECT_GE(eig.eigenvalues().minCoeff(), (A.inv_mass() + B.inv_mass()) * (1 - 1e-12));

        Body2 A2 = rng.body2(), B2 = rng.body2();
        if (i % 4 == 1) B2.is_static = true;
        const Vec2 p2 = rng.vec2(-1, 1);
        const Mat2 K2 = collision_matrix(at_contact(A2, p2), at_contact(B2, p2));
        EXPECT_NEAR_ABS_REL(K2, Mat2(K2.transpose()), 0.0, 1e-14);
        Eigen::SelfAdjointEigenSolver<Mat2> eig2(K2);
        EXPECT_GE(eig2.eigenvalues().minCoeff(), (A2.inv_mass() + B2.inv_mass()) * (1 - 1e-12));
    }
}

// The frictionless denominator is n.K n: with [r]x^T = -[r]x,
// n.(-[r]x I^-1 [r]x) n = ([r]x n).I^-1 ([r]x n) = (r x n).I^-1 (r x n), the rotational term.
// So n.K n = 1/ma + 1/mb + rotational_term(a, n) + rotational_term(b, n), and the frictionless
// impulse is j = -(1 + e) un / (n.K n).
TEST(CollisionMatrix, NormalEntryIsTheFrictionlessDenominator) {
    collide_test::Random rng(604);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p = rng.vec3(-1, 1);
        const ImpactBody3 a = at_contact(rng.body3(), p), b = at_contact(rng.body3(), p);
        Vec3 n = rng.unit3();
        if (relative_velocity(a, b).dot(n) > 0) n = -n;
        const double nKn = n.dot(collision_matrix(a, b) * n);
        EXPECT_NEAR_ABS_REL(a.inv_m + b.inv_m + rotational_term(a, n) + rotational_term(b, n), nKn, 0.0, 1e-12);
        const double e = rng.uniform(0, 1);
        EXPECT_NEAR_ABS_REL(frictionless(a, b, n, e).P, Vec3(-(1 + e) * relative_velocity(a, b).dot(n) / nKn * n),
                            kAtol, kRtol);

        const Vec2 p2 = rng.vec2(-1, 1);
        const ImpactBody2 a2 = at_contact(rng.body2(), p2), b2 = at_contact(rng.body2(), p2);
        Vec2 n2 = rng.unit2();
        if (relative_velocity(a2, b2).dot(n2) > 0) n2 = -n2;
        const double nKn2 = n2.dot(collision_matrix(a2, b2) * n2);
        EXPECT_NEAR_ABS_REL(a2.inv_m + b2.inv_m + rotational_term(a2, n2) + rotational_term(b2, n2), nKn2, 0.0, 1e-12);
        EXPECT_NEAR_ABS_REL(frictionless(a2, b2, n2, e).P,
                            Vec2(-(1 + e) * relative_velocity(a2, b2).dot(n2) / nKn2 * n2), kAtol, kRtol);
    }
}

// Solid sphere (m, R) on static ground, rb = (0, -R, 0):
// -[r]x I^-1 [r]x = (R^2/I)(E - y y^T), I = 2/5 m R^2: K = diag(7/(2m), 1/m, 7/(2m)).
// 2D disc (I = m R^2/2), rb = (0, -R): perp(rb) = (R, 0), K = diag(1/m + R^2/I, 1/m) = diag(3/m, 1/m).
TEST(CollisionMatrix, SphereAndDiscOnGroundHandValues) {
    const double m = 2.0, R = 0.4;
    ImpactBody3 ground;
    ground.r = Vec3(0.3, 1.0, -0.2);
    ImpactBody3 ball;
    ball.inv_m = 1 / m;
    ball.inv_I = Mat3::Identity() / (0.4 * m * R * R);
    ball.I = Mat3::Identity() * (0.4 * m * R * R);
    ball.r = Vec3(0, -R, 0);
    EXPECT_NEAR_ABS_REL(collision_matrix(ground, ball), Mat3(Vec3(3.5 / m, 1 / m, 3.5 / m).asDiagonal()), kAtol, kRtol);
    ImpactBody2 ground2;
    ImpactBody2 disc;
    disc.inv_m = 1 / m;
    disc.I = 0.5 * m * R * R;
    disc.inv_I = 1 / disc.I;
    disc.r = Vec2(0, -R);
    EXPECT_NEAR_ABS_REL(collision_matrix(ground2, disc), Mat2(Vec2(3 / m, 1 / m).asDiagonal()), kAtol, kRtol);
}

// K P is the change of u caused by P (+P on B, -P on A): apply_impulse with a random P and
// compare the recomputed u with u + K P. Also the page's corrected point-velocity change:
// du = delta_vp(b, P) - delta_vp(a, -P) = delta_vp(b, P) + delta_vp(a, P).
TEST(CollisionMatrix, KPIsTheChangeOfU) {
    collide_test::Random rng(602);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p = rng.vec3(-1, 1);
        const ImpactBody3 a = at_contact(rng.body3(), p), b = at_contact(rng.body3(), p);
        Response3 r;
        r.P = rng.vec3(-2, 2);
        apply_impulse(a, b, &r);
        const Vec3 du = u_after(a, b, r) - relative_velocity(a, b);
        const Vec3 KP = collision_matrix(a, b) * r.P;
        const double scale = relative_velocity(a, b).norm() + KP.norm();
        EXPECT_NEAR_SCALED(du, KP, kAtol, kRtol, scale);
        EXPECT_NEAR_SCALED(Vec3(page::delta_vp(b, r.P) + page::delta_vp(a, r.P)), KP, kAtol, kRtol, scale);

        const Vec2 p2 = rng.vec2(-1, 1);
        const ImpactBody2 a2 = at_contact(rng.body2(), p2), b2 = at_contact(rng.body2(), p2);
        Response2 r2;
        r2.P = rng.vec2(-2, 2);
        apply_impulse(a2, b2, &r2);
        const Vec2 du2 = u_after(a2, b2, r2) - relative_velocity(a2, b2);
        const Vec2 KP2 = collision_matrix(a2, b2) * r2.P;
        EXPECT_NEAR_SCALED(du2, KP2, kAtol, kRtol, relative_velocity(a2, b2).norm() + KP2.norm());
    }
}

// The matrix model: K P = -(1 + e) u, so u' = u + K P = -e u: the whole relative velocity,
// tangential part included, is reversed and scaled by e. Approaching pairs only.
TEST(MatrixModel, ReversesTheWholeRelativeVelocity) {
    collide_test::Random rng(603);
    for (int i = 0; i < 2000; ++i) {
        const double e = rng.uniform(0, 1);
        const Vec3 p = rng.vec3(-1, 1);
        const ImpactBody3 a = at_contact(rng.body3(), p), b = at_contact(rng.body3(), p);
        Vec3 n = rng.unit3();
        const Vec3 u = relative_velocity(a, b);
        if (u.dot(n) > 0) n = -n;
        const Response3 r = matrix(a, b, n, e);
        ASSERT_FALSE(r.separating);
        const double scale = u.norm() + a.v.norm() + b.v.norm() + a.r.norm() * a.w.norm() + b.r.norm() * b.w.norm();
        EXPECT_NEAR_SCALED(u_after(a, b, r), Vec3(-e * u), kAtol, 1e-11, scale);
        EXPECT_NEAR_ABS_REL(Vec3(collision_matrix(a, b) * r.P), Vec3(-(1 + e) * u), kAtol, 1e-11);

        const Vec2 p2 = rng.vec2(-1, 1);
        const ImpactBody2 a2 = at_contact(rng.body2(), p2), b2 = at_contact(rng.body2(), p2);
        Vec2 n2 = rng.unit2();
        const Vec2 u2 = relative_velocity(a2, b2);
        if (u2.dot(n2) > 0) n2 = -n2;
        const Response2 r2 = matrix(a2, b2, n2, e);
        const double scale2 =
            u2.norm() + a2.v.norm() + b2.v.norm() + a2.r.norm() * std::abs(a2.w) + b2.r.norm() * std::abs(b2.w);
        EXPECT_NEAR_SCALED(u_after(a2, b2, r2), Vec2(-e * u2), kAtol, 1e-11, scale2);
    }
}

// Superball: a solid sphere (m, R) with velocity (vt, -vn, 0) and spin wz hits static ground.
// u = (vt + wz R, -vn, 0), K = diag(7/(2m), 1/m, 7/(2m)) (above), P = -(1 + e) K^-1 u:
//   Px = -(1 + e)(2/7) m (vt + wz R), Py = (1 + e) m vn,
//   vt' = vt - (1 + e)(2/7)(vt + wz R), wz' = wz + R Px/I = wz - (1 + e)(5/7)(vt + wz R)/R.
// e = 1: vt' = (3 vt - 4 R wz)/7, R wz' = (-10 vt - 3 R wz)/7, and the contact slip reverses:
// vt' + R wz' = -(vt + R wz). Numbers: vt = 2, wz = 1, R = 0.5, vn = 3:
// vt' = (6 - 2)/7 = 4/7, wz' = (-20 - 1.5)/(7 * 0.5) = -43/7, vy' = 3.
TEST(MatrixModel, SuperballClosedForm) {
    const double m = 0.05, R = 0.5, vt = 2.0, wz = 1.0, vn = 3.0;
    Body3 ball;
    ball.mass = m;
    ball.inertia = sphere_inertia(m, R);
    ball.position = Vec3(0, R, 0);
    ball.v = Vec3(vt, -vn, 0);
    ball.w = Vec3(0, 0, wz);
    Body3 ground;
    ground.is_static = true;
    const Vec3 p = Vec3::Zero();
    const Response3 r = matrix(at_contact(ground, p), at_contact(ball, p), Vec3::UnitY(), 1.0);
    EXPECT_NEAR_ABS_REL(r.vb, Vec3(4.0 / 7.0, vn, 0.0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.wb, Vec3(0.0, 0.0, -43.0 / 7.0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.vb.x() + R * r.wb.z(), -(vt + R * wz), kAtol, kRtol);
    // Energy is kept (e = 1): 1/2 m v^2 + 1/2 I w^2 before and after.
    const double I = 0.4 * m * R * R;
    EXPECT_NEAR_ABS_REL(0.5 * m * r.vb.squaredNorm() + 0.5 * I * r.wb.squaredNorm(),
                        0.5 * m * ball.v.squaredNorm() + 0.5 * I * ball.w.squaredNorm(), kAtol, kRtol);
}

// The matrix model can pull: reversing the whole relative velocity may need a negative normal
// impulse. Thin rod (m, L) leaning at 45 degrees on static ground, foot at rb = -(L/2)(c, s), no
// spin, foot velocity u = (ux, -v). With m K = [[1 + 3 s^2, -3 s c], [-3 s c, 1 + 3 c^2]] (det 4):
//   P = -(1 + e) K^-1 u = (1 + e)(m/4) [[1 + 3 c^2, 3 s c], [3 s c, 1 + 3 s^2]] (-ux, v),
//   Pn = (1 + e)(m/4)(-3 s c ux + (1 + 3 s^2) v) < 0 once ux > (1 + 3 s^2) v/(3 s c) = 5v/3.
// ux = 2, v = 1, m = 1, e = 0.5: P = 1.5/4 (-2.5*2 + 1.5, -1.5*2 + 2.5) = (-1.3125, -0.1875):
// the ground pulls the foot down while the foot still ends separating, u' = -e u = (-1, 0.5).
// (The frictionless and Coulomb models never pull here.)
TEST(MatrixModel, CanPullTheBodiesTogether) {
    const double m = 1.0, L = 1.0, e = 0.5, t = collide_test::kPi / 4;
    Body2 ground;
    ground.is_static = true;
    Body2 rod;
    rod.mass = m;
    rod.inertia = rod_inertia_2d(m, L);
    rod.angle = t;
    rod.position = Vec2(0.0, 0.5 * L * std::sin(t));
    rod.v = Vec2(2.0, -1.0);
    const Vec2 p(-0.5 * L * std::cos(t), 0.0);
    const ImpactBody2 a = at_contact(ground, p), b = at_contact(rod, p);
    const Response2 r = matrix(a, b, Vec2(0, 1), e);
    EXPECT_NEAR_ABS_REL(r.P, Vec2(-1.3125, -0.1875), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(u_after(a, b, r), Vec2(-1.0, 0.5), kAtol, kRtol);
    EXPECT_GT(frictionless(a, b, Vec2(0, 1), e).P.y(), 0.0);
    EXPECT_GE(coulomb(a, b, Vec2(0, 1), e, 0.5).P.y(), 0.0);
}

// The matrix model differs from the frictionless one whenever u has a tangential part: for the
// superball above the frictionless impulse is vertical, the matrix one is not.
TEST(MatrixModel, DiffersFromFrictionlessWithTangentialSlip) {
    const double m = 0.05, R = 0.5;
    ImpactBody3 ground;
    ImpactBody3 ball;
    ball.inv_m = 1 / m;
    ball.I = Mat3::Identity() * (0.4 * m * R * R);
    ball.inv_I = ball.I.inverse();
    ball.r = Vec3(0, -R, 0);
    ball.v = Vec3(2, -3, 0);
    const Response3 mx = matrix(ground, ball, Vec3::UnitY(), 1.0);
    const Response3 fr = frictionless(ground, ball, Vec3::UnitY(), 1.0);
    EXPECT_NEAR_ABS_REL(fr.P, Vec3(0, 2 * m * 3, 0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(mx.P, Vec3(-2 * (2.0 / 7.0) * m * 2, 2 * m * 3, 0), kAtol, kRtol);
}

}  // namespace
