// Shared helpers of the engine tests: seeded random bodies and near-equality with an absolute
// plus relative tolerance.
//
// Random draws are reproducible: every generator is a std::mt19937_64 with a fixed seed, and the
// doubles are made from its raw 64-bit output (not std::uniform_real_distribution, whose output
// may differ between standard libraries).
//
// Physical inertia tensors: a body's principal moments are I1 = m (b + c), I2 = m (a + c),
// I3 = m (a + b) with a, b, c >= 0 its mean squared extents (a = <x^2> etc.). Every such triple
// obeys the triangle inequality I1 + I2 >= I3 (and cyclically), as every real body does; the
// world tensor is R diag(I1, I2, I3) R^T with a uniformly random rotation R.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "engine/body.h"

namespace collide_test {

using collide::Body2;
using collide::Body3;
using collide::kPi;
using collide::Mat3;
using collide::Quat;
using collide::Vec2;
using collide::Vec3;

class Random {
public:
    explicit Random(std::uint64_t seed) : gen_(seed) {}

    // Uniform in [lo, hi).
    double uniform(double lo, double hi) {
        const double unit = static_cast<double>(gen_() >> 11) * 0x1.0p-53;
        return lo + (hi - lo) * unit;
    }
    // log-uniform in [lo, hi).
    double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
    // Masses: log-uniform 0.1 .. 10 kg.
    double mass() { return log_uniform(0.1, 10.0); }

    Vec2 vec2(double lo, double hi) { return Vec2(uniform(lo, hi), uniform(lo, hi)); }
    Vec3 vec3(double lo, double hi) { return Vec3(uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)); }
    Vec2 unit2() {
        const double angle = uniform(0.0, 2.0 * kPi);
        return Vec2(std::cos(angle), std::sin(angle));
    }
    Vec3 unit3() { return rotation() * Vec3::UnitX(); }

    // Uniformly distributed rotation (Shoemake's method).
    Quat rotation() {
        const double u1 = uniform(0.0, 1.0), u2 = uniform(0.0, 2.0 * kPi), u3 = uniform(0.0, 2.0 * kPi);
        const double s = std::sqrt(1.0 - u1), t = std::sqrt(u1);
        return Quat(t * std::cos(u3), s * std::sin(u2), s * std::cos(u2), t * std::sin(u3));
    }

    // Principal moments of a body of mass m whose mean squared extents a, b, c are log-uniform
    // in 0.005 .. 0.5 m^2: I1 = m (b + c), I2 = m (a + c), I3 = m (a + b).
    Vec3 principal_moments(double m) {
        const double a = log_uniform(0.005, 0.5), b = log_uniform(0.005, 0.5), c = log_uniform(0.005, 0.5);
        return m * Vec3(b + c, a + c, a + b);
    }
    // Body-frame tensor, itself rotated by a random rotation so that it is not diagonal
    // (the engine must not assume principal body axes).
    Mat3 inertia_body(double m) {
        const Mat3 R = rotation().toRotationMatrix();
        return R * principal_moments(m).asDiagonal() * R.transpose();
    }

    // Dynamic body: mass, general inertia, orientation, position in [-1, 1]^3 m,
    // velocity in [-2, 2]^3 m/s, angular velocity in [-3, 3]^3 rad/s.
    Body3 body3() {
        Body3 b;
        b.mass = mass();
        b.inertia = inertia_body(b.mass);
        b.orientation = rotation();
        b.position = vec3(-1.0, 1.0);
        b.v = vec3(-2.0, 2.0);
        b.w = vec3(-3.0, 3.0);
        return b;
    }
    // 2D counterpart: inertia m k^2 with k^2 log-uniform in 0.01 .. 1 m^2.
    Body2 body2() {
        Body2 b;
        b.mass = mass();
        b.inertia = b.mass * log_uniform(0.01, 1.0);
        b.angle = uniform(-kPi, kPi);
        b.position = vec2(-1.0, 1.0);
        b.v = vec2(-2.0, 2.0);
        b.w = uniform(-3.0, 3.0);
        return b;
    }

private:
    std::mt19937_64 gen_;
};

// |a - b| <= atol + rtol * max(|a|, |b|) for vectors and matrices (Frobenius norm).
template <class A, class B>
::testing::AssertionResult near(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b, double atol,
                                double rtol) {
    const double err = (a - b).norm();
    const double bound = atol + rtol * std::max(a.norm(), b.norm());
    if (err <= bound) return ::testing::AssertionSuccess();
    std::ostringstream os;
    os.precision(17);
    os << "|a - b| = " << err << " > " << bound << " (atol " << atol << ", rtol " << rtol
       << ")\n  a = " << a.transpose() << "\n  b = " << b.transpose();
    return ::testing::AssertionFailure() << os.str();
}

// The same with an explicit scale (e.g. the size of the terms a conserved sum is made of).
template <class A, class B>
::testing::AssertionResult near_scaled(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b, double atol,
                                       double rtol, double scale) {
    const double err = (a - b).norm();
    const double bound = atol + rtol * scale;
    if (err <= bound) return ::testing::AssertionSuccess();
    std::ostringstream os;
    os.precision(17);
    os << "|a - b| = " << err << " > " << bound << " (atol " << atol << ", rtol " << rtol << ", scale " << scale
       << ")\n  a = " << a.transpose() << "\n  b = " << b.transpose();
    return ::testing::AssertionFailure() << os.str();
}

// Scalars: |a - b| <= atol + rtol * max(|a|, |b|).
inline ::testing::AssertionResult near(double a, double b, double atol, double rtol) {
    const double err = std::abs(a - b);
    const double bound = atol + rtol * std::max(std::abs(a), std::abs(b));
    if (err <= bound) return ::testing::AssertionSuccess();
    std::ostringstream os;
    os.precision(17);
    os << "a = " << a << ", b = " << b << ", |a - b| = " << err << " > " << bound;
    return ::testing::AssertionFailure() << os.str();
}

}  // namespace collide_test

// EXPECT_LE(|a - b|, atol + rtol * scale), reported at the caller's line.
#define EXPECT_NEAR_ABS_REL(a, b, atol, rtol) EXPECT_TRUE(::collide_test::near((a), (b), (atol), (rtol)))
#define EXPECT_NEAR_SCALED(a, b, atol, rtol, scale)                                                                    \
    EXPECT_TRUE(::collide_test::near_scaled((a), (b), (atol), (rtol), (scale)))
