#include "compare/match.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace collide::compare {

namespace {

constexpr double kDegrees = 180.0 / kPi;

std::string short_number(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
}

std::pair<Velocity, Velocity> after(const Event2& e) { return {e.after_a, e.after_b}; }
std::pair<Velocity, Velocity> before(const Event2& e) { return {e.before_a, e.before_b}; }
std::pair<Velocity, Velocity> after(const Box2DEvent& e) { return {e.after_a, e.after_b}; }
std::pair<Velocity, Velocity> before(const Box2DEvent& e) { return {e.before_a, e.before_b}; }

// Box2D clamps a body's motion per step to b2_maxTranslation and b2_maxRotation: a reason
// naming the limit, or empty.
std::string speed_cap(const Scene& scene, const Comparison& c, double dt) {
    std::vector<std::pair<Velocity, Velocity>> states;
    if (c.collide) states = {before(*c.collide), after(*c.collide)};
    if (c.box2d) states.push_back(before(*c.box2d));
    for (const auto& [va, vb] : states)
        for (const auto& [i, u] : {std::pair{c.a, va}, std::pair{c.b, vb}}) {
            if (scene.bodies[i].is_static()) continue;
            if (u.v.norm() * dt > kBox2DMaxTranslation)
                return "speed cap (Box2D moves a body at most b2_maxTranslation = 2 m per step: "
                       "|v| <= " +
                       short_number(kBox2DMaxTranslation / dt) + " m/s at this dt; " + scene.bodies[i].name + " has " +
                       short_number(u.v.norm()) + " m/s)";
            if (std::abs(u.w) * dt > kBox2DMaxRotation)
                return "speed cap (Box2D turns a body at most b2_maxRotation = pi/2 per step: "
                       "|w| <= " +
                       short_number(kBox2DMaxRotation / dt) + " rad/s at this dt; " + scene.bodies[i].name + " has " +
                       short_number(std::abs(u.w)) + " rad/s)";
        }
    return "";
}

// A possible cause of a difference and its estimated size (relative, as the difference);
// size < 0: always named (no estimate), `only_if_unexplained`: named when the estimated
// causes leave most of the difference unexplained.
struct Cause {
    double size = -1.0;
    std::string text;
    bool only_if_unexplained = false;
};

void explain(const Scene& scene, const Box2DSettings& settings, Comparison* c) {
    if (!c->collide || !c->box2d) {
        c->reason = "no matching event";
        return;
    }
    const double difference = *c->difference;
    if (difference <= kAgree) return;
    const Event2& ours = *c->collide;
    const Box2DEvent& theirs = *c->box2d;
    const std::vector<double> radii = lever_radii(scene);
    const double scale = velocity_scale(radii, c->a, c->b, {before(ours), after(ours), before(theirs), after(theirs)});
    const double e = scene.pair_restitution(c->a, c->b);
    const Vec2 g = scene.gravity.head<2>();
    const double un = (ours.before_b.v - ours.before_a.v).dot(ours.normal);  // centres only
    const bool suppressed = theirs.threshold > 0.0 && theirs.approach < theirs.threshold && theirs.restitution > 0.0;

    std::vector<Cause> causes;
    // The causes with no estimate of their size: always named, or named only when the
    // estimated ones leave most of the difference unexplained.
    const auto always = [&](std::string text) { causes.push_back({-1.0, std::move(text), false}); };
    const auto if_unexplained = [&](std::string text) { causes.push_back({-1.0, std::move(text), true}); };
    const std::string cap = speed_cap(scene, *c, settings.dt);
    if (!cap.empty()) always(cap);
    if (scene.model == Model::matrix || scene.model == Model::stick)
        always(std::string("model (collide's ") + model_name(scene.model) + "; Box2D has Coulomb friction only)");
    if (theirs.points == 2 && scene.policy == Policy::sequential)
        always(
            "two-point contact (Box2D's block solver solved both points together; collide's sequential policy "
            "one at a time)");
    if (suppressed)
        causes.push_back({e * theirs.approach / scale,
                          "restitution threshold (approach " + short_number(theirs.approach) + " m/s < " +
                              short_number(theirs.threshold) + " m/s: Box2D does not bounce)"});
    if (std::abs(theirs.restitution - e) > 1e-6)
        causes.push_back({std::abs(theirs.restitution - e) * theirs.approach / scale,
                          "restitution mixing (Box2D e = " + short_number(theirs.restitution) +
                              ", the larger; collide e = " + short_number(e) + ", the smaller)"});
    if (!suppressed && theirs.restitution > 0.0 && g.norm() > 0.0)
        causes.push_back({theirs.restitution * std::abs(g.dot(theirs.normal)) * settings.dt / scale,
                          "step gravity (Box2D adds this step's g dt = " + short_number(g.norm() * settings.dt) +
                              " m/s before it applies restitution)"});
    causes.push_back({(1.0 + e) * *c->difference_before,
                      "velocities before differ (by " + short_number(*c->difference_before) + "; Box2D's step began " +
                          short_number(std::abs(theirs.t - ours.t) * 1e3) + " ms " +
                          (theirs.t <= ours.t ? "before" : "after") + " collide's instant)"});
    if (*c->normal_degrees > kNormalDegrees)
        causes.push_back({(1.0 + e) * std::abs(un) * std::sin(*c->normal_degrees / kDegrees) / scale,
                          "normal off by " + short_number(*c->normal_degrees) + " degrees"});
    if (theirs.points == 2 && scene.policy == Policy::simultaneous)
        if_unexplained("two-point contact (Box2D had two manifold points)");
    if (theirs.others > 0)
        if_unexplained("other contacts in the same step (Box2D solves this one with " + std::to_string(theirs.others) +
                       " more together, by iteration; collide resolves each at its own instant)");
    if (theirs.friction > 0.0)
        if_unexplained("friction (Box2D iterates Coulomb friction per point, " +
                       std::to_string(settings.velocity_iterations) +
                       " velocity iterations, against the slip as it ends; collide's one-step model against the "
                       "slip before)");

    // Named: the causes without an estimate, then the estimated ones that matter, largest
    // first; then, if those leave most of it unexplained, the conditional ones.
    std::vector<const Cause*> named;
    double explained = 0.0;
    for (const Cause& k : causes)
        if (k.size < 0.0 && !k.only_if_unexplained) named.push_back(&k);
    std::vector<const Cause*> sized;
    for (const Cause& k : causes)
        if (k.size >= 0.0 && k.size >= std::max(0.5 * kAgree, 0.1 * difference)) sized.push_back(&k);
    std::stable_sort(sized.begin(), sized.end(), [](const Cause* x, const Cause* y) { return x->size > y->size; });
    for (const Cause* k : sized) {
        named.push_back(k);
        explained += k->size;
    }
    if (named.empty() || difference - explained > std::max(kAgree, 0.5 * difference))
        for (const Cause& k : causes)
            if (k.only_if_unexplained) named.push_back(&k);
    if (named.empty()) {
        c->reason = "unexplained";
        return;
    }
    for (const Cause* k : named) {
        if (!c->reason.empty()) c->reason += "; ";
        c->reason += k->text;
        if (k->size >= 0.0) c->reason += " [~" + short_number(k->size) + "]";
    }
}

}  // namespace

