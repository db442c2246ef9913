// 3D contact detection against hand-computed geometry.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/shape3d.h"
#include "tests/engine/random_bodies.h"

namespace collide {
namespace {

constexpr double kTol = 1e-12;

Shape3 sphere(double r) {
    Shape3 s;
    s.kind = Shape3::Kind::sphere;
    s.radius = r;
    return s;
}
Shape3 box(double hx, double hy, double hz) {
    Shape3 s;
    s.kind = Shape3::Kind::box;
    s.half = Vec3(hx, hy, hz);
    return s;
}
Shape3 half_space(const Vec3& normal, double offset) {
    Shape3 s;
    s.kind = Shape3::Kind::half_space;
    s.normal = normal;
    s.offset = offset;
    return s;
}
Shape3 ground() { return half_space(Vec3(0, 1, 0), 0.0); }
Pose3 at(double x, double y, double z, const Quat& q = Quat::Identity()) { return Pose3{Vec3(x, y, z), q}; }
Quat about(const Vec3& axis, double angle) { return Quat(Eigen::AngleAxisd(angle, axis.normalized())); }

// Exact signed distance of p from the shape's surface (negative inside), from Eigen directly.
double signed_distance(const Shape3& s, const Pose3& pose, const Vec3& p) {
    switch (s.kind) {
        case Shape3::Kind::sphere: return (p - pose.x).norm() - s.radius;
        case Shape3::Kind::half_space: return s.normal.dot(p) - s.offset;
        case Shape3::Kind::box: {
            const Vec3 q = (pose.q.conjugate() * (p - pose.x)).cwiseAbs() - s.half;
            return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
        }
    }
    return 0.0;
}

// The manifold's points as a sorted list, to compare two manifolds whatever the point order.
std::vector<Vec3> sorted_points(const Manifold3& m) {
    std::vector<Vec3> p(m.points.begin(), m.points.begin() + m.count);
    std::sort(p.begin(), p.end(), [](const Vec3& a, const Vec3& b) {
        return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    });
    return p;
}

// True if p is within tol of one of the expected points.
bool near_one_of(const Vec3& p, const std::vector<Vec3>& expected, double tol) {
    for (const Vec3& e : expected)
        if ((p - e).norm() <= tol) return true;
    return false;
}

// A fixed rotation and shift applied to a whole scene, so that the hand computation can be done
// in the box's frame and the code still sees a general pose.
struct Scene {
    Quat q = about(Vec3(1, 2, 3), 0.7);
    Vec3 t = Vec3(0.4, -1.2, 2.5);
    Vec3 point(const Vec3& local) const { return t + q * local; }
    Vec3 dir(const Vec3& local) const { return q * local; }
    Pose3 pose(const Vec3& local) const { return Pose3{point(local), q}; }
};

// Two spheres: separation |xb - xa| - ra - rb along the line of centres.
TEST(Shape3d, SphereSphere) {
    const Manifold3 m = collide(sphere(0.5), at(0, 0, 0), sphere(0.25), at(1, 2, 2), 1.0);
    EXPECT_NEAR(m.separation, 3 - 0.75, kTol);
    EXPECT_LE((m.normal - Vec3(1, 2, 2) / 3).norm(), kTol);
    EXPECT_EQ(m.count, 0);  // 2.25 m apart: beyond the 1 m margin
    const Manifold3 touch = collide(sphere(0.5), at(0, 0, 0), sphere(0.5), at(0, 0.9, 0));
    ASSERT_EQ(touch.count, 1);
    EXPECT_NEAR(touch.separation, -0.1, kTol);
    EXPECT_NEAR(touch.depths[0], -0.1, kTol);
    EXPECT_LE((touch.normal - Vec3(0, 1, 0)).norm(), kTol);
    EXPECT_LE((touch.points[0] - Vec3(0, 0.45, 0)).norm(), kTol);  // midway between surfaces
    // Coincident centres: the normal falls back to +x, depth ra + rb.
    const Manifold3 same = collide(sphere(0.5), at(1, 1, 1), sphere(0.25), at(1, 1, 1));
    EXPECT_LE((same.normal - Vec3(1, 0, 0)).norm(), kTol);
    EXPECT_NEAR(same.separation, -0.75, kTol);
    ASSERT_EQ(same.count, 1);
    EXPECT_LE((same.points[0] - Vec3(1.125, 1, 1)).norm(), kTol);
}

// A sphere above the +y face of a 2 x 1 x 1.5 box (box frame): separation y - 0.5 - r,
// point halfway between the face (y = 0.5) and the sphere's bottom (y = 0.45).
TEST(Shape3d, SphereAboveBoxFace) {
    const Scene sc;
    const Manifold3 m =
        collide(box(1, 0.5, 0.75), sc.pose(Vec3::Zero()), sphere(0.2), sc.pose(Vec3(0.3, 0.65, -0.2)), 0.1);
    EXPECT_NEAR(m.separation, -0.05, kTol);
    EXPECT_LE((m.normal - sc.dir(Vec3(0, 1, 0))).norm(), kTol);
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.depths[0], -0.05, kTol);
    EXPECT_LE((m.points[0] - sc.point(Vec3(0.3, 0.475, -0.2))).norm(), kTol);
}

// Beyond the edge x = 1, y = 0.5 (along z) by (0.3, 0.4): distance 0.5 to the edge, normal
// (0.6, 0.8, 0); nearest box point (1, 0.5, 0.1), sphere point 0.1 back along the normal.
TEST(Shape3d, SphereNearBoxEdge) {
    const Scene sc;
    const Manifold3 m =
        collide(box(1, 0.5, 0.75), sc.pose(Vec3::Zero()), sphere(0.1), sc.pose(Vec3(1.3, 0.9, 0.1)), 1.0);
    EXPECT_NEAR(m.separation, 0.5 - 0.1, kTol);
    EXPECT_LE((m.normal - sc.dir(Vec3(0.6, 0.8, 0))).norm(), kTol);
    ASSERT_EQ(m.count, 1);
    // Box point (1, 0.5, 0.1), sphere point (1.24, 0.82, 0.1): midway (1.12, 0.66, 0.1).
    EXPECT_LE((m.points[0] - sc.point(Vec3(1.12, 0.66, 0.1))).norm(), kTol);
}

// Beyond the corner (1, 0.5, 0.75) by (0.2, 0.4, 0.4): distance 0.6, normal (1, 2, 2) / 3
// from the box; with the sphere as A the normal points into the box.
TEST(Shape3d, SphereNearBoxCorner) {
    const Scene sc;
    const Manifold3 m = collide(sphere(0.1), sc.pose(Vec3(1.2, 0.9, 1.15)), box(1, 0.5, 0.75), sc.pose(Vec3::Zero()));
    EXPECT_NEAR(m.separation, 0.6 - 0.1, kTol);
    EXPECT_LE((m.normal - sc.dir(-Vec3(1, 2, 2) / 3)).norm(), kTol);
    EXPECT_EQ(m.count, 0);
}

// Centre inside the box at (0.3, 0.35, -0.2): the faces are 0.7, 1.3, 0.15, 0.85, 0.95, 0.55
// away; the nearest is +y (0.15), so the depth is 0.15 + r along +y.
TEST(Shape3d, SphereCentreInsideBox) {
    const Scene sc;
    const Manifold3 m = collide(box(1, 0.5, 0.75), sc.pose(Vec3::Zero()), sphere(0.1), sc.pose(Vec3(0.3, 0.35, -0.2)));
    EXPECT_NEAR(m.separation, -0.25, kTol);
    EXPECT_LE((m.normal - sc.dir(Vec3(0, 1, 0))).norm(), kTol);
    ASSERT_EQ(m.count, 1);
    // Face y = 0.5, sphere's far side y = 0.25: midway y = 0.375.
    EXPECT_LE((m.points[0] - sc.point(Vec3(0.3, 0.375, -0.2))).norm(), kTol);

    // Centre exactly on the +y face: depth r, normal +y, point between y = 0.5 and y = 0.4.
    const Manifold3 on = collide(box(1, 0.5, 0.75), at(0, 0, 0), sphere(0.1), at(0.3, 0.5, -0.2));
    EXPECT_NEAR(on.separation, -0.1, kTol);
    EXPECT_LE((on.normal - Vec3(0, 1, 0)).norm(), kTol);
    ASSERT_EQ(on.count, 1);
    EXPECT_LE((on.points[0] - Vec3(0.3, 0.45, -0.2)).norm(), kTol);

    // Centre at the centre of a cube: every face is 1 away; any axis will do, no NaN.
    const Manifold3 mid = collide(box(1, 1, 1), at(0, 0, 0), sphere(0.5), at(0, 0, 0));
    EXPECT_NEAR(mid.separation, -1.5, kTol);
    EXPECT_NEAR(mid.normal.norm(), 1.0, kTol);
    EXPECT_NEAR(mid.normal.cwiseAbs().maxCoeff(), 1.0, kTol);
}

// A sphere on a tilted plane: separation n . c - offset - r, exact; two half-spaces never touch.
TEST(Shape3d, HalfSpaces) {
    const Vec3 n = Vec3(0, 3, 4) / 5;
    const Manifold3 m = collide(half_space(n, 1.0), at(0, 0, 0), sphere(0.5), at(2, 1, 1));
    // n . c = (3 + 4) / 5 = 1.4: 0.4 above the plane, 0.1 into it.
    EXPECT_NEAR(m.separation, -0.1, kTol);
    EXPECT_LE((m.normal - n).norm(), kTol);
    ASSERT_EQ(m.count, 1);
    EXPECT_LE((m.points[0] - (Vec3(2, 1, 1) - 0.45 * n)).norm(), kTol);
    const Manifold3 s = collide(sphere(0.5), at(2, 1, 1), half_space(n, 1.0), at(0, 0, 0));
    EXPECT_LE((s.normal + n).norm(), kTol);
    EXPECT_NEAR(s.separation, -0.1, kTol);

    const Manifold3 hh = collide(ground(), at(0, 0, 0), half_space(Vec3(0, -1, 0), 0), at(0, 0, 0));
    EXPECT_TRUE(std::isinf(hh.separation) && hh.separation > 0);
    EXPECT_EQ(hh.count, 0);
}

// A 1 x 0.5 x 0.6 box resting 1 mm into the ground: its 4 bottom corners, each 1 mm deep,
// halfway between y = -0.001 and y = 0; normal up (A = ground).
TEST(Shape3d, BoxFlatOnGroundHasFourPoints) {
    const Manifold3 m = collide(ground(), at(0, 0, 0), box(0.5, 0.25, 0.3), at(2, 0.249, -1));
    EXPECT_NEAR(m.separation, -0.001, kTol);
    EXPECT_LE((m.normal - Vec3(0, 1, 0)).norm(), kTol);
    ASSERT_EQ(m.count, 4);
    const std::vector<Vec3> corners = {Vec3(1.5, -0.0005, -1.3), Vec3(2.5, -0.0005, -1.3), Vec3(1.5, -0.0005, -0.7),
                                       Vec3(2.5, -0.0005, -0.7)};
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(m.depths[i], -0.001, kTol);
        EXPECT_TRUE(near_one_of(m.points[i], corners, kTol)) << m.points[i].transpose();
    }
    const std::vector<Vec3> p = sorted_points(m);
    for (int i = 1; i < 4; ++i) EXPECT_GT((p[i] - p[i - 1]).norm(), 0.5);  // four distinct corners
}

