// Pairs collide's collision events with Box2D's and explains where they differ.
//
// Matching: by the unordered pair of bodies and the order of occurrence for that pair (the
// k-th collision of ball and ground in one engine with the k-th in the other). An event left
// over on either side is reported with "no matching event".
//
// Difference of two sets of velocities of a pair of bodies A and B (static bodies left out):
//
//     max over A, B of  max(|v1 - v2|, R |w1 - w2|)  /  S
//
// R is the body's bounding radius (the farthest point of its surface from its centre), so a
// spin counts as the speed of its rim; S is the largest max(|v|, R |w|) of the two bodies
// before or after the event in either engine. `difference` compares the velocities after the
// event; the engines agree when it is at most kAgree (Box2D computes in float: 1e-7 relative).
//
// Reasons, given when the engines do not agree (joined by "; "). Each names a measured
// quantity; where its share of the difference can be estimated, "[~x]" gives it, and the
// estimated causes are listed largest first:
//   "no matching event"         one engine has a collision the other has not;
//   "speed cap"                 a body moves faster than b2_maxTranslation (2 m) or
//                               b2_maxRotation (pi/2) per step: Box2D clamps its velocity;
//   "model"                     collide's matrix or stick model: Box2D has Coulomb friction only;
//   "two-point contact"         Box2D solved two manifold points together (block solver) where
//                               collide's sequential policy takes one at a time (with the
//                               simultaneous policy: named only if the rest does not explain);
//   "restitution threshold"     Box2D's approach speed was below its threshold: no bounce
//                               (~ e |un| / S);
//   "restitution mixing"        Box2D's e (max of the two) is not collide's (min of the two);
//   "step gravity"              Box2D adds the step's g dt to the velocity before it applies
//                               restitution, so a bounce leaves with e (|un| + g dt)
//                               (~ e |g.n| dt / S: bounces under gravity gain energy);
//   "velocities before differ"  the state before the event already differs: an earlier
//                               difference, or gravity between the two instants
//                               (~ (1 + e) times the difference before);
//   "normal off by N degrees"   Box2D's manifold normal, taken from an overlapped pose
//                               (~ (1 + e) |un| sin N / S);
//   "other contacts in the same step"  Box2D solved this contact together with others of its
//                               bodies (Gauss-Seidel over the island) where collide resolves
//                               each at its own instant (named only if the rest does not explain);
//   "friction"                  Box2D iterates friction per point (named only if the rest does
//                               not explain);
//   "unexplained"               none of the above.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compare/box2d_world.h"
#include "engine/world.h"

namespace collide::compare {

constexpr double kAgree = 1e-4;          // difference up to which the engines agree
constexpr double kNormalDegrees = 0.01;  // normals closer than this are the same

struct Comparison {
    std::size_t a = 0, b = 0;  // scene body indices, a < b
    std::optional<Event2> collide;
    std::optional<Box2DEvent> box2d;
    std::optional<double> difference;         // after the event (both sides present)
    std::optional<double> difference_before;  // before the event
    std::optional<double> normal_degrees;     // angle between the two normals
    std::string reason;                       // empty when they agree
};

using Velocity = Event2::Velocity;

// Bounding radius R of each body (0 for planes and static bodies): the lever of the difference.
std::vector<double> lever_radii(const Scene& scene);

// The largest max(|v|, R |w|) of the dynamic bodies among the given velocities of bodies a, b.
double velocity_scale(const std::vector<double>& radii, std::size_t a, std::size_t b,
                      const std::vector<std::pair<Velocity, Velocity>>& states);
// max over a, b of max(|v1 - v2|, R |w1 - w2|) / scale (0 when scale is 0).
double velocity_difference(const std::vector<double>& radii, std::size_t a, std::size_t b,
                           const std::pair<Velocity, Velocity>& one, const std::pair<Velocity, Velocity>& two,
                           double scale);

// Matches the two runs' events of `scene` and fills in differences and reasons. The result is
// in time order (collide's time, or Box2D's for an event only Box2D has).
std::vector<Comparison> match_events(const Scene& scene, const Box2DSettings& settings, const std::vector<Event2>& ours,
                                     const std::vector<Box2DEvent>& theirs);

}  // namespace collide::compare
