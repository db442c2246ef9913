// DiagramView's geometry: what each body looks like from the front (kind, outline, reach), and
// fit(), which frames the run and fixes the arrow scales. The drawing is diagram_draw.cpp's.
#include "render/diagram_view.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/convex_hull.h"
#include "render/scale.h"

namespace collide::render {

namespace {

// The front view of a world point or vector (m): its x and y.
Vec2 xy(const Vec3& v) { return Vec2(v.x(), v.y()); }

}  // namespace

DiagramView::DiagramView(const Scene& scene, const Style& style) : scene_(scene), style_(style) {}

DiagramView::Kind DiagramView::kind(std::size_t i) const {
    const SceneBody& b = scene_.bodies[i];
    if (scene_.dimension == 1) return Kind::polygon;
    if (scene_.dimension == 2) {
        switch (b.shape2.kind) {
            case Shape2::Kind::disc: return Kind::round;
            case Shape2::Kind::polygon: return Kind::polygon;
            case Shape2::Kind::half_plane: return Kind::plane;
        }
    }
    switch (b.shape3.kind) {
        case Shape3::Kind::sphere: return Kind::round;
        case Shape3::Kind::box: return Kind::polygon;
        case Shape3::Kind::half_space: return xy(b.shape3.normal).norm() > 0.3 ? Kind::plane : Kind::none;
    }
    return Kind::none;
}

double DiagramView::radius(std::size_t i) const {
    const SceneBody& b = scene_.bodies[i];
    return scene_.dimension == 2 ? b.shape2.radius : b.shape3.radius;
}

double DiagramView::reach(std::size_t i) const {
    if (kind(i) == Kind::round) return radius(i);
    const std::vector<Vec2> o = outline(i, BodyState{});
    double r = 0.0;
    for (const Vec2& p : o) r = std::max(r, p.norm());
    return r;
}

float DiagramView::spin_radius(std::size_t i, double scale) const {
    // A long body (its reach more than twice its nearest side) gets an arc of twice that
    // side or 36 px, whichever is larger, but never more than its reach.
    double inner = reach(i);
    if (kind(i) != Kind::round) {
        const std::vector<Vec2> o = outline(i, BodyState{});
        for (std::size_t k = 0; k < o.size(); ++k) {
            const Vec2 e = o[(k + 1) % o.size()] - o[k];
            if (e.norm() > 0) inner = std::min(inner, std::abs(e.x() * o[k].y() - e.y() * o[k].x()) / e.norm());
        }
    }
    double r = reach(i) * scale;
    if (reach(i) > 2.0 * inner) r = std::min(r, std::max(2.0 * inner * scale, static_cast<double>(style_.px(36.0f))));
    return static_cast<float>(r) + style_.px(10.0f);
}

std::vector<Vec2> DiagramView::outline(std::size_t i, const BodyState& s) const {
    const SceneBody& b = scene_.bodies[i];
    const Vec2 c = xy(s.x);
    if (scene_.dimension == 1) {
        const double hx = 0.5 * b.length, hy = 0.5 * block_height(scene_, i);
        return {c + Vec2(-hx, -hy), c + Vec2(hx, -hy), c + Vec2(hx, hy), c + Vec2(-hx, hy)};
    }
    if (scene_.dimension == 2) {
        const double ca = std::cos(s.angle), sa = std::sin(s.angle);
        std::vector<Vec2> out;
        for (int k = 0; k < b.shape2.polygon.count; ++k) {
            const Vec2& v = b.shape2.polygon.vertices[static_cast<std::size_t>(k)];
            out.push_back(c + Vec2(ca * v.x() - sa * v.y(), sa * v.x() + ca * v.y()));
        }
        return out;
    }
    std::vector<Vec2> corners;
    const Vec3& h = b.shape3.half;
    for (int k = 0; k < 8; ++k) {
        const Vec3 local((k & 1 ? 1 : -1) * h.x(), (k & 2 ? 1 : -1) * h.y(), (k & 4 ? 1 : -1) * h.z());
        corners.push_back(xy(s.x + s.q * local));
    }
    return convex_hull(corners);
}

void DiagramView::plane_of(std::size_t i, Vec2* normal, double* offset) const {
    const SceneBody& b = scene_.bodies[i];
    if (scene_.dimension == 2) {
        *normal = b.shape2.normal;
        *offset = b.shape2.offset;
        return;
    }
    // A 3D half-space seen from the front: its trace in the xy plane.
    const Vec2 n = xy(b.shape3.normal);
    const double len = n.norm();
    *normal = n / len;
    *offset = b.shape3.offset / len;
}

void DiagramView::extent(std::size_t i, const BodyState& s, Vec2* lo, Vec2* hi) const {
    switch (kind(i)) {
        case Kind::round: {
            const double r = radius(i);
            *lo = lo->cwiseMin(xy(s.x) - Vec2(r, r));
            *hi = hi->cwiseMax(xy(s.x) + Vec2(r, r));
            break;
        }
        case Kind::polygon:
            for (const Vec2& p : outline(i, s)) {
                *lo = lo->cwiseMin(p);
                *hi = hi->cwiseMax(p);
            }
            break;
        default: break;
    }
}

void DiagramView::fit(const std::vector<FrameState>& samples, const std::vector<ImpactMark>& impacts, ImVec4 viewport) {
    viewport_ = viewport;
    // Room around the content for the margin and for labels at arrow tips near the edge.
    const double m = style_.px(style_.margin);
    const double room = style_.px(22.0f);
    const double vw = std::max(1.0, viewport.z - viewport.x - 2 * (m + room));
    const double vh = std::max(1.0, viewport.w - viewport.y - 2 * (m + room));
    const double inf = std::numeric_limits<double>::infinity();

    // 1. Where the bodies go over the run, and how fast they move and spin.
    Vec2 lo(inf, inf), hi(-inf, -inf);
    double max_speed = 0.0;
    std::vector<double> sizes;
    max_spin_ = 0.0;
    // With frame_only(), a static body among the framed ones counts only near the moving ones.
    const bool some = !frame_only_.empty();
    const auto counts = [&](std::size_t i) { return framed(i) && !(some && scene_.bodies[i].is_static()); };
    for (const FrameState& f : samples)
        for (std::size_t i = 0; i < f.bodies.size() && i < scene_.bodies.size(); ++i) {
            if (!counts(i)) continue;
            extent(i, f.bodies[i], &lo, &hi);
            if (scene_.bodies[i].is_static()) continue;
            max_speed = std::max(max_speed, xy(f.bodies[i].v).norm());
            max_spin_ = std::max(max_spin_, std::abs(f.bodies[i].w.z()));
        }
    for (const FrameState& f : samples)
        for (const PointMark& m : points_)
            if (m.velocity && m.body < f.bodies.size() && counts(m.body))
                max_speed = std::max(max_speed, xy(point_velocity(m, f.bodies[m.body], scene_.dimension)).norm());
    if (some && lo.x() < inf && !samples.empty()) {
        const Vec2 d = Vec2::Constant(0.5 * (hi - lo).maxCoeff());
        const Vec2 near_lo = lo - d, near_hi = hi + d;
        for (std::size_t i = 0; i < scene_.bodies.size() && i < samples.front().bodies.size(); ++i) {
            if (!framed(i) || !scene_.bodies[i].is_static()) continue;
            Vec2 l(inf, inf), h(-inf, -inf);
            extent(i, samples.front().bodies[i], &l, &h);
            l = l.cwiseMax(near_lo);
            h = h.cwiseMin(near_hi);
            if (l.x() <= h.x() && l.y() <= h.y()) {
                lo = lo.cwiseMin(l);
                hi = hi.cwiseMax(h);
            }
        }
    }
    for (std::size_t i = 0; i < scene_.bodies.size() && !samples.empty(); ++i) {
        Vec2 l(inf, inf), h(-inf, -inf);
        extent(i, samples.front().bodies[i], &l, &h);
        if (l.x() < inf && counts(i) && !scene_.bodies[i].is_static()) sizes.push_back((h - l).maxCoeff());
    }
    if (!(lo.x() < inf)) {
        lo = Vec2(-1, -1);
        hi = Vec2(1, 1);
    }
    // 2. Ground and walls near the bodies: their line, and room for the hatching below it.
    const auto include_planes = [&](double pixels_per_metre) {
        const Vec2 c = 0.5 * (lo + hi);
        const double diag = (hi - lo).norm();
        for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
            if (kind(i) != Kind::plane) continue;
            Vec2 n;
            double offset;
            plane_of(i, &n, &offset);
            const double distance = n.dot(c) - offset;    // of the box centre from the boundary
            if (distance > 0.75 * diag + 1e-9) continue;  // far away: not framed
            const Vec2 foot = c - distance * n;
            const Vec2 below = foot - n * (1.6 * style_.px(style_.hatch_depth) / pixels_per_metre);
            lo = lo.cwiseMin(foot).cwiseMin(below);
            hi = hi.cwiseMax(foot).cwiseMax(below);
        }
    };
    const auto fit_scale = [&] {
        const Vec2 size = (hi - lo).cwiseMax(Vec2(1e-6, 1e-6));
        return std::min(vw / size.x(), vh / size.y());
    };
    double s0 = fit_scale();
    include_planes(s0);
    s0 = fit_scale();

