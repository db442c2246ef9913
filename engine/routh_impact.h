// Routh's integration of one impact (engine/routh.h), inside the engine: the state of the impact
// over the normal impulse P_n in the contact frame (index 0 along n, then the tangent(s)), and
// its stages, defined by concept in three files:
//   routh.cpp          the straight (linear) stretches: slip with a fixed direction, stick,
//                      reversal; compression and restitution ends in closed form; the 2D method
//                      and the public routh();
//   routh_slip.cpp     3D slip whose direction turns, integrated by Taylor series;
//   routh_slip_end.cpp the end of that slip in closed form, as series about the ray it settles on.
// Not part of the engine's interface.
#pragma once

#include <algorithm>
#include <array>
#include <limits>

#include "engine/routh.h"

namespace collide::routh_impl {

constexpr double kNever = std::numeric_limits<double>::infinity();

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
    bool settled = true;      // 3D: the turning slip was integrated to its end (see finish_on_ray())
    bool compressed = false;  // compression has ended at least once
    RouthDetail* detail = nullptr;
    RouthIntegration how;    // 3D: the slip's step tolerance and closed-form end
    bool ray_known = false;  // 3D slip: the ray it settles on, found (see find_ray())
    Eigen::Matrix<double, 2, 1> ray = Eigen::Matrix<double, 2, 1>::Zero();
    double cos_x_ok = -2.0;   // 3D slip: cos of |th - th*| below which its end may converge
    bool ray_missed = false;  // 3D slip: a search for the ray found none, at missed_at
    Eigen::Matrix<double, 2, 1> missed_at = Eigen::Matrix<double, 2, 1>::Zero();
    int slip_steps = 0;
    bool slip_end_closed = false;
    bool slip_end_on_ray = false;
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

    // ---- The straight stretches, u linear in P_n (routh.cpp) ----

    double restitution_step(double a) const;
    bool run_linear(const V& d, double dP_stop);
    V no_slip_direction(Kind* k) const;
    void run_no_slip(bool at_start);
    void finish();

    // Delta E = integral of u . dP along the path, with u = u0 + K P:
    //   = u0 . P + P^T K P / 2, the same for every path since K is symmetric (u . dP is then
    //   the exact differential of that expression).
    double energy_change() const { return u0.dot(P) + 0.5 * P.dot(K * P); }

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
    // How far the current stage is from its end (< 0 before it): u_n in compression, else the
    // restitution law's quantity (restitution_quantity()) minus its target.
    double stage_gap() const { return compressing ? u[0] : restitution_quantity(u[0], P[0], W) - restitution_target(); }

    // ---- 3D slip whose direction turns, by Taylor series in sigma, dP_n = |u_t| dsigma
    // (routh_slip.cpp) ----
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

    void taylor(Series& s) const;
    void load(const Series& s, double t);
    const double* event_series(const Series& s, double* g) const;
    double restitution_end(const Series& s, double h);
    bool run_slip_3d();
    int follow_slip(double tolerance, int max_steps, bool on_ray);
    int finish_on_ray(double tolP, bool anyway);

    // ---- 3D slip: its end in closed form (routh_slip_end.cpp) ----
    struct SlipEnd;  // the series of the rest of the slip
    bool find_ray(const Eigen::Vector2d& s0, const Eigen::Vector2d& c, const Eigen::Matrix2d& A);
    void set_x_ok(double x);
    bool slip_end_series(const double tol[3], SlipEnd* f);
    void load_end(const SlipEnd& f, double tau, V* rate);
    int end_slip(const double tol[3]);
};

}  // namespace collide::routh_impl
