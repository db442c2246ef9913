// One time step of the stepped islands (engine/island_step.h) on its own, driven here as the
// world drives it (contacts within a margin at the step's start, the step, then x+ = x- + h v+):
// impulses between the bodies conserve momentum and angular momentum, Newton's law holds on
// the approach, a disc sliding on the ground ends rolling at the speed its angular momentum
// about the contact fixes, and a stack at rest stays at rest within the engine's stated
// tolerances (kStepSleepSpeed for speeds, the slop and one step of gravity for overlaps).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/island_step.h"
#include "engine/rotation.h"
#include "engine/world.h"
#include "tests/engine/random_bodies.h"
#include "tests/scenes/world_scenes.h"

namespace collide {
namespace {

using scenes::disc;
using scenes::half_plane;
using scenes::half_space;
using scenes::rectangle;
using scenes::sphere;

constexpr double kH = World2::kIslandStep;  // s

// Bodies and their shapes, stepped as engine/stepped.cpp steps them.
template <int D>
struct Bench {
    using Vec = typename Space<D>::Vec;
    using Body = typename Space<D>::Body;
    using Shape = typename Space<D>::Shape;
    std::vector<Body> bodies;
    std::vector<Shape> shapes;
    double e = 0.0, mu = 0.0;
    Vec g = Vec::Zero();
    IslandStepper<D> stepper;

    std::size_t add(const SceneBody& b) {
        if constexpr (D == 2) {
            bodies.push_back(b.body2);
            shapes.push_back(b.shape2);
        } else {
            bodies.push_back(b.body3);
            shapes.push_back(b.shape3);
        }
        return bodies.size() - 1;
    }

    // The step's contacts: every pair within the speculative margin plus what the step can close.
    std::vector<StepContact<D>> contacts() const {
        std::vector<StepContact<D>> out;
        for (std::size_t a = 0; a < bodies.size(); ++a)
            for (std::size_t b = a + 1; b < bodies.size(); ++b) {
                if (bodies[a].is_static && bodies[b].is_static) continue;
                const double margin =
                    World<D>::kSpeculative + (bodies[a].v.norm() + bodies[b].v.norm() + 2.0 * g.norm() * kH) * kH;
                StepContact<D> c;
                c.m = manifold(a, b, margin);
                if (c.m.count == 0) continue;
                c.a = a;
                c.b = b;
                c.e = e;
                c.mu = mu;
                out.push_back(c);
            }
        return out;
    }
    typename Space<D>::Manifold manifold(std::size_t a, std::size_t b, double margin) const {
        if constexpr (D == 2)
            return collide::collide(shapes[a], pose_of(bodies[a]), shapes[b], pose_of(bodies[b]), margin, Apart::axis);
        else return collide::collide(shapes[a], pose_of(bodies[a]), shapes[b], pose_of(bodies[b]), margin);
    }

