// The world (world.h): construction, motion between events, the narrow phase, the contacts of
// an instant and their resolution. Its parts live in files of their own: the event loop and
// prediction (advance.cpp), time of impact (toi.h), broad phase (broad_phase.h), contact solver
// (contact_solver.h), welds (weld.cpp), islands and sleeping (islands.cpp) and stepped islands
// (stepped.cpp, island_step.h).
#include "engine/world.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "engine/respond.h"
#include "engine/rotation.h"
#include "engine/run_error.h"
#include "engine/toi.h"

namespace collide {

namespace {

// ---- What differs between 2D and 3D, as overloads ----

const Body2& scene_body(const SceneBody& b, const Body2*) { return b.body2; }
const Body3& scene_body(const SceneBody& b, const Body3*) { return b.body3; }
const Shape2& scene_shape(const SceneBody& b, const Shape2*) { return b.shape2; }
const Shape3& scene_shape(const SceneBody& b, const Shape3*) { return b.shape3; }

bool is_round(const Shape2& s) { return s.kind == Shape2::Kind::disc; }
bool is_round(const Shape3& s) { return s.kind == Shape3::Kind::sphere; }
bool is_plane(const Shape2& s) { return s.kind == Shape2::Kind::half_plane; }
bool is_plane(const Shape3& s) { return s.kind == Shape3::Kind::half_space; }
bool turn_integrated(const Body2&) { return false; }  // a 2D turn is w t: exact
bool turn_integrated(const Body3& b) { return rotation_integrated(b); }

// Turning for dt seconds with a constant angular acceleration alpha (resting forces; 0 when
// free); returns the rotation steps taken (3D), refusing (RunError) a turn of more than
// `limit` steps before taking any.
std::uint64_t turn(Body2* b, double dt, double alpha, std::uint64_t) {
    b->angle += b->w * dt + 0.5 * alpha * dt * dt;
    b->w += alpha * dt;
    return 0;
}
[[noreturn]] void refuse_turn(double steps, double dt) {
    throw RunError("a turn of " + run_number(steps) + " rotation steps in " + run_number(dt) +
                   " s, more than the run's work budget has left");
}
std::uint64_t turn(Body3* b, double dt, const Vec3& alpha, std::uint64_t limit) {
    if (alpha.isZero(0.0)) {
        return rotate_free(b, dt, {}, limit);  // torque-free: L kept, gyroscopic term included
    }
    // Under the (small, constant) torque of resting forces: w(t) = w + alpha t, the orientation
    // turned by the midpoint spin of short steps.
    const double turned = (b->w.norm() + alpha.norm() * dt) * dt;
    const double steps = std::max(1.0, std::ceil(turned / 0.005));  // (as in rotate_free: no int)
    if (!(steps <= static_cast<double>(limit))) refuse_turn(steps, dt);
    const auto n = static_cast<std::uint64_t>(steps);
    const double h = dt / steps;
    for (std::uint64_t k = 0; k < n; ++k) {
        const Vec3 phi = (b->w + alpha * ((k + 0.5) * h)) * h;
        if (phi.squaredNorm() > 0.0) b->orientation = (exp_map(phi) * b->orientation).normalized();
    }
    b->w += alpha * dt;
    return n;
}

// The gap between two bodies' bounding circles (spheres), or between one's and a plane (m): no
// closer than their surfaces. (The circle about a centre of mass holds the body however it
// turns.) Not for two planes.
template <class Body, class Shapes>  // Shapes: World<D>::Shapes
double bounding_gap(const std::vector<Body>& bodies, const Shapes& shapes, std::size_t a, std::size_t b) {
    if (shapes.plane[a] || shapes.plane[b]) {
        const std::size_t p = shapes.plane[a] ? a : b, q = shapes.plane[a] ? b : a;
        return shapes.of[p].normal.dot(bodies[q].position) - shapes.of[p].offset - shapes.radius[q];
    }
    return (bodies[b].position - bodies[a].position).norm() - shapes.radius[a] - shapes.radius[b];
}

}  // namespace

// ---- Construction and motion ----

template <int D>
World<D>::World(const Scene& scene) : scene_(scene) {
    if (scene.dimension != D)
        throw std::invalid_argument("World<" + std::to_string(D) + "> needs a " + std::to_string(D) + "D scene");
    if (scene.model == Model::page_listing && (D != 3 || scene.policy != Policy::sequential))
        throw std::invalid_argument(
            "the page's listing (model page-listing) is 3D code resolving one point at "
            "a time: it runs only in 3D scenes with policy sequential");
    const std::size_t n = scene.bodies.size();
    for (const SceneBody& sb : scene.bodies) {
        bodies_.push_back(scene_body(sb, static_cast<const Body*>(nullptr)));
        shapes_.of.push_back(scene_shape(sb, static_cast<const Shape*>(nullptr)));
    }
    for (std::size_t i = 0; i < n; ++i) {
        shapes_.plane.push_back(is_plane(shapes_.of[i]));
        shapes_.round.push_back(is_round(shapes_.of[i]));
        shapes_.radius.push_back(shapes_.plane[i] ? 0.0 : bounding_radius(shapes_.of[i]));
        shapes_.inv_min_moment.push_back(inverse_smallest_moment(bodies_[i]));
    }
    grid_ = BroadPhase<D>(shapes_.plane);
    solver_ = ContactSolver<D>(shapes_.round);
    track_.resize(n);
    welds_.of.assign(n, -1);
    islands_.of.assign(n, 0);
    islands_.asleep.assign(n, 0);
    scratch_.mark.assign(n, 0);
    scratch_.searched.assign(n, 0);
    scratch_.parent.assign(n, 0);
    scratch_.before.resize(n);
    steps_.stepped.assign(n, 0);
    steps_.solved.assign(n, 0);
    steps_.until.assign(n, 0.0);
    steps_.still.assign(n, 0.0);
    // The resting speeds (see "Resting contact" in docs/stepping.md).
    const double g = gravity().norm();
    narrow_.rest_smooth = 0.5 * kZenoTime * g;
    narrow_.rest_cornered = std::max(narrow_.rest_smooth, std::sqrt(4.0 * g * kTouch));
    for (std::size_t i = 0; i < n; ++i) set_free(i);
    estimate_ = estimate_work();
    if (estimate_ > static_cast<double>(work_budget()))
        throw RunError(run_source(scene.file) + "the scene would take about " + run_number(estimate_, 3) +
                       " units of work (" + run_duration(estimate_) + ") to run its " + run_number(scene.duration) +
                       " s, more than its budget of " + run_number(scene.work_budget) +
                       " (--max-work raises it; see docs/stepping.md, \"Work budget\")");
}

template <int D>
typename World<D>::Vec World<D>::gravity() const {
    return scene_.gravity.template head<D>();
}

template <int D>
void World<D>::set_free(std::size_t i) {
    Track& k = track_[i];
    k.a = bodies_[i].is_static ? zero<Vec>() : gravity();
    k.alpha = zero<Spin>();
    ++k.version;
    islands_.of[i] = 0;
    islands_.asleep[i] = 0;
}

template <int D>
bool World<D>::turns_in_steps(std::size_t i) const {
    if (bodies_[i].is_static || islands_.asleep[i]) return false;
    return turn_integrated(welds_.of[i] >= 0 ? welds_.all[welds_.of[i]].body : bodies_[i]);
}

template <int D>
double World<D>::free_substep() const {
    double h = kLongestSubstep, speed = 0.0, size = 0.0;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_[i].is_static) continue;
        speed += bodies_[i].v.norm() + track_[i].a.norm() * kSpeedSpan;
        size += shapes_.radius[i];
        if (turns_in_steps(i)) {
            const bool welded = welds_.of[i] >= 0;
            const double spin = welded
                                    ? spin_bound(welds_.all[welds_.of[i]].body, welds_.all[welds_.of[i]].inv_min_moment)
                                    : spin_bound(bodies_[i], shapes_.inv_min_moment[i]);
            h = std::min(h, std::max(kRestStep, kTurnPerSubstep / spin));
        }
    }
    if (speed > 0.0) h = std::min(h, 4.0 * size / speed);
    return std::max(kShortestSubstep, h);
}

