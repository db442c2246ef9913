// Polynomials of Routh's 3D slip (engine/routh_slip.cpp, routh_slip_end.cpp): a polynomial of
// order N (its N + 1 coefficients, lowest first) evaluated by Horner's rule, with its slope;
// its first root in an interval; a root kept inside its bracket; and the base-2 logarithm the
// step lengths and convergence estimates are taken from.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace collide::polynomial {

// log2(v) to within 1e-7, for step lengths and estimates (v > 0 finite): v = m 2^e with
// 1/sqrt(2) <= m < sqrt(2) (from the bits of v), ln m = 2 atanh(z) = 2 (z + z^3/3 + z^5/5 +
// z^7/7 + ...), z = (m - 1)/(m + 1), |z| < 0.172.
inline double fast_log2(double v) {
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

// The polynomial x at t, by Horner's rule.
template <int N>
inline double value(const double* x, double t) {
    double v = x[N];
    for (int k = N - 1; k >= 0; --k) v = v * t + x[k];
    return v;
}
// g(t) and g'(t) of a polynomial, side by side.
template <int N>
inline double value_and_slope(const double* g, double t, double* slope) {
    double v = g[N], d = 0.0;
    for (int k = N - 1; k >= 0; --k) {
        d = d * t + v;
        v = v * t + g[k];
    }
    *slope = d;
    return v;
}

// The root of g in (lo, hi] (g(lo) < 0 <= g(hi)) from t: Newton's method on g(t, &rate),
// each step kept inside the bracket (else bisection), to 1e-15 of hi or rounding.
template <class G>
inline double bracketed_root(G g, double lo, double hi, double t) {
    bool close = false;  // the last Newton step was below 1e-8 of hi
    for (int it = 0; it < 100; ++it) {
        double rate;
        const double gt = g(t, &rate);
        if (gt >= 0.0) hi = t;
        else lo = t;
        const double newton_next = rate > 0.0 ? t - gt / rate : t;
        // A Newton step below 1e-15 of hi, or the step after one below 1e-8 (Newton's
        // method converging quadratically, that one is at rounding): done. (Checked before
        // the bracket, which the converged step may touch.)
        if (rate > 0.0 && (std::abs(newton_next - t) <= 1e-15 * hi || close)) return std::clamp(newton_next, lo, hi);
        const bool newton = rate > 0.0 && newton_next > lo && newton_next < hi;
        const double next = newton ? newton_next : 0.5 * (lo + hi);
        close = newton && std::abs(next - t) <= 1e-8 * hi;
        t = next;
        if (hi - lo <= 1e-15 * hi) break;
    }
    return t;
}

// The first root in (0, h] of the polynomial g (g(0) < 0), or -1 if g stays negative.
// g <= g_0 + sum of its positive terms at h on [0, h]: when that bound is negative there is
// no root; otherwise g is sampled at 8 points (evaluated side by side) and the first bracket
// refined by Newton's method with bisection as a guard.
template <int N>
inline double first_root(const double* g, double h) {
    // The bound by Horner's rule in h^2, even and odd terms side by side.
    const double h2 = h * h;
    double even = 0.0, odd = 0.0;
    for (int k = N - (N % 2); k >= 2; k -= 2) even = even * h2 + std::max(g[k], 0.0);
    for (int k = N - 1 + (N % 2); k >= 1; k -= 2) odd = odd * h2 + std::max(g[k], 0.0);
    if (g[0] + h2 * even + h * odd < 0.0) return -1.0;
    constexpr int kSamples = 8;
    double v[kSamples];
    for (int i = 0; i < kSamples; ++i) v[i] = g[N];
    for (int k = N - 1; k >= 0; --k)
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
    return bracketed_root([&](double t, double* rate) { return value_and_slope<N>(g, t, rate); }, lo, hi,
                          0.5 * (lo + hi));
}

}  // namespace collide::polynomial
