#include "compare/bullet_world.h"

#include <cmath>
#include <stdexcept>

#include <btBulletDynamicsCommon.h>

namespace collide::compare {

namespace {

btVector3 to_bt(const Vec3& v) {
    return btVector3(static_cast<btScalar>(v.x()), static_cast<btScalar>(v.y()), static_cast<btScalar>(v.z()));
}
Vec3 from_bt(const btVector3& v) { return Vec3(v.x(), v.y(), v.z()); }
btQuaternion to_bt(const Quat& q) {  // Bullet's order is x, y, z, w
    return btQuaternion(static_cast<btScalar>(q.x()), static_cast<btScalar>(q.y()), static_cast<btScalar>(q.z()),
                        static_cast<btScalar>(q.w()));
}
Quat from_bt(const btQuaternion& q) { return Quat(q.w(), q.x(), q.y(), q.z()); }

double restitution_of(const Scene& s, std::size_t i) { return s.bodies[i].restitution.value_or(s.restitution); }
double friction_of(const Scene& s, std::size_t i) {
    if (s.model == Model::frictionless) return 0.0;
    return s.bodies[i].friction.value_or(s.friction);
}

}  // namespace

std::optional<std::string> bullet_unsupported(const Scene& scene) {
    if (scene.dimension != 3)
        return "Bullet runs 3D scenes only (this one is " + std::to_string(scene.dimension) + "D)";
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const SceneBody& b = scene.bodies[i];
        if (restitution_of(scene, i) != restitution_of(scene, 0))
            return "body \"" + b.name +
                   "\": restitution: Bullet multiplies the bodies' values, "
                   "which gives collide's min(e_a, e_b) only when every body's is the same";
        if (b.body3.is_static) continue;
        const Mat3& I = b.body3.inertia;
        if (I(0, 1) != 0.0 || I(0, 2) != 0.0 || I(1, 2) != 0.0 || I(1, 0) != 0.0 || I(2, 0) != 0.0 || I(2, 1) != 0.0)
            return "body \"" + b.name +
                   "\": inertia: Bullet takes principal moments about the "
                   "body axes; this tensor is not diagonal there";
    }
    return std::nullopt;
}

// Owners in construction order: the world is declared last, so it is destroyed first, while
// the bodies, shapes and its helpers still exist.
struct BulletWorld::Impl {
    Scene scene;
    BulletSettings settings;
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    std::vector<std::unique_ptr<btCollisionShape>> shapes;  // per scene body
    std::vector<std::unique_ptr<btRigidBody>> body;         // per scene body
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
    std::size_t steps = 0;

    Impl(const Scene& s, const BulletSettings& st) : scene(s), settings(st) {
        world.setGravity(to_bt(s.gravity));
        world.getSolverInfo().m_restitutionVelocityThreshold = static_cast<btScalar>(st.restitution_threshold);
        for (std::size_t i = 0; i < scene.bodies.size(); ++i) create(i);
    }

    ~Impl() {
        for (auto& b : body) world.removeRigidBody(b.get());
    }

    void create(std::size_t i) {
        const SceneBody& sb = scene.bodies[i];
        const Body3& b = sb.body3;
        const Shape3& shape = sb.shape3;
        switch (shape.kind) {
            case Shape3::Kind::sphere:
                shapes.push_back(std::make_unique<btSphereShape>(static_cast<btScalar>(shape.radius)));
                break;
            case Shape3::Kind::box: shapes.push_back(std::make_unique<btBoxShape>(to_bt(shape.half))); break;
            case Shape3::Kind::half_space:
                shapes.push_back(
                    std::make_unique<btStaticPlaneShape>(to_bt(shape.normal), static_cast<btScalar>(shape.offset)));
                break;
        }
        const btScalar mass = b.is_static ? 0.0f : static_cast<btScalar>(b.mass);
        const btVector3 inertia = b.is_static ? btVector3(0, 0, 0) : to_bt(Vec3(b.inertia.diagonal()));
        btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shapes.back().get(), inertia);
        // A half-space's pose is ignored (the plane is in world coordinates).
        if (shape.kind != Shape3::Kind::half_space)
            info.m_startWorldTransform = btTransform(to_bt(b.orientation), to_bt(b.position));
        // Bullet multiplies the two bodies' values: each gets the square root (see the header).
        info.m_friction = static_cast<btScalar>(std::sqrt(friction_of(scene, i)));
        info.m_restitution = static_cast<btScalar>(std::sqrt(restitution_of(scene, i)));
        info.m_linearDamping = 0.0f;
        info.m_angularDamping = 0.0f;
        body.push_back(std::make_unique<btRigidBody>(info));
        btRigidBody* rb = body.back().get();
        if (!b.is_static) {
            rb->setLinearVelocity(to_bt(b.v));
            rb->setAngularVelocity(to_bt(b.w));
            if (!settings.allow_sleep) rb->setActivationState(DISABLE_DEACTIVATION);
        }
        world.addRigidBody(rb);
    }
};

BulletWorld::BulletWorld(const Scene& scene, const BulletSettings& settings) {
    if (const auto why = bullet_unsupported(scene)) throw std::invalid_argument(*why);
    if (!(settings.dt > 0.0)) throw std::invalid_argument("dt must be positive");
    impl_ = std::make_unique<Impl>(scene, settings);
}

BulletWorld::~BulletWorld() = default;

const Scene& BulletWorld::scene() const { return impl_->scene; }
std::size_t BulletWorld::steps() const { return impl_->steps; }
double BulletWorld::time() const { return static_cast<double>(impl_->steps) * impl_->settings.dt; }

void BulletWorld::step() {
    const btScalar dt = static_cast<btScalar>(impl_->settings.dt);
    impl_->world.stepSimulation(dt, 1, dt);
    ++impl_->steps;
}

void BulletWorld::advance_to(double t) {
    const double dt = impl_->settings.dt;
    while (static_cast<double>(impl_->steps + 1) * dt <= t + 1e-9 * dt) step();
}

std::vector<Body3> BulletWorld::bodies() const {
    std::vector<Body3> out;
    for (std::size_t i = 0; i < impl_->scene.bodies.size(); ++i) {
        Body3 b = impl_->scene.bodies[i].body3;
        if (!b.is_static) {
            const btRigidBody* x = impl_->body[i].get();
            const btTransform& pose = x->getCenterOfMassTransform();
            b.position = from_bt(pose.getOrigin());
            b.orientation = from_bt(pose.getRotation()).normalized();
            b.v = from_bt(x->getLinearVelocity());
            b.w = from_bt(x->getAngularVelocity());
        }
        out.push_back(b);
    }
    return out;
}

BulletMass BulletWorld::mass_of(std::size_t i) const {
    const btRigidBody* x = impl_->body.at(i).get();
    BulletMass m;
    if (x->getInvMass() == 0.0f) return m;
    m.mass = 1.0 / static_cast<double>(x->getInvMass());
    m.inertia = from_bt(x->getLocalInertia());
    return m;
}

BulletMaterial BulletWorld::material_of(std::size_t i, std::size_t j) const {
    const btRigidBody *a = impl_->body.at(i).get(), *b = impl_->body.at(j).get();
    return {btManifoldResult::calculateCombinedFriction(a, b), btManifoldResult::calculateCombinedRestitution(a, b)};
}

}  // namespace collide::compare
