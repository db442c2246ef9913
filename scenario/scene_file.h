// Scenario files (TOML): a [scene] table and [[body]] tables. Format: docs/formats/scenario-files.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/scene.h"
#include "scenario/toml_reader.h"

namespace collide {

// How the scenario asks to be shown: the optional [view] table (docs/formats/scenario-files.md), read by
// `collide render`. Unset camera values are chosen from the scene's extent.
// [[mark]]: a point fixed in a body, drawn in the figures and frames with its name (and, with
// `velocity`, its own velocity v + ω × r): a bat's handle end, its sweet spot. 1D and 2D.
struct ViewMark {
    std::size_t body = 0;    // scene index
    Vec3 at = Vec3::Zero();  // m, in the body's frame: from its centre along its unrotated axes
    std::string name;
    bool velocity = false;
};

struct SceneView {
    std::optional<double> camera_azimuth;    // degrees, -360..360: turned right of the front (+z)
    std::optional<double> camera_elevation;  // degrees, -89..89: above the horizon
    std::optional<Vec3> camera_target;       // m: the point looked at
    std::optional<double> camera_distance;   // m from the target, > 0
    bool directions = false;                 // the page's positive-direction arrows in the figure's panels
    std::vector<ViewMark> marks;
};

// The index of the body of `scene` named `name`; otherwise fails at `table`'s `key` with "no
// body named 'x'; did you mean 'y'?" (lessons' questions and figures, [[mark]]).
std::size_t body_named(const Scene& scene, const std::string& name, const TableReader& table, const std::string& key);

// Parses and validates; throws InputError naming file, line, column and key. Beyond the
// per-key checks: unique names, static bodies at rest, no two bodies overlapping at the start.
// `view`, when given, receives the [view] table (which is checked either way).
Scene parse_scene_file(const std::string& path, SceneView* view = nullptr);
// How far two bodies overlap where they are (m; <= 0: apart or touching). A file may not
// start with two bodies overlapping by more than kOverlapTolerance (nor may collide gui's or
// the interactive mode's edits): touching is fine, overlapping is not.
double start_overlap(const Scene& s, const SceneBody& a, const SceneBody& b);
constexpr double kOverlapTolerance = 1e-9;  // m
// `also_allowed`: more top-level tables the caller reads itself (a lesson's [lesson] and
// [[question]]).
Scene parse_scene_text(const std::string& text, const std::string& name, SceneView* view = nullptr,
                       const std::vector<std::string>& also_allowed = {});
// The same for a table built in memory rather than read from a file (the Python module's
// dicts): its values carry no line or column, so the messages name `name` and the key.
Scene parse_scene_table(const toml::table& table, const std::string& name, SceneView* view = nullptr,
                        const std::vector<std::string>& also_allowed = {});

}  // namespace collide
