// Free rotation of a rigid body in 3D: Euler's equations with the gyroscopic term.
//
// With no torque the world angular momentum L = R Ib R^T w is constant, but w is not: in the
// body frame, Lb = R^T L obeys
//     dLb/dt = Lb x wb,   wb = Ib^-1 Lb          (the gyroscopic term -wb x Ib wb)
// and the orientation follows dR/dt = R [wb]x. Both |Lb|^2 and Lb . Ib^-1 Lb (twice the kinetic
// energy) are quadratic invariants, so the implicit midpoint rule keeps them to round-off
// whatever the step; composed as Yoshida's triple jump it is fourth-order accurate in the motion
// itself (how fast an asymmetric body tumbles, when a Dzhanibekov flip happens).
#pragma once

#include <cstdint>

#include "engine/body.h"

namespace collide {

struct RotationSettings {
    double max_angle_per_step = 0.005;  // rad turned per substep (sets the substep count)
};

// The rotation by the vector phi (axis phi/|phi|, angle |phi| rad) as a unit quaternion.
Quat exp_map(const Vec3& phi);

// Turns the body for dt seconds with no torque: updates orientation and w (world frame), and
// returns the number of steps taken (each turns the body by at most max_angle_per_step).
// Static bodies and bodies at rest are left alone (0 steps). Throws RunError
// (engine/run_error.h), before taking any, if the steps would number more than max_steps (a
// world passes what its work budget has left) or 2^53.
// A sphere's inertia (isotropic) and a symmetric top's (diagonal in the body frame, two
// principal moments equal, all three positive) turn in closed form: one exact step whatever dt.
std::uint64_t rotate_free(Body3* body, double dt, const RotationSettings& settings = {},
                          std::uint64_t max_steps = UINT64_MAX);

// True when rotate_free integrates the body's turn in steps (neither a sphere's inertia nor a
// symmetric top's, and spinning): its pose later costs steps from where it is now.
bool rotation_integrated(const Body3& body);

}  // namespace collide
