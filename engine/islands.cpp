// Islands and sleeping ("Resting contact" and "Sleeping islands" in docs/stepping.md): after an
// instant, the bodies held by resting contacts are grouped into islands (union-find over the
// contacts), each island's constant contact forces for the rest of the substep are found by
// the contact solver, and an island that has come to rest falls asleep.
#include "engine/world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

namespace collide {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

}  // namespace

template <int D>
bool World<D>::same_island(std::size_t i, std::size_t j) const {
    const std::uint32_t a = bodies_[i].is_static ? 0 : islands_.of[i];
    const std::uint32_t b = bodies_[j].is_static ? 0 : islands_.of[j];
    if (bodies_[i].is_static) return b != 0;
    if (bodies_[j].is_static) return a != 0;
    return a != 0 && a == b;
}

// After an instant: the bodies reached (and the islands they belonged to) get new motions:
// those held by resting contacts form islands with constant contact forces, the rest are free.
template <int D>
void World<D>::settle(const std::vector<std::size_t>& reached, double t) {
    std::vector<std::size_t> bodies;
    const std::uint32_t in = fresh(&scratch_.mark, &scratch_.mark_id);
    fresh(&scratch_.searched, &scratch_.search);
    // A body brings the other members of the island it was in: their forces change too.
    std::vector<std::size_t> stack;
    auto add = [&](std::size_t first) {
        stack.assign(1, first);
        while (!stack.empty()) {
            const std::size_t k = stack.back();
            stack.pop_back();
            if (bodies_[k].is_static || steps_.stepped[k] || scratch_.mark[k] == in) continue;
            scratch_.mark[k] = in;
            scratch_.parent[k] = k;
            bodies.push_back(k);
            if (islands_.of[k] == 0) continue;
            auto it = islands_.members.find(islands_.of[k]);
            if (it == islands_.members.end()) continue;
            const std::vector<std::size_t> others = std::move(it->second);
            islands_.members.erase(it);
            stack.insert(stack.end(), others.rbegin(), others.rend());
        }
    };
    for (std::size_t k : reached) add(k);
    // Islands: connected through resting contacts (touching, |un| <= v_rest at every point),
    // found by union-find over scratch_.parent.
    auto root = [&](std::size_t k) {
        std::size_t r = k;
        while (scratch_.parent[r] != r) r = scratch_.parent[r];
        while (scratch_.parent[k] != r) {
            const std::size_t next = scratch_.parent[k];
            scratch_.parent[k] = r;
            k = next;
        }
        return r;
    };
    std::vector<Contact> contacts;
    std::vector<Contact> resting;
    for (std::size_t q = 0; q < bodies.size(); ++q) {
        const std::size_t start = contacts.size();
        contacts_of(bodies[q], t, &contacts);
        for (std::size_t c = start; c < contacts.size(); ++c) {
            const Contact& ct = contacts[c];
            const double v_rest = rest_speed(ct.a, ct.b);
            bool rests = false;  // some point slow (none approaches: impacts came first)
            for (int k = 0; k < ct.m.count; ++k)
                rests = rests || std::abs(normal_speed(ct.a, ct.b, ct.m.points[k], ct.m.normal)) <= v_rest;
            if (!rests) continue;
            resting.push_back(ct);
            for (std::size_t k : {ct.a, ct.b}) add(k);
        }
    }
    // Whatever touches a stepped body is stepped too (and, with stepping = always, whatever
    // rests on anything): passed on through touching bodies ("Stepped islands" in docs/stepping.md).
    for (bool changed = true; changed;) {
        changed = false;
        for (const Contact& ct : contacts) {
            const bool joins = steps_.stepped[ct.a] || steps_.stepped[ct.b] || scene_.stepping == StepMode::always;
            if (!joins) continue;
            for (std::size_t k : {ct.a, ct.b})
                if (!steps_.stepped[k] && may_step(k)) {
                    join(k, t);
                    changed = true;
                }
        }
    }
    resting.erase(std::remove_if(resting.begin(), resting.end(),
                                 [&](const Contact& ct) { return steps_.stepped[ct.a] || steps_.stepped[ct.b]; }),
                  resting.end());
    for (const Contact& ct : resting)
        if (!bodies_[ct.a].is_static && !bodies_[ct.b].is_static) scratch_.parent[root(ct.a)] = root(ct.b);
    // The islands in the order of their roots, each's contacts by pair.
    std::vector<std::pair<std::size_t, std::size_t>> order;  // (root, index in resting)
    for (std::size_t c = 0; c < resting.size(); ++c)
        order.emplace_back(root(bodies_[resting[c].a].is_static ? resting[c].b : resting[c].a), c);
    std::sort(order.begin(), order.end(), [&](const auto& x, const auto& y) {
        if (x.first != y.first) return x.first < y.first;
        const Contact &p = resting[x.second], &q = resting[y.second];
        return p.a != q.a ? p.a < q.a : p.b < q.b;
    });
    // Those that joined move freely until the next step.
    for (std::size_t k : bodies)
        if (steps_.stepped[k]) {
            insert(k, t, loop_.substep_end);
            predict(k, t);
        }
    bodies.erase(std::remove_if(bodies.begin(), bodies.end(), [&](std::size_t k) { return steps_.stepped[k] != 0; }),
                 bodies.end());
    for (std::size_t k : bodies) set_free(k);
    const std::uint32_t member = fresh(&scratch_.mark, &scratch_.mark_id);
    std::vector<Contact> island;
    std::vector<std::size_t> members;
    for (std::size_t first = 0; first < order.size();) {
        std::size_t last = first;
        while (last < order.size() && order[last].first == order[first].first) ++last;
        island.clear();
        members.clear();
        for (std::size_t c = first; c < last; ++c) {
            island.push_back(resting[order[c].second]);
            for (std::size_t k : {island.back().a, island.back().b})
                if (!bodies_[k].is_static && scratch_.mark[k] != member) {
                    scratch_.mark[k] = member;
                    members.push_back(k);
                }
        }
        solve_island(&island, members, t);
        first = last;
    }
    for (std::size_t k : bodies) {
        insert(k, t, loop_.substep_end);
        predict(k, t);  // also a new sleeper: its neighbours predicted it still moving
    }
}