    // One step: the solve, then the motion at the new velocities.
    std::vector<StepContact<D>> step() {
        std::vector<StepContact<D>> c = contacts();
        std::vector<std::size_t> members;
        for (std::size_t i = 0; i < bodies.size(); ++i)
            if (!bodies[i].is_static) members.push_back(i);
        stepper.step(&c, members, &bodies, g, kH);
        for (Body& b : bodies) {
            if (b.is_static) continue;
            b.position += kH * b.v;
            if constexpr (D == 2) {
                b.angle += kH * b.w;
            } else {
                const Vec3 phi = b.w * kH;
                if (phi.squaredNorm() > 0.0) b.orientation = (exp_map(phi) * b.orientation).normalized();
            }
        }
        return c;
    }
};

// Linear momentum, and angular momentum about the origin (2D: its z component).
template <class Body>
auto momentum(const std::vector<Body>& bs) {
    decltype(Body().v) p = decltype(Body().v)::Zero();
    for (const Body& b : bs) p += b.mass * b.v;
    return p;
}
double angular_momentum(const std::vector<Body2>& bs) {
    double L = 0.0;
    for (const Body2& b : bs) L += b.mass * cross(b.position, b.v) + b.inertia * b.w;
    return L;
}
Vec3 angular_momentum(const std::vector<Body3>& bs) {
    Vec3 L = Vec3::Zero();
    for (const Body3& b : bs) {
        const Mat3 R = b.rotation();
        L += b.mass * b.position.cross(b.v) + R * b.inertia * R.transpose() * b.w;
    }
    return L;
}

// A chain of discs (spheres), each touching the one before, the chain turning at random (by at
// most 30 degrees, so that no two of them overlap), moving and spinning at random, no gravity:
// the step's impulses act in equal and opposite pairs at common points, so momentum and
// angular momentum (about any point, here the origin, with the positions they acted at) are
// what they were.
template <int D>
void expect_impulses_conserve_momentum(std::uint64_t seed) {
    using Vec = typename Space<D>::Vec;
    collide_test::Random rng(seed);
    for (int trial = 0; trial < 20; ++trial) {
        Bench<D> s;
        s.e = rng.uniform(0.0, 1.0);
        s.mu = trial % 2 ? 0.0 : rng.uniform(0.1, 1.0);
        Vec x = Vec::Zero();
        double r_prev = 0.0;
        std::vector<std::size_t> all;
        for (int k = 0; k < 6; ++k) {
            const double r = rng.uniform(0.2, 0.6), m = rng.uniform(0.5, 3.0);
            if constexpr (D == 2) {
                const double a = rng.uniform(-0.5, 0.5);
                if (k > 0) x += (r_prev + r) * Vec2(std::cos(a), std::sin(a));
                all.push_back(s.add(disc("d", r, m, x, rng.vec2(-2, 2), rng.uniform(-5, 5))));
            } else {
                if (k > 0) x += (r_prev + r) * (Vec3::UnitX() + 0.5 * rng.unit3()).normalized();
                all.push_back(s.add(sphere("s", r, m, x, rng.vec3(-2, 2), rng.vec3(-5, 5))));
            }
            r_prev = r;
        }
        const Vec p0 = momentum(s.bodies);
        const auto L0 = angular_momentum(s.bodies);
        const auto start = s.bodies;
        std::vector<StepContact<D>> c = s.contacts();
        s.stepper.step(&c, all, &s.bodies, Vec::Zero(), kH);
        auto after = start;  // the step's velocities, at the positions they acted at
        for (std::size_t i = 0; i < after.size(); ++i) {
            EXPECT_EQ(s.bodies[i].position, start[i].position) << "no penetration: nothing to correct";
            after[i].v = s.bodies[i].v;
            after[i].w = s.bodies[i].w;
        }
        double impulse = 0.0;
        for (const StepContact<D>& ct : c) impulse += ct.impulse.norm();
        EXPECT_GT(impulse, 0.0) << "trial " << trial << ": the chain should collide somewhere";
        const double scale = p0.norm() + impulse;
        EXPECT_NEAR((momentum(after) - p0).norm(), 0.0, 1e-13 * scale) << "trial " << trial;
        EXPECT_NEAR(magnitude(angular_momentum(after) - L0), 0.0, 1e-12 * scale) << "trial " << trial;
    }
}

TEST(IslandStep, ImpulsesConserveMomentumAndAngularMomentum2D) { expect_impulses_conserve_momentum<2>(42); }
TEST(IslandStep, ImpulsesConserveMomentumAndAngularMomentum3D) { expect_impulses_conserve_momentum<3>(43); }

// Two discs meeting head on: Newton's law on the approach before the step, un+ = -e un-, and
// the centre-of-mass velocity kept.
TEST(IslandStep, HeadOnImpactFollowsNewtonsLaw) {
    for (double e : {0.0, 0.4, 1.0}) {
        Bench<2> s;
        s.e = e;
        const double m1 = 1.0, m2 = 3.0, v1 = 2.0, v2 = -1.0;
        s.add(disc("1", 0.5, m1, Vec2(0.0, 0.0), Vec2(v1, 0.0)));
        s.add(disc("2", 0.5, m2, Vec2(1.0, 0.0), Vec2(v2, 0.0)));
        s.step();
        const double u = v2 - v1;  // approach (< 0)
        EXPECT_NEAR(s.bodies[1].v.x() - s.bodies[0].v.x(), -e * u, 1e-12) << "e " << e;
        EXPECT_NEAR(m1 * s.bodies[0].v.x() + m2 * s.bodies[1].v.x(), m1 * v1 + m2 * v2, 1e-12) << "e " << e;
        EXPECT_NEAR(s.bodies[0].v.y(), 0.0, 1e-15);
        EXPECT_NEAR(s.bodies[0].w, 0.0, 1e-12);
    }
}

// A disc (I = m r^2 / 2) launched sliding at v0 without spin on rough ground: friction (mu m g
// per second) slows it and spins it up until it rolls. Friction and the normal force act at the
// contact and gravity through the centre, so the angular momentum about the contact point,
// m r v + I w, is kept: it rolls on at v0 / (1 + I / (m r^2)) = 2 v0 / 3. Before that, each
// step takes mu g h off its speed.
TEST(IslandStep, SlidingDiscEndsRollingAtTwoThirdsItsSpeed) {
    const double m = 2.0, r = 0.25, v0 = 3.0;
    Bench<2> s;
    s.mu = 0.4;
    s.g = Vec2(0.0, -9.81);
    s.add(half_plane("ground", Vec2(0.0, 1.0), 0.0));
    s.add(disc("disc", r, m, Vec2(0.0, r), Vec2(v0, 0.0)));
    s.step();
    EXPECT_NEAR(s.bodies[1].v.x(), v0 - s.mu * 9.81 * kH, 1e-9);
    // Rolling starts at t = v0 / (3 mu g) = 0.25 s; run well past it.
    for (int k = 0; k < 600; ++k) s.step();
    const Body2& d = s.bodies[1];
    EXPECT_NEAR(d.v.x(), 2.0 * v0 / 3.0, 1e-9 * v0);
    EXPECT_NEAR(d.v.x() + d.w * r, 0.0, 1e-9 * v0) << "rolling: the contact point at rest";
    EXPECT_NEAR(d.v.y(), 0.0, 1e-9);
}

// The same for a sphere (I = 2 m r^2 / 5): it rolls on at 5 v0 / 7, along its slide.
TEST(IslandStep, SlidingSphereEndsRollingAtFiveSeventhsItsSpeed) {
    const double m = 1.0, r = 0.2;
    const Vec3 v0(2.0, 0.0, -1.0);
    Bench<3> s;
    s.mu = 0.3;
    s.g = Vec3(0.0, -9.81, 0.0);
    s.add(half_space("ground", Vec3::UnitY(), 0.0));
    s.add(sphere("ball", r, m, Vec3(0.0, r, 0.0), v0));
    for (int k = 0; k < 600; ++k) s.step();
    const Body3& b = s.bodies[1];
    EXPECT_NEAR((b.v - 5.0 / 7.0 * v0).norm(), 0.0, 1e-9 * v0.norm());
    EXPECT_NEAR((b.v + b.w.cross(Vec3(0.0, -r, 0.0))).norm(), 0.0, 1e-9 * v0.norm());
}

// Three boxes stacked on the ground, exactly touching and at rest, with gravity and friction.
// The sweeps start cold and settle within a tenth of a second (warm-started from step to step);
// from then on, for the rest of a second, every body stays slower than kStepSleepSpeed (the
// speed under which the world lets a stepped island sleep), and no overlap ever grows beyond
// the slop the split impulse leaves plus one step of gravity, g h^2.
TEST(IslandStep, RestingStackStaysAtRest) {
    const double w = 1.0, hgt = 0.5, m = 1.0, g = 9.81;
    Bench<2> s;
    s.mu = 0.5;
    s.e = 0.3;
    s.g = Vec2(0.0, -g);
    s.add(half_plane("ground", Vec2(0.0, 1.0), 0.0));
    for (int k = 0; k < 3; ++k) s.add(rectangle("box", w, hgt, m, Vec2(0.1 * k, hgt * (k + 0.5))));
    const std::vector<Body2> start = s.bodies;
    const double deepest = IslandStepper<2>::kSlop + g * kH * kH;
    for (int step = 0; step < 600; ++step) {
        for (const StepContact<2>& c : s.step()) EXPECT_GE(c.m.separation, -deepest) << "step " << step;
        for (std::size_t i = 1; i < s.bodies.size(); ++i) {
            const Body2& b = s.bodies[i];
            const double surface = b.v.norm() + std::abs(b.w) * 0.5 * std::hypot(w, hgt);
            if (step * kH < 0.1) continue;
            ASSERT_LT(surface, World2::kStepSleepSpeed) << "body " << i << " at step " << step;
        }
    }
    for (std::size_t i = 1; i < s.bodies.size(); ++i) {
        // Each body sits at most the overlaps below it lower than it started, and never higher.
        EXPECT_LE(s.bodies[i].position.y(), start[i].position.y() + 1e-12);
        EXPECT_GE(s.bodies[i].position.y(), start[i].position.y() - i * deepest);
        EXPECT_NEAR(s.bodies[i].position.x(), start[i].position.x(), deepest);
    }
}

}  // namespace
}  // namespace collide
