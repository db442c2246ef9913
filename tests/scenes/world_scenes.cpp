// The scenes of tests/scenes/world_scenes.h.
#include "tests/scenes/world_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "engine/diagnostics.h"
#include "engine/mass.h"
#include "engine/space.h"

namespace collide::scenes {

namespace {

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

// A body of the scene: its name, its shape and its state (Body2, Body3) in the fields of its
// dimension.
void place(SceneBody* b, const Shape2& s, const Body2& body) {
    b->shape2 = s;
    b->body2 = body;
}
void place(SceneBody* b, const Shape3& s, const Body3& body) {
    b->shape3 = s;
    b->body3 = body;
}
template <class Shape, class Body>
SceneBody scene_body(const std::string& name, const char* shape, const Shape& s, const Body& body) {
    SceneBody b;
    b.name = name;
    b.shape = shape;
    place(&b, s, body);
    return b;
}

}  // namespace

Scene empty_scene(int dimension, Policy policy, double e, const Vec3& gravity) {
    Scene s;
    s.dimension = dimension;
    s.policy = policy;
    s.restitution = e;
    s.gravity = gravity;
    s.model = Model::frictionless;
    s.friction = 0.0;
    return s;
}

SceneBody disc(const std::string& name, double radius, double mass, const Vec2& x, const Vec2& v, double w,
               double angle) {
    // Body2 and Body3 are filled in the order of their members.
    const double inertia = disc_inertia_2d(mass, radius);
    return scene_body(name, "disc", Shape2::disc(radius), Body2{mass, false, inertia, angle, x, v, w});
}

SceneBody rectangle(const std::string& name, double width, double height, double mass, const Vec2& x, double angle,
                    const Vec2& v, double w) {
    const double inertia = rectangle_inertia_2d(mass, width, height);
    return scene_body(name, "rectangle", Shape2::rectangle(width, height), Body2{mass, false, inertia, angle, x, v, w});
}

SceneBody half_plane(const std::string& name, const Vec2& n, double offset) {
    SceneBody b;
    b.name = name;
    b.shape = "plane";
    b.shape2 = Shape2::half_plane(n, offset);
    b.body2.is_static = true;
    return b;
}

SceneBody sphere(const std::string& name, double radius, double mass, const Vec3& x, const Vec3& v, const Vec3& w) {
    Shape3 s;
    s.kind = Shape3::Kind::sphere;
    s.radius = radius;
    return scene_body(name, "sphere", s, Body3{mass, false, sphere_inertia(mass, radius), Quat::Identity(), x, v, w});
}

SceneBody box(const std::string& name, const Vec3& half, double mass, const Vec3& x, const Quat& q, const Vec3& v,
              const Vec3& w) {
    Shape3 s;
    s.kind = Shape3::Kind::box;
    s.half = half;
    return scene_body(name, "box", s, Body3{mass, false, box_inertia(mass, 2.0 * half), q, x, v, w});
}

SceneBody half_space(const std::string& name, const Vec3& n, double offset) {
    SceneBody b;
    b.name = name;
    b.shape = "plane";
    b.shape3.kind = Shape3::Kind::half_space;
    b.shape3.normal = n;
    b.shape3.offset = offset;
    b.body3.is_static = true;
    return b;
}

void add_walls2(Scene* s, double L) {
    s->bodies.push_back(half_plane("left", Vec2(1, 0), 0.0));
    s->bodies.push_back(half_plane("right", Vec2(-1, 0), -L));
    s->bodies.push_back(half_plane("floor", Vec2(0, 1), 0.0));
    s->bodies.push_back(half_plane("ceiling", Vec2(0, -1), -L));
}

void add_walls3(Scene* s, double L) {
    const char* names[3][2] = {{"x0", "x1"}, {"y0", "y1"}, {"z0", "z1"}};
    for (int k = 0; k < 3; ++k) {
        s->bodies.push_back(half_space(names[k][0], Vec3::Unit(k), 0.0));
        s->bodies.push_back(half_space(names[k][1], -Vec3::Unit(k), -L));
    }
}

double gas_box_size(int dimension, const GasSpec& g) {
    const double body = dimension == 2 ? kPi * g.radius * g.radius : 4.0 / 3.0 * kPi * g.radius * g.radius * g.radius;
    return std::pow(g.n * body / g.fraction, 1.0 / dimension);
}

Scene gas(int dimension, const GasSpec& g) {
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

Scene pile(int dimension, const PileSpec& p) {
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

Scene pyramid(const PyramidSpec& p) {
    Scene s = empty_scene(2, Policy::simultaneous, p.e, Vec3(0.0, -p.g, 0.0));
    s.model = Model::coulomb;
    s.friction = p.mu;
    s.bodies.push_back(half_plane("ground", Vec2(0, 1), 0.0));
    for (int k = 0; k < p.rows; ++k)
        for (int j = 0; j < p.rows - k; ++j) {
            const Vec2 x((k * 0.5 + j) * p.spacing, (k + 0.5) * p.size);
            s.bodies.push_back(rectangle("r" + std::to_string(k) + "b" + std::to_string(j), p.size, p.size, p.mass, x));
        }
    return s;
}

double bin_pitch(int dimension, const BinSpec& b) {
    return std::sqrt(static_cast<double>(dimension)) * b.max_side + 0.01;
}

int bin_columns(int dimension, const BinSpec& b) {
    if (b.columns > 0) return b.columns;
    const double c = dimension == 2 ? 2.0 * std::sqrt(static_cast<double>(b.n)) : std::cbrt(static_cast<double>(b.n));
    return std::max(1, static_cast<int>(std::ceil(c - 1e-9)));
}

double bin_width(int dimension, const BinSpec& b) { return bin_columns(dimension, b) * bin_pitch(dimension, b); }

Scene bin(int dimension, const BinSpec& b) {
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
            const double u1 = rng.uniform(0.0, 1.0), u2 = rng.uniform(0.0, 2.0 * kPi), u3 = rng.uniform(0.0, 2.0 * kPi);
            const double r1 = std::sqrt(1.0 - u1), r2 = std::sqrt(u1);
            const Quat q(r2 * std::cos(u3), r1 * std::sin(u2), r1 * std::cos(u2), r2 * std::sin(u3));
            const Vec3 x((i % c + 0.5) * pitch, (i / (c * c) + 0.5) * pitch, ((i / c) % c + 0.5) * pitch);
            s.bodies.push_back(box(name, 0.5 * size, b.density3 * size.prod(), x, q.normalized()));
        }
    }
    return s;
}

Scene tower3d(const TowerSpec& t) {
    Scene s = empty_scene(3, Policy::simultaneous, t.e, Vec3(0.0, -t.g, 0.0));
    s.model = Model::coulomb;
    s.friction = t.mu;
    s.bodies.push_back(half_space("ground", Vec3(0, 1, 0), 0.0));
    for (int i = 0; i < t.levels; ++i)
        s.bodies.push_back(
            box("box" + std::to_string(i), 0.5 * t.size, t.mass, Vec3(0.0, (i + 0.5) * t.size.y(), 0.0)));
    s.bodies.push_back(sphere("ball", t.ball_radius, t.ball_mass, t.ball_x, t.ball_v));
    return s;
}

namespace {

// A scene body's shape, as the dimension of the body asks.
const Shape2& shape_of(const SceneBody& b, const Body2&) { return b.shape2; }
const Shape3& shape_of(const SceneBody& b, const Body3&) { return b.shape3; }

template <class Body>
double deepest_overlap_of(const Scene& scene, const std::vector<Body>& bodies) {
    double deepest = 0.0;
    for (std::size_t i = 0; i < bodies.size(); ++i)
        for (std::size_t j = i + 1; j < bodies.size(); ++j) {
            const Body &a = bodies[i], &b = bodies[j];
            if (a.is_static && b.is_static) continue;
            const auto &sa = shape_of(scene.bodies[i], a), &sb = shape_of(scene.bodies[j], b);
            if (!a.is_static && !b.is_static &&
                (a.position - b.position).norm() > bounding_radius(sa) + bounding_radius(sb))
                continue;
            deepest = std::max(deepest, -collide(sa, pose_of(a), sb, pose_of(b)).separation);
        }
    return deepest;
}

template <class Body>
double fastest_surface_speed_of(const Scene& scene, const std::vector<Body>& bodies) {
    double fastest = 0.0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const Body& b = bodies[i];
        if (b.is_static) continue;
        const double R = bounding_radius(shape_of(scene.bodies[i], b));
        fastest = std::max(fastest, b.v.norm() + magnitude(b.w) * R);
    }
    return fastest;
}

}  // namespace

