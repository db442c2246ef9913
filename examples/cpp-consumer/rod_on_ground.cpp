// One collision with Collide's engine: a thin rod (m = 1 kg, L = 1 m) falls flat at 2 m/s and
// lands on its left end on the ground (static), e = 0.5, no friction. The page's formula gives
//   j = (1 + e) m v / (1 + m r^2 / I) = (1 + e) m v / 4   (r = L/2, I = m L^2 / 12),
// so the rod leaves with v = -2 + j/m = -1.25 m/s and w = -r j / I = -4.5 rad/s (clockwise).
// Prints the response and exits 1 when it differs from that.
#include <cmath>
#include <cstdio>

#include "engine/respond.h"

int main() {
    using namespace collide;
    const double m = 1.0, L = 1.0, v = 2.0, e = 0.5;
    ImpactBody2 ground;  // static: zero inverse mass and inertia
    ImpactBody2 rod;
    rod.inv_m = 1.0 / m;
    rod.I = m * L * L / 12.0;
    rod.inv_I = 1.0 / rod.I;
    rod.r = Vec2(-L / 2, 0.0);  // the contact point, from the rod's centre
    rod.v = Vec2(0.0, -v);
    const Vec2 n(0.0, 1.0);  // from the ground (A) into the rod (B)
    const Response2 r = respond(Model::frictionless, ground, rod, n, e, 0.0, RestitutionLaw::newton);

    std::printf("impulse on the rod: (%g, %g) N s\n", r.P.x(), r.P.y());
    std::printf("rod after: v = (%g, %g) m/s, w = %g rad/s\n", r.vb.x(), r.vb.y(), r.wb);
    const double j = (1 + e) * m * v / 4;
    const bool ok = std::abs(r.P.y() - j) < 1e-12 && std::abs(r.vb.y() - (-v + j / m)) < 1e-12 &&
                    std::abs(r.wb - (-L / 2 * j / rod.I)) < 1e-12;
    std::printf("%s\n", ok ? "as the closed form" : "DIFFERS from the closed form");
    return ok ? 0 : 1;
}