// A unit cube turned 45 degrees about z stands on its edge, sqrt(2)/2 below its centre: two
// points at the edge's ends (x = 0, z = +-0.5); the next corners are sqrt(2)/2 higher.
TEST(Shape3d, BoxOnEdgeHasTwoPoints) {
    const double h = std::sqrt(0.5);
    const Quat q = about(Vec3::UnitZ(), kPi / 4);
    const Manifold3 m = collide(ground(), at(0, 0, 0), box(0.5, 0.5, 0.5), at(0, h - 1e-3, 0, q));
    EXPECT_NEAR(m.separation, -1e-3, kTol);
    ASSERT_EQ(m.count, 2);
    const std::vector<Vec3> ends = {Vec3(0, -0.0005, -0.5), Vec3(0, -0.0005, 0.5)};
    for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(m.depths[i], -1e-3, kTol);
        EXPECT_TRUE(near_one_of(m.points[i], ends, kTol)) << m.points[i].transpose();
    }
    EXPECT_GT((m.points[0] - m.points[1]).norm(), 0.5);
}

// A unit cube with its body diagonal vertical stands on one corner, sqrt(3)/2 below its centre;
// the three neighbouring corners are 1/sqrt(3) higher.
TEST(Shape3d, BoxOnCornerHasOnePoint) {
    const double h = std::sqrt(0.75);
    const Quat q = Quat::FromTwoVectors(Vec3(-1, -1, -1).normalized(), Vec3(0, -1, 0));
    const Manifold3 m = collide(ground(), at(0.2, 0, 0.3), box(0.5, 0.5, 0.5), at(0.2, h - 1e-3, 0.3, q));
    EXPECT_NEAR(m.separation, -1e-3, kTol);
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.depths[0], -1e-3, kTol);
    EXPECT_LE((m.points[0] - Vec3(0.2, -0.0005, 0.3)).norm(), kTol);
}

