// The steps of the 2D and 3D responses that are the same expressions over Vec2/Mat2 and
// Vec3/Mat3: no impulse, the Coulomb cone and the page's matrix method, written once as
// templates and declared per dimension in response.h. What differs by dimension (the cross
// product a number or a vector, the inertia a scalar or a tensor) stays in response2d.cpp and
// response3d.cpp. Conventions: response.h (n from A into B, +P on B, -P on A).
#include <Eigen/Cholesky>

#include "engine/response.h"

namespace collide {
namespace {

template <class Response, class Body>
Response unchanged_nd(const Body& a, const Body& b) {
    Response r;
    r.separating = true;
    r.va = a.v;
    r.wa = a.w;
    r.vb = b.v;
    r.wb = b.w;
    return r;
}

// Final relative velocity -e un n: K P = -e un n - u.
template <class Vec, class Mat>
Vec sticking_impulse_nd(const Mat& K, const Vec& u, const Vec& n, double e) {
    return K.llt().solve(-e * u.dot(n) * n - u);
}

template <class Vec, class Mat>
Vec slip_direction_nd(const Mat& K, const Vec& u, const Vec& n) {
    Vec ut = u - u.dot(n) * n;
    // No initial slip: the contact starts to slip the way the normal impulse alone drives it.
    if (ut.norm() <= 1e-12 * u.norm()) {
        const Vec Kn = K * n;
        ut = Kn - Kn.dot(n) * n;
    }
    const double len = ut.norm();
    return len > 0.0 ? Vec(ut / len) : Vec(Vec::Zero());
}

template <class Vec, class Mat>
double sliding_denominator_nd(const Mat& K, const Vec& n, const Vec& t, double mu) {
    return n.dot(K * (n - mu * t));
}

template <class Response, class Body, class Vec>
Response coulomb_nd(const Body& a, const Body& b, const Vec& n, double e, double mu) {
    const Vec u = relative_velocity(a, b);
    const double un = u.dot(n);
    if (un >= 0.0) return unchanged(a, b);
    const auto K = collision_matrix(a, b);
    Response r;
    r.P = sticking_impulse_nd(K, u, n, e);
    const double Pn = r.P.dot(n);
    const double Pt = (r.P - Pn * n).norm();
    if (!(Pn >= 0.0 && Pt <= mu * Pn)) {
        // Outside the friction cone: slide, friction mu Pn against the initial slip.
        const Vec t = slip_direction_nd(K, u, n);
        const double denominator = sliding_denominator_nd(K, n, t, mu);
        if (denominator > 0.0) {
            r.P = (-(1.0 + e) * un / denominator) * (n - mu * t);
            r.sliding = true;
        } else if (Pn < 0.0) {
            // n . K (n - mu t) <= 0 (large mu, strongly coupled K: a Painleve-like case the
            // one-step model cannot resolve) and the sticking impulse would pull: no friction.
            r.P = (-(1.0 + e) * un / n.dot(K * n)) * n;
            r.painleve = true;
        }  // else keep the sticking impulse: it pushes, friction as large as needed.
    }
    apply_impulse(a, b, &r);
    return r;
}

// The whole relative velocity reversed: K P = -(1 + e) u.
template <class Response, class Body, class Vec>
Response matrix_nd(const Body& a, const Body& b, const Vec& n, double e) {
    const Vec u = relative_velocity(a, b);
    if (u.dot(n) >= 0.0) return unchanged(a, b);
    Response r;
    r.P = collision_matrix(a, b).llt().solve(-(1.0 + e) * u);
    apply_impulse(a, b, &r);
    return r;
}

}  // namespace

Response2 unchanged(const ImpactBody2& a, const ImpactBody2& b) { return unchanged_nd<Response2>(a, b); }
Response3 unchanged(const ImpactBody3& a, const ImpactBody3& b) { return unchanged_nd<Response3>(a, b); }

Vec2 sticking_impulse(const Mat2& K, const Vec2& u, const Vec2& n, double e) { return sticking_impulse_nd(K, u, n, e); }
Vec3 sticking_impulse(const Mat3& K, const Vec3& u, const Vec3& n, double e) { return sticking_impulse_nd(K, u, n, e); }

Vec2 slip_direction(const Mat2& K, const Vec2& u, const Vec2& n) { return slip_direction_nd(K, u, n); }
Vec3 slip_direction(const Mat3& K, const Vec3& u, const Vec3& n) { return slip_direction_nd(K, u, n); }

double sliding_denominator(const Mat2& K, const Vec2& n, const Vec2& t, double mu) {
    return sliding_denominator_nd(K, n, t, mu);
}
double sliding_denominator(const Mat3& K, const Vec3& n, const Vec3& t, double mu) {
    return sliding_denominator_nd(K, n, t, mu);
}

Response2 coulomb(const ImpactBody2& a, const ImpactBody2& b, const Vec2& n, double e, double mu) {
    return coulomb_nd<Response2>(a, b, n, e, mu);
}
Response3 coulomb(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e, double mu) {
    return coulomb_nd<Response3>(a, b, n, e, mu);
}

Response2 matrix(const ImpactBody2& a, const ImpactBody2& b, const Vec2& n, double e) {
    return matrix_nd<Response2>(a, b, n, e);
}
Response3 matrix(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e) {
    return matrix_nd<Response3>(a, b, n, e);
}

}  // namespace collide
