// Box2D 2.4.1 through the adapter (compare/box2d_world.h) against closed forms and collide's
// own response formulas, and collide's World<2> against the same closed forms.
//
// The single- and two-point cases start touching (overlapping by 1 micrometre, so that Box2D's
// float positions see the contact in its first step) with no gravity: both engines then solve
// the same contact at the same pose, and Box2D must agree to float precision. Tolerances are
// relative to the largest speed involved (1e-5: Box2D computes in float, about 1e-7).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "compare/box2d_world.h"
#include "compare/match.h"
#include "engine/response.h"
#include "engine/world.h"
#include "tests/scenes/world_scenes.h"

namespace collide::compare {
namespace {

namespace sc = collide::scenes;
constexpr double kRel = 1e-5;
constexpr double kOverlap = 1e-6;  // m

struct Runs {
    std::vector<Event2> ours;
    std::vector<Box2DEvent> theirs;
    std::vector<Body2> ours_end, theirs_end;
};

Runs run_both(const Scene& s, double t, const Box2DSettings& settings = {}) {
    Runs r;
    World2 world(s);
    world.advance_to(t, &r.ours);
    Box2DWorld box(s, settings);
    box.advance_to(t, &r.theirs);
    r.ours_end = world.bodies();
    r.theirs_end = box.bodies();
    return r;
}

// |x - y| <= kRel * scale for vectors and numbers.
void expect_close(const Vec2& x, const Vec2& y, double scale, const char* what) {
    EXPECT_LE((x - y).norm(), kRel * scale) << what << ": " << x.transpose() << " vs " << y.transpose();
}
void expect_close(double x, double y, double scale, const char* what) {
    EXPECT_LE(std::abs(x - y), kRel * scale) << what << ": " << x << " vs " << y;
}

// ---- A single contact: disc on disc --------------------------------------------------------

// Discs of radii 1/8 and 3/16 m whose centres are (3/16, 1/4) apart: the normal is (0.6, 0.8)
// and every number is exact in float too. Oblique, unequal masses, e = 0.7, frictionless.
TEST(Box2DWorld, DiscOnDiscSingleContactAgreesWithClosedForm) {
    Scene s = sc::empty_scene(2, Policy::sequential, 0.7);
    const Vec2 n(0.6, 0.8);
    const Vec2 xa(0.0, 0.0), xb = xa + (0.3125 - kOverlap) * n;
    const Vec2 va(2.0, 0.3), vb(-0.5, 0.2);
    const double ma = 1.0, mb = 2.5;
    s.bodies.push_back(sc::disc("a", 0.125, ma, xa, va, 0.4));
    s.bodies.push_back(sc::disc("b", 0.1875, mb, xb, vb, -1.0));

    // Closed form (PHYSICS.md): j = -(1 + e) un / (1/ma + 1/mb), P = j n on b; no spin change.
    const double un = (vb - va).dot(n);
    ASSERT_LT(un, 0.0);
    const double j = -(1.0 + 0.7) * un / (1.0 / ma + 1.0 / mb);
    const Vec2 va1 = va - j * n / ma, vb1 = vb + j * n / mb;
    const double scale = std::max(va.norm(), vb.norm());

    const Runs r = run_both(s, 0.01);
    ASSERT_EQ(r.ours.size(), 1u);
    ASSERT_EQ(r.theirs.size(), 1u);
    const Event2& o = r.ours[0];
    const Box2DEvent& b = r.theirs[0];
    EXPECT_EQ(b.points, 1);
    EXPECT_EQ(b.step, 0u);
    expect_close(o.after_a.v, va1, scale, "collide va");
    expect_close(o.after_b.v, vb1, scale, "collide vb");
    expect_close(b.after_a.v, va1, scale, "box2d va");
    expect_close(b.after_b.v, vb1, scale, "box2d vb");
    expect_close(b.after_a.w, 0.4, 1.0, "box2d wa");
    expect_close(b.after_b.w, -1.0, 1.0, "box2d wb");
    expect_close(b.normal, n, 1.0, "box2d normal");
    expect_close(b.impulse, j * n, j, "box2d impulse");

    const auto m = match_events(s, {}, r.ours, r.theirs);
    ASSERT_EQ(m.size(), 1u);
    ASSERT_TRUE(m[0].difference.has_value());
    EXPECT_LE(*m[0].difference, kRel);
    EXPECT_EQ(m[0].reason, "");
}

// ---- A single contact: a box's corner on a face --------------------------------------------

// The frictionless single-point impulse, written out here (PHYSICS.md), not the engine's:
// r = p - x, u_n = (v_b + w_b x r_b - v_a - w_a x r_a) . n (2D: w x r = w (-r_y, r_x)),
// j = -(1 + e) u_n / (1/m_a + 1/m_b + (r_a x n)^2 / I_a + (r_b x n)^2 / I_b), P = j n on b,
// v_a' = v_a - P/m_a, w_a' = w_a - (r_a x P)/I_a, v_b' = v_b + P/m_b, w_b' = w_b + (r_b x P)/I_b
// (a static body: 1/m = 1/I = 0).
struct ClosedForm {
    bool separating = false;
    Vec2 va, vb;
    double wa = 0, wb = 0;
};
ClosedForm single_point(const Body2& a, const Body2& b, const Vec2& p, const Vec2& n, double e) {
    const auto cross = [](const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); };
    const auto spin = [](double w, const Vec2& r) { return Vec2(-w * r.y(), w * r.x()); };
    const Vec2 ra = p - a.position, rb = p - b.position;
    const double un = ((b.v + spin(b.w, rb)) - (a.v + spin(a.w, ra))).dot(n);
    ClosedForm out;
    out.separating = un >= 0;
    const double den = a.inv_mass() + b.inv_mass() + std::pow(cross(ra, n), 2) * a.inv_inertia() +
                       std::pow(cross(rb, n), 2) * b.inv_inertia();
    const Vec2 P = (-(1 + e) * un / den) * n;
    out.va = a.v - a.inv_mass() * P;
    out.wa = a.w - a.inv_inertia() * cross(ra, P);
    out.vb = b.v + b.inv_mass() * P;
    out.wb = b.w + b.inv_inertia() * cross(rb, P);
    return out;
}

// A tilted, spinning box lands on one corner on the ground (e = 0.5).
TEST(Box2DWorld, BoxCornerOnGroundAgreesWithClosedForm) {
    Scene s = sc::empty_scene(2, Policy::sequential, 0.5);
    s.bodies.push_back(sc::half_plane("ground", Vec2(0, 1), 0.0));
    const double angle = 0.5, w = 1.5, W = 0.4, H = 0.2;
    const Vec2 corner_local(-0.5 * W, -0.5 * H);  // the lowest corner at this angle
    const Vec2 r = Pose2{Vec2::Zero(), angle}.rotate(corner_local);
    const Vec2 x(0.0, -r.y() - kOverlap);
    s.bodies.push_back(sc::rectangle("box", W, H, 1.5, x, angle, Vec2(0.3, -2.0), w));

    const Body2& ground = s.bodies[0].body2;
    const Body2& box = s.bodies[1].body2;
    const Vec2 p = x + r;
    const ClosedForm expect = single_point(ground, box, p, Vec2(0, 1), 0.5);
    ASSERT_FALSE(expect.separating);
    const double scale = std::max(box.v.norm(), 0.5 * std::hypot(W, H) * std::abs(w));

    const Runs run = run_both(s, 0.01);
    ASSERT_EQ(run.ours.size(), 1u);
    ASSERT_EQ(run.theirs.size(), 1u);
    const Box2DEvent& b = run.theirs[0];
    EXPECT_EQ(b.points, 1);
    expect_close(run.ours[0].after_b.v, expect.vb, scale, "collide v");
    expect_close(run.ours[0].after_b.w, expect.wb, scale, "collide w");
    expect_close(b.after_b.v, expect.vb, scale, "box2d v");
    expect_close(b.after_b.w, expect.wb, scale, "box2d w");
    expect_close(b.normal, Vec2(0, 1), 1.0, "box2d normal");
}

// Box A's corner strikes the middle of box B's left face, both dynamic (e = 0.8).
TEST(Box2DWorld, BoxCornerOnBoxFaceAgreesWithClosedForm) {
    Scene s = sc::empty_scene(2, Policy::sequential, 0.8);
    const double angle = 0.6;
    const Vec2 corner_local(0.25, -0.1);  // right-lower corner of a 0.5 x 0.2 box
    const Vec2 r = Pose2{Vec2::Zero(), angle}.rotate(corner_local);
    // B: a 0.3 x 0.6 box at the origin; its left face is x = -0.15.
    const Vec2 p(-0.15 + kOverlap, 0.05);
    s.bodies.push_back(sc::rectangle("A", 0.5, 0.2, 1.0, p - r, angle, Vec2(1.5, 0.4), -2.0));
    s.bodies.push_back(sc::rectangle("B", 0.3, 0.6, 2.0, Vec2::Zero(), 0.0, Vec2(-0.2, 0.1), 0.5));

    const ClosedForm expect = single_point(s.bodies[0].body2, s.bodies[1].body2, p, Vec2(1, 0), 0.8);
    ASSERT_FALSE(expect.separating);
    const double scale = 2.0;

    const Runs run = run_both(s, 0.005);
    ASSERT_EQ(run.ours.size(), 1u);
    ASSERT_EQ(run.theirs.size(), 1u);
    const Box2DEvent& b = run.theirs[0];
    EXPECT_EQ(b.points, 1);
    for (const auto* e : {&run.ours[0].after_a, &b.after_a}) {
        expect_close(e->v, expect.va, scale, "A v");
        expect_close(e->w, expect.wa, scale, "A w");
    }
    for (const auto* e : {&run.ours[0].after_b, &b.after_b}) {
        expect_close(e->v, expect.vb, scale, "B v");
        expect_close(e->w, expect.wb, scale, "B w");
    }
}

// ---- Two points: a box lands flat while spinning ---------------------------------------------

// A 0.4 x 0.2 box (m = 1) lands flat, v = (0, -2), w = 3 rad/s: its left corner approaches at
// 2.6 m/s, its right one at 1.4 m/s. e = 0.5, frictionless.
//   simultaneous: impulses l1, l2 >= 0 with K l = -(1 + e) un at both points, the LCP Box2D's
//     block solver solves (both l > 0 here: v' = 1, w' = -1.5);
//   one impulse at the centre of the face: r x n = 0, so the spin is untouched (w' = 3).
TEST(Box2DWorld, TwoPointFaceContactIsSolvedSimultaneously) {
    const double W = 0.4, H = 0.2, m = 1.0, e = 0.5;
    const Vec2 v(0.0, -2.0);
    const double w = 3.0;
    Scene s = sc::empty_scene(2, Policy::simultaneous, e);
    s.bodies.push_back(sc::half_plane("ground", Vec2(0, 1), 0.0));
    s.bodies.push_back(sc::rectangle("box", W, H, m, Vec2(0.0, 0.5 * H - kOverlap), 0.0, v, w));
    const Body2 box = s.bodies[1].body2;
    const Vec2 n(0, 1);

    // The 2x2 LCP with both impulses positive: K l = b.
    const Vec2 r1(-0.5 * W, -0.5 * H), r2(0.5 * W, -0.5 * H);
    const double I = box.inertia;
    auto un = [&](const Vec2& r) { return (v + cross(w, r)).dot(n); };
    Mat2 K;
    K << 1 / m + cross(r1, n) * cross(r1, n) / I, 1 / m + cross(r1, n) * cross(r2, n) / I,
        1 / m + cross(r2, n) * cross(r1, n) / I, 1 / m + cross(r2, n) * cross(r2, n) / I;
    const Vec2 l = K.ldlt().solve(Vec2(-(1 + e) * un(r1), -(1 + e) * un(r2)));
    ASSERT_GT(l.minCoeff(), 0.0);
    const Vec2 v_sim = v + (l[0] + l[1]) * n / m;
    const double w_sim = w + (cross(r1, n) * l[0] + cross(r2, n) * l[1]) / I;
    EXPECT_NEAR(v_sim.y(), 1.0, 1e-12);
    EXPECT_NEAR(w_sim, -1.5, 1e-12);

    // The alternative: one impulse at the patch centre (the closed form above).
    Body2 ground;
    ground.is_static = true;
    const ClosedForm centre = single_point(ground, box, box.position + Vec2(0, -0.5 * H), n, e);
    EXPECT_NEAR(centre.wb, w, 1e-12);

    const double scale = 2.0;
    const Runs run = run_both(s, 0.01);
    ASSERT_EQ(run.ours.size(), 1u);
    ASSERT_EQ(run.theirs.size(), 1u);
    const Box2DEvent& b = run.theirs[0];
    EXPECT_EQ(b.points, 2);
    for (const auto* after : {&run.ours[0].after_b, &b.after_b}) {
        expect_close(after->v, v_sim, scale, "v, simultaneous");
        expect_close(after->w, w_sim, scale, "w, simultaneous");
        EXPECT_GT(std::abs(after->w - centre.wb), 1.0) << "w equals the patch-centre impulse's";
    }
    const auto m2 = match_events(s, {}, run.ours, run.theirs);
    ASSERT_EQ(m2.size(), 1u);
    EXPECT_LE(*m2[0].difference, kRel);
}

// The same landing with collide's sequential policy (one point at a time) is not Box2D's
// answer, and compare says why.
TEST(Box2DWorld, TwoPointFaceContactSequentialDiffersAndIsExplained) {
    Scene s = sc::empty_scene(2, Policy::sequential, 0.5);
    s.bodies.push_back(sc::half_plane("ground", Vec2(0, 1), 0.0));
    s.bodies.push_back(sc::rectangle("box", 0.4, 0.2, 1.0, Vec2(0.0, 0.1 - kOverlap), 0.0, Vec2(0.0, -2.0), 3.0));
    const Runs run = run_both(s, 0.01);
    const auto m = match_events(s, {}, run.ours, run.theirs);
    ASSERT_GE(m.size(), 1u);
    ASSERT_TRUE(m[0].difference.has_value());
    EXPECT_GT(*m[0].difference, 0.01);
    EXPECT_NE(m[0].reason.find("two-point contact"), std::string::npos) << m[0].reason;
}

// ---- The restitution threshold -------------------------------------------------------------

// A ball with e = 1 dropped from h = 0.8^2 / (2 g) lands at 0.8 m/s. collide keeps its energy
// for ever; Box2D with its defaults (threshold 1 m/s) does not bounce it: the ball stays on the
// ground and the kinetic energy of the fall, m g h, is gone. Matched (threshold 0) it bounces.
TEST(Box2DWorld, SlowElasticBounceIsSuppressedByBox2DsThreshold) {
    const double g = 9.81, r = 0.1, m = 1.0, v_land = 0.8, h = v_land * v_land / (2 * g);
    Scene s = sc::empty_scene(2, Policy::sequential, 1.0, Vec3(0.0, -g, 0.0));
    s.bodies.push_back(sc::half_plane("ground", Vec2(0, 1), 0.0));
    s.bodies.push_back(sc::disc("ball", r, m, Vec2(0.0, r + h)));
    const double E0 = m * g * (r + h);
    auto energy = [&](const std::vector<Body2>& b) {
        return 0.5 * m * b[1].v.squaredNorm() + m * g * b[1].position.y();
    };

    Box2DSettings defaults;
    defaults.box2d_defaults = true;
    const Runs d = run_both(s, 1.0, defaults);
    // collide: elastic, every bounce at 0.8 m/s, energy kept.
    ASSERT_GE(d.ours.size(), 5u);  // a bounce period of 2 v / g = 0.163 s
    for (const Event2& e : d.ours) EXPECT_NEAR(e.after_b.v.y(), v_land, 1e-6);
    EXPECT_NEAR(energy(d.ours_end), E0, 1e-9 * E0);
    // Box2D: one landing, no bounce; resting on the ground within its linear slop (5 mm).
    ASSERT_EQ(d.theirs.size(), 1u);
    EXPECT_NEAR(d.theirs[0].restitution, 1.0, 1e-7);
    EXPECT_NEAR(d.theirs[0].threshold, kBox2DThreshold, 1e-7);
    EXPECT_LT(d.theirs[0].approach, kBox2DThreshold);
    EXPECT_NEAR(d.theirs[0].after_b.v.y(), 0.0, 1e-3);
    EXPECT_NEAR(d.theirs_end[1].v.norm(), 0.0, 1e-3);
    EXPECT_NEAR(d.theirs_end[1].position.y(), r, 0.006);
    EXPECT_NEAR(E0 - energy(d.theirs_end), m * g * h, 0.006 * m * g);
    const auto cmp = match_events(s, defaults, d.ours, d.theirs);
    EXPECT_NE(cmp[0].reason.find("restitution threshold"), std::string::npos) << cmp[0].reason;
    EXPECT_EQ(cmp.back().reason, "no matching event");

    // Matched: Box2D bounces too, up to the g dt its step adds before it applies restitution.
    const Box2DSettings matched;
    const Runs b = run_both(s, 0.2, matched);
    ASSERT_GE(b.theirs.size(), 1u);
    EXPECT_EQ(b.theirs[0].threshold, 0.0);
    EXPECT_NEAR(b.theirs[0].after_b.v.y(), v_land, 2.0 * g * matched.dt);
}

// ---- Mass data and the initial state --------------------------------------------------------

// Free flight under gravity: Box2D's symplectic Euler gives x(t) = x0 + v0 t + g t^2 / 2 +
// g t dt / 2 (each step adds g dt before it moves), and keeps w; mass and inertia are ours.
TEST(Box2DWorld, FreeFlightMatchesClosedFormOfItsIntegrator) {
    const Vec2 g(0.0, -9.81), x0(0.3, 1.0), v0(1.0, 2.0);
    Scene s = sc::empty_scene(2, Policy::sequential, 1.0, Vec3(g.x(), g.y(), 0.0));
    s.bodies.push_back(sc::rectangle("box", 0.3, 0.1, 2.0, x0, 0.2, v0, 4.0));
    Box2DSettings settings;
    Box2DWorld box(s, settings);
    box.advance_to(0.5, nullptr);
    ASSERT_EQ(box.steps(), 300u);
    const double t = box.time();
    const Body2 b = box.bodies()[0];
    const Vec2 x = x0 + v0 * t + 0.5 * g * t * t + 0.5 * g * t * settings.dt;
    // Float: about 1e-7 relative per step, over 300 steps.
    EXPECT_LE((b.position - x).norm(), 1e-4);
    EXPECT_LE((b.v - (v0 + g * t)).norm(), 1e-4);
    EXPECT_NEAR(b.w, 4.0, 1e-6);
    EXPECT_NEAR(b.angle, 0.2 + 4.0 * t, 1e-4);
    EXPECT_EQ(b.mass, 2.0);
}

// ---- The same surfaces ------------------------------------------------------------------------

// A body 1 mm from a surface, closing at 1 m/s, meets it after 1 ms: inside Box2D's second step
// (dt = 1/600 s), not its first. With Box2D's 1 cm polygon skin left as it is the contact would
// already be in the first step: the adapter's planes, static boxes and dynamic polygons collide
// where collide's do.
TEST(Box2DWorld, SurfacesAreWhereCollidesAre) {
    const double gap = 1e-3;
    struct Case {
        const char* what;
        SceneBody still, mover;
    };
    const std::vector<Case> cases = {
        {"disc on plane", sc::half_plane("ground", Vec2(0, 1), 0.0),
         sc::disc("disc", 0.1, 1.0, Vec2(0.0, 0.1 + gap), Vec2(0.0, -1.0))},
        {"box on plane", sc::half_plane("ground", Vec2(0, 1), 0.0),
         sc::rectangle("box", 0.4, 0.2, 1.0, Vec2(0.0, 0.1 + gap), 0.0, Vec2(0.0, -1.0))},
        {"disc on static box", sc::rectangle("block", 1.0, 0.5, 1.0, Vec2(0.0, -0.25)),
         sc::disc("disc", 0.1, 1.0, Vec2(0.0, 0.1 + gap), Vec2(0.0, -1.0))},
        {"box on static box", sc::rectangle("block", 1.0, 0.5, 1.0, Vec2(0.0, -0.25)),
         sc::rectangle("box", 0.4, 0.2, 1.0, Vec2(0.0, 0.1 + gap), 0.0, Vec2(0.0, -1.0))},
        {"box on box", sc::rectangle("block", 1.0, 0.5, 1.0, Vec2(0.0, -0.25)),
         sc::rectangle("box", 0.4, 0.2, 1.0, Vec2(0.0, 0.1 + gap), 0.0, Vec2(0.0, -1.0))},
    };
    for (std::size_t k = 0; k < cases.size(); ++k) {
        Scene s = sc::empty_scene(2, Policy::simultaneous, 0.0);
        s.bodies = {cases[k].still, cases[k].mover};
        if (k >= 2 && k <= 3) s.bodies[0].body2.is_static = true;
        Box2DWorld box(s, {});
        std::vector<Box2DEvent> events;
        box.advance_to(0.01, &events);
        ASSERT_GE(events.size(), 1u) << cases[k].what;
        EXPECT_EQ(events[0].step, 1u) << cases[k].what;
    }
}

// Box2D's continuous collision against static bodies needs a skin; the adapter keeps one on the
// static side. A box falling fast (20 m/s at the ground) and a slow one both come to rest on
// the ground, within Box2D's linear slop (5 mm), neither tunnelling nor hovering.
TEST(Box2DWorld, BoxesComeToRestOnTheGround) {
    for (double height : {0.05, 20.0}) {
        Scene s = sc::empty_scene(2, Policy::simultaneous, 0.0, Vec3(0.0, -9.81, 0.0));
        s.model = Model::coulomb;
        s.friction = 0.5;
        s.bodies.push_back(sc::half_plane("ground", Vec2(0, 1), 0.0));
        s.bodies.push_back(sc::rectangle("box", 0.4, 0.2, 1.0, Vec2(0.0, 0.1 + height), 0.0));
        Box2DWorld box(s, {});
        box.advance_to(3.0, nullptr);
        const Body2 b = box.bodies()[1];
        EXPECT_NEAR(b.position.y(), 0.1, 0.0051) << "dropped from " << height << " m";
        EXPECT_LT(b.v.norm(), 1e-3) << "dropped from " << height << " m";
    }
}

// ---- What Box2D cannot run -------------------------------------------------------------------

TEST(Box2DWorld, RefusesWhatBox2DCannotRepresent) {
    Scene s3 = sc::empty_scene(3);
    ASSERT_TRUE(box2d_unsupported(s3).has_value());
    EXPECT_EQ(box2d_unsupported(s3)->key, "dimension");
    EXPECT_THROW(Box2DWorld(s3, {}), std::invalid_argument);

    Scene s = sc::empty_scene(2);
    SceneBody nine = sc::disc("nine", 0.1, 1.0, Vec2::Zero());
    std::vector<Vec2> v;
    for (int k = 0; k < 9; ++k) v.emplace_back(std::cos(2 * kPi * k / 9), std::sin(2 * kPi * k / 9));
    std::string error;
    ASSERT_TRUE(make_polygon(v, &nine.shape2.polygon, &error)) << error;
    nine.shape2.kind = Shape2::Kind::polygon;
    nine.shape = "polygon";
    s.bodies.push_back(nine);
    const auto why = box2d_unsupported(s);
    ASSERT_TRUE(why.has_value());
    EXPECT_EQ(why->body, "nine");
    EXPECT_EQ(why->key, "vertices");
}

}  // namespace
}  // namespace collide::compare
