// Conservation checks: total linear momentum, angular momentum about a fixed point, kinetic
// energy with the full inertia tensor. Static bodies (infinite mass) are left out of the sums.
#pragma once

#include <vector>

#include "engine/body.h"

namespace collide {

struct Totals1 {
    double momentum = 0.0;        // kg m/s
    double kinetic_energy = 0.0;  // J
};

struct Totals2 {
    Vec2 momentum = Vec2::Zero();
    double angular_momentum = 0.0;  // kg m^2/s, about the chosen point, +z
    double kinetic_energy = 0.0;
};

struct Totals3 {
    Vec3 momentum = Vec3::Zero();
    Vec3 angular_momentum = Vec3::Zero();
    double kinetic_energy = 0.0;
};

// p = sum m v; KE = sum 1/2 m v^2.
Totals1 totals(const std::vector<Body1>& bodies);
// L about o = sum (I w + m (x - o) x v); KE = sum 1/2 m v.v + 1/2 I w^2.
Totals2 totals(const std::vector<Body2>& bodies, const Vec2& about = Vec2::Zero());
// L about o = sum (R Ibody R^T w + m (x - o) x v); KE = sum 1/2 m v.v + 1/2 w.(R Ibody R^T) w,
// off-diagonal inertia terms included.
Totals3 totals(const std::vector<Body3>& bodies, const Vec3& about = Vec3::Zero());

// Whether an impact left its bodies with more kinetic energy than they had: `after` exceeds
// `before` by more than 1e-9 of it (the round-off of an elastic impact is about 1e-16 of it).
// No passive impact can do that. The one-step Coulomb model, or Routh's with Newton's law, can
// when slip stops or reverses during the impact (Kane's paradox; the matrix method cannot:
// its change is -(1 - e^2)/2 u.K^-1 u), and so can the page's listing as written;
// `collide solve` and `collide step --events` say so whenever it happens.
bool gains_energy(double before, double after);

// Potential energy in uniform gravity g (1D: g.x along the line; 2D: g.x, g.y), zero at the
// origin: U = -m g . x. Static bodies have none.
double potential_energy(const Body1& b, const Vec3& g);
double potential_energy(const Body2& b, const Vec3& g);
double potential_energy(const Body3& b, const Vec3& g);

}  // namespace collide