template <int D>
void World<D>::move(Body* b, const Track& k, double dt) const {
    if (b->is_static || dt == 0.0) return;
    b->position += b->v * dt + 0.5 * dt * dt * k.a;
    b->v += k.a * dt;
    const std::uint64_t spent = work_done(), budget = work_budget();
    try {
        work_.rotation_steps += turn(b, dt, k.alpha, spent < budget ? budget - spent : 0);
    } catch (const RunError& e) {  // named as every other refusal of the run
        throw RunError(run_source(scene_.file) + e.what() +
                       " (--max-work raises it; see docs/stepping.md, \"Work budget\")");
    }
}

template <int D>
void World<D>::drift(std::size_t i, double t) {
    Track& k = track_[i];
    if (t <= k.t) return;
    if (welds_.of[i] >= 0) {
        weld_to(&welds_.all[welds_.of[i]], t);
        place(i);
    } else if (!islands_.asleep[i]) {
        move(&bodies_[i], k, t - k.t);  // asleep: it does not move at all
    }
    k.t = t;
}

template <int D>
std::vector<typename World<D>::Body> World<D>::bodies_at(double t) const {
    // What drift() would do to each body, on copies.
    std::vector<Body> out = bodies_;
    for (std::size_t i = 0; i < out.size(); ++i) {
        const Track& k = track_[i];
        if (t <= k.t) continue;
        if (welds_.of[i] >= 0) {
            Weld w = welds_.all[welds_.of[i]];
            weld_to(&w, t);
            const auto at = std::find(w.members.begin(), w.members.end(), i) - w.members.begin();
            place_on(w.body, w.rel[at], &out[i]);
        } else if (!islands_.asleep[i]) {
            move(&out[i], k, t - k.t);
        }
    }
    return out;
}

