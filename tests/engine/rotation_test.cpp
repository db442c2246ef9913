// Torque-free rotation: closed forms (steady spin, the symmetric top's precession), the
// invariants over 10^4 output steps, and the Dzhanibekov flip of the intermediate axis.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "engine/rotation.h"

namespace collide {
namespace {

Body3 body_with(const Vec3& principal, const Vec3& w_body, const Quat& q = Quat::Identity()) {
    Body3 b;
    b.mass = 1.0;
    b.inertia = principal.asDiagonal();
    b.orientation = q;
    b.w = q * w_body;
    return b;
}
Vec3 body_w(const Body3& b) { return b.orientation.conjugate() * b.w; }
Vec3 world_L(const Body3& b) { return b.inertia_world() * b.w; }
double energy(const Body3& b) { return 0.5 * b.w.dot(b.inertia_world() * b.w); }

// Spin about a principal axis is steady: w stays, and the body turns by w t about that axis.
TEST(Rotation, SteadySpinAboutPrincipalAxis) {
    Body3 b = body_with(Vec3(1, 2, 3), Vec3(0, 0, 4));
    rotate_free(&b, 0.7);
    EXPECT_LE((b.w - Vec3(0, 0, 4)).norm(), 1e-13);
    const Quat expected(Eigen::AngleAxisd(4 * 0.7, Vec3::UnitZ()));
    EXPECT_NEAR(std::abs(b.orientation.dot(expected)), 1.0, 1e-13);
}

// Symmetric top (I1 = I2 = Ip): Euler's equations give, in the body frame,
//   w1 = A cos(W t), w2 = A sin(W t), w3 constant, W = (I3 - Ip) w3 / Ip.
TEST(Rotation, SymmetricTopPrecessesAtTheEulerRate) {
    const double Ip = 2.0, I3 = 0.5, A = 0.8, w3 = 6.0, T = 3.3;
    const Quat q0(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()));
    Body3 b = body_with(Vec3(Ip, Ip, I3), Vec3(A, 0, w3), q0);
    const double W = (I3 - Ip) * w3 / Ip;
    rotate_free(&b, T);
    EXPECT_LE((body_w(b) - Vec3(A * std::cos(W * T), A * std::sin(W * T), w3)).norm(), 1e-9);
}

// The regular precession of a torque-free symmetric top, in closed form: its figure axis e3
// turns about the fixed L at |L| / I1 (any mechanics text), and its orientation q(t) obeys
// dq/dt = w q / 2 with w = I(t)^-1 L: checked against a central difference of q (to 1e-7 of
// |w|), with |L|, L and the energy kept to 1e-12 and one exact step whatever the time.
TEST(Rotation, SymmetricTopTurnsInClosedForm) {
    const double Ip = 2.0, I3 = 0.5;
    const Quat q0(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()));
    const Body3 start = body_with(Vec3(Ip, Ip, I3), Vec3(0.8, -0.3, 6.0), q0);
    EXPECT_FALSE(rotation_integrated(start));
    EXPECT_TRUE(rotation_integrated(body_with(Vec3(1, 2, 3), Vec3(0.8, -0.3, 6.0), q0)));
    const Vec3 L0 = world_L(start);
    const double E0 = energy(start);
    auto at = [&](double t) {
        Body3 b = start;
        EXPECT_EQ(rotate_free(&b, t), 1u);
        return b;
    };
    for (double T : {0.3, 3.3, 100.0}) {
        const Body3 b = at(T);
        EXPECT_LE((world_L(b) - L0).norm(), 1e-12 * L0.norm()) << T;
        EXPECT_NEAR(energy(b), E0, 1e-12 * E0) << T;
        // The figure axis: turned about L by |L| T / I1 from where it was.
        const Vec3 e3 = b.orientation * Vec3::UnitZ();
        const Vec3 expected = Eigen::AngleAxisd(L0.norm() * T / Ip, L0.normalized()) * (q0 * Vec3::UnitZ());
        EXPECT_LE((e3 - expected).norm(), 1e-11 * std::max(1.0, T)) << T;
        // dq/dt = w q / 2: (q(T + d) q(T - d)^*) is the turn by w 2d.
        const double d = 1e-6;
        const Quat turn = at(T + d).orientation * at(T - d).orientation.conjugate();
        const Eigen::AngleAxisd aa(turn);
        const Vec3 w_fd = aa.axis() * (aa.angle() / (2.0 * d));
        EXPECT_LE((w_fd - b.w).norm(), 1e-7 * b.w.norm()) << T;
    }
}

// An asymmetric body tumbling for 10^4 output steps of 0.01 s: |L| and kinetic energy kept to
// 1e-9 relative (the midpoint rule keeps both quadratic invariants), and the direction of the
// world angular momentum too.
TEST(Rotation, InvariantsOverTenThousandSteps) {
    const Quat q0(Eigen::AngleAxisd(1.1, Vec3(-1, 0.5, 2).normalized()));
    Body3 b = body_with(Vec3(0.3, 0.7, 0.9), Vec3(3, -2, 5), q0);
    const Vec3 L0 = world_L(b);
    const double E0 = energy(b);
    double worst_L = 0, worst_E = 0, worst_dir = 0;
    for (int i = 0; i < 10000; ++i) {
        rotate_free(&b, 0.01);
        const Vec3 L = world_L(b);
        worst_L = std::max(worst_L, std::abs(L.norm() - L0.norm()) / L0.norm());
        worst_E = std::max(worst_E, std::abs(energy(b) - E0) / E0);
        worst_dir = std::max(worst_dir, (L - L0).norm() / L0.norm());
    }
    EXPECT_LT(worst_L, 1e-9);
    EXPECT_LT(worst_E, 1e-9);
    EXPECT_LT(worst_dir, 1e-8);
    char text[64];
    std::snprintf(text, sizeof text, "|L| %.2e, energy %.2e, direction of L %.2e", worst_L, worst_E, worst_dir);
    RecordProperty("relative_drift", text);
}

// Dzhanibekov: spun almost exactly about the intermediate axis (I2 of 1 < 2 < 3), the body
// flips over and back again (w2 changes sign); spun the same way about the smallest or the
// largest axis it stays put.
int sign_changes(const Vec3& principal, int axis, double seconds) {
    Vec3 w = Vec3::Constant(1e-3);
    w[axis] = 5.0;
    Body3 b = body_with(principal, w);
    int changes = 0;
    double last = w[axis];
    for (int i = 0; i < static_cast<int>(seconds / 0.01); ++i) {
        rotate_free(&b, 0.01);
        const double now = body_w(b)[axis];
        if ((now > 0) != (last > 0)) ++changes;
        last = now;
    }
    return changes;
}

TEST(Rotation, DzhanibekovFlipOfTheIntermediateAxis) {
    const Vec3 I(1, 2, 3);
    EXPECT_GE(sign_changes(I, 1, 30.0), 2);  // over and back
    EXPECT_EQ(sign_changes(I, 0, 30.0), 0);
    EXPECT_EQ(sign_changes(I, 2, 30.0), 0);
}

TEST(Rotation, StaticAndRestingBodiesStay) {
    Body3 b = body_with(Vec3(1, 2, 3), Vec3::Zero());
    rotate_free(&b, 1.0);
    EXPECT_EQ(b.orientation.coeffs(), Quat::Identity().coeffs());
    Body3 s = body_with(Vec3(1, 2, 3), Vec3(1, 1, 1));
    s.is_static = true;
    rotate_free(&s, 1.0);
    EXPECT_EQ(s.w, Vec3(1, 1, 1));
}

}  // namespace
}  // namespace collide
