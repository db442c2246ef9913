// The bundled lessons' answers against closed forms computed here from each lesson's own scene
// (masses, sizes, velocities, e, mu read from the loaded Lesson), never from the program's
// printed numbers. Tolerances: 1e-12 (relative to the numbers' size) where the run's contact
// geometry is exact by construction (1D; bodies that do not turn before the hit); 1e-7 where
// the instant of contact of a turning body is found by the world to its 1e-10 m contact
// tolerance; 1e-9 s for the end of a bounce series (the world merges the last 1e-12 s).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "engine/diagnostics.h"
#include "teach/answers.h"
#include "teach/lesson_penalty.h"

namespace collide {
namespace {

const std::string kDir = std::string(COLLIDE_SOURCE_DIR) + "/lessons";

const Lesson& lesson(const std::string& id) {
    static const std::vector<Lesson> all = load_lessons(kDir);
    for (const Lesson& L : all)
        if (L.id == id) return L;
    throw std::runtime_error("no lesson " + id);
}

const SceneBody& body(const Lesson& L, const std::string& name) {
    for (const SceneBody& b : L.scene.bodies)
        if (b.name == name) return b;
    throw std::runtime_error("no body " + name);
}

std::size_t index_of(const Lesson& L, const std::string& name) {
    for (std::size_t i = 0; i < L.scene.bodies.size(); ++i)
        if (L.scene.bodies[i].name == name) return i;
    throw std::runtime_error("no body " + name);
}

// A quantity by its name in lesson files: the tests ask by name, as the lessons do.
Quantity named(const std::string& name) {
    if (const std::optional<Quantity> q = quantity_named(name)) return *q;
    throw std::runtime_error("no quantity named " + name);
}

// The answer to a lesson's question asked by what it asks (quantity, body, collision), not by
// its place in the lesson: reordering or adding questions leaves the checks on the right ones.
const LessonAnswer& ans(const Lesson& L, const std::vector<LessonAnswer>& a, const std::string& quantity,
                        const std::string& body_name = "", int event = 1) {
    const LessonAnswer* found = nullptr;
    const Quantity asked = named(quantity);
    for (std::size_t i = 0; i < L.questions.size() && i < a.size(); ++i) {
        const LessonQuestion& q = L.questions[i];
        // A what-if question asks the same of another scene: its own tests check it.
        if (q.quantity != asked || q.body != body_name || q.event != event || !q.what_if.empty()) continue;
        if (found) throw std::runtime_error(L.id + ": two questions ask " + quantity + " of '" + body_name + "'");
        found = &a[i];
    }
    if (!found) throw std::runtime_error(L.id + ": no question asks " + quantity + " of '" + body_name + "'");
    return *found;
}

// How many answers the engine computed from the lesson's own run (not the written answers of
// choice and explain questions, not the what-if runs).
std::size_t engine_answers(const Lesson& L, const std::vector<LessonAnswer>& a) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < L.questions.size() && i < a.size(); ++i)
        k += a[i].computed && L.questions[i].what_if.empty();
    return k;
}

// The same for point_velocity_* questions that differ only in their point (world frame, m).
const LessonAnswer& ans_at(const Lesson& L, const std::vector<LessonAnswer>& a, const std::string& quantity,
                           const std::string& body_name, const Vec3& at) {
    const Quantity asked = named(quantity);
    for (std::size_t i = 0; i < L.questions.size() && i < a.size(); ++i) {
        const LessonQuestion& q = L.questions[i];
        if (q.quantity == asked && q.body == body_name && q.at && (*q.at - at).norm() < 1e-12) return a[i];
    }
    throw std::runtime_error(L.id + ": no question asks " + quantity + " of '" + body_name + "' at that point");
}

// The answer to the question that names its collision by `pair` (a, b) and `collision`; the
// what-if one when `what_if` is true.
const LessonAnswer& ans_pair(const Lesson& L, const std::vector<LessonAnswer>& a, const std::string& quantity,
                             const std::string& body_name, const std::string& pa, const std::string& pb,
                             bool what_if = false) {
    const Quantity asked = named(quantity);
    for (std::size_t i = 0; i < L.questions.size() && i < a.size(); ++i) {
        const LessonQuestion& q = L.questions[i];
        if (q.quantity == asked && q.body == body_name && q.has_pair() && q.pair[0] == pa && q.pair[1] == pb &&
            q.what_if.empty() != what_if)
            return a[i];
    }
    throw std::runtime_error(L.id + ": no question asks " + quantity + " of " + pa + " and " + pb);
}

// Half extents of a 2D rectangle, in its own axes (its polygon is centred on the body).
Vec2 half_size(const SceneBody& b) {
    Vec2 h = Vec2::Zero();
    for (int i = 0; i < b.shape2.polygon.count; ++i) h = h.cwiseMax(b.shape2.polygon.vertices[i].cwiseAbs());
    return h;
}

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
Vec2 spin_x(double w, const Vec2& r) { return Vec2(-w * r.y(), w * r.x()); }  // w z x r
Vec2 rotate(double angle, const Vec2& p) {
    const double c = std::cos(angle), s = std::sin(angle);
    return Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y());
}

// Uniform rectangle and disc inertia (2D), to check what the scene computed.
double rectangle_inertia(double m, const Vec2& half) {
    return m * (4 * half.x() * half.x() + 4 * half.y() * half.y()) / 12;
}

void expect_vec2(const LessonAnswer& a, const Vec2& v, double tol) {
    ASSERT_TRUE(a.is_vector) << a.text;
    EXPECT_NEAR(a.vector.x(), v.x(), tol) << a.text;
    EXPECT_NEAR(a.vector.y(), v.y(), tol) << a.text;
}
void expect_vec3(const LessonAnswer& a, const Vec3& v, double tol) {
    ASSERT_TRUE(a.is_vector) << a.text;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.vector[k], v[k], tol) << a.text << " [" << k << "]";
}

// A frictionless 2D collision: P = j n on b, -P on a (static: inverse mass and inertia 0).
struct Hit2 {
    double j;
    Vec2 P, va, vb;
    double wa, wb;
};
Hit2 frictionless2(double e, double ima, double iIa, const Vec2& ra, const Vec2& va, double wa, double imb, double iIb,
                   const Vec2& rb, const Vec2& vb, double wb, const Vec2& n) {
    const double un = ((vb + spin_x(wb, rb)) - (va + spin_x(wa, ra))).dot(n);
    const double den = ima + imb + std::pow(cross2(ra, n), 2) * iIa + std::pow(cross2(rb, n), 2) * iIb;
    Hit2 h;
    h.j = -(1 + e) * un / den;
    h.P = h.j * n;
    h.va = va - ima * h.P;
    h.vb = vb + imb * h.P;
    h.wa = wa - cross2(ra, h.P) * iIa;
    h.wb = wb + cross2(rb, h.P) * iIb;
    return h;
}

TEST(LessonAnswers, Reversed) {
    // B (left, faster) catches A. The lesson names A as a and B as b, as the page does: our n
    // points from A into B, n = -x, and B receives P = j n with j >= 0, so P along x is the
    // page's J = -j < 0.
    const Lesson& L = lesson("reversed");
    const std::vector<LessonAnswer> a = answer_questions(L);
    const SceneBody &B = body(L, "B"), &A = body(L, "A");
    const double ma = A.body1.mass, mb = B.body1.mass, va = A.body1.v, vb = B.body1.v;
    const double e = L.scene.restitution;
    ASSERT_LT(B.body1.position, A.body1.position);
    const double j = (1 + e) * ma * mb * (vb - va) / (ma + mb);
    const double J_page = (1 + e) * ma * mb * (va - vb) / (ma + mb);
    ASSERT_EQ(engine_answers(L, a), 5u);
    EXPECT_GT(j, 0.0);
    EXPECT_LT(J_page, 0.0);
    EXPECT_NEAR(ans(L, a, "impulse").value, -j, 1e-12);
    EXPECT_NEAR(ans(L, a, "impulse").value, J_page, 1e-12);
    EXPECT_NEAR(ans(L, a, "velocity_after", "A").value, va - J_page / ma,
                1e-12);  // the page's formulas with its negative J
    EXPECT_NEAR(ans(L, a, "velocity_after", "B").value, vb + J_page / mb, 1e-12);
    EXPECT_NEAR(ans(L, a, "normal_velocity_after").value, -e * (va - vb), 1e-12);
    EXPECT_NEAR(ans(L, a, "energy_lost").value, (1 - e * e) * ma * mb * (vb - va) * (vb - va) / (2 * (ma + mb)), 1e-12);
}

