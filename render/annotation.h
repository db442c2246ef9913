// What a view draws, as a list, made before anything is drawn: the bodies at their poses, every
// arrow with the quantity it stands for, the contact points, and the labels with the text and
// the screen box each was given. The view then draws the list and nothing else, so that tests
// can read a picture's meaning from it (tests/cli/annotation_test.cpp) and check with a few
// pixels that the list is what was drawn. `collide render` writes the lists of its figure's
// three panels as annotations.json (docs/commands/render.md).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <imgui.h>

#include "engine/body.h"
#include "engine/math.h"
#include "render/draw2d.h"
#include "render/style.h"

namespace collide::render {

enum class Mark {
    body,            // a body at its pose; `value` the pose (see Annotation)
    plane,           // ground or a wall: `from` a point of its line, `value` its outward normal
    velocity,        // v of `body`: from its centre to the arrow's tip
    spin,            // ω of `body`: an arc about its centre, `sweep` its signed angle
    impulse,         // the impulse on `body`: +P on b, −P on a, from the contact point
    normal,          // n, from a into b, drawn beside the contact point
    lever_arm,       // r of `body`: from its centre to the contact point
    contact,         // the contact point
    direction,       // a positive direction (+x, +y, +ω, +v), not a quantity
    label,           // text; `of` is the item it names or gives the value of
    point,           // a point of `body` a lesson marks (a handle): `from` where it is, `text` its name
    point_velocity,  // that point's velocity v + ω × (p − x) (m/s), from the point
    // The overlays (frames with the table, formula and plots on; not in figure panels):
    table_cell,    // a cell of the data table: `text`, `box`, `of` its column (0 the name, then
                   // m, v, ω in 2D and 3D, p, E_k), `body` its row's (-1: header, totals),
                   // `value` its quantity at full precision (empty: header, name)
    formula_line,  // a line of the formula box: `text`, `box`, `of` its line from the top
    plot_value,    // a plot's series at the frame's time: `text` its label, `value` the value
                   // drawn, `anchor` the dot (pixels), `box` the plot
};
const char* mark_name(Mark kind);

struct Annotation {
    Mark kind = Mark::label;
    int body = -1;  // scene index of the body it shows or acts on; -1: none
    // World (m): an arrow's tail and tip; a body's or spin's centre (both); a label's anchor,
    // the point it belongs to (both).
    Vec3 from = Vec3::Zero(), to = Vec3::Zero();
    // The quantity, in SI units and the scene's dimension: velocity (m/s), spin ω (rad/s; in
    // 2D the number about +z), impulse (N s, on `body`), normal (unit), lever arm r (m). A
    // body's pose: 1D [x]; 2D [x, y, angle]; 3D [x, y, z, qw, qx, qy, qz]. A label: the number
    // it prints, at full precision (empty for names).
    std::vector<double> value;
    std::string text;             // labels: as drawn (rich text: "r_{a}", "ω = 1.5 rad/s"); 3D lever
                                  // arms: their name ("r_{a}")
    ImVec4 box{0, 0, 0, 0};       // pixels (x0, y0, x1, y1): a label's box, an arrow's extent
    double sweep = 0.0;           // spin: the arc's angle, radians, + counter-clockwise as seen
    int of = -1;                  // labels: the index of the item labelled; -1: none
    float font_px = 0.0f;         // labels: the font's size (pixels): how tall the text is drawn
    std::vector<ImVec2> outline;  // bodies in the 3D view: the projected outline (pixels, convex)

    // How it is drawn (not part of annotations.json).
    Colour colour = 0;
    bool small = false;   // labels: the small font; bodies: with a centre-of-mass marker
    ImVec2 anchor{0, 0};  // labels: the point they belong to (pixels)
    float radius = 0.0f;  // spin: the arc's radius (pixels)
    bool faint = false;   // the reaction −P on a: drawn lighter; 2D labels: no backing
                          // (they stand where they are: names inside bodies, +x, +y)
};
using Annotations = std::vector<Annotation>;

// A vector's components in the scene's dimension (1D: x; 2D: x, y): an item's value.
std::vector<double> components(const Vec3& v, int dimension);
// A body's pose as a body item's value: 1D [x]; 2D [x, y, angle]; 3D [x, y, z, qw, qx, qy, qz].
std::vector<double> pose_value(const BodyState& s, int dimension);
// The state a body item is drawn at: its centre (`from`) and its pose's angle or orientation.
BodyState pose_of(const Annotation& body);
// An arrow (or point) item: its kind, body, world tail and tip, value and colour.
Annotation arrow_annotation(Mark kind, int body, const Vec3& from, const Vec3& to, std::vector<double> value,
                            Colour colour);

// A label still to be placed: the index of the item it labels, the point it belongs to and the
// side it prefers (pixels), its text and the number it prints (empty for names).
struct LabelRequest {
    int of = -1;
    ImVec2 anchor{0, 0}, direction{0, -1};
    std::string text;
    std::vector<double> value;
    Colour colour = 0;
    bool small = false;  // the small font
};
// The label item for `request`, its box placed by `placer` (LabelPlacer::place, `pad` and
// `gap` as place_label's); its body is the labelled item's.
Annotation placed_label(const FontSet& fonts, LabelPlacer* placer, const Annotations& items,
                        const LabelRequest& request, float pad, float gap);

// The items as JSON objects {"kind", "body", "from", "to", "value", "text", "box"} (and
// "sweep" for spins, "of" and "font_px" for labels, "outline" for bodies of the 3D view): points and vectors with `dimension` components, a
// one-component value as a number, `body` as the body's name (null for none).
void write_annotations_json(std::ostream& out, const Annotations& items, int dimension,
                            const std::vector<std::string>& body_names, int indent);

}  // namespace collide::render