// B (1 x 0.5 x 1) sits 1 cm into the top of A (2 x 1 x 2), shifted to (0.8, ., -0.7):
// B's bottom covers x in [0.3, 1.3], z in [-1.2, -0.2]; A's top x, z in [-1, 1]; the overlap is
// x in [0.3, 1], z in [-1, -0.2], at y halfway between 0.49 and 0.5.
TEST(Shape3d, StackedBoxesClipToTheOverlap) {
    const Shape3 a = box(1, 0.5, 1), b = box(0.5, 0.25, 0.5);
    const Manifold3 m = collide(a, at(0, 0, 0), b, at(0.8, 0.74, -0.7));
    EXPECT_NEAR(m.separation, -0.01, kTol);
    EXPECT_LE((m.normal - Vec3(0, 1, 0)).norm(), kTol);
    ASSERT_EQ(m.count, 4);
    const std::vector<Vec3> corners = {Vec3(0.3, 0.495, -1), Vec3(1, 0.495, -1), Vec3(1, 0.495, -0.2),
                                       Vec3(0.3, 0.495, -0.2)};
    const std::vector<Vec3> p = sorted_points(m);
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(m.depths[i], -0.01, kTol);
        EXPECT_TRUE(near_one_of(m.points[i], corners, kTol)) << m.points[i].transpose();
    }
    for (int i = 1; i < 4; ++i) EXPECT_GT((p[i] - p[i - 1]).norm(), 0.5);  // four distinct corners
    // The same with B as A: normal down, the same separation and points.
    const Manifold3 s = collide(b, at(0.8, 0.74, -0.7), a, at(0, 0, 0));
    EXPECT_LE((s.normal - Vec3(0, -1, 0)).norm(), kTol);
    EXPECT_NEAR(s.separation, -0.01, kTol);
    ASSERT_EQ(s.count, 4);
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(near_one_of(s.points[i], corners, kTol));

    // 5 cm apart with a 10 cm margin: the same region, reported with depth +0.05.
    const Manifold3 gap = collide(a, at(0, 0, 0), b, at(0.8, 0.8, -0.7), 0.1);
    EXPECT_NEAR(gap.separation, 0.05, kTol);
    ASSERT_EQ(gap.count, 4);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(gap.depths[i], 0.05, kTol);
}

