#include "compare/box2d_world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <box2d/box2d.h>

namespace collide::compare {

namespace {

b2Vec2 to_b2(const Vec2& v) { return b2Vec2(static_cast<float>(v.x()), static_cast<float>(v.y())); }
Vec2 from_b2(const b2Vec2& v) { return Vec2(v.x, v.y); }

double restitution_of(const Scene& s, std::size_t i) { return s.bodies[i].restitution.value_or(s.restitution); }
// The frictionless model ignores mu; Box2D then gets none either.
double friction_of(const Scene& s, std::size_t i) {
    if (s.model == Model::frictionless) return 0.0;
    return s.bodies[i].friction.value_or(s.friction);
}

// A convex counter-clockwise polygon moved inwards by `d` along every edge normal (the vertices
// where the shifted edge lines meet). Empty when an edge would vanish or turn round.
std::vector<Vec2> shrink(const Polygon& p, double d) {
    const int n = p.count;
    std::vector<Vec2> out;
    for (int j = 0; j < n; ++j) {
        const int i = (j + n - 1) % n;  // edge i ends at vertex j, edge j starts there
        const Vec2 &ni = p.normals[i], &nj = p.normals[j];
        const double ci = ni.dot(p.vertices[i]) - d, cj = nj.dot(p.vertices[j]) - d;
        const double det = ni.x() * nj.y() - ni.y() * nj.x();
        if (std::abs(det) < 1e-12) return {};
        out.emplace_back((ci * nj.y() - cj * ni.y()) / det, (ni.x() * cj - nj.x() * ci) / det);
    }
    for (int j = 0; j < n; ++j) {
        const Vec2 before = p.vertices[(j + 1) % n] - p.vertices[j];
        const Vec2 after = out[(j + 1) % n] - out[j];
        if (after.dot(before) <= 0.0 || after.norm() < 2.0 * b2_linearSlop) return {};
    }
    return out;
}

}  // namespace

std::optional<Unsupported> box2d_unsupported(const Scene& scene) {
    if (scene.dimension != 2)
        return Unsupported{"", "dimension",
                           "Box2D is a 2D engine: collide compare runs 2D scenes only (this one is " +
                               std::to_string(scene.dimension) + "D)"};
    for (const SceneBody& b : scene.bodies) {
        if (b.shape2.kind != Shape2::Kind::polygon) continue;
        const Polygon& p = b.shape2.polygon;
        if (p.count > kBox2DMaxVertices)
            return Unsupported{b.name, "vertices",
                               "Box2D polygons have at most " + std::to_string(kBox2DMaxVertices) +
                                   " vertices (b2_maxPolygonVertices); this one has " + std::to_string(p.count)};
        for (int k = 0; k < p.count; ++k)
            if ((p.vertices[(k + 1) % p.count] - p.vertices[k]).norm() < b2_linearSlop)
                return Unsupported{b.name, b.shape == "rectangle" ? "size" : "vertices",
                                   "Box2D welds vertices closer than b2_linearSlop (0.005 m); "
                                   "this polygon has a shorter edge"};
    }
    return std::nullopt;
}

// The Box2D world and the contact listener that applies the material rules and records events.
struct Box2DWorld::Impl final : b2ContactListener {
    Scene scene;
    Box2DSettings settings;
    b2World world;
    std::vector<b2Body*> body;  // per scene body
    std::size_t steps = 0;

    // Events of the step being taken.
    struct Open {
        b2Contact* contact;
        bool swapped;   // Box2D's fixture A is our body b
        b2Vec2 normal;  // Box2D's, from its A into its B, at PreSolve
        Box2DEvent event;
    };
    std::vector<Open> open;
    bool continuous_phase = false;  // a PostSolve of this step has been seen: later PreSolves
                                    // come from continuous-collision sub-steps
    double resting_speed = 0.0;     // m/s: 2 |g| dt, slower approaches are resting contact

    Impl(const Scene& s, const Box2DSettings& st)
        : scene(s), settings(st), world(b2Vec2(static_cast<float>(s.gravity.x()), static_cast<float>(s.gravity.y()))) {
        world.SetContactListener(this);
        resting_speed = 2.0 * s.gravity.norm() * st.dt;
        for (std::size_t i = 0; i < scene.bodies.size(); ++i) body.push_back(create(i));
    }

    static std::size_t index(b2Body* b) { return b->GetUserData().pointer; }

