// 2D frictionless response (engine/response2d.cpp) against closed forms: a rod's end striking
// the ground, a bar striking a post, a rod struck at its centre of percussion, and contacts that
// separate because of spin.
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

Body2 static_ground() {
    Body2 g;
    g.is_static = true;
    g.position = Vec2(0.0, -1.0);
    return g;
}

// Uniform thin rod (m, L) at angle theta above the horizontal, its lower end on frictionless
// static ground (A), centre falling at v0, no spin. n = +y (from the ground into the rod).
// rb = -(L/2)(cos t, sin t), rb x n = -(L/2) cos t, I = m L^2/12:
//   (rb x n)^2/I = 3 cos^2 t / m, un = -v0,
//   j = (1 + e) m v0 / (1 + 3 cos^2 t),
//   vb' = (0, -v0 + j/m), wb' = (rb x P)/I = -6 j cos t/(m L) (clockwise: the end is pushed up),
// and the end then rises at e v0: -v0 + j/m + wb' rbx = -v0 + (j/m)(1 + 3 cos^2 t) = e v0,
// while sliding outwards (frictionless) at -wb' rby = -(6 j c/(m L))(L/2) sin t = -3 j s c/m.
TEST(Response2D, RodEndStrikesGround) {
    const double m = 2.0, L = 1.5, v0 = 3.0, e = 0.6;
    for (double deg : {0.0, 20.0, 30.0, 45.0, 60.0, 75.0, 90.0}) {
        SCOPED_TRACE(deg);
        const double t = deg * kPi / 180.0, c = std::cos(t);
        Body2 rod;
        rod.mass = m;
        rod.inertia = rod_inertia_2d(m, L);
        rod.angle = t;
        rod.position = Vec2(0.0, 0.5 * L * std::sin(t));
        rod.v = Vec2(0.0, -v0);
        const Vec2 p(-0.5 * L * c, 0.0);
        const ImpactBody2 a = at_contact(static_ground(), p), b = at_contact(rod, p);
        const Response2 r = frictionless(a, b, Vec2(0, 1), e);

        const double j = (1 + e) * m * v0 / (1 + 3 * c * c);
        EXPECT_FALSE(r.separating);
        EXPECT_NEAR_ABS_REL(r.P, Vec2(0.0, j), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(r.vb, Vec2(0.0, -v0 + j / m), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(r.wb, -6.0 * j * c / (m * L), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(Vec2(r.vb + cross(r.wb, b.r)), Vec2(-3.0 * j * std::sin(t) * c / m, e * v0), kAtol, kRtol);
        // The static ground keeps its (zero) motion.
        EXPECT_EQ(r.va, Vec2::Zero());
        EXPECT_EQ(r.wa, 0.0);
    }
}

// A bar (m, L x h) sliding sideways at v (along -y) hits a fixed post A at distance d from its
// centre along the bar. Contact on the bar's lower face: rb = (d, -h/2), n = +y, rb x n = d:
//   j = (1 + e) m v / (1 + m d^2 / I),  vb' = (0, -v + j/m),  wb' = d j / I
// (counter-clockwise: the bar's right part is stopped). d = 0: j = (1 + e) m v, no spin.
TEST(Response2D, BarStrikesPost) {
    const double m = 3.0, L = 2.0, h = 0.2, v = 1.5, e = 0.4;
    const double I = rectangle_inertia_2d(m, L, h);
    for (double d : {0.0, 0.25, 0.5, 0.8, 1.0}) {
        SCOPED_TRACE(d);
        Body2 bar;
        bar.mass = m;
        bar.inertia = I;
        bar.v = Vec2(0.0, -v);
        Body2 post = static_ground();
        post.position = Vec2(d, -1.0);
        const Vec2 p(d, -0.5 * h);
        const Response2 r = frictionless(at_contact(post, p), at_contact(bar, p), Vec2(0, 1), e);
        const double j = (1 + e) * m * v / (1 + m * d * d / I);
        EXPECT_NEAR_ABS_REL(r.P, Vec2(0.0, j), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(r.vb, Vec2(0.0, -v + j / m), kAtol, kRtol);
        EXPECT_NEAR_ABS_REL(r.wb, d * j / I, kAtol, kRtol);
    }
}

// A free rod (m, L) at rest along x is struck perpendicularly at distance d from its centre by a
// ball A whose contact lever is along n (ra x n = 0, no spin for the ball). With the impulse j:
//   v = j/m, w = j d / I = 12 j d/(m L^2); the far end (x = -L/2) moves at
//   j/m - w L/2 = (j/m)(1 - 6 d/L)
// which vanishes at the centre of percussion d = L/6 ("the pivot end is momentarily at rest")
// and is -j/(2m) for d = L/4.
TEST(Response2D, CentreOfPercussionLeavesFarEndAtRest) {
    const double m = 1.2, L = 0.9, R = 0.1;
    for (double d : {L / 6.0, L / 4.0}) {
        Body2 rod;
        rod.mass = m;
        rod.inertia = rod_inertia_2d(m, L);
        Body2 ball;
        ball.mass = 0.3;
        ball.inertia = disc_inertia_2d(0.3, R);
        ball.position = Vec2(d, -R);
        ball.v = Vec2(0.0, 2.0);
        const Vec2 p(d, 0.0);
        const ImpactBody2 a = at_contact(ball, p), b = at_contact(rod, p);
        const Response2 r = frictionless(a, b, Vec2(0, 1), 0.7);
        const double j = r.P.y();
        EXPECT_GT(j, 0.0);
        EXPECT_EQ(r.P.x(), 0.0);
        EXPECT_EQ(r.wa, 0.0);  // the ball's lever is along n
        const Vec2 far_end = r.vb + cross(r.wb, Vec2(-0.5 * L, 0.0));
        if (d == L / 6.0) {
            EXPECT_LE(far_end.norm(), 1e-12);
        } else {
            EXPECT_NEAR_ABS_REL(far_end, Vec2(0.0, -j / (2 * m)), kAtol, kRtol);
        }
    }
}

// The rod's centre falls (v = (0, -1)) but it spins clockwise fast enough that its lower end
// rises: horizontal rod, L = 1, end at r = (-1/2, 0), w = -4: vp_y = -1 + (-4)(-1/2) = +1 > 0.
// No model gives an impulse to a separating contact.
TEST(Response2D, SpinningAwayIsSeparating) {
    Body2 rod;
    rod.mass = 1.0;
    rod.inertia = rod_inertia_2d(1.0, 1.0);
    rod.position = Vec2(0.0, 0.0);
    rod.v = Vec2(0.0, -1.0);
    rod.w = -4.0;
    const Vec2 p(-0.5, 0.0);
    const ImpactBody2 a = at_contact(static_ground(), p), b = at_contact(rod, p);
    EXPECT_NEAR_ABS_REL(relative_velocity(a, b), Vec2(0.0, 1.0), kAtol, kRtol);
    const Vec2 n(0, 1);
    for (const Response2& r :
         {frictionless(a, b, n, 1.0), coulomb(a, b, n, 0.5, 1.0), matrix(a, b, n, 0.5), stick(a, b, n)}) {
        EXPECT_TRUE(r.separating);
        EXPECT_EQ(r.P, Vec2::Zero());
        EXPECT_EQ(r.vb, rod.v);
        EXPECT_EQ(r.wb, rod.w);
    }
}

// rotational_term = (r x n)^2 / I: r = (3, 4), n = (0, 1): r x n = 3, I = 2: 9/2.
TEST(Response2D, RotationalTermHandValue) {
    ImpactBody2 b;
    b.inv_m = 1.0;
    b.inv_I = 0.5;
    b.I = 2.0;
    b.r = Vec2(3, 4);
    EXPECT_NEAR_ABS_REL(rotational_term(b, Vec2(0, 1)), 4.5, kAtol, kRtol);
}

}  // namespace
