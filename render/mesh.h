// Triangle meshes of the 3D view as plain arrays: what the GPU is given, built without GL so
// that their geometry can be checked on its own (tests/render/mesh_test.cpp).
//
// Conventions: a mesh is a triangle soup (vertices 3k, 3k+1, 3k+2 are triangle k); lengths in
// metres, or in units of the scale a model matrix applies (the arrow parts). Triangles are
// counter-clockwise seen from outside: (b - a) x (c - a) points out of the solid. Normals are
// unit vectors pointing out: per face on flat faces, per vertex on round ones (smooth shading).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace collide::render {

using Vec3f = Eigen::Vector3f;
using Mat3f = Eigen::Matrix3f;
using Mat4f = Eigen::Matrix4f;

struct Vertex {
    float p[3];  // position, in the mesh's frame
    float n[3];  // unit normal, outward
    float l[3];  // the position again: the shader paints patterns from it, so they turn with it
};
using Mesh = std::vector<Vertex>;

// Axis-aligned bounds of a mesh in its own frame (both zero for an empty mesh).
struct Box3f {
    Vec3f lo = Vec3f::Zero(), hi = Vec3f::Zero();
};
Box3f bounds(const Mesh& mesh);

// A box of half sizes h about the origin: 6 faces of 2 triangles (36 vertices).
Mesh box_mesh(const Vec3f& h);

// A sphere of radius r about the origin, y the polar axis: `rings` bands from pole to pole of
// `sectors` quads each, a quad being two triangles (6 rings sectors vertices; at the poles one
// of the two is degenerate).
Mesh sphere_mesh(float r, int rings = 24, int sectors = 48);

// A convex outline (counter-clockwise seen from +z, in the plane z = 0) extruded from
// z = -depth/2 to +depth/2: the two caps (fans of n - 2 triangles each) and n side quads.
// smooth: side normals radial from the z axis (a cylinder), else one per face (a prism).
Mesh prism_mesh(const std::vector<Vec3f>& outline, float depth, bool smooth);

// n points on a circle of radius r about the origin in the plane z = 0, counter-clockwise
// from +x: the outline of a disc.
std::vector<Vec3f> circle_outline(float r, int n);

// The parts of an arrow along +y, scaled by its model matrix: a cylinder of radius 1 from
// y = 0 to 1 (open ends, `segments` quads) and a cone of base radius 1 from its base at y = 0
// to its tip at y = 1 (`segments` side triangles, `segments` base triangles).
Mesh arrow_shaft(int segments = 20);
Mesh arrow_head(int segments = 24);

// The rotation taking +y (the arrow parts' axis) to the unit vector d. Within 0.26 degrees of
// +y or -y (|d.y| > 0.99999) it takes +y to exactly +y (identity) or -y (a half turn about x).
// In float, a few degrees from -y it is off by up to 1e-3 in direction and 0.5% in scale
// (Eigen's quaternion between nearly opposite vectors); elsewhere to 1e-5.
Mat3f rotation_from_y(const Vec3f& d);

}  // namespace collide::render
