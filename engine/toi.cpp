// Time of impact (toi.h): the 2D conservative advancement, the closed forms and the spin bound.
#include "engine/toi.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

namespace collide {

TimeOfImpact time_of_impact(const Shape2& a, const Motion2& ma, const Shape2& b, const Motion2& mb, double t_end,
                            const ToiSettings& settings) {
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
        const double rate =
            std::max(0.0, -m.normal.dot(dv)) + std::max(0.0, -m.normal.dot(dg)) * (t_end - t) + spin_bound;
        if (!(rate > 0.0)) return out;  // nothing closes the gap
        t += m.separation / rate;
        if (t > t_end) return out;
    }
    out.converged = false;  // the caller decides: never silently treated as a miss
    return out;
}

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

template <class Vec>
double plane_time(const Vec& n, const Vec& v, const Vec& a, double gap, bool touching) {
    // gap(s) = n.x(s) - offset - r: a quadratic in s.
    const double bb = n.dot(v), aa = 0.5 * n.dot(a);
    // Touching and parting: the gap returns to zero at the larger root (s = -b/a).
    return touching ? (aa < 0.0 && bb > 0.0 ? -bb / aa : kNever) : first_root(aa, bb, std::max(gap, 0.0));
}

template <class Vec>
double round_time(const Vec& d, const Vec& u, double R, bool touching) {
    // |d + u s| = rp + rq with d, u the relative position and velocity.
    double s = kNever;
    const double uu = u.squaredNorm(), du = d.dot(u), c = d.squaredNorm() - R * R;
    if (du < 0.0 && uu > 0.0 && !touching) {
        const double disc = du * du - uu * c;
        if (disc >= 0.0) s = std::max(0.0, c / (-du + std::sqrt(disc)));
    }
    return s;
}

}  // namespace

double plane_contact_time(const Vec2& n, const Vec2& v, const Vec2& a, double gap, bool touching) {
    return plane_time(n, v, a, gap, touching);
}
double plane_contact_time(const Vec3& n, const Vec3& v, const Vec3& a, double gap, bool touching) {
    return plane_time(n, v, a, gap, touching);
}
double round_contact_time(const Vec2& d, const Vec2& u, double R, bool touching) {
    return round_time(d, u, R, touching);
}
double round_contact_time(const Vec3& d, const Vec3& u, double R, bool touching) {
    return round_time(d, u, R, touching);
}

double spin_bound(const Body2& b, double inv_min_moment) {
    (void)inv_min_moment;
    return std::abs(b.w);
}
double spin_bound(const Body3& b, double inv_min_moment) {
    const double twice_energy = b.w.dot(b.inertia_world() * b.w);
    return std::max(b.w.norm(), std::sqrt(std::max(0.0, twice_energy * inv_min_moment)));
}
double inverse_smallest_moment(const Body2& b) { return b.is_static ? 0.0 : 1.0 / b.inertia; }
double inverse_smallest_moment(const Body3& b) {
    if (b.is_static) return 0.0;
    const double least = Eigen::SelfAdjointEigenSolver<Mat3>(b.inertia).eigenvalues().minCoeff();
    return least > 0.0 ? 1.0 / least : 0.0;
}

}  // namespace collide
