// The 1D world against closed forms: impact times, Newton's cradle under both policies, a
// bounce series under gravity, an elastic gas of blocks between walls.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "engine/world1d.h"

namespace collide {
namespace {

SceneBody block(const std::string& name, double x, double v, double length = 0.2, double mass = 1.0,
                bool is_static = false) {
    SceneBody b;
    b.name = name;
    b.shape = "block";
    b.length = length;
    b.body1 = Body1{mass, is_static, x, v};
    return b;
}

Scene line(Policy policy = Policy::sequential, double e = 1.0) {
    Scene s;
    s.dimension = 1;
    s.policy = policy;
    s.restitution = e;
    s.duration = 10.0;
    return s;
}

// Gap 1 m (centres 1.2 m apart, lengths 0.2) closing at 3 m/s: impact at exactly 1/3 s; with
// e = 1 and equal masses the velocities exchange.
TEST(World1d, ImpactTimeAndExchange) {
    Scene s = line();
    s.bodies = {block("a", 0.0, 1.0), block("b", 1.2, -2.0)};
    World1 w(s);
    std::vector<Event1> events;
    w.advance_to(1.0, &events);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_NEAR(events[0].t, 1.0 / 3.0, 1e-15);
    EXPECT_NEAR(events[0].point, 1.0 / 3.0 + 0.1, 1e-12);
    EXPECT_EQ(events[0].va_after, -2.0);
    EXPECT_EQ(events[0].vb_after, 1.0);
    EXPECT_DOUBLE_EQ(events[0].impulse, 3.0);  // B, arriving at -2 m/s, is pushed back along +x
    EXPECT_DOUBLE_EQ(w.time(), 1.0);
    EXPECT_NEAR(w.bodies()[0].position, 1.0 / 3.0 - 2.0 * (2.0 / 3.0), 1e-12);
}

// Newton's cradle, three equal touching blocks, the first arriving at v, e = 1.
// Sequential: (0, 0, v). Simultaneous: K = [[2, -1], [-1, 2]], K P = (2v, 0) gives
// P = (4v/3, 2v/3) and (-v/3, 2v/3, 2v/3). Both keep momentum and energy.
TEST(World1d, NewtonsCradleSequential) {
    Scene s = line(Policy::sequential);
    s.bodies = {block("1", -0.5, 2.0), block("2", 0.0, 0.0), block("3", 0.2, 0.0)};
    World1 w(s);
    std::vector<Event1> events;
    w.advance_to(0.3, &events);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_NEAR(events[0].t, 0.15, 1e-15);
    EXPECT_NEAR(w.bodies()[0].v, 0.0, 1e-15);
    EXPECT_NEAR(w.bodies()[1].v, 0.0, 1e-15);
    EXPECT_NEAR(w.bodies()[2].v, 2.0, 1e-15);
}

TEST(World1d, NewtonsCradleSimultaneous) {
    Scene s = line(Policy::simultaneous);
    s.bodies = {block("1", -0.5, 2.0), block("2", 0.0, 0.0), block("3", 0.2, 0.0)};
    World1 w(s);
    std::vector<Event1> events;
    w.advance_to(0.3, &events);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_NEAR(w.bodies()[0].v, -2.0 / 3.0, 1e-14);
    EXPECT_NEAR(w.bodies()[1].v, 4.0 / 3.0, 1e-14);
    EXPECT_NEAR(w.bodies()[2].v, 4.0 / 3.0, 1e-14);
    EXPECT_NEAR(events[0].impulse, 8.0 / 3.0, 1e-14);
    EXPECT_NEAR(events[1].impulse, 4.0 / 3.0, 1e-14);
}

// A block falls (gravity -g along x) from rest with a gap h onto a static block, e = 1/2:
// it lands at t1 = sqrt(2h/g) with speed u1 = g t1, and each bounce k leaves at e^k u1 and
// returns 2 e^k u1 / g later.
TEST(World1d, BounceSeriesUnderGravity) {
    const double g = 9.81, h = 1.0, e = 0.5;
    Scene s = line(Policy::sequential, e);
    s.gravity = Vec3(-g, 0, 0);
    s.bodies = {block("floor", 0.0, 0.0, 0.2, 1.0, true), block("ball", 0.2 + h, 0.0)};
    World1 w(s);
    std::vector<Event1> events;
    const double t1 = std::sqrt(2 * h / g), u1 = g * t1;
    w.advance_to(2.8 * t1, &events);  // the fourth landing is at 2.75 t1
    ASSERT_EQ(events.size(), 4u);
    double t = t1, u = u1;
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(events[k].t, t, 1e-12 * t) << "bounce " << k;
        EXPECT_NEAR(events[k].vb_before, -u, 1e-12 * u1);
        EXPECT_NEAR(events[k].vb_after, e * u, 1e-12 * u1);
        u *= e;
        t += 2 * u / g;
    }
}

// The series accumulates at t1 (1 + 2e/(1 - e)) = t1 (1 + e)/(1 - e) (= sqrt(2H/g)(1+e)/(1-e)):
// the ball is at rest on the floor from then on, touching it, with a finite number of events.
TEST(World1d, BouncingBallRestsAfterTheSeriesTime) {
    const double g = 9.81, H = 1.0, e = 0.5;
    Scene s = line(Policy::sequential, e);
    s.gravity = Vec3(-g, 0, 0);
    s.bodies = {block("floor", 0.0, 0.0, 0.2, 1.0, true), block("ball", 0.2 + H, 0.0)};
    World1 w(s);
    std::vector<Event1> events;
    const double t_rest = std::sqrt(2 * H / g) * (1 + e) / (1 - e);
    w.advance_to(t_rest + 0.5, &events);
    ASSERT_FALSE(events.empty());
    EXPECT_LT(events.size(), 100u);
    EXPECT_NEAR(events.back().t, t_rest, 1e-9);
    EXPECT_TRUE(w.resting(1));
    EXPECT_EQ(w.bodies()[1].v, 0.0);
    EXPECT_NEAR(w.bodies()[1].position, 0.2, 1e-12);  // on the floor: 0.1 + 0.1
    const std::size_t n = events.size();
    w.advance_to(t_rest + 10.0, &events);  // and stays
    EXPECT_EQ(events.size(), n);
    EXPECT_NEAR(w.bodies()[1].position, 0.2, 1e-12);
}

// A block placed on the floor under gravity stays exactly where it is: no jitter, no events.
TEST(World1d, BlockOnTheFloorStays) {
    Scene s = line(Policy::sequential, 0.5);
    s.gravity = Vec3(-9.81, 0, 0);
    s.bodies = {block("floor", 0.0, 0.0, 0.2, 1.0, true), block("box", 0.2, 0.0)};
    World1 w(s);
    std::vector<Event1> events;
    for (int k = 1; k <= 100; ++k) w.advance_to(0.05 * k, &events);
    EXPECT_TRUE(events.empty());
    EXPECT_EQ(w.bodies()[1].position, 0.2);
    EXPECT_EQ(w.bodies()[1].v, 0.0);
}

// A block dropped with e = 0 onto one resting on the floor: it lands at sqrt(2h/g) and both
// rest (the impulse passes through the lower block into the floor).
TEST(World1d, StackRestsAfterAPerfectlyInelasticLanding) {
    const double g = 9.81, h = 0.5;
    for (Policy policy : {Policy::sequential, Policy::simultaneous}) {
        Scene s = line(policy, 0.0);
        s.gravity = Vec3(-g, 0, 0);
        s.bodies = {block("floor", 0.0, 0.0, 0.2, 1.0, true), block("low", 0.2, 0.0), block("high", 0.4 + h, 0.0)};
        World1 w(s);
        std::vector<Event1> events;
        w.advance_to(1.0, &events);
        ASSERT_FALSE(events.empty());
        EXPECT_NEAR(events.front().t, std::sqrt(2 * h / g), 1e-12);
        EXPECT_TRUE(w.resting(1) && w.resting(2));
        EXPECT_EQ(w.bodies()[2].v, 0.0);
        EXPECT_NEAR(w.bodies()[2].position, 0.4, 1e-12);
    }
}

// e = 1: no accumulation; every landing is at the same speed sqrt(2 g H), 2 sqrt(2H/g) apart.
TEST(World1d, ElasticBallBouncesForever) {
    const double g = 9.81, H = 1.0;
    Scene s = line(Policy::sequential, 1.0);
    s.gravity = Vec3(-g, 0, 0);
    s.bodies = {block("floor", 0.0, 0.0, 0.2, 1.0, true), block("ball", 0.2 + H, 0.0)};
    World1 w(s);
    std::vector<Event1> events;
    w.advance_to(20.0, &events);
    const double t1 = std::sqrt(2 * H / g), u = g * t1;
    ASSERT_EQ(events.size(), static_cast<std::size_t>((20.0 - t1) / (2 * t1)) + 1);
    for (std::size_t k = 0; k < events.size(); ++k) {
        EXPECT_NEAR(events[k].t, t1 + 2 * t1 * k, 1e-12 * (1 + k));
        EXPECT_NEAR(events[k].vb_before, -u, 1e-12 * u * (1 + k));
    }
    EXPECT_FALSE(w.resting(1));
}

// Elastic blocks of random masses between two walls for 100 s: the energy stays to 1e-12, no
// two blocks ever overlap, and the same scene gives the same history.
TEST(World1d, ElasticGasKeepsEnergyAndOrder) {
    Scene s = line(Policy::sequential, 1.0);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> V(-3, 3), M(0.5, 2);
    s.bodies.push_back(block("left", -0.1, 0.0, 0.2, 1.0, true));
    for (int i = 0; i < 8; ++i) s.bodies.push_back(block("b" + std::to_string(i), 0.5 + i, V(rng), 0.3, M(rng)));
    s.bodies.push_back(block("right", 8.6, 0.0, 0.2, 1.0, true));
    auto energy = [](const World1& w) {
        double e = 0;
        for (const Body1& b : w.bodies())
            if (!b.is_static) e += 0.5 * b.mass * b.v * b.v;
        return e;
    };
    World1 w(s), twin(s);
    const double e0 = energy(w);
    std::vector<Event1> events, twin_events;
    for (int step = 1; step <= 1000; ++step) {
        w.advance_to(0.1 * step, &events);
        twin.advance_to(0.1 * step, &twin_events);
        for (std::size_t i = 0; i + 1 < s.bodies.size(); ++i) {
            const double gap = (w.bodies()[i + 1].position - 0.5 * s.bodies[i + 1].length) -
                               (w.bodies()[i].position + 0.5 * s.bodies[i].length);
            ASSERT_GE(gap, -1e-9) << "overlap at t = " << w.time();
        }
    }
    EXPECT_GT(events.size(), 100u);
    EXPECT_NEAR(energy(w), e0, 1e-12 * e0);
    ASSERT_EQ(events.size(), twin_events.size());
    for (std::size_t k = 0; k < events.size(); ++k) EXPECT_EQ(events[k].t, twin_events[k].t);
}

TEST(World1d, PartingBlocksNeverMeet) {
    Scene s = line();
    s.bodies = {block("a", 0.0, -1.0), block("b", 0.2, 1.0)};  // touching, parting
    World1 w(s);
    std::vector<Event1> events;
    w.advance_to(5.0, &events);
    EXPECT_TRUE(events.empty());
    EXPECT_NEAR(w.bodies()[1].position - w.bodies()[0].position, 10.2, 1e-12);
}

}  // namespace
}  // namespace collide
