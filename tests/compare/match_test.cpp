// The event matcher and the difference (compare/match.h), on hand-made events: the definitions
// as documented, not numbers from a run.
#include <gtest/gtest.h>

#include "compare/match.h"
#include "tests/scenes/world_scenes.h"

namespace collide::compare {
namespace {

namespace sc = collide::scenes;

Scene two_discs_and_ground() {
    Scene s = sc::empty_scene(2);
    s.bodies.push_back(sc::half_plane("ground", Vec2(0, 1), 0.0));
    s.bodies.push_back(sc::disc("p", 0.5, 1.0, Vec2(0, 1)));
    s.bodies.push_back(sc::disc("q", 0.25, 1.0, Vec2(2, 1)));
    return s;
}

Event2 ours(std::size_t a, std::size_t b, double t, double vb_after = 1.0) {
    Event2 e;
    e.t = t;
    e.a = a;
    e.b = b;
    e.normal = Vec2(0, 1);
    e.impulse = Vec2::Zero();
    e.point = Vec2::Zero();
    e.before_a = {Vec2(0, 0), 0.0};
    e.before_b = {Vec2(0, -1), 0.0};
    e.after_a = {Vec2(0, 0), 0.0};
    e.after_b = {Vec2(0, vb_after), 0.0};
    return e;
}

Box2DEvent theirs(std::size_t a, std::size_t b, double t, double vb_after = 1.0) {
    Box2DEvent e;
    e.t = t;
    e.a = a;
    e.b = b;
    e.normal = Vec2(0, 1);
    e.points = 1;
    e.restitution = 1.0;
    e.approach = 1.0;
    e.before_a = {Vec2(0, 0), 0.0};
    e.before_b = {Vec2(0, -1), 0.0};
    e.after_a = {Vec2(0, 0), 0.0};
    e.after_b = {Vec2(0, vb_after), 0.0};
    return e;
}

// max over the bodies of max(|dv|, R |dw|), over the largest max(|v|, R |w|).
TEST(Match, DifferenceIsTheLargestRimSpeedGapOverTheLargestRimSpeed) {
    const Scene s = two_discs_and_ground();
    const auto radii = lever_radii(s);
    EXPECT_EQ(radii, (std::vector<double>{0.0, 0.5, 0.25}));
    const std::pair<Velocity, Velocity> one{{Vec2(1, 0), 2.0}, {Vec2(0, 0), 0.0}};
    const std::pair<Velocity, Velocity> two{{Vec2(1, 0.1), 2.4}, {Vec2(0, 0.05), 0.0}};
    const double scale = velocity_scale(radii, 1, 2, {one, two});
    EXPECT_DOUBLE_EQ(scale, 0.5 * 2.4);  // R |w| = 1.2 beats |v| = 1.005
    // |dv| = 0.1, R |dw| = 0.2 for p; 0.05 for q.
    EXPECT_DOUBLE_EQ(velocity_difference(radii, 1, 2, one, two, scale), 0.2 / 1.2);
    EXPECT_EQ(velocity_difference(radii, 1, 2, one, two, 0.0), 0.0);
}

// k-th event of a pair with the k-th of the same pair; left-overs unmatched; time order.
TEST(Match, PairsByBodiesAndOrderOfOccurrence) {
    const Scene s = two_discs_and_ground();
    const std::vector<Event2> a{ours(0, 1, 0.1), ours(1, 2, 0.2), ours(0, 1, 0.3)};
    const std::vector<Box2DEvent> b{theirs(0, 1, 0.1), theirs(0, 1, 0.31), theirs(0, 1, 0.5)};
    const auto m = match_events(s, {}, a, b);
    ASSERT_EQ(m.size(), 4u);
    EXPECT_EQ(m[0].a, 0u);
    EXPECT_EQ(m[0].b, 1u);
    EXPECT_TRUE(m[0].collide && m[0].box2d);
    EXPECT_DOUBLE_EQ(*m[0].difference, 0.0);
    EXPECT_EQ(m[0].reason, "");
    EXPECT_EQ(m[1].a, 1u);  // q - p at 0.2: collide only
    EXPECT_TRUE(m[1].collide && !m[1].box2d);
    EXPECT_EQ(m[1].reason, "no matching event");
    EXPECT_FALSE(m[1].difference.has_value());
    EXPECT_DOUBLE_EQ(m[2].collide->t, 0.3);  // the second of each: 0.3 with 0.31
    EXPECT_DOUBLE_EQ(m[2].box2d->t, 0.31);
    EXPECT_TRUE(!m[3].collide && m[3].box2d);  // Box2D's third has no partner
    EXPECT_EQ(m[3].reason, "no matching event");
}

// collide's b-before-a order is turned into a < b with the normal and impulse flipped.
TEST(Match, OrdersEachPairAsBox2DDoes) {
    const Scene s = two_discs_and_ground();
    Event2 e = ours(2, 1, 0.1);
    e.normal = Vec2(1, 0);
    e.after_a = {Vec2(3, 0), 0.0};
    const auto m = match_events(s, {}, {e}, {});
    ASSERT_EQ(m.size(), 1u);
    EXPECT_EQ(m[0].collide->a, 1u);
    EXPECT_EQ(m[0].collide->normal, Vec2(-1, 0));
    EXPECT_EQ(m[0].collide->after_b.v, Vec2(3, 0));
}

// A bounce Box2D suppressed: its approach (0.8 m/s) below its threshold (1 m/s), e = 1.
TEST(Match, NamesTheRestitutionThreshold) {
    const Scene s = two_discs_and_ground();
    Box2DEvent b = theirs(0, 1, 0.1, 0.0);
    b.threshold = 1.0;
    b.approach = 0.8;
    const auto m = match_events(s, {}, {ours(0, 1, 0.1, 0.8)}, {b});
    ASSERT_EQ(m.size(), 1u);
    EXPECT_GT(*m[0].difference, 0.5);
    EXPECT_EQ(m[0].reason.rfind("restitution threshold", 0), 0u) << m[0].reason;
}

// Normals 3 degrees apart, the same state before: "normal off by 3 degrees".
TEST(Match, NamesANormalOff) {
    const Scene s = two_discs_and_ground();
    const double angle = 3.0 * kPi / 180.0;
    Box2DEvent b = theirs(0, 1, 0.1, 0.95);
    b.normal = Vec2(std::sin(angle), std::cos(angle));
    b.after_b.v = Vec2(0.1, 0.95);
    const auto m = match_events(s, {}, {ours(0, 1, 0.1)}, {b});
    ASSERT_EQ(m.size(), 1u);
    EXPECT_NEAR(*m[0].normal_degrees, 3.0, 1e-9);
    EXPECT_NE(m[0].reason.find("normal off by 3 degrees"), std::string::npos) << m[0].reason;
}

}  // namespace
}  // namespace collide::compare
