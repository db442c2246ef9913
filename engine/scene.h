// A scene: the bodies of a 1D, 2D or 3D simulation with their shapes and materials, and the
// settings of the run. Data only; the world that steps it comes later (engine/world*.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/body.h"
#include "engine/response.h"
#include "engine/routh.h"
#include "engine/shape2d.h"
#include "engine/shape3d.h"

namespace collide {

// How several contacts at one instant are resolved.
//   sequential:   one contact at a time, in a defined, deterministic order;
//   simultaneous: all active contact points of a touching group solved together.
enum class Policy { sequential, simultaneous };
const char* policy_name(Policy p);

// Which contacts of a 2D or 3D world advance by time steps instead of event by event
// (docs/stepping.md, "Stepped islands"):
//   automatic: where contacts persist (two moving bodies colliding again and again) and
//              whatever touches them; every other impact exact;
//   always:    every body from its first touching contact on (impacts of free bodies exact);
//   never:     none: every contact exact, event by event (slow where contacts persist).
enum class StepMode { automatic, always, never };
const char* step_mode_name(StepMode s);  // "auto", "always", "never" (the scene file's words)

struct SceneBody {
    std::string name;     // unique
    std::string shape;    // as named in the file: block, disc, rectangle, polygon, sphere, box, plane
    double length = 0.0;  // 1D block: full length, m (the body spans position -+ length/2)
    Body1 body1;          // the dimension's body; the others stay default
    Body2 body2;
    Body3 body3;
    Shape2 shape2;
    Shape3 shape3;
    std::optional<double> restitution, friction;  // the body's own; else the scene's
    bool is_static() const { return body1.is_static || body2.is_static || body3.is_static; }
};

// The work a run may take before the world refuses it (RunError: exit 2), in units of about a
// microsecond (docs/stepping.md, "Work budget"): each moving body's share of a substep, each
// free-rotation step, each time-of-impact prediction, each collision (1D: each event and each
// motion between them). The worlds estimate it before they start (what the scene costs if
// nothing but its free motion happens) and count it while they run, refusing as soon as the
// estimate or the count passes the budget. The default is kDefaultWorkBudget (about a
// minute); the commands take --max-work, the Python module max_work=, and the WebAssembly
// module gives each call kWasmWorkBudget (a few seconds: a page never freezes).
constexpr double kDefaultWorkBudget = 1e8;
constexpr double kWasmWorkBudget = 5e6;
double default_work_budget();                // kDefaultWorkBudget unless set below
void set_default_work_budget(double units);  // process-wide: every Scene made after takes it

struct Scene {
    std::string file;  // where it was read from ("<stdin>", a lesson's file), for messages; may be ""
    std::string title;
    int dimension = 2;
    Vec3 gravity = Vec3::Zero();  // m/s^2 (2D: z = 0; 1D: along x)
    double duration = 1.0;        // s
    double output_dt = 0.01;      // s between printed / rendered states
    Model model = Model::frictionless;
    // How a routh impact ends (engine/routh.h); the other models use Newton's law.
    RestitutionLaw restitution_law = RestitutionLaw::stronge;
    Policy policy = Policy::sequential;
    StepMode stepping = StepMode::automatic;
    double restitution = 1.0;  // for bodies that set none
    double friction = 0.0;
    std::vector<SceneBody> bodies;
    double work_budget = default_work_budget();  // see kDefaultWorkBudget

    // Pair rules: e = min(ea, eb) (the less bouncy body decides: clay on rubber does not
    // bounce); mu = sqrt(mua mub) (either surface being frictionless makes the pair so).
    double pair_restitution(std::size_t i, std::size_t j) const;
    double pair_friction(std::size_t i, std::size_t j) const;
};

}  // namespace collide
