#include "engine/scene.h"

#include <algorithm>
#include <cmath>

namespace collide {

namespace {
double the_default_work_budget = kDefaultWorkBudget;
}  // namespace

double default_work_budget() { return the_default_work_budget; }
void set_default_work_budget(double units) { the_default_work_budget = units; }

const char* policy_name(Policy p) { return p == Policy::sequential ? "sequential" : "simultaneous"; }

const char* step_mode_name(StepMode s) {
    return s == StepMode::automatic ? "auto" : s == StepMode::always ? "always" : "never";
}

double Scene::pair_restitution(std::size_t i, std::size_t j) const {
    return std::min(bodies[i].restitution.value_or(restitution), bodies[j].restitution.value_or(restitution));
}

double Scene::pair_friction(std::size_t i, std::size_t j) const {
    return std::sqrt(bodies[i].friction.value_or(friction) * bodies[j].friction.value_or(friction));
}

}  // namespace collide