    // 3. Arrow scales: the fastest body's arrow about one body size long, between 10% and
    // 25% of the view's smaller side.
    std::sort(sizes.begin(), sizes.end());
    const double body_px = sizes.empty() ? 0.2 * std::min(vw, vh) : sizes[sizes.size() / 2] * s0;
    const double arrow_px = std::clamp(body_px, 0.10 * std::min(vw, vh), 0.25 * std::min(vw, vh));
    k_velocity_ = max_speed > 0 ? arrow_px / s0 / max_speed : 0.0;
    // Impulses: the largest about as long as the fastest velocity, and none longer than half
    // the smaller body it acts on (the arrows of one contact must not reach the next).
    double max_impulse = 0.0;
    k_impulse_ = std::numeric_limits<double>::infinity();
    for (const ImpactMark& im : impacts) {
        if (!framed(im.a) && !framed(im.b)) continue;
        const double p = xy(im.impulse).norm();
        if (!(p > 0)) continue;
        max_impulse = std::max(max_impulse, p);
        for (std::size_t i : {im.a, im.b})
            if (i < scene_.bodies.size() && kind(i) != Kind::plane && kind(i) != Kind::none)
                k_impulse_ = std::min(k_impulse_, 0.45 * 2.0 * reach(i) / p);
    }
    k_impulse_ = max_impulse > 0 ? std::min(k_impulse_, 0.9 * arrow_px / s0 / max_impulse) : 0.0;

