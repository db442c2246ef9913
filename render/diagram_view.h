// The 2D diagram view, in the style of a textbook figure: light paper, flat filled bodies with
// crisp dark outlines, anti-aliased lines, arrows with labels. Used for 1D scenes (blocks as
// boxes standing on the x axis), 2D scenes, and as the front view (the xy plane) of 3D ones.
//
// What it draws, bottom to top:
//   ground and walls (half-planes: a line with hatching on the solid side; 1D: the x axis),
//   fading trails of the centres, the bodies (discs with a radius line so that spin shows,
//   polygons; static bodies grey), centre-of-mass markers, the r vectors from each centre to
//   the contact point (dashed), velocity arrows (one scale for all of them), angular velocity
//   as a curved arrow whose sweep grows with |w|, and at a collision the normal n (unit length),
//   the impulse +P on b and -P on a at the contact point (one scale for all impulses); then the
//   labels with values and units, placed so that they do not overlap.
//
// annotate() makes the list of all that (render/annotation.h) and draw() draws the list.
// fit() frames the camera once for a whole run (so that it does not jump between frames) from
// sampled states, and fixes the arrow scales from the largest speed, spin and impulse.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include <imgui.h>

#include "engine/scene.h"
#include "render/annotation.h"
#include "render/draw2d.h"
#include "render/frame_state.h"
#include "render/style.h"

namespace collide::render {

// A point fixed in a body that a lesson marks (a bat's handle end, its sweet spot), given in
// the body's frame: from its centre along its unrotated axes (m; 1D: along x).
struct PointMark {
    std::size_t body = 0;
    Vec3 at = Vec3::Zero();
    std::string name;       // drawn beside the point
    bool velocity = false;  // also its velocity v + ω × r where the body's velocity is drawn
};

// What a frame shows besides the bodies.
struct Decor {
    bool velocities = true;  // velocity arrows and spin arcs
    bool impacts = true;     // the frame's impacts: impulse, normal, r vectors, contact point
    bool trails = true;
    bool labels = true;  // values and names
    bool com = true;     // centre-of-mass markers
    // The positive directions, as in the page's "Directions" figures: 1D, over each moving
    // block an arrow along +x ("+v": velocities are measured that way, and may be negative);
    // 2D, one glyph in the corner: +x, +y and the counter-clockwise arc of +ω.
    bool directions = false;
    // When not empty: velocities and spins of these bodies only (scene indices): a figure
    // about one pair of a busy scene leaves the others' arrows out.
    std::vector<std::size_t> focus;
    std::vector<PointMark> points;  // marked points (1D and 2D diagrams) of the bodies in focus
    bool in_focus(std::size_t i) const {
        return focus.empty() || std::find(focus.begin(), focus.end(), i) != focus.end();
    }
};

class DiagramView {
public:
    DiagramView(const Scene& scene, const Style& style);

    // Frames everything the samples show, with their arrows, inside `viewport` (pixels:
    // x0, y0, x1, y1). Impacts set the impulse scale. Call before draw().
    void fit(const std::vector<FrameState>& samples, const std::vector<ImpactMark>& impacts, ImVec4 viewport);
    // Leave room above the moving bodies for the positive-direction arrows (Decor::directions).
    void reserve_directions(bool on) { directions_room_ = on; }
    // Frame `bodies` only (empty: all). A static body among them (a cushion, a wall) is framed
    // only near the moving ones, so that a long wall does not shrink the pair that hits it;
    // the rest of the scene is drawn where it falls in the view, and cut at its edge.
    void frame_only(std::vector<std::size_t> bodies) { frame_only_ = std::move(bodies); }
    // Marked points whose velocities the frames draw (Decor::points): fit() counts their
    // speeds in the arrow scale and frames their arrows' tips too.
    void frame_points(std::vector<PointMark> points) { points_ = std::move(points); }
    // Where a marked point is and how fast it moves in the state `s` of its body.
    static Vec3 point_position(const PointMark& m, const BodyState& s, int dimension);
    static Vec3 point_velocity(const PointMark& m, const BodyState& s, int dimension);

    // What draw() draws of `frame`, in drawing order, the labels placed by `labels` (which
    // holds what the other overlays took; null: no labels).
    Annotations annotate(const FontSet& fonts, const FrameState& frame, const Decor& decor, LabelPlacer* labels) const;
    // Draws the ground and walls, the trails (Decor::trails), then `items` and nothing else.
    void draw(ImDrawList* dl, const FontSet& fonts, const FrameState& frame, const Decor& decor,
              const Annotations& items) const;

    // World (m) to pixels and back (the xy plane), and pixels per metre.
    ImVec2 to_screen(const Vec3& world) const;
    Vec3 to_world(ImVec2 screen) const;
    float pixels_per_metre() const { return static_cast<float>(scale_); }

    // The legends: a round value and its arrow length in pixels (value 0: no such arrows).
    struct Legend {
        double value = 0.0;
        float pixels = 0.0f;
    };
    Legend velocity_legend() const;
    Legend impulse_legend() const;
    double metres_per_speed() const { return k_velocity_; }  // arrow length per m/s
    double metres_per_impulse() const { return k_impulse_; }
    // The world box fit() framed (m): lower and upper corners.
    Vec2 box_lo() const { return box_lo_; }
    Vec2 box_hi() const { return box_hi_; }

private:
    enum class Kind { round, polygon, plane, none };
    Kind kind(std::size_t i) const;
    double radius(std::size_t i) const;  // round bodies
    double reach(std::size_t i) const;   // largest distance of the surface from the centre (m)
    // The radius of body i's spin arc in pixels at `scale` (px per m): just outside a small
    // body, a fixed size around the centre of a long one (a bar's arc would span the frame).
    float spin_radius(std::size_t i, double scale) const;
    std::vector<Vec2> outline(std::size_t i, const BodyState& s) const;  // polygons, CCW
    void plane_of(std::size_t i, Vec2* normal, double* offset) const;
    void extent(std::size_t i, const BodyState& s, Vec2* lo, Vec2* hi) const;
    Legend legend_for(double metres_per_unit) const;

    void draw_planes(ImDrawList* dl) const;
    void draw_axis_1d(ImDrawList* dl) const;
    void draw_body(ImDrawList* dl, std::size_t i, const BodyState& s, bool com) const;

    const Scene& scene_;
    Style style_;
    ImVec4 viewport_{0, 0, 1, 1};
    Vec2 centre_ = Vec2::Zero();  // world point at the viewport's centre
    bool directions_room_ = false;
    std::vector<std::size_t> frame_only_;
    std::vector<PointMark> points_;
    bool framed(std::size_t i) const {
        return frame_only_.empty() || std::find(frame_only_.begin(), frame_only_.end(), i) != frame_only_.end();
    }
    double scale_ = 100.0;     // pixels per metre
    double k_velocity_ = 0.0;  // metres of arrow per m/s
    double k_impulse_ = 0.0;   // metres of arrow per N s
    double max_spin_ = 0.0;    // rad/s, the largest |w| of the run
    Vec2 box_lo_ = Vec2::Zero(), box_hi_ = Vec2::Zero();
};

}  // namespace collide::render
