// What one frame shows, whatever the scene's dimension: every body's state lifted to 3D
// (1D: x along the x axis; 2D: the xy plane, the angle about +z), the collisions to annotate,
// and the recent path of each body for its trail.
#pragma once

#include <cstddef>
#include <vector>

#include "engine/body.h"
#include "engine/scene.h"
#include "engine/world.h"
#include "engine/world1d.h"

namespace collide::render {

using collide::BodyState;  // engine/body.h: every body's state lifted to 3D

// One collision as the diagrams draw it (docs/conventions.md: n from a into b, +P on b).
struct ImpactMark : LiftedEvent {  // t, a, b, point, normal, impulse on b (engine/world.h)
    bool detailed = true;          // drawn with its value, n and r_a, r_b; else its impulse arrow only
};

struct TrailPoint {
    double t;  // s
    Vec3 x;    // m
};

struct FrameState {
    double t = 0.0;                               // s
    std::vector<BodyState> bodies;                // scene order
    std::vector<ImpactMark> impacts;              // drawn as "at the collision" annotations
    std::vector<std::vector<TrailPoint>> trails;  // per body, oldest first (may be empty)
};

// 1D blocks are drawn as boxes standing on the x axis: this is the height of block i (m) and
// where its centre is drawn (y = height / 2).
double block_height(const Scene& scene, std::size_t i);

FrameState frame_state(const Scene& scene, double t, const std::vector<Body1>& bodies);
FrameState frame_state(const Scene& scene, double t, const std::vector<Body2>& bodies);
FrameState frame_state(const Scene& scene, double t, const std::vector<Body3>& bodies);

ImpactMark impact_mark(const Scene& scene, const Event1& e);
ImpactMark impact_mark(const Scene& scene, const Event2& e);
ImpactMark impact_mark(const Scene& scene, const Event3& e);

// The collisions a frame draws, out of those since the previous frame. A contact-rich run has
// hundreds between two frames (a box settling on a box: micro-collisions of 10^-5 N s); drawn
// all, they bury the frame. Kept: those whose impulse is at least kShownImpulseFraction of the
// largest among them, the kMaxShownImpacts largest, in time order. A frame with a few
// collisions of similar size is unchanged.
constexpr double kShownImpulseFraction = 0.1;
constexpr std::size_t kMaxShownImpacts = 6;
std::vector<ImpactMark> shown_impacts(std::vector<ImpactMark> impacts);
// How many of a frame's (shown) collisions get their full annotation (ImpactMark::detailed):
// the impulse's value, the normal n and the lever arms r_a, r_b; not two of one pair at the
// same point. The others draw their impulse arrow only.
constexpr std::size_t kDetailedImpacts = 3;

// Velocity and spin labels in a frame of more than kFewBodies moving bodies: only for the
// bodies whose speed (or spin) is at least kShownMotionFraction of the frame's largest (a
// tower's resting boxes do not get "ω = 9.03×10⁻⁴ rad/s" beside the falling ones), and with
// more than kQuietBodies, only the kMaxMotionLabels largest of those (their arrows are drawn
// all the same: a pile of 40 boxes settling turns them all a little). Up to kFewBodies: every
// one is labelled (a lesson's two or three bodies, a body at rest included).
constexpr std::size_t kFewBodies = 4;
constexpr std::size_t kQuietBodies = 8;
constexpr double kShownMotionFraction = 0.1;
constexpr std::size_t kMaxMotionLabels = 6;
// How many velocity (or spin) labels a frame of `moving` moving bodies gets at most: every one
// that motion_labelled() admits up to kQuietBodies, else kMaxMotionLabels (in scene order among
// equals: a bin's 100 boxes falling together all have the sixth largest speed).
inline std::size_t motion_label_budget(std::size_t moving) { return moving > kQuietBodies ? kMaxMotionLabels : moving; }
// Which moving bodies get a velocity (or spin) label: `sizes` their speeds (or spins) and
// `first` the bodies of the frame's collisions, one entry each, in scene order. Those that
// motion_labelled() admits, at most motion_label_budget() of them: the bodies of a collision
// first, then the largest, in scene order among equals.
std::vector<bool> motion_labels(const std::vector<double>& sizes, const std::vector<bool>& first);
// The same for a frame, by scene index: which of the `counted` bodies (the moving ones a view
// draws) get a velocity label and which a spin label, from their |v| and |ω|, the bodies of
// the frame's collisions first. `count`: how many bodies were counted.
struct FrameMotionLabels {
    std::vector<bool> speed, spin;
    std::size_t count = 0;
};
FrameMotionLabels motion_labels(const FrameState& frame, const std::vector<bool>& counted);
// With more than kManyBodies moving bodies (a bin of boxes) a body's name is shown only where
// it fits inside the body, or where the body carries a velocity, spin or impulse label (which
// body that number is about): a name beside each of 100 boxes buries the frame, and the data
// table names the bodies that move most. A row of 15 dominoes keeps every name.
constexpr std::size_t kManyBodies = 20;
// The smallest speed (or spin) labelled in a frame whose moving bodies' speeds (or spins) are
// `sizes`: 0 (every one) for up to kFewBodies of them; else kShownMotionFraction of the
// largest, and beyond kQuietBodies at least the kMaxMotionLabels-th largest.
double motion_label_floor(std::vector<double> sizes);
// Whether a value of `size` is labelled (`floor` from motion_label_floor).
inline bool motion_labelled(double size, double floor) { return size >= floor; }

// The data table's rows in a frame of many bodies. The table has room for at most `rows`
// bodies (kTableBodies, or fewer when the frame is short); with more moving bodies than that,
// rows - 1 of them get a row and one line tells the others' count and how fast the fastest of
// them moves and turns. The rows go to the two bodies of the frame's largest (shown) collision,
// then to those with the most kinetic energy (ties: scene order): what moves, not the many
// bodies that a settling pile's small collisions touch. They are listed in scene order. The
// totals below them stay those of every moving body.
constexpr std::size_t kTableBodies = 8;
struct TableRows {
    std::vector<std::size_t> shown;  // scene indices of the bodies with a row, in scene order
    std::size_t others = 0;          // moving bodies without a row
    double others_speed = 0.0;       // m/s: the largest |v| among them
    double others_spin = 0.0;        // rad/s: the largest |ω| among them
};
// `moving`: the moving bodies' scene indices, in order; `kinetic`: each body's kinetic energy
// (J), by scene index; `frame`: its bodies and collisions (ImpactMark::a, b).
TableRows table_rows(const std::vector<std::size_t>& moving, const std::vector<double>& kinetic,
                     const FrameState& frame, std::size_t rows = kTableBodies);

// Fills frame.trails from earlier frames: for each body the centres at the frames within
// `span` seconds before frame.t (in `history`, time order), then its current centre.
void add_trails(const std::vector<FrameState>& history, double span, FrameState* frame);

// Mass of body i (kg), whatever the dimension.
double body_mass(const Scene& scene, std::size_t i);

// Kinetic energy of body i (J), by the engine's formula (engine/diagnostics.h). 0 for static
// bodies.
double kinetic_energy(const Scene& scene, std::size_t i, const BodyState& s);

// Totals of the moving bodies of a frame, by the engine's formulas (engine/diagnostics.h):
// kinetic energy, potential energy in the scene's gravity (zero at the origin), momentum (1D: x;
// 2D: x, y) and angular momentum about the origin (2D: z; 1D: none, zero).
struct FrameTotals {
    double kinetic = 0.0;                  // J
    double potential = 0.0;                // J
    Vec3 momentum = Vec3::Zero();          // kg m/s
    Vec3 angular_momentum = Vec3::Zero();  // kg m^2/s
};
FrameTotals frame_totals(const Scene& scene, const FrameState& frame);
// The same of body i alone (a static body's are zero).
FrameTotals body_totals(const Scene& scene, const FrameState& frame, std::size_t i);

// A run's totals as columns, for plots: kinetic, potential and their sum (J), momentum
// components (kg m/s).
struct TotalsColumns {
    std::vector<double> kinetic, potential, total, px, py, pz;
};
TotalsColumns totals_columns(const std::vector<FrameTotals>& totals);

}  // namespace collide::render