template <int D>
typename World<D>::Mover World<D>::mover(std::size_t i) const {
    Mover m;
    m.i = i;
    m.body = bodies_[i];
    if (welds_.of[i] >= 0) m.compound = welds_.all[welds_.of[i]].body;
    return m;
}

template <int D>
void World<D>::step(Mover* m, double dt) const {
    if (welds_.of[m->i] < 0) {
        move(&m->body, track_[m->i], dt);
        return;
    }
    const Weld& w = welds_.all[welds_.of[m->i]];
    Track free;
    free.a = gravity();
    free.alpha = zero<Spin>();
    move(&m->compound, free, dt);
    const auto at = std::find(w.members.begin(), w.members.end(), m->i) - w.members.begin();
    place_on(m->compound, w.rel[at], &m->body);
}

// ---- The page's listing: pairs let through ----

template <int D>
bool World<D>::passed(std::size_t i, std::size_t j) const {
    return !narrow_.passed.empty() &&
           narrow_.passed.count(static_cast<std::uint64_t>(std::min(i, j)) << 32 | std::max(i, j));
}

// ---- A body set from outside ----

template <int D>
void World<D>::set_body(std::size_t i, const Body& body) {
    for (std::size_t j = 0; j < bodies_.size(); ++j) drift(j, loop_.time);
    unweld(i);  // its new state is its own
    steps_.stepped[i] = 0;
    steps_.solved[i] = 0;
    bodies_[i] = body;
    track_[i].t = loop_.time;
    // Whatever rested on or under it is re-examined at the start of the next substep.
    for (std::size_t j = 0; j < bodies_.size(); ++j)
        if (islands_.of[j] != 0 || j == i) set_free(j);
    loop_.heap.clear();
    loop_.open = false;  // a new substep starts here
}

// ---- Broad phase (engine/broad_phase.h): each body's swept box ----