TEST(LessonAnswers, RotationDirections) {
    // A's lower right corner (L/2, -h/2), turned by theta, reaches B's top face:
    // (L/2) sin(theta) - (h/2) cos(theta) = y_top, the root between the start angle and -pi/2.
    const Lesson& L = lesson("rotation-directions");
    const std::vector<LessonAnswer> a = answer_questions(L);
    const SceneBody &A = body(L, "A"), &B = body(L, "B");
    const Vec2 ha = half_size(A), hb = half_size(B);
    const double Ia = A.body2.inertia, Ib = B.body2.inertia;
    EXPECT_NEAR(Ia, rectangle_inertia(A.body2.mass, ha), 1e-15);
    EXPECT_NEAR(Ib, rectangle_inertia(B.body2.mass, hb), 1e-15);
    ASSERT_EQ(A.body2.position, Vec2::Zero());  // A's centre at rest at the origin
    const double top = B.body2.position.y() + hb.y();
    const double R = std::hypot(ha.x(), ha.y()), phi = std::atan2(-ha.y(), ha.x());
    const double theta = std::asin(top / R) - phi;  // R sin(theta + phi) = top
    ASSERT_LT(theta, A.body2.angle);
    const Vec2 ra = rotate(theta, Vec2(ha.x(), -ha.y()));
    const Vec2 rb = ra - B.body2.position;
    const Hit2 h = frictionless2(L.scene.restitution, 1 / A.body2.mass, 1 / Ia, ra, A.body2.v, A.body2.w,
                                 1 / B.body2.mass, 1 / Ib, rb, B.body2.v, B.body2.w, Vec2(0, -1));
    ASSERT_EQ(engine_answers(L, a), 5u);
    EXPECT_GT(h.wb, 0.0);       // anticlockwise
    EXPECT_LT(A.body2.w, 0.0);  // from a clockwise A
    EXPECT_NEAR(ans(L, a, "spin_after", "B").value, h.wb, 1e-7);
    EXPECT_NEAR(ans(L, a, "spin_after", "A").value, h.wa, 1e-7);
    EXPECT_NEAR(ans(L, a, "spin_angular_momentum_after", "B").value, Ib * h.wb, 1e-7);
    EXPECT_NEAR(ans(L, a, "spin_angular_momentum_after", "A").value, Ia * h.wa, 1e-7);
    // About the origin: before, only A's spin; kept.
    EXPECT_NEAR(ans(L, a, "angular_momentum_after").value, Ia * A.body2.w, 1e-7);
    EXPECT_NEAR(Ia * h.wa + Ib * h.wb + B.body2.mass * cross2(B.body2.position, h.vb), Ia * A.body2.w, 1e-12);
}

TEST(LessonAnswers, ContactPointVelocity) {
    // The bar is level when it touches the ball: at t = -angle / w, its centre at x + v t and
    // the contact at (x_ball, y_centre - h/2).
    const Lesson& L = lesson("contact-point-velocity");
    const std::vector<LessonAnswer> a = answer_questions(L);
    const SceneBody &A = body(L, "A"), &B = body(L, "B");
    const Vec2 ha = half_size(A);
    const double t = -A.body2.angle / A.body2.w;
    const Vec2 xa = A.body2.position + A.body2.v * t;
    const Vec2 p(B.body2.position.x(), xa.y() - ha.y());
    EXPECT_NEAR(B.body2.position.y() + B.shape2.radius, p.y(), 1e-15);  // the ball touches there
    const Vec2 ra = p - xa, rb = p - B.body2.position, n(0, -1);
    const Vec2 vpa = A.body2.v + spin_x(A.body2.w, ra);
    const Hit2 h = frictionless2(L.scene.restitution, 1 / A.body2.mass, 1 / A.body2.inertia, ra, A.body2.v, A.body2.w,
                                 1 / B.body2.mass, 1 / B.body2.inertia, rb, B.body2.v, 0.0, n);
    ASSERT_EQ(engine_answers(L, a), 5u);
    EXPECT_LT(A.body2.v.dot(n), 0.0);  // the centre moves away from the ball ...
    EXPECT_GT(vpa.dot(n), 0.0);        // ... its touching point towards it
    expect_vec2(ans(L, a, "point_velocity_before", "A"), vpa, 1e-7);
    EXPECT_NEAR(ans(L, a, "normal_velocity_before").value, -vpa.dot(n), 1e-7);
    expect_vec2(ans(L, a, "impulse"), h.P, 1e-7);
    expect_vec2(ans(L, a, "velocity_after", "B"), h.vb, 1e-7);
    expect_vec2(ans(L, a, "point_velocity_after", "A"), h.va + spin_x(h.wa, ra), 1e-7);
    // The closed form's impulse and the ball's velocity are along n alone: the world's
    // tangential part (its contact found to 1e-10 m) is below 1e-9 of the normal one and the
    // text writes it as 0, as the lesson's explanation does.
    ASSERT_EQ(h.P.x(), 0.0);
    ASSERT_LT(std::abs(ans(L, a, "impulse").vector.x()), 1e-9 * std::abs(ans(L, a, "impulse").vector.y()));
    EXPECT_EQ(ans(L, a, "impulse").text.rfind("(0, ", 0), 0u) << ans(L, a, "impulse").text;
    EXPECT_EQ(ans(L, a, "velocity_after", "B").text.rfind("(0, ", 0), 0u) << ans(L, a, "velocity_after", "B").text;
}

TEST(LessonAnswers, Restitution) {
    // Three rows (ball, bar) hit in order; u_n' = -e u_n at the touching points.
    const Lesson& L = lesson("restitution");
    const std::vector<LessonAnswer> a = answer_questions(L);
    ASSERT_EQ(engine_answers(L, a), 5u);
    std::vector<double> e(3);
    for (std::size_t k = 0; k < 3; ++k) e[k] = L.scene.pair_restitution(2 * k, 2 * k + 1);
    EXPECT_EQ(e[0], 0.1);
    EXPECT_EQ(e[1], 0.5);
    EXPECT_EQ(e[2], 1.0);
    const SceneBody& A0 = L.scene.bodies[0];
    EXPECT_NEAR(ans(L, a, "normal_velocity_before").value, -A0.body2.v.x(), 1e-12);
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(a[1 + k].value, e[k] * L.scene.bodies[2 * k].body2.v.x(), 1e-12) << "row " << k;
    // Bottom row: the bar's centre moves at j / m_b.
    const SceneBody &A2 = L.scene.bodies[4], &B2 = L.scene.bodies[5];
    const Vec2 hb = half_size(B2);
    const Vec2 rb(-hb.x(), A2.body2.position.y() - B2.body2.position.y());
    const Vec2 ra(A2.shape2.radius, 0.0);
    const Hit2 h = frictionless2(e[2], 1 / A2.body2.mass, 1 / A2.body2.inertia, ra, A2.body2.v, 0.0, 1 / B2.body2.mass,
                                 1 / B2.body2.inertia, rb, B2.body2.v, 0.0, Vec2(1, 0));
    expect_vec2(ans(L, a, "velocity_after", "B (e=1)", 3), h.vb, 1e-12);
}

TEST(LessonAnswers, General2d) {
    // A does not turn before the hit: its right-most corner strikes B's left face.
    // At the instant of contact the two are ~1e-17 m apart: the normal must still be B's face
    // normal (1, 0) (engine/shape2d, Shape2d.CornerTouchingFaceExactlyLesson6).
    const Lesson& L = lesson("general-2d");
    const std::vector<LessonAnswer> a = answer_questions(L);
    const SceneBody &A = body(L, "A"), &B = body(L, "B");
    const Vec2 ha = half_size(A), hb = half_size(B);
    Vec2 ra(-1e9, 0);
    for (double sx : {-1.0, 1.0})
        for (double sy : {-1.0, 1.0}) {
            const Vec2 c = rotate(A.body2.angle, Vec2(sx * ha.x(), sy * ha.y()));
            if (c.x() > ra.x()) ra = c;
        }
    const Vec2 p(B.body2.position.x() - hb.x(), A.body2.position.y() + ra.y());
    const Vec2 rb = p - B.body2.position;
    const Hit2 h = frictionless2(L.scene.restitution, 1 / A.body2.mass, 1 / A.body2.inertia, ra, A.body2.v, 0.0,
                                 1 / B.body2.mass, 1 / B.body2.inertia, rb, B.body2.v, 0.0, Vec2(1, 0));
    const double ke0 = 0.5 * A.body2.mass * A.body2.v.squaredNorm();
    const double ke1 = 0.5 * A.body2.mass * h.va.squaredNorm() + 0.5 * A.body2.inertia * h.wa * h.wa +
                       0.5 * B.body2.mass * h.vb.squaredNorm() + 0.5 * B.body2.inertia * h.wb * h.wb;
    ASSERT_EQ(engine_answers(L, a), 5u);
    expect_vec2(ans(L, a, "impulse"), h.P, 1e-12);
    expect_vec2(ans(L, a, "velocity_after", "A"), h.va, 1e-12);
    EXPECT_NEAR(ans(L, a, "spin_after", "A").value, h.wa, 1e-11);
    EXPECT_NEAR(ans(L, a, "spin_after", "B").value, h.wb, 1e-11);
    EXPECT_NEAR(ans(L, a, "energy_lost").value, ke0 - ke1, 1e-12);
}