    b2Body* create(std::size_t i) {
        const SceneBody& sb = scene.bodies[i];
        const Body2& b = sb.body2;
        const Shape2& shape = sb.shape2;
        b2BodyDef def;
        def.type = b.is_static ? b2_staticBody : b2_dynamicBody;
        def.allowSleep = settings.allow_sleep;
        def.userData.pointer = i;
        if (shape.kind != Shape2::Kind::half_plane) {
            def.position = to_b2(b.position);  // the body origin is the centre of mass
            def.angle = static_cast<float>(b.angle);
            def.linearVelocity = to_b2(b.v);
            def.angularVelocity = static_cast<float>(b.w);
        }
        b2Body* body2 = world.CreateBody(&def);

        b2FixtureDef fd;
        fd.density = 1.0f;  // replaced by SetMassData below
        fd.restitution = static_cast<float>(restitution_of(scene, i));
        fd.friction = static_cast<float>(friction_of(scene, i));
        fd.restitutionThreshold = settings.box2d_defaults ? static_cast<float>(kBox2DThreshold) : 0.0f;

        b2CircleShape circle;
        b2PolygonShape polygon;
        b2EdgeShape edge;
        switch (shape.kind) {
            case Shape2::Kind::disc:
                circle.m_radius = static_cast<float>(shape.radius);
                fd.shape = &circle;
                break;
            case Shape2::Kind::polygon: {
                const Polygon& p = shape.polygon;
                std::vector<Vec2> v(p.vertices.begin(), p.vertices.begin() + p.count);
                float radius = 0.0f;  // dynamic polygons: no skin (see the header)
                if (b.is_static) {
                    const std::vector<Vec2> inner = shrink(p, kBox2DSkin);
                    if (!inner.empty()) v = inner;
                    radius = b2_polygonRadius;  // the skin brings the faces back where ours are
                }
                std::vector<b2Vec2> pts;
                for (const Vec2& x : v) pts.push_back(to_b2(x));
                polygon.Set(pts.data(), static_cast<int32>(pts.size()));
                polygon.m_radius = radius;
                fd.shape = &polygon;
                break;
            }
            case Shape2::Kind::half_plane: {
                // The edge lies one skin behind the plane; its skin's surface is the plane.
                const Vec2 n = shape.normal, t(-n.y(), n.x());
                const Vec2 p0 = (shape.offset - kBox2DSkin) * n;
                edge.SetTwoSided(to_b2(p0 - kPlaneLength * t), to_b2(p0 + kPlaneLength * t));
                fd.shape = &edge;
                break;
            }
        }
        body2->CreateFixture(&fd);
        if (!b.is_static) {
            b2MassData md;
            md.mass = static_cast<float>(b.mass);
            md.center.SetZero();
            md.I = static_cast<float>(b.inertia);  // about the origin = the centre of mass
            body2->SetMassData(&md);
        }
        return body2;
    }

    // Velocity of body `b` at world point p, as the solver of this step will see it: in the
    // discrete phase Box2D adds this step's gravity before solving.
    b2Vec2 point_velocity(const b2Body* b, const b2Vec2& p) const {
        b2Vec2 v = b->GetLinearVelocityFromWorldPoint(p);
        if (b->GetType() == b2_dynamicBody && !continuous_phase)
            v += static_cast<float>(settings.dt) * world.GetGravity();
        return v;
    }

    Box2DEvent::Velocity velocity(std::size_t i) const {
        return {from_b2(body[i]->GetLinearVelocity()), body[i]->GetAngularVelocity()};
    }

    void PreSolve(b2Contact* contact, const b2Manifold* old) override {
        b2Body* A = contact->GetFixtureA()->GetBody();
        b2Body* B = contact->GetFixtureB()->GetBody();
        const std::size_t ia = index(A), ib = index(B);
        if (!settings.box2d_defaults) {  // collide's pair rules, no threshold
            contact->SetRestitution(static_cast<float>(scene.pair_restitution(ia, ib)));
            contact->SetFriction(
                static_cast<float>(scene.model == Model::frictionless ? 0.0 : scene.pair_friction(ia, ib)));
            contact->SetRestitutionThreshold(0.0f);
        }
        if (!settings.record_events) return;

        const b2Manifold* m = contact->GetManifold();
        b2WorldManifold wm;
        contact->GetWorldManifold(&wm);
        double approach = 0.0;
        bool fresh = false;
        for (int k = 0; k < m->pointCount; ++k) {
            bool known = false;
            for (int q = 0; q < old->pointCount; ++q) known = known || old->points[q].id.key == m->points[k].id.key;
            if (known) continue;
            const b2Vec2 u = point_velocity(B, wm.points[k]) - point_velocity(A, wm.points[k]);
            const double un = b2Dot(u, wm.normal);
            if (un < -resting_speed) {
                fresh = true;
                approach = std::max(approach, -un);
            }
        }
        if (!fresh) return;
        for (const Open& o : open)
            if (o.contact == contact) return;  // this step already has it (a TOI re-evaluation)

        Open o;
        o.contact = contact;
        o.swapped = ia > ib;
        o.normal = wm.normal;
        Box2DEvent& e = o.event;
        e.step = steps;
        e.t = static_cast<double>(steps) * settings.dt;
        e.continuous = continuous_phase;
        e.a = std::min(ia, ib);
        e.b = std::max(ia, ib);
        e.normal = (o.swapped ? -1.0 : 1.0) * from_b2(wm.normal);
        e.points = m->pointCount;
        e.approach = approach;
        e.restitution = contact->GetRestitution();
        e.friction = contact->GetFriction();
        e.threshold = contact->GetRestitutionThreshold();
        e.before_a = velocity(e.a);
        e.before_b = velocity(e.b);
        open.push_back(o);
    }

