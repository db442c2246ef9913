// The event loop (world.h; "Time of impact" in docs/stepping.md): each substep's start, every
// body's next impact predicted (time of impact: engine/toi.h) into a heap, and advance_to taking
// them in time order, pausing inside a substep where it is asked to stop.
#include "engine/world.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>

#include "engine/run_error.h"
#include "engine/toi.h"

namespace collide {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

}  // namespace

// ---- Prediction ----

template <int D>
double World<D>::predict_pair(std::size_t i, std::size_t j, double t, double t1) {
    // Neither moves (static or asleep): nothing can happen between them.
    if ((bodies_[i].is_static || islands_.asleep[i]) && (bodies_[j].is_static || islands_.asleep[j])) return kNever;
    if (same_weld(i, j)) return kNever;  // stuck together
    // Stepped bodies meet each other and static ones at their steps (see "Stepped islands").
    if (meet_at_steps(i, j)) return kNever;
    if (passed(i, j)) return kNever;  // let through each other by the page's listing
    if (t == loop_.stall_time && loop_.stalled.count(static_cast<std::uint64_t>(std::min(i, j)) << 32 | std::max(i, j)))
        return kNever;
    drift(i, t);
    drift(j, t);
    ++counters_.predictions;
    const std::size_t a = std::min(i, j), b = std::max(i, j);
    // Too far apart to meet within the substep: the gap between their bounding circles (or a
    // body's and a plane) exceeds what their relative motion can close by t1. (The circle about
    // a body's centre of mass holds it however it turns: spin does not move it.)
    if (welds_.of[a] < 0 && welds_.of[b] < 0 && !(shapes_.plane[a] && shapes_.plane[b])) {
        const double h = t1 - t;
        const std::size_t q = shapes_.plane[a] ? b : a;  // with a plane: the body that is not one
        const double closing =
            shapes_.plane[a] || shapes_.plane[b]
                ? bodies_[q].v.norm() * h + 0.5 * track_[q].a.norm() * h * h
                : (bodies_[b].v - bodies_[a].v).norm() * h + 0.5 * (track_[b].a - track_[a].a).norm() * h * h;
        if (apart(a, b, closing + 2.0 * kTouch)) return kNever;
    }
    const double v_rest = rest_speed(a, b);
    const Track& ka = track_[a];
    const Track& kb = track_[b];
    // A round body q against a plane or a round body p moving alike: closed forms.
    std::size_t p = a, q = b;
    if (!shapes_.round[q]) std::swap(p, q);
    const bool closed = shapes_.round[q] && (shapes_.plane[p] || (shapes_.round[p] && track_[p].a == track_[q].a)) &&
                        welds_.of[p] < 0 && welds_.of[q] < 0;  // (a welded body's centre circles)
    const Body& P = bodies_[p];
    const Body& Q = bodies_[q];
    const double gap = !closed ? 0.0
                       : shapes_.plane[p]
                           ? shapes_.of[p].normal.dot(Q.position) - shapes_.of[p].offset - shapes_.of[q].radius
                           : (Q.position - P.position).norm() - shapes_.of[p].radius - shapes_.of[q].radius;
    Manifold m;
    bool touching = false;
    if (!closed || gap <= kTouch) {
        m = manifold(a, b);
        touching = m.separation <= kTouch && m.count > 0;
    }
    if (touching) {
        bool slow = false;
        for (int k = 0; k < m.count; ++k) {
            const double un = normal_speed(a, b, m.points[k], m.normal);
            if (un < -v_rest) return t;  // approaching now: an impact at this instant
            slow = slow || std::abs(un) <= v_rest;
        }
        // A slow point rests: the pair belongs in an island (its forces), formed now if not yet
        // (stepped bodies have no islands: a free one touching them joins them).
        const bool steps = (steps_.stepped[a] || bodies_[a].is_static) && (steps_.stepped[b] || bodies_[b].is_static);
        if (slow && !same_island(a, b) && !steps) return t;
    }
    if (closed) {
        const double s = shapes_.plane[p] ? plane_contact_time(shapes_.of[p].normal, Q.v, track_[q].a, gap, touching)
                                          : round_contact_time(Vec(Q.position - P.position), Vec(Q.v - P.v),
                                                               shapes_.of[p].radius + shapes_.of[q].radius, touching);
        return t + s <= t1 ? t + s : kNever;
    }
    // Conservative advancement (engine/toi.h): copies of both bodies moved forward.
    Approach<Vec> c;
    c.t = t;
    c.horizon = t1 - t;
    c.touch = kTouch;
    c.v_rest = v_rest;
    c.radius_a = shapes_.radius[a];
    c.radius_b = shapes_.radius[b];
    c.touching = touching;
    c.acc_a = ka.a;
    c.acc_b = kb.a;
    // How fast a body's surface can turn towards the other: spin times reach; a welded body's
    // centre also circles its compound's, so its velocity changes by up to 2 |w| |d|.
    auto turning = [&](std::size_t k, const Track& tk) {
        if (welds_.of[k] < 0)
            return shapes_.round[k]
                       ? 0.0
                       : (spin_bound(bodies_[k], shapes_.inv_min_moment[k]) + magnitude(tk.alpha) * c.horizon) *
                             shapes_.radius[k];
        const Weld& w = welds_.all[welds_.of[k]];
        const auto at = std::find(w.members.begin(), w.members.end(), k) - w.members.begin();
        return spin_bound(w.body, w.inv_min_moment) * (2.0 * w.rel[at].x.norm() + shapes_.radius[k]);
    };
    c.turn_rate = turning(a, ka) + turning(b, kb);
    return advance_to_contact(
        shapes_.of[a], shapes_.of[b], mover(a), mover(b), [this](Mover* m, double dt) { step(m, dt); }, c);
}