TEST(LessonAnswers, FrameOfA) {
    // Lesson 6's scene minus A's velocity: the same geometry at every instant, so the same
    // impulse, spins and energy lost; velocities after are lesson 6's minus A's velocity.
    const Lesson& L = lesson("frame-of-a");
    const Lesson& L6 = lesson("general-2d");
    const std::vector<LessonAnswer> a = answer_questions(L);
    const SceneBody &A = body(L, "A"), &B = body(L, "B");
    const SceneBody &A6 = body(L6, "A"), &B6 = body(L6, "B");
    const Vec2 frame = A6.body2.v;
    ASSERT_EQ(A.body2.v, A6.body2.v - frame);
    ASSERT_EQ(B.body2.v, B6.body2.v - frame);
    const Vec2 ha = half_size(A), hb = half_size(B);
    Vec2 ra(-1e9, 0);
    for (double sx : {-1.0, 1.0})
        for (double sy : {-1.0, 1.0}) {
            const Vec2 c = rotate(A.body2.angle, Vec2(sx * ha.x(), sy * ha.y()));
            if (c.x() > ra.x()) ra = c;
        }
    // B's left face meets A's corner; relative to B's centre the point is the same as in lesson 6.
    const Vec2 rb(-hb.x(), A.body2.position.y() + ra.y() - B.body2.position.y());
    const Hit2 h = frictionless2(L.scene.restitution, 1 / A.body2.mass, 1 / A.body2.inertia, ra, A.body2.v, 0.0,
                                 1 / B.body2.mass, 1 / B.body2.inertia, rb, B.body2.v, 0.0, Vec2(1, 0));
    const Hit2 h6 = frictionless2(L6.scene.restitution, 1 / A6.body2.mass, 1 / A6.body2.inertia, ra, A6.body2.v, 0.0,
                                  1 / B6.body2.mass, 1 / B6.body2.inertia, rb, B6.body2.v, 0.0, Vec2(1, 0));
    const auto ke = [&](const Hit2& x, const SceneBody& a0, const SceneBody& b0) {
        const double before =
            0.5 * a0.body2.mass * a0.body2.v.squaredNorm() + 0.5 * b0.body2.mass * b0.body2.v.squaredNorm();
        const double after = 0.5 * a0.body2.mass * x.va.squaredNorm() + 0.5 * a0.body2.inertia * x.wa * x.wa +
                             0.5 * b0.body2.mass * x.vb.squaredNorm() + 0.5 * b0.body2.inertia * x.wb * x.wb;
        return before - after;
    };
    ASSERT_EQ(engine_answers(L, a), 5u);
    expect_vec2(ans(L, a, "impulse"), h.P, 1e-12);
    EXPECT_NEAR(h.j, h6.j, 1e-12);
    expect_vec2(ans(L, a, "velocity_after", "A"), h6.va - frame, 1e-12);
    expect_vec2(ans(L, a, "velocity_after", "B"), h6.vb - frame, 1e-12);
    EXPECT_NEAR(ans(L, a, "spin_after", "B").value, h6.wb, 1e-11);
    EXPECT_NEAR(ans(L, a, "energy_lost").value, ke(h, A, B), 1e-12);
    EXPECT_NEAR(ans(L, a, "energy_lost").value, ke(h6, A6, B6), 1e-12);
}

TEST(LessonAnswers, General3d) {
    // A does not turn before the hit; its right-most vertex strikes B's face x = x_b - half_x
    // (B is turned about x only). I = R I_body R^T for both.
    const Lesson& L = lesson("general-3d");
    const std::vector<LessonAnswer> a = answer_questions(L);
    const SceneBody &A = body(L, "A"), &B = body(L, "B");
    const Mat3 Ra = A.body3.orientation.toRotationMatrix(), Rb = B.body3.orientation.toRotationMatrix();
    ASSERT_NEAR((Rb * Vec3::UnitX() - Vec3::UnitX()).norm(), 0.0, 1e-15);
    const Mat3 Ia = Ra * A.body3.inertia * Ra.transpose(), Ib = Rb * B.body3.inertia * Rb.transpose();
    const Vec3 s = 2.0 * A.shape3.half;
    EXPECT_NEAR(A.body3.inertia(0, 0), A.body3.mass * (s.y() * s.y() + s.z() * s.z()) / 12, 1e-15);
    Vec3 ra(-1e9, 0, 0);
    for (double sx : {-1.0, 1.0})
        for (double sy : {-1.0, 1.0})
            for (double sz : {-1.0, 1.0}) {
                const Vec3 c = Ra * A.shape3.half.cwiseProduct(Vec3(sx, sy, sz));
                if (c.x() > ra.x()) ra = c;
            }
    const Vec3 p(B.body3.position.x() - B.shape3.half.x(), A.body3.position.y() + ra.y(),
                 A.body3.position.z() + ra.z());
    const Vec3 rb = p - B.body3.position, n = Vec3::UnitX();
    const double e = L.scene.restitution, ma = A.body3.mass, mb = B.body3.mass;
    const Vec3 ca = ra.cross(n), cb = rb.cross(n);
    const double un = (B.body3.v - A.body3.v).dot(n);
    const double j = -(1 + e) * un / (1 / ma + 1 / mb + ca.dot(Ia.inverse() * ca) + cb.dot(Ib.inverse() * cb));
    const Vec3 P = j * n;
    const Vec3 va = A.body3.v - P / ma, vb = B.body3.v + P / mb;
    const Vec3 wa = -Ia.inverse() * ra.cross(P), wb = Ib.inverse() * rb.cross(P);
    const double ke0 = 0.5 * ma * A.body3.v.squaredNorm();
    const double ke1 =
        0.5 * ma * va.squaredNorm() + 0.5 * wa.dot(Ia * wa) + 0.5 * mb * vb.squaredNorm() + 0.5 * wb.dot(Ib * wb);
    ASSERT_EQ(engine_answers(L, a), 5u);
    expect_vec3(ans(L, a, "impulse"), P, 1e-12);
    expect_vec3(ans(L, a, "velocity_after", "A"), va, 1e-12);
    expect_vec3(ans(L, a, "spin_after", "A"), wa, 1e-11);
    expect_vec3(ans(L, a, "spin_after", "B"), wb, 1e-11);
    EXPECT_NEAR(ans(L, a, "energy_lost").value, ke0 - ke1, 1e-12);
}

TEST(LessonAnswers, Friction) {
    // A puck (disc) on a static cushion, n = (0, 1), r = (0, -R). Normal impulse
    // (1 + e) m |v_y|; sticking needs P_t = -v_x / (1/m + R^2 / I); if that exceeds
    // mu j_n the puck slides with P_t = -mu j_n.
    const Lesson& L = lesson("friction");
    const std::vector<LessonAnswer> a = answer_questions(L);
    ASSERT_EQ(engine_answers(L, a), 5u);
    struct Out {
        Vec2 P, v;
        double w;
        bool sticks;
    };
    const auto hit = [&](const std::string& cushion, const std::string& puck) {
        const SceneBody& b = body(L, puck);
        const std::size_t i = index_of(L, cushion), k = index_of(L, puck);
        const double e = L.scene.pair_restitution(i, k), mu = L.scene.pair_friction(i, k);
        const double m = b.body2.mass, I = b.body2.inertia, R = b.shape2.radius;
        EXPECT_NEAR(I, m * R * R / 2, 1e-15);
        const double jn = -(1 + e) * m * b.body2.v.y();
        const double stick = -b.body2.v.x() / (1 / m + R * R / I);
        Out o;
        o.sticks = std::abs(stick) <= mu * jn;
        o.P = Vec2(o.sticks ? stick : -mu * jn * (b.body2.v.x() > 0 ? 1 : -1), jn);
        o.v = b.body2.v + o.P / m;
        o.w = cross2(Vec2(0, -R), o.P) / I;
        return o;
    };
    const Out smooth = hit("smooth cushion", "puck 1"), rough = hit("rough cushion", "puck 2");
    EXPECT_FALSE(smooth.sticks);
    EXPECT_TRUE(rough.sticks);
    expect_vec2(ans(L, a, "impulse"), smooth.P, 1e-12);
    EXPECT_NEAR(ans(L, a, "spin_after", "puck 1").value, smooth.w, 1e-11);
    expect_vec2(ans(L, a, "impulse", "", 2), rough.P, 1e-12);
    EXPECT_NEAR(ans(L, a, "spin_after", "puck 2", 2).value, rough.w, 1e-11);
    const double R = body(L, "puck 2").shape2.radius;
    expect_vec2(ans(L, a, "point_velocity_after", "puck 2", 2), rough.v + spin_x(rough.w, Vec2(0, -R)), 1e-12);
    EXPECT_NEAR(ans(L, a, "point_velocity_after", "puck 2", 2).vector.x(), 0.0, 1e-12);  // no slip after sticking
}

