#include "engine/shape2d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "engine/trig.h"

namespace collide {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Mat2 rotation(double angle) {
    const SinCos sc = sin_cos(angle);  // engine/trig.h: the same in every build
    const double c = sc.cos, s = sc.sin;
    Mat2 R;
    R << c, -s, s, c;
    return R;
}

// Outward normal of the edge a -> b of a counter-clockwise polygon.
Vec2 outward(const Vec2& a, const Vec2& b) {
    const Vec2 e = b - a;
    return Vec2(e.y(), -e.x()).normalized();
}

Manifold2 flipped(Manifold2 m) {
    m.normal = -m.normal;
    return m;
}

// Disc (centre c, radius r) against a world-space polygon: normal from the polygon to the disc.
// The distance is exact (face, or vertex Voronoi region).
Manifold2 polygon_disc(const std::vector<Vec2>& v, const std::vector<Vec2>& nrm, const Vec2& c, double r,
                       double margin) {
    const int n = static_cast<int>(v.size());
    int face = 0;
    double s = -kInf;
    for (int i = 0; i < n; ++i) {
        const double si = nrm[i].dot(c - v[i]);
        if (si > s) {
            s = si;
            face = i;
        }
    }
    Manifold2 m;
    m.normal = nrm[face];
    double dist = s;  // centre to polygon surface, along the face normal
    if (s > 0) {      // the centre is outside: it may be nearest to a vertex, not the face
        const Vec2& v1 = v[face];
        const Vec2& v2 = v[(face + 1) % n];
        const Vec2* corner = nullptr;
        if ((c - v1).dot(v2 - v1) <= 0) corner = &v1;
        else if ((c - v2).dot(v1 - v2) <= 0) corner = &v2;
        if (corner) {
            dist = (c - *corner).norm();
            if (dist > 0) m.normal = (c - *corner) / dist;
        }
    }
    m.separation = dist - r;
    if (m.separation < margin) {
        m.count = 1;
        m.points[0] = c - m.normal * (r + 0.5 * m.separation);
        m.depths[0] = m.separation;
    }
    return m;
}

void world_polygon(const Polygon& p, const Pose2& pose, std::vector<Vec2>* v, std::vector<Vec2>* n) {
    v->resize(p.count);
    n->resize(p.count);
    const Mat2 R = rotation(pose.angle);  // (Pose2::apply and rotate, one sine and cosine)
    for (int i = 0; i < p.count; ++i) {
        (*v)[i] = pose.x + R * p.vertices[i];
        (*n)[i] = R * p.normals[i];
    }
}

// Largest separation of B's vertices from A's faces: (separation, face of A).
std::pair<double, int> max_face_separation(const std::vector<Vec2>& va, const std::vector<Vec2>& na,
                                           const std::vector<Vec2>& vb) {
    double best = -kInf;
    int face = 0;
    for (std::size_t i = 0; i < va.size(); ++i) {
        double deepest = kInf;
        for (const Vec2& p : vb) deepest = std::min(deepest, na[i].dot(p - va[i]));
        if (deepest > best) {
            best = deepest;
            face = static_cast<int>(i);
        }
    }
    return {best, face};
}

// Exact distance between two separated convex polygons (the nearest vertex-edge pair) and the
// unit direction from A's nearest point to B's. When the nearest point lies inside the edge, the
// direction is the edge's outward normal (exact), not the difference of the two points (whose
// rounding error grows as the distance shrinks).
double polygon_distance(const std::vector<Vec2>& va, const std::vector<Vec2>& na, const std::vector<Vec2>& vb,
                        const std::vector<Vec2>& nb, Vec2* dir) {
    double d = kInf;
    for (int pass = 0; pass < 2; ++pass) {
        const auto& p = pass == 0 ? va : vb;
        const auto& q = pass == 0 ? vb : va;
        const auto& qn = pass == 0 ? nb : na;
        const double sign = pass == 0 ? -1.0 : 1.0;  // q's outward normal, turned from A into B
        for (const Vec2& x : p)
            for (std::size_t j = 0; j < q.size(); ++j) {
                const Vec2& a = q[j];
                const Vec2& b = q[(j + 1) % q.size()];
                const Vec2 e = b - a;
                const double t = (x - a).dot(e) / e.squaredNorm();
                if (t > 0.0 && t < 1.0) {
                    // A vertex behind the edge's line (outside through another edge) is nearer
                    // to that other edge: its |distance| here is never the smallest.
                    const double dj = std::abs(qn[j].dot(x - a));
                    if (dj < d) {
                        d = dj;
                        *dir = sign * qn[j];
                    }
                    continue;
                }
                const Vec2& y = t <= 0.0 ? a : b;
                const double dj = (x - y).norm();
                if (dj < d) {  // (two corners on each other: the distance 0, no direction)
                    d = dj;
                    if (dj > 0) *dir = pass == 0 ? Vec2((y - x) / dj) : Vec2((x - y) / dj);
                }
            }
    }
    return d;
}

// Polygon against polygon by separating axes, then clipping the incident edge against the
// reference face (as in Box2D's b2CollidePolygons): up to two contact points.
Manifold2 polygon_polygon(const Polygon& A, const Pose2& pa, const Polygon& B, const Pose2& pb, double margin,
                          Apart apart) {
    thread_local std::vector<Vec2> va, na, vb, nb;  // (kept: no allocation per call)
    world_polygon(A, pa, &va, &na);
    world_polygon(B, pb, &vb, &nb);
    const auto [sa, fa] = max_face_separation(va, na, vb);
    const auto [sb, fb] = max_face_separation(vb, nb, va);
    // Prefer A's face unless B's is clearly better (stable choice between near ties).
    const bool ref_is_a = sb <= sa + 1e-9 * (1.0 + std::abs(sa));
    const auto& rv = ref_is_a ? va : vb;
    const auto& rn = ref_is_a ? na : nb;
    const auto& iv = ref_is_a ? vb : va;
    const auto& in = ref_is_a ? nb : na;
    const int rf = ref_is_a ? fa : fb;
    const double sat = std::max(sa, sb);

    Manifold2 m;
    m.normal = ref_is_a ? rn[rf] : Vec2(-rn[rf]);
    m.separation = sat;
    // Rounding error of a separation or of a point at these coordinates (a few ulps, kept wide).
    double scale = 1.0;
    for (const Vec2& p : va) scale = std::max(scale, p.cwiseAbs().maxCoeff());
    for (const Vec2& p : vb) scale = std::max(scale, p.cwiseAbs().maxCoeff());
    const double tol = 1e-12 * scale;
    // Apart: the exact distance, along the line between the nearest points. Touching (apart by a
    // rounding error, as at the instant of a hit) there is no such line to resolve, the nearest
    // features themselves are in doubt (a corner at the end of a face): keep the separating axis,
    // as for an overlap, so that the normal is the reference face's, as the points are.
    if (sat > 0 && apart == Apart::exact) {
        Vec2 dir = m.normal;
        const double d = polygon_distance(va, na, vb, nb, &dir);
        if (std::isfinite(d)) m.separation = std::max(d, sat);
        if (std::isfinite(d) && d > tol) m.normal = dir;
    }
    if (sat >= margin) return m;

    // Incident edge: the edge of the other polygon most anti-parallel to the reference normal.
    int ie = 0;
    double most = kInf;
    for (std::size_t i = 0; i < in.size(); ++i) {
        const double d = in[i].dot(rn[rf]);
        if (d < most) {
            most = d;
            ie = static_cast<int>(i);
        }
    }
    std::array<Vec2, 2> clip = {iv[ie], iv[(ie + 1) % iv.size()]};
    const Vec2 r1 = rv[rf], r2 = rv[(rf + 1) % rv.size()];
    const Vec2 tangent = (r2 - r1).normalized();
    // Clip the segment to the slab between the reference face's side planes. A corner touching
    // a corner (or a face's end) is on a side plane: a rounding error beyond it, it is kept.
    auto clip_side = [&](const Vec2& dir, double offset) {
        const double d0 = dir.dot(clip[0]) - offset, d1 = dir.dot(clip[1]) - offset;
        if (d0 > tol && d1 > tol) return false;
        if (d0 > 0 && d1 > 0) {  // only an end within the rounding error: that end alone
            clip[0] = clip[1] = d0 <= d1 ? clip[0] : clip[1];
            return true;
        }
        if (d0 > 0) clip[0] = clip[0] + (d0 / (d0 - d1)) * (clip[1] - clip[0]);
        else if (d1 > 0) clip[1] = clip[1] + (d1 / (d1 - d0)) * (clip[0] - clip[1]);
        return true;
    };
    if (!clip_side(-tangent, -tangent.dot(r1)) || !clip_side(tangent, tangent.dot(r2))) return m;
    // A segment clipped down to a point (corner on corner): one contact point, not two alike.
    const int ends = (clip[1] - clip[0]).norm() <= tol ? 1 : 2;
    for (int k = 0; k < ends; ++k) {
        const Vec2& p = clip[k];
        const double depth = rn[rf].dot(p - r1);
        if (depth < margin && m.count < 2) {
            m.points[m.count] = p - 0.5 * depth * rn[rf];
            m.depths[m.count] = depth;
            ++m.count;
        }
    }
    return m;
}

// A shape against a half-plane (solid side normal . p <= offset): normal out of the half-plane.
Manifold2 halfplane_shape(const Shape2& plane, const Shape2& s, const Pose2& ps, double margin) {
    Manifold2 m;
    m.normal = plane.normal;
    if (s.kind == Shape2::Kind::disc) {
        m.separation = plane.normal.dot(ps.x) - plane.offset - s.radius;
        if (m.separation < margin) {
            m.count = 1;
            m.points[0] = ps.x - plane.normal * (s.radius + 0.5 * m.separation);
            m.depths[0] = m.separation;
        }
        return m;
    }
    if (s.kind == Shape2::Kind::half_plane) {
        m.separation = kInf;  // two static half-planes never need a contact
        return m;
    }
    // Polygon: its deepest vertices; two when an edge lies (nearly) flat on the plane.
    std::array<std::pair<double, Vec2>, Polygon::kMaxVertices> d;
    const Mat2 R = rotation(ps.angle);
    for (int i = 0; i < s.polygon.count; ++i) {
        const Vec2 p = ps.x + R * s.polygon.vertices[i];
        d[i] = {plane.normal.dot(p) - plane.offset, p};
    }
    std::sort(d.begin(), d.begin() + s.polygon.count, [](const auto& l, const auto& r) { return l.first < r.first; });
    m.separation = d[0].first;
    for (int i = 0; i < 2 && i < s.polygon.count; ++i) {
        if (d[i].first >= margin) break;
        m.points[i] = d[i].second - plane.normal * (0.5 * d[i].first);
        m.depths[i] = d[i].first;
        m.count = i + 1;
    }
    return m;
}

}  // namespace

