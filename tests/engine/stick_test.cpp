// Perfectly inelastic "stick together" (engine stick(), stick_newton_euler(),
// newton_euler_matrix()): the two bodies continue as one rigid body.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>

#include "engine/diagnostics.h"
#include "engine/mass.h"
#include "engine/response.h"
#include "tests/engine/random_bodies.h"

namespace {

using namespace collide;

constexpr double kAtol = 1e-13;
constexpr double kRtol = 1e-12;

struct Pair3 {
    Body3 A, B;
    Vec3 p, n;
};
Pair3 random_approaching(collide_test::Random& rng) {
    Pair3 s{rng.body3(), rng.body3(), rng.vec3(-1, 1), rng.unit3()};
    if (relative_velocity(at_contact(s.A, s.p), at_contact(s.B, s.p)).dot(s.n) > 0) s.n = -s.n;
    return s;
}

// The page's 6x6 Newton-Euler form, (NEMa + NEMb) V = NEMa Va + NEMb Vb about the contact point,
// is the same physics as the combined body (momentum and angular momentum about p conserved,
// one rigid motion): both functions agree to 1e-12 relative.
TEST(Stick, EqualsNewtonEuler) {
    collide_test::Random rng(701);
    for (int i = 0; i < 5000; ++i) {
        const Pair3 s = random_approaching(rng);
        const ImpactBody3 a = at_contact(s.A, s.p), b = at_contact(s.B, s.p);
        const Response3 x = stick(a, b, s.n), y = stick_newton_euler(a, b, s.n);
        EXPECT_NEAR_ABS_REL(x.va, y.va, 1e-14, 1e-12);
        EXPECT_NEAR_ABS_REL(x.vb, y.vb, 1e-14, 1e-12);
        EXPECT_NEAR_ABS_REL(x.wa, y.wa, 1e-14, 1e-12);
        EXPECT_NEAR_ABS_REL(x.wb, y.wb, 1e-14, 1e-12);
        EXPECT_NEAR_ABS_REL(x.P, y.P, 1e-14, 1e-12);
        EXPECT_NEAR_ABS_REL(x.couple, y.couple, 1e-14, 1e-11);
    }
}

// The Newton-Euler matrix about p of a body is its spatial inertia: acting on (w, v_p) (v_p the
// velocity of the body's material point at p) it gives (angular momentum about p, linear
// momentum):  L_p = I w + m (x - p) x v,  p_lin = m v, with v = v_p + w x (x - p) the centre's
// velocity; and 1/2 V.NEM V is the kinetic energy 1/2 m v.v + 1/2 w.I w. Hence it is symmetric
// positive definite (for a body with positive definite I).
TEST(NewtonEulerMatrix, IsTheSpatialInertia) {
    collide_test::Random rng(702);
    for (int i = 0; i < 2000; ++i) {
        const Body3 B = rng.body3();
        const Vec3 p = rng.vec3(-1, 1);
        const ImpactBody3 b = at_contact(B, p);
        const Mat6 N = newton_euler_matrix(b);
        EXPECT_NEAR_ABS_REL(N, Mat6(N.transpose()), 0.0, 1e-14);
        Eigen::SelfAdjointEigenSolver<Mat6> eig(N);
        EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);

        Vec6 V;
        V << B.w, point_velocity(b);
        const Vec6 h = N * V;
        const Mat3 I = B.inertia_world();
        const Vec3 Lp = I * B.w + B.mass * (B.position - p).cross(B.v);
        const double scale = (I * B.w).norm() + B.mass * (B.position - p).norm() * B.v.norm();
        EXPECT_NEAR_SCALED(Vec3(h.head<3>()), Lp, kAtol, kRtol, scale);
        EXPECT_NEAR_ABS_REL(Vec3(h.tail<3>()), Vec3(B.mass * B.v), kAtol, kRtol);
        const double ke = 0.5 * B.mass * B.v.squaredNorm() + 0.5 * B.w.dot(I * B.w);
        EXPECT_NEAR_ABS_REL(0.5 * V.dot(h), ke, kAtol, 1e-11);
    }
}