TEST(LessonAnswers, KanesParadox) {
    // Routh's method by hand for the rod's end on the ground (n = +y from the ground into the
    // rod, static ground), written here in world components: u0 = v + w x r, K = E/m +
    // perp(r) perp(r)^T / I; while the end slides with sign s along x, dP = (-mu s, 1) dP_n and
    // du = K dP. Phase 1 slides right until u_x = 0 (P1); sticking would need |K_xy / K_xx| <= mu,
    // else it slides back (s = sign K_xy). Compression ends at u_y = 0; Stronge's law ends the
    // impact when the work of the normal impulse in restitution, 1/2 a2 h^2, is e^2 times minus
    // that in compression. Then P = P1 d1 + h2 d2 and dE = u0.P + 1/2 P.K P. The rod is 1e-6 m
    // thick (its corner, not its axis, touches): 1e-5 covers that.
    const Lesson& L = lesson("kanes-paradox");
    const std::vector<LessonAnswer> a = answer_questions(L);
    const SceneBody& rod = body(L, "rod");
    const double m = rod.body2.mass, I = rod.body2.inertia, e = L.scene.restitution, mu = L.scene.friction;
    const double T = 0.1;  // the lesson starts the rod 0.1 s before the impact, no gravity
    const double angle = rod.body2.angle + rod.body2.w * T;
    EXPECT_NEAR(angle, 50.0 * kPi / 180.0, 1e-12);
    const Vec2 r = rotate(angle, Vec2(-0.5, 0.0));
    const Vec2 u0 = rod.body2.v + spin_x(rod.body2.w, r);
    const Vec2 perp(-r.y(), r.x());
    const Mat2 K = Mat2::Identity() / m + perp * perp.transpose() / I;
    ASSERT_GT(u0.x(), 0.0);  // sliding right
    const Vec2 d1(-mu, 1.0);
    const double P1 = -u0.x() / (K * d1).x();
    const Vec2 u1 = u0 + P1 * (K * d1);
    ASSERT_LT(u1.y(), 0.0);                      // still compressing when the slip stops
    ASSERT_GT(std::abs(K(0, 1) / K(0, 0)), mu);  // sticking cannot hold: it slides back
    const Vec2 d2(mu * (K(0, 1) > 0 ? -1.0 : 1.0), 1.0);
    const double a1 = (K * d1).y(), a2 = (K * d2).y();
    const double hc = -u1.y() / a2;  // to the end of compression
    const double Wc = u0.y() * P1 + 0.5 * a1 * P1 * P1 + u1.y() * hc + 0.5 * a2 * hc * hc;
    const double hr = std::sqrt(2.0 * e * e * -Wc / a2);  // 1/2 a2 hr^2 = -e^2 Wc
    const Vec2 P = P1 * d1 + (hc + hr) * d2;
    const double dE = u0.dot(P) + 0.5 * P.dot(K * P);
    EXPECT_NEAR(dE, -0.7527, 1e-4);  // the reference
    EXPECT_NEAR(ans(L, a, "energy_lost").value, -dE, 1e-5);
    EXPECT_NEAR(ans(L, a, "impulse_normal").value, P.y(), 1e-5);
    EXPECT_NEAR(ans(L, a, "slip_stop_impulse").value, P1, 1e-5);
    expect_vec2(ans(L, a, "point_velocity_after", "rod"), u0 + K * P, 1e-5);
}

TEST(LessonAnswers, MatrixMethod) {
    // The rod lands on its lowest corner without turning: K = E / m + r_perp r_perp^T / I,
    // P = -(1 + e) K^-1 u, and the corner leaves with -e u.
    const Lesson& L = lesson("matrix-method");
    const std::vector<LessonAnswer> a = answer_questions(L);
    const SceneBody& rod = body(L, "rod");
    const Vec2 h = half_size(rod);
    Vec2 r(0, 1e9);
    for (double sx : {-1.0, 1.0})
        for (double sy : {-1.0, 1.0}) {
            const Vec2 c = rotate(rod.body2.angle, Vec2(sx * h.x(), sy * h.y()));
            if (c.y() < r.y()) r = c;
        }
    const double m = rod.body2.mass, I = rod.body2.inertia, e = L.scene.restitution;
    EXPECT_NEAR(I, rectangle_inertia(m, h), 1e-15);
    const Vec2 rp(-r.y(), r.x());
    const Mat2 K = Mat2::Identity() / m + rp * rp.transpose() / I;
    const Vec2 u = rod.body2.v;
    const Vec2 P = -(1 + e) * K.inverse() * u;
    const Vec2 v = u + P / m;
    const double w = cross2(r, P) / I;
    ASSERT_EQ(engine_answers(L, a), 5u);
    expect_vec2(ans(L, a, "impulse"), P, 1e-12);
    expect_vec2(ans(L, a, "velocity_after", "rod"), v, 1e-12);
    EXPECT_NEAR(ans(L, a, "spin_after", "rod").value, w, 1e-11);
    expect_vec2(ans(L, a, "point_velocity_after", "rod"), -e * u, 1e-12);
    EXPECT_NEAR(ans(L, a, "energy_lost").value, 0.5 * m * u.squaredNorm() - 0.5 * m * v.squaredNorm() - 0.5 * I * w * w,
                1e-12);
}

TEST(LessonAnswers, Stick) {
    // Clay hits a resting rod and sticks: one rigid body. Momentum gives the common centre's
    // velocity vc = m v / (m + M); angular momentum about the centre of mass at the hit,
    // L = m (d x v), gives w = L / Ic with Ic = I_rod + M |d_rod|^2 + I_clay + m |d_clay|^2.
    const Lesson& L = lesson("stick");
    const std::vector<LessonAnswer> a = answer_questions(L);
    ASSERT_EQ(engine_answers(L, a), 6u);
    const SceneBody &clay = body(L, "clay"), &rod = body(L, "rod");
    const double m = clay.body2.mass, M = rod.body2.mass, R = clay.shape2.radius;
    ASSERT_EQ(rod.body2.v, Vec2::Zero());
    ASSERT_EQ(clay.body2.v.x(), 0.0);  // straight up onto the rod's lower face
    // Where the clay touches: its centre R below the face.
    const Vec2 x_clay(clay.body2.position.x(), rod.body2.position.y() - half_size(rod).y() - R);
    const Vec2 x_rod = rod.body2.position;
    const Vec2 xc = (m * x_clay + M * x_rod) / (m + M);
    const Vec2 vc = m * clay.body2.v / (m + M);
    const Vec2 d_clay = x_clay - xc, d_rod = x_rod - xc;
    const double Lc = m * cross2(d_clay, clay.body2.v);
    const double Ic =
        rectangle_inertia(M, half_size(rod)) + M * d_rod.squaredNorm() + 0.5 * m * R * R + m * d_clay.squaredNorm();
    const double w = Lc / Ic;
    expect_vec2(ans(L, a, "velocity_after", "clay"), vc + spin_x(w, d_clay), 1e-12);
    EXPECT_NEAR(ans(L, a, "spin_after", "rod").value, w, 1e-12);
    expect_vec2(ans(L, a, "velocity_after", "rod"), vc + spin_x(w, d_rod), 1e-12);
    const double before = 0.5 * m * clay.body2.v.squaredNorm();
    EXPECT_NEAR(ans(L, a, "energy_lost").value, before - (0.5 * (m + M) * vc.squaredNorm() + 0.5 * Ic * w * w), 1e-12);
    ASSERT_TRUE(L.questions[4].about.has_value());
    EXPECT_NEAR((L.questions[4].about->head<2>() - xc).norm(), 0.0, 1e-15);  // the text's point
    EXPECT_NEAR(ans(L, a, "angular_momentum_after").value, Lc, 1e-12);
    EXPECT_NEAR(ans(L, a, "final_spin", "rod").value, w, 1e-12);  // nothing else touches it: the spin stays
}