Vec2 Pose2::apply(const Vec2& local) const { return x + rotation(angle) * local; }
Vec2 Pose2::rotate(const Vec2& local) const { return rotation(angle) * local; }

bool make_polygon(const std::vector<Vec2>& vertices, Polygon* out, std::string* error, Vec2* centroid) {
    const int n = static_cast<int>(vertices.size());
    if (n < 3 || n > Polygon::kMaxVertices) {
        *error = "a polygon needs 3 to " + std::to_string(Polygon::kMaxVertices) + " vertices";
        return false;
    }
    double scale = 0.0;
    for (const Vec2& v : vertices) scale = std::max(scale, v.cwiseAbs().maxCoeff());
    for (int i = 0; i < n; ++i) {
        const Vec2 e = vertices[(i + 1) % n] - vertices[i];
        if (e.norm() <= 1e-9 * scale) {
            *error = "vertices " + std::to_string(i + 1) + " and " + std::to_string((i + 1) % n + 1) + " coincide";
            return false;
        }
        const Vec2 next = vertices[(i + 2) % n] - vertices[(i + 1) % n];
        if (cross(e, next) <= 1e-12 * e.norm() * next.norm()) {
            *error = "the polygon must be convex and counter-clockwise (the turn at vertex " +
                     std::to_string((i + 1) % n + 1) + " is not a left turn)";
            return false;
        }
    }
    // Centroid of a uniform plate: sum over triangles (0, v_i, v_i+1).
    double area = 0.0;
    Vec2 c = Vec2::Zero();
    for (int i = 0; i < n; ++i) {
        const double a = 0.5 * cross(vertices[i], vertices[(i + 1) % n]);
        area += a;
        c += a * (vertices[i] + vertices[(i + 1) % n]) / 3.0;
    }
    c /= area;
    Polygon p;
    p.count = n;
    for (int i = 0; i < n; ++i) p.vertices[i] = vertices[i] - c;
    for (int i = 0; i < n; ++i) p.normals[i] = outward(p.vertices[i], p.vertices[(i + 1) % n]);
    *out = p;
    if (centroid) *centroid = c;
    return true;
}

