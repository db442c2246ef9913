// 3D contact detection: spheres, boxes, half-spaces (see engine/shape3d.h).
//
// Box numbering, in the body frame (half extents hx, hy, hz about the centre):
//
//              y
//              |
//          2 --------- 3         vertex i = (+-hx, +-hy, +-hz): bit 0 of i set -> +hx,
//         /|          /|         bit 1 -> +hy, bit 2 -> +hz (0 = (-,-,-), 7 = (+,+,+)).
//        6 --------- 7 |
//        | |         | |         face f lies on axis f / 2, outward + when f is even;
//        | 0 --------|-1 --- x   its vertices, counter-clockwise seen from outside:
//        |/          |/            0 +x: 1 3 7 5     1 -x: 0 4 6 2
//        4 --------- 5             2 +y: 2 6 7 3     3 -y: 0 1 5 4
//       /                          4 +z: 4 5 7 6     5 -z: 0 2 3 1
//      z
//
// Box against box follows the separating axis test of Gottschalk et al. and the face clipping
// of Box2D / ODE (dBoxBox): the face axis of least penetration becomes the reference face, the
// most anti-parallel face of the other box the incident face, clipped to the reference face's
// side planes (Sutherland-Hodgman).
#include "engine/shape3d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace collide {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Edge-edge axes a x b with |a x b| (the sine of the angle between the edges) below this are
// skipped: near-parallel edges give no reliable axis, and their face axes cover them.
constexpr double kParallelSine = 1e-6;

// Axis preference, relative to the size of the two boxes (m per m): a candidate axis replaces
// an earlier one only if it separates by more than this. The order is A's faces, B's faces,
// then the edge pairs, so faces win near-ties (a face gives a stable multi-point manifold).
constexpr double kAxisTolerance = 1e-6;

