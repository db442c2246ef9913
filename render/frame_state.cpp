#include "render/frame_state.h"

#include <algorithm>
#include <functional>
#include <type_traits>

#include "engine/diagnostics.h"

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
        BodyState s = lifted(bodies[i]);
        s.x.y() = 0.5 * block_height(scene, i);  // standing on the x axis
        f.bodies.push_back(s);
    }
    return f;
}

template <class Body>
FrameState frame_state_of(double t, const std::vector<Body>& bodies) {
    FrameState f;
    f.t = t;
    for (const Body& b : bodies) f.bodies.push_back(lifted(b));
    return f;
}

FrameState frame_state(const Scene&, double t, const std::vector<Body2>& bodies) { return frame_state_of(t, bodies); }
FrameState frame_state(const Scene&, double t, const std::vector<Body3>& bodies) { return frame_state_of(t, bodies); }

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

template <int D>
ImpactMark impact_mark_of(const Event<D>& e) {
    ImpactMark m;
    static_cast<LiftedEvent&>(m) = lifted(e);
    return m;
}

double motion_label_floor(std::vector<double> sizes) {
    if (sizes.size() <= kFewBodies) return 0.0;
    std::sort(sizes.begin(), sizes.end(), std::greater<double>());
    const double fraction = kShownMotionFraction * sizes.front();
    return sizes.size() <= kQuietBodies ? fraction : std::max(fraction, sizes[kMaxMotionLabels - 1]);
}

std::vector<bool> motion_labels(const std::vector<double>& sizes, const std::vector<bool>& first) {
    const double floor = motion_label_floor(sizes);
    std::vector<std::size_t> order(sizes.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    const auto is_first = [&](std::size_t k) { return k < first.size() && first[k]; };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (is_first(a) != is_first(b)) return is_first(a);
        return sizes[a] > sizes[b];
    });
    std::vector<bool> out(sizes.size(), false);
    std::size_t given = 0;
    const std::size_t budget = motion_label_budget(sizes.size());
    for (std::size_t k : order)
        if (given < budget && motion_labelled(sizes[k], floor)) {
            out[k] = true;
            ++given;
        }
    return out;
}

FrameMotionLabels motion_labels(const FrameState& frame, const std::vector<bool>& counted) {
    const std::size_t n = std::min(frame.bodies.size(), counted.size());
    std::vector<bool> in_impact(n, false), first;
    for (const ImpactMark& im : frame.impacts)
        if (im.a < n && im.b < n) in_impact[im.a] = in_impact[im.b] = true;
    std::vector<double> speeds, spins;
    for (std::size_t i = 0; i < n; ++i)
        if (counted[i]) {
            speeds.push_back(frame.bodies[i].v.norm());
            spins.push_back(frame.bodies[i].w.norm());
            first.push_back(in_impact[i]);
        }
    const std::vector<bool> speed = motion_labels(speeds, first), spin = motion_labels(spins, first);
    FrameMotionLabels out;
    out.speed.assign(n, false);
    out.spin.assign(n, false);
    out.count = speeds.size();
    for (std::size_t i = 0, k = 0; i < n; ++i)
        if (counted[i]) {
            out.speed[i] = speed[k];
            out.spin[i] = spin[k];
            ++k;
        }
    return out;
}

TableRows table_rows(const std::vector<std::size_t>& moving, const std::vector<double>& kinetic,
                     const FrameState& frame, std::size_t rows) {
    TableRows out;
    if (moving.size() <= rows) {
        out.shown = moving;
        return out;
    }
    const std::size_t room = rows > 0 ? rows - 1 : 0;  // one line goes to the others
    std::vector<bool> is_moving(frame.bodies.size(), false), taken(frame.bodies.size(), false);
    for (std::size_t i : moving) is_moving[i] = true;
    const auto take = [&](std::size_t i) {
        if (out.shown.size() < room && i < taken.size() && is_moving[i] && !taken[i]) {
            taken[i] = true;
            out.shown.push_back(i);
        }
    };
    // The two bodies of the frame's largest collision (the first of equals).
    const ImpactMark* largest = nullptr;
    for (const ImpactMark& m : frame.impacts)
        if (!largest || m.impulse.norm() > largest->impulse.norm()) largest = &m;
    if (largest) take(largest->b), take(largest->a);
    // Then the most kinetic energy.
    std::vector<std::size_t> by_energy = moving;
    std::stable_sort(by_energy.begin(), by_energy.end(),
                     [&](std::size_t x, std::size_t y) { return kinetic[x] > kinetic[y]; });
    for (std::size_t i : by_energy) take(i);
    std::sort(out.shown.begin(), out.shown.end());
    for (std::size_t i : moving) {
        if (taken[i]) continue;
        ++out.others;
        out.others_speed = std::max(out.others_speed, frame.bodies[i].v.norm());
        out.others_spin = std::max(out.others_spin, frame.bodies[i].w.norm());
    }
    return out;
}

ImpactMark impact_mark(const Scene&, const Event2& e) { return impact_mark_of(e); }
ImpactMark impact_mark(const Scene&, const Event3& e) { return impact_mark_of(e); }

