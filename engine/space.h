// What differs between the 2D and 3D worlds: their types (Space<D>) and the few overloads
// through which one algorithm serves both (World<2>, World<3>: engine/world.h). A 2D spin is
// a number (rad/s about +z), a 3D one a vector; w x r, r x P and a body's pose follow.
#pragma once

#include <array>
#include <cmath>

#include "engine/body.h"
#include "engine/shape2d.h"
#include "engine/shape3d.h"

namespace collide {

template <int D>
struct Space;

template <>
struct Space<2> {
    using Vec = Vec2;
    using Spin = double;  // rad/s about +z
    using Body = Body2;
    using Shape = Shape2;
    using Pose = Pose2;
    using Manifold = Manifold2;
    static constexpr int kMaxPoints = 2;
};

template <>
struct Space<3> {
    using Vec = Vec3;
    using Spin = Vec3;  // rad/s, world frame
    using Body = Body3;
    using Shape = Shape3;
    using Pose = Pose3;
    using Manifold = Manifold3;
    static constexpr int kMaxPoints = 4;
};

template <class T>
T zero();
template <>
inline double zero<double>() {
    return 0.0;
}
template <>
inline Vec2 zero<Vec2>() {
    return Vec2::Zero();
}
template <>
inline Vec3 zero<Vec3>() {
    return Vec3::Zero();
}

inline double magnitude(double w) { return std::abs(w); }
inline double magnitude(const Vec3& w) { return w.norm(); }

inline Vec2 spin_cross(double w, const Vec2& r) { return cross(w, r); }  // w x r
inline Vec3 spin_cross(const Vec3& w, const Vec3& r) { return w.cross(r); }
inline double lever(const Vec2& r, const Vec2& P) { return cross(r, P); }  // r x P
inline Vec3 lever(const Vec3& r, const Vec3& P) { return r.cross(P); }

// Unit tangents spanning the contact plane of normal n: 2D one, 3D two (returns how many).
inline int tangents(const Vec2& n, std::array<Vec2, 2>* t) {
    (*t)[0] = perp(n);
    return 1;
}
inline int tangents(const Vec3& n, std::array<Vec3, 2>* t) {
    const Vec3 helper = std::abs(n.x()) < 0.57 ? Vec3::UnitX() : Vec3::UnitY();
    (*t)[0] = n.cross(helper).normalized();
    (*t)[1] = n.cross((*t)[0]);
    return 2;
}

inline Pose2 pose_of(const Body2& b) { return Pose2{b.position, b.angle}; }
inline Pose3 pose_of(const Body3& b) { return Pose3{b.position, b.orientation}; }

}  // namespace collide