TEST(LessonAnswers, ErrataListingAsWritten) {
    // The page's listing on a ball hitting a resting bar straight up (n = +y) at p, worked here
    // by hand (not with engine/page.h): scalar = 1/ma + 1/mb minus the bar's rotational term
    // (rb x n).Ib^-1(rb x n) (erratum 5: the listing's crosses subtract it), Jmod =
    // (e + 1)|va - vb| / scalar (erratum 6), vaf = va - Jmod n/ma, vbf = vb - Jmod n/mb
    // (erratum 7), wbf = wb - Ib^-1 (n x rb) (erratum 8: per unit impulse). The ball's r is
    // along n, so it gets no spin term.
    const Lesson& L = lesson("errata");
    const std::vector<LessonAnswer> a = answer_questions(L);
    ASSERT_EQ(engine_answers(L, a), 6u);
    const SceneBody &ball = body(L, "ball"), &bar = body(L, "bar");
    const double ma = ball.body3.mass, mb = bar.body3.mass, e = L.scene.restitution;
    const double half_y = bar.shape3.half.y();  // the bar's lower face is at -half_y
    ASSERT_EQ(bar.body3.v, Vec3::Zero());
    ASSERT_EQ(ball.body3.v.x(), 0.0);
    ASSERT_EQ(ball.body3.v.z(), 0.0);
    const Vec3 n(0, 1, 0);
    const Vec3 p(ball.body3.position.x(), bar.body3.position.y() - half_y, 0.0);
    const Vec3 rb = p - bar.body3.position;
    // The bar's world inertia is its body inertia (not turned); its inverse is diagonal.
    const Mat3 inv_Ib = bar.body3.inertia.inverse();
    const Vec3 change_b = inv_Ib * n.cross(rb);  // angularVelChangeb
    const double scalar = 1 / ma + 1 / mb + change_b.cross(rb).dot(n);
    const double rotational = rb.cross(n).dot(inv_Ib * rb.cross(n));
    EXPECT_NEAR(scalar, 1 / ma + 1 / mb - rotational, 1e-15);  // erratum 5, as the text says
    const double Jmod = (e + 1) * (ball.body3.v - bar.body3.v).norm() / scalar;
    const Vec3 vaf = ball.body3.v - Jmod * n / ma, vbf = bar.body3.v - Jmod * n / mb;
    const Vec3 wbf = -change_b;
    expect_vec3(ans(L, a, "velocity_after", "bar"), vbf, 1e-12);
    expect_vec3(ans(L, a, "velocity_after", "ball"), vaf, 1e-12);
    expect_vec3(ans(L, a, "spin_after", "bar"), wbf, 1e-12);
    expect_vec3(ans(L, a, "momentum_after"), ma * vaf + mb * vbf, 1e-12);
    EXPECT_LT(ans(L, a, "momentum_after").vector.y(), 0.0);  // momentum reversed: not conserved
    const double energy =
        0.5 * ma * vaf.squaredNorm() + 0.5 * mb * vbf.squaredNorm() + 0.5 * wbf.dot(bar.body3.inertia * wbf);
    EXPECT_NEAR(ans(L, a, "kinetic_energy_after").value, energy, 1e-12);
    EXPECT_GT(ans(L, a, "kinetic_energy_after").value, 0.5 * ma * ball.body3.v.squaredNorm());  // energy out of nothing
    const double un = (vbf + wbf.cross(rb) - vaf).dot(n);
    EXPECT_NEAR(ans(L, a, "normal_velocity_after").value, un, 1e-12);
    EXPECT_LT(ans(L, a, "normal_velocity_after").value, 0.0);  // still approaching: they pass through each other
    // The corrected variant gives the frictionless answer: j = (1 + e) |un| / (1/ma + 1/mb + rotational).
    ASSERT_EQ(L.variants.size(), 1u);
    EXPECT_EQ(L.variants[0].scene.model, Model::frictionless);
}

TEST(LessonAnswers, Superball) {
    // Dropped from rest: it lands at sqrt(2 g h) and leaves at the same speed (e = 1, no
    // sliding). Thrown: u = (v_x, -sqrt(2 g h)), K = diag(1/m + R^2/I, 1/m), P = -2 K^-1 u.
    const Lesson& L = lesson("superball");
    const std::vector<LessonAnswer> a = answer_questions(L);
    const double g = -L.scene.gravity.y(), e = L.scene.restitution;
    ASSERT_EQ(e, 1.0);
    const SceneBody &d = body(L, "dropped"), &t = body(L, "thrown");
    const double hd = d.body2.position.y() - d.shape2.radius, ht = t.body2.position.y() - t.shape2.radius;
    ASSERT_EQ(d.body2.v, Vec2::Zero());
    ASSERT_EQ(t.body2.v.y(), 0.0);
    const double m = t.body2.mass, I = t.body2.inertia, R = t.shape2.radius;
    const Vec2 u(t.body2.v.x(), -std::sqrt(2 * g * ht));
    const Vec2 P(-(1 + e) * u.x() / (1 / m + R * R / I), -(1 + e) * u.y() * m);
    const Vec2 v = u + P / m;
    const double w = cross2(Vec2(0, -R), P) / I;
    ASSERT_EQ(engine_answers(L, a), 5u);
    expect_vec2(ans(L, a, "velocity_after", "dropped"), Vec2(0, std::sqrt(2 * g * hd)), 1e-9);
    expect_vec2(ans(L, a, "impulse", "", 2), P, 1e-9);
    expect_vec2(ans(L, a, "velocity_after", "thrown", 2), v, 1e-9);
    EXPECT_NEAR(ans(L, a, "spin_after", "thrown", 2).value, w, 1e-8);
    EXPECT_NEAR(ans(L, a, "energy_lost", "", 2).value, 0.0, 1e-12);
    EXPECT_NEAR(0.5 * m * v.squaredNorm() + 0.5 * I * w * w, 0.5 * m * u.squaredNorm(), 1e-12);
}

TEST(LessonAnswers, Conservation) {
    // Nothing acts between collisions, so the totals at the hit are those at t = 0:
    // p = sum m v, L_o = sum R I R^T w + (x - o) x m v, KE = sum 1/2 m v.v + 1/2 w.(R I R^T) w.
    const Lesson& L = lesson("conservation");
    const std::vector<LessonAnswer> a = answer_questions(L);
    const Vec3 o(0.0, 0.5, 0.0);
    Vec3 p = Vec3::Zero(), Lo = Vec3::Zero();
    double ke = 0;
    for (const SceneBody& b : L.scene.bodies) {
        const Mat3 R = b.body3.orientation.toRotationMatrix();
        const Mat3 I = R * b.body3.inertia * R.transpose();
        p += b.body3.mass * b.body3.v;
        Lo += I * b.body3.w + (b.body3.position - o).cross(b.body3.mass * b.body3.v);
        ke += 0.5 * b.body3.mass * b.body3.v.squaredNorm() + 0.5 * b.body3.w.dot(I * b.body3.w);
    }
    ASSERT_EQ(engine_answers(L, a), 5u);
    ASSERT_EQ(L.questions[1].about, o);
    expect_vec3(ans(L, a, "momentum_after"), p, 1e-12);
    expect_vec3(ans(L, a, "angular_momentum_before"), Lo, 1e-9);
    expect_vec3(ans(L, a, "angular_momentum_after"), Lo, 1e-9);
    EXPECT_NEAR(ans(L, a, "kinetic_energy_before").value, ke, 1e-9);
    EXPECT_NEAR(ans(L, a, "kinetic_energy_after").value, ke, 1e-9);
}

TEST(LessonAnswers, NewtonsCradle) {
    // Sequential, equal masses, e = 1: (v, 0, 0) -> (0, v, 0) -> (0, 0, v), j = m v each time.
    const Lesson& L = lesson("newtons-cradle");
    const std::vector<LessonAnswer> a = answer_questions(L);
    const double v = L.scene.bodies[0].body1.v, m = L.scene.bodies[0].body1.mass;
    ASSERT_EQ(engine_answers(L, a), 5u);
    EXPECT_NEAR(ans(L, a, "impulse").value, m * v, 1e-12);
    EXPECT_EQ(ans(L, a, "collisions").value, 2.0);
    EXPECT_NEAR(ans(L, a, "final_velocity", "first").value, 0.0, 1e-12);
    EXPECT_NEAR(ans(L, a, "final_velocity", "second").value, 0.0, 1e-12);
    EXPECT_NEAR(ans(L, a, "final_velocity", "third").value, v, 1e-12);
}

TEST(LessonAnswers, BouncingBall) {
    // Dropped from H: first bounce at sqrt(2H/g), leaving at e sqrt(2gH); the bounces end at
    // T = sqrt(2H/g) (1 + e) / (1 - e).
    const Lesson& L = lesson("bouncing-ball");
    const std::vector<LessonAnswer> a = answer_questions(L);
    const SceneBody &floor = body(L, "floor"), &ball = body(L, "ball");
    ASSERT_EQ(floor.shape2.kind, Shape2::Kind::half_plane);  // the floor, y = its offset
    const double H = (ball.body2.position.y() - ball.shape2.radius) - floor.shape2.offset;
    const double g = -L.scene.gravity.y(), e = L.scene.restitution;
    EXPECT_EQ(L.scene.gravity.x(), 0.0);  // drawn upright: gravity along -y
    const double t0 = std::sqrt(2 * H / g);
    ASSERT_EQ(engine_answers(L, a), 4u);
    EXPECT_NEAR(ans(L, a, "time").value, t0, 1e-12);
    EXPECT_NEAR(ans(L, a, "velocity_after", "ball").value, e * std::sqrt(2 * g * H), 1e-12);
    EXPECT_NEAR(ans(L, a, "last_collision_time").value, t0 * (1 + e) / (1 - e), 1e-9);
    EXPECT_NEAR(ans(L, a, "final_velocity", "ball").value, 0.0, 1e-12);
}

