// Scenes for the 2D and 3D worlds built in code, shared by the tests (tests/engine/, compare/,
// cli/) and the benchmarks (bench/) through the library collide_test_scenes: single bodies, static
// planes, an elastic gas in a walled box, a pile of falling columns, a pyramid of boxes at rest,
// boxes dropped into a bin and a tower knocked over by a ball; and measures of how well a scene
// has settled (overlap, surface speed) that judge any engine's poses alike. Scene and SceneBody
// are plain data (engine/scene.h); masses and inertia come from engine/mass.h as the scene file
// reader (scenario/scene_file.cpp) computes them.
//
// Random draws are reproducible on every standard library: a std::mt19937_64 with a fixed seed
// whose raw 64-bit output is turned into doubles by hand (as tests/engine/random_bodies.h does).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "engine/diagnostics.h"
#include "engine/mass.h"
#include "engine/scene.h"

namespace collide::scenes {

// ---- Scenes and bodies -------------------------------------------------------------------

Scene empty_scene(int dimension, Policy policy = Policy::sequential, double e = 1.0,
                  const Vec3& gravity = Vec3::Zero());

SceneBody disc(const std::string& name, double radius, double mass, const Vec2& x, const Vec2& v = Vec2::Zero(),
               double w = 0.0, double angle = 0.0);

// A rectangle width x height (full edge lengths), centred on x, turned by angle.
SceneBody rectangle(const std::string& name, double width, double height, double mass, const Vec2& x,
                    double angle = 0.0, const Vec2& v = Vec2::Zero(), double w = 0.0);

// Static half-plane: the solid side is {p : n . p <= offset} (n the outward unit normal).
SceneBody half_plane(const std::string& name, const Vec2& n, double offset);

SceneBody sphere(const std::string& name, double radius, double mass, const Vec3& x, const Vec3& v = Vec3::Zero(),
                 const Vec3& w = Vec3::Zero());

// A box with half extents `half` along its body axes.
SceneBody box(const std::string& name, const Vec3& half, double mass, const Vec3& x, const Quat& q = Quat::Identity(),
              const Vec3& v = Vec3::Zero(), const Vec3& w = Vec3::Zero());

// Static half-space: the solid side is {p : n . p <= offset}.
SceneBody half_space(const std::string& name, const Vec3& n, double offset);

// The walls of the square [0, L]^2: solid outside, x <= 0, x >= L, y <= 0, y >= L.
void add_walls2(Scene* s, double L);

// The walls of the cube [0, L]^3.
void add_walls3(Scene* s, double L);

// ---- An elastic gas in a walled box --------------------------------------------------------

// n discs (2D) or spheres (3D) of one radius and mass filling `fraction` of the area / volume of
// the box [0, L]^D (L follows from n, radius, fraction), on a jittered lattice (no two overlap,
// none touches a wall), moving in random directions at speeds uniform in [0.5, 1.5] speed.
// Frictionless, e = 1 (unless changed), no gravity. The walls come first (4 or 6 static
// planes), then the n dynamic bodies.
struct GasSpec {
    int n = 200;
    double fraction = 0.05;
    double radius = 0.05;  // m
    double mass = 1.0;     // kg
    double speed = 1.0;    // m/s (mean)
    std::uint64_t seed = 1;
};

double gas_box_size(int dimension, const GasSpec& g);

Scene gas(int dimension, const GasSpec& g);

// ---- A pile of falling columns -------------------------------------------------------------

// n discs / spheres in vertical columns of `per_column` over the ground plane y = 0 (solid
// below), at rest: the lowest of a column `gap` above the ground, `gap` between neighbours in a
// column; columns `spacing` apart (centre to centre) along x (2D) or on a square grid in xz
// (3D). Gravity (0, -g, 0), restitution e. The ground comes first, then the n bodies.
struct PileSpec {
    int n = 100;
    int per_column = 5;
    double radius = 0.05;   // m
    double mass = 1.0;      // kg
    double gap = 0.01;      // m
    double spacing = 0.15;  // m, centre to centre (3 radii)
    double e = 0.5;
    double g = 9.81;  // m/s^2
};

Scene pile(int dimension, const PileSpec& p);

// ---- A pyramid of boxes at rest ------------------------------------------------------------

// `rows` rows of square boxes (edge `size`) resting on the ground plane y = 0, as in Box2D's
// pyramid benchmark: row k (0 at the bottom) holds rows - k boxes `spacing` apart, shifted by
// spacing / 2 per row, so that each box rests on two below it. The rows touch exactly (no
// gaps) and every box starts at rest. Coulomb friction mu, restitution e, gravity (0, -g),
// simultaneous policy. The ground comes first, then the boxes row by row from the bottom
// (rows (rows + 1) / 2 of them: 210 for 20 rows).
struct PyramidSpec {
    int rows = 20;
    double size = 1.0;       // m (Box2D's pyramid: half-extent 0.5 m)
    double spacing = 1.125;  // m, centre to centre within a row
    double mass = 1.0;       // kg
    double mu = 0.6;
    double e = 0.0;
    double g = 9.81;  // m/s^2
};

Scene pyramid(const PyramidSpec& p);

// ---- Boxes dropped into a walled bin --------------------------------------------------------

// n boxes with sides drawn uniformly in [min_side, max_side] (each side on its own: two in 2D,
// three in 3D) at random angles (3D: orientations uniform over all rotations), at rest on a
// grid above the floor of a bin open at the top, dropped under gravity (0, -g, 0). The bin is
// the floor y = 0 and walls x = 0, x = W (3D also z = 0, z = W), static half-planes /
// half-spaces solid outside. Grid cells are `bin_pitch` apart, a centimetre more than the
// largest box's diagonal, so no two boxes overlap and none touches a wall whatever its angle;
// the lowest layer's centres are half a pitch above the floor. The bin is exactly
// `bin_columns` cells wide: 2D 2 sqrt(n) columns (100 boxes: 20 columns, 8.7 m, 5 rows),
// 3D cbrt(n) columns each way (100 boxes: 5 x 5, 2.6 m, 4 layers); settled, the boxes lie a
// few deep (2D 100: about 4 layers; 400: 8). Uniform density, a box of the mean size
// (0.25 m sides) weighing 1 kg: 16 kg/m^2 in 2D (0.64 to 1.44 kg), 64 kg/m^3 in 3D (0.51 to
// 1.73 kg); inertia of a uniform box. Coulomb friction mu, restitution e, simultaneous
// policy. The walls come first (2D: floor, left, right; 3D: floor, x0, x1, z0, z1), then the
// boxes b0, b1, ... row by row from the bottom.
struct BinSpec {
    int n = 100;
    std::uint64_t seed = 1;
    double min_side = 0.2;   // m
    double max_side = 0.3;   // m
    double density2 = 16.0;  // kg/m^2 (2D)
    double density3 = 64.0;  // kg/m^3 (3D)
    double mu = 0.5;
    double e = 0.2;
    double g = 9.81;  // m/s^2
    int columns = 0;  // cells across the bin (each way in 3D); 0: as above
};

// m: grid cell size, the largest box's diagonal plus 1 cm.
double bin_pitch(int dimension, const BinSpec& b);
int bin_columns(int dimension, const BinSpec& b);
// m: the inner width W of the bin.
double bin_width(int dimension, const BinSpec& b);

Scene bin(int dimension, const BinSpec& b);

// ---- A tower of boxes knocked over by a ball -----------------------------------------------

// `levels` boxes (mass 1 kg, 0.2 x 0.1 x 0.2 m, the short side up) stacked exactly touching on
// the ground plane y = 0 (normal +y) at y = 0.05 + 0.1 i, x = z = 0, at rest; a 2 kg ball
// (r = 0.08 m) at (-0.8, 0.45, 0) thrown at them at (4, 0, 0) m/s (it meets the fourth box,
// 0.3 to 0.4 m up, after about 0.15 s). Coulomb mu 0.5, e 0.3, simultaneous policy, gravity
// (0, -9.81, 0). The ground comes first, then the boxes from the bottom (box0, ...), then the
// ball.
struct TowerSpec {
    int levels = 6;
    double mass = 1.0;                    // kg, each box
    Vec3 size = Vec3(0.2, 0.1, 0.2);      // m, full edge lengths
    double ball_mass = 2.0;               // kg
    double ball_radius = 0.08;            // m
    Vec3 ball_x = Vec3(-0.8, 0.45, 0.0);  // m
    Vec3 ball_v = Vec3(4.0, 0.0, 0.0);    // m/s
    double mu = 0.5;
    double e = 0.3;
    double g = 9.81;  // m/s^2
};

Scene tower3d(const TowerSpec& t);

// ---- How well a scene has settled ----------------------------------------------------------

// The deepest overlap (m, >= 0) between any two bodies, static ones included, at the given
// poses, measured with collide's own narrow phase (engine/shape2d.h, shape3d.h: minus the
// signed separation), so that poses read back from any engine are judged alike. Pairs whose
// bounding circles / spheres are apart are skipped; two static bodies are never compared.
double deepest_overlap(const Scene& scene, const std::vector<Body2>& bodies);
double deepest_overlap(const Scene& scene, const std::vector<Body3>& bodies);

// The fastest surface point's speed bound over the dynamic bodies (m/s): max |v| + |w| R,
// R the shape's bounding radius. Zero when everything is at rest.
double fastest_surface_speed(const Scene& scene, const std::vector<Body2>& bodies);
double fastest_surface_speed(const Scene& scene, const std::vector<Body3>& bodies);

// ---- Energies ------------------------------------------------------------------------------

// Kinetic energy of the dynamic bodies (engine/diagnostics.h: full inertia tensor in 3D).
double kinetic_energy(const std::vector<Body2>& bodies);
double kinetic_energy(const std::vector<Body3>& bodies);

// Potential energy in uniform gravity g: sum over dynamic bodies of -m g . x.
double potential_energy(const std::vector<Body2>& bodies, const Vec3& g);
double potential_energy(const std::vector<Body3>& bodies, const Vec3& g);

}  // namespace collide::scenes
