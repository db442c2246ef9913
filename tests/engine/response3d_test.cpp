// 3D frictionless response (engine/response3d.cpp) against closed forms: the rod's end striking
// the ground at any heading, a bar striking a post, the centre of percussion in a rotated frame,
// billiard balls, and a contact separating because of spin. World inertia tensors here are
// not diagonal (bodies are turned), so R I R^T is exercised.
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

Quat about(const Vec3& axis, double angle) { return Quat(Eigen::AngleAxisd(angle, axis)); }

Body3 static_ground() {
    Body3 g;
    g.is_static = true;
    g.position = Vec3(0.0, -1.0, 0.0);
    return g;
}

// The rod of Response2D.RodEndStrikesGround in 3D (y up, ground y = 0, n = +y), turned by a
// heading psi about y: orientation Ry(psi) Rz(theta), axis a = Ry(psi)(cos t, sin t, 0), centre
// at height (L/2) sin t, foot at centre - (L/2) a, so rb = -(L/2) a.
//   rb x n = -(L/2) Ry(psi) ((cos t, sin t, 0) x y) = -(L/2) cos t Ry(psi) z,
// which is across the rod, where the moment is T (thin rod: m L^2/12; solid rod of radius R:
// m (3 R^2 + L^2)/12). So
//   j = (1 + e) m v0 / (1 + m (L/2)^2 cos^2 t / T)   (thin rod: (1 + e) m v0/(1 + 3 cos^2 t)),
//   vb' = vb + (j/m) y,   wb' = -(L/2) cos t j / T  Ry(psi) z.
// The thin rod's tensor is singular: the engine's pseudo-inverse is used.
TEST(Response3D, RodEndStrikesGroundAtAnyHeading) {
    const double m = 2.0, L = 1.5, v0 = 3.0, e = 0.6;
    for (double radius : {0.0, 0.1}) {
        const double T = m * (3 * radius * radius + L * L) / 12.0;
        for (double psi_deg : {0.0, 35.0, 90.0, 200.0}) {
            for (double deg : {0.0, 20.0, 30.0, 45.0, 60.0, 75.0, 90.0}) {
                SCOPED_TRACE(::testing::Message() << "radius " << radius << " heading " << psi_deg << " tilt " << deg);
                const double t = deg * kPi / 180.0, psi = psi_deg * kPi / 180.0;
                const double c = std::cos(t);
                Body3 rod;
                rod.mass = m;
                rod.inertia = rod_inertia(m, L, radius);
                rod.orientation = about(Vec3::UnitY(), psi) * about(Vec3::UnitZ(), t);
                rod.position = Vec3(0.0, 0.5 * L * std::sin(t), 0.0);
                rod.v = Vec3(0.0, -v0, 0.0);
                const Vec3 axis = rod.rotation().col(0);
                const Vec3 p = rod.position - 0.5 * L * axis;
                ASSERT_NEAR(p.y(), 0.0, 1e-14);
                const ImpactBody3 a = at_contact(static_ground(), p), b = at_contact(rod, p);
                const Response3 r = frictionless(a, b, Vec3::UnitY(), e);

                const double j = (1 + e) * m * v0 / (1 + m * 0.25 * L * L * c * c / T);
                if (radius == 0.0) {
                    EXPECT_NEAR_ABS_REL(j, (1 + e) * m * v0 / (1 + 3 * c * c), kAtol, kRtol);
                }
                const Vec3 spin_axis = about(Vec3::UnitY(), psi) * Vec3::UnitZ();
                EXPECT_NEAR_ABS_REL(r.P, Vec3(0.0, j, 0.0), kAtol, kRtol);
                EXPECT_NEAR_ABS_REL(r.vb, Vec3(0.0, -v0 + j / m, 0.0), kAtol, kRtol);
                EXPECT_NEAR_ABS_REL(r.wb, Vec3(-0.5 * L * c * j / T * spin_axis), kAtol, kRtol);
                // The foot leaves the ground at e v0.
                EXPECT_NEAR_ABS_REL(Vec3(r.vb + r.wb.cross(b.r)).dot(Vec3::UnitY()), e * v0, kAtol, kRtol);
            }
        }
    }
}

