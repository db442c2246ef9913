// Routh's method (engine/routh.h). The impact is followed in the contact frame: index 0 along n,
// then the tangent(s) (2D: t = perp(n); 3D: t1, t2 = n x t1). There u, P and K are
//   u_c = R^T u,  P_c = R^T P,  K_c = R^T K R,  R = [n t] or [n t1 t2],
// so u_c[0] = u_n, P_c[0] = P_n, and dP_c = dP_n d with d = (1, tangential rate).
#include "engine/routh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
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
    bool compressed = false;  // compression has ended at least once
    RouthDetail* detail = nullptr;
    RouthIntegration how;  // 3D: the slip's step tolerance and closed-form end
    bool ray_known = false;      // 3D slip: the ray it settles on, found (see find_ray())
    Eigen::Matrix<double, 2, 1> ray = Eigen::Matrix<double, 2, 1>::Zero();
    double cos_x_ok = -2.0;      // 3D slip: cos of |th - th*| below which its end may converge
    bool ray_missed = false;     // 3D slip: a search for the ray found none, at missed_at
    Eigen::Matrix<double, 2, 1> missed_at = Eigen::Matrix<double, 2, 1>::Zero();
    int slip_steps = 0;
    bool slip_end_closed = false;
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

    // u_n reaches 0 from below. In 3D the turning slip can make u_n fall again after that
    // (du_n/dP_n = K_nn - mu K_nt s changes sign with s): the approach resumes, and restitution
    // with it waits until u_n is back at 0. P_c and W_c are those of the deepest compression,
    // where W is least (Stronge's maximum compression: W is minus the energy the contact has
    // absorbed), so an approach that resumes but does not go deeper changes neither.
    void end_compression() {
        compressing = false;
        u[0] = 0.0;  // exactly, rather than to rounding
        if (!compressed || W < Wc) {
            Pc = Pn();
            Wc = W;
        }
        compressed = true;
    }
    // u_n falls back to 0 from above in restitution: the approach resumes.
    void resume_compression() {
        compressing = true;
        u[0] = 0.0;
    }

    // Normal impulse still to go in restitution along a straight stretch with du_n/dP_n = a > 0:
    //   newton:  u_n + a h = -e un0                  -> h = (-e un0 - u_n) / a
    //   poisson: P_n + h = (1 + e) P_c               -> h = (1 + e) P_c - P_n
    //   stronge: W + u_n h + a h^2/2 = (1 - e^2) W_c (so that W_r = W - W_c = -e^2 W_c), the
    //            positive root h = 2 R / (u_n + sqrt(u_n^2 + 2 a R)), R = (1 - e^2) W_c - W.
    double restitution_step(double a) const {
        switch (law) {
            case RestitutionLaw::newton:
                return a > 0.0 ? std::max(0.0, (restitution_target() - u[0]) / a) : kNever;
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
    bool run_linear(const V& d, double dP_stop) {
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
            detail->slip_steps = slip_steps;
            detail->slip_end_in_closed_form = slip_end_closed;
        }
    }

    // Delta E = integral of u . dP along the path, with u = u0 + K P:
    //   = u0 . P + P^T K P / 2, the same for every path since K is symmetric (u . dP is then
    //   the exact differential of that expression).
    double energy_change() const {
        return u0.dot(P) + 0.5 * P.dot(K * P);
    }

    // ---- 3D slip: the direction s = u_t/|u_t| turns. ----
    // With w = u_t (2 components) and q = |w|, the slip obeys dw/dP_n = K_tn - mu K_tt w/q,
    // whose direction turns ever faster (rate 1/q) as slip stops. Measured in the rescaled
    // impulse sigma, dP_n = q dsigma, every rate is a polynomial in the state:
    //   w'   = q K_tn - mu K_tt w     P_n' = q     P_t' = -mu w     u_n' = K_nn q - mu K_nt w
    // and D = integral of |u_t| dP_n (friction's loss) has D' = q^2 = w.w. The work of the normal
    // impulse needs no series of its own: with dE = integral of u . dP = energy_change(),
    //   W = integral of u_n dP_n = dE + mu D   (dE = W + integral of u_t . dP_t, dP_t = -mu s dP_n).
    // The system is smooth for every sigma (w shrinks at most exponentially, so slip that stops
    // does so at sigma = infinity), and it is integrated by Taylor series: the coefficients of
    // each quantity follow from those of lower order (q from q^2 = w.w), so one step of order
    // kOrder costs a few hundred multiplications and no sine, exponential or division by |w|.
    static constexpr int kOrder = 20;
    // Taylor coefficients in sigma, one row per quantity, then W and dE at the step's start.
    enum Row { kUn, kW1, kW2, kPn, kPt1, kPt2, kLoss, kQ, kRows };
    struct Series {
        double c[kRows][kOrder + 1];
        double W0, dE0;
        double* operator[](int r) { return c[r]; }
        const double* operator[](int r) const { return c[r]; }
    };
    static constexpr int kEndOrder = 20;  // the largest order of the slip's end (below)
    static constexpr int kMaxOrder = std::max(kOrder, kEndOrder);
    static constexpr std::array<double, kMaxOrder + 1> kInverse = [] {  // 1 / k
        std::array<double, kMaxOrder + 1> a{};
        for (int k = 1; k <= kMaxOrder; ++k) a[k] = 1.0 / k;
        return a;
    }();

    // The Taylor coefficients at the current state, order by order.
    void taylor(Series& s) const {
        const double c1 = K(1, 0), c2 = K(2, 0), knn = K(0, 0);
        const double a11 = K(1, 1), a12 = K(1, 2), a22 = K(2, 2);
        double* w1 = s[kW1];
        double* w2 = s[kW2];
        double* q = s[kQ];
        s[kUn][0] = u[0], w1[0] = u[1], w2[0] = u[2];
        s[kPn][0] = P[0], s[kPt1][0] = P[1], s[kPt2][0] = P[2], s[kLoss][0] = 0.0;
        s.W0 = W, s.dE0 = energy_change();
        double half_q0 = 0.0;  // 1 / (2 q_0)
        double s0[2] = {0.0, 0.0};  // w_0 / q_0, the slip direction
        for (int k = 0; k < kOrder; ++k) {
            // q^2 = w.w:  2 q_0 q_k = sum_j w_j . w_{k-j} - sum_{j=1}^{k-1} q_j q_{k-j}, each
            // symmetric sum taken once and doubled. The old terms are summed first, from the
            // oldest, in two accumulators each, and those with the newest coefficients (w_k,
            // q_{k-1}) last: only those wait for the previous order.
            double a0 = 0.0, a1 = 0.0, b0 = 0.0, b1 = 0.0, e0 = 0.0, e1 = 0.0;
            int j = (k - 1) / 2;  // the largest j with 2 j < k
            for (; j >= 2; j -= 2) {
                a0 += w1[j] * w1[k - j];
                a1 += w1[j - 1] * w1[k - j + 1];
                b0 += w2[j] * w2[k - j];
                b1 += w2[j - 1] * w2[k - j + 1];
                e0 += q[j] * q[k - j];
                if (j > 2) e1 += q[j - 1] * q[k - j + 1];
            }
            if (j == 1) {
                a1 += w1[1] * w1[k - 1];
                b1 += w2[1] * w2[k - 1];
            }
            if (k > 2) e1 += q[1] * q[k - 1];
            double mid_w = 0.0, mid_q = 0.0;  // the middle terms (even k), once
            if (k % 2 == 0) {
                mid_w = w1[k / 2] * w1[k / 2] + w2[k / 2] * w2[k / 2];
                if (k > 0) mid_q = q[k / 2] * q[k / 2];
            }
            // Everything but the newest term first, so that from w_k to w_{k+1} only
            //   q_k = old / (2 q_0) + (w_0 / q_0) . w_k,  w_{k+1} = (q_k K_tn - mu K_tt w_k) / (k+1)
            // remain (a few multiplications deep).
            const double old_p = k == 0 ? mid_w : 2.0 * ((a0 + a1) + (b0 + b1)) + mid_w;
            const double inv = kInverse[k + 1];
            const double m1 = -mu * inv * (a11 * w1[k] + a12 * w2[k]);
            const double m2 = -mu * inv * (a12 * w1[k] + a22 * w2[k]);
            double pk;
            if (k == 0) {
                pk = old_p;
                q[0] = std::sqrt(pk);
                half_q0 = 0.5 / q[0];
                s0[0] = w1[0] / q[0];
                s0[1] = w2[0] / q[0];
            } else {
                const double old_q = (old_p - (2.0 * (e0 + e1) + mid_q)) * half_q0;
                q[k] = old_q + (s0[0] * w1[k] + s0[1] * w2[k]);
                pk = old_p + 2.0 * (w1[0] * w1[k] + w2[0] * w2[k]);
            }
            const double qk = q[k];
            w1[k + 1] = c1 * inv * qk + m1;
            w2[k + 1] = c2 * inv * qk + m2;
            s[kPn][k + 1] = qk * inv;
            s[kPt1][k + 1] = -mu * w1[k] * inv;
            s[kPt2][k + 1] = -mu * w2[k] * inv;
            s[kUn][k + 1] = (knn * qk - mu * (c1 * w1[k] + c2 * w2[k])) * inv;
            s[kLoss][k + 1] = pk * inv;
        }
        q[kOrder] = 0.0;  // not needed beyond kOrder - 1
    }

    // The state (u, P, W) at sigma = t of the step: seven polynomials evaluated side by side.
    void load(const Series& s, double t) {
        double v[kQ];
        for (int i = 0; i < kQ; ++i) v[i] = s[i][kOrder];
        for (int k = kOrder - 1; k >= 0; --k)
            for (int i = 0; i < kQ; ++i) v[i] = v[i] * t + s[i][k];
        u << v[kUn], v[kW1], v[kW2];
        P << v[kPn], v[kPt1], v[kPt2];
        W = s.W0 + (energy_change() - s.dE0) + mu * v[kLoss];
    }

    // The event that ends the current stage, g reaching 0 from below:
    //   compression: g = u_n;  newton: g = u_n + e un0;  poisson: g = P_n - (1 + e) P_c;
    //   stronge: g = W - (1 - e^2) W_c.
    // The first three are polynomials in sigma (returned in g); Stronge's is found on the state
    // itself (restitution_end()), and this returns null.
    const double* event_series(const Series& s, double* g) const {
        if (!compressing && law == RestitutionLaw::stronge) return nullptr;
        const Row row = compressing || law == RestitutionLaw::newton ? kUn : kPn;
        std::copy(s[row], s[row] + kOrder + 1, g);
        if (!compressing) g[0] -= restitution_target();
        return g;
    }
    // The quantity whose target ends restitution (see event_series()), of the state (u_n, P_n, W).
    double restitution_quantity(double un, double Pn_, double W_) const {
        return law == RestitutionLaw::poisson ? Pn_ : law == RestitutionLaw::stronge ? W_ : un;
    }
    // The value of the stage's quantity that ends restitution (see event_series()).
    double restitution_target() const {
        switch (law) {
            case RestitutionLaw::newton: return -e * un0;
            case RestitutionLaw::poisson: return (1.0 + e) * Pc;
            case RestitutionLaw::stronge: return (1.0 - e * e) * Wc;
        }
        return 0.0;
    }

    // log2(v) to within 1e-7, for step lengths and estimates (v > 0 finite): v = m 2^e with
    // 1/sqrt(2) <= m < sqrt(2) (from the bits of v), ln m = 2 atanh(z) = 2 (z + z^3/3 + z^5/5 +
    // z^7/7 + ...), z = (m - 1)/(m + 1), |z| < 0.172.
    static double fast_log2(double v) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        int e = static_cast<int>((bits >> 52) & 0x7ff);
        if (e == 0) return fast_log2(v * 0x1p64) - 64.0;  // subnormal
        e -= 1023;
        bits = (bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL;
        double m;
        std::memcpy(&m, &bits, sizeof m);  // 1 <= m < 2
        if (m > 1.4142135623730951) {
            m *= 0.5;
            ++e;
        }
        const double z = (m - 1.0) / (m + 1.0), z2 = z * z;
        return e + 2.8853900817779268 * z * (1.0 + z2 * (1.0 / 3.0 + z2 * (0.2 + z2 / 7.0)));
    }

    static double horner(const double* x, double t) {
        double v = x[kOrder];
        for (int k = kOrder - 1; k >= 0; --k) v = v * t + x[k];
        return v;
    }
    // g(t) and g'(t) of a polynomial, side by side.
    static double poly(const double* g, double t, double* slope) {
        double v = g[kOrder], d = 0.0;
        for (int k = kOrder - 1; k >= 0; --k) {
            d = d * t + v;
            v = v * t + g[k];
        }
        *slope = d;
        return v;
    }

    // The first root in (0, h] of the polynomial g (g(0) < 0), or -1 if g stays negative.
    // g <= g_0 + sum of its positive terms at h on [0, h]: when that bound is negative there is
    // no root; otherwise g is sampled at 8 points (evaluated side by side) and the first bracket
    // refined by Newton's method with bisection as a guard.
    static double first_root(const double* g, double h) {
        // The bound by Horner's rule in h^2, even and odd terms side by side.
        const double h2 = h * h;
        double even = 0.0, odd = 0.0;
        for (int k = kOrder - (kOrder % 2); k >= 2; k -= 2) even = even * h2 + std::max(g[k], 0.0);
        for (int k = kOrder - 1 + (kOrder % 2); k >= 1; k -= 2) odd = odd * h2 + std::max(g[k], 0.0);
        if (g[0] + h2 * even + h * odd < 0.0) return -1.0;
        constexpr int kSamples = 8;
        double v[kSamples];
        for (int i = 0; i < kSamples; ++i) v[i] = g[kOrder];
        for (int k = kOrder - 1; k >= 0; --k)
            for (int i = 0; i < kSamples; ++i) v[i] = v[i] * (h * (i + 1) / kSamples) + g[k];
        double lo = 0.0, hi = -1.0;
        for (int i = 0; i < kSamples; ++i) {
            if (v[i] >= 0.0) {
                hi = h * (i + 1) / kSamples;
                break;
            }
            lo = h * (i + 1) / kSamples;
        }
        if (hi < 0.0) return -1.0;
        return bracketed_root([&](double t, double* rate) { return poly(g, t, rate); }, lo, hi,
                              0.5 * (lo + hi));
    }

    // The root of g in (lo, hi] (g(lo) < 0 <= g(hi)) from t: Newton's method on g(t, &rate),
    // each step kept inside the bracket (else bisection), to 1e-15 of hi or rounding.
    template <class G>
    static double bracketed_root(G g, double lo, double hi, double t) {
        bool close = false;  // the last Newton step was below 1e-8 of hi
        for (int it = 0; it < 100; ++it) {
            double rate;
            const double gt = g(t, &rate);
            if (gt >= 0.0) hi = t; else lo = t;
            const double newton_next = rate > 0.0 ? t - gt / rate : t;
            // A Newton step below 1e-15 of hi, or the step after one below 1e-8 (Newton's
            // method converging quadratically, that one is at rounding): done. (Checked before
            // the bracket, which the converged step may touch.)
            if (rate > 0.0 && (std::abs(newton_next - t) <= 1e-15 * hi || close))
                return std::clamp(newton_next, lo, hi);
            const bool newton = rate > 0.0 && newton_next > lo && newton_next < hi;
            const double next = newton ? newton_next : 0.5 * (lo + hi);
            close = newton && std::abs(next - t) <= 1e-8 * hi;
            t = next;
            if (hi - lo <= 1e-15 * hi) break;
        }
        return t;
    }

    // Stronge's end of restitution within the step, or -1: W - (1 - e^2) W_c, rising while
    // u_n > 0 (dW/dsigma = u_n q), is checked at the step's end and, if reached, found by
    // Newton's method on sigma with bisection as a guard.
    double restitution_end(const Series& s, double h) {
        const double target = restitution_target();
        load(s, h);
        if (W < target) return -1.0;
        return bracketed_root(
            [&](double t, double* rate) {
                load(s, t);
                *rate = u[0] * horner(s[kQ], t);
                return W - target;
            },
            0.0, h, h);
    }

    // ---- 3D slip: its end in closed form, as series about the ray it settles on ----
    // In polar form w = q s, s = (cos th, sin th), p = (-sin th, cos th), the slip equation
    // w' = q c - mu A w (c = K_tn, A = K_tt, ' = d/dsigma) splits into
    //   th' = G(th) = p.c - mu p.A s,     (ln q)' = F(th) = s.c - mu s.A s:
    // the direction obeys an equation of its own and moves monotonically to a zero th* of G
    // with G'(th*) < 0 (the ray that attracts it). With th as the variable, x = th - th*, the
    // rest of the slip is a set of quadratures:
    //   d ln q/dx = F/G,   dP_n = q dx/G,   dP_t = -mu s dP_n,   dD = q dP_n  (D = int q dP_n).
    // About th*, with s*, p* its s and p (s = s* cos x + p* sin x), sc = s*.c, pc = p*.c,
    // h = (s*.A s* - p*.A p*)/2, j = s*.A p*, m = tr A / 2:
    //   F(x) = sc cos x + pc sin x - mu (m + h cos 2x + j sin 2x),
    //   G(x) = pc cos x - sc sin x - mu (j cos 2x - h sin 2x) = x Gt(x)   (G(0) = 0),
    // Gt(0) = G'(th*) < 0. So F/G = Phi/x with Phi = F/Gt, alpha = Phi(0) = F(th*)/G'(th*), and
    // in y = x/x_now (1 now, 0 at th*), with E(y) = exp(sum_{k>=1} Phi_k x_now^k y^k / k) > 0:
    //   q = q_now y^alpha E(y)/E(1),   dP_n = -r y^(alpha-1) B(y) dy,   r = q_now/E(1),
    //   B = E/(-Gt) > 0.
    // The slip stops at th* (q -> 0 as y -> 0) when alpha > 0, i.e. F(th*) < 0. Integrated term
    // by term from the stop, what remains of the slip at y (t = y^alpha) is
    //   R_n = r t sum_k B_k y^k/(alpha+k),
    //   R_t = -mu r t sum_k (s* Bc_k + p* Bs_k) y^k/(alpha+k),
    //   R_D = r^2 t^2 sum_k BD_k y^k/(2 alpha+k),
    // where Bc = B cos(x_now y), Bs = B sin(x_now y), BD = E B; their rates are
    // dR_n/dt = (r/alpha) B(y), dR_t/dt = -(mu r/alpha)(s* Bc(y) + p* Bs(y)).
    // The series converge while |x_now| is below the distance from th* to the next (complex)
    // zero of G. They are taken to the order where their last two terms (at y = 1, the largest)
    // are within the tolerances of the Taylor steps, and refused if no order up to kEndOrder is.
    struct SlipEnd {
        double alpha = 0.0, r = 0.0, x0 = 0.0;  // x0 = x_now = th_now - th*
        Eigen::Vector2d s, p;                  // s*, p*
        int n = 0;                             // the series' order
        // B, Bc, Bs (the rates), and the tails of B/(alpha+k), Bc/(alpha+k), Bs/(alpha+k),
        // BD/(2 alpha+k): cB_i = sum_{k>i} B_k/(alpha+k) etc., and their sums at y = 1.
        double B[kEndOrder + 1], Bc[kEndOrder + 1], Bs[kEndOrder + 1];
        double cB[kEndOrder + 1], cBc[kEndOrder + 1], cBs[kEndOrder + 1], cBD[kEndOrder + 1];
        double B1 = 0.0, Bc1 = 0.0, Bs1 = 0.0, BD1 = 0.0;
        V u1, P1;  // the state where the end began (tau = 0)
        double W1 = 0.0;
    };
    // 1/k! and 2^k/k!, k = 0 .. kEndOrder + 1.
    static constexpr std::array<std::array<double, kEndOrder + 2>, 2> kFactorials = [] {
        std::array<std::array<double, kEndOrder + 2>, 2> a{};
        a[0][0] = a[1][0] = 1.0;
        for (int k = 1; k <= kEndOrder + 1; ++k) {
            a[0][k] = a[0][k - 1] / k;
            a[1][k] = a[1][k - 1] * 2.0 / k;
        }
        return a;
    }();

    // The ray s* = s(th*) the slip settles on (the slip's end, below), into `ray`: false if
    // none is found within 15/16 of half a turn. th* is the same for the whole slip (the
    // direction's equation is autonomous), so it is found once.
    bool find_ray(const Eigen::Vector2d& s0, const Eigen::Vector2d& c, const Eigen::Matrix2d& A) {
        const Eigen::Vector2d p0(-s0[1], s0[0]);
        // th*: the first zero of G from th_now on the side the slip turns to, dir = sign G(th_now).
        // With th = th_now + dir 2 atan(t) (t >= 0; half a turn is t = infinity),
        //   s = ((1 - t^2) s0 + 2 dir t p0)/(1 + t^2), and (1 + t^2)^2 G dir = M(t), a quartic:
        //   M = |G0| + a1 t + dir a2 t^2 + a3 t^3 + dir a4 t^4,
        //   a1 = -2 sc0 + 4 mu h0, a2 = 6 mu j0, a3 = -2 sc0 - 4 mu h0, a4 = -(pc0 + mu j0),
        // with sc0 = s0.c, pc0 = p0.c, h0 = (s0.A s0 - p0.A p0)/2, j0 = s0.A p0, G0 = pc0 - mu j0.
        // M's first sign change among 15 steps of th of pi/16 brackets th*; Newton's method with
        // bisection as a guard finds it there. (Two zeros within one step are passed over: the
        // series about the zero found beyond them do not converge and are refused.)
        const Eigen::Vector2d As0 = A * s0, Ap0 = A * p0;
        const double sc0 = s0.dot(c), pc0 = p0.dot(c), j0 = s0.dot(Ap0);
        const double h0 = 0.5 * (s0.dot(As0) - p0.dot(Ap0)), G0 = pc0 - mu * j0;
        const double dir = G0 >= 0.0 ? 1.0 : -1.0;
        const double m0 = std::abs(G0), m1 = -2.0 * sc0 + 4.0 * mu * h0, m2 = dir * 6.0 * mu * j0;
        const double m3 = -2.0 * sc0 - 4.0 * mu * h0, m4 = -dir * (pc0 + mu * j0);
        const auto M = [&](double t, double* slope) {
            *slope = ((4.0 * m4 * t + 3.0 * m3) * t + 2.0 * m2) * t + m1;
            return (((m4 * t + m3) * t + m2) * t + m1) * t + m0;
        };
        double t_star = 0.0;
        if (m0 > 0.0) {
            static constexpr std::array<double, 16> kGrid = {  // tan(i pi/32)
                0.0,                 0.09849140335716425, 0.19891236737965800,
                0.30334668360734239, 0.41421356237309503, 0.53451113595079159,
                0.66817863791929890, 0.82067879082866024, 1.0,
                1.21850352558797255, 1.49660576266548898, 1.87086841178938664,
                2.41421356237309492, 3.29655820893832213, 5.02733949212584761,
                10.15317038760883958};
            int i = 1;
            double slope;
            while (i < 16 && M(kGrid[i], &slope) > 0.0) ++i;
            if (i == 16) return false;  // no zero within 15/16 of half a turn
            t_star = bracketed_root(
                [&](double t, double* rate) {
                    const double v = -M(t, rate);
                    *rate = -*rate;
                    return v;
                },
                kGrid[i - 1], kGrid[i], 0.5 * (kGrid[i - 1] + kGrid[i]));
        }
        const double t2 = t_star * t_star, inv = 1.0 / (1.0 + t2);
        const Eigen::Vector2d ss = ((1.0 - t2) * inv) * s0 + (2.0 * dir * t_star * inv) * p0;
        ray = ss;
        ray_known = true;
        cos_x_ok = -2.0;
        return true;
    }

    // No series of the slip's end is tried again before |th - th*| < x (an estimate).
    void set_x_ok(double x) { cos_x_ok = x < 3.14159 ? std::cos(x) : -2.0; }

    // The series of the slip's end from the current state, into *f; false if they do not apply
    // (no attracting ray within reach, slip that does not stop on it, or series that do not
    // converge within kEndOrder). A refusal estimates how close to th* the series would
    // converge (x_ok), and none is tried again before the slip is that close.
    bool slip_end_series(const double tol[3], SlipEnd* f) {
        const Eigen::Vector2d w = u.template tail<2>();
        const double q0 = w.norm();
        if (!(q0 > 0.0)) return false;
        const Eigen::Vector2d s0 = w / q0;
        const Eigen::Vector2d c = K.template block<2, 1>(1, 0);
        const Eigen::Matrix2d A = K.template block<2, 2>(1, 1);
        if (!ray_known) {
            // After a search that found no ray, the next waits for a turn of pi/16 (its grid).
            if (ray_missed && s0.dot(missed_at) > 0.98078528040323043) return false;
            if (!find_ray(s0, c, A)) {
                ray_missed = true;
                missed_at = s0;
                return false;
            }
            ray_missed = false;
        }
        const Eigen::Vector2d ss = ray, pp(-ss[1], ss[0]);
        if (ss.dot(s0) < cos_x_ok) return false;  // |x0| > x_ok: not yet
        // x0 = th_now - th*; th* must lie on the side the direction turns to (G(th_now) x0 <= 0).
        const double x0 = std::atan2(ss[0] * s0[1] - ss[1] * s0[0], ss.dot(s0));
        if (x0 * Eigen::Vector2d(-s0[1], s0[0]).dot(c - mu * (A * s0)) > 0.0) {
            ray_known = false;  // th* passed or not the one ahead: look for it again next time
            return false;
        }
        const Eigen::Vector2d As = A * ss, Ap = A * pp;
        const double sc = ss.dot(c), pc = pp.dot(c), h = 0.5 * (ss.dot(As) - pp.dot(Ap));
        const double j = ss.dot(Ap), m = 0.5 * A.trace();
        const double tolP = tol[1], tolW = tol[2];
        // y^k coefficients of cos(x0 y), sin(x0 y), F(x0 y) and Gt(x0 y) = G(x0 y)/(x0 y): x^k
        // carries 1/k! (2^k/k! in cos 2x, sin 2x) and the sign of the k-th derivative of cos or
        // sin at 0; Gt_k is G's coefficient of x^(k+1), times x0^k.
        constexpr double kCos[4] = {1.0, 0.0, -1.0, 0.0}, kSin[4] = {0.0, 1.0, 0.0, -1.0};
        double Phi[kEndOrder + 1], E[kEndOrder + 1], BD[kEndOrder + 1];
        double Gt[kEndOrder + 1], Fk[kEndOrder + 1], cs[kEndOrder + 1], sn[kEndOrder + 1];
        double* const B = f->B;
        double* const Bc = f->Bc;
        double* const Bs = f->Bs;
        double xk = 1.0;  // x0^k
        const auto coefficients = [&](int k) {
            const double f1 = kFactorials[0][k] * xk, f2 = kFactorials[1][k] * xk;
            const double g1 = kFactorials[0][k + 1] * xk, g2 = kFactorials[1][k + 1] * xk;
            const double ck = kCos[k & 3], sk = kSin[k & 3];
            const double ck1 = kCos[(k + 1) & 3], sk1 = kSin[(k + 1) & 3];
            cs[k] = ck * f1, sn[k] = sk * f1;
            Fk[k] = (sc * ck + pc * sk) * f1 - mu * (h * ck + j * sk) * f2;
            Gt[k] = (pc * ck1 - sc * sk1) * g1 - mu * (j * ck1 - h * sk1) * g2;
            xk *= x0;
        };
        coefficients(0);
        Fk[0] -= mu * m;
        if (!(Gt[0] < 0.0)) return false;
        const double V0 = 1.0 / Gt[0];
        const double alpha = Fk[0] * V0;
        if (!(alpha > 0.0)) return false;  // the slip does not stop on this ray
        // How fast the series will converge, from that of 1/Gt: its coefficients fall as
        // (|x0|/rho)^k, rho the distance from th* to the nearest other zero of G (a simple pole
        // of 1/G), and so do the others' (whose singularities are there too). Terms of order k
        // are then about R rho_k, R ~ q0 B_0/alpha the whole rest; if order kEndOrder - 1 would
        // not bring them within tolerance, give up now (see set_x_ok()).
        constexpr int kProbe = 8;
        {
            double V[kProbe + 1];
            V[0] = V0;
            for (int k = 1; k <= kProbe; ++k) {
                coefficients(k);
                double acc = 0.0;
                for (int i = 1; i <= k; ++i) acc += Gt[i] * V[k - i];
                V[k] = -V0 * acc;
            }
            const double top = std::max({std::abs(V[kProbe - 2]), std::abs(V[kProbe - 1]),
                                         std::abs(V[kProbe])});
            const double log_ratio =
                top > 0.0 ? fast_log2(top / std::abs(V0)) / (kProbe - 1) : -kNever;
            const double log_tol = fast_log2(tolP * alpha / (q0 * -V0));
            if (log_ratio * (kEndOrder - 1) > log_tol) {
                set_x_ok(std::abs(x0) * std::exp2(log_tol / (kEndOrder - 1) - log_ratio));
                return false;
            }
        }
        // Order 0, then order by order: Phi = F/Gt, E = exp(int (Phi - Phi_0)/y) (that is,
        // k E_k = sum_{i=1..k} Phi_i E_{k-i}), B = -E/Gt, Bc + i Bs = B e^(i x0 y), BD = E B.
        // The terms of lower order are summed first, in one loop of independent sums; those
        // with the newest coefficients follow, in their order.
        Phi[0] = alpha;
        f->alpha = alpha;
        E[0] = 1.0;
        B[0] = -V0;
        Bc[0] = B[0], Bs[0] = 0.0, BD[0] = B[0];
        double E1 = 1.0, over_before = kNever, last[8];
        f->n = -1;
        const double q0B0 = q0 * B[0] * (1.0 + mu) / alpha;  // for the test of E(1) below
        last[0] = kNever;
        for (int k = 1; k <= kEndOrder; ++k) {
            if (k > kProbe) coefficients(k);
            double aPhi = Gt[k] * Phi[0], aB = Gt[k] * B[0], aE = 0.0, aD = 0.0;
            for (int i = 1; i < k; ++i) {
                aPhi += Gt[i] * Phi[k - i];
                aB += Gt[i] * B[k - i];
                aE += Phi[i] * E[k - i];
                aD += E[i] * B[k - i];
            }
            double aC = 0.0, aS = 0.0;  // cos has even terms only, sin odd ones
            for (int i = 2; i <= k; i += 2) aC += B[k - i] * cs[i];
            for (int i = 1; i <= k; i += 2) aS += B[k - i] * sn[i];
            Phi[k] = (Fk[k] - aPhi) * V0;
            E[k] = (Phi[k] + aE) * kInverse[k];
            B[k] = -(E[k] + aB) * V0;
            Bc[k] = B[k] + aC;
            Bs[k] = aS;
            BD[k] = B[k] + E[k] * B[0] + aD;
            E1 += E[k];
            // The last terms at y = 1 over their tolerances: r |B_k|/(alpha+k) (P_n), mu r
            // (|Bc_k| + |Bs_k|)/(alpha+k) (P_t), mu r^2 |BD_k|/(2 alpha+k) (W), and E(1)'s last
            // term relative to E(1) times the whole rest (1 + mu) R_n, R_n ~ r B_0/alpha.
            const double r = q0 / E1;
            const double over = std::max(
                {r * (std::abs(B[k]) + mu * (std::abs(Bc[k]) + std::abs(Bs[k]))) /
                     ((alpha + k) * tolP),
                 mu * r * r * std::abs(BD[k]) / ((2.0 * alpha + k) * tolW),
                 std::abs(E[k]) * q0B0 / (E1 * E1 * tolP)});
            last[k & 7] = std::max(over, over_before);  // the last two terms
            over_before = over;
            if (last[k & 7] <= 1.0) {
                f->n = k;
                break;
            }
            // At orders 8, 12, ...: if the last two terms, falling on at the rate they fell over
            // the last 4 orders, would still be over tolerance (by more than 2^4, the estimate
            // being rough) at kEndOrder, give up now. Terms of order k scale as x0^k, so the
            // series would converge by kEndOrder where |x0| is at_end^(1/kEndOrder) times less:
            // x_ok; none is tried again before the slip's direction is that close to s*.
            if (k >= 8 && k % 4 == 0) {
                const double l = fast_log2(last[k & 7]), l4 = fast_log2(last[(k - 4) & 7]);
                const double at_end = l + (l - l4) * (kEndOrder - k) * 0.25;
                if (at_end > 4.0) {
                    set_x_ok(std::abs(x0) * std::exp2(-at_end / kEndOrder));
                    break;
                }
            }
        }
        if (f->n < 0 || !(E1 > 0.0) || !std::isfinite(E1)) return false;
        const int n = f->n;
        f->r = q0 / E1;
        f->s = ss, f->p = pp, f->x0 = x0;
        // Tails from the top: cB_i = cB_{i+1} + B_{i+1}/(alpha+i+1); cB_-1 is the sum B1.
        double tb = 0.0, tc = 0.0, ts = 0.0, td = 0.0;
        for (int k = n; k >= 0; --k) {
            f->cB[k] = tb, f->cBc[k] = tc, f->cBs[k] = ts, f->cBD[k] = td;
            const double ia = 1.0 / (f->alpha + k);
            tb += f->B[k] * ia, tc += f->Bc[k] * ia, ts += f->Bs[k] * ia;
            td += BD[k] / (2.0 * f->alpha + k);
        }
        f->B1 = tb, f->Bc1 = tc, f->Bs1 = ts, f->BD1 = td;
        f->u1 = u, f->P1 = P, f->W1 = W;
        return true;
    }

    // The state at tau = 1 - t of the slip's end (0 where it began, 1 at the stop), and the rate
    // dP/dtau there. What the slip has used since it began is R(t = 1) - R(t); for each series
    // S(y) = sum_k S_k y^k/(alpha+k) (t y^k = y^(alpha+k)), without cancellation:
    //   S(1) - t S(y) = tau S(1) + t (S(1) - S(y)),  S(1) - S(y) = delta sum_i cS_i y^i,
    // delta = 1 - y = -expm1(log1p(-tau)/alpha) (S's divided difference, cS its tails); for D
    // (t^2 y^k): S(1) - t^2 S(y) = tau (2 - tau) S(1) + t^2 (S(1) - S(y)). Then
    //   P = P1 + dP,  u = u1 + K dP,  W = W1 + dP.(u1 + K dP/2) + mu dD
    // (W = dE + mu D, see taylor(); dE's change along a path from P1 is dP.(u1 + K dP/2)), and
    // dP/dtau = -dR/dt = (r/alpha) (B(y), -mu (s* Bc(y) + p* Bs(y))).
    void load_end(const SlipEnd& f, double tau, V* rate) {
        const double t = 1.0 - tau;
        const double delta = tau < 1.0 ? -std::expm1(std::log1p(-tau) / f.alpha) : 1.0;
        const double y = 1.0 - delta;
        double b = 0.0, bc = 0.0, bs = 0.0, qb = 0.0, qc = 0.0, qs = 0.0, qd = 0.0;
        for (int k = f.n; k >= 0; --k) {
            b = b * y + f.B[k], bc = bc * y + f.Bc[k], bs = bs * y + f.Bs[k];
            qb = qb * y + f.cB[k], qc = qc * y + f.cBc[k], qs = qs * y + f.cBs[k];
            qd = qd * y + f.cBD[k];
        }
        const double td = t * delta;
        const double used_c = tau * f.Bc1 + td * qc, used_s = tau * f.Bs1 + td * qs;
        V dP;
        dP << f.r * (tau * f.B1 + td * qb), -mu * f.r * (used_c * f.s + used_s * f.p);
        const double dD = f.r * f.r * (tau * (2.0 - tau) * f.BD1 + t * td * qd);
        const V Kdp = K * dP;
        P = f.P1 + dP;
        u = f.u1 + Kdp;
        W = f.W1 + dP.dot(f.u1 + 0.5 * Kdp) + mu * dD;
        const double ra = f.r / f.alpha;
        *rate << ra * b, -mu * ra * (bc * f.s + bs * f.p);
    }

    // How far the current stage is from its end (< 0 before it): u_n in compression, else the
    // restitution law's quantity (restitution_quantity()) minus its target.
    double stage_gap() const {
        return compressing ? u[0] : restitution_quantity(u[0], P[0], W) - restitution_target();
    }

    // The slip finished by its series (slip_end_series()), the stage ends on the way found on
    // them: returns 1 if the slip stopped, 0 if the impact ended first, -1 if the series do not
    // apply (the state untouched). Taken only where u_n rises with P_n all along the rest
    // (du_n/dP_n = K_nn - mu K_nt.s > 0 for s from s_now to s*): then every stage's quantity
    // (u_n; P_n; W, whose rate is u_n > 0 in restitution) rises with P_n, so a stage ends on the
    // way if and only if its quantity at the stop has reached its target, at the single root
    // of the gap in t (Newton's method with bisection as a guard, from the linear guess).
    int end_slip(const double tol[3]) {
        SlipEnd f;
        if (!slip_end_series(tol, &f)) return -1;
        {
            // K_nt.s(x) = a cos x + b sin x, largest at x = atan2(b, a) if that is between 0
            // and x0.
            const Eigen::Vector2d knt(K(0, 1), K(0, 2));
            const double a = knt.dot(f.s), b = knt.dot(f.p), x0 = f.x0;
            double top = std::max(a, a * std::cos(x0) + b * std::sin(x0));
            if (K(0, 0) <= mu * std::hypot(a, b)) {
                const double xm = std::atan2(b, a);
                if (xm * x0 > 0.0 && std::abs(xm) < std::abs(x0)) top = std::hypot(a, b);
            }
            if (!(K(0, 0) - mu * top > 0.0)) return -1;
        }
        double lo = 0.0;
        V rate;
        for (;;) {
            const double gap_lo = stage_gap();
            load_end(f, 1.0, &rate);
            const double gap_stop = stage_gap();
            if (gap_stop < 0.0) {
                u.template tail<2>().setZero();  // the stop, exactly
                return 1;
            }
            const auto gap = [&](double tau, double* slope) {
                load_end(f, tau, &rate);
                const V du = K * rate;
                *slope = compressing || law == RestitutionLaw::newton ? du[0]
                         : law == RestitutionLaw::poisson           ? rate[0]
                                                                      : u[0] * rate[0];
                return stage_gap();
            };
            const double tau = bracketed_root(
                gap, lo, 1.0, lo + (1.0 - lo) * -gap_lo / (gap_stop - gap_lo));
            double slope;
            gap(tau, &slope);
            if (!compressing) return 0;
            end_compression();
            if (stage_gap() >= 0.0) return 0;  // e = 0: restitution has nothing to do
            lo = tau;
        }
    }

    // Integrate the turning slip until it stops (returns true) or the impact ends. Each step's
    // length h makes the last two terms of every series at most kTol = 1e-11 (how.tolerance) of
    // its scale (|u0| for velocities, P_0 = -un0/K_nn for impulses, |u0| P_0 for the work), the
    // terms' decay then bounding the rest (Jorba and Zou's rule). A stage end inside a step is
    // found on the step's polynomial (bounded, sampled at 8 points, then Newton's method with
    // bisection as a guard). Before each step the rest of the slip is tried in closed form
    // (end_slip()); slip below kStopped = 10 kTol of |u0| counts as stopped (straight to the
    // stop if shrinking, its error |u_t| times the turn of s still to come; otherwise handed to
    // run_no_slip(), as slip that passes that close to 0 and turns away is the same within
    // |u_t|). Accuracy: the planar test holds the result to 1e-9 of the exact 2D answer; against
    // the same integration with kTol = 1e-13 and no closed form, over 3000 random impacts (mu up
    // to 1.5, every law; routh_test.cpp) the impulse differs by at most 2.3e-10 of it, 1.6e-11
    // where the closed form was taken.
    bool run_slip_3d() {
        const double kTol = how.tolerance;
        const double kStopped = 10.0 * kTol;
        constexpr int kMaxSteps = 500;  // beyond: jammed (see routh())
        const double uscale = u.norm(), Pscale = -un0 / K(0, 0);
        const double tol[3] = {kTol * uscale, kTol * Pscale, kTol * uscale * Pscale};
        const double inv_tol2[3] = {1.0 / (tol[0] * tol[0]), 1.0 / (tol[1] * tol[1]),
                                    1.0 / (tol[2] * tol[2])};
        Series s;
        double g[kOrder + 1];
        for (int step = 0; step < kMaxSteps; ++step) {
            const int end = how.closed_form_end ? end_slip(tol) : -1;
            if (end >= 0) {
                slip_end_closed = true;
                return end == 1;
            }
            const double len = u.template tail<2>().norm();
            if (len <= kStopped * uscale) {
                const Eigen::Vector2d dir = u.template tail<2>() / len;
                V d;
                d << 1.0, -mu * dir;
                const V Kd = K * d;
                const double rate = dir.dot(Kd.template tail<2>());  // d|u_t|/dP_n along d
                return rate < 0.0 ? run_linear(d, len / -rate) : true;
            }
            taylor(s);
            ++slip_steps;
            // Step length (Jorba and Zou): the last term of every group at most its tolerance,
            // h = (tol / |term_N|)^(1/N), then shortened if the term before it is still larger
            // at h (a last coefficient small by chance).
            const auto worst = [&](int k) {
                const auto sq = [&](Row r) { return s[r][k] * s[r][k]; };
                return std::max({(sq(kW1) + sq(kW2) + sq(kUn)) * inv_tol2[0],
                                 (sq(kPn) + sq(kPt1) + sq(kPt2)) * inv_tol2[1],
                                 mu * mu * sq(kLoss) * inv_tol2[2]});
            };
            // The term before, squared and over its tolerance, is before h^(2N-2) at h, so
            //   h = min(last^(-1/(2N)), before^(-1/(2N-2))),
            // by base-2 logarithms (fast_log2(): h to 1e-8 of itself).
            const double last = worst(kOrder), before = worst(kOrder - 1);
            const double log_h_last = last > 0.0 ? fast_log2(last) * (-0.5 / kOrder) : kNever;
            const double log_h_before =
                before > 0.0 ? fast_log2(before) * (-0.5 / (kOrder - 1)) : kNever;
            const double h = std::exp2(std::min(log_h_last, log_h_before));
            if (!(h < kNever)) {
                jammed = true;
                return false;
            }
            // (restitution_end(), finding no end, leaves the state at the step's end.)
            const bool by_series = event_series(s, g) != nullptr;
            const double t = by_series ? first_root(g, h) : restitution_end(s, h);
            if (!compressing) {  // the approach resuming: -u_n reaching 0 from below
                for (int k = 0; k <= kOrder; ++k) g[k] = -s[kUn][k];
                const double t_back = first_root(g, h);
                if (t_back >= 0.0 && (t < 0.0 || t_back < t)) {
                    load(s, t_back);
                    resume_compression();
                    continue;
                }
            }
            if (t < 0.0) {
                if (by_series) load(s, h);
                continue;
            }
            load(s, t);
            if (!compressing) return false;
            end_compression();
            // e = 0: restitution has nothing to do.
            if (restitution_quantity(u[0], P[0], W) >= restitution_target()) return false;
        }
        jammed = true;
        return false;
    }
};

