// 3D collision response. Keep parallel to response2d.cpp. Conventions: response.h.
#include <Eigen/Cholesky>

#include "engine/response.h"

namespace collide {

Vec3 relative_velocity(const ImpactBody3& a, const ImpactBody3& b) { return point_velocity(b) - point_velocity(a); }

double rotational_term(const ImpactBody3& body, const Vec3& n) {
    const Vec3 rn = body.r.cross(n);
    return rn.dot(body.inv_I * rn);
}

Mat3 collision_matrix(const ImpactBody3& a, const ImpactBody3& b) {
    const Mat3 Ra = skew(a.r), Rb = skew(b.r);
    return (a.inv_m + b.inv_m) * Mat3::Identity() - Ra * a.inv_I * Ra - Rb * b.inv_I * Rb;
}

void apply_impulse(const ImpactBody3& a, const ImpactBody3& b, Response3* r) {
    r->va = a.v - a.inv_m * r->P;
    r->wa = a.w - a.inv_I * (a.r.cross(r->P) + r->couple);
    r->vb = b.v + b.inv_m * r->P;
    r->wb = b.w + b.inv_I * (b.r.cross(r->P) + r->couple);
}

Response3 frictionless(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e) {
    const double un = relative_velocity(a, b).dot(n);
    if (un >= 0.0) return unchanged(a, b);
    // Spin change per unit impulse along n, I^-1 (r x n): it gives both the rotational terms
    // (r x n).I^-1(r x n) of the denominator and, times j, the final spins (no second product).
    const Vec3 rna = a.r.cross(n), rnb = b.r.cross(n);
    const Vec3 dwa = a.inv_I * rna, dwb = b.inv_I * rnb;
    const double denominator = a.inv_m + b.inv_m + rna.dot(dwa) + rnb.dot(dwb);
    const double j = -(1.0 + e) * un / denominator;
    Response3 r;
    r.P = j * n;
    r.va = a.v - a.inv_m * r.P;
    r.wa = a.w - j * dwa;
    r.vb = b.v + b.inv_m * r.P;
    r.wb = b.w + j * dwb;
    return r;
}

// The combined rigid motion (v at point x, w) of the welded pair, evaluated for each body.
static Response3 move_together(const ImpactBody3& a, const ImpactBody3& b, const Vec3& vp, const Vec3& w) {
    // vp: velocity of the combined body's material point at the contact point p.
    // Body centres are at p - r, so v_body = vp + w x (-r).
    Response3 r;
    r.va = vp - w.cross(a.r);
    r.vb = vp - w.cross(b.r);
    r.wa = w;
    r.wb = w;
    if (!b.is_static()) {
        // Impulse on B and the couple beyond rb x P: dLb (about xb) = Ib dwb = rb x P + C.
        r.P = (r.vb - b.v) / b.inv_m;
        r.couple = b.I * (r.wb - b.w) - b.r.cross(r.P);
    } else {
        r.P = -(r.va - a.v) / a.inv_m;
        r.couple = -(a.I * (r.wa - a.w)) - a.r.cross(r.P);
    }
    return r;
}

Combined3 combined_body(const ImpactBody3& a, const ImpactBody3& b) {
    Combined3 c;
    const double ma = 1.0 / a.inv_m, mb = 1.0 / b.inv_m;
    c.M = ma + mb;
    c.xc = (ma * -a.r + mb * -b.r) / c.M;  // centres are at x - p = -r
    c.da = -a.r - c.xc;
    c.db = -b.r - c.xc;
    // Parallel axis: I = Ic + m (|d|^2 E - d d^T).
    auto shifted = [](const Mat3& I, double m, const Vec3& d) {
        return Mat3(I + m * (d.squaredNorm() * Mat3::Identity() - d * d.transpose()));
    };
    c.I = shifted(a.I, ma, c.da) + shifted(b.I, mb, c.db);
    c.v = (ma * a.v + mb * b.v) / c.M;
    c.L = a.I * a.w + ma * c.da.cross(a.v) + b.I * b.w + mb * c.db.cross(b.v);
    c.w = c.I.llt().solve(c.L);
    return c;
}

Response3 stick(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n) {
    if (relative_velocity(a, b).dot(n) >= 0.0) return unchanged(a, b);
    // A static partner carries the other body with its own (prescribed) motion.
    if (a.is_static()) return move_together(a, b, point_velocity(a), a.w);
    if (b.is_static()) return move_together(a, b, point_velocity(b), b.w);
    const Combined3 c = combined_body(a, b);
    // Velocity of the combined body at p: v + w x (p - xc) = v + w x (-xc).
    return move_together(a, b, c.v - c.w.cross(c.xc), c.w);
}

Mat6 newton_euler_matrix(const ImpactBody3& body) {
    const double m = 1.0 / body.inv_m;
    const Vec3 c = -body.r;  // centre of mass relative to the contact point
    const Mat3 C = skew(c);
    const Mat3 H = m * C;  // [h]x with h = m c
    Mat6 nem;
    nem.topLeftCorner<3, 3>() = body.I + m * C * C.transpose();
    nem.topRightCorner<3, 3>() = H;
    nem.bottomLeftCorner<3, 3>() = H.transpose();
    nem.bottomRightCorner<3, 3>() = m * Mat3::Identity();
    return nem;
}

Response3 stick_newton_euler(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n) {
    if (relative_velocity(a, b).dot(n) >= 0.0) return unchanged(a, b);
    if (a.is_static()) return move_together(a, b, point_velocity(a), a.w);
    if (b.is_static()) return move_together(a, b, point_velocity(b), b.w);
    // Each body's motion as the 6-vector (w, v at p).
    auto twist = [](const ImpactBody3& body) {
        Vec6 V;
        V << body.w, point_velocity(body);
        return V;
    };
    const Mat6 Na = newton_euler_matrix(a), Nb = newton_euler_matrix(b);
    const Vec6 V = (Na + Nb).llt().solve(Na * twist(a) + Nb * twist(b));
    return move_together(a, b, V.tail<3>(), V.head<3>());
}

}  // namespace collide
