#include "engine/trig.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace collide {

namespace {

// sin r and cos r for |r| <= pi/4 by their Taylor series, z = r^2:
//   sin r = r + r z (-1/3! + z (1/5! - ... + z 1/17!)),   cos r = 1 - z/2 + z^2 (1/4! - ... + z^7 1/18!);
// the first terms left out, r^19/19! and r^20/20!, are below 1e-19 at r = pi/4 (sin r, cos r
// >= 0.7 there), so the error is the rounding of Horner's rule, within 1 ulp.
double sin_kernel(double r) {
    const double z = r * r;
    const double p =
        -0.16666666666666666 +
        z * (0.008333333333333333 + z * (-0.0001984126984126984 +
                                         z * (2.7557319223985893e-06 +
                                              z * (-2.505210838544172e-08 +
                                                   z * (1.6059043836821613e-10 +
                                                        z * (-7.647163731819816e-13 + z * 2.8114572543455206e-15))))));
    return r + r * z * p;
}
double cos_kernel(double r) {
    const double z = r * r;
    const double p =
        0.041666666666666664 +
        z * (-0.001388888888888889 +
             z * (2.48015873015873e-05 +
                  z * (-2.755731922398589e-07 +
                       z * (2.08767569878681e-09 + z * (-1.1470745597729725e-11 +
                                                        z * (4.779477332387385e-14 + z * -1.5619206968586225e-16))))));
    return (1.0 - 0.5 * z) + z * z * p;
}

}  // namespace

// x = n pi/2 + r with |r| <= pi/4 (Cody and Waite's reduction): pi/2 = P1 + P2 + P3 with P1 and
// P2 of 33 significant bits, so n P1 and n P2 are exact for |n| < 2^20, x - n P1 is exact
// (Sterbenz), and r is good to about 1e-31 rad absolute; pi/2 - (P1 + P2 + P3) = 1e-37. Then
// by the quadrant n mod 4: (sin, cos) x = (s, c), (c, -s), (-s, -c), (-c, s) of r. Worked on
// |x|: sin(-x) = -sin x, cos(-x) = cos x exactly.
SinCos sin_cos(double x) {
    constexpr double kP1 = 0x1.921fb54400000p+0;   // 1.5707963267341256
    constexpr double kP2 = 0x1.0b4611a600000p-34;  // 6.077100506303966e-11
    constexpr double kP3 = 0x1.3198a2e037073p-69;  // 2.0222662487959506e-21
    constexpr double kTwoOverPi = 0.6366197723675814;
    constexpr double kTwoPi = 6.283185307179586;  // 2 pi rounded: fmod by it is exact
    constexpr double kLargest = 823549.0;         // (2^19 - 1) pi/2: |n| < 2^19
    if (!std::isfinite(x)) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return {nan, nan};
    }
    const double sign = std::copysign(1.0, x);
    double a = std::abs(x);
    if (a > kLargest) a = std::fmod(a, kTwoPi);
    const double n = std::floor(a * kTwoOverPi + 0.5);
    const double r = ((a - n * kP1) - n * kP2) - n * kP3;
    const double s = sin_kernel(r), c = cos_kernel(r);
    switch (static_cast<std::int64_t>(n) & 3) {
        case 0: return {sign * s, c};
        case 1: return {sign * c, -s};
        case 2: return {-sign * s, -c};
        default: return {-sign * c, s};
    }
}

}  // namespace collide
