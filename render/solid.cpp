#include "render/solid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/shape2d.h"
#include "engine/shape3d.h"
#include "render/frame_state.h"  // block_height

namespace collide::render {

namespace {

// Extrusion depth for 1D and 2D bodies: 0.6 x the median body size (m; 0 for 3D scenes).
double extrusion(const Scene& scene) {
    std::vector<double> extents;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const SceneBody& b = scene.bodies[i];
        if (scene.dimension == 1) extents.push_back(b.length);
        else if (scene.dimension == 2 && b.shape2.kind != Shape2::Kind::half_plane)
            extents.push_back(2.0 * bounding_radius(b.shape2));
    }
    if (extents.empty()) return 0.0;
    std::nth_element(extents.begin(), extents.begin() + extents.size() / 2, extents.end());
    return 0.6 * extents[extents.size() / 2];
}

// The edges of an outline extruded to +-z: both rims and the vertical edges.
void prism_edges(const std::vector<Vec3f>& o, float z, Solid* s) {
    for (std::size_t k = 0; k < o.size(); ++k) {
        const Vec3f a = o[k], c = o[(k + 1) % o.size()];
        s->edges.push_back({a + Vec3f(0, 0, z), c + Vec3f(0, 0, z)});
        s->edges.push_back({a - Vec3f(0, 0, z), c - Vec3f(0, 0, z)});
        s->edges.push_back({a - Vec3f(0, 0, z), a + Vec3f(0, 0, z)});
    }
}

// A 1D block: a box standing on the x axis, `extrude` deep.
Solid block(const Scene& scene, std::size_t i, double extrude) {
    Solid s;
    const SceneBody& b = scene.bodies[i];
    const float hx = static_cast<float>(0.5 * b.length);
    const float hy = static_cast<float>(0.5 * block_height(scene, i));
    const std::vector<Vec3f> o = {{-hx, -hy, 0}, {hx, -hy, 0}, {hx, hy, 0}, {-hx, hy, 0}};
    s.kind = Solid::Kind::box;
    s.mesh = prism_mesh(o, static_cast<float>(extrude), false);
    prism_edges(o, static_cast<float>(0.5 * extrude), &s);
    s.half = Vec3(0.5 * b.length, 0.5 * block_height(scene, i), 0.5 * extrude);
    s.size = 2.0f * std::hypot(hx, hy);
    return s;
}

// A 2D disc (a cylinder along z: its rims and a radius line on the front, so that spin shows)
// or polygon (a prism).
Solid extruded(const Shape2& shape, double extrude) {
    Solid s;
    const float z = static_cast<float>(0.5 * extrude);
    if (shape.kind == Shape2::Kind::disc) {
        s.kind = Solid::Kind::cylinder;
        s.radius = static_cast<float>(shape.radius);
        const std::vector<Vec3f> o = circle_outline(s.radius, 64);
        s.mesh = prism_mesh(o, static_cast<float>(extrude), true);
        for (std::size_t k = 0; k < o.size(); ++k) {
            const Vec3f a = o[k], c = o[(k + 1) % o.size()];
            s.edges.push_back({a + Vec3f(0, 0, z), c + Vec3f(0, 0, z)});
            s.edges.push_back({a - Vec3f(0, 0, z), c - Vec3f(0, 0, z)});
        }
        s.edges.push_back({Vec3f(0, 0, z), Vec3f(s.radius, 0, z)});
        s.size = 2 * s.radius;
        return s;
    }
    std::vector<Vec3f> o;
    for (int k = 0; k < shape.polygon.count; ++k) {
        const Vec2& p = shape.polygon.vertices[static_cast<std::size_t>(k)];
        o.push_back(Vec3f(static_cast<float>(p.x()), static_cast<float>(p.y()), 0));
    }
    s.kind = Solid::Kind::prism;
    s.mesh = prism_mesh(o, static_cast<float>(extrude), false);
    prism_edges(o, z, &s);
    s.size = static_cast<float>(2.0 * bounding_radius(shape));
    return s;
}

// A 3D sphere (no edges: its silhouette and equator are drawn per view) or box (its 12 edges).
Solid solid3(const Shape3& shape) {
    Solid s;
    if (shape.kind == Shape3::Kind::sphere) {
        s.kind = Solid::Kind::sphere;
        s.radius = static_cast<float>(shape.radius);
        s.mesh = sphere_mesh(s.radius);
        s.size = 2 * s.radius;
        return s;
    }
    const Vec3f h = shape.half.cast<float>();
    s.kind = Solid::Kind::box;
    s.mesh = box_mesh(h);
    // Along each axis a, the 4 edges from -h[a] to +h[a] at the corners of the other two.
    for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 4; ++k) {
            Vec3f p = -h, q;
            const int u = (a + 1) % 3, w = (a + 2) % 3;
            if (k & 1) p[u] = h[u];
            if (k & 2) p[w] = h[w];
            q = p;
            q[a] = h[a];
            s.edges.push_back({p, q});
        }
    s.half = shape.half;
    s.size = 2.0f * h.norm();
    return s;
}

}  // namespace

Solids make_solids(const Scene& scene) {
    Solids out;
    out.extrude = extrusion(scene);
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const SceneBody& b = scene.bodies[i];
        Solid s;
        if (scene.dimension == 1) {
            s = block(scene, i, out.extrude);
        } else if (scene.dimension == 2) {
            if (b.shape2.kind == Shape2::Kind::half_plane)
                out.planes.push_back({Vec3(b.shape2.normal.x(), b.shape2.normal.y(), 0.0), b.shape2.offset});
            else s = extruded(b.shape2, out.extrude);
        } else {
            if (b.shape3.kind == Shape3::Kind::half_space) out.planes.push_back({b.shape3.normal, b.shape3.offset});
            else s = solid3(b.shape3);
        }
        out.bodies.push_back(std::move(s));
    }
    return out;
}

double exit_distance(const Solid& solid, const Quat& q, const Vec3& d) {
    if (solid.kind == Solid::Kind::sphere) return solid.radius;
    if (solid.kind != Solid::Kind::box) return 0.5 * solid.size;
    // The slab test in the body frame: the nearest face the ray reaches.
    const Vec3 local = q.conjugate() * d;
    double t = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k)
        if (std::abs(local[k]) > 1e-12) t = std::min(t, solid.half[k] / std::abs(local[k]));
    return std::isfinite(t) ? t : 0.0;
}

}  // namespace collide::render
