// Scenes for the 2D and 3D worlds built in code (tests/engine/world*_test.cpp,
// bench/world_bench.cpp and bench/box2d_bench.cpp): single bodies, static planes, an elastic gas
// in a walled box, a pile of falling columns and a pyramid of boxes at rest. Scene and SceneBody are plain data (engine/scene.h); masses and
// inertia come from engine/mass.h as the scene file reader (scenario/scene_file.cpp) computes them.
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

inline Scene empty_scene(int dimension, Policy policy = Policy::sequential, double e = 1.0,
                         const Vec3& gravity = Vec3::Zero()) {
    Scene s;
    s.dimension = dimension;
    s.policy = policy;
    s.restitution = e;
    s.gravity = gravity;
    s.model = Model::frictionless;
    s.friction = 0.0;
    return s;
}

inline SceneBody disc(const std::string& name, double radius, double mass, const Vec2& x,
                      const Vec2& v = Vec2::Zero(), double w = 0.0, double angle = 0.0) {
    SceneBody b;
    b.name = name;
    b.shape = "disc";
    b.shape2 = Shape2::disc(radius);
    b.body2.mass = mass;
    b.body2.inertia = disc_inertia_2d(mass, radius);
    b.body2.position = x;
    b.body2.angle = angle;
    b.body2.v = v;
    b.body2.w = w;
    return b;
}

// A rectangle width x height (full edge lengths), centred on x, turned by angle.
inline SceneBody rectangle(const std::string& name, double width, double height, double mass,
                           const Vec2& x, double angle = 0.0, const Vec2& v = Vec2::Zero(),
                           double w = 0.0) {
    SceneBody b;
    b.name = name;
    b.shape = "rectangle";
    b.shape2 = Shape2::rectangle(width, height);
    b.body2.mass = mass;
    b.body2.inertia = rectangle_inertia_2d(mass, width, height);
    b.body2.position = x;
    b.body2.angle = angle;
    b.body2.v = v;
    b.body2.w = w;
    return b;
}

// Static half-plane: the solid side is {p : n . p <= offset} (n the outward unit normal).
inline SceneBody half_plane(const std::string& name, const Vec2& n, double offset) {
    SceneBody b;
    b.name = name;
    b.shape = "plane";
    b.shape2 = Shape2::half_plane(n, offset);
    b.body2.is_static = true;
    return b;
}

inline SceneBody sphere(const std::string& name, double radius, double mass, const Vec3& x,
                        const Vec3& v = Vec3::Zero(), const Vec3& w = Vec3::Zero()) {
    SceneBody b;
    b.name = name;
    b.shape = "sphere";
    b.shape3.kind = Shape3::Kind::sphere;
    b.shape3.radius = radius;
    b.body3.mass = mass;
    b.body3.inertia = sphere_inertia(mass, radius);
    b.body3.position = x;
    b.body3.v = v;
    b.body3.w = w;
    return b;
}

// A box with half extents `half` along its body axes.
inline SceneBody box(const std::string& name, const Vec3& half, double mass, const Vec3& x,
                     const Quat& q = Quat::Identity(), const Vec3& v = Vec3::Zero(),
                     const Vec3& w = Vec3::Zero()) {
    SceneBody b;
    b.name = name;
    b.shape = "box";
    b.shape3.kind = Shape3::Kind::box;
    b.shape3.half = half;
    b.body3.mass = mass;
    b.body3.inertia = box_inertia(mass, 2.0 * half);
    b.body3.orientation = q;
    b.body3.position = x;
    b.body3.v = v;
    b.body3.w = w;
    return b;
}

// Static half-space: the solid side is {p : n . p <= offset}.
inline SceneBody half_space(const std::string& name, const Vec3& n, double offset) {
    SceneBody b;
    b.name = name;
    b.shape = "plane";
    b.shape3.kind = Shape3::Kind::half_space;
    b.shape3.normal = n;
    b.shape3.offset = offset;
    b.body3.is_static = true;
    return b;
}

// The walls of the square [0, L]^2: solid outside, x <= 0, x >= L, y <= 0, y >= L.
inline void add_walls2(Scene* s, double L) {
    s->bodies.push_back(half_plane("left", Vec2(1, 0), 0.0));
    s->bodies.push_back(half_plane("right", Vec2(-1, 0), -L));
    s->bodies.push_back(half_plane("floor", Vec2(0, 1), 0.0));
    s->bodies.push_back(half_plane("ceiling", Vec2(0, -1), -L));
}

// The walls of the cube [0, L]^3.
inline void add_walls3(Scene* s, double L) {
    const char* names[3][2] = {{"x0", "x1"}, {"y0", "y1"}, {"z0", "z1"}};
    for (int k = 0; k < 3; ++k) {
        s->bodies.push_back(half_space(names[k][0], Vec3::Unit(k), 0.0));
        s->bodies.push_back(half_space(names[k][1], -Vec3::Unit(k), -L));
    }
}

// ---- Reproducible random numbers -----------------------------------------------------------

