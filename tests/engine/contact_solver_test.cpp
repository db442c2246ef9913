// The contact solver (engine/contact_solver.h) on its own, against closed forms: a body resting
// on the ground takes the normal impulse that stops gravity's m g dt, two supports share a
// plank's load by the lever rule, friction holds inside the Coulomb cone and slides at its edge
// beyond it, and a simultaneous impact of three discs in a row ends as its LCP says.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "engine/contact_solver.h"
#include "tests/scenes/world_scenes.h"

namespace collide {
namespace {

constexpr double kG = 9.81;     // m/s^2
constexpr double kDt = 1e-3;    // s: the velocity gravity adds over one rest step
constexpr double kTol = 1e-12;  // relative: the solves below are exact up to round-off

// The bodies as the scenes build them (tests/scenes/world_scenes.h: inertia of uniform shapes).
Body2 ground2() { return scenes::half_plane("ground", Vec2(0.0, 1.0), 0.0).body2; }
Body3 ground3() { return scenes::half_space("ground", Vec3::UnitY(), 0.0).body3; }

template <int D>
Contact<D> contact(std::size_t a, std::size_t b, const typename Space<D>::Vec& n,
                   const std::vector<typename Space<D>::Vec>& points) {
    Contact<D> c;
    c.a = a;
    c.b = b;
    c.m.normal = n;
    c.m.count = static_cast<int>(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) c.m.points[k] = points[k];
    return c;
}

// One goal per point: leave with un >= target, friction limit mu (0: none).
template <int D>
std::vector<PointGoal<D>> goals(const std::vector<Contact<D>>& contacts, double un, double mu) {
    std::vector<PointGoal<D>> out;
    for (const Contact<D>& c : contacts)
        for (int k = 0; k < c.m.count; ++k) {
            PointGoal<D> g;
            g.un = un;
            g.mu = mu;
            out.push_back(g);
        }
    return out;
}

// A plank (2 kg, 1 m) resting flat on the ground with both bottom corners touching, falling at
// the speed gravity gave it over dt: the impulse is m g dt upwards, and it stops dead.
TEST(ContactSolver, RestingBoxTakesTheImpulseOfGravity2D) {
    const double m = 2.0, L = 1.0, H = 0.2;
    const Vec2 falling(0.0, -kG * kDt);
    std::vector<Body2> bodies = {ground2(), scenes::rectangle("plank", L, H, m, Vec2(0.0, H / 2), 0.0, falling).body2};
    std::vector<Contact<2>> contacts = {contact<2>(0, 1, Vec2(0.0, 1.0), {Vec2(-L / 2, 0.0), Vec2(L / 2, 0.0)})};
    ContactSolver<2>({false, false}).solve(&contacts, goals(contacts, 0.0, 0.0), &bodies);
    EXPECT_NEAR(contacts[0].impulse.y(), m * kG * kDt, kTol * m * kG * kDt);
    EXPECT_NEAR(contacts[0].impulse.x(), 0.0, kTol * m * kG * kDt);
    EXPECT_NEAR(contacts[0].weight, m * kG * kDt, kTol * m * kG * kDt);
    EXPECT_NEAR(bodies[1].v.norm(), 0.0, kTol * kG * kDt);
    EXPECT_NEAR(bodies[1].w, 0.0, kTol * kG * kDt);
}

// The same in 3D: a box on its four bottom corners (a redundant set of points; the total is
// still determined).
TEST(ContactSolver, RestingBoxTakesTheImpulseOfGravity3D) {
    const double m = 3.0;
    const Vec3 half(0.4, 0.1, 0.25);
    Body3 box = scenes::box("box", half, m, Vec3(0.0, half.y(), 0.0)).body3;
    box.v = Vec3(0.0, -kG * kDt, 0.0);
    std::vector<Body3> bodies = {ground3(), box};
    std::vector<Vec3> corners;
    for (double x : {-half.x(), half.x()})
        for (double z : {-half.z(), half.z()}) corners.emplace_back(x, 0.0, z);
    std::vector<Contact<3>> contacts = {contact<3>(0, 1, Vec3::UnitY(), corners)};
    ContactSolver<3>({false, false}).solve(&contacts, goals(contacts, 0.0, 0.0), &bodies);
    const double P = m * kG * kDt;
    EXPECT_NEAR(contacts[0].weight, P, 1e-10 * P);
    EXPECT_NEAR((contacts[0].impulse - Vec3(0.0, P, 0.0)).norm(), 0.0, 1e-10 * P);
    EXPECT_LT(bodies[1].v.norm(), 1e-10 * kG * kDt);
    EXPECT_LT(bodies[1].w.norm(), 1e-10 * kG * kDt);
}

// A plank on two supports at unequal distances a and b from its centre of mass: they share
// the load by the lever rule, P_a = P b / (a + b) and P_b = P a / (a + b) (the sum stops the
// fall, the moments about the centre cancel so it does not start turning).
TEST(ContactSolver, TwoSupportsShareTheLoadByTheLeverRule) {
    const double m = 5.0, L = 2.0;
    for (double centre : {0.0, 0.15, -0.35}) {
        const double xa = -0.7, xb = 0.3;  // the supports
        std::vector<Body2> bodies = {
            ground2(), ground2(),
            scenes::rectangle("plank", L, 0.1, m, Vec2(centre, 0.05), 0.0, Vec2(0.0, -kG * kDt)).body2};
        std::vector<Contact<2>> contacts = {contact<2>(0, 2, Vec2(0.0, 1.0), {Vec2(xa, 0.0)}),
                                            contact<2>(1, 2, Vec2(0.0, 1.0), {Vec2(xb, 0.0)})};
        ContactSolver<2>({false, false, false}).solve(&contacts, goals(contacts, 0.0, 0.0), &bodies);
        const double P = m * kG * kDt, a = centre - xa, b = xb - centre;
        EXPECT_NEAR(contacts[0].weight, P * b / (a + b), kTol * P) << "centre " << centre;
        EXPECT_NEAR(contacts[1].weight, P * a / (a + b), kTol * P) << "centre " << centre;
        EXPECT_NEAR(bodies[2].w, 0.0, kTol * kG * kDt);
    }
}

// A disc (I = m r^2 / 2) sliding on the ground at vt while landing at u. Sticking needs the
// tangential impulse m vt / 3 (the contact point's tangential mass: 1 / (1/m + r^2/I) = m/3);
// inside the cone (vt <= 3 mu u) it sticks, beyond it the impulse is mu m u against the slip
// and the point keeps sliding at vt - 3 mu u.
TEST(ContactSolver, FrictionSticksInsideTheCoulombConeAndSlidesBeyond) {
    const double m = 1.5, r = 0.5, u = 1.0, mu = 0.5;
    for (double vt : {0.4, 1.0, 1.5 - 1e-6, 1.5 + 1e-6, 2.0, 4.0}) {
        std::vector<Body2> bodies = {ground2(), scenes::disc("disc", r, m, Vec2(0.0, r), Vec2(vt, -u)).body2};
        std::vector<Contact<2>> contacts = {contact<2>(0, 1, Vec2(0.0, 1.0), {Vec2(0.0, 0.0)})};
        ContactSolver<2>({false, true}).solve(&contacts, goals(contacts, 0.0, mu), &bodies);
        const double Pn = m * u;
        const bool sticks = vt <= 3.0 * mu * u;
        const double Pt = sticks ? m * vt / 3.0 : mu * Pn;
        EXPECT_NEAR(contacts[0].impulse.y(), Pn, kTol * Pn) << "vt " << vt;
        EXPECT_NEAR(contacts[0].impulse.x(), -Pt, kTol * Pn) << "vt " << vt;
        EXPECT_LE(std::abs(contacts[0].impulse.x()), mu * contacts[0].impulse.y() * (1.0 + kTol));
        const Body2& d = bodies[1];
        const double slip = d.v.x() + d.w * r;  // the contact point's velocity: v + w x (0, -r)
        EXPECT_NEAR(slip, sticks ? 0.0 : vt - 3.0 * mu * u, kTol * 4.0) << "vt " << vt;
    }
}

// In 3D the cone is round: a sphere (I = 2 m r^2 / 5, tangential mass m / 3.5) sliding along
// a diagonal gets a friction impulse of mu P_n exactly against its slip.
TEST(ContactSolver, FrictionIsACircularConeIn3D) {
    const double m = 2.0, r = 0.3, u = 2.0, mu = 0.3;
    const Vec3 slip_dir = Vec3(1.0, 0.0, 2.0).normalized();
    for (double vt : {0.5, 5.0}) {
        const Vec3 v = vt * slip_dir - u * Vec3::UnitY();
        std::vector<Body3> bodies = {ground3(), scenes::sphere("ball", r, m, Vec3(0.0, r, 0.0), v).body3};
        std::vector<Contact<3>> contacts = {contact<3>(0, 1, Vec3::UnitY(), {Vec3::Zero()})};
        ContactSolver<3>({false, true}).solve(&contacts, goals(contacts, 0.0, mu), &bodies);
        const double Pn = m * u;
        const bool sticks = vt <= 3.5 * mu * u;
        const Vec3 Pt = -(sticks ? m * vt / 3.5 : mu * Pn) * slip_dir;
        EXPECT_NEAR((contacts[0].impulse - (Pt + Pn * Vec3::UnitY())).norm(), 0.0, 1e-10 * Pn) << "vt " << vt;
    }
}

// Three equal discs in a row, the first moving at v into the two at rest (e = 1): the
// simultaneous impulses with P_k >= 0 and un+ >= -e un- (equality where P_k > 0) give
// (-v/3, 2v/3, 2v/3) (world.h: the cradle under the simultaneous policy).
TEST(ContactSolver, SimultaneousImpactOfThreeDiscsSolvesItsLCP) {
    const double m = 1.0, r = 0.5, v = 3.0;
    std::vector<Body2> bodies = {scenes::disc("1", r, m, Vec2(0.0, 0.0), Vec2(v, 0.0)).body2,
                                 scenes::disc("2", r, m, Vec2(2 * r, 0.0)).body2,
                                 scenes::disc("3", r, m, Vec2(4 * r, 0.0)).body2};
    std::vector<Contact<2>> contacts = {contact<2>(0, 1, Vec2(1.0, 0.0), {Vec2(r, 0.0)}),
                                        contact<2>(1, 2, Vec2(1.0, 0.0), {Vec2(3 * r, 0.0)})};
    std::vector<PointGoal<2>> g(2);
    g[0].un = v;    // -e un- with un- = -v
    g[1].un = 0.0;  // the second pair does not approach
    ContactSolver<2>({true, true, true}).solve(&contacts, g, &bodies);
    EXPECT_NEAR(bodies[0].v.x(), -v / 3.0, kTol * v);
    EXPECT_NEAR(bodies[1].v.x(), 2.0 * v / 3.0, kTol * v);
    EXPECT_NEAR(bodies[2].v.x(), 2.0 * v / 3.0, kTol * v);
    EXPECT_NEAR(contacts[0].weight, 4.0 * m * v / 3.0, kTol * m * v);
    EXPECT_NEAR(contacts[1].weight, 2.0 * m * v / 3.0, kTol * m * v);
    EXPECT_NEAR(bodies[0].v.x() + bodies[1].v.x() + bodies[2].v.x(), v, kTol * v);  // momentum
}

// A point already leaving faster than its goal gets no impulse (P.n >= 0: contacts push, never
// pull), and a goal of -infinity leaves its point out.
TEST(ContactSolver, PointsThatSeparateGetNoImpulse) {
    for (double goal : {0.0, -std::numeric_limits<double>::infinity()}) {
        std::vector<Body2> bodies = {ground2(),
                                     scenes::disc("disc", 0.5, 1.0, Vec2(0.0, 0.5), Vec2(0.3, 2.0), 0.7).body2};
        const Body2 before = bodies[1];
        std::vector<Contact<2>> contacts = {contact<2>(0, 1, Vec2(0.0, 1.0), {Vec2(-0.2, 0.0), Vec2(0.2, 0.0)})};
        ContactSolver<2>({false, false}).solve(&contacts, goals(contacts, goal, 0.5), &bodies);
        EXPECT_EQ(contacts[0].weight, 0.0);
        EXPECT_EQ(bodies[1].v, before.v);
        EXPECT_EQ(bodies[1].w, before.w);
    }
}

}  // namespace
}  // namespace collide