    // 4. Room for the arrows and spin arcs, then the final scale.
    const Vec2 lo0 = lo, hi0 = hi;
    for (const FrameState& f : samples)
        for (std::size_t i = 0; i < f.bodies.size() && i < scene_.bodies.size(); ++i) {
            if (scene_.bodies[i].is_static() || !framed(i)) continue;
            const Vec2 tip = xy(f.bodies[i].x + k_velocity_ * f.bodies[i].v);
            lo = lo.cwiseMin(tip);
            hi = hi.cwiseMax(tip);
            if (directions_room_ && scene_.dimension == 1) {  // the arrows over the blocks
                Vec2 l(inf, inf), h(-inf, -inf);
                extent(i, f.bodies[i], &l, &h);
                hi.y() = std::max(hi.y(), h.y() + style_.px(60.0f) / s0);
            }
            if (std::abs(f.bodies[i].w.z()) > 0) {  // the spin arc
                const Vec2 c = xy(f.bodies[i].x);
                const double r = (spin_radius(i, s0) + style_.px(4.0f)) / s0;
                lo = lo.cwiseMin(c - Vec2(r, r));
                hi = hi.cwiseMax(c + Vec2(r, r));
            }
        }
    for (const FrameState& f : samples)
        for (const PointMark& m : points_) {
            if (!m.velocity || m.body >= f.bodies.size() || !framed(m.body)) continue;
            const BodyState& s = f.bodies[m.body];
            const Vec2 tip =
                xy(point_position(m, s, scene_.dimension) + k_velocity_ * point_velocity(m, s, scene_.dimension));
            lo = lo.cwiseMin(tip);
            hi = hi.cwiseMax(tip);
        }
    for (const ImpactMark& im : impacts) {
        if (!framed(im.a) && !framed(im.b)) continue;
        const Vec2 p = xy(im.point), P = xy(im.impulse) * k_impulse_;
        lo = lo.cwiseMin(p + P).cwiseMin(p - P);
        hi = hi.cwiseMax(p + P).cwiseMax(p - P);
    }
    // Arrows may stretch the frame by at most half again: a single fast body should not
    // shrink the whole diagram.
    const Vec2 grow = 0.5 * (hi0 - lo0).cwiseMax(Vec2(1e-6, 1e-6));
    lo = lo.cwiseMax(lo0 - grow);
    hi = hi.cwiseMin(hi0 + grow);
    scale_ = fit_scale();
    centre_ = 0.5 * (lo + hi);
    box_lo_ = lo;
    box_hi_ = hi;
}

Vec3 DiagramView::point_position(const PointMark& m, const BodyState& s, int dimension) {
    if (dimension == 1) return s.x + Vec3(m.at.x(), 0, 0);
    const double ca = std::cos(s.angle), sa = std::sin(s.angle);
    return s.x + Vec3(ca * m.at.x() - sa * m.at.y(), sa * m.at.x() + ca * m.at.y(), 0);
}

// v_p = v + ω × r, r from the centre to the point (1D: the body's v).
Vec3 DiagramView::point_velocity(const PointMark& m, const BodyState& s, int dimension) {
    if (dimension == 1) return Vec3(s.v.x(), 0, 0);
    return s.v + s.w.cross(point_position(m, s, dimension) - s.x);
}

ImVec2 DiagramView::to_screen(const Vec3& world) const {
    const double cx = 0.5 * (viewport_.x + viewport_.z), cy = 0.5 * (viewport_.y + viewport_.w);
    return ImVec2(static_cast<float>(cx + (world.x() - centre_.x()) * scale_),
                  static_cast<float>(cy - (world.y() - centre_.y()) * scale_));
}

DiagramView::Legend DiagramView::legend_for(double metres_per_unit) const {
    if (!(metres_per_unit > 0)) return {};
    const double px_per_unit = metres_per_unit * scale_;
    // A round value whose arrow is about 70 px (at 720p) long.
    const double value = round_value(style_.px(70.0f) / px_per_unit);
    return {value, static_cast<float>(value * px_per_unit)};
}

DiagramView::Legend DiagramView::velocity_legend() const { return legend_for(k_velocity_); }
DiagramView::Legend DiagramView::impulse_legend() const { return legend_for(k_impulse_); }

}  // namespace collide::render
