#include "engine/rotation.h"

#include <cmath>
#include <cstdint>
#include <string>

#include "engine/run_error.h"
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
        const double change2 = (candidate - next).squaredNorm();
        next = candidate;
        if (change2 <= 1e-32 * next.squaredNorm()) break;  // |change| <= 1e-16 |next|
    }
    const Vec3 mid = 0.5 * (*Lb + next);
    *q = (*q * exp_map(h * (inv_Ib * mid))).normalized();
    *Lb = next;
}

}  // namespace

// q = (cos(|phi|/2), sin(|phi|/2) phi/|phi|). Up to 0.2 rad (a substep's turn: the common
// case) by the series in x = |phi|^2 / 4, which need no square root:
//   cos(|phi|/2) = 1 - x/2! + x^2/4! - x^3/6! + x^4/8! - x^5/10!,
//   sin(|phi|/2) / |phi| = (1 - x/3! + x^2/5! - x^3/7! + x^4/9! - x^5/11!) / 2,
// the terms left out below 3e-21 (x <= 0.01); beyond, by engine/trig.h. Either way the same to
// the last bit in every build.
Quat exp_map(const Vec3& phi) {
    const double angle2 = phi.squaredNorm();
    if (angle2 <= 0.04) {
        const double x = 0.25 * angle2;
        const double c =
            1.0 +
            x * (-1.0 / 2.0 + x * (1.0 / 24.0 + x * (-1.0 / 720.0 + x * (1.0 / 40320.0 + x * (-1.0 / 3628800.0)))));
        const double s =
            0.5 * (1.0 + x * (-1.0 / 6.0 + x * (1.0 / 120.0 +
                                                x * (-1.0 / 5040.0 + x * (1.0 / 362880.0 + x * (-1.0 / 39916800.0))))));
        return Quat(c, s * phi.x(), s * phi.y(), s * phi.z());
    }
    const double angle = std::sqrt(angle2);
    const SinCos half = sin_cos(0.5 * angle);
    const Vec3 v = (half.sin / angle) * phi;
    return Quat(half.cos, v.x(), v.y(), v.z());
}

namespace {

// The body-frame axis of a symmetric top's distinct moment (0, 1, 2), or -1: the inertia is
// diagonal in the body frame with exactly two principal moments equal and all three positive.
// (An isotropic inertia, a sphere's, is not a top: rotate_free turns it first.)
int symmetry_axis(const Mat3& Ib) {
    if (!(Ib - Mat3(Ib.diagonal().asDiagonal())).isZero(0.0)) return -1;
    const Vec3 d = Ib.diagonal();
    if (!(d.minCoeff() > 0.0)) return -1;
    for (int k = 0; k < 3; ++k) {
        const double a = d[(k + 1) % 3], b = d[(k + 2) % 3];
        if (a == b && d[k] != a) return k;
    }
    return -1;
}

}  // namespace

bool rotation_integrated(const Body3& body) {
    const Mat3& Ib = body.inertia;
    return !body.is_static && !body.w.isZero(0.0) && Ib != Mat3::Identity() * Ib(0, 0) && symmetry_axis(Ib) < 0;
}

std::uint64_t rotate_free(Body3* body, double dt, const RotationSettings& settings, std::uint64_t max_steps) {
    if (body->is_static || dt == 0.0) return 0;
    const Mat3& Ib = body->inertia;
    if (Ib == Mat3::Identity() * Ib(0, 0)) {
        // A sphere's inertia is isotropic: w stays constant and one exact turn does.
        body->orientation = (exp_map(body->w * dt) * body->orientation).normalized();
        return 1;
    }
    if (const int k = symmetry_axis(Ib); k >= 0) {
        // A symmetric top (moments I1 = I2 about the axes across its symmetry axis e3, I3 along
        // it): with L = R Ib R^T w fixed and L3 = L.e3 kept (Euler's third equation: I1 = I2),
        //     w = I^-1 L = L / I1 + L3 (1/I3 - 1/I1) e3,
        // a turn about the fixed L at |L| / I1 (precession) plus one about its own e3 at
        // b = L3 (1/I3 - 1/I1) (spin): q(t) = exp(L t / I1) q0 exp(e3_body b t), whose spin is
        // L / I1 + b q(t) e3_body. Exact for any dt.
        const double I1 = Ib((k + 1) % 3, (k + 1) % 3), I3 = Ib(k, k);
        const Quat q0 = body->orientation.normalized();
        const Vec3 Lb = Ib * (q0.conjugate() * body->w);
        const Vec3 L = q0 * Lb;
        const Vec3 e3 = Vec3::Unit(k);
        const double b = Lb[k] * (1.0 / I3 - 1.0 / I1);
        const Quat q = (exp_map(L * (dt / I1)) * q0 * exp_map(e3 * (b * dt))).normalized();
        body->orientation = q;
        body->w = L / I1 + b * (q * e3);
        return 1;
    }
    const Mat3 inv_Ib = inertia_pseudo_inverse(Ib);
    Quat q = body->orientation.normalized();
    Vec3 Lb = body->inertia * (q.conjugate() * body->w);
    const Vec3 wb = inv_Ib * Lb;
    if (wb.norm() == 0.0) return 0;
    // The count as a double first: a spin of 1e9 rad/s for 0.01 s is 2e9 steps, more than an
    // int holds (a cast would be undefined; it gave one giant step and NaN). A world passes
    // what its work budget has left (engine/scene.h, Scene::work_budget); beyond 2^53 no
    // 64-bit count is exact.
    const double steps = std::max(1.0, std::ceil(wb.norm() * std::abs(dt) / settings.max_angle_per_step));
    if (!(steps <= 0x1p53) || steps > static_cast<double>(max_steps))
        throw RunError("a free rotation of " + run_number(wb.norm()) + " rad/s for " + run_number(dt) +
                       " s would take " + run_number(steps) + " steps" +
                       (steps <= 0x1p53 ? ", more than the run's work budget has left" : ""));
    const auto n = static_cast<std::uint64_t>(steps);
    const double h = dt / steps;
    // Yoshida's triple jump: symmetric steps of g1 h, g2 h, g1 h (g2 < 0) give fourth order.
    const double c = 1.2599210498948732, g1 = 1.0 / (2.0 - c), g2 = -c / (2.0 - c);  // c = cbrt 2
    for (std::uint64_t i = 0; i < n; ++i) {
        midpoint_step(inv_Ib, g1 * h, &q, &Lb);
        midpoint_step(inv_Ib, g2 * h, &q, &Lb);
        midpoint_step(inv_Ib, g1 * h, &q, &Lb);
    }
    body->orientation = q;
    body->w = q * (inv_Ib * Lb);
    return n;
}

}  // namespace collide
