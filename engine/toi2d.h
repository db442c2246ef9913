// Exact time of impact in 2D, by conservative advancement.
//
// Each body follows a known free motion over the interval: x(t) = x + v t + g t^2/2 (g: the
// body's own acceleration, gravity for dynamic bodies, 0 for static ones) and angle(t) =
// angle + w t (a torque-free body in the plane keeps w). At time t the shapes are d apart along
// the unit normal n between their nearest points. Before they can touch, some point of B must
// gain d on A along n; it gains at most
//     rate = max(0, -n.(vb - va)) + max(0, -n.(gb - ga)) (t_end - t) + |wa| Ra + |wb| Rb
// per second (R: each shape's bounding radius), so the next time to look is t + d / rate. The
// iteration stops when d <= tolerance: the first contact, never a pose that already overlaps
// by more than round-off.
#pragma once

#include "engine/shape2d.h"

namespace collide {

struct Motion2 {
    Vec2 x = Vec2::Zero();  // centre of mass at t = 0, m
    Vec2 v = Vec2::Zero();  // m/s
    Vec2 g = Vec2::Zero();  // m/s^2
    double angle = 0.0;     // rad
    double w = 0.0;         // rad/s
    Pose2 at(double t) const { return Pose2{x + v * t + 0.5 * t * t * g, angle + w * t}; }
    Vec2 velocity(double t) const { return v + g * t; }
};

struct TimeOfImpact {
    bool hit = false;   // contact within [0, t_end]
    double t = 0.0;     // s, the first time the separation is <= tolerance
    Manifold2 manifold; // at t (points reported within the tolerance)
    int iterations = 0;
    bool converged = true;  // false: max_iterations ran out first (hit is then false)
};

struct ToiSettings {
    double tolerance = 1e-10;  // m: contact when the separation is at most this
    int max_iterations = 10000;
};

TimeOfImpact time_of_impact(const Shape2& a, const Motion2& ma, const Shape2& b,
                            const Motion2& mb, double t_end, const ToiSettings& settings = {});

}  // namespace collide
