// The bodies of a scene as the 3D view shows them (render/solid.h), without GL: the shapes'
// sizes, the edges that are outlined, the extrusion of 1D and 2D bodies, and where a ray from
// the centre leaves the surface (arrows start there).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/math.h"
#include "engine/scene.h"
#include "render/solid.h"

namespace collide::render {
namespace {

SceneBody body3(const Shape3& shape) {
    SceneBody b;
    b.shape3 = shape;
    return b;
}

Shape3 box(const Vec3& half) {
    Shape3 s;
    s.kind = Shape3::Kind::box;
    s.half = half;
    return s;
}

Shape3 sphere(double r) {
    Shape3 s;
    s.kind = Shape3::Kind::sphere;
    s.radius = r;
    return s;
}

Scene scene3(const std::vector<Shape3>& shapes) {
    Scene scene;
    scene.dimension = 3;
    for (const Shape3& s : shapes) scene.bodies.push_back(body3(s));
    return scene;
}

TEST(SolidTest, BoxOutlinesItsTwelveEdges) {
    const Vec3 h(0.4, 0.1, 0.25);
    const Solids solids = make_solids(scene3({box(h)}));
    ASSERT_EQ(solids.bodies.size(), 1u);
    const Solid& s = solids.bodies[0];
    EXPECT_EQ(s.kind, Solid::Kind::box);
    EXPECT_EQ(s.mesh.size(), 36u);
    ASSERT_EQ(s.edges.size(), 12u);
    // Each edge joins two corners along one axis: 4 along each of x, y, z, all different.
    int along[3] = {0, 0, 0};
    for (const auto& [a, b] : s.edges) {
        for (int k = 0; k < 3; ++k) {
            EXPECT_FLOAT_EQ(std::abs(a[k]), static_cast<float>(h[k]));
            EXPECT_FLOAT_EQ(std::abs(b[k]), static_cast<float>(h[k]));
        }
        const Vec3f d = b - a;
        int axis = -1;
        for (int k = 0; k < 3; ++k)
            if (d[k] != 0.0f) axis = k;
        ASSERT_GE(axis, 0);
        EXPECT_FLOAT_EQ(d.norm(), static_cast<float>(2.0 * h[axis]));
        ++along[axis];
        int same = 0;
        for (const auto& [a2, b2] : s.edges) same += (a2 == a && b2 == b) || (a2 == b && b2 == a);
        EXPECT_EQ(same, 1) << "an edge outlined twice";
    }
    EXPECT_EQ(along[0], 4);
    EXPECT_EQ(along[1], 4);
    EXPECT_EQ(along[2], 4);
    EXPECT_NEAR(s.size, 2.0 * h.norm(), 1e-6);
}

TEST(SolidTest, RayLeavesABoxThroughTheFaceItMeets) {
    const Vec3 h(0.4, 0.1, 0.25);
    const Solid s = make_solids(scene3({box(h)})).bodies[0];
    const Quat none = Quat::Identity();
    EXPECT_DOUBLE_EQ(exit_distance(s, none, Vec3::UnitX()), 0.4);
    EXPECT_DOUBLE_EQ(exit_distance(s, none, -Vec3::UnitY()), 0.1);
    EXPECT_DOUBLE_EQ(exit_distance(s, none, Vec3::UnitZ()), 0.25);
    // Towards a corner: the whole half diagonal.
    EXPECT_NEAR(exit_distance(s, none, h.normalized()), h.norm(), 1e-12);
    // Turned a quarter about z: world x runs along the body's y.
    const Quat quarter(Eigen::AngleAxisd(kPi / 2, Vec3::UnitZ()));
    EXPECT_NEAR(exit_distance(s, quarter, Vec3::UnitX()), 0.1, 1e-12);
}

TEST(SolidTest, SphereHasNoEdgesAndIsLeftAtItsRadius) {
    const Solids solids = make_solids(scene3({sphere(0.3)}));
    const Solid& s = solids.bodies[0];
    EXPECT_EQ(s.kind, Solid::Kind::sphere);
    EXPECT_TRUE(s.edges.empty());
    EXPECT_FLOAT_EQ(s.radius, 0.3f);
    EXPECT_FLOAT_EQ(s.size, 0.6f);
    const Quat q(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
    EXPECT_NEAR(exit_distance(s, q, Vec3(1, -1, 1).normalized()), 0.3, 1e-7);
}

TEST(SolidTest, HalfSpacesArePlanesNotSolids) {
    Shape3 ground;
    ground.kind = Shape3::Kind::half_space;
    ground.normal = Vec3::UnitY();
    ground.offset = -0.5;
    const Solids solids = make_solids(scene3({sphere(0.3), ground}));
    ASSERT_EQ(solids.bodies.size(), 2u);
    EXPECT_FALSE(solids.bodies[1].drawn());
    EXPECT_TRUE(solids.bodies[0].drawn());
    ASSERT_EQ(solids.planes.size(), 1u);
    EXPECT_EQ(solids.planes[0].normal, Vec3::UnitY());
    EXPECT_EQ(solids.planes[0].offset, -0.5);
    EXPECT_EQ(solids.extrude, 0.0);  // 3D bodies are not extruded
}

TEST(SolidTest, TwoDimensionalBodiesAreExtrudedToACommonDepth) {
    Scene scene;
    scene.dimension = 2;
    for (const Shape2& shape :
         {Shape2::disc(0.25), Shape2::rectangle(1.0, 0.5), Shape2::disc(0.5), Shape2::half_plane(Vec2(0, 1), 0.0)}) {
        SceneBody b;
        b.shape2 = shape;
        scene.bodies.push_back(b);
    }
    const Solids solids = make_solids(scene);
    // 0.6 x the median size of the three bodies (0.5, 1.118, 1.0).
    EXPECT_NEAR(solids.extrude, 0.6 * 1.0, 1e-12);
    ASSERT_EQ(solids.bodies.size(), 4u);
    for (std::size_t i = 0; i < 3; ++i) {
        const Box3f b = bounds(solids.bodies[i].mesh);
        EXPECT_NEAR(b.lo.z(), -0.3f, 1e-6f);
        EXPECT_NEAR(b.hi.z(), 0.3f, 1e-6f);
    }
    // A disc: a cylinder, outlined by its two rims (64 segments each) and a radius line.
    const Solid& disc = solids.bodies[0];
    EXPECT_EQ(disc.kind, Solid::Kind::cylinder);
    EXPECT_EQ(disc.edges.size(), 2u * 64 + 1);
    EXPECT_NEAR(bounds(disc.mesh).hi.x(), 0.25f, 1e-6f);
    // A rectangle: a prism with both rims and its 4 vertical edges.
    const Solid& rectangle = solids.bodies[1];
    EXPECT_EQ(rectangle.kind, Solid::Kind::prism);
    EXPECT_EQ(rectangle.edges.size(), 12u);
    EXPECT_NEAR(rectangle.size, std::hypot(1.0, 0.5), 1e-6);
    // The half-plane: a plane in the xy plane's 3D lift.
    EXPECT_FALSE(solids.bodies[3].drawn());
    ASSERT_EQ(solids.planes.size(), 1u);
    EXPECT_EQ(solids.planes[0].normal, Vec3(0, 1, 0));
}

TEST(SolidTest, OneDimensionalBlocksAreBoxesOnTheAxis) {
    Scene scene;
    scene.dimension = 1;
    for (double length : {0.5, 1.0, 2.0}) {
        SceneBody b;
        b.length = length;
        scene.bodies.push_back(b);
    }
    const Solids solids = make_solids(scene);
    EXPECT_NEAR(solids.extrude, 0.6 * 1.0, 1e-12);  // the median length
    const Solid& s = solids.bodies[2];
    EXPECT_EQ(s.kind, Solid::Kind::box);
    const Box3f b = bounds(s.mesh);
    // 2 m long, as tall as 0.8 of the median length (frame_state.h: block_height), extruded.
    EXPECT_NEAR(b.hi.x(), 1.0f, 1e-6f);
    EXPECT_NEAR(b.hi.y(), 0.4f, 1e-6f);
    EXPECT_NEAR(b.hi.z(), 0.3f, 1e-6f);
    EXPECT_NEAR(exit_distance(s, Quat::Identity(), -Vec3::UnitX()), 1.0, 1e-12);
    EXPECT_NEAR(exit_distance(s, Quat::Identity(), Vec3::UnitZ()), 0.3, 1e-12);
}

}  // namespace
}  // namespace collide::render
