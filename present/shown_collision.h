// Which collisions a page shows: a lesson's [[figure]] entries, else the run's first collision.
// The one rule that `collide render` (its figures and worked example), the site and the
// WebAssembly module's Try-it panel (the collision it works out) share.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "engine/record.h"
#include "scenario/lesson.h"
#include "teach/event_problem.h"

namespace collide {

// A collision to show: the `order`-th recorded instant (from 1) at which bodies a and b
// collide, with a as body a and b as body b (teach/event_problem.h with_roles).
struct CollisionPick {
    std::size_t a = 0, b = 0;
    int order = 1;
    bool whole_instant = false;  // every impact of that instant, before and after all of them
    bool touching = false;       // before and after drawn at the instant's poses
};

// What a lesson's [[figure]] entries pick, in order; empty for a scenario or a lesson without
// figures (then the page shows the run's first collision: first_collision_pick).
std::vector<CollisionPick> figure_picks(const Lesson* lesson);

// The collisions a lesson's figures show, for the record to keep wherever they fall
// (RecordOptions::keep).
std::vector<RecordOptions::Keep> figure_keeps(const Lesson* lesson);

// The run's first collision, as a pick: the pair of its first event, with the whole instant.
// nullopt when the run has no collision.
template <int D>
std::optional<CollisionPick> first_collision_pick(const Recording<D>& rec) {
    if (rec.events.empty()) return std::nullopt;
    return CollisionPick{rec.events.front().a, rec.events.front().b, 1, true};
}

// The collision a page works out first: the first of `picks` (a lesson's first [[figure]]),
// else the run's first collision.
template <int D>
std::optional<CollisionPick> page_pick(const std::vector<CollisionPick>& picks, const Recording<D>& rec) {
    if (!picks.empty()) return picks.front();
    return first_collision_pick(rec);
}

// The events of `pick` in the run: the instant and the range of its pair's events there
// (find_pair_collision); nullopt when the run has no such collision.
template <int D>
std::optional<PairCollision> find_pick(const Recording<D>& rec, const CollisionPick& pick) {
    return find_pair_collision(rec, pick.a, pick.b, pick.order);
}

// The collision a page works out (page_pick), in the pick's roles; nullopt when the run has
// none (or not the one a figure names).
template <int D>
std::optional<CollisionInstant> page_collision(const std::vector<CollisionPick>& picks, const Recording<D>& rec) {
    const std::optional<CollisionPick> pick = page_pick(picks, rec);
    if (!pick) return std::nullopt;
    const std::optional<PairCollision> c = find_pick(rec, *pick);
    if (!c) return std::nullopt;
    return with_roles(collision_instant(rec.events[c->first]), pick->a, pick->b);
}

}  // namespace collide
