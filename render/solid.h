// The bodies of a scene as the 3D view shows them: a mesh, the edges outlined in ink, and what
// the view needs to know of the shape (its kind, radius or half sizes, a bounding size). Plain
// data, no GL.
//
// 1D and 2D scenes are extruded along z to a common depth (Solids::extrude): 1D blocks become
// boxes standing on the x axis, 2D discs cylinders and polygons prisms. Half-planes and
// half-spaces have no solid; they are kept as planes (the ground and walls).
#pragma once

#include <utility>
#include <vector>

#include "engine/scene.h"
#include "render/mesh.h"

namespace collide::render {

struct Solid {
    // none: nothing drawn (a plane). sphere and cylinder (axis z): their silhouettes are drawn
    // per view, as their outline depends on where the eye is.
    enum class Kind { none, sphere, cylinder, box, prism };
    Kind kind = Kind::none;
    Mesh mesh;                                   // body frame, m (empty for none)
    std::vector<std::pair<Vec3f, Vec3f>> edges;  // outlined segments, body frame, m
    float radius = 0.0f;                         // m: sphere, cylinder
    Vec3 half = Vec3::Zero();                    // m: box half sizes
    float size = 0.0f;                           // m: bounding diameter (0 for none)
    bool drawn() const { return !mesh.empty(); }
};

// A half-space { p : normal . p <= offset } (normal not necessarily unit).
struct Plane {
    Vec3 normal;
    double offset;  // m times |normal|
};

struct Solids {
    std::vector<Solid> bodies;  // scene order
    std::vector<Plane> planes;  // scene order
    double extrude = 0.0;       // m: the depth of 1D and 2D bodies along z (0.6 x median size)
};
Solids make_solids(const Scene& scene);

// Where a ray from the solid's centre along the unit vector d (world) leaves its surface, for
// a body turned by q (m from the centre). Boxes exactly; cylinders and prisms at their
// bounding sphere.
double exit_distance(const Solid& solid, const Quat& q, const Vec3& d);

}  // namespace collide::render