// B (2 x 0.5 x 2) turned 45 degrees about y on A's 2 x 2 top: the overlap is the regular
// octagon |x|, |z| <= 1, |x| + |z| <= sqrt(2) (vertices (1, sqrt2 - 1) and its images). Its
// largest inscribed quadrilateral takes every other vertex: a square of area 2 R^2 with
// R^2 = 1 + (sqrt2 - 1)^2 = 4 - 2 sqrt2.
TEST(Shape3d, RotatedStackKeepsFourSpanningPoints) {
    const Manifold3 m =
        collide(box(1, 0.5, 1), at(0, 0, 0), box(1, 0.25, 1), at(0, 0.74, 0, about(Vec3::UnitY(), kPi / 4)));
    EXPECT_NEAR(m.separation, -0.01, kTol);
    EXPECT_LE((m.normal - Vec3(0, 1, 0)).norm(), kTol);
    ASSERT_EQ(m.count, 4);
    const double k = std::sqrt(2.0) - 1;
    std::vector<Vec3> octagon;
    for (const double sx : {-1.0, 1.0})
        for (const double sz : {-1.0, 1.0}) {
            octagon.push_back(Vec3(sx, 0.495, sz * k));
            octagon.push_back(Vec3(sx * k, 0.495, sz));
        }
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(m.depths[i], -0.01, kTol);
        EXPECT_TRUE(near_one_of(m.points[i], octagon, kTol)) << m.points[i].transpose();
    }
    // Area of the kept quadrilateral (points ordered by angle about the centre, shoelace in xz).
    std::vector<Vec3> p(m.points.begin(), m.points.end());
    std::sort(p.begin(), p.end(),
              [](const Vec3& a, const Vec3& b) { return std::atan2(a.z(), a.x()) < std::atan2(b.z(), b.x()); });
    double area = 0.0;
    for (int i = 0; i < 4; ++i) area += 0.5 * (p[i].x() * p[(i + 1) % 4].z() - p[(i + 1) % 4].x() * p[i].z());
    EXPECT_NEAR(std::abs(area), 8 - 4 * std::sqrt(2.0), 1e-9);
}

