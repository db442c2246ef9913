// Rigid bodies in 1D, 2D and 3D, and what the collision formulas need of one at a contact.
//
// A body is either dynamic (finite mass, inertia about its centre of mass) or static
// (immovable: infinite mass and inertia, e.g. the ground or a wall; it may still move at a
// prescribed velocity). Inverse mass and inverse inertia of a static body are zero, so the
// formulas need no special case for it.
#pragma once

#include "engine/math.h"

namespace collide {

struct Body1 {
    double mass = 1.0;       // kg (ignored when is_static)
    bool is_static = false;  // immovable: infinite mass
    double position = 0.0;   // m, centre of mass on the line
    double v = 0.0;          // m/s
    double inv_mass() const { return is_static ? 0.0 : 1.0 / mass; }
    bool state_finite() const { return std::isfinite(position) && std::isfinite(v); }
};

struct Body2 {
    double mass = 1.0;  // kg (ignored when is_static)
    bool is_static = false;
    double inertia = 1.0;          // kg m^2, about the centre of mass (the z axis)
    double angle = 0.0;            // rad, counter-clockwise
    Vec2 position = Vec2::Zero();  // m, centre of mass
    Vec2 v = Vec2::Zero();         // m/s
    double w = 0.0;                // rad/s, counter-clockwise positive
    double inv_mass() const { return is_static ? 0.0 : 1.0 / mass; }
    double inv_inertia() const { return is_static ? 0.0 : 1.0 / inertia; }
    // Position, angle and velocities all finite (no NaN or infinity).
    bool state_finite() const {
        return position.allFinite() && v.allFinite() && std::isfinite(angle) && std::isfinite(w);
    }
};

struct Body3 {
    double mass = 1.0;  // kg (ignored when is_static)
    bool is_static = false;
    Mat3 inertia = Mat3::Identity();      // kg m^2, body frame, about the centre of mass
    Quat orientation = Quat::Identity();  // body frame -> world frame
    Vec3 position = Vec3::Zero();         // m, centre of mass
    Vec3 v = Vec3::Zero();                // m/s
    Vec3 w = Vec3::Zero();                // rad/s, world frame

    double inv_mass() const { return is_static ? 0.0 : 1.0 / mass; }
    // Position, orientation and velocities all finite (no NaN or infinity).
    bool state_finite() const {
        return position.allFinite() && v.allFinite() && orientation.coeffs().allFinite() && w.allFinite();
    }
    Mat3 rotation() const { return orientation.toRotationMatrix(); }
    // World inertia I = R Ibody R^T: recomputed from the orientation, never integrated.
    Mat3 inertia_world() const;
    // I^-1 = R Ibody^-1 R^T. A thin rod has a zero moment about its own axis; there the
    // pseudo-inverse is used (no torque about that axis can arise from an impulse applied on it).
    Mat3 inv_inertia_world() const;
};

// Inverse of a symmetric positive semi-definite inertia tensor; zero eigenvalues (a thin rod's
// axis) are left at zero (pseudo-inverse).
Mat3 inertia_pseudo_inverse(const Mat3& inertia);

// What the response formulas need of one body at the contact point p, all in world frame.
// r = p - x is measured from the body's centre of mass.
struct ImpactBody3 {
    double inv_m = 0.0;         // 1/kg (0: static)
    Mat3 inv_I = Mat3::Zero();  // world inverse inertia, 1/(kg m^2) (0: static)
    Mat3 I = Mat3::Zero();      // world inertia, kg m^2 (used by the stick model)
    Vec3 r = Vec3::Zero();      // m, contact point relative to the centre of mass
    Vec3 v = Vec3::Zero();      // m/s
    Vec3 w = Vec3::Zero();      // rad/s
    bool is_static() const { return inv_m == 0.0; }
};

struct ImpactBody2 {
    double inv_m = 0.0;
    double inv_I = 0.0;
    double I = 0.0;
    Vec2 r = Vec2::Zero();
    Vec2 v = Vec2::Zero();
    double w = 0.0;
    bool is_static() const { return inv_m == 0.0; }
};

struct ImpactBody1 {
    double inv_m = 0.0;
    double v = 0.0;
    bool is_static() const { return inv_m == 0.0; }
};

ImpactBody3 at_contact(const Body3& body, const Vec3& p);
ImpactBody2 at_contact(const Body2& body, const Vec2& p);
ImpactBody1 at_contact(const Body1& body);

// Contact-point velocity vp = v + w x r (the page: vpa = vca + wa x (r - pa)).
inline Vec3 point_velocity(const ImpactBody3& b) { return b.v + b.w.cross(b.r); }
inline Vec2 point_velocity(const ImpactBody2& b) { return b.v + cross(b.w, b.r); }

// A body's state in 3D form whatever its dimension (engine/math.h's lift): 1D along x, 2D in
// the xy plane turned by `angle` about +z. What the teaching code and the renderer show.
struct BodyState {
    Vec3 x = Vec3::Zero();      // m, centre of mass
    Quat q = Quat::Identity();  // orientation (2D: lift_angle(angle))
    double angle = 0.0;         // rad, 2D only
    Vec3 v = Vec3::Zero();      // m/s
    Vec3 w = Vec3::Zero();      // rad/s (2D: (0, 0, w); 1D: 0)
};
inline BodyState lifted(const Body1& b) {
    return {lift_line(b.position), Quat::Identity(), 0.0, lift_line(b.v), Vec3::Zero()};
}
inline BodyState lifted(const Body2& b) {
    return {lift(b.position), lift_angle(b.angle), b.angle, lift(b.v), lift_spin(b.w)};
}
inline BodyState lifted(const Body3& b) { return {b.position, b.orientation, 0.0, b.v, b.w}; }

}  // namespace collide
