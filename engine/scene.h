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

struct Scene {
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

    // Pair rules: e = min(ea, eb) (the less bouncy body decides: clay on rubber does not
    // bounce); mu = sqrt(mua mub) (either surface being frictionless makes the pair so).
    double pair_restitution(std::size_t i, std::size_t j) const;
    double pair_friction(std::size_t i, std::size_t j) const;
};

}  // namespace collide
