#include "render/frame_state.h"

#include <algorithm>

namespace collide::render {

double block_height(const Scene& scene, std::size_t i) {
    // Boxes as tall as 0.8 of the median block length (never taller than their own length),
    // so that carts of different lengths stand on the axis with a common look.
    std::vector<double> lengths;
    for (const SceneBody& b : scene.bodies) lengths.push_back(b.length);
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    const double median = lengths[lengths.size() / 2];
    return 0.8 * std::min(scene.bodies[i].length, median);
}

FrameState frame_state(const Scene& scene, double t, const std::vector<Body1>& bodies) {
    FrameState f;
    f.t = t;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        BodyState s;
        s.x = Vec3(bodies[i].position, 0.5 * block_height(scene, i), 0.0);
        s.v = Vec3(bodies[i].v, 0.0, 0.0);
        f.bodies.push_back(s);
    }
    return f;
}

FrameState frame_state(const Scene&, double t, const std::vector<Body2>& bodies) {
    FrameState f;
    f.t = t;
    for (const Body2& b : bodies) {
        BodyState s;
        s.x = Vec3(b.position.x(), b.position.y(), 0.0);
        s.angle = b.angle;
        s.q = Quat(Eigen::AngleAxisd(b.angle, Vec3::UnitZ()));
        s.v = Vec3(b.v.x(), b.v.y(), 0.0);
        s.w = Vec3(0.0, 0.0, b.w);
        f.bodies.push_back(s);
    }
    return f;
}

FrameState frame_state(const Scene&, double t, const std::vector<Body3>& bodies) {
    FrameState f;
    f.t = t;
    for (const Body3& b : bodies) {
        BodyState s;
        s.x = b.position;
        s.q = b.orientation;
        s.v = b.v;
        s.w = b.w;
        f.bodies.push_back(s);
    }
    return f;
}

ImpactMark impact_mark(const Scene& scene, const Event1& e) {
    ImpactMark m;
    m.t = e.t;
    m.a = e.a;
    m.b = e.b;
    const double h = std::min(block_height(scene, e.a), block_height(scene, e.b));
    // The blocks touch along a whole face; the point is drawn in its upper part, clear of the
    // centre line where the velocity arrows run.
    m.point = Vec3(e.point, 0.78 * h, 0.0);
    m.normal = Vec3::UnitX();  // a is the left block
    m.impulse = Vec3(e.impulse, 0.0, 0.0);
    return m;
}

ImpactMark impact_mark(const Scene&, const Event2& e) {
    ImpactMark m;
    m.t = e.t;
    m.a = e.a;
    m.b = e.b;
    m.point = Vec3(e.point.x(), e.point.y(), 0.0);
    m.normal = Vec3(e.normal.x(), e.normal.y(), 0.0);
    m.impulse = Vec3(e.impulse.x(), e.impulse.y(), 0.0);
    return m;
}

ImpactMark impact_mark(const Scene&, const Event3& e) {
    ImpactMark m;
    m.t = e.t;
    m.a = e.a;
    m.b = e.b;
    m.point = e.point;
    m.normal = e.normal;
    m.impulse = e.impulse;
    return m;
}

void add_trails(const std::vector<FrameState>& history, double span, FrameState* frame) {
    frame->trails.assign(frame->bodies.size(), {});
    const auto first = std::lower_bound(
        history.begin(), history.end(), frame->t - span,
        [](const FrameState& f, double t) { return f.t < t; });
    for (auto it = first; it != history.end() && it->t < frame->t; ++it)
        for (std::size_t i = 0; i < frame->bodies.size() && i < it->bodies.size(); ++i)
            frame->trails[i].push_back({it->t, it->bodies[i].x});
    for (std::size_t i = 0; i < frame->bodies.size(); ++i)
        frame->trails[i].push_back({frame->t, frame->bodies[i].x});
}

double kinetic_energy(const Scene& scene, std::size_t i, const BodyState& s) {
    const SceneBody& b = scene.bodies[i];
    if (b.is_static()) return 0.0;
    switch (scene.dimension) {
    case 1:
        return 0.5 * b.body1.mass * s.v.squaredNorm();
    case 2:
        return 0.5 * b.body2.mass * s.v.squaredNorm() + 0.5 * b.body2.inertia * s.w.z() * s.w.z();
    default: {
        const Mat3 R = s.q.toRotationMatrix();
        const Mat3 I = R * b.body3.inertia * R.transpose();
        return 0.5 * b.body3.mass * s.v.squaredNorm() + 0.5 * s.w.dot(I * s.w);
    }
    }
}

}  // namespace collide::render
