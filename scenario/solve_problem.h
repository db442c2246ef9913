// The input of `collide solve`: one collision, read from a TOML file (format: docs/formats/collision-files.md).
#pragma once

#include <string>

#include <toml++/toml.h>

#include "engine/body.h"
#include "engine/response.h"
#include "engine/routh.h"

namespace collide {

// One body as described in the file; only the members of the problem's dimension are used.
struct SolveBody {
    std::string name;   // "A" / "B" unless the file names them
    std::string shape;  // "" when the inertia was given directly
    Body1 b1;
    Body2 b2;
    Body3 b3;
};

struct SolveProblem {
    std::string file;   // as given on the command line ("<stdin>" for -)
    std::string title;  // optional, shown as the heading of the worked example
    int dimension = 3;
    Model model = Model::frictionless;
    RestitutionLaw restitution_law = RestitutionLaw::stronge;  // model routh only
    double restitution = 0.0;                                  // e
    double friction = 0.0;                                     // mu
    // Unit normal from A into B. 1D: +1 or -1 in x. 2D: z = 0.
    Vec3 normal = Vec3::UnitX();
    Vec3 point = Vec3::Zero();  // contact point, world frame (2D: z = 0; unused in 1D)
    Vec3 about = Vec3::Zero();  // angular momentum reference point
    SolveBody a, b;
};

// Parses and validates; throws InputError naming file, line, column and key.
SolveProblem parse_solve_file(const std::string& path);
SolveProblem parse_solve_text(const std::string& text, const std::string& name);
// The same for a table built in memory rather than read from a file (the Python module's
// dicts): its values carry no line or column, so the messages name `name` and the key.
SolveProblem parse_solve_table(const toml::table& table, const std::string& name);

}  // namespace collide
