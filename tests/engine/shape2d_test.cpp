// 2D contact detection against hand-computed geometry.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/mass.h"
#include "engine/shape2d.h"

namespace collide {
namespace {

constexpr double kTol = 1e-12;

Shape2 disc(double r) { return Shape2::disc(r); }
Shape2 rect(double w, double h) { return Shape2::rectangle(w, h); }
Shape2 ground(double height = 0.0) { return Shape2::half_plane(Vec2(0, 1), height); }
Pose2 at(double x, double y, double angle = 0.0) { return Pose2{Vec2(x, y), angle}; }

// Two discs: separation |xb - xa| - ra - rb along the line of centres.
TEST(Shape2d, DiscDisc) {
    const Manifold2 m = collide(disc(0.5), at(0, 0), disc(0.25), at(3, 4), 1.0);
    EXPECT_NEAR(m.separation, 5 - 0.75, kTol);
    EXPECT_LE((m.normal - Vec2(0.6, 0.8)).norm(), kTol);
    EXPECT_EQ(m.count, 0);  // 4.25 m apart: beyond the 1 m margin
    const Manifold2 touch = collide(disc(0.5), at(0, 0), disc(0.5), at(0.9, 0));
    ASSERT_EQ(touch.count, 1);
    EXPECT_NEAR(touch.separation, -0.1, kTol);
    EXPECT_LE((touch.points[0] - Vec2(0.45, 0)).norm(), kTol);  // midway between surfaces
}

// A disc above the middle of a 2 x 1 rectangle: face region, separation = y - 0.5 - r.
TEST(Shape2d, DiscAboveRectangleFace) {
    const Manifold2 m = collide(rect(2, 1), at(0, 0), disc(0.2), at(0.3, 0.65), 0.1);
    EXPECT_NEAR(m.separation, 0.65 - 0.5 - 0.2, kTol);
    EXPECT_LE((m.normal - Vec2(0, 1)).norm(), kTol);
    ASSERT_EQ(m.count, 1);
    EXPECT_LE((m.points[0] - Vec2(0.3, 0.475)).norm(), kTol);
}

// Beyond a corner the nearest feature is the vertex: separation |c - corner| - r, normal along it.
TEST(Shape2d, DiscNearRectangleCorner) {
    const Manifold2 m = collide(disc(0.1), at(1 + 0.3, 0.5 + 0.4), rect(2, 1), at(0, 0));
    EXPECT_NEAR(m.separation, 0.5 - 0.1, kTol);
    EXPECT_LE((m.normal - Vec2(-0.6, -0.8)).norm(), kTol);  // from the disc (A) into the box (B)
}

// A 1 x 0.5 box resting 1 mm into the ground: two points, both 1 mm deep, normal up (A = ground).
TEST(Shape2d, BoxOnGroundHasTwoPoints) {
    const Manifold2 m = collide(ground(), at(0, 0), rect(1, 0.5), at(2, 0.249));
    EXPECT_NEAR(m.separation, -0.001, kTol);
    ASSERT_EQ(m.count, 2);
    EXPECT_LE((m.normal - Vec2(0, 1)).norm(), kTol);
    for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(m.depths[i], -0.001, kTol);
        EXPECT_NEAR(std::abs(m.points[i].x() - 2), 0.5, kTol);
    }
    // Swapping the bodies flips the normal only.
    const Manifold2 s = collide(rect(1, 0.5), at(2, 0.249), ground(), at(0, 0));
    EXPECT_LE((s.normal - Vec2(0, -1)).norm(), kTol);
    EXPECT_NEAR(s.separation, m.separation, kTol);
}

// A box tilted by 45 degrees touches the ground with one corner, sqrt(2)/2 below its centre.
TEST(Shape2d, TiltedBoxCornerOnGround) {
    const double h = std::sqrt(0.5);
    const Manifold2 m = collide(ground(), at(0, 0), rect(1, 1), at(0, h - 1e-3, M_PI / 4));
    EXPECT_NEAR(m.separation, -1e-3, 1e-12);
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.points[0].x(), 0.0, 1e-12);
}

// Two unit squares stacked with 0.01 overlap and offset by 0.5 in x: the overlap of their faces
// is [0, 0.5] wide, so the clipped points are at x = 0 and x = 0.5, each 0.01 deep.
TEST(Shape2d, FaceOnFaceClipsToTheOverlap) {
    const Manifold2 m = collide(rect(1, 1), at(0, 0), rect(1, 1), at(0.5, 0.99));
    EXPECT_NEAR(m.separation, -0.01, kTol);
    EXPECT_LE((m.normal - Vec2(0, 1)).norm(), kTol);
    ASSERT_EQ(m.count, 2);
    const double x0 = std::min(m.points[0].x(), m.points[1].x());
    const double x1 = std::max(m.points[0].x(), m.points[1].x());
    EXPECT_NEAR(x0, 0.0, kTol);
    EXPECT_NEAR(x1, 0.5, kTol);
    EXPECT_NEAR(m.depths[0], -0.01, kTol);
}

// Separated squares meeting corner to corner along the diagonal: the exact distance is between
// the two corners, not the (smaller) separation along a face axis.
TEST(Shape2d, SeparatedCornersReportExactDistance) {
    const Manifold2 m = collide(rect(1, 1), at(0, 0), rect(1, 1), at(1.3, 1.4));
    EXPECT_NEAR(m.separation, std::hypot(0.3, 0.4), kTol);
    EXPECT_LE((m.normal - Vec2(0.6, 0.8)).norm(), kTol);  // corner to corner, A into B
    EXPECT_EQ(m.count, 0);
}

TEST(Shape2d, PolygonValidation) {
    Polygon p;
    std::string err;
    EXPECT_FALSE(make_polygon({Vec2(0, 0), Vec2(0, 1), Vec2(1, 0)}, &p, &err));  // clockwise
    EXPECT_NE(err.find("counter-clockwise"), std::string::npos);
    EXPECT_FALSE(make_polygon({Vec2(0, 0), Vec2(2, 0), Vec2(1, 0.2), Vec2(2, 2), Vec2(0, 2)}, &p, &err));
    EXPECT_FALSE(make_polygon({Vec2(0, 0), Vec2(1, 0)}, &p, &err));
    EXPECT_FALSE(make_polygon({Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(0, 1)}, &p, &err));
    // Right triangle (0,0), (3,0), (0,3): centroid (1, 1), area 4.5.
    Vec2 c;
    ASSERT_TRUE(make_polygon({Vec2(0, 0), Vec2(3, 0), Vec2(0, 3)}, &p, &err, &c));
    EXPECT_LE((c - Vec2(1, 1)).norm(), kTol);
    EXPECT_NEAR(polygon_area(p), 4.5, kTol);
    // Its polar moment per unit mass about the centroid: (a^2 + b^2) / 18 for legs a, b.
    EXPECT_NEAR(polygon_inertia_per_mass(p), (9.0 + 9.0) / 18.0, kTol);
}

TEST(Shape2d, RectangleInertiaMatchesMassProperties) {
    const Polygon p = make_rectangle(2, 0.5);
    EXPECT_NEAR(polygon_area(p), 1.0, kTol);
    EXPECT_NEAR(polygon_inertia_per_mass(p), rectangle_inertia_2d(1.0, 2, 0.5), kTol);
    EXPECT_NEAR(bounding_radius(rect(2, 0.5)), std::hypot(1, 0.25), kTol);
}

}  // namespace
}  // namespace collide
