// Bullet 3.24 as a 3D benchmark peer: the bodies of a collide::Scene (the same shapes, masses,
// inertia, initial state and materials as collide's World<3>) stepped by Bullet's
// btDiscreteDynamicsWorld at a fixed time step. Only collide-bench and its tests link it (not
// the collide library or command); Bullet's own types stay inside bullet_world.cpp, and this
// header speaks the engine's types (SI units, double). Debian's default Bullet build computes
// in float, like Box2D.
//
// How a scene becomes a Bullet world:
//   sphere             btSphereShape of the same radius;
//   box                btBoxShape of the same half extents (Bullet's collision margin lies
//                      inside a box, so its faces are ours; box-box and box-plane contacts use
//                      Bullet's exact box algorithms);
//   half-space         btStaticPlaneShape(n, offset): solid where n . p <= offset, as ours;
//   mass, inertia      Bullet's mass and principal moments in the body frame: the scene's
//                      (a body whose inertia tensor is not diagonal in its body frame is refused);
//   x, orientation, v, w  the scene's initial state; gravity the scene's; no damping.
// Materials. Bullet combines a pair's friction and restitution by multiplying the two bodies'
// values (btManifoldResult::calculateCombinedFriction / Restitution). Each body gets the square
// root of its value: the pair's friction is then sqrt(mu_a mu_b), collide's rule exactly, and
// its restitution sqrt(e_a e_b), which is collide's min(e_a, e_b) only when the two are equal,
// so scenes whose bodies' restitutions differ are refused. The frictionless model gives 0.
// Bullet drops restitution below a relative speed of 0.2 m/s by default
// (btContactSolverInfo::m_restitutionVelocityThreshold); like `collide compare`'s matched
// Box2D, the peer sets it to 0, collide having no such threshold (BulletSettings).
// Everything else is Bullet's default: 10 solver iterations, split impulse, warm starting,
// bodies at rest for 2 s falling asleep, no continuous collision.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/scene.h"

namespace collide::compare {

struct BulletSettings {
    double dt = 1.0 / 600.0;             // s: Bullet's fixed step
    double restitution_threshold = 0.0;  // m/s: Bullet's own default is 0.2
    bool allow_sleep = true;             // Bullet's default: bodies at rest for 2 s sleep
};

// Why a scene cannot be run through Bullet, or nothing.
std::optional<std::string> bullet_unsupported(const Scene& scene);

// What Bullet holds for one body (read back from it, for tests).
struct BulletMass {
    double mass = 0.0;            // kg (0: static)
    Vec3 inertia = Vec3::Zero();  // kg m^2: principal moments about the body axes
};
struct BulletMaterial {
    double friction = 0.0;  // the pair's combined values, as Bullet's solver uses them
    double restitution = 0.0;
};

class BulletWorld {
public:
    // Throws std::invalid_argument (with bullet_unsupported's message) for a scene it cannot run.
    BulletWorld(const Scene& scene, const BulletSettings& settings);
    ~BulletWorld();
    BulletWorld(const BulletWorld&) = delete;
    BulletWorld& operator=(const BulletWorld&) = delete;

    const Scene& scene() const;
    double time() const;  // s: steps() dt
    std::size_t steps() const;

    // One fixed step of dt: stepSimulation(dt, 1, dt).
    void step();
    // Steps while the next step ends at or before t (to 1e-9 dt).
    void advance_to(double t);

    // Every body's state now, as the engine's bodies (mass and inertia from the scene).
    std::vector<Body3> bodies() const;

    BulletMass mass_of(std::size_t i) const;
    BulletMaterial material_of(std::size_t i, std::size_t j) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace collide::compare