template <int D>
void World<D>::predict(std::size_t i, double t) {
    if (bodies_[i].is_static) return;
    // A stepped body meets stepped and static ones at its steps (predict_pair says never).
    if (steps_.stepped[i] && !steps_.exact_bodies) return;
    double best = kNever;
    std::size_t partner = i;
    for_each_neighbour(i, t, [&](std::size_t j) {
        if (steps_.stepped[i] && (steps_.stepped[j] || bodies_[j].is_static)) return;
        const double tj = predict_pair(i, j, t, loop_.substep_end);
        if (tj < best) {
            best = tj;
            partner = j;
        }
    });
    if (best <= loop_.substep_end) {
        loop_.heap.push_back(Pending{best, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(partner),
                                     track_[i].version, track_[partner].version});
        std::push_heap(loop_.heap.begin(), loop_.heap.end(), std::greater<Pending>());
    }
}

// ---- Stepping ----

template <int D>
void World<D>::advance_to(double t_end, std::vector<Event<D>>* events, const ImpactHook& on_impact) {
    if (!(t_end >= loop_.time)) throw std::invalid_argument("advance_to: time runs forward only");
    std::vector<Event<D>> scratch;
    if (!events) events = &scratch;
    std::uint64_t handled = 0;
    for (;;) {
        if (!loop_.open) {
            if (!(loop_.time < t_end)) break;
            // Nothing awake: nothing moves and nothing can happen until t_end.
            bool awake = false;
            for (std::size_t i = 0; i < bodies_.size() && !awake; ++i)
                awake = !bodies_[i].is_static && !islands_.asleep[i];
            if (!awake) {
                loop_.time = t_end;
                for (std::size_t i = 0; i < bodies_.size(); ++i) track_[i].t = t_end;
                break;
            }
            begin_substep(events, on_impact);
        }
        // The substep's impacts up to t_end.
        const double stop = std::min(t_end, loop_.substep_end);
        while (!loop_.heap.empty() && !(loop_.heap.front().t > stop)) {
            std::pop_heap(loop_.heap.begin(), loop_.heap.end(), std::greater<Pending>());
            const Pending p = loop_.heap.back();
            loop_.heap.pop_back();
            if (p.t > loop_.now) {
                loop_.now = p.t;
                loop_.pops_at_now = 0;
            }
            // Never hang: an instant that keeps producing work without time moving on is a
            // failure to report (see "Known limits" in docs/stepping.md).
            if (++loop_.pops_at_now > kMaxWorkPerInstant)
                throw std::runtime_error("the simulation is stuck at t = " + std::to_string(loop_.now) + " s between " +
                                         scene_.bodies[p.i].name + " and " + scene_.bodies[p.j].name +
                                         " (a known limit of resting contact, see engine/world.h)");
            const bool valid_i = track_[p.i].version == p.vi;
            const bool valid_j = track_[p.j].version == p.vj;
            if (!valid_i) continue;  // i predicted again when it changed
            if (!valid_j) {
                predict(p.i, loop_.now);
                continue;
            }
            if (loop_.now > loop_.stall_time) {
                loop_.stall_time = loop_.now;
                loop_.stalls.clear();
                loop_.stalled.clear();
            }
            if (++handled > kMaxEventsPerAdvance)
                throw std::runtime_error("more than " + std::to_string(kMaxEventsPerAdvance) +
                                         " collisions before t = " + std::to_string(t_end) +
                                         " s: the scene does not settle");
            // A pair predicted to meet now whose instant has no impact (nothing approaches: the
            // prediction saw a contact the contact manifold does not) more than 8 times is left
            // to the next substep's contact search instead of being predicted again and again.
            // (Round-off impulses of resting neighbours do not count as progress.)
            const std::size_t recorded = events->size();
            if (!resolve(p.i, p.j, loop_.now, events)) {
                const std::uint64_t key = static_cast<std::uint64_t>(std::min(p.i, p.j)) << 32 | std::max(p.i, p.j);
                if (++loop_.stalls[key] > 8) loop_.stalled.insert(key);
            }
            if (on_impact && events->size() > recorded) on_impact(loop_.now);
        }
        if (t_end < loop_.substep_end) {
            // Paused inside the substep: every body at t_end along its motion, the world's own
            // state untouched (the next advance goes on from here).
            loop_.time = t_end;
            loop_.bodies_now = bodies_at(t_end);
            check_finite(loop_.bodies_now, t_end);
            break;
        }
        for (std::size_t i = 0; i < bodies_.size(); ++i) drift(i, loop_.substep_end);
        check_finite(bodies_, loop_.substep_end);
        loop_.time = loop_.substep_end;
        loop_.open = false;
        loop_.heap.clear();
    }
}

