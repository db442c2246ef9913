// Routh's method in 3D (engine/routh.h, routh_impact.h): slip whose direction s = u_t/|u_t| turns.
//
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
#include <algorithm>
#include <cmath>

#include "engine/polynomial.h"
#include "engine/routh_impact.h"

namespace collide::routh_impl {

using polynomial::bracketed_root;
using polynomial::fast_log2;
using polynomial::first_root;

// The Taylor coefficients at the current state, order by order.
template <int D>
void Impact<D>::taylor(Series& s) const {
    const double c1 = K(1, 0), c2 = K(2, 0), knn = K(0, 0);
    const double a11 = K(1, 1), a12 = K(1, 2), a22 = K(2, 2);
    double* w1 = s[kW1];
    double* w2 = s[kW2];
    double* q = s[kQ];
    s[kUn][0] = u[0], w1[0] = u[1], w2[0] = u[2];
    s[kPn][0] = P[0], s[kPt1][0] = P[1], s[kPt2][0] = P[2], s[kLoss][0] = 0.0;
    s.W0 = W, s.dE0 = energy_change();
    double half_q0 = 0.0;       // 1 / (2 q_0)
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
template <int D>
void Impact<D>::load(const Series& s, double t) {
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
template <int D>
const double* Impact<D>::event_series(const Series& s, double* g) const {
    if (!compressing && law == RestitutionLaw::stronge) return nullptr;
    const Row row = compressing || law == RestitutionLaw::newton ? kUn : kPn;
    std::copy(s[row], s[row] + kOrder + 1, g);
    if (!compressing) g[0] -= restitution_target();
    return g;
}

// Stronge's end of restitution within the step, or -1: W - (1 - e^2) W_c, rising while
// u_n > 0 (dW/dsigma = u_n q), is checked at the step's end and, if reached, found by
// Newton's method on sigma with bisection as a guard.
template <int D>
double Impact<D>::restitution_end(const Series& s, double h) {
    const double target = restitution_target();
    load(s, h);
    if (W < target) return -1.0;
    return bracketed_root(
        [&](double t, double* rate) {
            load(s, t);
            *rate = u[0] * polynomial::value<kOrder>(s[kQ], t);
            return W - target;
        },
        0.0, h, h);
}

// Integrate the turning slip until it stops (returns true) or the impact ends: follow_slip()
// below, in up to 500 Taylor steps (how.first_pass_steps). Slip that needs more is slip near
// the stick threshold (see finish_on_ray()): followed again from the start, each step first
// trying to finish on the ray the slip settles on (within 20000 steps, how.last_step; beyond,
// finished along its direction and flagged). Every impact that ends within 500 steps is integrated as it
// was before this second pass existed, bit for bit; the second pass agrees with an independent
// integration to 2e-10 of the impulse from mu = 0.99 to 0.9999999 of the threshold
// (routh_test.cpp, Routh.NearTheStickThreshold...).
//
// follow_slip(): returns 1 if the slip stopped, 0 if the impact ended, -1 after max_steps
// steps (first pass only). Each step's
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
template <int D>
bool Impact<D>::run_slip_3d() {
    const Impact start = *this;
    const int end = follow_slip(how.tolerance, how.first_pass_steps, false);
    if (end >= 0) return end == 1;
    const int first_pass = slip_steps;
    *this = start;
    const bool stopped = follow_slip(how.tolerance, how.last_step, true) == 1;
    slip_steps += first_pass;
    return stopped;
}

template <int D>
int Impact<D>::follow_slip(double kTol, int max_steps, bool on_ray) {
    const double kStopped = 10.0 * kTol;
    const double uscale = u.norm(), Pscale = -un0 / K(0, 0);
    const double tol[3] = {kTol * uscale, kTol * Pscale, kTol * uscale * Pscale};
    const double inv_tol2[3] = {1.0 / (tol[0] * tol[0]), 1.0 / (tol[1] * tol[1]), 1.0 / (tol[2] * tol[2])};
    Series s;
    double g[kOrder + 1];
    for (int step = 0;; ++step) {
        if (on_ray) {
            const int end = finish_on_ray(tol[1], step >= max_steps);
            if (end >= 0) return end;
        } else if (step >= max_steps) {
            return -1;
        }
        const int end = how.closed_form_end ? end_slip(tol) : -1;
        if (end >= 0) {
            slip_end_closed = true;
            return end;
        }
        const double len = u.template tail<2>().norm();
        if (len <= kStopped * uscale) {
            const Eigen::Vector2d dir = u.template tail<2>() / len;
            V d;
            d << 1.0, -mu * dir;
            const V Kd = K * d;
            const double rate = dir.dot(Kd.template tail<2>());  // d|u_t|/dP_n along d
            return rate < 0.0 ? run_linear(d, len / -rate) : 1;
        }
        taylor(s);
        ++slip_steps;
        // Step length (Jorba and Zou): the last term of every group at most its tolerance,
        // h = (tol / |term_N|)^(1/N), then shortened if the term before it is still larger
        // at h (a last coefficient small by chance).
        const auto worst = [&](int k) {
            const auto sq = [&](Row r) { return s[r][k] * s[r][k]; };
            return std::max({(sq(kW1) + sq(kW2) + sq(kUn)) * inv_tol2[0], (sq(kPn) + sq(kPt1) + sq(kPt2)) * inv_tol2[1],
                             mu * mu * sq(kLoss) * inv_tol2[2]});
        };
        // The term before, squared and over its tolerance, is before h^(2N-2) at h, so
        //   h = min(last^(-1/(2N)), before^(-1/(2N-2))),
        // by base-2 logarithms (fast_log2(): h to 1e-8 of itself).
        const double last = worst(kOrder), before = worst(kOrder - 1);
        const double log_h_last = last > 0.0 ? fast_log2(last) * (-0.5 / kOrder) : kNever;
        const double log_h_before = before > 0.0 ? fast_log2(before) * (-0.5 / (kOrder - 1)) : kNever;
        const double h = std::exp2(std::min(log_h_last, log_h_before));
        if (!(h < kNever)) {
            jammed = true;
            return 0;
        }
        // (restitution_end(), finding no end, leaves the state at the step's end.)
        const bool by_series = event_series(s, g) != nullptr;
        const double t = by_series ? first_root<kOrder>(g, h) : restitution_end(s, h);
        if (!compressing) {  // the approach resuming: -u_n reaching 0 from below
            for (int k = 0; k <= kOrder; ++k) g[k] = -s[kUn][k];
            const double t_back = first_root<kOrder>(g, h);
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
        if (!compressing) return 0;
        end_compression();
        // e = 0: restitution has nothing to do.
        if (restitution_quantity(u[0], P[0], W) >= restitution_target()) return 0;
    }
}

// Slip near the stick threshold (mu just below |K_tt^-1 K_tn|, the friction sticking needs)
// settles on a ray s* along which it grows or shrinks at a rate F = s*.(K_tn - mu K_tt s*)
// close to 0; in sigma (dP_n = |u_t| dsigma) that is a slow exponential, and the Taylor steps,
// sized by the direction's fast decay onto the ray, would need millions of steps to cover it.
// Along the ray the slip is straight: with the tangential rate -mu s* held, u_t' = F s*
// exactly (K_tn - mu K_tt s* is parallel to s*, the ray's definition G = 0), so the rest of the
// impact is one straight stretch in closed form (run_linear()). s* is found by Newton's method
// on th from the current direction s: G(th) = p.(K_tn - mu K_tt s), p = s turned by +90
// degrees, G'(th) = -s.K_tn + mu (s.K_tt s - p.K_tt p) < 0 on an attracting ray. What the
// stretch leaves out is the rest of the turn: the angle x from s to s* decays as
// exp(G' sigma) while |u_t| = q grows as exp(F sigma), so the tangential impulse still owed to
// it is mu int x dP_n = mu x q / |G' + F|; the stretch is taken once that is within tolP (the
// steps' tolerance on impulses). (Slip this slow is often small, its direction then known to
// no better than the absolute error of u_t over q: the bound is on the impulse, not on the
// angle.) `anyway`: wherever the direction is, with settled = false (the answer says so:
// RouthDetail::settled). Returns 1 if the slip stopped on the way, 0 if the impact ended, -1
// if not taken.
template <int D>
int Impact<D>::finish_on_ray(double tolP, bool anyway) {
    const Eigen::Vector2d w = u.template tail<2>();
    const double len = w.norm();
    if (!(len > 0.0)) return -1;
    const Eigen::Vector2d c = K.template block<2, 1>(1, 0);
    const Eigen::Matrix2d A = K.template block<2, 2>(1, 1);
    const Eigen::Vector2d s = w / len;
    Eigen::Vector2d ray = s;
    double dG = 0.0;
    bool found = false;
    for (int it = 0; it < 12 && !found; ++it) {
        const Eigen::Vector2d p(-ray[1], ray[0]);
        const double G = p.dot(c - mu * (A * ray));
        dG = -ray.dot(c) + mu * (ray.dot(A * ray) - p.dot(A * p));
        if (!(dG < 0.0)) break;
        const double dx = -G / dG;
        if (!(std::abs(dx) < 0.5)) break;  // not near an attracting ray
        ray = (ray + dx * p).normalized();
        found = std::abs(dx) <= 1e-15;
    }
    const double rate = ray.dot(c - mu * (A * ray));  // F = d|u_t|/dP_n on the ray
    const double decay = -(dG + rate);                // -(G' + F)
    const double x = (s - ray).norm();
    if (!anyway && !(found && decay > 0.0 && mu * x * len <= tolP * decay)) return -1;
    if (anyway) {
        settled = false;
        if (!found) ray = s;
    }
    slip_end_on_ray = true;
    V d;
    d << 1.0, -mu * ray;
    return run_linear(d, rate < 0.0 ? len / -rate : kNever) ? 1 : 0;
}

template bool Impact<3>::run_slip_3d();
template int Impact<3>::finish_on_ray(double, bool);
template int Impact<3>::follow_slip(double, int, bool);

}  // namespace collide::routh_impl
