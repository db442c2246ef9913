// Coulomb friction, one step (engine coulomb()): limits (mu = 0, huge mu), closed-form sliding
// and sticking cases, and the properties every result must have.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/mass.h"
#include "engine/response.h"
#include "tests/engine/random_bodies.h"

namespace {

using namespace collide;
using collide_test::kPi;

constexpr double kAtol = 1e-13;
constexpr double kRtol = 1e-12;

Body3 static_ground3() {
    Body3 g;
    g.is_static = true;
    g.position = Vec3(0.0, -1.0, 0.0);
    return g;
}
Body2 static_ground2() {
    Body2 g;
    g.is_static = true;
    g.position = Vec2(0.0, -1.0);
    return g;
}

// Random approaching pair: random bodies, contact point and normal; n is flipped so that
// un < 0 (draws with un = 0 are skipped by the caller's check).
struct Pair3 {
    ImpactBody3 a, b;
    Vec3 n;
};
Pair3 random_pair3(collide_test::Random& rng) {
    const Body3 A = rng.body3(), B = rng.body3();
    const Vec3 p = rng.vec3(-1, 1);
    Pair3 s{at_contact(A, p), at_contact(B, p), rng.unit3()};
    if (relative_velocity(s.a, s.b).dot(s.n) > 0.0) s.n = -s.n;
    return s;
}
struct Pair2 {
    ImpactBody2 a, b;
    Vec2 n;
};
Pair2 random_pair2(collide_test::Random& rng) {
    const Body2 A = rng.body2(), B = rng.body2();
    const Vec2 p = rng.vec2(-1, 1);
    Pair2 s{at_contact(A, p), at_contact(B, p), rng.unit2()};
    if (relative_velocity(s.a, s.b).dot(s.n) > 0.0) s.n = -s.n;
    return s;
}

// mu = 0: the friction cone is the normal ray; the sticking impulse (which has a tangential
// part) leaves it, and the sliding impulse j (n - 0 t) with j = -(1 + e) un/(n.K n) is the
// frictionless one, since n.K n = 1/ma + 1/mb + (ra x n).Ia^-1 (ra x n) + (rb x n).Ib^-1 (rb x n).
TEST(Coulomb, MuZeroIsFrictionless) {
    collide_test::Random rng(501);
    for (int i = 0; i < 2000; ++i) {
        const Pair3 s = random_pair3(rng);
        const double e = rng.uniform(0, 1);
        const Response3 c = coulomb(s.a, s.b, s.n, e, 0.0), f = frictionless(s.a, s.b, s.n, e);
        EXPECT_NEAR_ABS_REL(c.P, f.P, kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(c.vb, f.vb, kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(c.wa, f.wa, kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(c.wb, f.wb, kAtol, kRtol);

        const Pair2 t = random_pair2(rng);
        const Response2 c2 = coulomb(t.a, t.b, t.n, e, 0.0), f2 = frictionless(t.a, t.b, t.n, e);
        EXPECT_NEAR_ABS_REL(c2.P, f2.P, kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(c2.va, f2.va, kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(c2.wb, f2.wb, kAtol, kRtol);
    }
}

// Huge mu (1e6), e = 0: the sticking impulse K^-1 (-u) is the matrix model's
// -(1 + 0) K^-1 u. Whenever it pushes (P.n > 0) it lies inside a cone that wide, and coulomb
// returns it. (When it would pull, P.n < 0, no friction cone contains it and the models differ:
// those draws are counted, not compared.)
TEST(Coulomb, HugeMuElasticZeroIsMatrix) {
    collide_test::Random rng(502);
    int compared3 = 0, compared2 = 0;
    for (int i = 0; i < 2000; ++i) {
        const Pair3 s = random_pair3(rng);
        const Response3 m = matrix(s.a, s.b, s.n, 0.0);
        if (m.P.dot(s.n) > 1e-6 * m.P.norm()) {
            ++compared3;
            const Response3 c = coulomb(s.a, s.b, s.n, 0.0, 1e6);
            EXPECT_FALSE(c.sliding);
            EXPECT_NEAR_ABS_REL(c.P, m.P, kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(c.va, m.va, kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(c.wb, m.wb, kAtol, kRtol);
        }
        const Pair2 t = random_pair2(rng);
        const Response2 m2 = matrix(t.a, t.b, t.n, 0.0);
        if (m2.P.dot(t.n) > 1e-6 * m2.P.norm()) {
            ++compared2;
            const Response2 c2 = coulomb(t.a, t.b, t.n, 0.0, 1e6);
            EXPECT_FALSE(c2.sliding);
            EXPECT_NEAR_ABS_REL(c2.P, m2.P, kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(c2.wa, m2.wa, kAtol, kRtol);
        }
    }
    // Most draws push; the comparison is not vacuous.
    EXPECT_GT(compared3, 1000);
    EXPECT_GT(compared2, 1000);
}

// Solid sphere (m, R) falls on static ground (A) with velocity (vt, -vn, 0), no spin; n = +y,
// rb = (0, -R, 0). K = (1/m) E + (R^2/I)(E - y y^T) = diag(7/(2m), 1/m, 7/(2m)) (I = 2/5 m R^2).
// Sticking impulse K^-1 ((-e un) n - u) = (-(2/7) m vt, (1 + e) m vn, 0): it would need
// |Pt|/Pn = 2 vt/(7 (1 + e) vn) = 6/(7 * 1.5 * 2) = 0.286 > mu = 0.1, so the sphere slides:
//   t = +x, n.K (n - mu t) = 1/m, j = (1 + e) m vn, P = (-mu j, j, 0)  (|Pt| = mu Pn exactly,
//   against the slip), vb' = (vt - mu (1 + e) vn, e vn, 0),
//   wb' = I^-1 (rb x P) = I^-1 (0, 0, -R mu j) = (0, 0, -5 mu j/(2 m R)),
// and the contact still slips forward: vt' + wz' R = vt - (7/2) mu (1 + e) vn = 3 - 1.05 > 0.
TEST(Coulomb, SphereSlidesOnGroundClosedForm) {
    const double m = 2.0, R = 0.3, vt = 3.0, vn = 2.0, e = 0.5, mu = 0.1;
    Body3 ball;
    ball.mass = m;
    ball.inertia = sphere_inertia(m, R);
    ball.position = Vec3(0.0, R, 0.0);
    ball.v = Vec3(vt, -vn, 0.0);
    const Vec3 p = Vec3::Zero();
    const ImpactBody3 a = at_contact(static_ground3(), p), b = at_contact(ball, p);
    const Response3 r = coulomb(a, b, Vec3::UnitY(), e, mu);
    const double j = (1 + e) * m * vn;
    EXPECT_TRUE(r.sliding);
    EXPECT_NEAR_ABS_REL(r.P, Vec3(-mu * j, j, 0.0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.vb, Vec3(vt - mu * (1 + e) * vn, e * vn, 0.0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.wb, Vec3(0.0, 0.0, -5.0 * mu * j / (2 * m * R)), kAtol, kRtol);
    const Vec3 slip = r.vb + r.wb.cross(b.r);
    EXPECT_NEAR_ABS_REL(slip, Vec3(vt - 3.5 * mu * (1 + e) * vn, e * vn, 0.0), kAtol, kRtol);
}

// 2D: a disc (I = m R^2/2) in the same throw. K = diag(1/m + R^2/I, 1/m) = diag(3/m, 1/m);
// sticking would need |Pt|/Pn = vt/(3 (1 + e) vn) = 1/3 > mu = 0.1: slides,
// P = (-mu j, j), j = (1 + e) m vn, vb' = (vt - mu (1 + e) vn, e vn),
// wb' = (rb x P)/I = (0 (j) - (-R)(-mu j))/I = -mu j R/I = -2 mu j/(m R).
TEST(Coulomb, DiscSlidesOnGroundClosedForm2D) {
    const double m = 2.0, R = 0.3, vt = 3.0, vn = 2.0, e = 0.5, mu = 0.1;
    Body2 disc;
    disc.mass = m;
    disc.inertia = disc_inertia_2d(m, R);
    disc.position = Vec2(0.0, R);
    disc.v = Vec2(vt, -vn);
    const Vec2 p = Vec2::Zero();
    const Response2 r = coulomb(at_contact(static_ground2(), p), at_contact(disc, p), Vec2(0, 1), e, mu);
    const double j = (1 + e) * m * vn;
    EXPECT_TRUE(r.sliding);
    EXPECT_NEAR_ABS_REL(r.P, Vec2(-mu * j, j), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.vb, Vec2(vt - mu * (1 + e) * vn, e * vn), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.wb, -2.0 * mu * j / (m * R), kAtol, kRtol);
}

// Solid sphere with backspin hits the ground, e = 0, large mu: it sticks and then rolls.
// u = v + w x rb = (vt + wz R, -vn, 0) (w x (0, -R, 0) = (wz R, 0, -wx R) with wx = 0).
// Sticking impulse K^-1 (-u) = (-(2/7) m (vt + wz R), m vn, 0); cone: (2/7)|vt + wz R| <= mu vn.
//   vt' = vt - (2/7)(vt + wz R) = (5 vt - 2 R wz)/7,
//   wz' = wz + R Px / I = wz - (5/7)(vt + wz R)/R, so wz' R = (2 R wz - 5 vt)/7 = -vt':
// rolling without slipping (with clockwise-positive omega = -wz this is the textbook
// (5 v + 2 R omega)/7). Numbers: m = 2, R = 0.5, vt = 3, wz = +4 (backspin), vn = 1:
// vt' = (15 - 4)/7 = 11/7, cone needs mu >= (2/7) 5 = 1.43: mu = 2.
TEST(Coulomb, SphereSticksAndRollsClosedForm) {
    const double m = 2.0, R = 0.5, vt = 3.0, wz = 4.0, vn = 1.0, mu = 2.0;
    Body3 ball;
    ball.mass = m;
    ball.inertia = sphere_inertia(m, R);
    ball.position = Vec3(0.0, R, 0.0);
    ball.v = Vec3(vt, -vn, 0.0);
    ball.w = Vec3(0.0, 0.0, wz);
    const Vec3 p = Vec3::Zero();
    const ImpactBody3 a = at_contact(static_ground3(), p), b = at_contact(ball, p);
    const Response3 r = coulomb(a, b, Vec3::UnitY(), 0.0, mu);
    EXPECT_FALSE(r.sliding);
    EXPECT_NEAR_ABS_REL(r.P, Vec3(-(2.0 / 7.0) * m * (vt + wz * R), m * vn, 0.0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.vb, Vec3(11.0 / 7.0, 0.0, 0.0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.wb, Vec3(0.0, 0.0, -11.0 / 7.0 / R), kAtol, kRtol);
    // The contact point is at rest afterwards.
    EXPECT_LE(Vec3(r.vb + r.wb.cross(b.r)).norm(), 1e-13);
}

// 2D disc with backspin, e = 0: K = diag(3/m, 1/m); sticking impulse (-(m/3)(vt + w R), m vn):
//   vt' = vt - (vt + w R)/3 = (2 vt - w R)/3,  w' = w + R Px/I = w - (2/(3R))(vt + w R),
//   w' R = (w R - 2 vt)/3 = -vt': rolling. vt = 3, w = 4, R = 0.5: vt' = (6 - 2)/3 = 4/3;
//   cone: (1/3) 5 <= mu 1: mu = 2.
TEST(Coulomb, DiscSticksAndRollsClosedForm2D) {
    const double m = 2.0, R = 0.5, vt = 3.0, w = 4.0, vn = 1.0, mu = 2.0;
    Body2 disc;
    disc.mass = m;
    disc.inertia = disc_inertia_2d(m, R);
    disc.position = Vec2(0.0, R);
    disc.v = Vec2(vt, -vn);
    disc.w = w;
    const Vec2 p = Vec2::Zero();
    const ImpactBody2 b = at_contact(disc, p);
    const Response2 r = coulomb(at_contact(static_ground2(), p), b, Vec2(0, 1), 0.0, mu);
    EXPECT_FALSE(r.sliding);
    EXPECT_NEAR_ABS_REL(r.vb, Vec2(4.0 / 3.0, 0.0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.wb, -4.0 / 3.0 / R, kAtol, kRtol);
    EXPECT_LE(Vec2(r.vb + cross(r.wb, b.r)).norm(), 1e-13);
}

// A leaning rod (thin, m, L, angle t, no spin) falls straight down on its foot: no initial
// slip, but the normal impulse alone would kick the foot outwards. With s = sin t, c = cos t,
// rb = -(L/2)(c, s), perp(rb) = (L/2)(s, -c), I = m L^2/12:
//   K = (1/m) [[1 + 3 s^2, -3 s c], [-3 s c, 1 + 3 c^2]], det(m K) = 4.
// Sticking impulse K^-1 ((1 + e) v0 n) = (1 + e) m v0 (3 s c, 1 + 3 s^2)/4, which needs
// mu >= 3 s c/(1 + 3 s^2) (0.6 at 45 degrees).
//  - mu = 1 >= 0.6: sticks; the foot ends at (0, e v0).
//  - mu = 0.2 < 0.6: slides. The slip direction is that of (K n)_t = -3 s c/m, t = -x; friction
//    pushes the foot back: P = j (n - mu t) = j (mu, 1), with
//    j = (1 + e) m v0 / (m n.K (n - mu t)) = (1 + e) m v0/(1 + 3 c^2 - 3 mu s c) = (1 + e) m v0/2.2.
//    The foot still slides outwards: (K P)_x = (j/m)(-3 s c + mu (1 + 3 s^2)) < 0.
TEST(Coulomb, LeaningRodFootStickOrSlideClosedForm2D) {
    const double m = 1.5, L = 1.2, v0 = 2.0, e = 0.3, t = kPi / 4;
    const double s = std::sin(t), c = std::cos(t);
    Body2 rod;
    rod.mass = m;
    rod.inertia = rod_inertia_2d(m, L);
    rod.angle = t;
    rod.position = Vec2(0.0, 0.5 * L * s);
    rod.v = Vec2(0.0, -v0);
    const Vec2 p(-0.5 * L * c, 0.0);
    const ImpactBody2 a = at_contact(static_ground2(), p), b = at_contact(rod, p);

    const Response2 stuck = coulomb(a, b, Vec2(0, 1), e, 1.0);
    EXPECT_FALSE(stuck.sliding);
    EXPECT_NEAR_ABS_REL(stuck.P, Vec2((1 + e) * m * v0 * Vec2(3 * s * c, 1 + 3 * s * s) / 4.0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(Vec2(stuck.vb + cross(stuck.wb, b.r)), Vec2(0.0, e * v0), kAtol, kRtol);

    const double mu = 0.2;
    const Response2 slid = coulomb(a, b, Vec2(0, 1), e, mu);
    const double j = (1 + e) * m * v0 / (1 + 3 * c * c - 3 * mu * s * c);
    EXPECT_NEAR_ABS_REL(1 + 3 * c * c - 3 * mu * s * c, 2.2, 1e-14, 1e-14);
    EXPECT_TRUE(slid.sliding);
    EXPECT_NEAR_ABS_REL(slid.P, Vec2(mu * j, j), kAtol, kRtol);
    const Vec2 foot = slid.vb + cross(slid.wb, b.r);
    EXPECT_NEAR_ABS_REL(foot, Vec2((j / m) * (-3 * s * c + mu * (1 + 3 * s * s)), e * v0), kAtol, kRtol);
    EXPECT_LT(foot.x(), 0.0);
}

// The same leaning rod in 3D, turned by a heading psi about y (thin rod: pseudo-inverse); the
// 2D results rotate with the heading: P = Ry(psi)(Px, Py, 0).
TEST(Coulomb, LeaningRodFootStickOrSlideClosedForm3D) {
    const double m = 1.5, L = 1.2, v0 = 2.0, e = 0.3, t = kPi / 4;
    const double s = std::sin(t), c = std::cos(t);
    for (double psi : {0.0, 0.7, 2.5}) {
        const Quat heading(Eigen::AngleAxisd(psi, Vec3::UnitY()));
        Body3 rod;
        rod.mass = m;
        rod.inertia = rod_inertia(m, L);
        rod.orientation = heading * Quat(Eigen::AngleAxisd(t, Vec3::UnitZ()));
        rod.position = Vec3(0.0, 0.5 * L * s, 0.0);
        rod.v = Vec3(0.0, -v0, 0.0);
        const Vec3 p = rod.position - 0.5 * L * rod.rotation().col(0);
        const ImpactBody3 a = at_contact(static_ground3(), p), b = at_contact(rod, p);
        const Response3 stuck = coulomb(a, b, Vec3::UnitY(), e, 1.0);
        EXPECT_FALSE(stuck.sliding);
        EXPECT_NEAR_ABS_REL(
            stuck.P,
            Vec3(heading * Vec3((1 + e) * m * v0 * 3 * s * c / 4.0, (1 + e) * m * v0 * (1 + 3 * s * s) / 4.0, 0.0)),
            kAtol, kRtol);
        const double mu = 0.2, j = (1 + e) * m * v0 / 2.2;
        const Response3 slid = coulomb(a, b, Vec3::UnitY(), e, mu);
        EXPECT_TRUE(slid.sliding);
        EXPECT_NEAR_ABS_REL(slid.P, Vec3(heading * Vec3(mu * j, j, 0.0)), kAtol, kRtol);
    }
}

// Properties of every one-step Coulomb result (random bodies, mu in [0, 2], e in [0, 1]):
//  - u'.n = -e un in every branch (sticking: u' = -e un n by construction; sliding:
//    u'.n = un + j n.K d = un - (1 + e) un);
//  - sticking: u' has no tangential part, and the impulse is inside the cone |Pt| <= mu Pn;
//  - sliding: |Pt| = mu Pn exactly, Pn > 0, and the friction opposes the initial slip
//    (Pt . ut <= 0).
// A sticking impulse outside the cone is allowed only where no sliding impulse can reverse the
// approach (n.K (n - mu t) <= 0); those draws are counted.
TEST(Coulomb, PropertiesOfEveryResult3D) {
    collide_test::Random rng(503);
    int sliding = 0, sticking = 0, fallback = 0;
    for (int i = 0; i < 10000; ++i) {
        const Pair3 s = random_pair3(rng);
        const double e = rng.uniform(0, 1), mu = rng.uniform(0, 2);
        const Vec3 u = relative_velocity(s.a, s.b);
        const double un = u.dot(s.n);
        if (!(un < 0.0)) continue;
        const Response3 r = coulomb(s.a, s.b, s.n, e, mu);
        ImpactBody3 a1 = s.a, b1 = s.b;
        a1.v = r.va, a1.w = r.wa, b1.v = r.vb, b1.w = r.wb;
        const Vec3 u1 = relative_velocity(a1, b1);
        const double scale =
            u.norm() + s.a.r.norm() * s.a.w.norm() + s.b.r.norm() * s.b.w.norm() + s.a.v.norm() + s.b.v.norm();
        EXPECT_NEAR_ABS_REL(u1.dot(s.n), -e * un, 1e-11 * scale, 0.0);
        const double Pn = r.P.dot(s.n);
        const Vec3 Pt = r.P - Pn * s.n;
        const Vec3 ut = u - un * s.n;
        if (r.painleve) {
            // No sliding impulse can reverse the approach and sticking would pull: the
            // frictionless impulse (pushes, no tangential part).
            ++fallback;
            const Mat3 K = collision_matrix(s.a, s.b);
            EXPECT_LE(s.n.dot(K * (s.n - mu * slip_direction(K, u, s.n))), 0.0);
            EXPECT_GT(Pn, 0.0);
            EXPECT_LE(Pt.norm(), 1e-12 * r.P.norm());
        } else if (r.sliding) {
            ++sliding;
            EXPECT_GT(Pn, 0.0);
            EXPECT_NEAR_ABS_REL(Pt.norm(), mu * Pn, 1e-13 * r.P.norm(), 1e-11);
            EXPECT_LE(Pt.dot(ut), 1e-12 * Pt.norm() * ut.norm());
        } else {
            const Vec3 u1t = u1 - u1.dot(s.n) * s.n;
            EXPECT_LE(u1t.norm(), 1e-11 * scale);
            if (Pn >= 0.0 && Pt.norm() <= mu * Pn * (1 + 1e-12)) {
                ++sticking;
            } else {
                ++fallback;
                EXPECT_GE(Pn, 0.0);  // kept only when it pushes
                const Mat3 K = collision_matrix(s.a, s.b);
                const Vec3 t = slip_direction(K, u, s.n);
                EXPECT_LE(s.n.dot(K * (s.n - mu * t)), 0.0);
            }
        }
    }
    EXPECT_GT(sliding, 1000);
    EXPECT_GT(sticking, 1000);
    RecordProperty("fallback_draws", fallback);
}

TEST(Coulomb, PropertiesOfEveryResult2D) {
    collide_test::Random rng(504);
    int sliding = 0, sticking = 0, fallback = 0;
    for (int i = 0; i < 10000; ++i) {
        const Pair2 s = random_pair2(rng);
        const double e = rng.uniform(0, 1), mu = rng.uniform(0, 2);
        const Vec2 u = relative_velocity(s.a, s.b);
        const double un = u.dot(s.n);
        if (!(un < 0.0)) continue;
        const Response2 r = coulomb(s.a, s.b, s.n, e, mu);
        ImpactBody2 a1 = s.a, b1 = s.b;
        a1.v = r.va, a1.w = r.wa, b1.v = r.vb, b1.w = r.wb;
        const Vec2 u1 = relative_velocity(a1, b1);
        const double scale =
            u.norm() + s.a.r.norm() * std::abs(s.a.w) + s.b.r.norm() * std::abs(s.b.w) + s.a.v.norm() + s.b.v.norm();
        EXPECT_NEAR_ABS_REL(u1.dot(s.n), -e * un, 1e-11 * scale, 0.0);
        const double Pn = r.P.dot(s.n);
        const Vec2 Pt = r.P - Pn * s.n;
        const Vec2 ut = u - un * s.n;
        if (r.painleve) {
            ++fallback;
            const Mat2 K = collision_matrix(s.a, s.b);
            EXPECT_LE(s.n.dot(K * (s.n - mu * slip_direction(K, u, s.n))), 0.0);
            EXPECT_GT(Pn, 0.0);
            EXPECT_LE(Pt.norm(), 1e-12 * r.P.norm());
        } else if (r.sliding) {
            ++sliding;
            EXPECT_GT(Pn, 0.0);
            EXPECT_NEAR_ABS_REL(Pt.norm(), mu * Pn, 1e-13 * r.P.norm(), 1e-11);
            EXPECT_LE(Pt.dot(ut), 1e-12 * Pt.norm() * ut.norm());
        } else {
            const Vec2 u1t = u1 - u1.dot(s.n) * s.n;
            EXPECT_LE(u1t.norm(), 1e-11 * scale);
            if (Pn >= 0.0 && Pt.norm() <= mu * Pn * (1 + 1e-12)) {
                ++sticking;
            } else {
                ++fallback;
                EXPECT_GE(Pn, 0.0);  // kept only when it pushes
                const Mat2 K = collision_matrix(s.a, s.b);
                const Vec2 t = slip_direction(K, u, s.n);
                EXPECT_LE(s.n.dot(K * (s.n - mu * t)), 0.0);
            }
        }
    }
    EXPECT_GT(sliding, 1000);
    EXPECT_GT(sticking, 1000);
    RecordProperty("fallback_draws", fallback);
}

// slip_direction: the unit tangential part of u; with no initial slip, the unit tangential part
// of K n (where the normal impulse alone drives the contact). u = (3, -1, 4), n = y:
// ut = (3, 0, 4), t = (0.6, 0, 0.8).
TEST(Coulomb, SlipDirectionHandValues) {
    const Mat3 K = Mat3::Identity();
    EXPECT_NEAR_ABS_REL(slip_direction(K, Vec3(3, -1, 4), Vec3::UnitY()), Vec3(0.6, 0, 0.8), kAtol, kRtol);
    Mat3 K2;
    K2 << 2, 1, 0, 1, 3, 0, 0, 0, 1;  // K n = (1, 3, 0): tangential part (1, 0, 0)
    EXPECT_NEAR_ABS_REL(slip_direction(K2, Vec3(0, -2, 0), Vec3::UnitY()), Vec3(1, 0, 0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(slip_direction(Mat2(Mat2::Identity()), Vec2(-5, -1), Vec2(0, 1)), Vec2(-1, 0), kAtol, kRtol);
}

}  // namespace
