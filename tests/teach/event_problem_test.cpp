// A world's collision event as a `collide solve` problem (teach/event_problem.h): the worked
// example of a rendered scene must reproduce the impulse the world applied, and both must be
// the closed forms (1D, 2D) or the model's defining conditions (3D Coulomb) computed here.
#include "teach/event_problem.h"

#include <string>

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

// A sphere strikes a rotated, spinning box off its centre, with Coulomb friction mu.
std::string ball_on_box(double mu) {
    return R"([scene]
dimension = 3
duration = 1.0
model = "coulomb"
restitution = 0.6
friction = )" +
           std::to_string(mu) + R"(
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
)";
}

// The one-step Coulomb model by its definition (PHYSICS.md), from the test's own rigid-body
// formulas, for ball_on_box(): I_world = R I_body R^T (sphere 2/5 m r^2, box m (b^2 + c^2) / 12
// ...), the velocities after from -P on a and +P on b (v += P/m, w += I^-1 (r x P)); then
// Newton's law on the normal, u_n' = -e u_n, and either sticking (no slip after, |P_t| <= mu P_n)
// or sliding (P = j (n - mu t), t the initial slip direction). Checks all that; returns
// whether it slid.
bool check_one_step_coulomb(const CollisionInstant& c, const Solution& s, double e, double mu) {
    bool slid = false;
    const Vec3 n = c.normal, ra = c.point - c.before_a.x, rb = c.point - c.before_b.x;
    const double ma = 0.3, mb = 1.5;
    const Mat3 Ia = Mat3::Identity() * (0.4 * ma * 0.1 * 0.1);
    const Mat3 R = c.before_b.q.toRotationMatrix();
    const Mat3 Ib =
        R *
        Vec3(mb * (0.4 * 0.4 + 0.5 * 0.5) / 12, mb * (0.3 * 0.3 + 0.5 * 0.5) / 12, mb * (0.3 * 0.3 + 0.4 * 0.4) / 12)
            .asDiagonal() *
        R.transpose();
    EXPECT_EQ(c.a, 0u);  // the ball is a
    const Vec3 P = s.P;
    const Vec3 va = c.before_a.v - P / ma, vb = c.before_b.v + P / mb;
    const Vec3 wa = c.before_a.w + Ia.inverse() * ra.cross(-P), wb = c.before_b.w + Ib.inverse() * rb.cross(P);
    EXPECT_NEAR((s.va - va).norm(), 0.0, 1e-12);
    EXPECT_NEAR((s.wb - wb).norm(), 0.0, 1e-12);
    EXPECT_NEAR((s.wa - wa).norm(), 0.0, 1e-12);
    const Vec3 u0 = (c.before_b.v + c.before_b.w.cross(rb)) - (c.before_a.v + c.before_a.w.cross(ra));
    const Vec3 u1 = (vb + wb.cross(rb)) - (va + wa.cross(ra));
    const double un = u0.dot(n);
    EXPECT_LT(un, 0.0);
    EXPECT_NEAR(u1.dot(n), -e * un, 1e-12);
    const double Pn = P.dot(n);
    const Vec3 Pt = P - Pn * n, slip0 = u0 - un * n, slip1 = u1 - u1.dot(n) * n;
    EXPECT_GT(slip0.norm(), 0.1);  // a glancing hit: friction has work to do
    if (Pt.norm() < mu * Pn - 1e-12) {
        EXPECT_NEAR(slip1.norm(), 0.0, 1e-12);  // sticks
    } else {
        const Vec3 t = slip0.normalized();
        EXPECT_NEAR((Pt + mu * Pn * t).norm(), 0.0, 1e-12 * Pn);  // slides, against the slip
        slid = true;
    }
    return slid;
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
)",
                                         "1d.toml");
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
)",
                                         "2d.toml");
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

    // The closed form, from the event's geometry and the scene's numbers alone: in 2D the
    // cross product r x n is the scalar r_x n_y - r_y n_x, I = m r^2 / 2 for the disc and
    // m (w^2 + h^2) / 12 for the plank, u = (v_b + w_b x r_b) - (v_a + w_a x r_a), and
    // j = -(1 + e) u.n / (1/m_a + 1/m_b + (r_a x n)^2 / I_a + (r_b x n)^2 / I_b).
    const auto cross = [](const Vec3& r, const Vec3& n) { return r.x() * n.y() - r.y() * n.x(); };
    const auto spin_x = [](double w, const Vec3& r) { return Vec3(-w * r.y(), w * r.x(), 0.0); };
    const Vec3 n = c.normal, p = c.point;
    const Vec3 ra = p - c.before_a.x, rb = p - c.before_b.x;
    const double ma = 0.5, mb = 2.0, Ia = 0.5 * ma * 0.1 * 0.1, Ib = mb * (0.1 * 0.1 + 0.6 * 0.6) / 12.0;
    const Vec3 u = (c.before_b.v + spin_x(c.before_b.w.z(), rb)) - (c.before_a.v + spin_x(c.before_a.w.z(), ra));
    const double j = -(1.0 + 0.7) * u.dot(n) /
                     (1.0 / ma + 1.0 / mb + cross(ra, n) * cross(ra, n) / Ia + cross(rb, n) * cross(rb, n) / Ib);
    ASSERT_EQ(c.a, 0u);  // the disc is a
    EXPECT_NEAR((s.P - j * n).norm(), 0.0, 1e-12 * std::abs(j));
    EXPECT_NEAR((c.impulse - j * n).norm(), 0.0, 1e-9 * std::abs(j));  // the world's too
    // -P on a, +P on b, each turning by r x P / I.
    EXPECT_NEAR((s.va - (c.before_a.v - j * n / ma)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((s.vb - (c.before_b.v + j * n / mb)).norm(), 0.0, 1e-12);
    EXPECT_NEAR(s.wa.z(), c.before_a.w.z() - j * cross(ra, n) / Ia, 1e-12);
    EXPECT_NEAR(s.wb.z(), c.before_b.w.z() + j * cross(rb, n) / Ib, 1e-12);
}

TEST(EventProblem, ThreeDimensionalFrictionalHitReproducesTheWorldsImpulse) {
    // A sphere strikes a rotated box, Coulomb friction: the sequential policy applies the
    // foundation's model to the one point, so the worked example gives the same impulse.
    const Scene scene = parse_scene_text(ball_on_box(0.4), "3d.toml");
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

    EXPECT_FALSE(check_one_step_coulomb(c, s, 0.6, 0.4));  // it sticks

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

// With little friction the same hit slides: P = j (n - mu t).
TEST(EventProblem, ThreeDimensionalSlidingHitIsTheOneStepCoulombModel) {
    const Scene scene = parse_scene_text(ball_on_box(0.05), "3d-slide.toml");
    Event3 e;
    const CollisionInstant c = first_instant<World<3>>(scene, &e);
    const Solution s = solve(collision_problem(scene, c));
    EXPECT_TRUE(check_one_step_coulomb(c, s, 0.6, 0.05));
    EXPECT_NEAR((s.P - e.impulse).norm(), 0.0, 1e-9 * e.impulse.norm());
}

// A routh scene's worked example uses the scene's restitution law: with Newton's law the rod of
// Kane's paradox gains energy in the world and in its worked example alike (Stronge's would not).
TEST(EventProblem, RouthKeepsTheScenesRestitutionLaw) {
    const Scene scene = parse_scene_text(R"([scene]
dimension = 2
duration = 0.1
model = "routh"
restitution_law = "newton"
restitution = 0.9
friction = 0.5
[[body]]
name = "ground"
shape = "plane"
normal = [0.0, 1.0]
offset = 0.0
[[body]]
name = "rod"
shape = "rectangle"
size = [1.0, 1e-6]
mass = 1.0
angle = 0.8726646259971648
position = [0.32139342182104813, 0.38302254295429383]
v = [-0.2, -1.0]
w = 6.0
)",
                                         "kane.toml");
    Event2 e;
    const CollisionInstant c = first_instant<World<2>>(scene, &e);
    const SolveProblem p = collision_problem(scene, c);
    EXPECT_EQ(p.restitution_law, RestitutionLaw::newton);
    const Solution s = solve(p);
    EXPECT_NEAR((s.P.head<2>() - e.impulse).norm(), 0.0, 1e-9 * e.impulse.norm());
    EXPECT_GT(s.ke_after, s.ke_before);  // Newton's law gains here (Kane's paradox)
    // u_n' = -e u_n: Newton's law itself.
    EXPECT_NEAR(s.un_after, -0.9 * s.un, 1e-9);
}

}  // namespace
}  // namespace collide