template <int D>
void World<D>::swept_box(std::size_t i, double t0, double t1, Vec* lo, Vec* hi) const {
    // A welded body stays within its reach of its compound's centre.
    const bool welded = welds_.of[i] >= 0;
    const Weld* w = welded ? &welds_.all[welds_.of[i]] : nullptr;
    const Body& b = welded ? w->body : bodies_[i];
    const Vec acc = welded ? gravity() : track_[i].a;
    const double clock = welded ? w->t : track_[i].t;
    const double s0 = t0 - clock, s1 = t1 - clock;
    double margin = shapes_.radius[i] + kTouch;
    if (welded) {
        const auto at = std::find(w->members.begin(), w->members.end(), i) - w->members.begin();
        margin = w->reach[at] + kTouch;
    }
    BroadPhase<D>::swept_box(b.position, b.v, acc, s0, s1, margin, lo, hi);
}

template <int D>
void World<D>::insert(std::size_t i, double t0, double t1) {
    Vec lo, hi;
    swept_box(i, t0, t1, &lo, &hi);
    grid_.insert(i, lo, hi);
}

template <int D>
void World<D>::build_grid(double t0, double t1) {
    std::vector<std::array<Vec, 2>> moving;  // the moving bodies' swept boxes size the cells
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_[i].is_static) continue;
        Vec a, b;
        swept_box(i, t0, t1, &a, &b);
        // A box beyond the doubles (a body about to overflow them) would size a grid without
        // end: the run stops here, as at a state that is no longer finite (check_finite).
        if (!a.allFinite() || !b.allFinite())
            throw RunError(run_source(scene_.file) + "'" + scene_.bodies[i].name +
                           "' moves beyond the range of numbers after t = " + run_number(t0) +
                           " s (the scene's speeds or distances are beyond what the run can follow)");
        moving.push_back({a, b});
    }
    grid_.build(moving);
    for (std::size_t i = 0; i < bodies_.size(); ++i)
        if (!shapes_.plane[i]) insert(i, t0, t1);
}

// ---- Narrow phase ----

template <int D>
typename World<D>::Manifold World<D>::manifold(std::size_t a, std::size_t b) const {
    return collide(shapes_.of[a], pose_of(bodies_[a]), shapes_.of[b], pose_of(bodies_[b]), kTouch);
}

template <int D>
bool World<D>::apart(std::size_t a, std::size_t b, double gap) const {
    return !(shapes_.plane[a] && shapes_.plane[b]) && bounding_gap(bodies_, shapes_, a, b) > gap;
}

template <int D>
double World<D>::normal_speed(std::size_t a, std::size_t b, const Vec& p, const Vec& n) const {
    const Body& A = bodies_[a];
    const Body& B = bodies_[b];
    const Vec u = (B.v + spin_cross(B.w, p - B.position)) - (A.v + spin_cross(A.w, p - A.position));
    return u.dot(n);
}

template <int D>
double World<D>::rest_speed(std::size_t i, std::size_t j) const {
    const bool smooth = (shapes_.round[i] || shapes_.plane[i]) && (shapes_.round[j] || shapes_.plane[j]);
    // Round-off: a normal speed below 1e-12 of the pair's own speeds is no approach. (Without
    // gravity the resting speeds are zero, and a contact left at u_n = 0 by e = 0 or by a
    // sticking impulse would otherwise be answered again and again for its -1e-18 m/s.)
    const Body& A = bodies_[i];
    const Body& B = bodies_[j];
    const double scale =
        A.v.norm() + B.v.norm() + magnitude(A.w) * shapes_.radius[i] + magnitude(B.w) * shapes_.radius[j];
    return std::max(smooth ? narrow_.rest_smooth : narrow_.rest_cornered, 1e-12 * scale);
}

// The tangential limit of the points of a group or an island, as PointGoal::mu: coulomb the
// pair's mu, matrix and stick unlimited (they hold the tangential velocity), frictionless 0.
template <int D>
double World<D>::friction_limit(std::size_t a, std::size_t b) const {
    switch (scene_.model) {
        case Model::coulomb:
        case Model::routh: return scene_.pair_friction(a, b);
        case Model::matrix:
        case Model::stick: return -1.0;
        default: return 0.0;
    }
}

// ---- Contacts at one instant ----

