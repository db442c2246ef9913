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
    const Manifold2 m = collide(ground(), at(0, 0), rect(1, 1), at(0, h - 1e-3, kPi / 4));
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

// ---- Exact touching (separation within rounding of 0) --------------------------------------
// At the instant of a hit the separation is a rounding error (~1e-17 m, either sign). The normal
// must still be the face's, and a touching feature must still give contact points. The world
// asks with the margin World::kTouch = 1e-10 m.
constexpr double kTouchMargin = 1e-10;

Vec2 rotated(const Vec2& v, double angle) {
    return Vec2(std::cos(angle) * v.x() - std::sin(angle) * v.y(), std::sin(angle) * v.x() + std::cos(angle) * v.y());
}

// Lesson 6 (lessons/06-general-2d.toml) at the instant of its hit: A (0.4 x 0.2, 45 degrees)
// has its right-most corner on B's (0.2 x 0.6, upright at (0.3, 0.25)) left face x = 0.2,
// ~1e-17 m away. It came back with the normal (0.894, -0.447): the direction of the rounding
// noise between the two nearest points.
TEST(Shape2d, CornerTouchingFaceExactlyLesson6) {
    const Pose2 pa = at(-0.012132034355964327, 0, kPi / 4);
    const Pose2 pb = at(0.3, 0.25);
    const Vec2 corner = pa.apply(rect(0.4, 0.2).polygon.vertices[0]);  // (w, -h): right-most
    ASSERT_NEAR(corner.x(), 0.2, 1e-15);
    for (const double margin : {kTouchMargin, 0.0}) {
        SCOPED_TRACE(margin);
        const Manifold2 m = collide(rect(0.4, 0.2), pa, rect(0.2, 0.6), pb, margin);
        EXPECT_LE((m.normal - Vec2(1, 0)).norm(), 1e-12);  // B's face normal, from A into B
        EXPECT_NEAR(m.separation, 0.0, 1e-15);
        if (margin == 0.0) continue;  // reported apart by a rounding error: no points (contract)
        ASSERT_EQ(m.count, 1);
        EXPECT_LE((m.points[0] - corner).norm(), 1e-15);
        EXPECT_NEAR(m.depths[0], 0.0, 1e-15);
    }
    // B against A: the same contact, the normal flipped.
    const Manifold2 s = collide(rect(0.2, 0.6), pb, rect(0.4, 0.2), pa, kTouchMargin);
    EXPECT_LE((s.normal - Vec2(-1, 0)).norm(), 1e-12);
    ASSERT_EQ(s.count, 1);
    EXPECT_LE((s.points[0] - corner).norm(), 1e-15);
}

// A (0.4 x 0.2) turned by many angles, its right-most corner placed on the left face of B
// (0.2 x 0.6) at several heights, 0, +-1e-15 or +-1e-12 m from it. The whole scene is also
// turned by quarter turns (other faces of B) and by an arbitrary angle, and A and B swapped.
TEST(Shape2d, CornerTouchingFaceSweep) {
    const Shape2 a = rect(0.4, 0.2), b = rect(0.2, 0.6);
    const Vec2 xb(0.3, 0.25);
    int cases = 0;
    for (double theta = 0.05; theta <= 1.5 + 1e-9; theta += 0.01)
        for (const double height : {-0.04, 0.0707, 0.25, 0.5})  // corner height on B's face
            for (const double gap : {0.0, 1e-15, -1e-15, 1e-12, -1e-12})
                for (const double turn : {0.0, kPi / 2, kPi, 1.5 * kPi, 0.3})
                    for (const bool swap : {false, true}) {
                        // In B's frame: the corner (w, -h) of A, turned by theta, at (0.2 - gap, height).
                        const Vec2 c_local = rotated(Vec2(0.2, -0.1), theta);
                        const Vec2 xa = Vec2(0.2 - gap, height) - c_local;
                        const Pose2 pa{rotated(xa, turn), theta + turn};
                        const Pose2 pb{rotated(xb, turn), turn};
                        const Vec2 corner = pa.apply(a.polygon.vertices[0]);
                        const Vec2 face_normal = rotated(Vec2(-1, 0), turn);  // B's, outward
                        const Vec2 on_face = rotated(Vec2(0.2, 0.0), turn);
                        const Manifold2 m =
                            swap ? collide(b, pb, a, pa, kTouchMargin) : collide(a, pa, b, pb, kTouchMargin);
                        SCOPED_TRACE(testing::Message() << "theta " << theta << " height " << height << " gap " << gap
                                                        << " turn " << turn << " swap " << swap);
                        const Vec2 expected = swap ? face_normal : Vec2(-face_normal);
                        ASSERT_LE((m.normal - expected).norm(), 1e-9);
                        ASSERT_NEAR(m.separation, gap, 1e-14);
                        ASSERT_GE(m.count, 1);
                        // The point nearest the corner is at it and on B's face.
                        int k = 0;
                        if (m.count == 2 && (m.points[1] - corner).norm() < (m.points[0] - corner).norm()) k = 1;
                        EXPECT_LE((m.points[k] - corner).norm(), 1e-9);
                        EXPECT_LE(std::abs(face_normal.dot(m.points[k] - on_face)), 1e-9);
                        EXPECT_NEAR(m.depths[k], gap, 1e-14);
                        ++cases;
                    }
    EXPECT_GT(cases, 1000);
}