// The face table of the diagram.
constexpr int kFaceVertices[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                                     {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};

// Room for a quadrilateral clipped by four planes (8 points), with slack for rounding.
constexpr int kMaxClip = 16;

Manifold3 flipped(Manifold3 m) {
    m.normal = -m.normal;
    return m;
}

// A box in world coordinates: centre, axes (the columns of R), half extents.
struct Box {
    Vec3 c;
    Mat3 R;
    Vec3 h;
    Box(const Shape3& s, const Pose3& p) : c(p.x), R(p.q.toRotationMatrix()), h(s.half) {}
    Vec3 axis(int k) const { return R.col(k); }
    Vec3 vertex(int i) const {
        const Vec3 local((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
        return c + R * local;
    }
    // Half the box's extent along the unit direction n.
    double radius(const Vec3& n) const {
        return h.x() * std::abs(axis(0).dot(n)) + h.y() * std::abs(axis(1).dot(n)) + h.z() * std::abs(axis(2).dot(n));
    }
};

// Sphere (centre c, radius r) against a box: normal from the box to the sphere. Exact distance.
Manifold3 box_sphere(const Box& b, const Vec3& c, double r, double margin) {
    Manifold3 m;
    // Sphere centre in the box frame, and the nearest point of the solid box.
    const Vec3 p = b.R.transpose() * (c - b.c);
    const Vec3 q = p.cwiseMax(-b.h).cwiseMin(b.h);
    const double dist = (p - q).norm();
    if (dist > 0) {
        // Outside: the clamped point is on a face, an edge or a corner (its Voronoi region).
        m.normal = b.R * ((p - q) / dist);
        m.separation = dist - r;
    } else {
        // Inside or on the surface: out through the face of least penetration (first on ties).
        double least = kInf;
        for (int k = 0; k < 3; ++k) {
            for (const double sign : {1.0, -1.0}) {
                const double to_face = b.h[k] - sign * p[k];
                if (to_face < least) {
                    least = to_face;
                    m.normal = sign * b.axis(k);
                }
            }
        }
        m.separation = -least - r;
    }
    // One point, midway between the box surface and the sphere's.
    if (m.separation < margin) {
        m.count = 1;
        m.points[0] = c - m.normal * (r + 0.5 * m.separation);
        m.depths[0] = m.separation;
    }
    return m;
}

// Keep the part of the polygon `in` (n points) with dir . p <= limit (Sutherland-Hodgman).
int clip_polygon(const std::array<Vec3, kMaxClip>& in, int n, const Vec3& dir, double limit,
                 std::array<Vec3, kMaxClip>* out) {
    int count = 0;
    for (int i = 0; i < n; ++i) {
        const Vec3& p = in[i];
        const Vec3& q = in[(i + 1) % n];
        const double dp = dir.dot(p) - limit, dq = dir.dot(q) - limit;
        // The start point if inside, then the crossing if the edge crosses the plane.
        if (dp <= 0 && count < kMaxClip) (*out)[count++] = p;
        if (((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) && count < kMaxClip)
            (*out)[count++] = p + (dp / (dp - dq)) * (q - p);
    }
    return count;
}

// Indices of at most four of the n points: the deepest, the farthest from it, then the two that
// add the most area (measured in the plane normal to n), so the kept ones span a large region.
int reduce_to_four(const std::array<Vec3, kMaxClip>& p, const std::array<double, kMaxClip>& depth, int n,
                   const Vec3& normal, std::array<int, 4>* keep) {
    if (n <= 4) {
        for (int i = 0; i < n; ++i) (*keep)[i] = i;
        return n;
    }
    // Twice the signed area of triangle (a, b, c), counter-clockwise about the normal.
    auto area = [&](const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a).dot(normal); };
    // The deepest point.
    int i0 = 0;
    for (int i = 1; i < n; ++i)
        if (depth[i] < depth[i0]) i0 = i;
    // The point farthest from it.
    int i1 = i0;
    double far = 0.0;
    for (int i = 0; i < n; ++i) {
        const double d2 = (p[i] - p[i0]).squaredNorm();
        if (d2 > far) {
            far = d2;
            i1 = i;
        }
    }
    (*keep)[0] = i0;
    if (i1 == i0) return 1;  // all points coincide
    (*keep)[1] = i1;
    // The point making the largest triangle with these two.
    int i2 = -1;
    double best = 0.0;
    for (int i = 0; i < n; ++i) {
        const double a = std::abs(area(p[i0], p[i1], p[i]));
        if (a > best) {
            best = a;
            i2 = i;
        }
    }
    if (i2 < 0) return 2;                                  // collinear
    if (area(p[i0], p[i1], p[i2]) < 0) std::swap(i1, i2);  // counter-clockwise triangle
    // The point adding the most area outside one of the triangle's edges.
    const int tri[3] = {i0, i1, i2};
    int i3 = -1;
    best = 0.0;
    for (int i = 0; i < n; ++i) {
        for (int e = 0; e < 3; ++e) {
            const double added = -area(p[tri[e]], p[tri[(e + 1) % 3]], p[i]);
            if (added > best) {
                best = added;
                i3 = i;
            }
        }
    }
    (*keep)[0] = i0;
    (*keep)[1] = i1;
    (*keep)[2] = i2;
    if (i3 < 0) return 3;
    (*keep)[3] = i3;
    return 4;
}

// Closest points of the segments ca + s ua (|s| <= ha) and cb + t ub (|t| <= hb), unit
// directions, not parallel (Ericson, Real-Time Collision Detection, 5.1.9).
std::pair<Vec3, Vec3> closest_on_segments(const Vec3& ca, const Vec3& ua, double ha, const Vec3& cb, const Vec3& ub,
                                          double hb) {
    const Vec3 r = ca - cb;
    const double b = ua.dot(ub), c = ua.dot(r), f = ub.dot(r);
    const double denom = 1.0 - b * b;  // sin^2 of the angle: > kParallelSine^2
    double s = std::clamp((b * f - c) / denom, -ha, ha);
    const double t = std::clamp(f + s * b, -hb, hb);
    s = std::clamp(t * b - c, -ha, ha);
    return {ca + s * ua, cb + t * ub};
}

// Box against box by separating axes; normal from A into B.
Manifold3 box_box(const Box& A, const Box& B, double margin) {
    const Vec3 d = B.c - A.c;
    const double tolerance = kAxisTolerance * (A.h.maxCoeff() + B.h.maxCoeff());
    // The best axis so far: 0..2 a face of A, 3..5 a face of B, 6..14 edge pair (i, j).
    double best = -kInf;
    int best_axis = -1;
    Vec3 best_n = Vec3::UnitX();
    auto consider = [&](Vec3 n, int axis) {
        // Gap along n between the two projections, n oriented from A towards B.
        if (d.dot(n) < 0) n = -n;
        const double s = d.dot(n) - A.radius(n) - B.radius(n);
        if (s > best + tolerance) {
            best = s;
            best_axis = axis;
            best_n = n;
        }
    };
    // The 3 face normals of A, the 3 of B, the 9 edge-edge cross products.
    for (int i = 0; i < 3; ++i) consider(A.axis(i), i);
    for (int j = 0; j < 3; ++j) consider(B.axis(j), 3 + j);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const Vec3 n = A.axis(i).cross(B.axis(j));
            const double len = n.norm();
            if (len > kParallelSine) consider(n / len, 6 + 3 * i + j);
        }
    }

    Manifold3 m;
    m.normal = best_n;
    m.separation = best;
    if (best >= margin) return m;

    // Edge against edge: one point midway between the closest points of the two edges.
    if (best_axis >= 6) {
        const int i = (best_axis - 6) / 3, j = (best_axis - 6) % 3;
        // A's edge along axis i that lies furthest towards B, B's along j furthest towards A.
        Vec3 ca = A.c, cb = B.c;
        for (int k = 0; k < 3; ++k) {
            if (k != i) ca += (A.axis(k).dot(best_n) >= 0 ? A.h[k] : -A.h[k]) * A.axis(k);
            if (k != j) cb -= (B.axis(k).dot(best_n) >= 0 ? B.h[k] : -B.h[k]) * B.axis(k);
        }
        const auto [pa, pb] = closest_on_segments(ca, A.axis(i), A.h[i], cb, B.axis(j), B.h[j]);
        m.count = 1;
        m.points[0] = 0.5 * (pa + pb);
        m.depths[0] = best;
        return m;
    }

    // Face: the reference face and its outward normal (towards the other box).
    const bool ref_is_a = best_axis < 3;
    const Box& ref = ref_is_a ? A : B;
    const Box& inc = ref_is_a ? B : A;
    const int k = ref_is_a ? best_axis : best_axis - 3;
    const Vec3 n = ref_is_a ? best_n : Vec3(-best_n);
    // Incident face: the other box's face most anti-parallel to n.
    int ik = 0;
    for (int j = 1; j < 3; ++j)
        if (std::abs(inc.axis(j).dot(n)) > std::abs(inc.axis(ik).dot(n))) ik = j;
    const int face = 2 * ik + (inc.axis(ik).dot(n) > 0 ? 1 : 0);
    std::array<Vec3, kMaxClip> poly, tmp;
    for (int v = 0; v < 4; ++v) poly[v] = inc.vertex(kFaceVertices[face][v]);
    int count = 4;
    // Clip it to the slab of each of the reference face's two in-plane axes.
    for (int e = 1; e <= 2 && count > 0; ++e) {
        const Vec3 u = ref.axis((k + e) % 3);
        const double hu = ref.h[(k + e) % 3], cu = u.dot(ref.c);
        count = clip_polygon(poly, count, u, cu + hu, &tmp);
        count = clip_polygon(tmp, count, -u, -cu + hu, &poly);
    }
    // Keep the points closer than the margin to the reference face: depth below its plane.
    const double plane = n.dot(ref.c) + ref.h[k];
    std::array<Vec3, kMaxClip> kept;
    std::array<double, kMaxClip> depth{};
    int kept_count = 0;
    for (int v = 0; v < count; ++v) {
        const double dv = n.dot(poly[v]) - plane;
        if (dv < margin) {
            kept[kept_count] = poly[v] - 0.5 * dv * n;
            depth[kept_count] = dv;
            ++kept_count;
        }
    }
    // At most four: the deepest and the ones spanning the largest area.
    std::array<int, 4> keep{};
    m.count = reduce_to_four(kept, depth, kept_count, n, &keep);
    for (int v = 0; v < m.count; ++v) {
        m.points[v] = kept[keep[v]];
        m.depths[v] = depth[keep[v]];
    }
    return m;
}

// A shape against a half-space (solid side normal . p <= offset): normal out of the half-space.
Manifold3 halfspace_shape(const Shape3& plane, const Shape3& s, const Pose3& ps, double margin) {
    Manifold3 m;
    m.normal = plane.normal;
    // Sphere: its lowest point, exact.
    if (s.kind == Shape3::Kind::sphere) {
        m.separation = plane.normal.dot(ps.x) - plane.offset - s.radius;
        if (m.separation < margin) {
            m.count = 1;
            m.points[0] = ps.x - plane.normal * (s.radius + 0.5 * m.separation);
            m.depths[0] = m.separation;
        }
        return m;
    }
    // Two static half-spaces never need a contact.
    if (s.kind == Shape3::Kind::half_space) {
        m.separation = kInf;
        return m;
    }
    // Box: its deepest vertices; four when a face lies (nearly) flat on the plane.
    const Box box(s, ps);
    std::array<std::pair<double, Vec3>, 8> d;
    for (int i = 0; i < 8; ++i) {
        const Vec3 p = box.vertex(i);
        d[i] = {plane.normal.dot(p) - plane.offset, p};
    }
    // Deepest first, ties in vertex order (a stable insertion sort: std::stable_sort would ask
    // for a buffer on the heap at every call).
    for (int i = 1; i < 8; ++i)
        for (int k = i; k > 0 && d[k].first < d[k - 1].first; --k) std::swap(d[k], d[k - 1]);
    m.separation = d[0].first;
    for (int i = 0; i < 4; ++i) {
        if (d[i].first >= margin) break;
        m.points[i] = d[i].second - plane.normal * (0.5 * d[i].first);
        m.depths[i] = d[i].first;
        m.count = i + 1;
    }
    return m;
}

}  // namespace