// Combined rigid motion: afterwards both bodies have the same w, and their centres move as points
// of one rigid body: vb - va = w x (xb - xa). Momentum is conserved (see also
// conservation_test.cpp); energy is never gained.
TEST(Stick, OneRigidMotionAfterwards) {
    collide_test::Random rng(703);
    for (int i = 0; i < 2000; ++i) {
        const Pair3 s = random_approaching(rng);
        const Response3 r = stick(at_contact(s.A, s.p), at_contact(s.B, s.p), s.n);
        EXPECT_NEAR_ABS_REL(r.wa, r.wb, 0.0, 0.0);
        const Vec3 rigid = r.wa.cross(s.B.position - s.A.position);
        EXPECT_NEAR_SCALED(Vec3(r.vb - r.va), rigid, kAtol, kRtol, r.va.norm() + r.vb.norm() + rigid.norm());
    }
}

// A static partner (infinite mass) moving at a prescribed (v_s, w_s) carries the other body
// with its own rigid motion: wb' = w_s, vb' = v_s + w_s x (xb - xs). Either order.
TEST(Stick, StaticPartnerCarriesTheBody) {
    collide_test::Random rng(704);
    for (int i = 0; i < 500; ++i) {
        Pair3 s = random_approaching(rng);
        s.A.is_static = true;  // moves at A.v, A.w, prescribed
        const ImpactBody3 a = at_contact(s.A, s.p), b = at_contact(s.B, s.p);
        Vec3 n = s.n;
        if (relative_velocity(a, b).dot(n) > 0) n = -n;
        const Vec3 expected_v = s.A.v + s.A.w.cross(s.B.position - s.A.position);
        const Response3 r = stick(a, b, n);
        EXPECT_NEAR_ABS_REL(r.wb, s.A.w, kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(r.vb, expected_v, kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(r.va, s.A.v, kAtol, kRtol);  // the static body keeps its motion
        // Swapped: the static body as B.
        const Response3 q = stick(b, a, -n);
        EXPECT_NEAR_ABS_REL(q.wa, s.A.w, kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(q.va, expected_v, kAtol, kRtol);
        // B's change of momentum is the impulse it received: m (vb' - vb) = P (P on B).
        EXPECT_NEAR_ABS_REL(Vec3(s.B.mass * (r.vb - s.B.v)), r.P, kAtol, kRtol);
        const Response3 y = stick_newton_euler(a, b, n);
        EXPECT_NEAR_ABS_REL(y.vb, expected_v, kAtol, kRtol);
    }
}

// Point masses meeting at p (r = 0, no spin): the common velocity is total momentum / total mass,
// (2 (3, 0, 1) + 6 (-1, 2, 1)) / 8 = (0, 1.5, 1); no rotation arises (L about p is zero).
TEST(Stick, PointMassesCommonVelocity) {
    ImpactBody3 a, b;
    a.inv_m = 0.5;
    a.I = Mat3::Identity() * 0.1;
    a.inv_I = a.I.inverse();
    a.v = Vec3(3, 0, 1);
    b.inv_m = 1.0 / 6.0;
    b.I = Mat3::Identity() * 0.2;
    b.inv_I = b.I.inverse();
    b.v = Vec3(-1, 2, 1);
    const Response3 r = stick(a, b, Vec3::UnitX());
    EXPECT_NEAR_ABS_REL(r.va, Vec3(0, 1.5, 1), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.vb, Vec3(0, 1.5, 1), kAtol, kRtol);
    EXPECT_LE(r.wa.norm(), 1e-15);
    EXPECT_NEAR_ABS_REL(stick_newton_euler(a, b, Vec3::UnitX()).va, Vec3(0, 1.5, 1), kAtol, kRtol);
}

// Two identical solid spheres (m, R) meet head-on, off-centre by b (impact parameter), at +-v
// along x. Centres xa = (-h, -b/2, 0), xb = (h, b/2, 0), h = sqrt(4 R^2 - b^2)/2, touching at
// p = 0; n = (xb - xa)/(2R). The common centre is p and total momentum is zero, so v' = 0.
// L about 0: m xa x (v, 0, 0) + m xb x (-v, 0, 0) = (0, 0, m v b/2 + m v b/2) = (0, 0, m v b).
// Inertia about z: 2 (2/5 m R^2) + 2 m R^2 (each centre is R from p) = 14/5 m R^2, so
//   w = 5 b v / (14 R^2) about +z (counter-clockwise: the upper sphere B moved left),
// and each centre moves with w x x.
TEST(Stick, IdenticalSpheresOffCentreSpin) {
    const double m = 0.4, R = 0.1, v = 2.0, b = 0.08;
    const double h = 0.5 * std::sqrt(4 * R * R - b * b);
    Body3 A, B;
    A.mass = B.mass = m;
    A.inertia = B.inertia = sphere_inertia(m, R);
    A.position = Vec3(-h, -0.5 * b, 0);
    B.position = Vec3(h, 0.5 * b, 0);
    A.v = Vec3(v, 0, 0);
    B.v = Vec3(-v, 0, 0);
    A.orientation = Quat(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
    const Vec3 p = Vec3::Zero(), n = (B.position - A.position) / (2 * R);
    ASSERT_NEAR((B.position - A.position).norm(), 2 * R, 1e-14);
    const Vec3 w(0, 0, 5 * b * v / (14 * R * R));
    for (const Response3& r :
         {stick(at_contact(A, p), at_contact(B, p), n), stick_newton_euler(at_contact(A, p), at_contact(B, p), n)}) {
        EXPECT_NEAR_ABS_REL(r.wa, w, kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(r.wb, w, kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(r.va, Vec3(w.cross(A.position)), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(r.vb, Vec3(w.cross(B.position)), kAtol, kRtol);
    }
}

// combined_body() for the spheres above, positions relative to p = 0: M = 2 m, xc = 0,
// da = xa, db = xb (|da| = |db| = R), I = 2 (2/5 m R^2) E + m (R^2 E - da da^T) + m (R^2 E - db db^T)
// = (14/5 m R^2) E - 2 m da da^T (db = -da), Izz = 14/5 m R^2; v = 0; L = (0, 0, m v b).
TEST(CombinedBody, IdenticalSpheresHandValues) {
    const double m = 0.4, R = 0.1, v = 2.0, b = 0.08;
    const double h = 0.5 * std::sqrt(4 * R * R - b * b);
    ImpactBody3 A, B;
    A.inv_m = B.inv_m = 1 / m;
    A.I = B.I = sphere_inertia(m, R);
    A.inv_I = B.inv_I = A.I.inverse();
    const Vec3 xa(-h, -0.5 * b, 0), xb(h, 0.5 * b, 0);
    A.r = -xa;  // p = 0
    B.r = -xb;
    A.v = Vec3(v, 0, 0);
    B.v = Vec3(-v, 0, 0);
    const Combined3 c = combined_body(A, B);
    EXPECT_NEAR_ABS_REL(c.M, 2 * m, kAtol, kRtol);
    EXPECT_LE(c.xc.norm(), 1e-16);
    EXPECT_NEAR_ABS_REL(c.da, xa, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(c.db, xb, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(c.I, Mat3(2.8 * m * R * R * Mat3::Identity() - 2 * m * xa * xa.transpose()), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(c.I(2, 2), 2.8 * m * R * R, kAtol, kRtol);
    EXPECT_LE(c.v.norm(), 1e-16);
    EXPECT_NEAR_ABS_REL(c.L, Vec3(0, 0, m * v * b), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(c.w, Vec3(0, 0, 5 * b * v / (14 * R * R)), kAtol, kRtol);
    // 2D: the same numbers about z.
    ImpactBody2 A2, B2;
    A2.inv_m = B2.inv_m = 1 / m;
    A2.I = B2.I = 0.4 * m * R * R;
    A2.inv_I = B2.inv_I = 1 / A2.I;
    A2.r = -xa.head<2>();
    B2.r = -xb.head<2>();
    A2.v = Vec2(v, 0);
    B2.v = Vec2(-v, 0);
    const Combined2 c2 = combined_body(A2, B2);
    EXPECT_NEAR_ABS_REL(c2.M, 2 * m, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(c2.I, 2.8 * m * R * R, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(c2.L, m * v * b, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(c2.w, 5 * b * v / (14 * R * R), kAtol, kRtol);
}

// combined_body() for random pairs, against the definitions: xc (relative to p) is the centre of
// mass (ma xa + mb xb)/M, da = xa - xc, db = xb - xc; v = total momentum / M; L is the total
// angular momentum about the common centre p + xc (computed independently by totals()); I is
// symmetric positive definite and I w = L.
TEST(CombinedBody, RandomPairsMatchDefinitions) {
    collide_test::Random rng(706);
    for (int i = 0; i < 2000; ++i) {
        const Body3 A = rng.body3(), B = rng.body3();
        const Vec3 p = rng.vec3(-1, 1);
        const Combined3 c = combined_body(at_contact(A, p), at_contact(B, p));
        const double M = A.mass + B.mass;
        const Vec3 centre = (A.mass * A.position + B.mass * B.position) / M;
        EXPECT_NEAR_ABS_REL(c.M, M, 0.0, 1e-14);
        EXPECT_NEAR_ABS_REL(Vec3(p + c.xc), centre, kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(c.da, Vec3(A.position - centre), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(c.db, Vec3(B.position - centre), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(c.v, Vec3(totals({A, B}).momentum / M), kAtol, kRtol);
        EXPECT_NEAR_SCALED(c.L, totals({A, B}, centre).angular_momentum, kAtol, kRtol,
                           (A.inertia_world() * A.w).norm() + (B.inertia_world() * B.w).norm() +
                               A.mass * c.da.norm() * A.v.norm() + B.mass * c.db.norm() * B.v.norm());
        EXPECT_NEAR_ABS_REL(c.I, Mat3(c.I.transpose()), 0.0, 1e-14);
        EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat3>(c.I).eigenvalues().minCoeff(), 0.0);
        EXPECT_NEAR_ABS_REL(Vec3(c.I * c.w), c.L, kAtol, 1e-11);
        // Kinetic energy of the combined motion: 1/2 M v^2 + 1/2 w.I w (<= the bodies' total).
        const double ke = 0.5 * M * c.v.squaredNorm() + 0.5 * c.w.dot(c.I * c.w);
        EXPECT_LE(ke, totals({A, B}).kinetic_energy * (1 + 1e-12));
    }
}

// The same in 2D with discs of the sphere's moment 2/5 m R^2: w = 5 b v / (14 R^2).
TEST(Stick, IdenticalSpheresOffCentreSpin2D) {
    const double m = 0.4, R = 0.1, v = 2.0, b = 0.08;
    const double h = 0.5 * std::sqrt(4 * R * R - b * b);
    Body2 A, B;
    A.mass = B.mass = m;
    A.inertia = B.inertia = 0.4 * m * R * R;
    A.position = Vec2(-h, -0.5 * b);
    B.position = Vec2(h, 0.5 * b);
    A.v = Vec2(v, 0);
    B.v = Vec2(-v, 0);
    const Vec2 p = Vec2::Zero(), n = (B.position - A.position) / (2 * R);
    const Response2 r = stick(at_contact(A, p), at_contact(B, p), n);
    const double w = 5 * b * v / (14 * R * R);
    EXPECT_NEAR_ABS_REL(r.wa, w, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.wb, w, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.vb, cross(w, B.position), kAtol, kRtol);
}

// 2D static partner: the disc ends with the static body's rigid motion.
TEST(Stick, StaticPartnerCarriesTheBody2D) {
    Body2 wall;
    wall.is_static = true;
    wall.position = Vec2(0, -1);
    wall.v = Vec2(0.5, 0);
    wall.w = 0.2;
    Body2 disc;
    disc.mass = 2.0;
    disc.inertia = 0.1;
    disc.position = Vec2(1, 0.3);
    disc.v = Vec2(-1, -2);
    disc.w = 3.0;
    const Vec2 p(1, 0);
    const Response2 r = stick(at_contact(wall, p), at_contact(disc, p), Vec2(0, 1));
    // v = (0.5, 0) + 0.2 z x ((1, 0.3) - (0, -1)) = (0.5, 0) + 0.2 (-1.3, 1) = (0.24, 0.2).
    EXPECT_NEAR_ABS_REL(r.vb, Vec2(0.24, 0.2), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.wb, 0.2, kAtol, kRtol);
}

// Stick never gains energy: the combined rigid motion is the least-energy motion with the given
// momentum and angular momentum (random 3D pairs).
TEST(Stick, NeverGainsEnergy) {
    collide_test::Random rng(705);
    for (int i = 0; i < 2000; ++i) {
        Pair3 s = random_approaching(rng);
        const Response3 r = stick(at_contact(s.A, s.p), at_contact(s.B, s.p), s.n);
        const double before = totals({s.A, s.B}).kinetic_energy;
        s.A.v = r.va, s.A.w = r.wa, s.B.v = r.vb, s.B.w = r.wb;
        EXPECT_LE(totals({s.A, s.B}).kinetic_energy, before * (1 + 1e-12));
    }
}

}  // namespace
