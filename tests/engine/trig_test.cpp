// The engine's own sine and cosine (engine/trig.h) against the C library's, which rounds them
// to within an ulp: ours within 2 ulp of it up to 8e5 rad, within |x| 1e-16 beyond; the exact
// values, symmetries and NaNs. That both builds compute them alike is tests/wasm/equal.js's.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "engine/rotation.h"
#include "engine/trig.h"

namespace collide {
namespace {

// The spacing of doubles at |v| (the smallest normal's for tiny v).
double ulp(double v) {
    const double a = std::max(std::abs(v), std::numeric_limits<double>::min());
    return std::nextafter(a, std::numeric_limits<double>::infinity()) - a;
}

// Ours against the C library's at x, within `ulps` of its value.
void expect_near_libm(double x, double ulps) {
    const SinCos sc = sin_cos(x);
    EXPECT_LE(std::abs(sc.sin - std::sin(x)), ulps * ulp(std::sin(x))) << "sin " << x;
    EXPECT_LE(std::abs(sc.cos - std::cos(x)), ulps * ulp(std::cos(x))) << "cos " << x;
}

TEST(Trig, WithinTwoUlpOfTheCLibrary) {
    std::mt19937_64 rng(7);
    for (const double range : {0.8, 3.2, 100.0, 1e4, 8e5}) {
        std::uniform_real_distribution<double> draw(-range, range);
        for (int i = 0; i < 100000; ++i) expect_near_libm(draw(rng), 2.0);
    }
    // Tiny angles (sin x = x to rounding) and the quadrants' edges.
    for (double x = 1e-300; x < 1e-3; x *= 3.7) expect_near_libm(x, 2.0);
    for (int k = -40; k <= 40; ++k)
        for (const double d : {-1e-9, -1e-15, 0.0, 1e-15, 1e-9}) expect_near_libm(k * (kPi / 4) + d, 2.0);
}

// Near a multiple of pi the sine is small: the reduction keeps it to its own ulps.
TEST(Trig, NearMultiplesOfPiTheSineKeepsItsDigits) {
    for (int k = 1; k <= 100000; k *= 3) {
        const double x = k * kPi;  // x differs from k pi by up to an ulp of x
        expect_near_libm(x, 2.0);
        expect_near_libm(std::nextafter(x, 0.0), 2.0);
    }
}

TEST(Trig, ExactValuesAndSymmetries) {
    EXPECT_EQ(sin_cos(0.0).sin, 0.0);
    EXPECT_EQ(sin_cos(0.0).cos, 1.0);
    EXPECT_TRUE(std::signbit(sin_cos(-0.0).sin));
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> draw(0.0, 1e3);
    for (int i = 0; i < 10000; ++i) {
        const double x = draw(rng);
        const SinCos p = sin_cos(x), m = sin_cos(-x);
        EXPECT_EQ(m.sin, -p.sin);
        EXPECT_EQ(m.cos, p.cos);
        EXPECT_NEAR(p.sin * p.sin + p.cos * p.cos, 1.0, 4.5e-16);
    }
    for (const double x : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()}) {
        EXPECT_TRUE(std::isnan(sin_cos(x).sin));
        EXPECT_TRUE(std::isnan(sin_cos(x).cos));
    }
}

// Beyond 8e5 rad x is reduced by fmod(x, 2 pi rounded): exact, but 2 pi is off by 2.4e-16.
TEST(Trig, LargeAnglesLoseAboutXTimes1e16) {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> draw(8e5, 1e9);
    for (int i = 0; i < 10000; ++i) {
        const double x = draw(rng);
        const SinCos sc = sin_cos(x);
        EXPECT_LE(std::abs(sc.sin - std::sin(x)), 1e-16 * x + 1e-15) << x;
        EXPECT_LE(std::abs(sc.cos - std::cos(x)), 1e-16 * x + 1e-15) << x;
    }
}

// The rotation vector's quaternion: the rotation Eigen's angle-axis gives, to rounding.
TEST(Trig, ExpMapIsTheAngleAxisRotation) {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> draw(-4.0, 4.0);
    for (int i = 0; i < 10000; ++i) {
        const Vec3 phi(draw(rng), draw(rng), draw(rng));
        const Quat q = exp_map(phi);
        const Quat expected(Eigen::AngleAxisd(phi.norm(), phi.normalized()));
        EXPECT_NEAR(q.norm(), 1.0, 4e-16);
        EXPECT_LE((q.coeffs() - expected.coeffs()).norm(), 1e-15);
    }
    // Small turns (every substep's) by their series, up to 0.2 rad, and just beyond it.
    for (double a = 1e-12; a < 0.3; a *= 1.01) {
        const Vec3 phi = a * Vec3(0.48, -0.6, 0.64);  // a unit axis
        const Quat q = exp_map(phi);
        EXPECT_NEAR(q.w(), std::cos(0.5 * a), 2.3e-16) << a;
        EXPECT_LE((q.vec() - std::sin(0.5 * a) * Vec3(0.48, -0.6, 0.64)).norm(), 4.5e-16 * std::sin(0.5 * a))
            << a;  // 2 ulp
    }
    EXPECT_EQ(exp_map(Vec3::Zero()).coeffs(), Quat::Identity().coeffs());
}

}  // namespace
}  // namespace collide
