// Scenes for the 2D and 3D worlds built in code (tests/engine/world*_test.cpp,
// bench/world_bench.cpp, bench/box2d_bench.cpp, bench/bullet_bench.cpp): single bodies, static
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
    double min_side = 0.2;    // m
    double max_side = 0.3;    // m
    double density2 = 16.0;   // kg/m^2 (2D)
    double density3 = 64.0;   // kg/m^3 (3D)
    double mu = 0.5;
    double e = 0.2;
    double g = 9.81;          // m/s^2
    int columns = 0;          // cells across the bin (each way in 3D); 0: as above
};

// m: grid cell size, the largest box's diagonal plus 1 cm.
inline double bin_pitch(int dimension, const BinSpec& b) {
    return std::sqrt(static_cast<double>(dimension)) * b.max_side + 0.01;
}
inline int bin_columns(int dimension, const BinSpec& b) {
    if (b.columns > 0) return b.columns;
    const double c = dimension == 2 ? 2.0 * std::sqrt(static_cast<double>(b.n))
                                    : std::cbrt(static_cast<double>(b.n));
    return std::max(1, static_cast<int>(std::ceil(c - 1e-9)));
}
// m: the inner width W of the bin.
inline double bin_width(int dimension, const BinSpec& b) {
    return bin_columns(dimension, b) * bin_pitch(dimension, b);
}

inline Scene bin(int dimension, const BinSpec& b) {
    Scene s = empty_scene(dimension, Policy::simultaneous, b.e, Vec3(0.0, -b.g, 0.0));
    s.model = Model::coulomb;
    s.friction = b.mu;
    const double pitch = bin_pitch(dimension, b), W = bin_width(dimension, b);
    const int c = bin_columns(dimension, b);
    if (dimension == 2) {
        s.bodies.push_back(half_plane("floor", Vec2(0, 1), 0.0));
        s.bodies.push_back(half_plane("left", Vec2(1, 0), 0.0));
        s.bodies.push_back(half_plane("right", Vec2(-1, 0), -W));
    } else {
        s.bodies.push_back(half_space("floor", Vec3(0, 1, 0), 0.0));
        s.bodies.push_back(half_space("x0", Vec3(1, 0, 0), 0.0));
        s.bodies.push_back(half_space("x1", Vec3(-1, 0, 0), -W));
        s.bodies.push_back(half_space("z0", Vec3(0, 0, 1), 0.0));
        s.bodies.push_back(half_space("z1", Vec3(0, 0, -1), -W));
    }
    Random rng(b.seed);
    for (int i = 0; i < b.n; ++i) {
        const std::string name = "b" + std::to_string(i);
        if (dimension == 2) {
            const double w = rng.uniform(b.min_side, b.max_side);
            const double h = rng.uniform(b.min_side, b.max_side);
            const double angle = rng.uniform(0.0, 2.0 * kPi);
            const Vec2 x((i % c + 0.5) * pitch, (i / c + 0.5) * pitch);
            s.bodies.push_back(rectangle(name, w, h, b.density2 * w * h, x, angle));
        } else {
            Vec3 size;
            for (int k = 0; k < 3; ++k) size[k] = rng.uniform(b.min_side, b.max_side);
            // Uniform over rotations (Shoemake's subgroup algorithm: three uniform draws).
            const double u1 = rng.uniform(0.0, 1.0), u2 = rng.uniform(0.0, 2.0 * kPi),
                         u3 = rng.uniform(0.0, 2.0 * kPi);
            const double r1 = std::sqrt(1.0 - u1), r2 = std::sqrt(u1);
            const Quat q(r2 * std::cos(u3), r1 * std::sin(u2), r1 * std::cos(u2),
                         r2 * std::sin(u3));
            const Vec3 x((i % c + 0.5) * pitch, (i / (c * c) + 0.5) * pitch,
                         ((i / c) % c + 0.5) * pitch);
            s.bodies.push_back(box(name, 0.5 * size, b.density3 * size.prod(), x, q.normalized()));
        }
    }
    return s;
}

// ---- A tower of boxes knocked over by a ball -----------------------------------------------