Vec3 Pose3::apply(const Vec3& local) const { return x + q * local; }
Vec3 Pose3::rotate(const Vec3& local) const { return q * local; }

double bounding_radius(const Shape3& s) {
    switch (s.kind) {
        case Shape3::Kind::sphere: return s.radius;
        case Shape3::Kind::box: return s.half.norm();
        case Shape3::Kind::half_space: return 0.0;
    }
    return 0.0;
}

Manifold3 collide(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, double margin) {
    using K = Shape3::Kind;
    // Half-spaces first (either side).
    if (a.kind == K::half_space) return halfspace_shape(a, b, pb, margin);
    if (b.kind == K::half_space) return flipped(halfspace_shape(b, a, pa, margin));
    // Sphere against sphere: along the line of centres; coincident centres use +x.
    if (a.kind == K::sphere && b.kind == K::sphere) {
        Manifold3 m;
        const Vec3 d = pb.x - pa.x;
        const double dist = d.norm();
        m.normal = dist > 0 ? Vec3(d / dist) : Vec3(1.0, 0.0, 0.0);
        m.separation = dist - a.radius - b.radius;
        if (m.separation < margin) {
            m.count = 1;
            m.points[0] = pa.x + m.normal * (a.radius + 0.5 * m.separation);
            m.depths[0] = m.separation;
        }
        return m;
    }
    // Box against box.
    if (a.kind == K::box && b.kind == K::box) return box_box(Box(a, pa), Box(b, pb), margin);
    // Sphere and box, either order.
    const bool box_a = a.kind == K::box;
    const Box box = box_a ? Box(a, pa) : Box(b, pb);
    const Shape3& sphere = box_a ? b : a;
    const Pose3& ps = box_a ? pb : pa;
    const Manifold3 m = box_sphere(box, ps.x, sphere.radius, margin);
    return box_a ? m : flipped(m);
}

}  // namespace collide