double deepest_overlap(const Scene& scene, const std::vector<Body2>& bodies) {
    return deepest_overlap_of(scene, bodies);
}
double deepest_overlap(const Scene& scene, const std::vector<Body3>& bodies) {
    return deepest_overlap_of(scene, bodies);
}
double fastest_surface_speed(const Scene& scene, const std::vector<Body2>& bodies) {
    return fastest_surface_speed_of(scene, bodies);
}
double fastest_surface_speed(const Scene& scene, const std::vector<Body3>& bodies) {
    return fastest_surface_speed_of(scene, bodies);
}

double kinetic_energy(const std::vector<Body2>& bodies) { return totals(bodies).kinetic_energy; }

double kinetic_energy(const std::vector<Body3>& bodies) { return totals(bodies).kinetic_energy; }

double potential_energy(const std::vector<Body2>& bodies, const Vec3& g) {
    double u = 0.0;
    for (const Body2& b : bodies)
        if (!b.is_static) u -= b.mass * g.head<2>().dot(b.position);
    return u;
}

double potential_energy(const std::vector<Body3>& bodies, const Vec3& g) {
    double u = 0.0;
    for (const Body3& b : bodies)
        if (!b.is_static) u -= b.mass * g.dot(b.position);
    return u;
}

}  // namespace collide::scenes