TEST(LessonAnswers, CentreOfPercussion) {
    // A ball hits a free bar at d from its centre: v = j/m, w = j d / I; the handle end
    // (-L/2 from the centre) moves at j (1/m - d L / (2 I)), zero at d = 2 I / (m L).
    const Lesson& L = lesson("centre-of-percussion");
    const std::vector<LessonAnswer> a = answer_questions(L);
    ASSERT_EQ(engine_answers(L, a), 4u);
    const auto hit = [&](const std::string& ball, const std::string& bat, double* j, Vec2* handle, Vec2* tip) {
        const SceneBody &b = body(L, ball), &B = body(L, bat);
        const Vec2 h = half_size(B);
        const double e = L.scene.pair_restitution(index_of(L, ball), index_of(L, bat));
        const Vec2 rb(b.body2.position.x() - B.body2.position.x(), -h.y()), n(0, 1);
        const Hit2 H = frictionless2(e, 1 / b.body2.mass, 1 / b.body2.inertia, Vec2(0, b.shape2.radius), b.body2.v, 0.0,
                                     1 / B.body2.mass, 1 / B.body2.inertia, rb, B.body2.v, 0.0, n);
        *j = H.j;
        *handle = H.vb + spin_x(H.wb, Vec2(-h.x(), 0));
        *tip = H.vb + spin_x(H.wb, Vec2(h.x(), 0));
    };
    double j1 = 0, j2 = 0;
    Vec2 handle1, tip1, handle2, tip2;
    hit("ball 1", "bat 1", &j1, &handle1, &tip1);
    hit("ball 2", "bat 2", &j2, &handle2, &tip2);
    const SceneBody& bat1 = body(L, "bat 1");
    const double d1 = body(L, "ball 1").body2.position.x() - bat1.body2.position.x();
    EXPECT_NEAR(d1, 2 * bat1.body2.inertia / (bat1.body2.mass * 2 * half_size(bat1).x()), 1e-15);
    expect_vec2(ans(L, a, "impulse"), Vec2(0, j1), 1e-12);
    // The points the lesson asks about: bat 1's handle end (x = -1.1) and its other end (-0.1).
    const LessonAnswer& handle = ans_at(L, a, "point_velocity_after", "bat 1", Vec3(-1.1, 0.0, 0.0));
    const LessonAnswer& tip = ans_at(L, a, "point_velocity_after", "bat 1", Vec3(-0.1, 0.0, 0.0));
    expect_vec2(handle, handle1, 1e-12);
    EXPECT_NEAR(handle.value, 0.0, 1e-12);  // the sweet spot: no jolt
    expect_vec2(tip, tip1, 1e-12);
    expect_vec2(ans(L, a, "point_velocity_after", "bat 2", 2), handle2, 1e-12);
    EXPECT_LT(ans(L, a, "point_velocity_after", "bat 2", 2).vector.y(), 0.0);  // near the tip: the handle jumps back
}

TEST(LessonAnswers, Box2dSlowElasticBounce) {
    // A disc dropped from rest onto a plane with e = 1: it lands at v = sqrt(2 g h) after
    // t1 = sqrt(2 h / g), leaves at +v, and lands again every 2 v / g; no energy is lost.
    const Lesson& L = lesson("box2d");
    const SceneBody& ball = body(L, "ball");
    const double g = -L.scene.gravity.y();
    const double h = ball.body2.position.y() - ball.shape2.radius;
    const double v = std::sqrt(2 * g * h), t1 = std::sqrt(2 * h / g), period = 2 * v / g;
    const std::vector<LessonAnswer> a = answer_questions(L);
    ASSERT_EQ(engine_answers(L, a), 4u);
    ASSERT_TRUE(ans(L, a, "velocity_after", "ball").is_vector);
    EXPECT_NEAR(ans(L, a, "velocity_after", "ball").vector.x(), 0.0, 1e-12);
    EXPECT_NEAR(ans(L, a, "velocity_after", "ball").vector.y(), v, 1e-9);  // contact found to 1e-10 m
    EXPECT_NEAR(ans(L, a, "time").value, t1, 1e-9);
    EXPECT_EQ(ans(L, a, "collisions").value, std::floor((L.scene.duration - t1) / period) + 1);
    EXPECT_NEAR(ans(L, a, "energy_lost").value, 0.0, 1e-12);
}

TEST(LessonAnswers, PenaltyContactMatchesTheDampedOscillator) {
    // Two blocks on a line, A (m_a, v_a) onto B at rest, with e. The impulse model gives
    // P = (1 + e) m v_0, m = m_a m_b / (m_a + m_b). The spring-damper k, c = 2 zeta sqrt(k m):
    // the overlap obeys m delta'' + c delta' + k delta = 0 from delta = 0, delta' = v_0, so
    // delta = (v_0 / w_d) exp(-s t) sin(w_d t), s = zeta w_0, w_0 = sqrt(k/m), w_d = w_0 sqrt(1 - zeta^2);
    // the blocks let go when F = k delta + c delta' = 0, at t_c = (pi - 2 asin zeta) / w_d, and
    // then e = exp(-zeta (pi - 2 asin zeta) / sqrt(1 - zeta^2)). The answered zeta must give the
    // lesson's e through that formula. Tolerances: 1e-12 for the closed forms; 1e-9 for what
    // the run integrates (RK4, step pi sqrt(m/k) / 2000, end found by bisection); 1e-6 for the
    // peak force and overlap, maxima sampled at the steps ((w h)^2 / 8 = 3e-7 at most).
    Lesson L = lesson("penalty");
    ASSERT_TRUE(L.penalty);
    const double ma = body(L, "A").body1.mass, mb = body(L, "B").body1.mass;
    const double v0 = body(L, "A").body1.v - body(L, "B").body1.v;
    const double e = L.scene.restitution, k = L.penalty->stiffness;
    const double m = ma * mb / (ma + mb);
    L.questions.clear();
    for (const char* q : {"penalty_damping_ratio", "penalty_damping", "penalty_contact_time", "penalty_peak_force",
                          "penalty_max_overlap", "penalty_impulse", "penalty_restitution", "impulse"}) {
        LessonQuestion Q;
        Q.text = q;
        Q.quantity = named(q);
        L.questions.push_back(Q);
    }
    const std::vector<LessonAnswer> a = answer_questions(L);
    ASSERT_EQ(engine_answers(L, a), 8u);
    const double zeta = ans(L, a, "penalty_damping_ratio").value;
    ASSERT_GT(zeta, 0.0);
    ASSERT_LT(zeta, 1.0);
    EXPECT_NEAR(std::exp(-zeta * (kPi - 2 * std::asin(zeta)) / std::sqrt(1 - zeta * zeta)), e, 1e-12);
    const double c = 2 * zeta * std::sqrt(k * m);
    EXPECT_NEAR(ans(L, a, "penalty_damping").value, c, 1e-12 * c);
    const double w0 = std::sqrt(k / m), wd = w0 * std::sqrt(1 - zeta * zeta), sg = zeta * w0;
    const double tc = (kPi - 2 * std::asin(zeta)) / wd;
    EXPECT_NEAR(ans(L, a, "penalty_contact_time").value, tc, 1e-9 * tc);
    // The maxima of the closed forms over the contact, densely sampled (error < 1e-9 relative).
    double peak = 0, deepest = 0;
    for (int i = 0; i <= 400000; ++i) {
        const double t = tc * i / 400000;
        const double delta = v0 / wd * std::exp(-sg * t) * std::sin(wd * t);
        const double rate = v0 * std::exp(-sg * t) * (std::cos(wd * t) - sg / wd * std::sin(wd * t));
        peak = std::max(peak, k * delta + c * rate);
        deepest = std::max(deepest, delta);
    }
    EXPECT_NEAR(ans(L, a, "penalty_peak_force").value, peak, 1e-6 * peak);
    EXPECT_NEAR(ans(L, a, "penalty_max_overlap").value, deepest, 1e-6 * deepest);
    const double P = (1 + e) * m * v0;
    EXPECT_NEAR(ans(L, a, "penalty_impulse").value, P, 1e-9 * P);
    EXPECT_NEAR(ans(L, a, "penalty_restitution").value, e, 1e-9);
    EXPECT_NEAR(ans(L, a, "impulse").value, P, 1e-12 * P);

    // The study's tables: each damping ratio's e by both formulas (no pull: the spring lets go
    // at F = 0; pull: half a period, e = exp(-zeta pi / sqrt(1 - zeta^2))), and the matched zeta
    // at each stiffness: e unchanged, the contact time (pi - 2 asin zeta) / w_d with w_0 = sqrt(k/m).
    const PenaltyStudy st = penalty_study(L, record_any(L.scene, {L.scene.duration}));
    ASSERT_EQ(st.rows.size(), L.penalty->damping_ratios.size());
    for (const PenaltyStudy::Row& r : st.rows) {
        const double z = r.zeta, q = std::sqrt(1 - z * z);
        EXPECT_NEAR(r.push.restitution, std::exp(-z * (kPi - 2 * std::asin(z)) / q), 1e-9) << z;
        EXPECT_NEAR(r.pull.restitution, std::exp(-z * kPi / q), 1e-9) << z;
    }
    ASSERT_EQ(st.stiffer.size(), L.penalty->stiffnesses.size());
    for (const PenaltyStudy::Stiff& r : st.stiffer) {
        const double wdk = std::sqrt(r.stiffness / m) * std::sqrt(1 - zeta * zeta);
        EXPECT_NEAR(r.run.restitution, e, 1e-9) << r.stiffness;
        EXPECT_NEAR(r.run.contact_time, (kPi - 2 * std::asin(zeta)) / wdk, 1e-9 * tc) << r.stiffness;
        EXPECT_NEAR(r.run.impulse, P, 1e-9 * P) << r.stiffness;
    }
}

