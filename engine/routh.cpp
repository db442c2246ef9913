// Routh's method (engine/routh.h). The impact is followed in the contact frame: index 0 along n,
// then the tangent(s) (2D: t = perp(n); 3D: t1, t2 = n x t1). There u, P and K are
//   u_c = R^T u,  P_c = R^T P,  K_c = R^T K R,  R = [n t] or [n t1 t2],
// so u_c[0] = u_n, P_c[0] = P_n, and dP_c = dP_n d with d = (1, tangential rate).
#include "engine/routh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

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
    for (RestitutionLaw law :
         {RestitutionLaw::newton, RestitutionLaw::poisson, RestitutionLaw::stronge}) {
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

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
// Relative size of |u_t| (to |u|) below which the contact counts as not slipping at the start:
// the same threshold as slip_direction().
constexpr double kNoSlip = 1e-12;

using Kind = RouthPhase::Kind;

// The state of one impact, over the normal impulse P_n, in the contact frame (D = 2 or 3).
template <int D>
struct Impact {
    using V = Eigen::Matrix<double, D, 1>;
    using M = Eigen::Matrix<double, D, D>;

    M K;  // K_c
    double e = 0.0, mu = 0.0;
    RestitutionLaw law = RestitutionLaw::newton;
    double un0 = 0.0;
    V u0 = V::Zero();                // u_c before the impact
    V u = V::Zero(), P = V::Zero();  // u_c now, P_c so far (P[0] = P_n)
    double W = 0.0;                  // work of the normal impulse so far, integral u_n dP_n
    double Pc = 0.0, Wc = 0.0;       // P_n and W at the end of compression
    bool compressing = true, jammed = false;
    RouthDetail* detail = nullptr;
    Kind kind = Kind::slip;
    double from = 0.0;  // P_n where the current phase began

    double Pn() const { return P[0]; }

    void begin(Kind k) {
        if (detail && Pn() > from) detail->phases.push_back({kind, from, Pn()});
        kind = k;
        from = Pn();
    }

    // Straight stretch dP = d dP_n: du = K d dP_n, so u_n grows at the rate a = (K d)_n and
    //   W(h) = W + u_n h + a h^2 / 2  (the work of the normal impulse is quadratic in h).
    void advance(const V& d, const V& Kd, double h) {
        W += u[0] * h + 0.5 * Kd[0] * h * h;
        u += Kd * h;
        P += d * h;
    }

    void end_compression() {
        compressing = false;
        u[0] = 0.0;  // exactly, rather than to rounding
        Pc = Pn();
        Wc = W;
    }

    // Normal impulse still to go in restitution along a straight stretch with du_n/dP_n = a > 0:
    //   newton:  u_n + a h = -e un0                  -> h = (-e un0 - u_n) / a
    //   poisson: P_n + h = (1 + e) P_c               -> h = (1 + e) P_c - P_n
    //   stronge: W + u_n h + a h^2/2 = (1 - e^2) W_c (so that W_r = W - W_c = -e^2 W_c), the
    //            positive root h = 2 R / (u_n + sqrt(u_n^2 + 2 a R)), R = (1 - e^2) W_c - W.
    double restitution_step(double a) const {
        switch (law) {
            case RestitutionLaw::newton:
                return a > 0.0 ? std::max(0.0, (-e * un0 - u[0]) / a) : kNever;
            case RestitutionLaw::poisson: return std::max(0.0, (1.0 + e) * Pc - Pn());
            case RestitutionLaw::stronge: {
                const double R = (1.0 - e * e) * Wc - W;
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
    // ends (returns false). Compression ends where u_n = 0: h = -u_n / a, a = (K d)_n.
    bool run_linear(const V& d, double dP_stop) {
        const V Kd = K * d;
        const double a = Kd[0];
        for (;;) {
            const double h_end = compressing ? (a > 0.0 ? std::max(0.0, -u[0] / a) : kNever)
                                             : restitution_step(a);
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
            if (!compressing) return false;
            end_compression();
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
    V no_slip_direction(Kind* k) const {
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
                Eigen::Vector2d s = eig.eigenvectors() *
                                    Eigen::Vector2d(ci[0] / (kappa + ki[0]), ci[1] / (kappa + ki[1]));
                s.normalize();
                d.template tail<2>() = -mu * s;
            }
        }
        return d;
    }

    // After slip stopped (or with none at the start): stick or slide on, to the end.
    void run_no_slip(bool at_start) {
        u.template tail<D - 1>().setZero();
        Kind k;
        const V d = no_slip_direction(&k);
        // Slip that starts at the first instant is the initial slip, not a reversal.
        begin(at_start && k == Kind::reverse ? Kind::slip : k);
        run_linear(d, kNever);
    }

    void finish() {
        if (detail) {
            if (Pn() > from || detail->phases.empty()) detail->phases.push_back({kind, from, Pn()});
            detail->compression_impulse = Pc;
            detail->final_normal_impulse = Pn();
            detail->compression_work = Wc;
            detail->restitution_work = W - Wc;
            detail->energy_change = energy_change();
            detail->jammed = jammed;
        }
    }

    // Delta E = integral of u . dP along the path, with u = u0 + K P:
    //   = u0 . P + P^T K P / 2, the same for every path since K is symmetric (u . dP is then
    //   the exact differential of that expression).
    double energy_change() const {
        return u0.dot(P) + 0.5 * P.dot(K * P);
    }

    // ---- 3D slip: the direction s = u_t/|u_t| turns; integrate y = (u, P, W) over P_n. ----
    using Y = Eigen::Matrix<double, 2 * D + 1, 1>;

    Y rate(const Y& y) const {
        V d = V::Zero();
        d[0] = 1.0;
        const V ut_full = y.template head<D>();
        Eigen::Matrix<double, D - 1, 1> ut = ut_full.template tail<D - 1>();
        const double len = ut.norm();
        if (len > 0.0) d.template tail<D - 1>() = -mu * ut / len;
        Y f;
        f.template head<D>() = K * d;
        f.template segment<D>(D) = d;
        f[2 * D] = y[0];
        return f;
    }

    // The event that ends the current stage, g(y) reaching 0 from below, with its predicted
    // distance from the rates (u_n' = a, W' = u_n, W'' = a):
    //   compression: g = u_n;  newton: g = u_n + e un0;  poisson: g = P_n - (1 + e) P_c;
    //   stronge: g = W - (1 - e^2) W_c.
    double event_g(const Y& y) const {
        if (compressing) return y[0];
        switch (law) {
            case RestitutionLaw::newton: return y[0] + e * un0;
            case RestitutionLaw::poisson: return y[D] - (1.0 + e) * Pc;
            case RestitutionLaw::stronge: return y[2 * D] - (1.0 - e * e) * Wc;
        }
        return 0.0;
    }
    double event_h(double a) const {
        if (compressing) return a > 0.0 ? std::max(0.0, -u[0] / a) : kNever;
        return restitution_step(a);
    }

    void load(const Y& y) {
        u = y.template head<D>();
        P = y.template segment<D>(D);
        W = y[2 * D];
    }
    Y store() const {
        Y y;
        y << u, P, W;
        return y;
    }

    // Integrate the turning slip (Dormand-Prince 5(4), local error per step <= kTol relative to
    // the scales |u0|, P_0 = -un0/K_nn and |u0| P_0; the planar test holds the result to 1e-9 of
    // the exact 2D answer). Slip stop is an event with a kink (|u_t| reaches 0 at a finite rate
    // r = d|u_t|/dP_n < 0): steps are kept to 0.7 |u_t|/(-r) so that none crosses it, and once
    // |u_t| < 1e-10 |u0| the last stretch |u_t|/(-r) is taken straight (its error is |u_t| times
    // the turn of s over it). Stage ends (u_n = 0, the law's end) are landed on by steps of the
    // predicted length, the last one (< 1e-7 P_0) straight. Returns true when slip stopped.
    bool run_slip_3d() {
        constexpr double kTol = 1e-11;
        constexpr int kMaxSteps = 4000;  // beyond: jammed (see routh())
        const double uscale = u.norm(), Pscale = -un0 / K(0, 0);
        Y scale;
        scale.template head<D>().setConstant(uscale);
        scale.template segment<D>(D).setConstant(Pscale);
        scale[2 * D] = uscale * Pscale;
        Y y = store();
        double h = 0.05 * Pscale;
        for (int step = 0; step < kMaxSteps; ++step) {
            const Y k1 = rate(y);
            const Eigen::Matrix<double, D - 1, 1> ut = y.template segment<D - 1>(1);
            const double len = ut.norm();
            const double r = len > 0.0 ? ut.dot(k1.template segment<D - 1>(1)) / len : -1.0;
            const double h_stop = r < 0.0 ? len / -r : kNever;
            load(y);
            const double h_event = event_h(k1[0]);
            if (h_stop <= h_event && len <= 1e-10 * uscale) {
                y += h_stop * k1;  // straight to the stop
                load(y);
                return true;
            }
            if (h_event <= h_stop && h_event <= 1e-7 * Pscale) {
                y += h_event * k1;  // straight onto the stage's end
                load(y);
                if (!compressing) return false;
                end_compression();
                y = store();
                continue;
            }
            double hh = std::min({h, h_event, 0.7 * h_stop});
            // Dormand-Prince 5(4) tableau.
            const Y k2 = rate(y + hh * (1.0 / 5) * k1);
            const Y k3 = rate(y + hh * (3.0 / 40 * k1 + 9.0 / 40 * k2));
            const Y k4 = rate(y + hh * (44.0 / 45 * k1 - 56.0 / 15 * k2 + 32.0 / 9 * k3));
            const Y k5 = rate(y + hh * (19372.0 / 6561 * k1 - 25360.0 / 2187 * k2 +
                                        64448.0 / 6561 * k3 - 212.0 / 729 * k4));
            const Y k6 = rate(y + hh * (9017.0 / 3168 * k1 - 355.0 / 33 * k2 +
                                        46732.0 / 5247 * k3 + 49.0 / 176 * k4 -
                                        5103.0 / 18656 * k5));
            const Y y5 = y + hh * (35.0 / 384 * k1 + 500.0 / 1113 * k3 + 125.0 / 192 * k4 -
                                   2187.0 / 6784 * k5 + 11.0 / 84 * k6);
            const Y k7 = rate(y5);
            const Y err = hh * (71.0 / 57600 * k1 - 71.0 / 16695 * k3 + 71.0 / 1920 * k4 -
                                17253.0 / 339200 * k5 + 22.0 / 525 * k6 - 1.0 / 40 * k7);
            const double en = (err.cwiseQuotient(scale)).cwiseAbs().maxCoeff() / kTol;
            const double grow = en > 0.0 ? 0.9 * std::pow(en, -0.2) : 5.0;
            if (en > 1.0) {
                h = hh * std::max(0.2, grow);
                continue;
            }
            const Eigen::Matrix<double, D - 1, 1> ut5 = y5.template segment<D - 1>(1);
            if (ut5.dot(ut) <= 0.0) {  // crossed the stop: shorter step
                h = 0.5 * hh;
                continue;
            }
            const double g5 = event_g(y5);
            if (g5 > 0.0) {  // past the stage's end: secant towards it
                const double g0 = event_g(y);
                h = hh * std::clamp(-g0 / (g5 - g0), 0.1, 0.9);
                continue;
            }
            y = y5;
            h = hh * std::min(5.0, grow);
        }
        load(y);
        jammed = true;
        return false;
    }
};

// u_c, K_c of the contact frame R (columns n, tangents), then Routh's integration.
template <int D>
Impact<D> integrate(const Eigen::Matrix<double, D, D>& R, const Eigen::Matrix<double, D, D>& Kw,
                    const Eigen::Matrix<double, D, 1>& uw, double e, double mu,
                    RestitutionLaw law, RouthDetail* detail) {
    Impact<D> s;
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

}  // namespace

Response2 routh(const ImpactBody2& a, const ImpactBody2& b, const Vec2& n, double e, double mu,
                RestitutionLaw law, RouthDetail* detail) {
    const Vec2 u = relative_velocity(a, b);
    if (!(u.dot(n) < 0.0)) {
        if (detail) *detail = RouthDetail();
        return unchanged(a, b);
    }
    Mat2 R;
    R.col(0) = n;
    R.col(1) = perp(n);
    const Impact<2> s = integrate<2>(R, collision_matrix(a, b), u, e, mu, law, detail);
    Response2 r;
    r.P = R * s.P;
    r.sliding = s.kind != Kind::stick && std::abs(s.u[1]) > 0.0;
    apply_impulse(a, b, &r);
    return r;
}

Response3 routh(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e, double mu,
                RestitutionLaw law, RouthDetail* detail) {
    const Vec3 u = relative_velocity(a, b);
    if (!(u.dot(n) < 0.0)) {
        if (detail) *detail = RouthDetail();
        return unchanged(a, b);
    }
    Mat3 R;
    R.col(0) = n;
    R.col(1) = n.unitOrthogonal();
    R.col(2) = n.cross(R.col(1));
    const Impact<3> s = integrate<3>(R, collision_matrix(a, b), u, e, mu, law, detail);
    if (s.jammed) {
        // The turning slip neither stopped nor let compression end within kMaxSteps steps (a
        // Painleve-like jam the integration does not resolve): the frictionless impulse, flagged.
        Response3 r = frictionless(a, b, n, e);
        r.painleve = true;
        return r;
    }
    Response3 r;
    r.P = R * s.P;
    r.sliding = s.kind != Kind::stick && s.u.tail<2>().norm() > 0.0;
    apply_impulse(a, b, &r);
    return r;
}

}  // namespace collide
