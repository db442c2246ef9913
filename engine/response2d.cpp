// 2D collision response, with scalar cross products r x n = rx ny - ry nx and scalar inertia.
// Keep parallel to response3d.cpp. Conventions: response.h.
#include <Eigen/Cholesky>

#include "engine/response.h"

namespace collide {

Vec2 relative_velocity(const ImpactBody2& a, const ImpactBody2& b) { return point_velocity(b) - point_velocity(a); }

double rotational_term(const ImpactBody2& body, const Vec2& n) {
    const double rn = cross(body.r, n);
    return rn * rn * body.inv_I;
}

Mat2 collision_matrix(const ImpactBody2& a, const ImpactBody2& b) {
    const Vec2 pa = perp(a.r), pb = perp(b.r);
    return (a.inv_m + b.inv_m) * Mat2::Identity() + a.inv_I * pa * pa.transpose() + b.inv_I * pb * pb.transpose();
}

void apply_impulse(const ImpactBody2& a, const ImpactBody2& b, Response2* r) {
    r->va = a.v - a.inv_m * r->P;
    r->wa = a.w - a.inv_I * (cross(a.r, r->P) + r->couple);
    r->vb = b.v + b.inv_m * r->P;
    r->wb = b.w + b.inv_I * (cross(b.r, r->P) + r->couple);
}

Response2 unchanged(const ImpactBody2& a, const ImpactBody2& b) {
    Response2 r;
    r.separating = true;
    r.va = a.v;
    r.wa = a.w;
    r.vb = b.v;
    r.wb = b.w;
    return r;
}

Response2 frictionless(const ImpactBody2& a, const ImpactBody2& b, const Vec2& n, double e) {
    const double un = relative_velocity(a, b).dot(n);
    if (un >= 0.0) return unchanged(a, b);
    // Spin change per unit impulse along n, (r x n)/I: it gives both the rotational terms
    // (r x n)^2/I of the denominator and, times j, the final spins.
    const double rna = cross(a.r, n), rnb = cross(b.r, n);
    const double dwa = a.inv_I * rna, dwb = b.inv_I * rnb;
    const double denominator = a.inv_m + b.inv_m + rna * dwa + rnb * dwb;
    const double j = -(1.0 + e) * un / denominator;
    Response2 r;
    r.P = j * n;
    r.va = a.v - a.inv_m * r.P;
    r.wa = a.w - j * dwa;
    r.vb = b.v + b.inv_m * r.P;
    r.wb = b.w + j * dwb;
    return r;
}

Vec2 sticking_impulse(const Mat2& K, const Vec2& u, const Vec2& n, double e) {
    return K.llt().solve(-e * u.dot(n) * n - u);
}

Vec2 slip_direction(const Mat2& K, const Vec2& u, const Vec2& n) {
    Vec2 ut = u - u.dot(n) * n;
    if (ut.norm() <= 1e-12 * u.norm()) {
        const Vec2 Kn = K * n;
        ut = Kn - Kn.dot(n) * n;
    }
    const double len = ut.norm();
    return len > 0.0 ? Vec2(ut / len) : Vec2::Zero();
}

double sliding_denominator(const Mat2& K, const Vec2& n, const Vec2& t, double mu) { return n.dot(K * (n - mu * t)); }

Response2 coulomb(const ImpactBody2& a, const ImpactBody2& b, const Vec2& n, double e, double mu) {
    const Vec2 u = relative_velocity(a, b);
    const double un = u.dot(n);
    if (un >= 0.0) return unchanged(a, b);
    const Mat2 K = collision_matrix(a, b);
    Response2 r;
    r.P = sticking_impulse(K, u, n, e);
    const double Pn = r.P.dot(n);
    const double Pt = (r.P - Pn * n).norm();
    if (!(Pn >= 0.0 && Pt <= mu * Pn)) {
        const Vec2 t = slip_direction(K, u, n);
        const double denominator = sliding_denominator(K, n, t, mu);
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

Response2 matrix(const ImpactBody2& a, const ImpactBody2& b, const Vec2& n, double e) {
    const Vec2 u = relative_velocity(a, b);
    if (u.dot(n) >= 0.0) return unchanged(a, b);
    Response2 r;
    r.P = collision_matrix(a, b).llt().solve(-(1.0 + e) * u);
    apply_impulse(a, b, &r);
    return r;
}

static Response2 move_together(const ImpactBody2& a, const ImpactBody2& b, const Vec2& vp, double w) {
    Response2 r;
    r.va = vp - cross(w, a.r);
    r.vb = vp - cross(w, b.r);
    r.wa = w;
    r.wb = w;
    if (!b.is_static()) {
        r.P = (r.vb - b.v) / b.inv_m;
        r.couple = b.I * (r.wb - b.w) - cross(b.r, r.P);
    } else {
        r.P = -(r.va - a.v) / a.inv_m;
        r.couple = -(a.I * (r.wa - a.w)) - cross(a.r, r.P);
    }
    return r;
}

Combined2 combined_body(const ImpactBody2& a, const ImpactBody2& b) {
    Combined2 c;
    const double ma = 1.0 / a.inv_m, mb = 1.0 / b.inv_m;
    c.M = ma + mb;
    c.xc = (ma * -a.r + mb * -b.r) / c.M;
    c.da = -a.r - c.xc;
    c.db = -b.r - c.xc;
    // Parallel axis: I = Ic + m |d|^2.
    c.I = a.I + ma * c.da.squaredNorm() + b.I + mb * c.db.squaredNorm();
    c.v = (ma * a.v + mb * b.v) / c.M;
    c.L = a.I * a.w + ma * cross(c.da, a.v) + b.I * b.w + mb * cross(c.db, b.v);
    c.w = c.L / c.I;
    return c;
}

Response2 stick(const ImpactBody2& a, const ImpactBody2& b, const Vec2& n) {
    if (relative_velocity(a, b).dot(n) >= 0.0) return unchanged(a, b);
    if (a.is_static()) return move_together(a, b, point_velocity(a), a.w);
    if (b.is_static()) return move_together(a, b, point_velocity(b), b.w);
    const Combined2 c = combined_body(a, b);
    return move_together(a, b, c.v - cross(c.w, c.xc), c.w);
}

}  // namespace collide