std::vector<double> lever_radii(const Scene& scene) {
    std::vector<double> r;
    for (const SceneBody& b : scene.bodies) r.push_back(b.is_static() ? 0.0 : bounding_radius(b.shape2));
    return r;
}

double velocity_scale(const std::vector<double>& radii, std::size_t a, std::size_t b,
                      const std::vector<std::pair<Velocity, Velocity>>& states) {
    double s = 0.0;
    for (const auto& [va, vb] : states) {
        s = std::max({s, va.v.norm(), radii[a] * std::abs(va.w)});
        s = std::max({s, vb.v.norm(), radii[b] * std::abs(vb.w)});
    }
    return s;
}

double velocity_difference(const std::vector<double>& radii, std::size_t a, std::size_t b,
                           const std::pair<Velocity, Velocity>& one, const std::pair<Velocity, Velocity>& two,
                           double scale) {
    if (!(scale > 0.0)) return 0.0;
    auto gap = [&](std::size_t i, const Velocity& x, const Velocity& y) {
        return std::max((x.v - y.v).norm(), radii[i] * std::abs(x.w - y.w));
    };
    return std::max(gap(a, one.first, two.first), gap(b, one.second, two.second)) / scale;
}

std::vector<Comparison> match_events(const Scene& scene, const Box2DSettings& settings, const std::vector<Event2>& ours,
                                     const std::vector<Box2DEvent>& theirs) {
    using Key = std::pair<std::size_t, std::size_t>;
    std::map<Key, std::vector<const Event2*>> by_pair_ours;
    std::map<Key, std::vector<const Box2DEvent*>> by_pair_theirs;
    for (const Event2& e : ours) by_pair_ours[{std::min(e.a, e.b), std::max(e.a, e.b)}].push_back(&e);
    for (const Box2DEvent& e : theirs) by_pair_theirs[{e.a, e.b}].push_back(&e);
    std::map<Key, int> keys;
    for (const auto& kv : by_pair_ours) keys[kv.first] = 0;
    for (const auto& kv : by_pair_theirs) keys[kv.first] = 0;

    const std::vector<double> radii = lever_radii(scene);
    std::vector<Comparison> out;
    for (const auto& kv : keys) {
        const Key key = kv.first;
        const auto& x = by_pair_ours[key];
        const auto& y = by_pair_theirs[key];
        for (std::size_t k = 0; k < std::max(x.size(), y.size()); ++k) {
            Comparison c;
            c.a = key.first;
            c.b = key.second;
            if (k < x.size()) {
                c.collide = *x[k];
                if (c.collide->a > c.collide->b) {  // as Box2D's: a < b, the normal from a
                    std::swap(c.collide->a, c.collide->b);
                    std::swap(c.collide->before_a, c.collide->before_b);
                    std::swap(c.collide->after_a, c.collide->after_b);
                    c.collide->normal = -c.collide->normal;
                    c.collide->impulse = -c.collide->impulse;
                }
            }
            if (k < y.size()) c.box2d = *y[k];
            if (c.collide && c.box2d) {
                const double scale = velocity_scale(
                    radii, c.a, c.b, {before(*c.collide), after(*c.collide), before(*c.box2d), after(*c.box2d)});
                c.difference = velocity_difference(radii, c.a, c.b, after(*c.collide), after(*c.box2d), scale);
                c.difference_before = velocity_difference(radii, c.a, c.b, before(*c.collide), before(*c.box2d), scale);
                const Vec2 &n1 = c.collide->normal, &n2 = c.box2d->normal;
                c.normal_degrees = std::atan2(std::abs(cross(n1, n2)), n1.dot(n2)) * kDegrees;
            }
            explain(scene, settings, &c);
            out.push_back(std::move(c));
        }
    }
    auto when = [](const Comparison& c) { return c.collide ? c.collide->t : c.box2d->t; };
    std::stable_sort(out.begin(), out.end(), [&](const Comparison& p, const Comparison& q) {
        return when(p) != when(q) ? when(p) < when(q) : (p.a != q.a ? p.a < q.a : p.b < q.b);
    });
    return out;
}

}  // namespace collide::compare