// Two faces flat against each other, 0, +-1e-15 or +-1e-12 m apart: two points, the ends of
// the overlap, in any orientation of the scene.
TEST(Shape2d, FaceOnFaceTouchingExactly) {
    int cases = 0;
    for (double turn = 0.0; turn < 2 * kPi; turn += 0.05)
        for (const double gap : {0.0, 1e-15, -1e-15, 1e-12, -1e-12})
            for (const double shift : {-0.3, 0.0, 0.45}) {
                // Before the turn: A 1 x 1 at the origin, B 2 x 0.5 above it, its bottom face at
                // y = 0.5 + gap; the scene then turned about A's centre and moved to (0.1, -0.2).
                const Pose2 pa{Vec2(0.1, -0.2), turn};
                const Pose2 pb{Vec2(0.1, -0.2) + rotated(Vec2(shift, 0.75 + gap), turn), turn};
                const Manifold2 m = collide(rect(1, 1), pa, rect(2, 0.5), pb, kTouchMargin);
                SCOPED_TRACE(testing::Message() << "turn " << turn << " gap " << gap << " shift " << shift);
                ASSERT_LE((m.normal - rotated(Vec2(0, 1), turn)).norm(), 1e-9);
                ASSERT_NEAR(m.separation, gap, 1e-14);
                ASSERT_EQ(m.count, 2);
                // B (2 wide) covers all of A's top face [-0.5, 0.5]: the points are its corners.
                for (int k = 0; k < 2; ++k) {
                    const Vec2 local = rotated(m.points[k] - pa.x, -turn);
                    EXPECT_NEAR(std::abs(local.x()), 0.5, 1e-9);
                    EXPECT_NEAR(local.y(), 0.5, 1e-9);
                    EXPECT_NEAR(m.depths[k], gap, 1e-14);
                }
                ++cases;
            }
    EXPECT_GT(cases, 1000);
}

// Corner on corner, a rounding error apart (B placed so that one of its corners is on one of
// A's, both turned): the line between the nearest points is rounding noise, so the normal must
// be an axis that separates the two shapes (every vertex of A behind it, every one of B in
// front, both through the shared corner), and the separation ~0.
TEST(Shape2d, CornerTouchingCornerExactly) {
    const Shape2 a = rect(1, 0.5), b = rect(0.6, 0.8);
    int cases = 0;
    for (double ta = 0.0; ta < 2 * kPi; ta += 0.1)
        for (double tb = 0.0; tb < 2 * kPi; tb += 0.1) {
            // A's corner i and B's corner j pointing at each other: the pair with A's corner
            // furthest along d and B's furthest along -d, d the direction from A to B.
            const Vec2 d = rotated(Vec2(1, 0), 0.5 * (ta + tb) + 0.25);
            const Pose2 pa = at(0.2, -0.1, ta);
            int i = 0, j = 0;
            for (int k = 1; k < 4; ++k) {
                if (d.dot(pa.rotate(a.polygon.vertices[k])) > d.dot(pa.rotate(a.polygon.vertices[i]))) i = k;
                if (-d.dot(rotated(b.polygon.vertices[k], tb)) > -d.dot(rotated(b.polygon.vertices[j], tb))) j = k;
            }
            const Vec2 c = pa.apply(a.polygon.vertices[i]);
            const Pose2 pb{c - rotated(b.polygon.vertices[j], tb), tb};
            // The pair is a corner-corner touch only if the two corners' outer cones overlap.
            bool separable = false;
            for (const Vec2& n :
                 {pa.rotate(a.polygon.normals[i]), pa.rotate(a.polygon.normals[(i + 3) % 4]),
                  Vec2(-pb.rotate(b.polygon.normals[j])), Vec2(-pb.rotate(b.polygon.normals[(j + 3) % 4]))}) {
                bool ok = true;
                for (int k = 0; k < 4; ++k) {
                    ok = ok && n.dot(pa.apply(a.polygon.vertices[k]) - c) <= 1e-12;
                    ok = ok && n.dot(pb.apply(b.polygon.vertices[k]) - c) >= -1e-12;
                }
                separable = separable || ok;
            }
            if (!separable) continue;
            const Manifold2 m = collide(a, pa, b, pb, kTouchMargin);
            SCOPED_TRACE(testing::Message() << "ta " << ta << " tb " << tb);
            EXPECT_NEAR(m.separation, 0.0, 1e-14);
            for (int k = 0; k < 4; ++k) {
                EXPECT_LE(m.normal.dot(pa.apply(a.polygon.vertices[k]) - c), 1e-9);
                EXPECT_GE(m.normal.dot(pb.apply(b.polygon.vertices[k]) - c), -1e-9);
            }
            EXPECT_GE(m.count, 1);
            ++cases;
        }
    EXPECT_GT(cases, 500);
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