// A state that is no longer finite (an overflow, an infinite impulse) never leaves the world
// as if it were one: it is caught at the end of the substep that made it.
template <int D>
void World<D>::check_finite(const std::vector<Body>& bodies, double t) const {
    for (std::size_t i = 0; i < bodies.size(); ++i)
        if (!bodies[i].state_finite())
            throw RunError(run_source(scene_.file) + "the state of '" + scene_.bodies[i].name +
                           "' is no longer finite by t = " + run_number(t) +
                           " s (a number overflowed: the scene's speeds, spins or sizes are beyond what the run "
                           "can follow)");
}

template <int D>
void World<D>::begin_substep(std::vector<Event<D>>* events, const ImpactHook& on_impact) {
    const double t0 = loop_.time;
    // Substep: free motion's (free_substep()), at most kRestStep while anything rests or falls.
    // Chosen from the bodies alone, never from where an advance stops.
    double h = free_substep();
    bool any_rest = false, any_stepped = false;
    std::size_t moving = 0;
    steps_.exact_bodies = false;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_[i].is_static) continue;
        steps_.exact_bodies = steps_.exact_bodies || !steps_.stepped[i];
        any_rest = any_rest || (islands_.of[i] != 0 && !islands_.asleep[i]);
        any_stepped = any_stepped || (steps_.stepped[i] && !islands_.asleep[i]);
        ++moving;
    }
    // Stepped islands: a substep never crosses a step's end; at a step's start they are solved.
    bool step_now = false;
    if (any_stepped) {
        step_now = !(steps_.end - t0 > 1e-9 * kIslandStep);
        h = std::min(h, step_now ? kIslandStep : steps_.end - t0);
        if (any_rest) h = std::min(h, kRestStep);
    } else if (any_rest || gravity().norm() > 0.0) {
        h = std::min(h, kRestStep);
    }
    work_.body_substeps += moving;
    if (work_done() > work_budget()) refuse_work(t0);
    const double t1 = t0 + h;
    loop_.substep_end = t1;
    loop_.open = true;
    loop_.now = t0;
    loop_.pops_at_now = 0;
    ++counters_.substeps;

    build_grid(t0, t1);
    loop_.heap.clear();
    // Resting contacts are found afresh each substep; then every body predicts its next impact.
    // Sleeping islands keep their (zero) motion and are neither re-solved nor predicted.
    std::vector<std::size_t> all;
    for (std::size_t i = 0; i < bodies_.size(); ++i)
        if (!bodies_[i].is_static && !islands_.asleep[i] && !steps_.stepped[i] &&
            (islands_.of[i] != 0 || gravity().norm() > 0.0))
            all.push_back(i);
    for (auto it = islands_.members.begin(); it != islands_.members.end();)
        it = islands_.asleep[it->second.front()] ? std::next(it) : islands_.members.erase(it);
    for (std::size_t i : all) set_free(i);
    if (!all.empty()) settle(all, t0);
    // Then the stepped islands' step, if one starts now (or settling brought bodies to them).
    if (step_now || steps_.restep) {
        const std::size_t recorded = events->size();
        step_islands(t0, events, !step_now);
        if (on_impact && events->size() > recorded) on_impact(t0);
    }
    std::unordered_set<std::size_t> predicted(all.begin(), all.end());
    for (std::size_t i = 0; i < bodies_.size(); ++i)
        if (!islands_.asleep[i] && !predicted.count(i)) predict(i, t0);
}

// The members defined here, for World<2> and World<3>.
#define COLLIDE_INSTANTIATE_ADVANCE(D)                                                                                 \
    template double World<D>::predict_pair(std::size_t, std::size_t, double, double);                                  \
    template void World<D>::predict(std::size_t, double);                                                              \
    template void World<D>::check_finite(const std::vector<Body>&, double) const;                                      \
    template void World<D>::advance_to(double, std::vector<Event<D>>*, const ImpactHook&);                             \
    template void World<D>::begin_substep(std::vector<Event<D>>*, const ImpactHook&);
COLLIDE_INSTANTIATE_ADVANCE(2)
COLLIDE_INSTANTIATE_ADVANCE(3)
#undef COLLIDE_INSTANTIATE_ADVANCE

}  // namespace collide
