// Box2D 2.4.1 as an independent reference for 2D scenes: the bodies of a collide::Scene (the
// same shapes, masses, inertia, initial state and materials as collide's World<2>) stepped by
// Box2D at a fixed time step, with its collisions recorded as events. Box2D's own types stay
// inside box2d_world.cpp; this header speaks the engine's types (SI units, double).
//
// How a scene becomes a Box2D world (docs/commands/compare.md):
//   disc               b2CircleShape of the same radius;
//   rectangle, polygon b2PolygonShape with the same vertices (Box2D allows at most 8);
//   plane              a long two-sided b2EdgeShape on a static body (half-length kPlaneLength);
//   mass, inertia      b2Body::SetMassData with the centre of mass at the body origin, so that
//                      Box2D's mass and rotational inertia about the centre are ours (to float);
//   x, angle, v, w     the scene's initial state; gravity the scene's; no damping.
// Surfaces. Box2D rounds polygons and edges by a skin of b2_polygonRadius (0.01 m): contacts
// begin 0.01 m before the drawn surfaces meet, and its continuous collision (TOI) against static
// bodies needs that skin. So that both engines collide the same surfaces:
//   plane edges keep the skin but lie b2_polygonRadius behind the plane, so the skin's surface is
//     the plane itself (exact for discs and polygons);
//   static polygons are shrunk by the skin and keep it: the same faces, corners rounded by 1 cm;
//   dynamic polygons get no skin (m_radius = 0): their contacts begin at touch, as discs' do.
// Materials. matched (default): every contact gets collide's pair rules in PreSolve
//   (e = min(ea, eb), mu = sqrt(mua mub), 0 with the frictionless model) and a restitution
//   threshold of 0; box2d_defaults: the fixtures carry each body's e and mu and Box2D mixes them
//   itself (e = max, mu = sqrt of the product) with its default threshold of 1 m/s (approaches
//   slower than that do not bounce).
//
// Events. Box2D finds contacts discretely: at the start of each step from the poses of that
// instant (already overlapping by up to |v_rel| dt), or in a continuous-collision sub-step. A
// collision event is recorded when a contact gets a new manifold point (a contact that begins
// touching, or a new corner of a persisting one, keyed by Box2D's feature ids) whose bodies
// approach there faster than 2 |g| dt (slower is resting contact in Box2D: what gravity adds in
// two steps; with a restitution threshold of 0 a resting box keeps making such micro-bounces,
// Box2D's well-known jitter). Its "before" velocities are those at PreSolve, its "after" velocities those
// after the whole b2World::Step, its impulse the sum of PostSolve's normal and tangent impulses.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/scene.h"
#include "engine/world.h"

namespace collide::compare {

struct Box2DSettings {
    double dt = 1.0 / 600.0;      // s: Box2D's fixed step
    int velocity_iterations = 8;  // Box2D's recommended 8 and 3 (its manual)
    int position_iterations = 3;
    bool box2d_defaults = false;  // Box2D's threshold and mixing instead of collide's rules
    bool record_events = true;    // off for benchmarks
    bool allow_sleep = true;      // Box2D's default: bodies at rest for 0.5 s sleep
};

// Box2D 2.4.1's constants that explain differences (b2_common.h), in SI units.
constexpr double kBox2DThreshold = 1.0;          // m/s: b2FixtureDef::restitutionThreshold default
constexpr double kBox2DMaxTranslation = 2.0;     // m per step: b2_maxTranslation
constexpr double kBox2DMaxRotation = 0.5 * kPi;  // rad per step: b2_maxRotation
constexpr double kBox2DSkin = 0.01;              // m: b2_polygonRadius
constexpr int kBox2DMaxVertices = 8;             // b2_maxPolygonVertices
constexpr double kPlaneLength = 1.0e3;           // m: half-length of the edge standing for a plane

struct Box2DEvent {
    using Velocity = Event2::Velocity;
    double t = 0.0;              // s: start of the step whose solve applied the collision
    std::size_t step = 0;        // that step's index (t = step dt)
    bool continuous = false;     // found in a continuous-collision (TOI) sub-step of that step
    std::size_t a = 0, b = 0;    // scene body indices, a < b (as collide's events)
    Vec2 normal = Vec2::Zero();  // unit, from a into b: Box2D's manifold normal
    int points = 0;              // manifold points Box2D solved together (1 or 2)
    int others = 0;              // other touching contacts of its dynamic bodies in that step
                                 // (Box2D solves them together with this one, by iteration)
    double approach = 0.0;       // m/s: the largest approach speed -un of a new point, with the
                                 // velocities Box2D's solver used (this step's gravity added)
    double restitution = 0.0;    // what the contact used
    double friction = 0.0;
    double threshold = 0.0;       // m/s
    Vec2 impulse = Vec2::Zero();  // N s on b (a receives -impulse): PostSolve, summed
    Velocity before_a{Vec2::Zero(), 0.0}, before_b{Vec2::Zero(), 0.0};
    Velocity after_a{Vec2::Zero(), 0.0}, after_b{Vec2::Zero(), 0.0};
};

// Why a scene cannot be run through Box2D, naming the body (empty for the scene) and the key.
struct Unsupported {
    std::string body;
    std::string key;
    std::string message;
};
std::optional<Unsupported> box2d_unsupported(const Scene& scene);

class Box2DWorld {
public:
    // Throws std::invalid_argument (with box2d_unsupported's message) for a scene it cannot run.
    Box2DWorld(const Scene& scene, const Box2DSettings& settings);
    ~Box2DWorld();
    Box2DWorld(const Box2DWorld&) = delete;
    Box2DWorld& operator=(const Box2DWorld&) = delete;

    const Scene& scene() const;
    const Box2DSettings& settings() const;
    double time() const;  // s: steps() dt
    std::size_t steps() const;

    // One b2World::Step of dt; appends the events it recorded (record_events) to `events`.
    void step(std::vector<Box2DEvent>* events);
    // Steps while the next step ends at or before t (to 1e-9 dt).
    void advance_to(double t, std::vector<Box2DEvent>* events);

    // Every body's state now, as the engine's bodies (mass and inertia from the scene).
    std::vector<Body2> bodies() const;

    // What Box2D holds for body i, read back from it (for tests): mass (kg, 0 when static) and
    // rotational inertia about the centre of mass (kg m^2).
    struct Mass {
        double mass = 0.0;
        double inertia = 0.0;
    };
    Mass mass_of(std::size_t i) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace collide::compare