TEST(LessonAnswers, APairNamesTheRunsCollisionInItsRoles) {
    // The bouncing ball's third bounce, by its number in the run and by its pair: the same
    // collision; asked with the roles the other way round, the impulse on b is the opposite.
    Lesson L = lesson("bouncing-ball");
    L.questions.clear();
    LessonQuestion by_event, by_pair, reversed;
    by_event.text = by_pair.text = reversed.text = "P?";
    by_event.quantity = by_pair.quantity = reversed.quantity = Quantity::impulse;
    by_event.event = 3;
    by_pair.pair = {"floor", "ball"};
    by_pair.pair_a = index_of(L, "floor");
    by_pair.pair_b = index_of(L, "ball");
    by_pair.collision = 3;
    reversed = by_pair;
    reversed.pair = {"ball", "floor"};
    std::swap(reversed.pair_a, reversed.pair_b);
    L.questions = {by_event, by_pair, reversed};
    const std::vector<LessonAnswer> a = answer_questions(L);
    ASSERT_EQ(a.size(), 3u);
    EXPECT_GT(a[0].vector.y(), 0.0);  // the floor pushes the ball up
    EXPECT_EQ(a[1].vector, a[0].vector);
    EXPECT_EQ(a[2].vector, -a[0].vector);
    L.questions[1].collision = 1000;
    EXPECT_THROW(answer_questions(L), InputError);
}

TEST(LessonAnswers, Tower) {
    // The ball flies ballistically to the tower's left faces (x = -w/2): its front reaches them
    // after t = (-w/2 - r - x0) / v, when it has fallen g t^2 / 2, into box 4's height. The
    // impact is solved with every touching contact of the resting tower together: each body's
    // momentum changes by the impulses it receives (round-off), the ball's by -P. Box 6
    // touches only box 5, so it rises at j56 / m; box 5 rides up with box 4's edge, so box 4
    // lifts both: j45 = 2 j56 to the difference of their rising speeds (4e-6 here).
    const Lesson& L = lesson("tower");
    const std::vector<LessonAnswer> a = answer_questions(L);
    ASSERT_EQ(engine_answers(L, a), 7u);
    const SceneBody& ball = body(L, "ball");
    const SceneBody& box4 = body(L, "box 4");
    const double g = -L.scene.gravity.y(), m = ball.body3.mass;
    const Vec3 x0 = ball.body3.position, v0 = ball.body3.v;
    const double t = (-box4.shape3.half.x() - ball.shape3.radius - x0.x()) / v0.x();
    EXPECT_NEAR(t, 0.155, 1e-12);
    const double y = x0.y() - 0.5 * g * t * t;
    EXPECT_GT(y, box4.body3.position.y() - box4.shape3.half.y());  // box 4's height
    EXPECT_LT(y, box4.body3.position.y() + box4.shape3.half.y());
    EXPECT_NEAR(ans_pair(L, a, "time", "", "ball", "box 4").value, t, 1e-9);  // contact to 1e-10 m
    const LessonAnswer& P = ans_pair(L, a, "impulse", "", "ball", "box 4");
    const Vec3 v_before(v0.x(), -g * t, 0.0);
    expect_vec3(ans_pair(L, a, "velocity_after", "ball", "ball", "box 4"), v_before - P.vector / m, 1e-8);

    // Every body's momentum at the impact's instant changes by the impulses it received.
    const AnyRecording run = record_any(L.scene, {L.scene.duration});
    const auto& rec = std::get<Recording<3>>(run);
    std::vector<Vec3> received(L.scene.bodies.size(), Vec3::Zero()), dp(L.scene.bodies.size(), Vec3::Zero());
    std::size_t at_impact = 0;
    for (const Event<3>& e : rec.events) {
        if (e.t != rec.events.front().t) break;
        ++at_impact;
        received[e.b] += e.impulse;
        received[e.a] -= e.impulse;
        for (const auto& [i, before, after] :
             {std::tuple{e.a, e.before_a, e.after_a}, std::tuple{e.b, e.before_b, e.after_b}})
            if (!L.scene.bodies[i].is_static()) dp[i] = L.scene.bodies[i].body3.mass * (after.v - before.v);
    }
    EXPECT_EQ(at_impact, 7u);  // ball-box 4, box 4 with 3 and 5, 5-6, 3-2, 2-1, 1-ground
    for (std::size_t i = 0; i < L.scene.bodies.size(); ++i) {
        if (L.scene.bodies[i].is_static()) continue;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(dp[i][k], received[i][k], 1e-9) << L.scene.bodies[i].name;
    }
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(received[index_of(L, "ball")][k], -P.vector[k], 1e-12);

    // Up the tower: box 6 rises at j56 / m, box 4 gives box 5 twice as much.
    double j56 = 0;  // no question asks it: from the record
    for (std::size_t k = 0; k < at_impact; ++k) {
        const Event<3>& e = rec.events[k];
        if (e.a == index_of(L, "box 5") && e.b == index_of(L, "box 6")) j56 = e.impulse.dot(e.normal);
    }
    const double j45 = ans_pair(L, a, "impulse_normal", "", "box 4", "box 5").value;
    EXPECT_NEAR(ans_pair(L, a, "velocity_after", "box 6", "box 5", "box 6").vector.y(),
                j56 / body(L, "box 6").body3.mass, 1e-9);
    EXPECT_NEAR(j45, 2 * j56, 1e-4 * j45);
    // Down the tower: box 3 passes on almost all it receives, with friction at the cone's edge.
    const double j34 = ans_pair(L, a, "impulse_normal", "", "box 3", "box 4").value;
    const double jg1 = ans_pair(L, a, "impulse_normal", "", "ground", "box 1").value;
    EXPECT_NEAR(jg1, j34, 1e-3 * j34);

    // The numbers the lesson's text quotes (to their printed digits).
    EXPECT_NEAR(P.vector.x(), 3.945, 5e-4);
    EXPECT_NEAR(P.vector.y(), -0.869, 5e-4);
    EXPECT_NEAR(j34, 1.234, 5e-4);
    EXPECT_NEAR(jg1, 1.234, 5e-4);
    EXPECT_NEAR(j56, 0.1217, 5e-5);
    EXPECT_NEAR(j45, 0.243, 5e-4);
    EXPECT_NEAR(ans_pair(L, a, "velocity_after", "ball", "ball", "box 4").vector.x(), 2.028, 5e-4);

    // Energy: 42.49 J at the start (closed form), less than a third of it at the end, and
    // between two frames (the lesson's output_dt) it never rises by more than 3 mJ.
    std::vector<double> times;
    for (int k = 0; k <= 200; ++k) times.push_back(0.01 * k);
    const AnyRecording sampled_run = record_any(L.scene, times);
    const auto& sampled = std::get<Recording<3>>(sampled_run);
    std::vector<double> E;
    for (const auto& state : sampled.states) {
        double potential = 0;
        for (const Body3& b : state)
            if (!b.is_static) potential += b.mass * g * b.position.y();
        E.push_back(totals(state).kinetic_energy + potential);
    }
    double boxes = 0;
    for (int i = 1; i <= 6; ++i) boxes += body(L, "box " + std::to_string(i)).body3.position.y() * g;
    EXPECT_NEAR(E.front(), boxes + m * g * x0.y() + 0.5 * m * v0.squaredNorm(), 1e-9);
    EXPECT_NEAR(E.front(), 42.49, 5e-3);
    EXPECT_LT(E.back(), E.front() / 3);
    for (std::size_t k = 1; k < E.size(); ++k) EXPECT_LT(E[k] - E[k - 1], 3e-3) << times[k];
}

