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
    static constexpr std::array<double, kOrder + 1> kInverse = [] {  // 1 / k
        std::array<double, kOrder + 1> a{};
        for (int k = 1; k <= kOrder; ++k) a[k] = 1.0 / k;
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

    // Slip close to its stop, along a direction near the ray s* that attracts it, finished in
    // closed form. With s = (cos th, sin th), s_perp = (-sin th, cos th), f = K_tn - mu K_tt s:
    //   d ln|w|/dsigma = F(th) = s.f,   d th/dsigma = G(th) = s_perp.f,
    //   F' = G - mu s.K_tt s_perp,      G' = -F - mu s_perp.K_tt s_perp   (d/dth).
    // s* has G = 0; Newton's step from th puts it at d = th - th* = G/G'. Slip stops along s* if
    // F* = F - F' d < 0 and s* attracts (G' < 0). Linearised about s* (a = -F*, g = -G'):
    //   d(sigma) = d e^(-g sigma),  |w| = r e^(-a sigma) (1 + (F' d/G') (e^(-g sigma) - 1)),
    // so over sigma = 0..infinity
    //   dP_n = r (1/a + k (1/(a+g) - 1/a)),      k = F' d / G'
    //   dP_t = -mu (dP_n s* + s*_perp r d / (a+g))          (w = |w| (s* + d s*_perp))
    //   dD   = r^2 (1/(2a) + 2k (1/(2a+g) - 1/(2a)))        (D = integral of |w| dP_n)
    // with errors of order dP_n d^2, and the work W = dE + mu D (dE = integral of u . dP:
    // energy_change()). Taken only where the turn still to come is small against the curvature
    // of F and G (|d| (1 + mu tr K_tt / g) <= 0.01), dP_n d^2 is under the impulse tolerance, and
    // the stage does not end on the way (its quantity, nearly linear there, still < 0). Against
    // the integration carried on to |u_t| = 1e-10 |u0|, over 6 10^4 random impacts, it differs by
    // at most 1e-12 of the impulse.
    bool close_slip(double tol_P) {
        const Eigen::Vector2d w = u.template tail<2>();
        const double r = w.norm();
        const Eigen::Vector2d s = w / r, sp(-s[1], s[0]);
        const Eigen::Vector2d c = K.template block<2, 1>(1, 0);
        const Eigen::Matrix2d A = K.template block<2, 2>(1, 1);
        const Eigen::Vector2d f = c - mu * (A * s);
        const double F = s.dot(f), G = sp.dot(f);
        const double Fp = G - mu * s.dot(A * sp), Gp = -F - mu * sp.dot(A * sp);
        if (!(Gp < 0.0)) return false;
        const double d = G / Gp, a = -(F - Fp * d), g = -Gp;
        const double kappa = mu * A.trace();
        if (!(a > 0.0) || std::abs(d) * (1.0 + kappa / g) > 1e-2) return false;
        const double k = Fp * d / Gp;
        const double dPn = r * (1.0 / a + k * (1.0 / (a + g) - 1.0 / a));
        if (dPn * d * d > tol_P) return false;
        const Eigen::Vector2d ss = std::cos(d) * s - std::sin(d) * sp, ssp(-ss[1], ss[0]);
        V dP;
        dP << dPn, -mu * (dPn * ss + ssp * (r * d / (a + g)));
        const double dD =
            r * r * (0.5 / a + 2.0 * k * (1.0 / (2.0 * a + g) - 0.5 / a));
        const V u1 = u + K * dP;
        const V P1 = P + dP;
        const double E0 = energy_change();
        const V P0 = P;
        P = P1;
        const double W1 = W + (energy_change() - E0) + mu * dD;
        P = P0;
        const double now = compressing ? u1[0] : restitution_quantity(u1[0], P1[0], W1);
        if (now >= (compressing ? 0.0 : restitution_target())) return false;
        u = u1;
        u.template tail<2>().setZero();
        P = P1;
        W = W1;
        return true;
    }

    // Integrate the turning slip until it stops (returns true) or the impact ends. Each step's
    // length h makes the last two terms of every series at most kTol = 1e-11 of its scale (|u0|
    // for velocities, P_0 = -un0/K_nn for impulses, |u0| P_0 for the work), the terms' decay then
    // bounding the rest (Jorba and Zou's rule). A stage end inside a step is found on the step's
    // polynomial (bounded, sampled at 8 points, then Newton's method with bisection as a guard).
    // Slip near its stop is finished by close_slip(); slip below kStopped |u0| counts as stopped
    // (straight to the stop if shrinking, its error |u_t| times the turn of s still to come;
    // otherwise handed to run_no_slip(), as slip that passes that close to 0 and turns away is
    // the same within |u_t|). Accuracy: the planar test holds the result to 1e-9 of the exact
    // 2D answer; against the same integration with kTol = 1e-13 and no closed-form finish, over
    // 3 10^4 random impacts (mu up to 1.5, every law) the impulse differs by at most 3e-10 of it.
    bool run_slip_3d() {
        constexpr double kTol = 1e-11;
        constexpr double kStopped = 1e-10;
        constexpr int kMaxSteps = 500;  // beyond: jammed (see routh())
        const double uscale = u.norm(), Pscale = -un0 / K(0, 0);
        const double tol[3] = {kTol * uscale, kTol * Pscale, kTol * uscale * Pscale};
        const double inv_tol2[3] = {1.0 / (tol[0] * tol[0]), 1.0 / (tol[1] * tol[1]),
                                    1.0 / (tol[2] * tol[2])};
        Series s;
        double g[kOrder + 1];
        for (int step = 0; step < kMaxSteps; ++step) {
            if (close_slip(tol[1])) return true;
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
            const double h = std::exp2(std::min(last > 0.0 ? fast_log2(last) * (-0.5 / kOrder) : kNever,
                                                before > 0.0 ? fast_log2(before) * (-0.5 / (kOrder - 1))
                                                             : kNever));
            if (!(h < kNever)) {
                jammed = true;
                return false;
            }
            const double t = event_series(s, g) ? first_root(g, h) : restitution_end(s, h);
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
                load(s, h);
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
