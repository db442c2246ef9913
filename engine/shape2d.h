// 2D shapes and contact detection. Geometry only: nothing here knows masses or velocities.
//
// Every query returns the contact normal pointing from shape A into shape B (docs/conventions.md)
// and a signed separation: positive when apart (the exact distance, the normal then along the
// line between the nearest points), negative when overlapping (minus the depth along the
// separating axis of least overlap). Touching (apart or overlapping by a rounding error, as at
// the instant of a hit) the normal is that of the separating face, as for an overlap.
//
// Polygons are convex, counter-clockwise, in body coordinates about the centre of mass:
//
//        v2 ------ v1        edge i runs from v[i] to v[i+1]; normal[i] is its outward unit
//        |    x    |         normal (edge direction turned clockwise). Up to kMaxVertices.
//        v3 ------ v0
#pragma once

#include <array>
#include <string>
#include <vector>

#include "engine/math.h"

namespace collide {

// Where a body is: centre of mass and angle (rad, counter-clockwise).
struct Pose2 {
    Vec2 x = Vec2::Zero();
    double angle = 0.0;
    Vec2 apply(const Vec2& local) const;   // body -> world point
    Vec2 rotate(const Vec2& local) const;  // body -> world direction
};

struct Polygon {
    static constexpr int kMaxVertices = 16;
    int count = 0;
    std::array<Vec2, kMaxVertices> vertices;
    std::array<Vec2, kMaxVertices> normals;
    Polygon() {
        vertices.fill(Vec2::Zero());
        normals.fill(Vec2::Zero());
    }
};

// A convex polygon from counter-clockwise vertices, shifted so that its centroid (the centre of
// mass of a uniform plate) is the origin. `error` explains a refusal: fewer than 3 or more than
// kMaxVertices vertices, clockwise order, repeated points or a dent (not convex).
bool make_polygon(const std::vector<Vec2>& vertices, Polygon* out, std::string* error, Vec2* centroid = nullptr);
// Throws std::invalid_argument when make_polygon refuses it: one side under about 2e-9 of the
// other (scenario files refuse a ratio over 1e9 first: kMaxRectangleAspect).
constexpr double kMaxRectangleAspect = 1e9;
Polygon make_rectangle(double width, double height);
// Area, and moment of inertia per unit mass about the centroid (uniform plate).
double polygon_area(const Polygon& p);
double polygon_inertia_per_mass(const Polygon& p);

struct Shape2 {
    enum class Kind { disc, polygon, half_plane };
    Kind kind = Kind::disc;
    double radius = 0.0;  // disc
    Polygon polygon;      // polygon (rectangles too)
    // half_plane (static ground or wall): the solid side is {p : normal . p <= offset}, in world
    // coordinates (the pose is ignored).
    Vec2 normal = Vec2(0.0, 1.0);
    double offset = 0.0;

    static Shape2 disc(double radius);
    static Shape2 rectangle(double width, double height);
    static Shape2 half_plane(const Vec2& unit_normal, double offset);
};

struct Manifold2 {
    Vec2 normal = Vec2(1.0, 0.0);                               // unit, from A into B
    double separation = 0.0;                                    // signed: > 0 apart, < 0 overlapping (m)
    int count = 0;                                              // contact points found (0, 1 or 2)
    std::array<Vec2, 2> points = {Vec2::Zero(), Vec2::Zero()};  // world, midway between surfaces
    std::array<double, 2> depths{};                             // per point: signed separation along the normal (m)
};

// How collide() measures two polygons that are apart: `exact`, the distance between their
// nearest features, with the normal along it; `axis`, the separating axis's separation (a
// lower bound of the distance) with the reference face's normal, as the contact points are
// measured: enough for a speculative contact of a time step (engine/island_step.h), and about
// half the work. Touching or overlapping polygons, and discs, are measured alike either way.
enum class Apart { exact, axis };

// Contact points are reported for pairs whose separation is below `margin` (m); the
// separation and normal are reported always.
Manifold2 collide(const Shape2& a, const Pose2& pa, const Shape2& b, const Pose2& pb, double margin = 0.0,
                  Apart apart = Apart::exact);

// The largest distance of the shape's surface from its centre (m): bounds how fast a surface
// point can move, v + |w| R (conservative advancement).
double bounding_radius(const Shape2& s);

}  // namespace collide