// The time a domino of thickness t and height h, turning about its front bottom corner at w0
// from upright, takes to turn by theta_end: its energy about the corner gives
// w(theta)^2 = w0^2 + (2 m g r_c / I_c) (cos phi0 - cos(theta - phi0)); T = integral dtheta / w,
// by the midpoint rule on theta = u^2 (smooth when w0 is small). Mass-free: I_c / m.
double domino_fall_time(double w0, double theta_end, double t, double h, double g) {
    const double Ic = (t * t + h * h) / 12 + (t * t + h * h) / 4, rc = 0.5 * std::hypot(t, h), phi0 = std::atan(t / h);
    const double k = 2 * g * rc / Ic, U = std::sqrt(theta_end);
    const int n = 200000;
    double T = 0;
    for (int i = 0; i < n; ++i) {
        const double u = (i + 0.5) / n * U, th = u * u;
        T += 2 * u * (U / n) / std::sqrt(w0 * w0 + k * (std::cos(phi0) - std::cos(th - phi0)));
    }
    return T;
}

TEST(LessonAnswers, Dominoes) {
    // Domino 1 turns about its front corner from upright at w0 until its top edge touches
    // domino 2: sin theta* = (d - t) / h. Its energy about the corner gives its spin there and,
    // integrated, the time (domino_fall_time). The run's corner rattles on the table at the start
    // and is then stepped: within 1 % of both. The wave then settles: the strikes of dominoes 11
    // to 15 come at one interval dt (their mean; each within 0.1 ms of it), shorter than the
    // time a struck domino needs alone (a lower bound on the speed d / dt), whatever the mass.
    // The measured numbers the text quotes are checked to the digits it gives them.
    const Lesson& L = lesson("dominoes");
    const std::vector<LessonAnswer> a = answer_questions(L);
    ASSERT_EQ(engine_answers(L, a), 5u);
    const SceneBody &d1 = body(L, "domino 1"), &d2 = body(L, "domino 2");
    const Vec2 half = half_size(d1);
    const double t = 2 * half.x(), h = 2 * half.y(), g = -L.scene.gravity.y(), w0 = -d1.body2.w;
    const double d = d2.body2.position.x() - d1.body2.position.x();
    EXPECT_NEAR(d1.body2.v.x(), -d1.body2.w * half.y(), 1e-15);  // turning about the corner (t/2, 0)
    EXPECT_NEAR(d1.body2.v.y(), -d1.body2.w * half.x(), 1e-15);
    const double theta = std::asin((d - t) / h);
    EXPECT_NEAR(theta * 180 / kPi, 27.28, 5e-3);
    const double Ic = (t * t + h * h) / 3, rc = 0.5 * std::hypot(t, h), phi0 = std::atan(t / h);  // per kg
    const double w_hit = std::sqrt(w0 * w0 + 2 * g * rc / Ic * (std::cos(phi0) - std::cos(theta - phi0)));
    EXPECT_NEAR(w_hit, 6.766, 5e-4);
    const double T1 = domino_fall_time(w0, theta, t, h, g);
    EXPECT_NEAR(T1, 0.1004, 5e-5);
    const double w_run = -ans_pair(L, a, "spin_before", "domino 1", "domino 1", "domino 2").value;
    const double t_run = ans_pair(L, a, "time", "", "domino 1", "domino 2").value;
    EXPECT_NEAR(w_run, w_hit, 0.01 * w_hit);
    EXPECT_NEAR(t_run, T1, 0.01 * T1);

    // The wave: the first strike of domino k on domino k + 1, for every k.
    const AnyRecording run = record_any(L.scene, {L.scene.duration});
    const auto& rec = std::get<Recording<2>>(run);
    std::vector<double> strike;  // strike[k]: domino k + 1 strikes domino k + 2
    for (int k = 1; k < 15; ++k) {
        const std::size_t i = index_of(L, "domino " + std::to_string(k)),
                          j = index_of(L, "domino " + std::to_string(k + 1));
        double first = -1;
        for (const Event<2>& e : rec.events)
            if ((e.a == i && e.b == j) || (e.a == j && e.b == i)) {
                first = e.t;
                break;
            }
        ASSERT_GT(first, 0.0) << "domino " << k << " never strikes the next";
        strike.push_back(first);
    }
    for (std::size_t k = 1; k < strike.size(); ++k) EXPECT_GT(strike[k] - strike[k - 1], 0.0);
    const double dt = (strike[13] - strike[9]) / 4;  // the last four intervals' mean
    for (std::size_t k = 10; k < strike.size(); ++k) EXPECT_NEAR(strike[k] - strike[k - 1], dt, 1e-4) << k;
    EXPECT_NEAR(dt, 0.0378, 1e-4);
    EXPECT_NEAR(d / dt, 0.794, 1.5e-3);
    EXPECT_NEAR(d / dt / std::sqrt(g * h), 1.16, 5e-3);
    EXPECT_NEAR(ans_pair(L, a, "time", "", "domino 10", "domino 11").value, strike[9], 1e-12);
    EXPECT_NEAR(ans_pair(L, a, "time", "", "domino 14", "domino 15").value, strike[13], 1e-12);
    EXPECT_NEAR(strike[9], 0.5293, 1e-4);
    EXPECT_NEAR(strike[13], 0.6803, 1e-4);
    // The bound: domino 15 alone from its strike's spin would take longer than the wave.
    const double w15 = -ans_pair(L, a, "spin_after", "domino 15", "domino 14", "domino 15").value;
    EXPECT_NEAR(w15, 8.2, 0.15);
    const double alone = domino_fall_time(w15, theta, t, h, g);
    EXPECT_NEAR(alone, 0.059, 1e-3);
    EXPECT_GT(alone, dt);
    EXPECT_GT(d / alone, 0.5);
    // Twice the mass: the same instants.
    EXPECT_NEAR(ans_pair(L, a, "time", "", "domino 14", "domino 15", true).value, strike[13], 1e-9);

    // The steady wave forgets the push (8 rad/s instead of 5: the same steady interval, to
    // 0.05 ms), and dominoes twice as large, spaced twice as far, take sqrt(2) times as long
    // (the time steps do not scale: 0.3 %). The lesson's file edited as the teacher notes say.
    std::ifstream in(L.file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Without its [[vary]] tables (the file's last): their ranges are around the lesson's own
    // spacing, which the larger row leaves.
    ASSERT_NE(text.find("[[vary]]"), std::string::npos);
    text = text.substr(0, text.find("[[vary]]"));
    const auto replaced = [](std::string s, const std::string& from, const std::string& to) {
        for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
            s.replace(at, from.size(), to);
        return s;
    };
    const auto last_interval = [&](const std::string& changed) {
        const Lesson V = parse_lesson_text(changed, "dominoes-variant.toml", L.file);
        const AnyRecording r = record_any(V.scene, {V.scene.duration});
        std::vector<double> first(16, -1.0);  // first[k]: domino k strikes domino k + 1
        for (const Event<2>& e : std::get<Recording<2>>(r).events) {
            const std::string &na = V.scene.bodies[e.a].name, &nb = V.scene.bodies[e.b].name;
            if (na.rfind("domino ", 0) != 0 || nb.rfind("domino ", 0) != 0) continue;
            const int k = std::stoi(na.substr(7));
            if (std::stoi(nb.substr(7)) == k + 1 && first[static_cast<std::size_t>(k)] < 0)
                first[static_cast<std::size_t>(k)] = e.t;
        }
        return (first[14] - first[10]) / 4;  // the last four intervals' mean
    };
    const double pushed = last_interval(replaced(text, "v = [0.12, 0.02]\nw = -5.0", "v = [0.192, 0.032]\nw = -8.0"));
    EXPECT_NEAR(pushed, dt, 5e-5);
    std::string big = replaced(text, "size = [0.008, 0.048]", "size = [0.016, 0.096]");
    for (int k = 14; k >= 0; --k) {  // positions [0.03 k, 0.024] -> [0.06 k, 0.048], from the last
        char from[64], to[64];
        std::snprintf(from, sizeof from, k == 0 ? "position = [0.0, 0.024]" : "position = [%g, 0.024]", 0.03 * k);
        std::snprintf(to, sizeof to, "position = [%g, 0.048]", 0.06 * k);
        ASSERT_NE(big.find(from), std::string::npos) << from;
        big = replaced(big, from, to);
    }
    big = replaced(replaced(big, "duration = 1.0", "duration = 1.5"), "v = [0.12, 0.02]", "v = [0.24, 0.04]");
    EXPECT_NEAR(last_interval(big) / dt, std::sqrt(2.0), 0.005 * std::sqrt(2.0));
}

}  // namespace
}  // namespace collide
