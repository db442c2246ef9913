#include "engine/toi2d.h"

#include <algorithm>
#include <cmath>

namespace collide {

TimeOfImpact time_of_impact(const Shape2& a, const Motion2& ma, const Shape2& b,
                            const Motion2& mb, double t_end, const ToiSettings& settings) {
    TimeOfImpact out;
    const double spin_bound = std::abs(ma.w) * bounding_radius(a) + std::abs(mb.w) * bounding_radius(b);
    double t = 0.0;
    for (out.iterations = 1; out.iterations <= settings.max_iterations; ++out.iterations) {
        const Manifold2 m = collide(a, ma.at(t), b, mb.at(t), settings.tolerance);
        if (m.separation <= settings.tolerance) {
            out.hit = true;
            out.t = t;
            out.manifold = m;
            return out;
        }
        // How fast the gap along n can close from now to t_end (see the header).
        const Vec2 dv = mb.velocity(t) - ma.velocity(t), dg = mb.g - ma.g;
        const double rate = std::max(0.0, -m.normal.dot(dv)) +
                            std::max(0.0, -m.normal.dot(dg)) * (t_end - t) + spin_bound;
        if (!(rate > 0.0)) return out;  // nothing closes the gap
        t += m.separation / rate;
        if (t > t_end) return out;
    }
    out.converged = false;  // the caller decides: never silently treated as a miss
    return out;
}

}  // namespace collide
