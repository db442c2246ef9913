// The 3D view's camera: a perspective camera looking at a target, drawn inside a viewport of
// the frame, and framed automatically on the box a run covers.
//
// Conventions: world y is up. Screen points are pixels of the frame, origin top left, y down.
// Angles of a CameraRequest are degrees; the azimuth turns the eye right of the front (+z)
// about +y, the elevation raises it above the horizon.
#pragma once

#include <optional>

#include <imgui.h>

#include "engine/math.h"
#include "render/mesh.h"  // Vec3f, Mat4f

namespace collide::render {

// A camera asked for by the scenario ([view] table); what is not set is chosen by the view.
struct CameraRequest {
    std::optional<double> azimuth;    // degrees: turned right of the front (+z) about +y
    std::optional<double> elevation;  // degrees above the horizon
    std::optional<Vec3> target;       // m: the point looked at
    std::optional<double> distance;   // m from the target
    double zoom = 1.0;                // the distance divided by this (collide gui's mouse wheel)
};

// The camera's angles when the scenario sets none (degrees): 1D and 2D scenes a little more
// from the front than 3D ones.
double default_azimuth(int dimension);
double default_elevation(int dimension);

class Camera {
public:
    static constexpr double kFovY = 30.0 * kPi / 180.0;  // rad, the vertical field of view

    // Where the view is drawn: `viewport` (pixels, x0, y0, x1, y1) of a frame `width` x `height`.
    void set_viewport(ImVec4 viewport, int width, int height);
    // Frames the box lo..hi (m) as the request asks: from its angles (else the defaults of
    // `dimension`), aimed and moved back so that the box's projection fills 80% of the
    // viewport, except what the request fixes (a target is not re-aimed, a distance not
    // changed); then the request's zoom. `radius` (m) sizes the depth range.
    void frame(const Vec3& lo, const Vec3& hi, const Vec3& centre, double radius, const CameraRequest& request,
               int dimension);

    // A world point (m) on the frame (pixels, top-left origin).
    ImVec2 project(const Vec3& p) const;
    // Whether a world point is in front of the eye (it projects; else it is behind or at the eye).
    bool in_front(const Vec3f& p) const;

    const Vec3f& eye() const { return eye_; }
    const Vec3f& target() const { return target_; }
    // Unit vectors of the view: along the line of sight, to the right, and up on the screen.
    Vec3f forward() const { return (target_ - eye_).normalized(); }
    Vec3f right() const { return forward().cross(Vec3f(0, 1, 0)).normalized(); }
    Vec3f up() const { return right().cross(forward()); }
    // World to the clip space of the whole frame (the ground and grid run to the frame's edges
    // while the scene stays framed in the viewport: an off-centre projection).
    const Mat4f& frame_projection() const { return frame_projection_; }
    const ImVec4& viewport() const { return viewport_; }
    int frame_width() const { return frame_w_; }
    int frame_height() const { return frame_h_; }

private:
    // Looks at `look` from `distance` (m) along the unit vector `dir` (target to eye).
    void look(const Vec3f& dir, float distance, const Vec3f& look, double radius);

    ImVec4 viewport_{0, 0, 1, 1};
    int frame_w_ = 1, frame_h_ = 1;
    Vec3f eye_ = Vec3f(0, 0, 5), target_ = Vec3f::Zero();
    Mat4f view_projection_ = Mat4f::Identity();   // world to the clip space of the viewport
    Mat4f frame_projection_ = Mat4f::Identity();  // world to the clip space of the frame
};

}  // namespace collide::render
