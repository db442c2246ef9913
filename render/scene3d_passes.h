// What the 3D view draws for one frame, worked out as geometry before anything is drawn: the
// ground's shadows, and over the ground the overlay: bodies, velocity and spin arrows,
// outlines, trails, spin curls and a collision's vectors. Batch3d draws these lists, and the
// overlay's screen rectangle is measured from the same lists (overlay_bounds), so what is
// measured is what is drawn. No GL here.
//
// Conventions: world coordinates in metres, y up; arrows are shaded 3D arrows whose length is
// the quantity times its scale (ArrowScales); line widths in pixels of the frame.
#pragma once

#include <cstddef>
#include <vector>

#include <imgui.h>

#include "engine/scene.h"
#include "render/batch3d.h"
#include "render/camera.h"
#include "render/diagram_view.h"  // Decor
#include "render/annotation.h"
#include "render/frame_state.h"
#include "render/solid.h"
#include "render/style.h"

namespace collide::render {

// The arrows' scales, fixed once for a run (Scene3dView::fit).
struct ArrowScales {
    double unit = 0.1;        // m: about a body's size; arrow thickness, curls, normals
    double k_velocity = 0.0;  // m of arrow per m/s
    double k_impulse = 0.0;   // m of arrow per N s
    double k_spin = 0.0;      // m of arrow per rad/s
    double max_spin = 0.0;    // rad/s: the largest |w| of the run
};

// The meshes the passes place, by their Batch3d id: the arrow's shaft and head (mesh.h), then
// one per body in scene order (empty for planes).
constexpr int kShaftMesh = 0;
constexpr int kHeadMesh = 1;
inline int body_mesh(std::size_t i) { return 2 + static_cast<int>(i); }

// What the passes read.
struct View3d {
    const Scene& scene;
    const Style& style;
    const Solids& solids;
    const ArrowScales& scales;
    const Camera& camera;
};

// The ground: a plane through `origin` with unit normal `normal` and in-plane unit axes u, v
// (v = normal x u), drawn `extent` m around the origin with grid lines every `spacing` m.
struct Ground {
    Vec3 origin = Vec3::Zero(), u = Vec3::UnitX(), v = -Vec3::UnitZ(), normal = Vec3::UnitY();
    double extent = 5.0, spacing = 0.5;  // m
};
// The first plane facing up (its normal's y at least 0.7), through the point under `centre`;
// else a level floor at height `floor` (m) under it. u runs along x where the plane allows.
Ground ground_under(const std::vector<Plane>& planes, const Vec3& centre, double floor);
GroundDraw ground_draw(const Ground& ground, const Style& style);
// A soft shadow under each body above the ground (none under bodies sunk half into it): wider
// and fainter the higher the body.
std::vector<Shadow> shadows(const View3d& view, const Ground& ground, const FrameState& frame);

// Everything above the ground, in drawing order.
struct Overlay {
    std::vector<MeshDraw> bodies;         // MeshDepth::behind_lines
    std::vector<MeshDraw> arrows;         // velocity and spin arrows, depth-tested
    std::vector<Segment> lines;           // outlines, silhouettes, trails, spin curls: depth-tested
    std::vector<MeshDraw> curl_heads;     // depth-tested
    std::vector<Segment> impact_lines;    // r vectors and normals: over everything
    std::vector<MeshDraw> impact_arrows;  // impulses and the normals' heads: over everything
};
// What the 3D view shows of a frame, as annotation items (render/annotation.h; no labels):
// the bodies, velocity arrows from the surface, spin arrows on the axis with their curl (sweep
// 3/4 turn: counter-clockwise seen from the tip), and at a collision the r vectors, the normal
// (0.95 units from the contact point), +P on b and -P on a, the contact point.
Annotations annotations3d(const View3d& view, const FrameState& frame, const Decor& decor);
// The geometry that draws `items` (and the trails of `frame`, Decor::trails).
Overlay overlay(const View3d& view, const FrameState& frame, const Decor& decor, const Annotations& items);

// The screen rectangle the overlay can touch (pixels, top-left origin, x0 <= x1, y0 <= y1, not
// clipped to the frame): each mesh's bounding box and each line's ends, with a margin of 2
// pixels (lines: and half their width) for anti-aliasing. A point behind the eye makes it the
// whole frame. False when the overlay is empty. mesh_bounds: by mesh id.
bool overlay_bounds(const Overlay& overlay, const Camera& camera, const std::vector<Box3f>& mesh_bounds, ImVec4* rect);

// Where body i's velocity arrow starts: where it leaves the surface, so that the body does not
// hide it.
Vec3 velocity_start(const Solid& solid, const BodyState& s);
// Whether a body shows its spin (an arrow on the axis and a curl), and where that arrow starts:
// on the axis, just inside the bounding sphere.
bool shows_spin(const ArrowScales& scales, const BodyState& s);
Vec3 spin_start(const Solid& solid, const BodyState& s);

}  // namespace collide::render