// Two 2 x 0.5 x 0.5 bars, each turned 45 degrees about its long axis so that an edge points up
// (A) or down (B), B's long axis along z: the edges cross. A's top edge runs along x at
// y = 0.25 sqrt2; B's bottom edge along z at y = yb - 0.25 sqrt2, x = 0.3. With yb = 0.5 sqrt2
// - 0.01 they overlap by 1 cm: one point at (0.3, 0.25 sqrt2 - 0.005, 0), normal x cross z.
TEST(Shape3d, CrossedEdgesHaveOnePoint) {
    const double r = 0.25 * std::sqrt(2.0);
    const Quat qa = about(Vec3::UnitX(), kPi / 4);
    const Quat qb = about(Vec3::UnitY(), kPi / 2) * qa;
    const Shape3 bar = box(1, 0.25, 0.25);
    const Manifold3 m = collide(bar, at(0, 0, 0, qa), bar, at(0.3, 2 * r - 0.01, -0.4, qb));
    EXPECT_NEAR(m.separation, -0.01, kTol);
    EXPECT_LE((m.normal - Vec3(0, 1, 0)).norm(), kTol);
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.depths[0], -0.01, kTol);
    EXPECT_LE((m.points[0] - Vec3(0.3, r - 0.005, 0)).norm(), kTol);
    // Swapped: the normal flips, the point stays.
    const Manifold3 s = collide(bar, at(0.3, 2 * r - 0.01, -0.4, qb), bar, at(0, 0, 0, qa));
    EXPECT_LE((s.normal - Vec3(0, -1, 0)).norm(), kTol);
    EXPECT_NEAR(s.separation, -0.01, kTol);
    ASSERT_EQ(s.count, 1);
    EXPECT_LE((s.points[0] - m.points[0]).norm(), kTol);
}

