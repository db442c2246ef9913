// One collision of a run, as `collide solve` would be given it: so the figures of a scenario
// (the formula overlay, the worked example of `collide render`) show the same worked example,
// computed by the same engine functions, as `collide solve`.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "scenario/solve_problem.h"
#include "teach/solve.h"
#include "engine/record.h"
#include "engine/scene.h"
#include "engine/world.h"
#include "engine/world1d.h"

namespace collide {

// The two bodies at the instant of a collision event, every vector embedded in 3D
// (1D: along x; 2D: the xy plane, spins along z).
// t, a, b (scene indices), point (m; 1D: unused), normal (unit; 1D: +x, b is to the right of
// a) and impulse (N s on b: what the world applied): engine/world.h.
struct CollisionInstant : LiftedEvent {
    using Side = BodyState;  // engine/body.h: x, q (2D: angle), v, w just before
    Side before_a, before_b;
    // Just after it, as the world resolved it.
    Vec3 va_after = Vec3::Zero(), wa_after = Vec3::Zero(), vb_after = Vec3::Zero(), wb_after = Vec3::Zero();
};

// Kinetic energy (J) of the two bodies of `c` with the velocities before (after = false) or
// after the impulse, by the engine's formula (engine/diagnostics.h).
double pair_kinetic_energy(const Scene& scene, const CollisionInstant& c, bool after);

// The kinetic energy (J) of the bodies of one instant's collisions (`instant`: the events of
// one time, in the order they were resolved) just before the first and just after the last:
// each body with its velocities before its first collision and after its last. (One pair of a
// simultaneous group may gain what another loses; the instant as a whole may not.)
struct InstantEnergy {
    double before = 0.0, after = 0.0;
};
InstantEnergy instant_kinetic_energy(const Scene& scene, const std::vector<CollisionInstant>& instant);

// A collision event as an instant: indices, point, normal, impulse, velocities and the
// bodies' poses, all from the event.
CollisionInstant collision_instant(const Event1& e);
CollisionInstant collision_instant(const Event2& e);
CollisionInstant collision_instant(const Event3& e);

// The same collision with the roles given: `a` as body a and `b` as body b. When the engine
// found them the other way round, the bodies swap sides and the normal and the impulse change
// sign (n from a into b, +P on b): the same physics in the other names. Unchanged otherwise.
CollisionInstant with_roles(const CollisionInstant& c, std::size_t a, std::size_t b);

// The problem: the bodies' masses and inertia from the scene, their state from `c`, the
// pair's restitution and friction (Scene::pair_restitution / pair_friction), the scene's
// model; angular momentum about the origin.
SolveProblem collision_problem(const Scene& scene, const CollisionInstant& c);

// The `order`-th recorded instant (from 1) at which bodies a and b collide (either way round):
// its index in rec.instants, and the range [first, end) of rec.events from that pair's first
// event there to its last. nullopt when the recorded instants have no such collision. (A
// lesson's [[figure]]: the figures of `collide render`, the site's Try-it panel.)
struct PairCollision {
    std::size_t instant = 0, first = 0, end = 0;
};
template <int D>
std::optional<PairCollision> find_pair_collision(const Recording<D>& rec, std::size_t a, std::size_t b, int order);

// What the worked example of collision `c` says beside the one-point formula's `solution`
// when the world resolved several contact points at that instant (a face on a face, a
// resting stack) and its total impulse differs: "The world resolved several contact points
// here; its total impulse is P = ..."; "" otherwise. (The page's listing model is left
// alone: its J is not what B receives, erratum 7, as its steps say.)
std::string world_note(const Scene& scene, const CollisionInstant& c, const Vec3& formula_impulse);

// Collision `c` as the run resolved it: `alone` (solve() of collision_problem(scene, c), the
// two bodies alone) with the run's impulse on b and the velocities just after, the checks
// recomputed (with_outcome). Where other contacts act at the same instant (a tower, a row of
// dominoes) the two differ.
Solution as_resolved(const SolveProblem& problem, const Solution& alone, const CollisionInstant& c);
// Whether they differ beyond rounding: by more than 1e-6 of the largest impulse or velocity
// (m/s and rad/s taken alike). Then a worked example is a simplified calculation, and the
// run's numbers are shown beside its results. (The page's listing model: velocities only, its J
// is not what B receives.)
bool resolved_differs(const SolveProblem& problem, const Solution& alone, const Solution& run);
// The results side by side, for a table: what, its unit, the two alone, the run (student
// numbers: 4 figures, no noise). Impulse on b, each body's velocity and (2D, 3D) spin after,
// the two bodies' kinetic energy after.
struct ResultBeside {
    std::string what, unit, alone, run;
};
std::vector<ResultBeside> results_beside(const SolveProblem& problem, const Solution& alone, const Solution& run);
// The words that label such a worked example, in two parts (the page sets the first in bold):
// "A simplified calculation: a and b alone." and what it means.
struct SimplifiedLabel {
    std::string lead, rest;
};
SimplifiedLabel simplified_label(const SolveProblem& problem);

}  // namespace collide
