#include "render/mesh.h"

#include <cmath>
#include <utility>

#include "engine/math.h"  // kPi

namespace collide::render {

namespace {

constexpr float kPiF = static_cast<float>(kPi);

// One triangle a, b, c (counter-clockwise from outside) with the normals at its corners.
void tri(Mesh* out, const Vec3f& a, const Vec3f& b, const Vec3f& c, const Vec3f& na, const Vec3f& nb, const Vec3f& nc) {
    for (const auto& [p, n] : {std::pair(a, na), std::pair(b, nb), std::pair(c, nc)})
        out->push_back({{p.x(), p.y(), p.z()}, {n.x(), n.y(), n.z()}, {p.x(), p.y(), p.z()}});
}
// A flat triangle: its face normal at every corner.
void flat_tri(Mesh* out, const Vec3f& a, const Vec3f& b, const Vec3f& c) {
    const Vec3f n = (b - a).cross(c - a).normalized();
    tri(out, a, b, c, n, n, n);
}

// The angle of step k of n around a circle (rad).
float turn(int k, int n) { return 2.0f * kPiF * static_cast<float>(k) / static_cast<float>(n); }

}  // namespace

Box3f bounds(const Mesh& mesh) {
    Box3f b;
    if (mesh.empty()) return b;
    b.lo = b.hi = Vec3f(mesh[0].p[0], mesh[0].p[1], mesh[0].p[2]);
    for (const Vertex& x : mesh) {
        const Vec3f p(x.p[0], x.p[1], x.p[2]);
        b.lo = b.lo.cwiseMin(p);
        b.hi = b.hi.cwiseMax(p);
    }
    return b;
}

Mesh box_mesh(const Vec3f& h) {
    Mesh v;
    for (int axis = 0; axis < 3; ++axis)
        for (int sign = -1; sign <= 1; sign += 2) {
            // The face at sign * h[axis]; u, w the next two axes (u x w = +axis).
            Vec3f n = Vec3f::Zero();
            n[axis] = static_cast<float>(sign);
            const int u = (axis + 1) % 3, w = (axis + 2) % 3;
            Vec3f c[4];
            const float su[4] = {-1, 1, 1, -1}, sw[4] = {-1, -1, 1, 1};
            for (int k = 0; k < 4; ++k) {
                c[k] = Vec3f::Zero();
                c[k][axis] = sign * h[axis];
                c[k][u] = su[k] * h[u];
                c[k][w] = sw[k] * h[w];
            }
            // c[0..3] run counter-clockwise seen from +axis: reversed on the - face.
            if (sign > 0) {
                tri(&v, c[0], c[1], c[2], n, n, n);
                tri(&v, c[0], c[2], c[3], n, n, n);
            } else {
                tri(&v, c[0], c[2], c[1], n, n, n);
                tri(&v, c[0], c[3], c[2], n, n, n);
            }
        }
    return v;
}

Mesh sphere_mesh(float r, int rings, int sectors) {
    Mesh v;
    // The unit point at polar angle th from +y (ring i) and azimuth ph from +x towards +z.
    const auto at = [&](int i, int j) {
        const float th = kPiF * static_cast<float>(i) / static_cast<float>(rings);
        const float ph = turn(j, sectors);
        return Vec3f(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
    };
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < sectors; ++j) {
            const Vec3f a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            tri(&v, a * r, c * r, b * r, a, c, b);
            tri(&v, a * r, d * r, c * r, a, d, c);
        }
    return v;
}

Mesh prism_mesh(const std::vector<Vec3f>& outline, float depth, bool smooth) {
    Mesh v;
    const float z = 0.5f * depth;
    const std::size_t n = outline.size();
    // The caps: fans from the first point, the bottom one reversed.
    for (std::size_t k = 1; k + 1 < n; ++k) {
        const Vec3f a = outline[0], b = outline[k], c = outline[k + 1];
        flat_tri(&v, a + Vec3f(0, 0, z), b + Vec3f(0, 0, z), c + Vec3f(0, 0, z));
        flat_tri(&v, a - Vec3f(0, 0, z), c - Vec3f(0, 0, z), b - Vec3f(0, 0, z));
    }
    // The sides: the quad under each edge a -> b (its outward normal is to the right of it).
    for (std::size_t k = 0; k < n; ++k) {
        const Vec3f a = outline[k], b = outline[(k + 1) % n];
        Vec3f na, nb;
        if (smooth) {
            na = Vec3f(a.x(), a.y(), 0).normalized();
            nb = Vec3f(b.x(), b.y(), 0).normalized();
        } else {
            na = nb = Vec3f(b.y() - a.y(), a.x() - b.x(), 0).normalized();
        }
        const Vec3f a0 = a - Vec3f(0, 0, z), a1 = a + Vec3f(0, 0, z);
        const Vec3f b0 = b - Vec3f(0, 0, z), b1 = b + Vec3f(0, 0, z);
        tri(&v, a0, b0, b1, na, nb, nb);
        tri(&v, a0, b1, a1, na, nb, na);
    }
    return v;
}

std::vector<Vec3f> circle_outline(float r, int n) {
    std::vector<Vec3f> o;
    for (int k = 0; k < n; ++k) {
        const float a = turn(k, n);
        o.push_back(Vec3f(r * std::cos(a), r * std::sin(a), 0));
    }
    return o;
}

Mesh arrow_shaft(int segments) {
    Mesh v;
    for (int k = 0; k < segments; ++k) {
        const float a0 = turn(k, segments), a1 = turn(k + 1, segments);
        const Vec3f n0(std::cos(a0), 0, std::sin(a0)), n1(std::cos(a1), 0, std::sin(a1));
        tri(&v, n0, n1 + Vec3f(0, 1, 0), n1, n0, n1, n1);
        tri(&v, n0, n0 + Vec3f(0, 1, 0), n1 + Vec3f(0, 1, 0), n0, n0, n1);
    }
    return v;
}

Mesh arrow_head(int segments) {
    Mesh v;
    const Vec3f tip(0, 1, 0);
    for (int k = 0; k < segments; ++k) {
        const float a0 = turn(k, segments), a1 = turn(k + 1, segments);
        const Vec3f p0(std::cos(a0), 0, std::sin(a0)), p1(std::cos(a1), 0, std::sin(a1));
        // The side's normal: (cos a, 1, sin a) normalised (a cone of height 1, radius 1); at the
        // tip the mean of the two edges'.
        const Vec3f n0 = Vec3f(p0.x(), 1.0f, p0.z()).normalized(), n1 = Vec3f(p1.x(), 1.0f, p1.z()).normalized();
        tri(&v, p0, tip, p1, n0, (n0 + n1).normalized(), n1);
        flat_tri(&v, p0, p1, Vec3f::Zero());
    }
    return v;
}

Mat3f rotation_from_y(const Vec3f& d) {
    const Vec3f y(0, 1, 0);
    const float c = y.dot(d);
    if (c > 0.99999f) return Mat3f::Identity();
    if (c < -0.99999f) return Eigen::AngleAxisf(kPiF, Vec3f::UnitX()).toRotationMatrix();
    return Eigen::Quaternionf::FromTwoVectors(y, d).toRotationMatrix();
}

}  // namespace collide::render