std::vector<ImpactMark> shown_impacts(std::vector<ImpactMark> impacts) {
    if (impacts.size() <= 1) return impacts;
    double largest = 0.0;
    for (const ImpactMark& m : impacts) largest = std::max(largest, m.impulse.norm());
    std::vector<std::size_t> order(impacts.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    // Largest first; equal impulses keep time order.
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
        return impacts[i].impulse.norm() > impacts[j].impulse.norm();
    });
    std::vector<bool> keep(impacts.size(), false);
    for (std::size_t r = 0; r < order.size() && r < kMaxShownImpacts; ++r)
        if (impacts[order[r]].impulse.norm() >= kShownImpulseFraction * largest) keep[order[r]] = true;
    // The detailed ones (the largest) first, then the others; each group in time order. A
    // collision of a pair already detailed at (nearly, 1 mm) the same point is not detailed
    // again: a ball's last bounces would stack their n and r labels on one point.
    std::vector<ImpactMark> out;
    for (std::size_t r = 0; r < order.size() && out.size() < kDetailedImpacts; ++r) {
        const ImpactMark& m = impacts[order[r]];
        if (!keep[order[r]]) continue;
        bool again = false;
        for (const ImpactMark& d : out)
            again = again || (d.a == m.a && d.b == m.b && (d.point - m.point).norm() < 1e-3);
        if (again) continue;
        keep[order[r]] = false;
        out.push_back(m);
    }
    std::stable_sort(out.begin(), out.end(), [](const ImpactMark& a, const ImpactMark& b) { return a.t < b.t; });
    for (std::size_t k = 0; k < impacts.size(); ++k)
        if (keep[k]) {
            out.push_back(impacts[k]);
            out.back().detailed = false;
        }
    return out;
}

void add_trails(const std::vector<FrameState>& history, double span, FrameState* frame) {
    frame->trails.assign(frame->bodies.size(), {});
    const auto first = std::lower_bound(history.begin(), history.end(), frame->t - span,
                                        [](const FrameState& f, double t) { return f.t < t; });
    for (auto it = first; it != history.end() && it->t < frame->t; ++it)
        for (std::size_t i = 0; i < frame->bodies.size() && i < it->bodies.size(); ++i)
            frame->trails[i].push_back({it->t, it->bodies[i].x});
    for (std::size_t i = 0; i < frame->bodies.size(); ++i) frame->trails[i].push_back({frame->t, frame->bodies[i].x});
}

double body_mass(const Scene& scene, std::size_t i) {
    const SceneBody& b = scene.bodies[i];
    return scene.dimension == 1 ? b.body1.mass : scene.dimension == 2 ? b.body2.mass : b.body3.mass;
}

namespace {

// Body i of the scene in the state `s`, as the engine's body of the scene's dimension.
Body1 body1_of(const Scene& scene, std::size_t i, const BodyState& s) {
    Body1 b = scene.bodies[i].body1;
    b.position = s.x.x();
    b.v = s.v.x();
    return b;
}
Body2 body2_of(const Scene& scene, std::size_t i, const BodyState& s) {
    Body2 b = scene.bodies[i].body2;
    b.position = s.x.head<2>();
    b.angle = s.angle;
    b.v = s.v.head<2>();
    b.w = s.w.z();
    return b;
}
Body3 body3_of(const Scene& scene, std::size_t i, const BodyState& s) {
    Body3 b = scene.bodies[i].body3;
    b.position = s.x;
    b.orientation = s.q;
    b.v = s.v;
    b.w = s.w;
    return b;
}

}  // namespace

double kinetic_energy(const Scene& scene, std::size_t i, const BodyState& s) {
    switch (scene.dimension) {
        case 1: return totals(std::vector<Body1>{body1_of(scene, i, s)}).kinetic_energy;
        case 2: return totals(std::vector<Body2>{body2_of(scene, i, s)}).kinetic_energy;
        default: return totals(std::vector<Body3>{body3_of(scene, i, s)}).kinetic_energy;
    }
}

namespace {

// The totals of the bodies [first, last) of a frame.
FrameTotals totals_of(const Scene& scene, const FrameState& frame, std::size_t first, std::size_t last) {
    FrameTotals t;
    const auto sum = [&](auto body_of) {
        using Body = decltype(body_of(std::size_t{0}));
        std::vector<Body> bodies;
        for (std::size_t i = first; i < last; ++i) {
            bodies.push_back(body_of(i));
            t.potential += potential_energy(bodies.back(), scene.gravity);
        }
        const auto sums = totals(bodies);
        t.kinetic = sums.kinetic_energy;
        if constexpr (std::is_same_v<Body, Body1>) t.momentum.x() = sums.momentum;
        else if constexpr (std::is_same_v<Body, Body2>) {
            t.momentum.head<2>() = sums.momentum;
            t.angular_momentum.z() = sums.angular_momentum;
        } else {
            t.momentum = sums.momentum;
            t.angular_momentum = sums.angular_momentum;
        }
    };
    switch (scene.dimension) {
        case 1: sum([&](std::size_t i) { return body1_of(scene, i, frame.bodies[i]); }); break;
        case 2: sum([&](std::size_t i) { return body2_of(scene, i, frame.bodies[i]); }); break;
        default: sum([&](std::size_t i) { return body3_of(scene, i, frame.bodies[i]); }); break;
    }
    return t;
}

}  // namespace

FrameTotals frame_totals(const Scene& scene, const FrameState& frame) {
    return totals_of(scene, frame, 0, std::min(scene.bodies.size(), frame.bodies.size()));
}

FrameTotals body_totals(const Scene& scene, const FrameState& frame, std::size_t i) {
    if (i >= std::min(scene.bodies.size(), frame.bodies.size())) return {};
    return totals_of(scene, frame, i, i + 1);
}

TotalsColumns totals_columns(const std::vector<FrameTotals>& totals) {
    TotalsColumns c;
    for (const FrameTotals& s : totals) {
        c.kinetic.push_back(s.kinetic);
        c.potential.push_back(s.potential);
        c.total.push_back(s.kinetic + s.potential);
        c.px.push_back(s.momentum.x());
        c.py.push_back(s.momentum.y());
        c.pz.push_back(s.momentum.z());
    }
    return c;
}

}  // namespace collide::render