// Every touching pair of body i at time t, appended to out. Within one search (begin_search)
// a pair is reported once: from whichever of its bodies is searched first (a plane searches
// only planes, so its pairs are always reported from the other side).
template <int D>
void World<D>::contacts_of(std::size_t i, double t, std::vector<Contact>* out) {
    drift(i, t);
    scratch_.searched[i] = scratch_.search;
    for_each_neighbour(i, t, [&](std::size_t j) {
        if (bodies_[i].is_static && bodies_[j].is_static) return;
        if (scratch_.searched[j] == scratch_.search && !shapes_.plane[j]) return;  // reported from j's side
        if (same_weld(i, j) || passed(i, j)) return;                               // stuck together, or let through
        // Stepped bodies touch each other and static ones at their steps, not at instants.
        if (meet_at_steps(i, j)) return;
        drift(j, t);
        const std::size_t a = std::min(i, j), b = std::max(i, j);
        if (welds_.of[a] < 0 && welds_.of[b] < 0 && apart(a, b, 2.0 * kTouch))
            return;  // their bounding circles (spheres) apart: not touching
        const Manifold m = manifold(a, b);
        if (m.separation > kTouch || m.count == 0) return;
        Contact c;
        c.a = a;
        c.b = b;
        c.m = m;
        out->push_back(c);
    });
}

// A fresh stamp for per-body marks (stamp vectors are cleared when the counter wraps).
template <int D>
std::uint32_t World<D>::fresh(std::vector<std::uint32_t>* marks, std::uint32_t* counter) {
    if (++*counter == 0) {
        std::fill(marks->begin(), marks->end(), 0);
        *counter = 1;
    }
    return *counter;
}

template <int D>
bool World<D>::resolve_point(Contact* c, int k) {
    const Vec& p = c->m.points[k];
    const Vec& n = c->m.normal;
    if (passed(c->a, c->b)) return false;  // the page's listing has answered this pair
    if (!(normal_speed(c->a, c->b, p, n) < -rest_speed(c->a, c->b))) return false;
    // A welded body answers with its compound's mass and inertia. (Round: see below; the stick
    // model's couple turns a round body too, so there its spin is the model's.)
    Body& A = *mobile(c->a);
    Body& B = *mobile(c->b);
    const bool plain = scene_.model != Model::stick && scene_.model != Model::page_listing;
    const bool round_a = plain && shapes_.round[c->a] && welds_.of[c->a] < 0;
    const bool round_b = plain && shapes_.round[c->b] && welds_.of[c->b] < 0;
    auto ia = at_contact(A, p), ib = at_contact(B, p);
    // A round body's surface normal passes through its centre: r is along n exactly (the
    // computed point is off by round-off, which would give a frictionless hit a spin of 1e-14).
    if (round_a) ia.r = ia.r.dot(n) * n;
    if (round_b) ib.r = ib.r.dot(n) * n;
    const double e = scene_.pair_restitution(c->a, c->b);
    const auto r = respond(scene_.model, ia, ib, n, e, scene_.pair_friction(c->a, c->b), scene_.restitution_law);
    if (r.separating) return false;
    if (scene_.model == Model::page_listing)  // one answer per pair: its J may push them together
        narrow_.passed.insert(static_cast<std::uint64_t>(c->a) << 32 | c->b);
    // Only the tangential part of P turns a round body (its normal part passes through the
    // centre); computed so, a frictionless hit leaves w exactly as it was.
    const Vec Pt = scene_.model == Model::frictionless ? zero<Vec>() : Vec(r.P - r.P.dot(n) * n);
    if (!A.is_static) {
        A.v = r.va;
        A.w = round_a ? Spin(A.w - ia.inv_I * lever(ia.r, Pt)) : r.wa;
    }
    if (!B.is_static) {
        B.v = r.vb;
        B.w = round_b ? Spin(B.w + ib.inv_I * lever(ib.r, Pt)) : r.wb;
    }
    moved(c->a);
    moved(c->b);
    c->impulse += r.P;
    c->approximate = c->approximate || r.approximate;
    c->weight += std::max(0.0, r.P.dot(n));
    c->moment += std::max(0.0, r.P.dot(n)) * p;
    return true;
}

