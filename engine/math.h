// Math vocabulary of the engine: Eigen aliases and the cross products of the page.
//
// Conventions (written once for the whole code base in docs/conventions.md):
//   SI units (m, kg, s, rad); right-handed frame; 3D: y is up; 2D: the xy plane,
//   angles and angular velocities positive counter-clockwise (about +z).
#pragma once

#include <cmath>
#include <limits>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "engine/trig.h"

namespace collide {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat2 = Eigen::Matrix2d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

constexpr double kPi = 3.14159265358979323846;

// One lift of lower dimensions into 3D, used wherever 1D and 2D results are shown or checked
// in 3D form: a 2D vector lies in the xy plane, a 2D spin (counter-clockwise +) points
// along +z, a 1D value lies along x. 3D values pass through.
inline Vec3 lift(const Vec2& v) { return Vec3(v.x(), v.y(), 0.0); }
inline Vec3 lift(const Vec3& v) { return v; }
inline Vec3 lift_spin(double w) { return Vec3(0.0, 0.0, w); }
inline Vec3 lift_spin(const Vec3& w) { return w; }
inline Vec3 lift_line(double x) { return Vec3(x, 0.0, 0.0); }
inline Quat lift_angle(double angle) {
    const SinCos half = sin_cos(0.5 * angle);
    return Quat(half.cos, 0.0, 0.0, half.sin);
}

// Cross-product matrix [r]x, so that [r]x a = r x a.
inline Mat3 skew(const Vec3& r) {
    Mat3 m;
    m << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
    return m;
}

// 2D scalar cross product a x b = ax by - ay bx (the z component of the 3D product).
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// 2D "w x r" for a spin w about +z: w (-ry, rx).
inline Vec2 cross(double w, const Vec2& r) { return Vec2(-w * r.y(), w * r.x()); }

// perp(r) = (-ry, rx): the direction in which a counter-clockwise spin moves the point r.
// r x P = perp(r) . P, so perp(r) is the 2D lever of an impulse P applied at r.
inline Vec2 perp(const Vec2& r) { return Vec2(-r.y(), r.x()); }

// Smallest t > 0 with c + b t + a t^2 = 0 (c >= 0: a gap now; b, 2a: its rate and acceleration),
// or +infinity: when a gap closing at constant acceleration first reaches zero. Stable roots:
// q = -(b + sgn(b) sqrt(b^2 - 4ac)) / 2, t1 = q / a, t2 = c / q.
inline double first_root(double a, double b, double c) {
    constexpr double never = std::numeric_limits<double>::infinity();
    if (a == 0.0) return b < 0.0 ? -c / b : never;
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return never;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    double best = never;
    for (double t : {q / a, q != 0.0 ? c / q : never})
        if (t > 0.0 && t < best) best = t;
    return best;
}

}  // namespace collide