// Unit cubes offset by (1.3, 1.4, 1.2): the largest gap along an axis is 0.4 (y), a lower bound
// of the true corner-to-corner distance sqrt(0.3^2 + 0.4^2 + 0.2^2).
TEST(Shape3d, SeparatedBoxesReportTheAxisGap) {
    const Shape3 cube = box(0.5, 0.5, 0.5);
    const Manifold3 m = collide(cube, at(0, 0, 0), cube, at(1.3, 1.4, 1.2));
    EXPECT_NEAR(m.separation, 0.4, kTol);
    EXPECT_LT(m.separation, std::sqrt(0.29));
    EXPECT_LE((m.normal - Vec3(0, 1, 0)).norm(), kTol);
    EXPECT_EQ(m.count, 0);
}

// Swapping A and B flips the normal and keeps the separation and the points, for every pair.
TEST(Shape3d, SwapFlipsTheNormal) {
    struct Pair {
        Shape3 a;
        Pose3 pa;
        Shape3 b;
        Pose3 pb;
    };
    const Quat tilt = about(Vec3(1, 1, 0), 0.3);
    const std::vector<Pair> pairs = {
        {sphere(0.5), at(0, 0, 0), sphere(0.4), at(0.3, 0.6, 0.2)},
        {sphere(0.5), at(0.9, 0.2, 0.1), box(0.5, 0.3, 0.4), at(0, 0, 0, tilt)},
        {box(0.5, 0.3, 0.4), at(0, 0.1, 0, tilt), ground(), at(0, 0, 0)},
        {sphere(0.5), at(0, 0.3, 0), ground(), at(0, 0, 0)},
        {box(0.5, 0.3, 0.4), at(0, 0, 0), box(0.3, 0.3, 0.3), at(0.2, 0.5, 0.1, tilt)},
    };
    for (const Pair& p : pairs) {
        const Manifold3 m = collide(p.a, p.pa, p.b, p.pb);
        const Manifold3 s = collide(p.b, p.pb, p.a, p.pa);
        EXPECT_LT(m.separation, 0);
        EXPECT_LE((m.normal + s.normal).norm(), kTol);
        EXPECT_NEAR(m.separation, s.separation, kTol);
        ASSERT_EQ(m.count, s.count);
        ASSERT_GE(m.count, 1);
        const std::vector<Vec3> pm = sorted_points(m), ps = sorted_points(s);
        for (int i = 0; i < m.count; ++i) EXPECT_LE((pm[i] - ps[i]).norm(), kTol);
    }
}

// Moves a shape by t (a half-space by shifting its offset: its pose is ignored).
void translate(Shape3* s, Pose3* p, const Vec3& t) {
    if (s->kind == Shape3::Kind::half_space) s->offset += s->normal.dot(t);
    else p->x += t;
}