// u_c, K_c of the contact frame R (columns n, tangents), then Routh's integration.
template <int D>
Impact<D> integrate(const Eigen::Matrix<double, D, D>& R, const Eigen::Matrix<double, D, D>& Kw,
                    const Eigen::Matrix<double, D, 1>& uw, double e, double mu,
                    RestitutionLaw law, const RouthIntegration& how, RouthDetail* detail) {
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
    const Impact<2> s =
        integrate<2>(R, collision_matrix(a, b), u, e, mu, law, RouthIntegration(), detail);
    Response2 r;
    r.P = R * s.P;
    r.sliding = s.kind != Kind::stick && std::abs(s.u[1]) > 0.0;
    apply_impulse(a, b, &r);
    return r;
}

Response3 routh(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e, double mu,
                RestitutionLaw law, RouthDetail* detail) {
    return routh(a, b, n, e, mu, law, RouthIntegration(), detail);
}

Response3 routh(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e, double mu,
                RestitutionLaw law, const RouthIntegration& how, RouthDetail* detail) {
    const Vec3 u = relative_velocity(a, b);
    if (!(u.dot(n) < 0.0)) {
        if (detail) *detail = RouthDetail();
        return unchanged(a, b);
    }
    Mat3 R;
    R.col(0) = n;
    R.col(1) = n.unitOrthogonal();
    R.col(2) = n.cross(R.col(1));
    const Impact<3> s = integrate<3>(R, collision_matrix(a, b), u, e, mu, law, how, detail);
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
