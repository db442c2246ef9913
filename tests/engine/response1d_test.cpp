// 1D collision response (engine/response1d.cpp): textbook cases on a line, r = 0.
//
// Momentum and Newton's rule give, for A left of B (n = +1):
//   ma va' + mb vb' = ma va + mb vb,   vb' - va' = -e (vb - va)
//   => va' = (ma va + mb vb + mb e (vb - va)) / (ma + mb)
//      vb' = (ma va + mb vb + ma e (va - vb)) / (ma + mb),   P = mb (vb' - vb).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "engine/response.h"
#include "tests/engine/random_bodies.h"

namespace {

using namespace collide;

constexpr double kAtol = 1e-13;
constexpr double kRtol = 1e-13;

ImpactBody1 body(double m, double v) {
    ImpactBody1 b;
    b.inv_m = 1.0 / m;
    b.v = v;
    return b;
}
ImpactBody1 wall(double v) {
    ImpactBody1 b;
    b.inv_m = 0.0;
    b.v = v;
    return b;
}

// Equal masses, e = 1: A (2 m/s) catches B (-1 m/s); they exchange velocities.
// un = (-1 - 2) = -3, P = -(1 + 1)(-3)/(1 + 1) = 3 N s (m = 1 kg).
TEST(Response1D, EqualMassesElasticExchangeVelocities) {
    const Response1 r = frictionless(body(1, 2), body(1, -1), +1.0, 1.0);
    EXPECT_FALSE(r.separating);
    EXPECT_NEAR_ABS_REL(r.P, 3.0, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.va, -1.0, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.vb, 2.0, kAtol, kRtol);
}

// e = 0: both end with the centre-of-mass velocity (2*3 + 6*(-1))/(2 + 6) = 0.
TEST(Response1D, PerfectlyInelasticCommonVelocity) {
    const Response1 r = frictionless(body(2, 3), body(6, -1), +1.0, 0.0);
    EXPECT_NEAR_ABS_REL(r.va, 0.0, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.vb, 0.0, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.P, 6.0, kAtol, kRtol);  // mb (vb' - vb) = 6 (0 + 1)
}

struct Case1D {
    double ma, mb, va, vb, e;
};

double va_after(const Case1D& c) { return (c.ma * c.va + c.mb * c.vb + c.mb * c.e * (c.vb - c.va)) / (c.ma + c.mb); }
double vb_after(const Case1D& c) { return (c.ma * c.va + c.mb * c.vb + c.ma * c.e * (c.va - c.vb)) / (c.ma + c.mb); }

// The general closed form (header comment) for a table of cases. Worked by hand for the first:
// ma = 2, mb = 3, va = 4, vb = -1, e = 0.5: va' = (8 - 3 + 1.5 (-5))/5 = -0.5,
// vb' = (5 + 1 * 5)/5 = 2, P = 3 (2 + 1) = 9.
TEST(Response1D, GeneralClosedFormAOnTheLeft) {
    const Response1 hand = frictionless(body(2, 4), body(3, -1), +1.0, 0.5);
    EXPECT_NEAR_ABS_REL(hand.va, -0.5, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(hand.vb, 2.0, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(hand.P, 9.0, kAtol, kRtol);
    const Case1D cases[] = {{2, 3, 4, -1, 0.5},          {1, 10, 1, 0, 1.0}, {10, 1, 1, 0, 1.0},
                            {0.1, 7, 3, 2, 0.3},         {5, 5, 0, -2, 0.0}, {0.3, 0.2, -1, -4, 0.9},
                            {1.5, 2.5, 2, 2 - 1e-3, 0.7}};
    for (const Case1D& c : cases) {
        const Response1 r = frictionless(body(c.ma, c.va), body(c.mb, c.vb), +1.0, c.e);
        EXPECT_NEAR_ABS_REL(r.va, va_after(c), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(r.vb, vb_after(c), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(r.P, c.mb * (vb_after(c) - c.vb), kAtol, kRtol);
        EXPECT_GT(r.P, 0.0);  // B, on the right, is pushed to the right
    }
}

// The same physical collisions with the labels swapped: the right-hand body is now A, the
// left-hand body B, and n (from A into B) is -1. This is the page's "negative J" case: the
// impulse on B (the left body) is negative, and the velocities are the same as before.
// Hand case: left body 2 kg at 4 m/s is B, right body 3 kg at -1 m/s is A:
// un = (4 - (-1)) (-1) = -5, P = -(1.5)(-5)/(1/3 + 1/2) (-1) = -9 N s; vb' = 4 - 9/2 = -0.5,
// va' = -1 + 9/3 = 2.
TEST(Response1D, GeneralClosedFormBOnTheLeftNegativeImpulse) {
    const Response1 hand = frictionless(body(3, -1), body(2, 4), -1.0, 0.5);
    EXPECT_NEAR_ABS_REL(hand.P, -9.0, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(hand.vb, -0.5, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(hand.va, 2.0, kAtol, kRtol);
    const Case1D cases[] = {{2, 3, 4, -1, 0.5}, {1, 10, 1, 0, 1.0}, {0.1, 7, 3, 2, 0.3}, {0.3, 0.2, -1, -4, 0.9}};
    for (const Case1D& c : cases) {
        // c.ma/c.va is the left body (now B), c.mb/c.vb the right body (now A).
        const Response1 r = frictionless(body(c.mb, c.vb), body(c.ma, c.va), -1.0, c.e);
        EXPECT_NEAR_ABS_REL(r.vb, va_after(c), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(r.va, vb_after(c), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(r.P, c.ma * (va_after(c) - c.va), kAtol, kRtol);
        EXPECT_LT(r.P, 0.0);
    }
}

// Static wall A (inv_m = 0) on the left, ball B coming at -3 m/s: un = -3,
// P = -(1 + e)(-3)/(1/m) = 3 (1 + e) m, vb' = -3 + 3 (1 + e) = 3 e; the wall does not move.
TEST(Response1D, StaticWallReversesVelocityTimesE) {
    for (double e : {0.0, 0.25, 0.8, 1.0}) {
        const Response1 r = frictionless(wall(0.0), body(2.0, -3.0), +1.0, e);
        EXPECT_NEAR_ABS_REL(r.vb, 3.0 * e, kAtol, kRtol);
        EXPECT_EQ(r.va, 0.0);
        EXPECT_NEAR_ABS_REL(r.P, 6.0 * (1.0 + e), kAtol, kRtol);
        // The wall on the right instead (B static, n = +1, A moving at +3 m/s).
        const Response1 s = frictionless(body(2.0, 3.0), wall(0.0), +1.0, e);
        EXPECT_NEAR_ABS_REL(s.va, -3.0 * e, kAtol, kRtol);
        EXPECT_EQ(s.vb, 0.0);
    }
}

// A wall moving at a prescribed 1 m/s keeps its velocity and reverses the relative velocity:
// vb' - 1 = -e (vb - 1). vb = -3, e = 0.5: vb' = 1 + 0.5 * 4 = 3.
TEST(Response1D, MovingWallReversesRelativeVelocity) {
    const Response1 r = frictionless(wall(1.0), body(2.0, -3.0), +1.0, 0.5);
    EXPECT_NEAR_ABS_REL(r.vb, 3.0, kAtol, kRtol);
    EXPECT_EQ(r.va, 1.0);
}

// Separating (un > 0) or resting (un = 0): no impulse, velocities unchanged.
TEST(Response1D, SeparatingOrRestingGivesNoImpulse) {
    for (const auto& [va, vb, n] : {std::tuple{-1.0, 2.0, 1.0}, std::tuple{1.0, 1.0, 1.0}, std::tuple{2.0, -1.0, -1.0},
                                    std::tuple{0.0, 0.0, -1.0}}) {
        const Response1 r = frictionless(body(1.0, va), body(2.0, vb), n, 1.0);
        EXPECT_TRUE(r.separating);
        EXPECT_EQ(r.P, 0.0);
        EXPECT_EQ(r.va, va);
        EXPECT_EQ(r.vb, vb);
        const Response1 s = stick(body(1.0, va), body(2.0, vb), n);
        EXPECT_TRUE(s.separating);
        EXPECT_EQ(s.va, va);
        EXPECT_EQ(s.vb, vb);
    }
}

// Stick on a line: common velocity = total momentum / total mass:
// (1.5 * 4 + 0.5 * (-2)) / 2 = 2.5 m/s; against a static wall, the wall's velocity.
TEST(Response1D, StickCommonVelocity) {
    const Response1 r = stick(body(1.5, 4.0), body(0.5, -2.0), +1.0);
    EXPECT_NEAR_ABS_REL(r.va, 2.5, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.vb, 2.5, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.P, 0.5 * (2.5 + 2.0), kAtol, kRtol);
    const Response1 w = stick(wall(-0.5), body(3.0, -2.0), +1.0);
    EXPECT_NEAR_ABS_REL(w.vb, -0.5, kAtol, kRtol);
}

// Random 1D collisions: momentum conserved, Newton's rule vb' - va' = -e (vb - va), energy lost
// by (1 - e^2) mu_red (vb - va)^2 / 2 with the reduced mass mu_red = ma mb/(ma + mb).
TEST(Response1D, RandomMomentumNewtonAndEnergyLoss) {
    collide_test::Random rng(301);
    for (int i = 0; i < 10000; ++i) {
        const double ma = rng.mass(), mb = rng.mass(), e = rng.uniform(0, 1);
        double va = rng.uniform(-3, 3), vb = rng.uniform(-3, 3);
        const double n = rng.uniform(0, 1) < 0.5 ? 1.0 : -1.0;
        if ((vb - va) * n >= 0.0) std::swap(va, vb);
        if ((vb - va) * n >= 0.0) continue;
        const Response1 r = frictionless(body(ma, va), body(mb, vb), n, e);
        const double scale = ma * std::abs(va) + mb * std::abs(vb);
        EXPECT_NEAR_ABS_REL(ma * r.va + mb * r.vb, ma * va + mb * vb, 1e-13 * scale, 1e-13);
        EXPECT_NEAR_ABS_REL(r.vb - r.va, -e * (vb - va), 1e-13 * (std::abs(va) + std::abs(vb)), 1e-12);
        const double ke0 = 0.5 * (ma * va * va + mb * vb * vb);
        const double ke1 = 0.5 * (ma * r.va * r.va + mb * r.vb * r.vb);
        const double reduced = ma * mb / (ma + mb);
        EXPECT_NEAR_ABS_REL(ke0 - ke1, 0.5 * (1 - e * e) * reduced * (vb - va) * (vb - va), 1e-12 * ke0, 1e-12);
    }
}

// Model names round-trip through parse_model; an unknown name is refused.
TEST(ResponseModels, NamesRoundTrip) {
    for (Model m : {Model::frictionless, Model::coulomb, Model::matrix, Model::stick, Model::page_listing}) {
        Model parsed = Model::frictionless;
        EXPECT_TRUE(parse_model(model_name(m), &parsed));
        EXPECT_EQ(parsed, m);
    }
    EXPECT_EQ(std::string(model_name(Model::page_listing)), "page-listing");
    Model unchanged = Model::matrix;
    EXPECT_FALSE(parse_model("newton", &unchanged));
    EXPECT_EQ(unchanged, Model::matrix);
}

}  // namespace
