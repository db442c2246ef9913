#include "teach/event_problem.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <utility>

#include "engine/diagnostics.h"
#include "teach/notation.h"

namespace collide {

namespace {

SolveBody solve_body(const Scene& scene, std::size_t i, const CollisionInstant::Side& s) {
    const SceneBody& sb = scene.bodies[i];
    SolveBody out;
    out.name = sb.name;
    out.shape = sb.shape;
    // Every dimension's member is filled, as the solve-file parser does: the worked example
    // reads positions and velocities from b3 whatever the dimension.
    const double mass = scene.dimension == 1 ? sb.body1.mass : scene.dimension == 2 ? sb.body2.mass : sb.body3.mass;
    const bool is_static = sb.is_static();
    out.b1 = Body1{mass, is_static, s.x.x(), s.v.x()};
    out.b2.mass = mass;
    out.b2.is_static = is_static;
    out.b2.inertia = sb.body2.inertia;
    out.b2.angle = s.angle;
    out.b2.position = s.x.head<2>();
    out.b2.v = s.v.head<2>();
    out.b2.w = s.w.z();
    out.b3.mass = mass;
    out.b3.is_static = is_static;
    // A 2D body as a 3D one in the xy plane: an isotropic inertia equal to its moment.
    out.b3.inertia = scene.dimension == 3 ? sb.body3.inertia : Mat3(Mat3::Identity() * sb.body2.inertia);
    out.b3.orientation = s.q;
    out.b3.position = s.x;
    out.b3.v = s.v;
    out.b3.w = s.w;
    return out;
}

void place(CollisionInstant::Side* side, const Pose2& p) {
    side->x = lift(p.x);
    side->angle = p.angle;
    side->q = lift_angle(p.angle);
}
void place(CollisionInstant::Side* side, const Pose3& p) {
    side->x = p.x;
    side->q = p.q;
}

template <int D>
CollisionInstant instant(const Event<D>& e) {
    CollisionInstant c;
    static_cast<LiftedEvent&>(c) = lifted(e);
    c.before_a.v = lift(e.before_a.v);
    c.before_a.w = lift_spin(e.before_a.w);
    c.before_b.v = lift(e.before_b.v);
    c.before_b.w = lift_spin(e.before_b.w);
    c.va_after = lift(e.after_a.v);
    c.wa_after = lift_spin(e.after_a.w);
    c.vb_after = lift(e.after_b.v);
    c.wb_after = lift_spin(e.after_b.w);
    place(&c.before_a, e.pose_a);
    place(&c.before_b, e.pose_b);
    return c;
}

}  // namespace

CollisionInstant collision_instant(const Event1& e) {
    CollisionInstant c;
    c.t = e.t;
    c.a = e.a;
    c.b = e.b;
    c.point = lift_line(e.point);
    c.normal = Vec3::UnitX();  // a is the left block
    c.impulse = lift_line(e.impulse);
    c.before_a.v = lift_line(e.va_before);
    c.before_b.v = lift_line(e.vb_before);
    c.va_after = lift_line(e.va_after);
    c.vb_after = lift_line(e.vb_after);
    c.before_a.x = lift_line(e.xa);
    c.before_b.x = lift_line(e.xb);
    return c;
}
CollisionInstant collision_instant(const Event2& e) { return instant(e); }
CollisionInstant collision_instant(const Event3& e) { return instant(e); }

CollisionInstant with_roles(const CollisionInstant& c, std::size_t a, std::size_t b) {
    if (c.a != b || c.b != a) return c;
    CollisionInstant out = c;
    out.a = c.b;
    out.b = c.a;
    out.normal = -c.normal;
    out.impulse = -c.impulse;  // what the new b (the old a) received
    out.before_a = c.before_b;
    out.before_b = c.before_a;
    out.va_after = c.vb_after;
    out.wa_after = c.wb_after;
    out.vb_after = c.va_after;
    out.wb_after = c.wa_after;
    return out;
}

namespace {

// One body's kinetic energy with the scene's mass and inertia, at the pose and velocities of
// `s` (static bodies: 0).
double body_kinetic_energy(const Scene& scene, std::size_t i, const BodyState& s) {
    const SceneBody& sb = scene.bodies[i];
    if (scene.dimension == 1) {
        Body1 b = sb.body1;
        b.v = s.v.x();
        return totals(std::vector<Body1>{b}).kinetic_energy;
    }
    if (scene.dimension == 2) {
        Body2 b = sb.body2;
        b.angle = s.angle;
        b.v = s.v.head<2>();
        b.w = s.w.z();
        return totals(std::vector<Body2>{b}).kinetic_energy;
    }
    Body3 b = sb.body3;
    b.orientation = s.q;
    b.v = s.v;
    b.w = s.w;
    return totals(std::vector<Body3>{b}).kinetic_energy;
}

}  // namespace

InstantEnergy instant_kinetic_energy(const Scene& scene, const std::vector<CollisionInstant>& instant) {
    std::map<std::size_t, std::pair<BodyState, BodyState>> bodies;  // before the first, after the last
    for (const CollisionInstant& c : instant) {
        const auto meet = [&](std::size_t i, const BodyState& before, const Vec3& v, const Vec3& w) {
            auto it = bodies.find(i);
            if (it == bodies.end()) it = bodies.emplace(i, std::make_pair(before, before)).first;
            it->second.second.v = v;
            it->second.second.w = w;
        };
        meet(c.a, c.before_a, c.va_after, c.wa_after);
        meet(c.b, c.before_b, c.vb_after, c.wb_after);
    }
    InstantEnergy out;
    for (const auto& [i, states] : bodies) {
        out.before += body_kinetic_energy(scene, i, states.first);
        out.after += body_kinetic_energy(scene, i, states.second);
    }
    return out;
}

double pair_kinetic_energy(const Scene& scene, const CollisionInstant& c, bool after) {
    const InstantEnergy e = instant_kinetic_energy(scene, {c});
    return after ? e.after : e.before;
}

SolveProblem collision_problem(const Scene& scene, const CollisionInstant& c) {
    SolveProblem p;
    p.file = scene.title;
    char when[64];
    std::snprintf(when, sizeof when, "%.6g", c.t);
    p.title = scene.bodies[c.a].name + " and " + scene.bodies[c.b].name + " at t = " + when + " s";
    p.dimension = scene.dimension;
    p.model = scene.model;
    p.restitution_law = scene.restitution_law;
    p.restitution = scene.pair_restitution(c.a, c.b);
    p.friction = scene.pair_friction(c.a, c.b);
    p.normal = c.normal;  // 1D: +x, or -x when b is the left block
    p.point = c.point;
    p.about = Vec3::Zero();
    p.a = solve_body(scene, c.a, c.before_a);
    p.b = solve_body(scene, c.b, c.before_b);
    return p;
}

template <int D>
std::optional<PairCollision> find_pair_collision(const Recording<D>& rec, std::size_t a, std::size_t b, int order) {
    int seen = 0;
    for (std::size_t i = 0; i < rec.instants.size(); ++i) {
        const auto& in = rec.instants[i];
        std::size_t f = in.end, l = in.end;
        for (std::size_t k = in.first; k < in.end; ++k) {
            const auto& e = rec.events[k];
            if ((e.a == a && e.b == b) || (e.a == b && e.b == a)) {
                if (f == in.end) f = k;
                l = k + 1;
            }
        }
        if (f != in.end && ++seen == order) return PairCollision{i, f, l};
    }
    return std::nullopt;
}
template std::optional<PairCollision> find_pair_collision(const Recording<1>&, std::size_t, std::size_t, int);
template std::optional<PairCollision> find_pair_collision(const Recording<2>&, std::size_t, std::size_t, int);
template std::optional<PairCollision> find_pair_collision(const Recording<3>&, std::size_t, std::size_t, int);

std::string world_note(const Scene& scene, const CollisionInstant& c, const Vec3& formula_impulse) {
    const double scale = std::max({formula_impulse.norm(), c.impulse.norm(), 1e-300});
    if ((formula_impulse - c.impulse).norm() <= 1e-6 * scale || scene.model == Model::page_listing) return "";
    const int d = scene.dimension;
    const std::string P = d == 1 ? notation::num_text(c.impulse.x()) : notation::vec(c.impulse, d).txt;
    return "The world resolved several contact points here; its total impulse is P = " + P + " N\u00B7s";
}

Solution as_resolved(const SolveProblem& P, const Solution& alone, const CollisionInstant& c) {
    return with_outcome(P, alone, c.impulse, c.va_after, c.wa_after, c.vb_after, c.wb_after);
}

bool resolved_differs(const SolveProblem& problem, const Solution& alone, const Solution& run) {
    // The page's listing: its J is not what B receives (erratum 7, as its steps say); the
    // velocities are compared, as world_note leaves it alone.
    const bool listing = problem.model == Model::page_listing;
    const double scale =
        std::max({alone.P.norm(), run.P.norm(), alone.va.norm(), alone.vb.norm(), run.va.norm(), run.vb.norm(),
                  alone.wa.norm(), alone.wb.norm(), run.wa.norm(), run.wb.norm(), 1e-300});
    const double gap = std::max({listing ? 0.0 : (alone.P - run.P).norm(), (alone.va - run.va).norm(),
                                 (alone.wa - run.wa).norm(), (alone.vb - run.vb).norm(), (alone.wb - run.wb).norm()});
    return gap > 1e-6 * scale;
}

std::vector<ResultBeside> results_beside(const SolveProblem& P, const Solution& alone, const Solution& run) {
    const int d = P.dimension;
    const auto vec = [d](const Vec3& v) { return notation::vec(v, d).txt; };
    const auto spin = [d](const Vec3& w) { return d == 2 ? notation::num_text(w.z()) : notation::vec(w, 3).txt; };
    std::vector<ResultBeside> out;
    out.push_back({"impulse P on " + P.b.name, "N s", vec(alone.P), vec(run.P)});
    out.push_back({P.a.name + "’s velocity after", "m/s", vec(alone.va), vec(run.va)});
    if (d > 1) out.push_back({P.a.name + "’s spin after", "rad/s", spin(alone.wa), spin(run.wa)});
    out.push_back({P.b.name + "’s velocity after", "m/s", vec(alone.vb), vec(run.vb)});
    if (d > 1) out.push_back({P.b.name + "’s spin after", "rad/s", spin(alone.wb), spin(run.wb)});
    out.push_back(
        {"kinetic energy of the two after", "J", notation::num_text(alone.ke_after), notation::num_text(run.ke_after)});
    return out;
}

SimplifiedLabel simplified_label(const SolveProblem& P) {
    return {"A simplified calculation: " + P.a.name + " and " + P.b.name + " alone.",
            "In the run other contacts act at the same instant, and the world solves them together; the numbers of "
            "the run follow the calculation."};
}

}  // namespace collide
