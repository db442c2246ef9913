// A world's work budget (docs/stepping.md, "Work budget"): the work it has done, its budget,
// the estimate of a scene without gravity made before it runs, and the refusal once the budget
// is spent. The turns' own refusal is world.cpp's (it counts the steps of a turn before taking it).
#include <algorithm>
#include <cstdint>
#include <string>

#include "engine/run_error.h"
#include "engine/world.h"

namespace collide {

template <int D>
std::uint64_t World<D>::work_done() const {
    return work_.body_substeps + work_.rotation_steps + counters_.predictions + counters_.events;
}

template <int D>
std::uint64_t World<D>::work_budget() const {
    const double b = scene_.work_budget;
    return b >= 0x1p63 ? UINT64_MAX : b > 0.0 ? static_cast<std::uint64_t>(b) : 0;
}

// What the scene costs if nothing but its free motion happens, without gravity (under gravity
// bodies may come to rest and sleep, costing nothing: only the count while running decides):
// every moving body in every substep, each substep as long as free_substep() makes it from the
// bodies' speeds and spins now (free flight keeps them), and each turn integrated in steps
// (turns_in_steps()), whose speed is at least 2E/|L| (E and L kept: 2E = w.L <= |w| |L|), at
// 0.005 rad a step.
template <int D>
double World<D>::estimate_work() const {
    if (gravity().norm() > 0.0) return 0.0;
    double turns = 0.0;
    std::size_t moving = 0;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        const Body& b = bodies_[i];
        if (b.is_static) continue;
        ++moving;
        if constexpr (D == 3) {
            const Vec3 L = b.inertia_world() * b.w;
            if (turns_in_steps(i) && L.norm() > 0.0) turns += b.w.dot(L) / L.norm();
        }
    }
    if (moving == 0) return 0.0;
    return static_cast<double>(moving) * (scene_.duration / free_substep()) + scene_.duration * turns / 0.005;
}

template <int D>
void World<D>::refuse_work(double t) const {
    const double done = static_cast<double>(work_done());
    // The whole run at this rate; none for a run taken past its duration (a program's own).
    const double all = t > 0.0 ? done * scene_.duration / t : done;
    const std::string rate =
        t < scene_.duration ? " (at this rate about " + run_number(all, 3) + " in all, " + run_duration(all) + ")" : "";
    throw RunError(run_source(scene_.file) + "the scene has taken " + run_number(done) +
                   " units of work by t = " + run_number(t) + " s of its " + run_number(scene_.duration) + " s" + rate +
                   ", more than its budget of " + run_number(scene_.work_budget) +
                   " (--max-work raises it; see docs/stepping.md, \"Work budget\")");
}

// The members defined here, for World<2> and World<3>.
#define COLLIDE_INSTANTIATE_WORK_BUDGET(D)                                                                             \
    template std::uint64_t World<D>::work_done() const;                                                                \
    template std::uint64_t World<D>::work_budget() const;                                                              \
    template double World<D>::estimate_work() const;                                                                   \
    template void World<D>::refuse_work(double) const;
COLLIDE_INSTANTIATE_WORK_BUDGET(2)
COLLIDE_INSTANTIATE_WORK_BUDGET(3)
#undef COLLIDE_INSTANTIATE_WORK_BUDGET

}  // namespace collide