class Random {
public:
    explicit Random(std::uint64_t seed) : gen_(seed) {}
    double uniform(double lo, double hi) {  // [lo, hi)
        return lo + (hi - lo) * (static_cast<double>(gen_() >> 11) * 0x1.0p-53);
    }
    Vec2 unit2() {
        const double a = uniform(0.0, 2.0 * kPi);
        return Vec2(std::cos(a), std::sin(a));
    }
    Vec3 unit3() {  // uniform on the sphere (Archimedes: z uniform in [-1, 1])
        const double z = uniform(-1.0, 1.0), a = uniform(0.0, 2.0 * kPi);
        const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
        return Vec3(s * std::cos(a), s * std::sin(a), z);
    }

private:
    std::mt19937_64 gen_;
};

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

inline double gas_box_size(int dimension, const GasSpec& g) {
    const double body = dimension == 2 ? kPi * g.radius * g.radius
                                       : 4.0 / 3.0 * kPi * g.radius * g.radius * g.radius;
    return std::pow(g.n * body / g.fraction, 1.0 / dimension);
}

inline Scene gas(int dimension, const GasSpec& g) {
    Scene s = empty_scene(dimension);
    const double L = gas_box_size(dimension, g);
    if (dimension == 2) add_walls2(&s, L);
    else add_walls3(&s, L);
    int k = 1;  // lattice cells per side
    while (std::pow(static_cast<double>(k), dimension) < g.n) ++k;
    const double cell = L / k;
    const double jitter = std::max(0.0, 0.5 * cell - g.radius) * 0.8;  // keeps 20% of the slack
    Random rng(g.seed);
    for (int i = 0; i < g.n; ++i) {
        const int ix = i % k, iy = (i / k) % k, iz = i / (k * k);
        const std::string name = "b" + std::to_string(i);
        const double speed = g.speed * rng.uniform(0.5, 1.5);
        if (dimension == 2) {
            const Vec2 x((ix + 0.5) * cell + rng.uniform(-jitter, jitter),
                         (iy + 0.5) * cell + rng.uniform(-jitter, jitter));
            s.bodies.push_back(disc(name, g.radius, g.mass, x, speed * rng.unit2()));
        } else {
            const Vec3 x((ix + 0.5) * cell + rng.uniform(-jitter, jitter),
                         (iy + 0.5) * cell + rng.uniform(-jitter, jitter),
                         (iz + 0.5) * cell + rng.uniform(-jitter, jitter));
            s.bodies.push_back(sphere(name, g.radius, g.mass, x, speed * rng.unit3()));
        }
    }
    return s;
}

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
    double g = 9.81;        // m/s^2
};

inline Scene pile(int dimension, const PileSpec& p) {
    Scene s = empty_scene(dimension, Policy::sequential, p.e, Vec3(0.0, -p.g, 0.0));
    if (dimension == 2) s.bodies.push_back(half_plane("ground", Vec2(0, 1), 0.0));
    else s.bodies.push_back(half_space("ground", Vec3(0, 1, 0), 0.0));
    const int columns = (p.n + p.per_column - 1) / p.per_column;
    int side = 1;  // 3D: columns per row of the square grid
    while (side * side < columns) ++side;
    for (int i = 0; i < p.n; ++i) {
        const int column = i / p.per_column, level = i % p.per_column;
        const double y = p.radius + p.gap + level * (2.0 * p.radius + p.gap);
        const std::string name = "b" + std::to_string(i);
        if (dimension == 2) {
            s.bodies.push_back(disc(name, p.radius, p.mass, Vec2(column * p.spacing, y)));
        } else {
            const Vec3 x((column % side) * p.spacing, y, (column / side) * p.spacing);
            s.bodies.push_back(sphere(name, p.radius, p.mass, x));
        }
    }
    return s;
}

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
    double g = 9.81;         // m/s^2
};

inline Scene pyramid(const PyramidSpec& p) {
    Scene s = empty_scene(2, Policy::simultaneous, p.e, Vec3(0.0, -p.g, 0.0));
    s.model = Model::coulomb;
    s.friction = p.mu;
    s.bodies.push_back(half_plane("ground", Vec2(0, 1), 0.0));
    for (int k = 0; k < p.rows; ++k)
        for (int j = 0; j < p.rows - k; ++j) {
            const Vec2 x((k * 0.5 + j) * p.spacing, (k + 0.5) * p.size);
            s.bodies.push_back(rectangle("r" + std::to_string(k) + "b" + std::to_string(j), p.size,
                                         p.size, p.mass, x));
        }
    return s;
}

// ---- Energies ------------------------------------------------------------------------------

// Kinetic energy of the dynamic bodies (engine/diagnostics.h: full inertia tensor in 3D).
inline double kinetic_energy(const std::vector<Body2>& bodies) { return totals(bodies).kinetic_energy; }
inline double kinetic_energy(const std::vector<Body3>& bodies) { return totals(bodies).kinetic_energy; }

// Potential energy in uniform gravity g: sum over dynamic bodies of -m g . x.
inline double potential_energy(const std::vector<Body2>& bodies, const Vec3& g) {
    double u = 0.0;
    for (const Body2& b : bodies)
        if (!b.is_static) u -= b.mass * g.head<2>().dot(b.position);
    return u;
}
inline double potential_energy(const std::vector<Body3>& bodies, const Vec3& g) {
    double u = 0.0;
    for (const Body3& b : bodies)
        if (!b.is_static) u -= b.mass * g.dot(b.position);
    return u;
}

}  // namespace collide::scenes