// The bar of Response2D.BarStrikesPost as a box (L, h, depth), turned by psi about y. The post
// touches the bar's lower face at Ry(psi)(d, -h/2, 0); n = +y.
//   rb x n = Ry(psi)((d, -h/2, 0) x y) = d Ry(psi) z, a principal axis with Izz = m (L^2 + h^2)/12:
//   j = (1 + e) m v / (1 + m d^2 / Izz), vb' = (0, -v + j/m, 0), wb' = (d j / Izz) Ry(psi) z.
TEST(Response3D, BarStrikesPost) {
    const double m = 3.0, L = 2.0, h = 0.2, depth = 0.3, v = 1.5, e = 0.4;
    const double Izz = m * (L * L + h * h) / 12.0;
    for (double psi : {0.0, 0.4, 1.3}) {
        for (double d : {0.0, 0.25, 0.5, 1.0}) {
            SCOPED_TRACE(::testing::Message() << "psi " << psi << " d " << d);
            Body3 bar;
            bar.mass = m;
            bar.inertia = box_inertia(m, Vec3(L, h, depth));
            bar.orientation = about(Vec3::UnitY(), psi);
            bar.v = Vec3(0.0, -v, 0.0);
            const Vec3 p = bar.orientation * Vec3(d, -0.5 * h, 0.0);
            Body3 post = static_ground();
            post.position = p - Vec3(0.0, 0.5, 0.0);
            const Response3 r = frictionless(at_contact(post, p), at_contact(bar, p), Vec3::UnitY(), e);
            const double j = (1 + e) * m * v / (1 + m * d * d / Izz);
            EXPECT_NEAR_ABS_REL(r.P, Vec3(0.0, j, 0.0), kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(r.vb, Vec3(0.0, -v + j / m, 0.0), kAtol, kRtol);
            EXPECT_NEAR_ABS_REL(r.wb, Vec3(d * j / Izz * (bar.orientation * Vec3::UnitZ())), kAtol, kRtol);
        }
    }
}

// Centre of percussion (see Response2D.CentreOfPercussionLeavesFarEndAtRest) in randomly
// rotated frames Q, with the rod already moving: the impulse j at d = L/6 changes the far end's
// velocity by (j/m)(1 - 6 d/L) = 0, so the far end keeps its velocity (and a rod at rest keeps
// its far end at rest). The rod is thin (singular tensor, pseudo-inverse); the strike is across
// it, n = Q y, from a ball whose lever is along n.
TEST(Response3D, CentreOfPercussionInRotatedFrames) {
    collide_test::Random rng(401);
    const double m = 1.2, L = 0.9, R = 0.1, d = L / 6.0;
    for (int i = 0; i < 100; ++i) {
        const Quat Q = rng.rotation();
        const bool at_rest = i % 2 == 0;
        Body3 rod;
        rod.mass = m;
        rod.inertia = rod_inertia(m, L);
        rod.orientation = Q;
        rod.position = rng.vec3(-1, 1);
        if (!at_rest) {
            rod.v = rng.vec3(-0.3, 0.3);
            rod.w = rng.vec3(-0.3, 0.3);
        }
        const Vec3 n = Q * Vec3::UnitY();
        const Vec3 p = rod.position + Q * Vec3(d, 0.0, 0.0);
        Body3 ball;
        ball.mass = rng.mass();
        ball.inertia = sphere_inertia(ball.mass, R);
        ball.position = p - R * n;
        ball.v = 5.0 * n;
        ball.w = rng.vec3(-3, 3);  // a spinning ball: its lever is along n, no effect
        const ImpactBody3 a = at_contact(ball, p), b = at_contact(rod, p);
        const Response3 r = frictionless(a, b, n, rng.uniform(0, 1));
        ASSERT_FALSE(r.separating);
        const Vec3 far = Q * Vec3(-0.5 * L, 0.0, 0.0);
        const Vec3 before = rod.v + rod.w.cross(far), after = r.vb + r.wb.cross(far);
        if (at_rest) {
            EXPECT_LE(after.norm(), 1e-12);
        } else {
            EXPECT_LE((after - before).norm(), 1e-12);
        }
        // The ball's spin is untouched (ra x n = 0).
        EXPECT_NEAR_ABS_REL(r.wa, ball.w, kAtol, kRtol);
    }
}

// Billiards: equal spheres, e = 1, B at rest, A at v = (2, 0, 0), line of centres n at 30 degrees.
// r is along n for both, so r x n = 0: j = -(1 + e) un/(2/m) = m (v.n). B leaves along n with
// (v.n) n, A keeps v - (v.n) n: the paths are at 90 degrees. Spins do not matter (w x r is
// perpendicular to n) and are unchanged.
TEST(Response3D, BilliardBallsLeaveAtRightAngles) {
    const double m = 0.17, R = 0.0285;
    const Vec3 n(std::cos(kPi / 6), std::sin(kPi / 6), 0.0);
    Body3 a, b;
    a.mass = b.mass = m;
    a.inertia = b.inertia = sphere_inertia(m, R);
    a.position = Vec3::Zero();
    b.position = 2 * R * n;
    a.v = Vec3(2, 0, 0);
    a.w = Vec3(1, -7, 3);
    b.w = Vec3(0, 4, 0);
    const Vec3 p = R * n;
    const Response3 r = frictionless(at_contact(a, p), at_contact(b, p), n, 1.0);
    const double vn = a.v.dot(n);
    EXPECT_NEAR_ABS_REL(r.P, Vec3(m * vn * n), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.vb, Vec3(vn * n), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.va, Vec3(a.v - vn * n), kAtol, kRtol);
    EXPECT_NEAR(r.va.dot(r.vb), 0.0, 1e-14);
    EXPECT_NEAR_ABS_REL(r.wa, a.w, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(r.wb, b.w, kAtol, kRtol);
}

// A horizontal rod (L = 1) whose centre falls at 1 m/s, spinning about z at w = -4 rad/s:
// its end at r = (-1/2, 0, 0) moves at -1 + (w x r).y = -1 + (-4)(-1/2) = +1 m/s: separating.
// No model gives an impulse.
TEST(Response3D, SpinningAwayIsSeparating) {
    Body3 rod;
    rod.mass = 1.0;
    rod.inertia = rod_inertia(1.0, 1.0);
    rod.v = Vec3(0.0, -1.0, 0.0);
    rod.w = Vec3(0.0, 0.0, -4.0);
    const Vec3 p(-0.5, 0.0, 0.0), n = Vec3::UnitY();
    const ImpactBody3 a = at_contact(static_ground(), p), b = at_contact(rod, p);
    EXPECT_NEAR_ABS_REL(relative_velocity(a, b), Vec3(0.0, 1.0, 0.0), kAtol, kRtol);
    for (const Response3& r : {frictionless(a, b, n, 1.0), coulomb(a, b, n, 0.5, 1.0), matrix(a, b, n, 0.5),
                               stick(a, b, n), stick_newton_euler(a, b, n)}) {
        EXPECT_TRUE(r.separating);
        EXPECT_EQ(r.P, Vec3::Zero());
        EXPECT_EQ(r.vb, rod.v);
        EXPECT_EQ(r.wb, rod.w);
    }
}

// rotational_term = (r x n).I^-1 (r x n): r = (1, 2, 0), n = z: r x n = (2, -1, 0);
// I^-1 = diag(1, 2, 3): 4*1 + 1*2 = 6.
TEST(Response3D, RotationalTermHandValue) {
    ImpactBody3 b;
    b.inv_m = 1.0;
    b.inv_I = Vec3(1, 2, 3).asDiagonal();
    b.r = Vec3(1, 2, 0);
    EXPECT_NEAR_ABS_REL(rotational_term(b, Vec3::UnitZ()), 6.0, kAtol, kRtol);
}

}  // namespace
