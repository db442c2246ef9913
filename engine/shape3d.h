// 3D shapes and contact detection. Geometry only: nothing here knows masses or velocities.
// The 3D counterpart of engine/shape2d.h; the box numbering is drawn at the top of shape3d.cpp.
//
// Every query returns the contact normal pointing from shape A into shape B (docs/conventions.md)
// and a signed separation: positive when apart, negative when overlapping (minus the depth).
// When apart, the separation is the exact distance for spheres, sphere-box and half-spaces; for
// two boxes it is the largest gap along the 15 separating axes, a lower bound of the distance
// (corner to corner, the true distance is larger).
//
// Swapping A and B flips the normal and keeps the separation and the points (up to the choice
// between two equally good axes of two boxes).
#pragma once

#include <array>

#include "engine/math.h"

namespace collide {

// Where a body is: centre of mass and orientation (a unit quaternion, body -> world).
struct Pose3 {
    Vec3 x = Vec3::Zero();
    Quat q = Quat::Identity();
    Vec3 apply(const Vec3& local) const;   // body -> world point
    Vec3 rotate(const Vec3& local) const;  // body -> world direction
};

struct Shape3 {
    enum class Kind { sphere, box, half_space };
    Kind kind = Kind::sphere;
    double radius = 0.0;       // sphere (m)
    Vec3 half = Vec3::Zero();  // box: half extents along the body axes (m), centred on the pose
    // half_space (static ground or wall): the solid side is {p : normal . p <= offset}, in world
    // coordinates (the pose is ignored). `normal` must be a unit vector.
    Vec3 normal = Vec3(0.0, 1.0, 0.0);
    double offset = 0.0;  // m
};

struct Manifold3 {
    Vec3 normal = Vec3(1.0, 0.0, 0.0);  // unit, from A into B
    double separation = 0.0;            // signed: > 0 apart, < 0 overlapping (m)
    int count = 0;                      // contact points found (0 to 4)
    // World, midway between the surfaces: p - depth/2 n lies on A, p + depth/2 n on B.
    std::array<Vec3, 4> points = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    std::array<double, 4> depths{};  // per point: signed separation along the normal (m)
};

// Contact points are reported for pairs whose separation is below `margin` (m), each point's
// depth below the margin too (so two boxes apart, whose separation is a lower bound, may have
// none); the separation and normal are reported always. Pairs:
//   sphere-sphere, sphere-box: exact (closest point on the box; a centre inside the box is
//     pushed out through the face of least penetration), one point;
//   box-box: separating axes, then the incident face clipped against the reference face
//     (up to 4 points: the deepest and those spanning the largest area), or one point
//     between two crossing edges;
//   against a half-space: a sphere's lowest point, a box's up to 4 deepest vertices;
//   half-space against half-space: separation +infinity, no point.
Manifold3 collide(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, double margin = 0.0);

// The largest distance of the shape's surface from its centre (m): bounds how fast a surface
// point can move, |v| + |w| R (conservative advancement). 0 for a half-space.
double bounding_radius(const Shape3& s);

}  // namespace collide