// The contact solver (engine/contact_solver.h) on the points of `contacts`. A welded body's
// rows would need its compound's mass and inertia: not modelled (see "Known limits").
template <int D>
void World<D>::solve_points(std::vector<Contact>* contacts, const std::vector<PointGoal>& goals,
                            std::vector<Body>* state) {
    for (const Contact& c : *contacts)
        for (std::size_t k : {c.a, c.b})
            if (welds_.of[k] >= 0)
                throw std::runtime_error(scene_.bodies[k].name +
                                         ", stuck to another body by the stick model, is in resting or "
                                         "simultaneous contact with " +
                                         scene_.bodies[k == c.a ? c.b : c.a].name +
                                         ": not modelled (see \"Stuck bodies\" in engine/world.h)");
    solver_.solve(contacts, goals, state);
}

template <int D>
void World<D>::resolve_simultaneous(std::vector<Contact>* contacts) {
    int points = 0;
    for (const Contact& c : *contacts) points += c.m.count;
    if (points == 1) {  // one point: the model's own formula
        for (Contact& c : *contacts)
            if (c.m.count == 1) resolve_point(&c, 0);
        return;
    }
    std::vector<PointGoal> goals;
    for (const Contact& c : *contacts) {
        const double e = scene_.model == Model::stick ? 0.0 : scene_.pair_restitution(c.a, c.b);
        const double v_rest = rest_speed(c.a, c.b);
        for (int k = 0; k < c.m.count; ++k) {
            const Body& A = bodies_[c.a];
            const Body& B = bodies_[c.b];
            const Vec& p = c.m.points[k];
            const Vec u = (B.v + spin_cross(B.w, p - B.position)) - (A.v + spin_cross(A.w, p - A.position));
            const double un = u.dot(c.m.normal);
            PointGoal goal;
            goal.un = un < -v_rest ? -e * un : 0.0;
            goal.mu = friction_limit(c.a, c.b);
            if (scene_.model == Model::matrix) goal.ut = -e * (u - un * c.m.normal);
            goals.push_back(goal);
        }
    }
    solve_points(contacts, goals, &bodies_);
}

