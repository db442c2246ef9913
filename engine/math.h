// Math vocabulary of the engine: Eigen aliases and the cross products of the page.
//
// Conventions (written once for the whole code base in docs/conventions.md):
//   SI units (m, kg, s, rad); right-handed frame; 3D: y is up; 2D: the xy plane,
//   angles and angular velocities positive counter-clockwise (about +z).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace collide {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat2 = Eigen::Matrix2d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

// Cross-product matrix [r]x, so that [r]x a = r x a.
inline Mat3 skew(const Vec3& r) {
    Mat3 m;
    m << 0.0, -r.z(), r.y(),
         r.z(), 0.0, -r.x(),
         -r.y(), r.x(), 0.0;
    return m;
}

// 2D scalar cross product a x b = ax by - ay bx (the z component of the 3D product).
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// 2D "w x r" for a spin w about +z: w (-ry, rx).
inline Vec2 cross(double w, const Vec2& r) { return Vec2(-w * r.y(), w * r.x()); }

// perp(r) = (-ry, rx): the direction in which a counter-clockwise spin moves the point r.
// r x P = perp(r) . P, so perp(r) is the 2D lever of an impulse P applied at r.
inline Vec2 perp(const Vec2& r) { return Vec2(-r.y(), r.x()); }

}  // namespace collide
