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
