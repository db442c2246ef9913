// The 3D view: shaded bodies with dark outlines on a ground grid, lit by a key light, a fill
// light and a sky-ground ambient term, seen by a perspective camera framed automatically from
// the run (from the front, a little to the right and above). Velocity arrows are shaded 3D
// arrows (one scale for all); angular velocity is an arrow on the axis with a curl around it;
// at a collision the impulse, the normal and the r vectors. Labels are drawn by ImGui at the
// projected points (annotate()).
//
// 1D and 2D scenes can be shown in 3D too: blocks become boxes, discs cylinders and polygons
// prisms, extruded along z; 2D half-planes become walls or the ground.
//
// The parts: camera.h (projection, framing), solid.h and mesh.h (the bodies as meshes, no GL),
// scene3d_passes.h (what a frame draws, as geometry), batch3d.h (the GL buffers and draw
// calls) and the GLSL programs in assets/shaders/.
#pragma once

#include <memory>
#include <vector>

#include <imgui.h>

#include "engine/scene.h"
#include "render/camera.h"        // CameraRequest, default_azimuth, default_elevation
#include "render/diagram_view.h"  // Decor
#include "render/draw2d.h"
#include "render/frame_state.h"
#include "render/gl.h"
#include "render/style.h"

namespace collide::render {

class Scene3dView {
public:
    Scene3dView(const Gl& gl, const Scene& scene, const Style& style);
    ~Scene3dView();
    Scene3dView(const Scene3dView&) = delete;
    Scene3dView& operator=(const Scene3dView&) = delete;

    // Frames the camera on the run inside `viewport` (pixels, top-left origin) of a frame
    // `frame_width` x `frame_height`; sets the arrow scales.
    void fit(const std::vector<FrameState>& samples, const std::vector<ImpactMark>& impacts, ImVec4 viewport,
             int frame_width, int frame_height);
    void set_camera(const CameraRequest& camera) { camera_ = camera; }
    // What a frame shows (render/annotation.h), its labels placed by `labels` (null: none).
    // Made first: the GL pass and the labels draw this list.
    Annotations annotate(const FontSet& fonts, const FrameState& frame, const Decor& decor, LabelPlacer* labels) const;
    // The GL pass (the render target is bound, colour and depth cleared): draw_ground() (the
    // ground, its grid and the shadows) then draw_above() (the items' bodies, arrows, outlines
    // and the collision's vectors; the trails of `frame`).
    void draw(const FrameState& frame, const Decor& decor, const Annotations& items);
    void draw_ground(const FrameState& frame);
    void draw_above(const FrameState& frame, const Decor& decor, const Annotations& items);
    // The screen rectangle draw_above() can touch (pixels, top-left origin, x0 <= x1, y0 <= y1,
    // not clipped to the frame), measured on the geometry it would draw; false when it draws
    // nothing. The multisampled render draws the frame's ground without MSAA and only this
    // rectangle with it (the ground's interior pixels are the same either way), which makes
    // anti-aliasing cost what the bodies cover.
    bool above_bounds(const FrameState& frame, const Decor& decor, const Annotations& items, ImVec4* rect);
    // Through ImGui, after draw(): the centre-of-mass markers, the axes glyph and the labels.
    void draw_labels(ImDrawList* dl, const FontSet& fonts, const Annotations& items) const;

    ImVec2 to_screen(const Vec3& world) const;  // pixels, top-left origin
    double pixels_per_metre() const;            // across the view, at the scene's centre
    DiagramView::Legend velocity_legend() const;
    DiagramView::Legend impulse_legend() const;
    bool spins() const { return max_spin_ > 0; }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    double max_spin_ = 0.0;
    CameraRequest camera_;
};

}  // namespace collide::render