template <int D>
bool World<D>::resolve(std::size_t i, std::size_t j, double t, std::vector<Event<D>>* events) {
    bool impact = false;  // some touching point approached faster than the resting speed
    std::vector<Contact> contacts;
    std::vector<std::size_t> group;  // dynamic bodies reached, in discovery order
    const std::uint32_t reached = fresh(&scratch_.mark, &scratch_.mark_id);
    fresh(&scratch_.searched, &scratch_.search);
    auto reach = [&](std::size_t k) {
        if (bodies_[k].is_static || scratch_.mark[k] == reached) return false;
        if (steps_.stepped[k]) {  // it answers with its own mass; its other contacts act at its next step
            scratch_.mark[k] = reached;
            drift(k, t);
            scratch_.before[k] = {bodies_[k].v, bodies_[k].w};
            group.push_back(k);
            return false;
        }
        // A welded body brings its weld: an impulse on it moves them all.
        const std::vector<std::size_t> alone{k};
        for (std::size_t m : welds_.of[k] >= 0 ? welds_.all[welds_.of[k]].members : alone) {
            scratch_.mark[m] = reached;
            drift(m, t);
            scratch_.before[m] = {bodies_[m].v, bodies_[m].w};
            group.push_back(m);
        }
        return true;
    };
    for (std::size_t k : {i, j}) reach(k);
    for (std::size_t k : {i, j}) contacts_of(k, t, &contacts);
    auto by_pair = [](const Contact& x, const Contact& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; };

    if (scene_.policy == Policy::simultaneous) {
        // The whole touching group: follow contacts through every dynamic body reached.
        for (std::size_t q = 0; q < contacts.size(); ++q)
            for (std::size_t k : {contacts[q].a, contacts[q].b})
                if (reach(k)) contacts_of(k, t, &contacts);
        std::sort(contacts.begin(), contacts.end(), by_pair);
        for (const Contact& c : contacts)
            for (int k = 0; k < c.m.count; ++k)
                impact = impact || normal_speed(c.a, c.b, c.m.points[k], c.m.normal) < -rest_speed(c.a, c.b);
        resolve_simultaneous(&contacts);
    } else {
        const std::size_t max_passes = 64 * std::max<std::size_t>(1, bodies_.size());
        bool settled = false;
        for (std::size_t pass = 0; pass < max_passes && !settled; ++pass) {
            std::sort(contacts.begin(), contacts.end(), by_pair);
            settled = true;
            const std::size_t count = contacts.size();
            for (std::size_t q = 0; q < count; ++q)
                for (int k = 0; k < contacts[q].m.count; ++k) {
                    if (!resolve_point(&contacts[q], k)) continue;
                    settled = false;
                    impact = true;
                    for (std::size_t body : {contacts[q].a, contacts[q].b})
                        if (reach(body)) contacts_of(body, t, &contacts);
                }
        }
        if (!settled) {
            std::sort(contacts.begin(), contacts.end(), by_pair);
            resolve_simultaneous(&contacts);
        }
    }

    // Stepped islands: a pair colliding again and again, and whatever a stepped body touched,
    // are stepped from now on (see "Stepped islands" in docs/stepping.md).
    for (const Contact& c : contacts) {
        if (!(c.weight > 0.0) && c.impulse.norm() == 0.0) continue;
        count_impact(c.a, c.b, t);
        if (steps_.stepped[c.a] || steps_.stepped[c.b] || scene_.stepping == StepMode::always)
            for (std::size_t k : {c.a, c.b}) join(k, t);
    }

    // The stick model welds what it stuck (see "Stuck bodies" in docs/stepping.md).
    if (scene_.model == Model::stick)
        for (const Contact& c : contacts)
            if (c.weight > 0.0 && !bodies_[c.a].is_static && !bodies_[c.b].is_static && !same_weld(c.a, c.b))
                weld(c.a, c.b, t);

    for (const Contact& c : contacts) {
        if (!(c.weight > 0.0) && c.impulse.norm() == 0.0) continue;
        auto vel = [&](std::size_t k) { return typename Event<D>::Velocity{bodies_[k].v, bodies_[k].w}; };
        record(c.a, c.b, t, c.m.normal, c.impulse, c.weight > 0.0 ? Vec(c.moment / c.weight) : c.m.points[0],
               scratch_.mark[c.a] == reached ? scratch_.before[c.a] : vel(c.a),
               scratch_.mark[c.b] == reached ? scratch_.before[c.b] : vel(c.b), events);
        events->back().approximate = c.approximate;
    }
    settle(group, t);  // (stepped bodies are left out)
    for (std::size_t k : group) {
        if (!steps_.stepped[k]) continue;
        if (bodies_[k].v != scratch_.before[k].v || bodies_[k].w != scratch_.before[k].w) {
            wake(k);
            steps_.restep = true;  // pushed: its island is stepped again from now
            steps_.reseed.push_back(k);
        }
    }
    if (steps_.restep) step_islands(t, events, true);
    return impact;
}

template <int D>
void World<D>::record(std::size_t a, std::size_t b, double t, const Vec& normal, const Vec& impulse, const Vec& point,
                      const typename Event<D>::Velocity& before_a, const typename Event<D>::Velocity& before_b,
                      std::vector<Event<D>>* events) {
    Event<D> ev;
    ev.t = t;
    ev.a = a;
    ev.b = b;
    ev.normal = normal;
    ev.impulse = impulse;
    ev.point = point;
    ev.before_a = before_a;
    ev.before_b = before_b;
    ev.after_a = {bodies_[a].v, bodies_[a].w};
    ev.after_b = {bodies_[b].v, bodies_[b].w};
    ev.pose_a = pose_of(bodies_[a]);
    ev.pose_b = pose_of(bodies_[b]);
    events->push_back(ev);
    ++counters_.events;
}

template class World<2>;
template class World<3>;

}  // namespace collide
