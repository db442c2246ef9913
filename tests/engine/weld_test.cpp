// Stuck bodies (engine/world.h, "Stuck bodies"): under the stick model two bodies that meet
// move on as one rigid body. Checked against the closed form of the compound's motion, which
// the test computes on its own from the bodies' data:
//   M = ma + mb, xc = (ma xa + mb xb) / M, vc = (ma va + mb vb) / M  (momentum kept),
//   Ic = Ia + Ib + ma |da|^2 + mb |db|^2 (2D, d = x - xc),  L = Ia wa + Ib wb + sum m d x v
//   (angular momentum about xc, kept through the impact: the contact impulses are internal),
//   w = L / Ic, and every later state a rigid motion: xc + vc t, the pair turned by w t.
// Tolerances: 1e-12 relative for quantities a few operations deep; 1e-9 for positions after
// several seconds of motion (round-off accumulated over many substeps, each exact in closed form).
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "engine/diagnostics.h"
#include "engine/world.h"
#include "tests/scenes/world_scenes.h"

namespace collide {
namespace {

using namespace scenes;

Scene stick_scene(int dimension, const Vec3& gravity = Vec3::Zero()) {
    Scene s = empty_scene(dimension, Policy::sequential, 0.0, gravity);
    s.model = Model::stick;
    return s;
}

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Two discs, an off-centre hit: they stick at the contact point and orbit their common centre.
TEST(Weld, StuckDiscsOrbitTheirCommonCentreOfMass) {
    const double ma = 1.0, mb = 3.0, ra = 0.1, rb = 0.2;
    Scene s = stick_scene(2);
    s.bodies.push_back(disc("a", ra, ma, Vec2(-1.0, 0.0), Vec2(2.0, 0.0), 0.5));
    s.bodies.push_back(disc("b", rb, mb, Vec2(0.0, 0.2), Vec2(0.0, 0.0), -1.0));
    // Closed form from the initial data (both free until the impact; then a rigid compound).
    const Body2 A = s.bodies[0].body2, B = s.bodies[1].body2;
    const double M = ma + mb;
    const Vec2 p0 = (ma * A.position + mb * B.position) / M, vc = (ma * A.v + mb * B.v) / M;
    const double L = A.inertia * A.w + B.inertia * B.w + cross2(A.position - p0, ma * A.v) +
                     cross2(B.position - p0, mb * B.v);  // about the (moving) centre of mass

    World2 world(s);
    std::vector<Event2> events;
    world.advance_to(6.0, &events);
    ASSERT_EQ(events.size(), 1u);  // stuck: they never meet again
    EXPECT_TRUE(world.welded(0) && world.welded(1));
    const Event2& ev = events[0];
    const double Ic_about = [&] {
        // Where they were at the impact (free flight until then), the compound's inertia.
        const Vec2 a_at = A.position + A.v * ev.t, b_at = B.position + B.v * ev.t;
        const Vec2 c_at = (ma * a_at + mb * b_at) / M;
        return A.inertia + B.inertia + ma * (a_at - c_at).squaredNorm() + mb * (b_at - c_at).squaredNorm();
    }();
    const double w = L / Ic_about;
    EXPECT_NEAR(ev.after_a.w, w, 1e-12 * std::abs(w));
    EXPECT_NEAR(ev.after_b.w, w, 1e-12 * std::abs(w));

    const Vec2 a_at = A.position + A.v * ev.t, b_at = B.position + B.v * ev.t;
    const double phi0 = std::atan2((b_at - a_at).y(), (b_at - a_at).x());
    for (double t : {ev.t + 0.3, 2.0, 4.5}) {
        World2 w2(s);
        w2.advance_to(t, nullptr);
        const Body2& a = w2.bodies()[0];
        const Body2& b = w2.bodies()[1];
        const Vec2 c = (ma * a.position + mb * b.position) / M;
        const Vec2 c_expected = p0 + vc * t;  // the centre of mass never notices the impact
        EXPECT_NEAR((c - c_expected).norm(), 0.0, 1e-9) << "t = " << t;
        EXPECT_NEAR((b.position - a.position).norm(), ra + rb, 1e-9) << "t = " << t;  // touching
        // The line of centres has turned by w (t - t_impact).
        const Vec2 d = b.position - a.position;
        const double turned = std::remainder(std::atan2(d.y(), d.x()) - phi0 - w * (t - ev.t), 2.0 * kPi);
        EXPECT_NEAR(turned, 0.0, 1e-9) << "t = " << t;
        EXPECT_NEAR(a.w, w, 1e-12 * std::abs(w));
        EXPECT_NEAR(b.w, w, 1e-12 * std::abs(w));
        // Each centre moves with the rigid motion: v = vc + w x (x - xc).
        for (const Body2* body : {&a, &b}) {
            const Vec2 r = body->position - c;
            const Vec2 v_rigid = vc + w * Vec2(-r.y(), r.x());
            EXPECT_NEAR((body->v - v_rigid).norm(), 0.0, 1e-9);
        }
        // Kinetic energy: that of the compound, constant after the impact.
        const double energy = totals(w2.bodies()).kinetic_energy;
        EXPECT_NEAR(energy, 0.5 * M * vc.squaredNorm() + 0.5 * Ic_about * w * w, 1e-12 * energy);
    }
}

// Three discs in a line, head on, all stick: A + B, then (A + B) + C. The second impact is
// answered with the compound's mass: the three move on at m v / 3m, without spin.
TEST(Weld, AStuckPairHitsAThirdBodyAsOneBody) {
    Scene s = stick_scene(2);
    s.bodies.push_back(disc("a", 0.1, 1.0, Vec2(-1.0, 0.0), Vec2(3.0, 0.0)));
    s.bodies.push_back(disc("b", 0.1, 1.0, Vec2(0.0, 0.0)));
    s.bodies.push_back(disc("c", 0.1, 1.0, Vec2(1.0, 0.0)));
    World2 world(s);
    std::vector<Event2> events;
    world.advance_to(3.0, &events);
    ASSERT_EQ(events.size(), 2u);
    // Closed form: first impact at t = 0.8 / 3, the pair at 1.5 m/s; b reaches c's gap of
    // 0.8 m at t = 0.8/3 + 0.8/1.5.
    EXPECT_NEAR(events[0].t, 0.8 / 3.0, 1e-9);
    EXPECT_NEAR(events[1].t, 0.8 / 3.0 + 0.8 / 1.5, 1e-9);
    for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(world.welded(i));
        EXPECT_NEAR(world.bodies()[i].v.x(), 1.0, 1e-12);
        EXPECT_NEAR(world.bodies()[i].v.y(), 0.0, 1e-12);
        EXPECT_NEAR(world.bodies()[i].w, 0.0, 1e-12);
    }
    EXPECT_NEAR((world.bodies()[2].position - world.bodies()[0].position).norm(), 0.4, 1e-9);
    EXPECT_EQ(world.counters().welds, 2u);
}

// 3D, boxes with full inertia tensors (rotated, spinning): after sticking, momentum and angular
// momentum about a fixed point are those before the impact, the kinetic energy stays constant
// (a torque-free compound), and the members keep their relative pose.
TEST(Weld, StuckBoxesIn3DKeepMomentaAndTheirRelativePose) {
    Scene s = stick_scene(3);
    const Quat qa = Quat(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()));
    const Quat qb = Quat(Eigen::AngleAxisd(-0.7, Vec3(-2, 1, 0.5).normalized()));
    s.bodies.push_back(
        box("a", Vec3(0.3, 0.1, 0.2), 2.0, Vec3(-1.2, 0.05, 0.1), qa, Vec3(2.0, 0.1, 0.0), Vec3(0.5, -1.0, 2.0)));
    s.bodies.push_back(
        box("b", Vec3(0.15, 0.25, 0.1), 1.0, Vec3(0.5, -0.1, 0.0), qb, Vec3(-0.5, 0.0, 0.2), Vec3(0.0, 3.0, -1.0)));
    World3 world(s);
    const Totals3 before = totals(world.bodies());
    std::vector<Event3> events;
    world.advance_to(1.0, &events);
    ASSERT_EQ(events.size(), 1u);
    ASSERT_TRUE(world.welded(0) && world.welded(1));
    const Totals3 at = totals(world.bodies());
    const Body3 a0 = world.bodies()[0], b0 = world.bodies()[1];
    const Vec3 d0 = a0.orientation.conjugate() * (b0.position - a0.position);
    const Quat q0 = a0.orientation.conjugate() * b0.orientation;
    world.advance_to(5.0, &events);
    EXPECT_EQ(events.size(), 1u);
    const Totals3 after = totals(world.bodies());
    const Body3& a = world.bodies()[0];
    const Body3& b = world.bodies()[1];
    const double p = before.momentum.norm(), l = before.angular_momentum.norm();
    EXPECT_NEAR((after.momentum - before.momentum).norm(), 0.0, 1e-12 * p);
    EXPECT_NEAR((after.angular_momentum - before.angular_momentum).norm(), 0.0, 1e-9 * l);
    EXPECT_LT(at.kinetic_energy, before.kinetic_energy);  // sticking loses energy
    EXPECT_NEAR(after.kinetic_energy, at.kinetic_energy, 1e-9 * at.kinetic_energy);
    // Rigidly joined: b's centre and frame as seen from a's do not change.
    EXPECT_NEAR((a.orientation.conjugate() * (b.position - a.position) - d0).norm(), 0.0, 1e-9);
    EXPECT_NEAR(std::abs((a.orientation.conjugate() * b.orientation).dot(q0)), 1.0, 1e-12);
    EXPECT_NEAR((a.w - b.w).norm(), 0.0, 1e-12 * a.w.norm());
}

// A stuck pair that lands and rests on the ground is beyond the model: a clear error, no hang.
TEST(Weld, AStuckPairRestingOnTheGroundIsAClearError) {
    Scene s = stick_scene(2, Vec3(0.0, -9.81, 0.0));
    s.bodies.push_back(half_plane("ground", Vec2(0, 1), 0.0));
    s.bodies.push_back(disc("a", 0.1, 1.0, Vec2(-1.0, 0.5), Vec2(3.0, 0.0)));
    s.bodies.push_back(disc("b", 0.1, 1.0, Vec2(0.0, 0.5), Vec2(-3.0, 0.0)));
    World2 world(s);
    try {
        world.advance_to(3.0, nullptr);
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("stuck to another body by the stick model"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace collide
