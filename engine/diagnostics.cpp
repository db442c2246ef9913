#include "engine/diagnostics.h"

#include <cmath>

namespace collide {

Totals1 totals(const std::vector<Body1>& bodies) {
    Totals1 t;
    for (const Body1& b : bodies) {
        if (b.is_static) continue;
        t.momentum += b.mass * b.v;
        t.kinetic_energy += 0.5 * b.mass * b.v * b.v;
    }
    return t;
}

Totals2 totals(const std::vector<Body2>& bodies, const Vec2& about) {
    Totals2 t;
    for (const Body2& b : bodies) {
        if (b.is_static) continue;
        t.momentum += b.mass * b.v;
        t.angular_momentum += b.inertia * b.w + b.mass * cross(Vec2(b.position - about), b.v);
        t.kinetic_energy += 0.5 * b.mass * b.v.squaredNorm() + 0.5 * b.inertia * b.w * b.w;
    }
    return t;
}

Totals3 totals(const std::vector<Body3>& bodies, const Vec3& about) {
    Totals3 t;
    for (const Body3& b : bodies) {
        if (b.is_static) continue;
        const Mat3 I = b.inertia_world();
        t.momentum += b.mass * b.v;
        t.angular_momentum += I * b.w + b.mass * (b.position - about).cross(b.v);
        t.kinetic_energy += 0.5 * b.mass * b.v.squaredNorm() + 0.5 * b.w.dot(I * b.w);
    }
    return t;
}

bool gains_energy(double before, double after) { return after - before > 1e-9 * std::abs(before); }

double potential_energy(const Body1& b, const Vec3& g) { return b.is_static ? 0.0 : -b.mass * g.x() * b.position; }
double potential_energy(const Body2& b, const Vec3& g) {
    return b.is_static ? 0.0 : -b.mass * g.head<2>().dot(b.position);
}
double potential_energy(const Body3& b, const Vec3& g) { return b.is_static ? 0.0 : -b.mass * g.dot(b.position); }

}  // namespace collide