    void PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) override {
        continuous_phase = true;
        for (Open& o : open) {
            if (o.contact != contact) continue;
            const b2Vec2 n = o.normal, t = b2Cross(n, 1.0f);  // Box2D's tangent
            b2Vec2 P(0.0f, 0.0f);                             // on Box2D's body B
            for (int k = 0; k < impulse->count; ++k)
                P += impulse->normalImpulses[k] * n + impulse->tangentImpulses[k] * t;
            o.event.impulse += (o.swapped ? -1.0 : 1.0) * from_b2(P);
        }
    }

    // Touching contacts other than c at c's dynamic bodies.
    static int other_contacts(b2Contact* c) {
        int n = 0;
        for (b2Body* b : {c->GetFixtureA()->GetBody(), c->GetFixtureB()->GetBody()}) {
            if (b->GetType() != b2_dynamicBody) continue;
            for (b2ContactEdge* e = b->GetContactList(); e; e = e->next)
                if (e->contact != c && e->contact->IsTouching()) ++n;
        }
        return n;
    }

    void step(std::vector<Box2DEvent>* events) {
        open.clear();
        continuous_phase = false;
        world.Step(static_cast<float>(settings.dt), settings.velocity_iterations, settings.position_iterations);
        ++steps;
        for (Open& o : open) {
            o.event.after_a = velocity(o.event.a);
            o.event.after_b = velocity(o.event.b);
            o.event.others = other_contacts(o.contact);
            if (events) events->push_back(o.event);
        }
        open.clear();
    }
};

Box2DWorld::Box2DWorld(const Scene& scene, const Box2DSettings& settings) {
    if (const auto why = box2d_unsupported(scene))
        throw std::invalid_argument((why->body.empty() ? "" : "body \"" + why->body + "\": ") + why->key + ": " +
                                    why->message);
    if (!(settings.dt > 0.0)) throw std::invalid_argument("dt must be positive");
    impl_ = std::make_unique<Impl>(scene, settings);
}

Box2DWorld::~Box2DWorld() = default;

const Scene& Box2DWorld::scene() const { return impl_->scene; }
const Box2DSettings& Box2DWorld::settings() const { return impl_->settings; }
std::size_t Box2DWorld::steps() const { return impl_->steps; }
double Box2DWorld::time() const { return static_cast<double>(impl_->steps) * impl_->settings.dt; }

void Box2DWorld::step(std::vector<Box2DEvent>* events) { impl_->step(events); }

void Box2DWorld::advance_to(double t, std::vector<Box2DEvent>* events) {
    const double dt = impl_->settings.dt;
    while (static_cast<double>(impl_->steps + 1) * dt <= t + 1e-9 * dt) impl_->step(events);
}

std::vector<Body2> Box2DWorld::bodies() const {
    std::vector<Body2> out;
    for (std::size_t i = 0; i < impl_->scene.bodies.size(); ++i) {
        Body2 b = impl_->scene.bodies[i].body2;
        const b2Body* x = impl_->body[i];
        if (!b.is_static) {
            b.position = from_b2(x->GetPosition());
            b.angle = x->GetAngle();
            b.v = from_b2(x->GetLinearVelocity());
            b.w = x->GetAngularVelocity();
        }
        out.push_back(b);
    }
    return out;
}

Box2DWorld::Mass Box2DWorld::mass_of(std::size_t i) const {
    const b2Body* x = impl_->body.at(i);
    // GetInertia is about the body origin, which is the centre of mass (see create()).
    return {x->GetMass(), x->GetInertia()};
}

}  // namespace collide::compare