Polygon make_rectangle(double width, double height) {
    const double w = 0.5 * width, h = 0.5 * height;
    Polygon p;
    std::string error;
    // make_polygon refuses an edge under 1e-9 of the largest coordinate: a sliver would come
    // back as an empty polygon, and collide() would index its empty vertex list.
    if (!make_polygon({Vec2(w, -h), Vec2(w, h), Vec2(-w, h), Vec2(-w, -h)}, &p, &error))
        throw std::invalid_argument("make_rectangle: " + error);
    return p;
}

Shape2 Shape2::disc(double radius) {
    Shape2 s;
    s.kind = Kind::disc;
    s.radius = radius;
    return s;
}

Shape2 Shape2::rectangle(double width, double height) {
    Shape2 s;
    s.kind = Kind::polygon;
    s.polygon = make_rectangle(width, height);
    return s;
}

Shape2 Shape2::half_plane(const Vec2& unit_normal, double offset) {
    Shape2 s;
    s.kind = Kind::half_plane;
    s.normal = unit_normal;
    s.offset = offset;
    return s;
}

double polygon_area(const Polygon& p) {
    double a = 0.0;
    for (int i = 0; i < p.count; ++i) a += 0.5 * cross(p.vertices[i], p.vertices[(i + 1) % p.count]);
    return a;
}

