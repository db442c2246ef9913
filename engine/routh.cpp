// Routh's method (engine/routh.h). The impact is followed in the contact frame: index 0 along n,
// then the tangent(s) (2D: t = perp(n); 3D: t1, t2 = n x t1). There u, P and K are
//   u_c = R^T u,  P_c = R^T P,  K_c = R^T K R,  R = [n t] or [n t1 t2],
// so u_c[0] = u_n, P_c[0] = P_n, and dP_c = dP_n d with d = (1, tangential rate).
//
// This file: the straight stretches of an impact (slip in a fixed direction, stick, reversal)
// and their ends in closed form, the 2D method entire, and routh() for both dimensions. The 3D
// slip whose direction turns: routh_slip.cpp (its end in closed form: routh_slip_end.cpp); the
// state they share: routh_impact.h.
#include "engine/routh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "engine/routh_impact.h"

namespace collide {

const char* restitution_law_name(RestitutionLaw law) {
    switch (law) {
        case RestitutionLaw::newton: return "newton";
        case RestitutionLaw::poisson: return "poisson";
        case RestitutionLaw::stronge: return "stronge";
    }
    return "?";
}

bool parse_restitution_law(const std::string& name, RestitutionLaw* out) {
    for (RestitutionLaw law : {RestitutionLaw::newton, RestitutionLaw::poisson, RestitutionLaw::stronge}) {
        if (name == restitution_law_name(law)) {
            *out = law;
            return true;
        }
    }
    return false;
}

const char* routh_phase_name(RouthPhase::Kind kind) {
    switch (kind) {
        case RouthPhase::Kind::slip: return "slip";
        case RouthPhase::Kind::stick: return "stick";
        case RouthPhase::Kind::reverse: return "reverse";
    }
    return "?";
}

namespace routh_impl {

// ---- The straight stretches ----

// Normal impulse still to go in restitution along a straight stretch with du_n/dP_n = a > 0:
//   newton:  u_n + a h = -e un0                  -> h = (-e un0 - u_n) / a
//   poisson: P_n + h = (1 + e) P_c               -> h = (1 + e) P_c - P_n
//   stronge: W + u_n h + a h^2/2 = (1 - e^2) W_c (so that W_r = W - W_c = -e^2 W_c), the
//            positive root h = 2 R / (u_n + sqrt(u_n^2 + 2 a R)), R = (1 - e^2) W_c - W.
template <int D>
double Impact<D>::restitution_step(double a) const {
    switch (law) {
        case RestitutionLaw::newton: return a > 0.0 ? std::max(0.0, (restitution_target() - u[0]) / a) : kNever;
        case RestitutionLaw::poisson: return std::max(0.0, restitution_target() - Pn());
        case RestitutionLaw::stronge: {
            const double R = restitution_target() - W;
            if (R <= 0.0) return 0.0;
            const double un = std::max(0.0, u[0]), disc = un * un + 2.0 * a * R;
            if (disc < 0.0) return kNever;
            const double den = un + std::sqrt(disc);
            return den > 0.0 ? 2.0 * R / den : kNever;
        }
    }
    return kNever;
}

// Follow the straight stretch d until slip stops (after dP_stop: returns true) or the impact
// ends (returns false). Compression ends where u_n = 0: h = -u_n / a, a = (K d)_n; in
// restitution with a < 0 the approach resumes where u_n is back at 0: h = u_n / -a.
template <int D>
bool Impact<D>::run_linear(const V& d, double dP_stop) {
    const V Kd = K * d;
    const double a = Kd[0];
    for (;;) {
        double h_end;
        bool resumes = false;
        if (compressing) {
            h_end = a > 0.0 ? std::max(0.0, -u[0] / a) : kNever;
        } else {
            h_end = restitution_step(a);
            if (a < 0.0 && std::max(0.0, u[0] / -a) < h_end) {
                h_end = std::max(0.0, u[0] / -a);
                resumes = true;
            }
        }
        if (dP_stop < h_end) {
            advance(d, Kd, dP_stop);
            return true;
        }
        if (!(h_end < kNever)) {  // cannot happen on the stretches used (see routh())
            jammed = true;
            return false;
        }
        advance(d, Kd, h_end);
        dP_stop -= h_end;
        if (resumes) {
            resume_compression();
        } else if (compressing) {
            end_compression();
        } else {
            return false;
        }
    }
}

// No slip (u_t = 0): the rate lambda of tangential impulse that keeps u_t = 0 solves
//   K_tn + K_tt lambda = 0  ->  lambda = -K_tt^-1 K_tn.
// Sticking holds if |lambda| <= mu: d = (1, lambda); then du_n/dP_n = K_nn - K_nt K_tt^-1 K_tn
// (a Schur complement of K: positive). Otherwise the contact slides along the unit s for
// which the tangential velocity grows along s itself:
//   (K (n - mu s))_t = K_tn - mu K_tt s = kappa s, kappa > 0   (d = (1, -mu s)).
// 2D: s = sign(K_tn), kappa = |K_tn| - mu K_tt > 0. 3D: s = (kappa E + mu K_tt)^-1 K_tn with
// |s| = 1; in the eigenbasis of K_tt (eigenvalues k_i, components c_i of K_tn),
//   g(kappa) = sum c_i^2 / (kappa + mu k_i)^2 - 1 = 0,
// g is convex and decreasing for kappa >= 0, g(0) = |K_tt^-1 K_tn|^2 / mu^2 - 1 > 0 here
// (approximately: |lambda| > mu), so Newton's method from kappa = 0 climbs monotonically to
// the single root. On that ray u_t stays along s: the stretch is straight, and
// du_n/dP_n = K_nn - mu K_nt s > 0 (mu (kappa E + mu K_tt)^-1 < K_tt^-1), so it never jams.
template <int D>
auto Impact<D>::no_slip_direction(Kind* k) const -> V {
    V d = V::Zero();
    d[0] = 1.0;
    if constexpr (D == 2) {
        const double c = K(1, 0), Ktt = K(1, 1), lambda = -c / Ktt;
        if (std::abs(lambda) <= mu) {
            *k = Kind::stick;
            d[1] = lambda;
        } else {
            *k = Kind::reverse;
            d[1] = -mu * (c > 0.0 ? 1.0 : -1.0);
        }
    } else {
        const Eigen::Vector2d c = K.template block<2, 1>(1, 0);
        const Eigen::Matrix2d Ktt = K.template block<2, 2>(1, 1);
        const Eigen::Vector2d lambda = -Ktt.ldlt().solve(c);
        if (lambda.norm() <= mu) {
            *k = Kind::stick;
            d.template tail<2>() = lambda;
        } else {
            *k = Kind::reverse;
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig;
            eig.computeDirect(Ktt);
            const Eigen::Vector2d ci = eig.eigenvectors().transpose() * c;
            const Eigen::Vector2d ki = mu * eig.eigenvalues();
            double kappa = 0.0;
            for (int it = 0; it < 100; ++it) {
                double g = -1.0, dg = 0.0;
                for (int i = 0; i < 2; ++i) {
                    const double q = 1.0 / (kappa + ki[i]);
                    g += ci[i] * ci[i] * q * q;
                    dg -= 2.0 * ci[i] * ci[i] * q * q * q;
                }
                const double step = -g / dg;
                kappa += step;
                if (!(std::abs(step) > 1e-15 * kappa)) break;
            }
            Eigen::Vector2d s = eig.eigenvectors() * Eigen::Vector2d(ci[0] / (kappa + ki[0]), ci[1] / (kappa + ki[1]));
            s.normalize();
            d.template tail<2>() = -mu * s;
        }
    }
    return d;
}

// After slip stopped (or with none at the start): stick or slide on, to the end.
template <int D>
void Impact<D>::run_no_slip(bool at_start) {
    u.template tail<D - 1>().setZero();
    Kind k;
    const V d = no_slip_direction(&k);
    // Slip that starts at the first instant is the initial slip, not a reversal.
    begin(at_start && k == Kind::reverse ? Kind::slip : k);
    run_linear(d, kNever);
}

// The phase under way closed, and the detail filled in.
template <int D>
void Impact<D>::finish() {
    if (detail) {
        if (Pn() > from || detail->phases.empty()) detail->phases.push_back({kind, from, Pn()});
        detail->compression_impulse = Pc;
        detail->final_normal_impulse = Pn();
        detail->compression_work = Wc;
        detail->restitution_work = W - Wc;
        detail->energy_change = energy_change();
        detail->jammed = jammed;
        detail->slip_steps = slip_steps;
        detail->slip_end_in_closed_form = slip_end_closed;
        detail->slip_end_on_ray = slip_end_on_ray;
        detail->settled = settled;
    }
}

// Both dimensions' stretches (the 3D slip's files use them too).
template struct Impact<2>;
template struct Impact<3>;

}  // namespace routh_impl

namespace {

using namespace routh_impl;

// Relative size of |u_t| (to |u|) below which the contact counts as not slipping at the start:
// the same threshold as slip_direction().
constexpr double kNoSlip = 1e-12;

// u_c, K_c of the contact frame R (columns n, tangents), then Routh's integration.
template <int D>
Impact<D> integrate(const Eigen::Matrix<double, D, D>& R, const Eigen::Matrix<double, D, D>& Kw,
                    const Eigen::Matrix<double, D, 1>& uw, double e, double mu, RestitutionLaw law,
                    const RouthIntegration& how, RouthDetail* detail) {
    Impact<D> s;
    s.how = how;
    s.K = R.transpose() * Kw * R;
    s.u = R.transpose() * uw;
    s.e = e;
    s.mu = mu;
    s.law = law;
    s.u0 = s.u;
    s.un0 = s.u[0];
    s.detail = detail;
    if (detail) *detail = RouthDetail();
    const double ut = s.u.template tail<D - 1>().norm();
    if (ut <= kNoSlip * s.u.norm()) {
        s.run_no_slip(true);
    } else if constexpr (D == 2) {
        // Slip with sign s: d = (1, -mu s), u_t changes at b = K_tn - mu s K_tt; it stops after
        // h = -u_t / b if b has the opposite sign to u_t. While it slips, u_n changes at
        // a = K_nn - mu s K_nt, which may be <= 0 (a jam: the approach speeds up). That needs
        // mu s K_nt >= K_nn > K_nt^2 / K_tt, so s b = |K_nt| - mu K_tt < 0: slip always stops at
        // a finite impulse, and every later stretch has a > 0 (no_slip_direction()). 2D never
        // loops or jams.
        const double sgn = s.u[1] > 0.0 ? 1.0 : -1.0;
        const Eigen::Vector2d d(1.0, -mu * sgn);
        const double b = s.K(1, 0) - mu * sgn * s.K(1, 1);
        const double h_stop = b * sgn < 0.0 ? -s.u[1] / b : kNever;
        s.begin(Kind::slip);
        if (s.run_linear(d, h_stop)) s.run_no_slip(false);
    } else {
        s.begin(Kind::slip);
        bool stopped;
        if (mu == 0.0) {
            stopped = s.run_linear(Eigen::Vector3d::UnitX(), kNever);  // u_n linear: exact
        } else {
            stopped = s.run_slip_3d();
        }
        if (stopped) s.run_no_slip(false);
    }
    s.finish();
    return s;
}

// Whether the bodies approach along n (u_n < 0, false for a NaN). When they do not there is
// no impact, and no detail.
template <class V>
bool approaching(const V& u, const V& n, RouthDetail* detail) {
    if (u.dot(n) < 0.0) return true;
    if (detail) *detail = RouthDetail();
    return false;
}

// The contact frame R (file comment): its columns n, then t = perp(n) in 2D, or t1 (any unit
// vector orthogonal to n) and t2 = n x t1 in 3D.
Mat2 contact_frame(const Vec2& n) {
    Mat2 R;
    R.col(0) = n;
    R.col(1) = perp(n);
    return R;
}
Mat3 contact_frame(const Vec3& n) {
    Mat3 R;
    R.col(0) = n;
    R.col(1) = n.unitOrthogonal();
    R.col(2) = n.cross(R.col(1));
    return R;
}

}  // namespace

Response2 routh(const ImpactBody2& a, const ImpactBody2& b, const Vec2& n, double e, double mu, RestitutionLaw law,
                RouthDetail* detail) {
    const Vec2 u = relative_velocity(a, b);
    if (!approaching(u, n, detail)) return unchanged(a, b);
    const Mat2 R = contact_frame(n);
    const Impact<2> s = integrate<2>(R, collision_matrix(a, b), u, e, mu, law, RouthIntegration(), detail);
    Response2 r;
    r.P = R * s.P;
    r.sliding = s.kind != Kind::stick && std::abs(s.u[1]) > 0.0;
    apply_impulse(a, b, &r);
    return r;
}

Response3 routh(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e, double mu, RestitutionLaw law,
                RouthDetail* detail) {
    return routh(a, b, n, e, mu, law, RouthIntegration(), detail);
}

Response3 routh(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e, double mu, RestitutionLaw law,
                const RouthIntegration& how, RouthDetail* detail) {
    const Vec3 u = relative_velocity(a, b);
    if (!approaching(u, n, detail)) return unchanged(a, b);
    const Mat3 R = contact_frame(n);
    const Impact<3> s = integrate<3>(R, collision_matrix(a, b), u, e, mu, law, how, detail);
    if (s.jammed) {
        // A straight stretch on which compression cannot end (u_n falling as P_n grows: a
        // Painleve-like jam, which the stretches the integration takes never are, see
        // no_slip_direction() and finish_on_ray()): the frictionless impulse, flagged
        // `approximate` and said so wherever the answer is shown.
        Response3 r = frictionless(a, b, n, e);
        r.painleve = true;
        r.approximate = true;
        return r;
    }
    Response3 r;
    r.approximate = !s.settled;
    r.P = R * s.P;
    r.sliding = s.kind != Kind::stick && s.u.tail<2>().norm() > 0.0;
    apply_impulse(a, b, &r);
    return r;
}

}  // namespace collide
