#include "engine/rotation.h"

#include <cmath>

#include "engine/trig.h"

namespace collide {

namespace {

// One implicit midpoint step of length h for (q, Lb):
//   Lb' = Lb + h (Lm x Ib^-1 Lm),  Lm = (Lb + Lb')/2;  q' = q exp(h Ib^-1 Lm)
// solved by fixed-point iteration to round-off (it contracts for h |w| < 1).
void midpoint_step(const Mat3& inv_Ib, double h, Quat* q, Vec3* Lb) {
    Vec3 next = *Lb;
    for (int i = 0; i < 50; ++i) {
        const Vec3 mid = 0.5 * (*Lb + next);
        const Vec3 candidate = *Lb + h * mid.cross(inv_Ib * mid);
        const double change = (candidate - next).norm();
        next = candidate;
        if (change <= 1e-16 * next.norm()) break;
    }
    const Vec3 mid = 0.5 * (*Lb + next);
    *q = (*q * exp_map(h * (inv_Ib * mid))).normalized();
    *Lb = next;
}

}  // namespace

// q = (cos(|phi|/2), sin(|phi|/2) phi/|phi|); the sine and cosine from engine/trig.h, so that
// every build turns bodies alike to the last bit.
Quat exp_map(const Vec3& phi) {
    const double angle = phi.norm();
    if (angle < 1e-300) return Quat::Identity();
    const SinCos half = sin_cos(0.5 * angle);
    const Vec3 v = (half.sin / angle) * phi;
    return Quat(half.cos, v.x(), v.y(), v.z());
}

void rotate_free(Body3* body, double dt, const RotationSettings& settings) {
    if (body->is_static || dt == 0.0) return;
    const Mat3& Ib = body->inertia;
    if (Ib == Mat3::Identity() * Ib(0, 0)) {
        // A sphere's inertia is isotropic: w stays constant and one exact turn does.
        body->orientation = (exp_map(body->w * dt) * body->orientation).normalized();
        return;
    }
    const Mat3 inv_Ib = inertia_pseudo_inverse(Ib);
    Quat q = body->orientation.normalized();
    Vec3 Lb = body->inertia * (q.conjugate() * body->w);
    const Vec3 wb = inv_Ib * Lb;
    if (wb.norm() == 0.0) return;
    const int n = std::max(1, static_cast<int>(std::ceil(wb.norm() * std::abs(dt) /
                                                         settings.max_angle_per_step)));
    const double h = dt / n;
    // Yoshida's triple jump: symmetric steps of g1 h, g2 h, g1 h (g2 < 0) give fourth order.
    const double c = std::cbrt(2.0), g1 = 1.0 / (2.0 - c), g2 = -c / (2.0 - c);
    for (int i = 0; i < n; ++i) {
        midpoint_step(inv_Ib, g1 * h, &q, &Lb);
        midpoint_step(inv_Ib, g2 * h, &q, &Lb);
        midpoint_step(inv_Ib, g1 * h, &q, &Lb);
    }
    body->orientation = q;
    body->w = q * (inv_Ib * Lb);
}

}  // namespace collide