double polygon_inertia_per_mass(const Polygon& p) {
    // Triangle (0, a, b) about the origin: area-weighted (|a|^2 + a.b + |b|^2) / 6.
    double area = 0.0, moment = 0.0;
    for (int i = 0; i < p.count; ++i) {
        const Vec2& a = p.vertices[i];
        const Vec2& b = p.vertices[(i + 1) % p.count];
        const double t = 0.5 * cross(a, b);
        area += t;
        moment += t * (a.squaredNorm() + a.dot(b) + b.squaredNorm()) / 6.0;
    }
    return moment / area;
}

double bounding_radius(const Shape2& s) {
    switch (s.kind) {
        case Shape2::Kind::disc: return s.radius;
        case Shape2::Kind::polygon: {
            double r = 0.0;
            for (int i = 0; i < s.polygon.count; ++i) r = std::max(r, s.polygon.vertices[i].norm());
            return r;
        }
        case Shape2::Kind::half_plane: return 0.0;
    }
    return 0.0;
}

Manifold2 collide(const Shape2& a, const Pose2& pa, const Shape2& b, const Pose2& pb, double margin, Apart apart) {
    using K = Shape2::Kind;
    if (a.kind == K::half_plane) return halfplane_shape(a, b, pb, margin);
    if (b.kind == K::half_plane) return flipped(halfplane_shape(b, a, pa, margin));
    if (a.kind == K::disc && b.kind == K::disc) {
        Manifold2 m;
        const Vec2 d = pb.x - pa.x;
        const double dist = d.norm();
        m.normal = dist > 0 ? Vec2(d / dist) : Vec2(1.0, 0.0);
        m.separation = dist - a.radius - b.radius;
        if (m.separation < margin) {
            m.count = 1;
            m.points[0] = pa.x + m.normal * (a.radius + 0.5 * m.separation);
            m.depths[0] = m.separation;
        }
        return m;
    }
    if (a.kind == K::polygon && b.kind == K::polygon)
        return polygon_polygon(a.polygon, pa, b.polygon, pb, margin, apart);
    // Disc and polygon, either order.
    const bool poly_a = a.kind == K::polygon;
    const Shape2& poly = poly_a ? a : b;
    const Pose2& pp = poly_a ? pa : pb;
    const Shape2& disc = poly_a ? b : a;
    const Pose2& pd = poly_a ? pb : pa;
    thread_local std::vector<Vec2> v, n;
    world_polygon(poly.polygon, pp, &v, &n);
    const Manifold2 m = polygon_disc(v, n, pd.x, disc.radius, margin);
    return poly_a ? m : flipped(m);
}

}  // namespace collide
