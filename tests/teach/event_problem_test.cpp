// A world's collision event as a `collide solve` problem (teach/event_problem.h): the worked
// example of a rendered scene must reproduce the impulse the world applied, and closed forms.
#include "teach/event_problem.h"

#include <gtest/gtest.h>

#include "scenario/scene_file.h"
#include "teach/solve.h"

namespace collide {
namespace {

// The first event of a scene, as an instant: the poses it carries are where the bodies
// touch (the tests below check the contact point against them).
template <class World, class Event>
CollisionInstant first_instant(const Scene& scene, Event* first) {
    std::vector<Event> events;
    World world(scene);
    world.advance_to(scene.duration, &events);
    EXPECT_FALSE(events.empty());
    *first = events.front();
    return collision_instant(events.front());
}

TEST(EventProblem, OneDimensionalImpulseIsTheClosedForm) {
    // P = (1 + e) m1 m2 / (m1 + m2) (v1 - v2) on the right block.
    const Scene scene = parse_scene_text(R"([scene]
dimension = 1
duration = 1.0
restitution = 0.5
[[body]]
name = "left"
shape = "block"
length = 0.2
mass = 2.0
position = -0.5
v = 3.0
[[body]]
name = "right"
shape = "block"
length = 0.2
mass = 1.0
position = 0.5
v = -1.0
)", "1d.toml");
    Event1 e;
    const CollisionInstant c = first_instant<World1>(scene, &e);
    const SolveProblem p = collision_problem(scene, c);
    EXPECT_EQ(p.dimension, 1);
    EXPECT_DOUBLE_EQ(p.restitution, 0.5);
    const Solution s = solve(p);
    const double expected = 1.5 * 2.0 * 1.0 / 3.0 * (3.0 - (-1.0));
    EXPECT_NEAR(s.P.x(), expected, 1e-12);
    EXPECT_NEAR(s.P.x(), e.impulse, 1e-12);
    EXPECT_NEAR(s.vb.x(), e.vb_after, 1e-12);

    // The same collision with the right block as a (a lesson's roles): n = -x from a into b,
    // and the left block, now b, receives P = -expected along x; the velocities are the same.
    EXPECT_EQ(with_roles(c, c.a, c.b).a, c.a);  // already in those roles: unchanged
    const CollisionInstant r = with_roles(c, c.b, c.a);
    EXPECT_EQ(r.a, c.b);
    const SolveProblem q = collision_problem(scene, r);
    EXPECT_EQ(q.normal.x(), -1.0);
    EXPECT_EQ(q.a.name, "right");
    const Solution t = solve(q);
    EXPECT_NEAR(t.P.x(), -expected, 1e-12);
    EXPECT_NEAR(t.va.x(), e.vb_after, 1e-12);
    EXPECT_NEAR(t.vb.x(), e.va_after, 1e-12);
    EXPECT_NEAR(t.un_after, -0.5 * t.un, 1e-12);
}

TEST(EventProblem, TwoDimensionalOffCentreHitReproducesTheWorldsImpulse) {
    // A disc strikes a tilted rectangle away from its centre: one contact point, frictionless.
    const Scene scene = parse_scene_text(R"([scene]
dimension = 2
duration = 1.0
restitution = 0.7
[[body]]
name = "disc"
shape = "disc"
radius = 0.1
mass = 0.5
position = [-0.6, 0.12]
v = [2.0, 0.0]
w = 1.0
[[body]]
name = "plank"
shape = "rectangle"
size = [0.1, 0.6]
mass = 2.0
position = [0.0, 0.0]
angle = 0.2
)", "2d.toml");
    Event2 e;
    const CollisionInstant c = first_instant<World<2>>(scene, &e);
    const Solution s = solve(collision_problem(scene, c));
    const double scale = e.impulse.norm();
    ASSERT_GT(scale, 0.1);
    EXPECT_NEAR((s.P.head<2>() - e.impulse).norm(), 0.0, 1e-9 * scale);
    EXPECT_NEAR((s.vb.head<2>() - e.after_b.v).norm(), 0.0, 1e-9);
    EXPECT_NEAR(s.wb.z(), e.after_b.w, 1e-9);
    EXPECT_NEAR(s.wa.z(), e.after_a.w, 1e-9);
    // Newton's law on the contact-point velocities: u_n' = -e u_n.
    EXPECT_NEAR(s.un_after, -0.7 * s.un, 1e-9);
}

TEST(EventProblem, ThreeDimensionalFrictionalHitReproducesTheWorldsImpulse) {
    // A sphere strikes a rotated box, Coulomb friction: the sequential policy applies the
    // foundation's model to the one point, so the worked example gives the same impulse.
    const Scene scene = parse_scene_text(R"([scene]
dimension = 3
duration = 1.0
model = "coulomb"
restitution = 0.6
friction = 0.4
[[body]]
name = "ball"
shape = "sphere"
radius = 0.1
mass = 0.3
position = [-0.8, 0.07, 0.05]
v = [3.0, 0.5, 0.0]
[[body]]
name = "box"
shape = "box"
size = [0.3, 0.4, 0.5]
mass = 1.5
position = [0.0, 0.0, 0.0]
orientation = [0.95, 0.1, 0.2, 0.2]
w = [0.0, 1.0, 0.0]
)", "3d.toml");
    Event3 e;
    const CollisionInstant c = first_instant<World<3>>(scene, &e);
    const SolveProblem p = collision_problem(scene, c);
    EXPECT_DOUBLE_EQ(p.friction, 0.4);
    const Solution s = solve(p);
    const double scale = e.impulse.norm();
    ASSERT_GT(scale, 0.1);
    EXPECT_NEAR((s.P - e.impulse).norm(), 0.0, 1e-9 * scale);
    EXPECT_NEAR((s.vb - e.after_b.v).norm(), 0.0, 1e-9);
    EXPECT_NEAR((s.wb - e.after_b.w).norm(), 0.0, 1e-9);
    // Momentum of the pair is kept by any impulse pair +P, -P.
    EXPECT_NEAR((s.p_after - s.p_before).norm(), 0.0, 1e-12);

    // With the box as a (a lesson's roles): the normal and the impulse on b change sign, and
    // each body ends as the world left it, whatever it is called.
    const Solution t = solve(collision_problem(scene, with_roles(c, c.b, c.a)));
    EXPECT_NEAR((t.n + c.normal).norm(), 0.0, 1e-15);
    EXPECT_NEAR((t.P + e.impulse).norm(), 0.0, 1e-9 * scale);
    EXPECT_NEAR((t.va - e.after_b.v).norm(), 0.0, 1e-9);
    EXPECT_NEAR((t.wa - e.after_b.w).norm(), 0.0, 1e-9);
    EXPECT_NEAR((t.vb - e.after_a.v).norm(), 0.0, 1e-9);
    EXPECT_NEAR((t.wb - e.after_a.w).norm(), 0.0, 1e-9);
}

}  // namespace
}  // namespace collide