// Random shapes and poses (4000 pairs, fixed seed). For every pair: no NaN, a unit normal,
// points only below the margin and always some when overlapping, every point's depth between
// the separation and the margin; swapping A and B flips the normal. When overlapping: each point
// lies halfway between the surfaces (p - depth/2 n on A, p + depth/2 n on B, checked with exact
// signed distances), and moving B along the normal by -separation + 1e-9 leaves the pair 1e-9
// apart (the depth is the translation that separates them). Tolerances are rounding-level for
// shapes of about 1 m.
TEST(Shape3d, RandomPosesAreConsistent) {
    collide_test::Random rng(20240611);
    auto random_shape = [&](Pose3* pose) {
        const double u = rng.uniform(0, 1);
        Shape3 s;
        if (u < 0.3) s = sphere(rng.uniform(0.1, 0.8));
        else if (u < 0.85) s = box(rng.uniform(0.1, 0.8), rng.uniform(0.1, 0.8), rng.uniform(0.1, 0.8));
        else s = half_space(rng.unit3(), rng.uniform(-0.5, 0.5));
        *pose = Pose3{rng.vec3(-0.8, 0.8), rng.rotation()};
        return s;
    };
    constexpr double kMargin = 0.05, kEps = 1e-9, kSurface = 1e-9;
    int overlapping = 0, face_points = 0, single_points = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        Pose3 pa, pb;
        const Shape3 a = random_shape(&pa);
        Shape3 b = random_shape(&pb);
        if (a.kind == Shape3::Kind::half_space && b.kind == Shape3::Kind::half_space) continue;
        SCOPED_TRACE(testing::Message() << "trial " << trial);
        const Manifold3 m = collide(a, pa, b, pb, kMargin);
        ASSERT_TRUE(std::isfinite(m.separation));
        ASSERT_TRUE(m.normal.allFinite());
        EXPECT_NEAR(m.normal.norm(), 1.0, kTol);
        ASSERT_GE(m.count, 0);
        ASSERT_LE(m.count, 4);
        // Points only below the margin; always some when overlapping (separated boxes within the
        // margin may have none: their separation is only a lower bound of the distance).
        EXPECT_TRUE(m.count == 0 || m.separation < kMargin);
        EXPECT_TRUE(m.separation >= 0 || m.count >= 1);
        for (int i = 0; i < m.count; ++i) {
            ASSERT_TRUE(m.points[i].allFinite());
            ASSERT_TRUE(std::isfinite(m.depths[i]));
            EXPECT_GE(m.depths[i], m.separation - kSurface);
            EXPECT_LT(m.depths[i], kMargin);
        }
        // Swapped: the normal flips, the separation and the number of points stay.
        const Manifold3 s = collide(b, pb, a, pa, kMargin);
        EXPECT_LE((s.normal + m.normal).norm(), 1e-9);
        EXPECT_NEAR(s.separation, m.separation, kTol);
        EXPECT_EQ(s.count, m.count);
        if (m.separation >= 0) continue;
        ++overlapping;
        (m.count > 1 ? face_points : single_points) += 1;
        for (int i = 0; i < m.count; ++i) {
            const Vec3 half = 0.5 * m.depths[i] * m.normal;
            EXPECT_NEAR(signed_distance(a, pa, m.points[i] - half), 0.0, kSurface);
            EXPECT_NEAR(signed_distance(b, pb, m.points[i] + half), 0.0, kSurface);
        }
        // B moved out along the normal by the depth plus 1e-9 (A moved back if B is a half-space).
        Shape3 a2 = a, b2 = b;
        Pose3 pa2 = pa, pb2 = pb;
        const Vec3 shift = (-m.separation + kEps) * m.normal;
        if (b.kind == Shape3::Kind::half_space) translate(&a2, &pa2, -shift);
        else translate(&b2, &pb2, shift);
        const Manifold3 moved = collide(a2, pa2, b2, pb2, kMargin);
        EXPECT_NEAR(moved.separation, kEps, 1e-12);
    }
    // The draw must exercise all the branches: many overlaps, single and multi-point manifolds.
    EXPECT_GT(overlapping, 1000);
    EXPECT_GT(face_points, 200);
    EXPECT_GT(single_points, 200);
}

TEST(Shape3d, BoundingRadius) {
    EXPECT_NEAR(bounding_radius(sphere(0.7)), 0.7, kTol);
    EXPECT_NEAR(bounding_radius(box(0.5, 0.25, 0.3)), std::sqrt(0.25 + 0.0625 + 0.09), kTol);
    EXPECT_EQ(bounding_radius(ground()), 0.0);
}

}  // namespace
}  // namespace collide
