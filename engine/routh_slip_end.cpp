// Routh's method in 3D (engine/routh.h, routh_impact.h): the end of the turning slip
// (routh_slip.cpp) in closed form, as series about the ray it settles on.
//
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
#include <algorithm>
#include <array>
#include <cmath>

#include "engine/polynomial.h"
#include "engine/routh_impact.h"

namespace collide::routh_impl {

using polynomial::bracketed_root;
using polynomial::fast_log2;

// What remains of the slip from where its end began (see above).
template <int D>
struct Impact<D>::SlipEnd {
    double alpha = 0.0, r = 0.0, x0 = 0.0;  // x0 = x_now = th_now - th*
    Eigen::Vector2d s, p;                   // s*, p*
    int n = 0;                              // the series' order
    // B, Bc, Bs (the rates), and the tails of B/(alpha+k), Bc/(alpha+k), Bs/(alpha+k),
    // BD/(2 alpha+k): cB_i = sum_{k>i} B_k/(alpha+k) etc., and their sums at y = 1.
    double B[kEndOrder + 1], Bc[kEndOrder + 1], Bs[kEndOrder + 1];
    double cB[kEndOrder + 1], cBc[kEndOrder + 1], cBs[kEndOrder + 1], cBD[kEndOrder + 1];
    double B1 = 0.0, Bc1 = 0.0, Bs1 = 0.0, BD1 = 0.0;
    V u1, P1;  // the state where the end began (tau = 0)
    double W1 = 0.0;
};

namespace {

// 1/k! and 2^k/k!, k = 0 .. kEndOrder + 1.
constexpr int kFactorialsUpTo = Impact<3>::kEndOrder + 1;
constexpr std::array<std::array<double, kFactorialsUpTo + 1>, 2> kFactorials = [] {
    std::array<std::array<double, kFactorialsUpTo + 1>, 2> a{};
    a[0][0] = a[1][0] = 1.0;
    for (int k = 1; k <= kFactorialsUpTo; ++k) {
        a[0][k] = a[0][k - 1] / k;
        a[1][k] = a[1][k - 1] * 2.0 / k;
    }
    return a;
}();

}  // namespace

// The ray s* = s(th*) the slip settles on (the slip's end, below), into `ray`: false if
// none is found within 15/16 of half a turn. th* is the same for the whole slip (the
// direction's equation is autonomous), so it is found once.
template <int D>
bool Impact<D>::find_ray(const Eigen::Vector2d& s0, const Eigen::Vector2d& c, const Eigen::Matrix2d& A) {
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
        static constexpr std::array<double, 16> kGrid = {// tan(i pi/32)
                                                         0.0,
                                                         0.09849140335716425,
                                                         0.19891236737965800,
                                                         0.30334668360734239,
                                                         0.41421356237309503,
                                                         0.53451113595079159,
                                                         0.66817863791929890,
                                                         0.82067879082866024,
                                                         1.0,
                                                         1.21850352558797255,
                                                         1.49660576266548898,
                                                         1.87086841178938664,
                                                         2.41421356237309492,
                                                         3.29655820893832213,
                                                         5.02733949212584761,
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
template <int D>
void Impact<D>::set_x_ok(double x) {
    cos_x_ok = x < 3.14159 ? std::cos(x) : -2.0;
}

// The series of the slip's end from the current state, into *f; false if they do not apply
// (no attracting ray within reach, slip that does not stop on it, or series that do not
// converge within kEndOrder). A refusal estimates how close to th* the series would
// converge (x_ok), and none is tried again before the slip is that close.
template <int D>
bool Impact<D>::slip_end_series(const double tol[3], SlipEnd* f) {
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
    // alpha > 0: the slip stops on this ray. Not for alpha < kMinAlpha = 1e-4 (slip that stops
    // ever more slowly as mu nears the stick threshold from above): there the series lost
    // accuracy (2.6e-3 of the impulse at mu = 1.0000001 mu*, alpha ~ 1e-7; 5e-8 at 1.000001,
    // against routh_test.cpp's independent integration), and the Taylor steps, then the
    // slip's end on its ray (routh_slip.cpp, finish_on_ray()), take it to 1e-9.
    constexpr double kMinAlpha = 1e-4;
    if (!(alpha > kMinAlpha)) return false;
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
        const double top = std::max({std::abs(V[kProbe - 2]), std::abs(V[kProbe - 1]), std::abs(V[kProbe])});
        const double log_ratio = top > 0.0 ? fast_log2(top / std::abs(V0)) / (kProbe - 1) : -kNever;
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
            {r * (std::abs(B[k]) + mu * (std::abs(Bc[k]) + std::abs(Bs[k]))) / ((alpha + k) * tolP),
             mu * r * r * std::abs(BD[k]) / ((2.0 * alpha + k) * tolW), std::abs(E[k]) * q0B0 / (E1 * E1 * tolP)});
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
template <int D>
void Impact<D>::load_end(const SlipEnd& f, double tau, V* rate) {
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

// The slip finished by its series (slip_end_series()), the stage ends on the way found on
// them: returns 1 if the slip stopped, 0 if the impact ended first, -1 if the series do not
// apply (the state untouched). Taken only where u_n rises with P_n all along the rest
// (du_n/dP_n = K_nn - mu K_nt.s > 0 for s from s_now to s*): then every stage's quantity
// (u_n; P_n; W, whose rate is u_n > 0 in restitution) rises with P_n, so a stage ends on the
// way if and only if its quantity at the stop has reached its target, at the single root
// of the gap in t (Newton's method with bisection as a guard, from the linear guess).
template <int D>
int Impact<D>::end_slip(const double tol[3]) {
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
                     : law == RestitutionLaw::poisson             ? rate[0]
                                                                  : u[0] * rate[0];
            return stage_gap();
        };
        const double tau = bracketed_root(gap, lo, 1.0, lo + (1.0 - lo) * -gap_lo / (gap_stop - gap_lo));
        double slope;
        gap(tau, &slope);
        if (!compressing) return 0;
        end_compression();
        if (stage_gap() >= 0.0) return 0;  // e = 0: restitution has nothing to do
        lo = tau;
    }
}

template int Impact<3>::end_slip(const double tol[3]);

}  // namespace collide::routh_impl