// `levels` boxes (mass 1 kg, 0.2 x 0.1 x 0.2 m, the short side up) stacked exactly touching on
// the ground plane y = 0 (normal +y) at y = 0.05 + 0.1 i, x = z = 0, at rest; a 2 kg ball
// (r = 0.08 m) at (-0.8, 0.45, 0) thrown at them at (4, 0, 0) m/s (it meets the fourth box,
// 0.3 to 0.4 m up, after about 0.15 s). Coulomb mu 0.5, e 0.3, simultaneous policy, gravity
// (0, -9.81, 0). The ground comes first, then the boxes from the bottom (box0, ...), then the
// ball.
struct TowerSpec {
    int levels = 6;
    double mass = 1.0;                       // kg, each box
    Vec3 size = Vec3(0.2, 0.1, 0.2);         // m, full edge lengths
    double ball_mass = 2.0;                  // kg
    double ball_radius = 0.08;               // m
    Vec3 ball_x = Vec3(-0.8, 0.45, 0.0);     // m
    Vec3 ball_v = Vec3(4.0, 0.0, 0.0);       // m/s
    double mu = 0.5;
    double e = 0.3;
    double g = 9.81;                         // m/s^2
};

inline Scene tower3d(const TowerSpec& t) {
    Scene s = empty_scene(3, Policy::simultaneous, t.e, Vec3(0.0, -t.g, 0.0));
    s.model = Model::coulomb;
    s.friction = t.mu;
    s.bodies.push_back(half_space("ground", Vec3(0, 1, 0), 0.0));
    for (int i = 0; i < t.levels; ++i)
        s.bodies.push_back(box("box" + std::to_string(i), 0.5 * t.size, t.mass,
                               Vec3(0.0, (i + 0.5) * t.size.y(), 0.0)));
    s.bodies.push_back(sphere("ball", t.ball_radius, t.ball_mass, t.ball_x, t.ball_v));
    return s;
}

// ---- How well a scene has settled ----------------------------------------------------------

// The deepest overlap (m, >= 0) between any two bodies, static ones included, at the given
// poses, measured with collide's own narrow phase (engine/shape2d.h, shape3d.h: minus the
// signed separation), so that poses read back from any engine are judged alike. Pairs whose
// bounding circles / spheres are apart are skipped; two static bodies are never compared.
inline double deepest_overlap(const Scene& scene, const std::vector<Body2>& bodies) {
    double deepest = 0.0;
    for (std::size_t i = 0; i < bodies.size(); ++i)
        for (std::size_t j = i + 1; j < bodies.size(); ++j) {
            const Body2 &a = bodies[i], &b = bodies[j];
            if (a.is_static && b.is_static) continue;
            const Shape2 &sa = scene.bodies[i].shape2, &sb = scene.bodies[j].shape2;
            if (!a.is_static && !b.is_static &&
                (a.position - b.position).norm() > bounding_radius(sa) + bounding_radius(sb))
                continue;
            const Manifold2 m =
                collide(sa, Pose2{a.position, a.angle}, sb, Pose2{b.position, b.angle});
            deepest = std::max(deepest, -m.separation);
        }
    return deepest;
}
inline double deepest_overlap(const Scene& scene, const std::vector<Body3>& bodies) {
    double deepest = 0.0;
    for (std::size_t i = 0; i < bodies.size(); ++i)
        for (std::size_t j = i + 1; j < bodies.size(); ++j) {
            const Body3 &a = bodies[i], &b = bodies[j];
            if (a.is_static && b.is_static) continue;
            const Shape3 &sa = scene.bodies[i].shape3, &sb = scene.bodies[j].shape3;
            if (!a.is_static && !b.is_static &&
                (a.position - b.position).norm() > bounding_radius(sa) + bounding_radius(sb))
                continue;
            const Manifold3 m = collide(sa, Pose3{a.position, a.orientation}, sb,
                                        Pose3{b.position, b.orientation});
            deepest = std::max(deepest, -m.separation);
        }
    return deepest;
}

// The fastest surface point's speed bound over the dynamic bodies (m/s): max |v| + |w| R,
// R the shape's bounding radius. Zero when everything is at rest.
inline double fastest_surface_speed(const Scene& scene, const std::vector<Body2>& bodies) {
    double fastest = 0.0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const Body2& b = bodies[i];
        if (b.is_static) continue;
        const double R = bounding_radius(scene.bodies[i].shape2);
        fastest = std::max(fastest, b.v.norm() + std::abs(b.w) * R);
    }
    return fastest;
}
inline double fastest_surface_speed(const Scene& scene, const std::vector<Body3>& bodies) {
    double fastest = 0.0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const Body3& b = bodies[i];
        if (b.is_static) continue;
        const double R = bounding_radius(scene.bodies[i].shape3);
        fastest = std::max(fastest, b.v.norm() + b.w.norm() * R);
    }
    return fastest;
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