// Constant contact forces for the rest of the substep (see "Resting contact" in docs/stepping.md):
// first the normal speeds of the resting points are set to zero (the last, shorter than
// kZenoTime, bounces merged), then forces F >= 0 keep the normal relative acceleration >= 0.
template <int D>
void World<D>::solve_island(std::vector<Contact>* contacts, const std::vector<std::size_t>& members, double t) {
    ++counters_.island_solves;
    const std::uint32_t id = islands_.next_id++;
    if (islands_.next_id == 0) islands_.next_id = 1;
    islands_.members[id] = members;
    for (std::size_t k : members) islands_.of[k] = id;
    // The slow points' normal speeds to zero; the others (parting) are left alone.
    std::vector<PointGoal> goals;
    for (const Contact& c : *contacts) {
        const double v_rest = rest_speed(c.a, c.b);
        for (int k = 0; k < c.m.count; ++k) {
            PointGoal g;
            g.mu = 0.0;
            if (std::abs(normal_speed(c.a, c.b, c.m.points[k], c.m.normal)) <= v_rest) g.push_only = false;
            else g.un = -kNever;
            goals.push_back(g);
        }
    }
    std::vector<Contact> merged = *contacts;
    solve_points(&merged, goals, &bodies_);
    const double h = loop_.substep_end - t;
    if (!(h > 0.0)) return;
    // Velocities a step h later with gravity, then the impulses that keep every point from
    // approaching; their average over h is the force.
    // (islands_.later is indexed like bodies_; only the island's bodies are copied into it.)
    std::vector<Body>& later = islands_.later;
    if (later.size() != bodies_.size()) later = bodies_;
    for (const Contact& c : *contacts)
        for (std::size_t k : {c.a, c.b}) later[k] = bodies_[k];
    for (std::size_t k : members) later[k].v += gravity() * h;
    goals.clear();
    for (const Contact& c : *contacts) {
        const double mu = friction_limit(c.a, c.b);
        // Two round bodies keep their centres ra + rb apart: d^2|d|/dt^2 = 0 asks for the
        // normal relative acceleration -|ut|^2 / |d| (ut: the centres' relative velocity across
        // n), the centripetal part of sliding over a curved partner. Constant forces then
        // follow the curve to third order in the substep instead of drifting into it.
        double curve = 0.0;
        if (shapes_.round[c.a] && shapes_.round[c.b]) {
            const Vec d = bodies_[c.b].position - bodies_[c.a].position;
            const Vec u = bodies_[c.b].v - bodies_[c.a].v;
            const Vec ut = u - u.dot(c.m.normal) * c.m.normal;
            curve = ut.squaredNorm() / d.norm();
        }
        for (int k = 0; k < c.m.count; ++k) {
            PointGoal g;
            g.mu = mu;
            g.un = -curve * h;
            goals.push_back(g);
        }
    }
    std::vector<Contact> forces = *contacts;
    solve_points(&forces, goals, &later);
    for (std::size_t k : members) {
        track_[k].a = (later[k].v - bodies_[k].v) / h;
        track_[k].alpha = (later[k].w - bodies_[k].w) / h;
    }
    // Sleep (see "Sleeping islands" in docs/stepping.md): every surface point of every member moves
    // slower than v_sleep = kZenoTime |g| / 2, the speed the world already counts as resting,
    // and would still after a rest step: |v| + |w| R + (|a| + |alpha| R) kRestStep <= v_sleep.
    const double v_sleep = 0.5 * kZenoTime * gravity().norm();
    for (std::size_t k : members) {
        const Track& tk = track_[k];
        const double speed = bodies_[k].v.norm() + magnitude(bodies_[k].w) * shapes_.radius[k] +
                             (tk.a.norm() + magnitude(tk.alpha) * shapes_.radius[k]) * kRestStep;
        if (!(speed <= v_sleep)) return;
    }
    ++counters_.sleeps;
    for (std::size_t k : members) {
        bodies_[k].v = zero<Vec>();
        bodies_[k].w = zero<Spin>();
        track_[k].a = zero<Vec>();
        track_[k].alpha = zero<Spin>();
        ++track_[k].version;
        islands_.asleep[k] = 1;
    }
}

// The members defined here, for World<2> and World<3>.
#define COLLIDE_INSTANTIATE_ISLANDS(D)                                                                                 \
    template bool World<D>::same_island(std::size_t, std::size_t) const;                                               \
    template void World<D>::settle(const std::vector<std::size_t>&, double);                                           \
    template void World<D>::solve_island(std::vector<Contact>*, const std::vector<std::size_t>&, double);
COLLIDE_INSTANTIATE_ISLANDS(2)
COLLIDE_INSTANTIATE_ISLANDS(3)
#undef COLLIDE_INSTANTIATE_ISLANDS

}  // namespace collide
