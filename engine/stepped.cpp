// Stepped islands ("Stepped islands" in docs/stepping.md): which bodies are stepped, and one step
// of them all (the solve itself: engine/island_step.h).
#include "engine/world.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/shape2d.h"
#include "engine/shape3d.h"

namespace collide {

namespace {

// A pair within the speculative margin, as the step needs it: 2D polygons apart are measured by
// their separating axis (Apart::axis: the normal the points' depths are measured along); 3D
// boxes always are.
Manifold2 step_manifold(const Shape2& a, const Pose2& pa, const Shape2& b, const Pose2& pb, double margin) {
    return collide(a, pa, b, pb, margin, Apart::axis);
}
Manifold3 step_manifold(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, double margin) {
    return collide(a, pa, b, pb, margin);
}

}  // namespace

template <int D>
bool World<D>::may_step(std::size_t i) const {
    return !bodies_[i].is_static && welds_.of[i] < 0 && scene_.stepping != StepMode::never &&
           scene_.model != Model::stick && scene_.model != Model::page_listing;
}

template <int D>
void World<D>::join(std::size_t i, double t) {
    if (steps_.stepped[i] || !may_step(i)) return;
    drift(i, t);
    set_free(i);  // out of its resting island
    steps_.stepped[i] = 1;
    steps_.solved[i] = 0;
    steps_.still[i] = 0.0;
    steps_.restep = true;
    steps_.reseed.push_back(i);
    ++counters_.joined;
}

template <int D>
void World<D>::wake(std::size_t i) {
    if (!islands_.asleep[i]) return;
    islands_.asleep[i] = 0;
    steps_.solved[i] = 0;
    steps_.still[i] = 0.0;
    steps_.restep = true;
    steps_.reseed.push_back(i);
    ++track_[i].version;
}

// stepping = auto: a pair colliding kPersistImpacts times within kPersistWindow is in
// persistent contact, unless both are smooth (round or plane: their last bounces merge exactly,
// "Resting contact"); its moving bodies are stepped.
template <int D>
void World<D>::count_impact(std::size_t a, std::size_t b, double t) {
    if (scene_.stepping != StepMode::automatic) return;
    if ((shapes_.round[a] || shapes_.plane[a]) && (shapes_.round[b] || shapes_.plane[b])) return;
    for (std::size_t k : {a, b})
        if (!bodies_[k].is_static && !may_step(k)) return;
    auto& r = steps_.rates[static_cast<std::uint64_t>(std::min(a, b)) << 32 | std::max(a, b)];
    if (t - r.since > kPersistWindow) {
        r.since = t;
        r.count = 0;
    }
    if (++r.count < kPersistImpacts) return;
    join(a, t);
    join(b, t);
}

template <int D>
double World<D>::surface_speed(std::size_t i) const {
    return bodies_[i].v.norm() + magnitude(bodies_[i].w) * shapes_.radius[i];
}

// One step of every stepped body that is awake, at t (the step's start): their contacts within
// the margin (bringing in the moving bodies that touch them and the sleepers they reach), the
// solve, their motion for the step, the first contacts as events, and sleeping.
template <int D>
void World<D>::step_islands(double t, std::vector<Event<D>>* events, bool within) {
    const double h = kIslandStep;
    const double g = gravity().norm();
    std::vector<std::size_t> members;
    const std::uint32_t in = fresh(&scratch_.mark, &scratch_.mark_id);
    if (!within) {
        steps_.end = t + h;
        for (std::size_t i = 0; i < bodies_.size(); ++i)
            if (steps_.stepped[i] && !islands_.asleep[i]) members.push_back(i);
    } else {
        for (std::size_t i : steps_.reseed)
            if (steps_.stepped[i] && !islands_.asleep[i] && scratch_.mark[i] != in) {
                members.push_back(i);
                scratch_.mark[i] = in;
            }
    }
    for (std::size_t i : members) scratch_.mark[i] = in;
    steps_.restep = false;
    steps_.reseed.clear();
    if (members.empty()) return;
    // The gravity impulse a body solved for a step longer than it moved on gives back.
    auto left = [&](std::size_t i) { return steps_.solved[i] ? std::max(0.0, steps_.until[i] - t) : 0.0; };
    ++counters_.steps;
    fresh(&scratch_.searched, &scratch_.search);
    std::vector<StepContact<D>> contacts;
    std::vector<int> touches(bodies_.size(), 0);  // contacts within the margin, per body
    for (std::size_t q = 0; q < members.size(); ++q) {
        const std::size_t i = members[q];
        drift(i, t);
        scratch_.searched[i] = scratch_.search;
        const double reach_i = kSpeculative + (surface_speed(i) + g * h) * h;
        auto box = [&](Vec* lo, Vec* hi) {
            swept_box(i, t, loop_.substep_end, lo, hi);
            *lo -= Vec::Constant(reach_i);
            *hi += Vec::Constant(reach_i);
        };
        grid_.for_each_neighbour(i, box, [&](std::size_t j) {
            if (scratch_.searched[j] == scratch_.search && !shapes_.plane[j]) return;  // from j's side
            if (welds_.of[j] >= 0 || passed(i, j)) return;
            drift(j, t);
            const std::size_t a = std::min(i, j), b = std::max(i, j);
            const double margin = kSpeculative + (surface_speed(a) + surface_speed(b) + 2.0 * g * h) * h;
            if (apart(a, b, margin)) return;  // their bounding circles (spheres) apart
            const Manifold m =
                step_manifold(shapes_.of[a], pose_of(bodies_[a]), shapes_.of[b], pose_of(bodies_[b]), margin);
            if (m.count == 0) return;
            if (!bodies_[j].is_static && !steps_.stepped[j]) {
                // A moving body not stepped joins when it touches (nearer, its impact is exact).
                if (m.separation > kTouch || !may_step(j)) return;
                join(j, t);
                members.push_back(j);
                scratch_.mark[j] = in;
            } else if (steps_.stepped[j] && islands_.asleep[j]) {
                wake(j);
                members.push_back(j);
                scratch_.mark[j] = in;
            } else if (steps_.stepped[j] && scratch_.mark[j] != in) {  // the rest of a restepped island
                members.push_back(j);
                scratch_.mark[j] = in;
            }
            StepContact<D> c;
            c.a = a;
            c.b = b;
            c.m = m;
            c.e = scene_.pair_restitution(a, b);
            c.mu = friction_limit(a, b);
            contacts.push_back(c);
            ++touches[a];
            ++touches[b];
        });
    }
    // A stepped body with nothing within the margin is free again.
    std::vector<std::size_t> stepped;
    for (std::size_t i : members) {
        if (touches[i] > 0) {
            stepped.push_back(i);
            continue;
        }
        steps_.stepped[i] = 0;
        steps_.exact_bodies = true;
        bodies_[i].v -= gravity() * left(i);
        steps_.solved[i] = 0;
        set_free(i);
        insert(i, t, loop_.substep_end);
    }
    for (std::size_t i : stepped) {
        bodies_[i].v -= gravity() * left(i);  // the step cut short: see the header
        scratch_.before[i] = {bodies_[i].v + gravity() * h, bodies_[i].w};
    }
    steps_.stepper.step(&contacts, stepped, &bodies_, gravity(), h);
    for (std::size_t i : stepped) {
        Track& k = track_[i];
        k.a = zero<Vec>();  // x+ = x- + h v+
        k.alpha = zero<Spin>();
        k.t = t;
        ++k.version;
        steps_.solved[i] = 1;
        steps_.until[i] = t + h;
    }

    // A pair's first contact is an impact: recorded as an event.
    for (const StepContact<D>& c : contacts) {
        if (!c.fresh || !(c.weight > 0.0) || !(c.approach < -rest_speed(c.a, c.b))) continue;
        auto vel = [&](std::size_t k) { return typename Event<D>::Velocity{bodies_[k].v, bodies_[k].w}; };
        record(c.a, c.b, t, c.m.normal, c.impulse, c.moment / c.weight,
               steps_.stepped[c.a] ? scratch_.before[c.a] : vel(c.a),
               steps_.stepped[c.b] ? scratch_.before[c.b] : vel(c.b), events);
    }

    // Sleeping: islands (connected through contacts between moving bodies) whose every body has
    // been slow for kStepSleepTime.
    for (std::size_t i : stepped) {
        scratch_.parent[i] = i;
        steps_.still[i] = surface_speed(i) <= kStepSleepSpeed ? steps_.still[i] + h : 0.0;
    }
    auto root = [&](std::size_t k) {
        while (scratch_.parent[k] != k) k = scratch_.parent[k] = scratch_.parent[scratch_.parent[k]];
        return k;
    };
    for (const StepContact<D>& c : contacts)
        if (steps_.stepped[c.a] && steps_.stepped[c.b]) scratch_.parent[root(c.a)] = root(c.b);
    std::vector<double> least(bodies_.size(), std::numeric_limits<double>::infinity());
    for (std::size_t i : stepped) least[root(i)] = std::min(least[root(i)], steps_.still[i]);
    for (std::size_t i : stepped) {
        if (least[root(i)] >= kStepSleepTime) {
            bodies_[i].v = zero<Vec>();
            bodies_[i].w = zero<Spin>();
            islands_.asleep[i] = 1;
            if (root(i) == i) ++counters_.sleeps;
        }
        insert(i, t, loop_.substep_end);
    }
    if (within)
        for (std::size_t i : stepped) predict(i, t);
    steps_.restep = false;  // (what woke here is in this step)
    steps_.reseed.clear();
}

// The members defined here, for World<2> and World<3>.
#define COLLIDE_INSTANTIATE_STEPPED(D)                                                                                 \
    template bool World<D>::may_step(std::size_t) const;                                                               \
    template void World<D>::join(std::size_t, double);                                                                 \
    template void World<D>::wake(std::size_t);                                                                         \
    template void World<D>::count_impact(std::size_t, std::size_t, double);                                            \
    template double World<D>::surface_speed(std::size_t) const;                                                        \
    template void World<D>::step_islands(double, std::vector<Event<D>>*, bool);
COLLIDE_INSTANTIATE_STEPPED(2)
COLLIDE_INSTANTIATE_STEPPED(3)
#undef COLLIDE_INSTANTIATE_STEPPED

}  // namespace collide
