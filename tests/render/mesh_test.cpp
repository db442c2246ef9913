// The 3D view's meshes as geometry (render/mesh.h), without GL: where the vertices lie, that
// normals are unit and point out, that every triangle is wound counter-clockwise from outside
// (so that its face normal agrees with the shading normals), how many vertices a tessellation
// gives, and that closed meshes enclose the volume of the solid they stand for.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/math.h"
#include "render/mesh.h"

namespace collide::render {
namespace {

Vec3f position(const Vertex& v) { return Vec3f(v.p[0], v.p[1], v.p[2]); }
Vec3f normal(const Vertex& v) { return Vec3f(v.n[0], v.n[1], v.n[2]); }

// (b - a) x (c - a) of triangle t: twice its area, along its face normal by the winding.
Vec3f face(const Mesh& m, std::size_t t) {
    const Vec3f a = position(m[3 * t]), b = position(m[3 * t + 1]), c = position(m[3 * t + 2]);
    return (b - a).cross(c - a);
}

// The volume a closed mesh encloses, by the divergence theorem: the sum of a . (b x c) / 6
// over its triangles. Positive when they are wound counter-clockwise from outside.
double enclosed_volume(const Mesh& m) {
    double v = 0.0;
    for (std::size_t t = 0; 3 * t + 2 < m.size(); ++t) {
        const Eigen::Vector3d a = position(m[3 * t]).cast<double>(), b = position(m[3 * t + 1]).cast<double>(),
                              c = position(m[3 * t + 2]).cast<double>();
        v += a.dot(b.cross(c)) / 6.0;
    }
    return v;
}

// Every triangle whose area is above `min_area` is wound so that its face normal agrees with
// the shading normals at its three corners.
void expect_winding_matches_normals(const Mesh& m, float min_area) {
    ASSERT_EQ(m.size() % 3, 0u);
    int checked = 0;
    for (std::size_t t = 0; t < m.size() / 3; ++t) {
        const Vec3f f = face(m, t);
        if (0.5f * f.norm() <= min_area) continue;
        ++checked;
        for (int k = 0; k < 3; ++k)
            EXPECT_GT(f.normalized().dot(normal(m[3 * t + k])), 0.0f) << "triangle " << t << " corner " << k;
    }
    EXPECT_GT(checked, 0);
}

void expect_unit_normals(const Mesh& m) {
    for (std::size_t i = 0; i < m.size(); ++i) EXPECT_NEAR(normal(m[i]).norm(), 1.0f, 1e-6f) << "vertex " << i;
}

// The local attribute is the position (patterns are painted from it).
void expect_local_is_position(const Mesh& m) {
    for (const Vertex& v : m)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(v.l[k], v.p[k]);
}

TEST(MeshTest, SphereVerticesLieOnItsSurfaceWithOutwardUnitNormals) {
    const float r = 0.37f;
    const Mesh m = sphere_mesh(r);
    ASSERT_EQ(m.size(), 6u * 24 * 48);
    for (const Vertex& v : m) {
        EXPECT_NEAR(position(v).norm(), r, 1e-6f * 4);
        // The normal is the outward radial direction.
        EXPECT_NEAR(normal(v).norm(), 1.0f, 1e-6f);
        EXPECT_LT((normal(v) - position(v) / r).norm(), 1e-5f);
    }
    expect_local_is_position(m);
    // Away from the poles (where one triangle of each quad has no area) every triangle faces out.
    expect_winding_matches_normals(m, 1e-6f * r * r);
}

TEST(MeshTest, SphereTessellationCountsAndReachesBothPoles) {
    for (const auto& [rings, sectors] : {std::pair(2, 3), std::pair(5, 7), std::pair(24, 48)}) {
        const Mesh m = sphere_mesh(1.0f, rings, sectors);
        EXPECT_EQ(m.size(), 6u * static_cast<std::size_t>(rings * sectors));
        const Box3f b = bounds(m);
        EXPECT_NEAR(b.hi.y(), 1.0f, 1e-6f);
        EXPECT_NEAR(b.lo.y(), -1.0f, 1e-6f);
    }
}

TEST(MeshTest, SphereEnclosesNearlyItsVolume) {
    // An inscribed polyhedron: a little less than 4/3 pi r^3, closer with finer tessellation.
    const double r = 2.0, sphere = 4.0 / 3.0 * kPi * r * r * r;
    const double coarse = enclosed_volume(sphere_mesh(static_cast<float>(r), 8, 16));
    const double fine = enclosed_volume(sphere_mesh(static_cast<float>(r)));
    EXPECT_LT(coarse, fine);
    EXPECT_LT(fine, sphere);
    EXPECT_GT(fine, 0.98 * sphere);
}

TEST(MeshTest, BoxCornersAreAtItsHalfSizesWithFaceNormals) {
    const Vec3f h(0.5f, 0.25f, 1.5f);
    const Mesh m = box_mesh(h);
    ASSERT_EQ(m.size(), 36u);
    const Box3f b = bounds(m);
    EXPECT_EQ(b.lo, -h);
    EXPECT_EQ(b.hi, h);
    for (const Vertex& v : m) {
        const Vec3f p = position(v), n = normal(v);
        // Every vertex is a corner, and its normal is the axis of the face it belongs to, out.
        for (int k = 0; k < 3; ++k) EXPECT_EQ(std::abs(p[k]), h[k]);
        EXPECT_EQ(n.cwiseAbs().sum(), 1.0f);
        EXPECT_EQ(n.dot(p), n.cwiseAbs().dot(h));
    }
    expect_unit_normals(m);
    expect_local_is_position(m);
    expect_winding_matches_normals(m, 0.0f);
    EXPECT_NEAR(enclosed_volume(m), 8.0 * 0.5 * 0.25 * 1.5, 1e-6);
}

TEST(MeshTest, BoxFacesEachCoverTheirRectangleOnce) {
    const Vec3f h(1.0f, 2.0f, 3.0f);
    const Mesh m = box_mesh(h);
    // Two triangles a face: their areas add up to the face's, for each of the 6 faces.
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            float area = 0.0f;
            int triangles = 0;
            for (std::size_t t = 0; t < 12; ++t)
                if (normal(m[3 * t])[axis] == sign) {
                    area += 0.5f * face(m, t).norm();
                    ++triangles;
                }
            const int u = (axis + 1) % 3, w = (axis + 2) % 3;
            EXPECT_EQ(triangles, 2);
            EXPECT_FLOAT_EQ(area, 4.0f * h[u] * h[w]);
        }
}

// A convex outline, counter-clockwise: an irregular pentagon.
std::vector<Vec3f> pentagon() {
    return {{0.0f, -1.0f, 0}, {1.2f, -0.4f, 0}, {0.9f, 0.8f, 0}, {-0.3f, 1.1f, 0}, {-1.0f, 0.1f, 0}};
}

// Its area (shoelace).
double outline_area(const std::vector<Vec3f>& o) {
    double a = 0.0;
    for (std::size_t k = 0; k < o.size(); ++k) {
        const Vec3f& p = o[k];
        const Vec3f& q = o[(k + 1) % o.size()];
        a += 0.5 * (static_cast<double>(p.x()) * q.y() - static_cast<double>(q.x()) * p.y());
    }
    return a;
}

TEST(MeshTest, PrismIsTheOutlineExtrudedToItsDepth) {
    const std::vector<Vec3f> o = pentagon();
    const float depth = 0.8f;
    const Mesh m = prism_mesh(o, depth, false);
    // Caps: 2 fans of n - 2 triangles; sides: n quads of 2 triangles.
    ASSERT_EQ(m.size(), 3u * (2 * (o.size() - 2) + 2 * o.size()));
    for (const Vertex& v : m) {
        EXPECT_EQ(std::abs(v.p[2]), 0.5f * depth);
        // Every vertex is one of the outline's points, raised or lowered.
        bool on_outline = false;
        for (const Vec3f& p : o) on_outline = on_outline || (p.x() == v.p[0] && p.y() == v.p[1]);
        EXPECT_TRUE(on_outline);
    }
    expect_unit_normals(m);
    expect_local_is_position(m);
    expect_winding_matches_normals(m, 0.0f);
    EXPECT_NEAR(enclosed_volume(m), outline_area(o) * depth, 1e-5);
}

TEST(MeshTest, PrismSideNormalsAreFlatOrRadial) {
    const std::vector<Vec3f> o = pentagon();
    const Mesh flat = prism_mesh(o, 1.0f, false);
    const Mesh smooth = prism_mesh(o, 1.0f, true);
    ASSERT_EQ(flat.size(), smooth.size());
    const std::size_t sides = 3 * 2 * (o.size() - 2);  // the caps come first
    for (std::size_t i = sides; i < flat.size(); ++i) {
        EXPECT_EQ(flat[i].n[2], 0.0f);
        // Smooth: the direction from the axis to the vertex.
        const Vec3f radial = Vec3f(smooth[i].p[0], smooth[i].p[1], 0.0f).normalized();
        EXPECT_LT((normal(smooth[i]) - radial).norm(), 1e-6f);
    }
    // Flat: the two triangles of a side share one normal, perpendicular to the side.
    for (std::size_t t = sides / 3; t < flat.size() / 3; ++t) {
        const Vec3f f = face(flat, t).normalized();
        for (int k = 0; k < 3; ++k) EXPECT_LT((normal(flat[3 * t + k]) - f).norm(), 1e-6f);
    }
}

TEST(MeshTest, DiscOutlineIsACounterClockwiseCircle) {
    const float r = 0.3f;
    const std::vector<Vec3f> o = circle_outline(r, 64);
    ASSERT_EQ(o.size(), 64u);
    EXPECT_EQ(o[0], Vec3f(r, 0, 0));
    for (const Vec3f& p : o) {
        EXPECT_NEAR(p.norm(), r, 1e-7f);
        EXPECT_EQ(p.z(), 0.0f);
    }
    // A regular 64-gon inscribed in the circle, counter-clockwise: positive area.
    EXPECT_NEAR(outline_area(o), 0.5 * 64 * r * r * std::sin(2 * kPi / 64), 1e-6);
    // Extruded smooth, it is the cylinder of a 2D disc.
    const Mesh m = prism_mesh(o, 0.5f, true);
    expect_winding_matches_normals(m, 0.0f);
}

TEST(MeshTest, ArrowShaftIsAUnitCylinderAlongY) {
    const int segments = 20;
    const Mesh m = arrow_shaft(segments);
    ASSERT_EQ(m.size(), 6u * segments);
    for (const Vertex& v : m) {
        EXPECT_NEAR(std::hypot(v.p[0], v.p[2]), 1.0f, 1e-6f);
        EXPECT_TRUE(v.p[1] == 0.0f || v.p[1] == 1.0f);
        EXPECT_EQ(v.n[1], 0.0f);
        EXPECT_NEAR(v.n[0], v.p[0], 1e-6f);
        EXPECT_NEAR(v.n[2], v.p[2], 1e-6f);
    }
    expect_unit_normals(m);
    expect_winding_matches_normals(m, 0.0f);
    const Box3f b = bounds(m);
    EXPECT_NEAR(b.lo.x(), -1.0f, 1e-6f);
    EXPECT_NEAR(b.hi.z(), 1.0f, 1e-6f);
    EXPECT_EQ(b.lo.y(), 0.0f);
    EXPECT_EQ(b.hi.y(), 1.0f);
}

TEST(MeshTest, ArrowHeadIsAClosedConeWithItsTipAtYOne) {
    const int n = 24;
    const Mesh m = arrow_head(n);
    ASSERT_EQ(m.size(), 6u * n);
    for (const Vertex& v : m) {
        const Vec3f p = position(v);
        // On the base circle, the tip or the base's centre.
        const bool rim = p.y() == 0.0f && std::abs(std::hypot(p.x(), p.z()) - 1.0f) < 1e-6f;
        EXPECT_TRUE(rim || p == Vec3f(0, 1, 0) || p == Vec3f::Zero()) << p.transpose();
    }
    expect_unit_normals(m);
    expect_winding_matches_normals(m, 0.0f);
    // A pyramid on the inscribed n-gon, height 1: a third of the base's area.
    EXPECT_NEAR(enclosed_volume(m), 0.5 * n * std::sin(2 * kPi / n) / 3.0, 1e-6);
}

TEST(MeshTest, RotationFromYTakesYToTheDirection) {
    const Vec3f directions[] = {Vec3f(0, 1, 0),
                                Vec3f(0, -1, 0),
                                Vec3f(1, 0, 0),
                                Vec3f(0, 0, -1),
                                Vec3f(0.3f, -0.8f, 0.52f).normalized(),
                                Vec3f(0.2f, -1, 0.1f).normalized()};
    for (const Vec3f& d : directions) {
        const Mat3f R = rotation_from_y(d);
        EXPECT_LT((R * Vec3f(0, 1, 0) - d).norm(), 1e-5f) << d.transpose();
        EXPECT_LT((R.transpose() * R - Mat3f::Identity()).norm(), 1e-5f);
        EXPECT_NEAR(R.determinant(), 1.0f, 1e-5f);
    }
    // Within a few degrees of -y, the looser bound mesh.h states.
    for (double deg : {0.3, 0.5, 1.0, 2.0, 5.0}) {
        const double a = deg * kPi / 180.0;
        const Vec3f d(static_cast<float>(std::sin(a)), static_cast<float>(-std::cos(a)), 0);
        const Mat3f R = rotation_from_y(d);
        EXPECT_LT((R * Vec3f(0, 1, 0) - d).norm(), 1e-3f) << deg << " degrees";
        EXPECT_NEAR(R.determinant(), 1.0f, 5e-3f) << deg << " degrees";
    }
}

TEST(MeshTest, RotationFromYIsExactlyVerticalNearTheVertical) {
    // 0.1 degree off +y and off -y: turned to the vertical itself, without rounding noise.
    const float off = static_cast<float>(0.1 * kPi / 180.0);
    const Vec3f up(std::sin(off), std::cos(off), 0), down(std::sin(off), -std::cos(off), 0);
    EXPECT_EQ(rotation_from_y(up) * Vec3f(0, 1, 0), Vec3f(0, 1, 0));
    EXPECT_LT((rotation_from_y(down) * Vec3f(0, 1, 0) - Vec3f(0, -1, 0)).norm(), 1e-6f);
    EXPECT_NEAR(rotation_from_y(down).determinant(), 1.0f, 1e-6f);
}

TEST(MeshTest, BoundsOfAnEmptyMeshAreZero) {
    const Box3f b = bounds(Mesh{});
    EXPECT_EQ(b.lo, Vec3f::Zero());
    EXPECT_EQ(b.hi, Vec3f::Zero());
}

}  // namespace
}  // namespace collide::render
