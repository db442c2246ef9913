// The page's formulas as written (engine/page.h), errors kept: each erratum of PHYSICS.md shown
// with numbers, beside the correct solver.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/mass.h"
#include "engine/page.h"
#include "engine/response.h"
#include "tests/engine/random_bodies.h"

namespace {

using namespace collide;
using collide_test::kPi;

constexpr double kAtol = 1e-13;
constexpr double kRtol = 1e-12;

ImpactBody3 point_body(double m, const Vec3& v) {
    ImpactBody3 b;
    b.inv_m = 1.0 / m;
    b.I = Mat3::Identity() * 0.1 * m;
    b.inv_I = b.I.inverse();
    b.v = v;
    return b;
}

struct Pair3 {
    ImpactBody3 a, b;
    Vec3 n;
};
Pair3 random_approaching(collide_test::Random& rng) {
    const Vec3 p = rng.vec3(-1, 1);
    Pair3 s{at_contact(rng.body3(), p), at_contact(rng.body3(), p), rng.unit3()};
    if (relative_velocity(s.a, s.b).dot(s.n) > 0) s.n = -s.n;
    return s;
}

// Erratum 7: the listing's vbf = vbi - J/mb subtracts. Head-on, r = 0, n = +x (A on the left),
// ma = 2, mb = 3, va = 1, vb = -1, e = 1: scalar = 1/2 + 1/3 = 5/6, Jmod = 2 * 2/(5/6) = 4.8;
//   listing: vaf = 1 - 4.8/2 = -1.4, vbf = -1 - 4.8/3 = -2.6 (B pushed towards A);
//   correct: va' = -1.4, vb' = -1 + 1.6 = 0.6.
// Momentum: before 2 - 3 = -1; the listing's after 2(-1.4) + 3(-2.6) = -10.6 = -1 - 2 Jmod.
TEST(PageListing, Erratum7MomentumNotConserved) {
    const ImpactBody3 a = point_body(2, Vec3(1, 0, 0)), b = point_body(3, Vec3(-1, 0, 0));
    const page::Listing3 L = page::listing(a, b, Vec3::UnitX(), 1.0);
    EXPECT_NEAR_ABS_REL(L.scalar, 5.0 / 6.0, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(L.Jmod, 4.8, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(L.vaf, Vec3(-1.4, 0, 0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(L.vbf, Vec3(-2.6, 0, 0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(Vec3(2 * L.vaf + 3 * L.vbf), Vec3(-10.6, 0, 0), kAtol, kRtol);
    const Response3 r = frictionless(a, b, Vec3::UnitX(), 1.0);
    EXPECT_NEAR_ABS_REL(r.vb, Vec3(0.6, 0, 0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(Vec3(2 * r.va + 3 * r.vb), Vec3(-1, 0, 0), kAtol, kRtol);

    // The 1D transcription gives the same numbers.
    ImpactBody1 a1, b1;
    a1.inv_m = 0.5, a1.v = 1;
    b1.inv_m = 1.0 / 3.0, b1.v = -1;
    const page::Listing1 L1 = page::listing(a1, b1, +1.0, 1.0);
    EXPECT_NEAR_ABS_REL(L1.vaf, -1.4, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(L1.vbf, -2.6, kAtol, kRtol);
}

// Reading `mul` as scaling in place: J.mul(1/ma) changes J, so the next line subtracts
// J/(ma mb): vbf = -1 - 4.8/(2 * 3) = -1.8 (vaf unchanged, -1.4).
TEST(PageListing, MulInPlaceScalesJTwice) {
    const ImpactBody3 a = point_body(2, Vec3(1, 0, 0)), b = point_body(3, Vec3(-1, 0, 0));
    const page::Listing3 L = page::listing(a, b, Vec3::UnitX(), 1.0, page::ListingReading{true});
    EXPECT_NEAR_ABS_REL(L.vaf, Vec3(-1.4, 0, 0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(L.vbf, Vec3(-1.8, 0, 0), kAtol, kRtol);
    ImpactBody1 a1, b1;
    a1.inv_m = 0.5, a1.v = 1;
    b1.inv_m = 1.0 / 3.0, b1.v = -1;
    const page::Listing1 L1 = page::listing(a1, b1, +1.0, 1.0, page::ListingReading{true});
    EXPECT_NEAR_ABS_REL(L1.vbf, -1.8, kAtol, kRtol);
}

// Erratum 5: (n x ra) then (Ia^-1 (n x ra)) x ra, dotted with n, is
// n.((Ia^-1 (n x ra)) x ra) = (Ia^-1 (n x ra)).(ra x n) = -(ra x n).Ia^-1 (ra x n):
// the listing's denominator is 1/ma + 1/mb - (ra x n).Ia^-1(ra x n) - (rb x n).Ib^-1(rb x n).
TEST(PageListing, Erratum5RotationalTermsSubtracted) {
    collide_test::Random rng(801);
    for (int i = 0; i < 1000; ++i) {
        const Pair3 s = random_approaching(rng);
        const page::Listing3 L = page::listing(s.a, s.b, s.n, 0.5);
        const double expected = s.a.inv_m + s.b.inv_m - rotational_term(s.a, s.n) - rotational_term(s.b, s.n);
        EXPECT_NEAR_ABS_REL(L.scalar, expected, 1e-14 * (s.a.inv_m + s.b.inv_m), 1e-12);
    }
}

// ... so it can vanish or go negative. A thin rod (m, L) on static ground at angle t
// (see Response3D.RodEndStrikesGroundAtAnyHeading): the rotational term is 3 cos^2 t / m, so
//   listing scalar = (1 - 3 cos^2 t)/m: 0 at cos^2 t = 1/3 (t = 54.74 degrees), -2/m for a
//   horizontal rod, where the correct denominator is (1 + 3 cos^2 t)/m = 2/m and 4/m.
// A negative scalar gives a negative Jmod for an approaching contact.
TEST(PageListing, Erratum5DenominatorZeroOrNegative) {
    const double m = 2.0, L = 1.0, v0 = 1.0;
    Body3 ground;
    ground.is_static = true;
    for (double t : {std::acos(1.0 / std::sqrt(3.0)), 0.0}) {
        Body3 rod;
        rod.mass = m;
        rod.inertia = rod_inertia(m, L);
        rod.orientation = Quat(Eigen::AngleAxisd(t, Vec3::UnitZ()));
        rod.position = Vec3(0, 0.5 * L * std::sin(t), 0);
        rod.v = Vec3(0, -v0, 0);
        const Vec3 p = rod.position - 0.5 * L * rod.rotation().col(0);
        const ImpactBody3 a = at_contact(ground, p), b = at_contact(rod, p);
        const page::Listing3 Lst = page::listing(a, b, Vec3::UnitY(), 1.0);
        const double c2 = std::cos(t) * std::cos(t);
        EXPECT_NEAR_ABS_REL(Lst.scalar, (1 - 3 * c2) / m, 1e-14, 1e-12);
        EXPECT_NEAR_ABS_REL(a.inv_m + b.inv_m + rotational_term(a, Vec3::UnitY()) + rotational_term(b, Vec3::UnitY()),
                            (1 + 3 * c2) / m, 1e-14, 1e-12);
        if (t == 0.0) {
            EXPECT_NEAR_ABS_REL(Lst.scalar, -2.0 / m, kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(Lst.Jmod, 2 * v0 / (-2.0 / m), kAtol, kRtol);  // -2 N s
            EXPECT_GT(frictionless(a, b, Vec3::UnitY(), 1.0).P.y(), 0.0);
        } else {
            // Zero up to rounding: the impulse is unbounded (or absurdly large).
            EXPECT_LE(std::abs(Lst.scalar), 1e-14);
            EXPECT_GT(std::abs(Lst.Jmod), 1e13);
        }
    }
    // Two thin rods whose ends meet, A along x (m = 1, L = 2, end at the origin), B along z
    // (m = 4, L = 2, end at the origin), A moving at +y into B, n = +y. ra = (1, 0, 0),
    // rb = (0, 0, -1): each lever is across its rod, (r x n)^2 / T = 1/(m L^2/12) = 3/m, so
    // scalar = (1/1 + 1/4) - 3/1 - 3/4 = -2.5 = -2 (1/ma + 1/mb); Jmod = (1 + 1) 1/(-2.5) = -0.8.
    Body3 A, B;
    A.mass = 1.0;
    A.inertia = rod_inertia(1.0, 2.0);
    A.position = Vec3(-1, 0, 0);
    A.v = Vec3(0, 1, 0);
    B.mass = 4.0;
    B.inertia = rod_inertia(4.0, 2.0);
    B.orientation = Quat(Eigen::AngleAxisd(-kPi / 2, Vec3::UnitY()));  // body x -> world z
    B.position = Vec3(0, 0, 1);
    ASSERT_NEAR((B.position - B.rotation().col(0)).norm(), 0.0, 1e-14);
    const page::Listing3 Lr = page::listing(at_contact(A, Vec3::Zero()), at_contact(B, Vec3::Zero()), Vec3::UnitY(), 1);
    EXPECT_NEAR_ABS_REL(Lr.scalar, -2.5, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(Lr.Jmod, -0.8, kAtol, kRtol);
}

// Erratum 6: Jmod = (e + 1)|vai - vbi|/scalar uses the centres' speed difference: its numerator
// is never negative, it ignores spin and the direction of approach. Separating bodies (A on the left
// moving left at 1, B moving right at 1, r = 0, ma = mb = 1, e = 0.5): Jmod = 1.5 * 2/2 = 1.5,
// vaf = -1 - 1.5 = -2.5, while the correct solver leaves them alone.
TEST(PageListing, Erratum6ImpulseForSeparatingBodies) {
    const ImpactBody3 a = point_body(1, Vec3(-1, 0, 0)), b = point_body(1, Vec3(1, 0, 0));
    const page::Listing3 L = page::listing(a, b, Vec3::UnitX(), 0.5);
    EXPECT_NEAR_ABS_REL(L.Jmod, 1.5, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(L.vaf, Vec3(-2.5, 0, 0), kAtol, kRtol);
    const Response3 r = frictionless(a, b, Vec3::UnitX(), 0.5);
    EXPECT_TRUE(r.separating);
    EXPECT_EQ(r.va, a.v);
}

// Erratum 6, spin and direction: for random pairs, Jmod = (1 + e)|va - vb|/scalar whatever the
// spins; giving the bodies new spins and turning va - vb (same length) leaves Jmod unchanged,
// while the correct impulse changes.
TEST(PageListing, Erratum6JmodIgnoresSpinAndDirection) {
    collide_test::Random rng(802);
    int correct_changed = 0;
    for (int i = 0; i < 1000; ++i) {
        const Pair3 s = random_approaching(rng);
        const double e = rng.uniform(0, 1);
        const page::Listing3 L = page::listing(s.a, s.b, s.n, e);
        EXPECT_NEAR_ABS_REL(L.Jmod, (1 + e) * (s.a.v - s.b.v).norm() / L.scalar, 1e-14, 1e-12);
        Pair3 t = s;
        t.a.w = rng.vec3(-3, 3);
        t.b.w = rng.vec3(-3, 3);
        t.b.v = t.a.v - rng.rotation() * (s.a.v - s.b.v);
        EXPECT_NEAR_ABS_REL(page::listing(t.a, t.b, t.n, e).Jmod, L.Jmod, 1e-14, 1e-11);
        const Response3 r0 = frictionless(s.a, s.b, s.n, e), r1 = frictionless(t.a, t.b, t.n, e);
        if ((r0.P - r1.P).norm() > 1e-6 * r0.P.norm()) ++correct_changed;
    }
    EXPECT_GT(correct_changed, 900);
}

// Erratum 8: waf = wai - angularVelChangea with angularVelChangea = Ia^-1 (n x ra): per unit
// impulse, not multiplied by Jmod, so doubling every velocity doubles Jmod but leaves the spin
// change alone. The correct change is wa' - wa = -Ia^-1 (ra x j n) = +j Ia^-1 (n x ra): the
// listing's A change is -1/j times it (wrong sign, unscaled); B's is +1/j times the correct
// one (right sign, unscaled).
TEST(PageListing, Erratum8SpinChangePerUnitImpulse) {
    collide_test::Random rng(803);
    for (int i = 0; i < 1000; ++i) {
        const Pair3 s = random_approaching(rng);
        const page::Listing3 L = page::listing(s.a, s.b, s.n, 0.5);
        const Vec3 per_unit_a = s.a.inv_I * s.n.cross(s.a.r);
        const Vec3 per_unit_b = s.b.inv_I * s.n.cross(s.b.r);
        EXPECT_NEAR_ABS_REL(L.angularVelChangea, per_unit_a, 1e-14, 1e-12);
        EXPECT_NEAR_ABS_REL(Vec3(L.waf - s.a.w), Vec3(-per_unit_a), 1e-14, 1e-11);
        EXPECT_NEAR_ABS_REL(Vec3(L.wbf - s.b.w), Vec3(-per_unit_b), 1e-14, 1e-11);
        Pair3 fast = s;
        fast.a.v *= 2, fast.b.v *= 2, fast.a.w *= 2, fast.b.w *= 2;
        const page::Listing3 F = page::listing(fast.a, fast.b, fast.n, 0.5);
        EXPECT_NEAR_ABS_REL(F.Jmod, 2 * L.Jmod, 1e-14, 1e-12);
        EXPECT_NEAR_ABS_REL(Vec3(F.waf - fast.a.w), Vec3(L.waf - s.a.w), 1e-14, 1e-11);

        const Response3 r = frictionless(s.a, s.b, s.n, 0.5);
        const double j = r.P.dot(s.n);
        EXPECT_NEAR_ABS_REL(Vec3(r.wa - s.a.w), Vec3(j * per_unit_a), 1e-13, 1e-11);
        EXPECT_NEAR_ABS_REL(Vec3(r.wb - s.b.w), Vec3(-j * per_unit_b), 1e-13, 1e-11);
    }
}

// Erratum 1: the summary's numerator (va - vb).n + (ra x n).wa - (rb x n).wb equals
// n.((va + wa x ra) - (vb + wb x rb)) = -un, so J = (1 + e) un / D = -j (j the correct
// impulse, > 0): negative for every approaching contact. With vaf = vai - J n/ma it adds j/ma
// along n to A (towards B) and takes j/mb from B (towards A). Its spin updates come out right
// (erratum 2 cancels erratum 1 there), so only the linear part is reversed:
//   un' = un - j (1/ma + 1/mb) + j (rot_a + rot_b)   (correct: un + j (1/ma + 1/mb + rot_a + rot_b)).
// For two point-like bodies (rot = 0) the contact approaches faster: un' = un - j (1/ma + 1/mb).
TEST(PageSummary, Erratum1ImpulseSignPushesATowardsB) {
    collide_test::Random rng(804);
    for (int i = 0; i < 1000; ++i) {
        const Pair3 s = random_approaching(rng);
        const double e = rng.uniform(0, 1);
        const page::Summary3 S = page::summary(s.a, s.b, s.n, e);
        const Response3 r = frictionless(s.a, s.b, s.n, e);
        const double j = r.P.dot(s.n);
        EXPECT_NEAR_ABS_REL(S.J, -j, 1e-14, 1e-11);
        EXPECT_LT(S.J, 0.0);
        EXPECT_GT(S.vaf.dot(s.n), s.a.v.dot(s.n));  // A pushed towards B
        EXPECT_LT(S.vbf.dot(s.n), s.b.v.dot(s.n));  // B pushed towards A
        ImpactBody3 a1 = s.a, b1 = s.b;
        a1.v = S.vaf, a1.w = S.waf, b1.v = S.vbf, b1.w = S.wbf;
        const double un = relative_velocity(s.a, s.b).dot(s.n);
        const double rot = rotational_term(s.a, s.n) + rotational_term(s.b, s.n);
        const double mass_term = s.a.inv_m + s.b.inv_m;
        EXPECT_NEAR_ABS_REL(relative_velocity(a1, b1).dot(s.n), un + j * (rot - mass_term),
                            1e-12 * (std::abs(un) + j * (rot + mass_term)), 1e-11);
    }
    // Head-on point masses (r = 0), ma = 2, mb = 3, va = 1, vb = -1, e = 1: j = 4.8,
    // J = -4.8; vaf = 1 + 4.8/2 = 3.4, vbf = -1 - 4.8/3 = -2.6: approaching at 6 m/s instead of
    // separating at 2 m/s.
    const ImpactBody3 a = point_body(2, Vec3(1, 0, 0)), b = point_body(3, Vec3(-1, 0, 0));
    const page::Summary3 S = page::summary(a, b, Vec3::UnitX(), 1.0);
    EXPECT_NEAR_ABS_REL(S.J, -4.8, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(S.vaf, Vec3(3.4, 0, 0), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(S.vbf, Vec3(-2.6, 0, 0), kAtol, kRtol);
}

// Erratum 2: with -J on A and +J on B (J = S.J n) the spin changes are Ia^-1 (ra x (-J)) and
// Ib^-1 (rb x J); the summary's -Ia^-1 (J x ra) and +Ib^-1 (J x rb) are their negatives.
// Since J itself has the wrong sign (erratum 1), the two errors cancel in the spins: the
// summary's waf, wbf equal the correct solver's, while its vaf, vbf do not.
TEST(PageSummary, Erratum2SpinSignsWrongForItsOwnImpulse) {
    collide_test::Random rng(805);
    for (int i = 0; i < 1000; ++i) {
        const Pair3 s = random_approaching(rng);
        const page::Summary3 S = page::summary(s.a, s.b, s.n, 0.7);
        const Vec3 J = S.J * s.n;
        const Vec3 torque_a = s.a.inv_I * s.a.r.cross(-J), torque_b = s.b.inv_I * s.b.r.cross(J);
        EXPECT_NEAR_ABS_REL(Vec3(S.waf - s.a.w), Vec3(-torque_a), 1e-13, 1e-11);
        EXPECT_NEAR_ABS_REL(Vec3(S.wbf - s.b.w), Vec3(-torque_b), 1e-13, 1e-11);
        const Response3 r = frictionless(s.a, s.b, s.n, 0.7);
        EXPECT_NEAR_ABS_REL(S.waf, r.wa, 1e-13, 1e-11);
        EXPECT_NEAR_ABS_REL(S.wbf, r.wb, 1e-13, 1e-11);
        EXPECT_GT((S.vbf - r.vb).norm(), 1e-3 * r.P.norm() * s.b.inv_m);
    }
}

// Erratum 4: dVp = J/M + (I^-1 (J x r)) x r as written has the angular part reversed;
// the corrected J/M + (I^-1 (r x J)) x r is the actual change of the point velocity (apply J to
// the body at r and recompute v + w x r), i.e. (1/m E - [r]x I^-1 [r]x) J, the body's share of K.
TEST(PageDerivation, Erratum4DeltaVpAngularPartReversed) {
    collide_test::Random rng(806);
    ImpactBody3 ground;  // static partner: K is the body's own share
    for (int i = 0; i < 1000; ++i) {
        const Body3 B = rng.body3();
        const ImpactBody3 b = at_contact(B, rng.vec3(-1, 1));
        const Vec3 J = rng.vec3(-2, 2);
        Response3 r;
        r.P = J;
        apply_impulse(ground, b, &r);
        const Vec3 actual = (r.vb + r.wb.cross(b.r)) - point_velocity(b);
        EXPECT_NEAR_ABS_REL(page::delta_vp(b, J), actual, 1e-13, 1e-12);
        EXPECT_NEAR_ABS_REL(page::delta_vp(b, J), Vec3(collision_matrix(ground, b) * J), 1e-13, 1e-12);
        const Vec3 linear = b.inv_m * J;
        const Vec3 as_written = page::delta_vp_as_written(b, J);
        EXPECT_NEAR_ABS_REL(Vec3(as_written - linear), Vec3(-(actual - linear)), 1e-13, 1e-11);
        EXPECT_GT((as_written - actual).norm(), 1e-6 * actual.norm());
    }
}

// Erratum 3: e = (vaf - vbf)/(vai - vbi) on the normal components of the contact-point
// velocities. For a correct collision un' = -e un, i.e. vbf - vaf = -e (vbi - vai), so the
// formula as written gives (vaf - vbf)/(vai - vbi) = (e un)/(-un) = -e.
TEST(PageDerivation, Erratum3RestitutionMissesMinusSign) {
    collide_test::Random rng(807);
    for (int i = 0; i < 1000; ++i) {
        const Pair3 s = random_approaching(rng);
        const double e = rng.uniform(0.05, 1);
        const Response3 r = frictionless(s.a, s.b, s.n, e);
        ImpactBody3 a1 = s.a, b1 = s.b;
        a1.v = r.va, a1.w = r.wa, b1.v = r.vb, b1.w = r.wb;
        const double vai = point_velocity(s.a).dot(s.n), vbi = point_velocity(s.b).dot(s.n);
        const double vaf = point_velocity(a1).dot(s.n), vbf = point_velocity(b1).dot(s.n);
        const double scale = std::abs(vai) + std::abs(vbi);
        EXPECT_NEAR_ABS_REL(page::restitution_as_written(vai, vbi, vaf, vbf) * (vai - vbi), -e * (vai - vbi),
                            1e-12 * scale, 1e-10);
    }
    // By hand: vai = 2, vbi = -1 approach; after e = 0.5: vaf = -0.25, vbf = 1.25
    // (vbf - vaf = 1.5 = -0.5 (-3)). As written: (-0.25 - 1.25)/(2 + 1) = -0.5.
    EXPECT_NEAR_ABS_REL(page::restitution_as_written(2, -1, -0.25, 1.25), -0.5, 1e-15, 1e-15);
}

}  // namespace
