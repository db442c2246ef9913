// DiagramView's drawing: ground and walls, trails, bodies, arrows and the collision's vectors,
// the positive directions, then the labels (render/diagram_view.h lists them bottom to top).
// Where things go (body outlines, the frame and the arrow scales) is diagram_view.cpp's.
#include "render/diagram_view.h"
#include "render/screen_vec.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace collide::render {

namespace {

using namespace screen;

// The part of segment a-b inside a convex polygon (screen points, either orientation).
bool clip_to_convex(const std::vector<ImVec2>& poly, ImVec2* a, ImVec2* b) {
    double t0 = 0.0, t1 = 1.0;
    double area = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const ImVec2& p = poly[i];
        const ImVec2& q = poly[(i + 1) % poly.size()];
        area += static_cast<double>(p.x) * q.y - static_cast<double>(q.x) * p.y;
    }
    const double sign = area > 0 ? 1.0 : -1.0;
    const double dx = b->x - a->x, dy = b->y - a->y;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const ImVec2& p = poly[i];
        const ImVec2& q = poly[(i + 1) % poly.size()];
        // Inside: sign * cross(q - p, x - p) >= 0.
        const double ex = q.x - p.x, ey = q.y - p.y;
        const double f0 = sign * (ex * (a->y - p.y) - ey * (a->x - p.x));
        const double fd = sign * (ex * dy - ey * dx);
        if (std::abs(fd) < 1e-12) {
            if (f0 < 0) return false;
            continue;
        }
        const double t = -f0 / fd;
        if (fd > 0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
        if (t0 >= t1) return false;
    }
    const ImVec2 a0 = *a;
    *a = ImVec2(static_cast<float>(a0.x + t0 * dx), static_cast<float>(a0.y + t0 * dy));
    *b = ImVec2(static_cast<float>(a0.x + t1 * dx), static_cast<float>(a0.y + t1 * dy));
    return true;
}

// Diagonal hatching (45 degrees) clipped to a convex screen polygon.
void hatch_convex(ImDrawList* dl, const std::vector<ImVec2>& poly, float step, Colour colour, float thickness) {
    if (poly.empty()) return;
    const ImVec4 box = bounds_of(poly);
    const float x0 = box.x, y0 = box.y, x1 = box.z, y1 = box.w;
    // Lines x - y = c.
    for (float c = x0 - y1; c <= x1 - y0; c += step) {
        ImVec2 a(c + y0, y0), b(c + y1, y1);
        if (clip_to_convex(poly, &a, &b)) dl->AddLine(a, b, colour, thickness);
    }
}

}  // namespace

void DiagramView::draw_planes(ImDrawList* dl) const {
    // The visible world rectangle (a little larger).
    const double pad = 40.0 / scale_;
    const double x0 = centre_.x() - 0.5 * (viewport_.z - viewport_.x) / scale_ - pad;
    const double x1 = centre_.x() + 0.5 * (viewport_.z - viewport_.x) / scale_ + pad;
    const double y0 = centre_.y() - 0.5 * (viewport_.w - viewport_.y) / scale_ - pad;
    const double y1 = centre_.y() + 0.5 * (viewport_.w - viewport_.y) / scale_ + pad;
    const Palette& c = style_.colours;
    for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
        if (kind(i) != Kind::plane) continue;
        Vec2 n;
        double offset;
        plane_of(i, &n, &offset);
        // The boundary line n.p = offset, clipped to the visible rectangle.
        const Vec2 t(-n.y(), n.x());
        const Vec2 p0 = n * offset;
        double t0 = -1e9, t1 = 1e9;
        const double lo[2] = {x0, y0}, hi[2] = {x1, y1};
        bool visible = true;
        for (int k = 0; k < 2; ++k) {
            if (std::abs(t[k]) < 1e-12) {
                if (p0[k] < lo[k] || p0[k] > hi[k]) visible = false;
                continue;
            }
            double a = (lo[k] - p0[k]) / t[k], b = (hi[k] - p0[k]) / t[k];
            if (a > b) std::swap(a, b);
            t0 = std::max(t0, a);
            t1 = std::min(t1, b);
        }
        if (!visible || t0 >= t1) continue;
        const ImVec2 a = to_screen(Vec3((p0 + t0 * t).x(), (p0 + t0 * t).y(), 0));
        const ImVec2 b = to_screen(Vec3((p0 + t1 * t).x(), (p0 + t1 * t).y(), 0));
        // The solid side in screen coordinates (y down).
        const ImVec2 down = unit(ImVec2(static_cast<float>(-n.x()), static_cast<float>(n.y())));
        const float depth = style_.px(style_.hatch_depth);
        std::vector<ImVec2> band = {a, b, b + down * depth, a + down * depth};
        // Clockwise on screen for the anti-aliased fill.
        const float area = (b.x - a.x) * (down.y) - (b.y - a.y) * (down.x);
        if (area < 0) std::reverse(band.begin(), band.end());
        dl->AddConvexPolyFilled(band.data(), 4, with_alpha(c.static_fill, 0.7f));
        hatch_convex(dl, band, style_.px(style_.hatch_step), c.hatch, style_.lw(1.1f));
        dl->AddLine(a, b, c.ink, style_.lw(style_.outline));
    }
}

void DiagramView::draw_axis_1d(ImDrawList* dl) const {
    // The x axis the blocks stand on, with the positive direction.
    const float y = to_screen(Vec3::Zero()).y;
    const float x0 = viewport_.x + style_.px(8), x1 = viewport_.z - style_.px(8);
    const Palette& c = style_.colours;
    dl->AddLine(ImVec2(x0, y), ImVec2(x1 - style_.px(10), y), c.ink, style_.lw(style_.outline));
    draw_arrow(dl, ImVec2(x1 - style_.px(30), y), ImVec2(x1, y), c.ink, style_.lw(style_.outline), style_.lw(12),
               style_.lw(9));
}

void DiagramView::draw_body(ImDrawList* dl, std::size_t i, const BodyState& s, bool com) const {
    const Palette& c = style_.colours;
    const SceneBody& body = scene_.bodies[i];
    int order = 0;  // colour by the order among moving bodies
    for (std::size_t j = 0; j < i; ++j) order += scene_.bodies[j].is_static() ? 0 : 1;
    const Colour fill = body.is_static() ? c.static_fill : c.fills[order % Palette::kFills];
    const float stroke = style_.lw(style_.outline);
    const ImVec2 centre = to_screen(s.x);
    float angle = static_cast<float>(s.angle);
    if (kind(i) == Kind::round) {
        const float r = static_cast<float>(radius(i) * scale_);
        dl->AddCircleFilled(centre, r, fill);
        if (body.is_static()) {
            // Hatch inside the circle: clip to a fine polygon.
            std::vector<ImVec2> poly;
            for (int k = 0; k < 48; ++k) {
                const float a = 2.0f * static_cast<float>(kPi) * static_cast<float>(k) / 48.0f;
                poly.push_back(centre + ImVec2(r * std::cos(a), r * std::sin(a)));
            }
            hatch_convex(dl, poly, style_.px(style_.hatch_step), with_alpha(c.hatch, 0.6f), style_.lw(1.0f));
        }
        dl->AddCircle(centre, r, c.ink, 0, stroke);
        // The radius line, turning with the body (3D: the body's x axis seen from the front).
        Vec2 d(std::cos(s.angle), std::sin(s.angle));
        if (scene_.dimension == 3) {
            d = xy(s.q * Vec3::UnitX());
            angle = static_cast<float>(std::atan2(d.y(), d.x()));
        }
        if (d.norm() > 0.2 && !body.is_static()) {
            const ImVec2 rim = centre + ImVec2(static_cast<float>(d.x()), static_cast<float>(-d.y())) * r;
            dl->AddLine(centre, rim, c.ink, style_.lw(style_.thin));
        }
    } else if (kind(i) == Kind::polygon) {
        std::vector<ImVec2> pts;
        for (const Vec2& p : outline(i, s)) pts.push_back(to_screen(Vec3(p.x(), p.y(), 0)));
        dl->AddConvexPolyFilled(pts.data(), static_cast<int>(pts.size()), fill);
        if (body.is_static())
            hatch_convex(dl, pts, style_.px(style_.hatch_step), with_alpha(c.hatch, 0.6f), style_.lw(1.0f));
        dl->AddPolyline(pts.data(), static_cast<int>(pts.size()), c.ink, ImDrawFlags_Closed, stroke);
        if (scene_.dimension == 3) {
            const Vec2 d = xy(s.q * Vec3::UnitX());
            angle = static_cast<float>(std::atan2(d.y(), d.x()));
        }
    }
    if (com && !body.is_static() && kind(i) != Kind::plane && kind(i) != Kind::none)
        draw_com_marker(dl, centre, style_.lw(style_.com), c.ink, c.background, angle);
}

Vec3 DiagramView::to_world(ImVec2 screen) const {
    const double cx = 0.5 * (viewport_.x + viewport_.z), cy = 0.5 * (viewport_.y + viewport_.w);
    return Vec3(centre_.x() + (screen.x - cx) / scale_, centre_.y() - (screen.y - cy) / scale_, 0.0);
}

void DiagramView::draw(ImDrawList* dl, const FontSet& fonts, const FrameState& frame, const Decor& decor,
                       const Annotations& items) const {
    const Palette& c = style_.colours;
    const std::size_t n = std::min(frame.bodies.size(), scene_.bodies.size());
    dl->PushClipRect(ImVec2(viewport_.x, viewport_.y), ImVec2(viewport_.z, viewport_.w), true);
    draw_planes(dl);
    if (scene_.dimension == 1) draw_axis_1d(dl);

    // Trails: the path of each centre over the last moments, fading with age.
    for (std::size_t i = 0; decor.trails && i < n && i < frame.trails.size(); ++i) {
        const auto& trail = frame.trails[i];
        if (scene_.bodies[i].is_static() || trail.size() < 2) continue;
        int order = 0;
        for (std::size_t j = 0; j < i; ++j) order += scene_.bodies[j].is_static() ? 0 : 1;
        const double span = std::max(1e-9, trail.back().t - trail.front().t);
        for (std::size_t k = 1; k < trail.size(); ++k) {
            const double age = (frame.t - trail[k].t) / span;
            const float alpha = static_cast<float>(0.55 * std::clamp(1.0 - age, 0.0, 1.0));
            dl->AddLine(to_screen(trail[k - 1].x), to_screen(trail[k].x),
                        with_alpha(c.darks[order % Palette::kFills], alpha), style_.lw(2.0f));
        }
    }

    const float arrow = style_.lw(style_.arrow);
    const float hl = style_.lw(style_.head_length), hw = style_.lw(style_.head_width);
    bool clipped = true;
    for (const Annotation& a : items) {
        const ImVec2 p = to_screen(a.from), q = to_screen(a.to);
        if (a.kind == Mark::label && clipped) {  // labels may reach past the view
            dl->PopClipRect();
            clipped = false;
        }
        switch (a.kind) {
            case Mark::plane: break;  // draw_planes
            case Mark::body: draw_body(dl, static_cast<std::size_t>(a.body), pose_of(a), a.small); break;
            case Mark::lever_arm: {
                const ImVec2 d = unit(q - p);
                draw_dashed_line(dl, p, q - d * style_.px(9), a.colour, style_.lw(style_.thin), style_.px(6),
                                 style_.px(4));
                draw_arrow(dl, q - d * style_.px(11), q, a.colour, style_.lw(style_.thin), style_.lw(9), style_.lw(7));
                break;
            }
            case Mark::normal: {
                // Beside the contact point, along the tangent line through it.
                const ImVec2 nd = unit(q - p);
                const ImVec2 td(-nd.y, nd.x);
                const float nl = style_.px(style_.normal_length);
                draw_dashed_line(dl, p - td * (0.9f * nl), p + td * (0.9f * nl), with_alpha(a.colour, 0.8f),
                                 style_.lw(style_.thin), style_.px(7), style_.px(4));
                const ImVec2 n0 = p + td * style_.px(18.0f);
                draw_arrow(dl, n0, n0 + nd * nl, a.colour, style_.lw(2.0f), hl * 0.85f, hw * 0.85f);
                break;
            }
            case Mark::impulse:
                draw_arrow(dl, p, q, a.faint ? with_alpha(a.colour, 0.75f) : a.colour, arrow, hl, hw);
                break;
            case Mark::contact:
                dl->AddCircleFilled(p, style_.px(4.5f), c.background);
                dl->AddCircleFilled(p, style_.px(3.2f), a.colour);
                break;
            case Mark::velocity: draw_arrow(dl, p, q, a.colour, arrow, hl, hw); break;
            case Mark::point:
                dl->AddCircleFilled(p, style_.px(5.0f), c.background);
                dl->AddCircle(p, style_.px(4.5f), a.colour, 0, style_.lw(2.0f));
                break;
            case Mark::point_velocity: draw_arrow(dl, p, q, a.colour, style_.lw(2.0f), hl * 0.85f, hw * 0.85f); break;
            case Mark::spin: {
                // An arc centred above the body, its head in the sense of the spin.
                const double mid = 0.5 * kPi;
                draw_curved_arrow(dl, p, a.radius, static_cast<float>(mid - a.sweep / 2),
                                  static_cast<float>(mid + a.sweep / 2), a.colour, style_.lw(2.5f), hl * 0.85f,
                                  hw * 0.85f);
                break;
            }
            case Mark::direction:
                if (a.radius > 0) {  // the counter-clockwise arc of +ω
                    draw_curved_arrow(dl, p, a.radius, static_cast<float>(-0.6 * kPi), static_cast<float>(0.9 * kPi),
                                      a.colour, style_.lw(1.8f), hl * 0.6f, hw * 0.6f);
                } else {
                    const float s = scene_.dimension == 1 ? 0.8f : 0.75f;
                    draw_arrow(dl, p, q, a.colour, style_.lw(2.0f), hl * s, hw * s);
                }
                break;
            case Mark::label: {
                ImFont* font = a.small ? fonts.small : fonts.text;
                if (a.faint) {  // where it stands, no backing
                    draw_rich_text(dl, fonts, font, ImVec2(a.box.x, a.box.y), a.colour, a.text);
                } else {
                    const float pad = style_.px(3.0f), gap = style_.px(6.0f);
                    draw_placed_label(dl, fonts, font, a.box, a.anchor, a.text, a.colour,
                                      with_alpha(c.background, 0.85f), pad, gap);
                }
                break;
            }
            case Mark::table_cell:
            case Mark::formula_line:
            case Mark::plot_value: break;  // the overlays draw their own
        }
    }
    if (clipped) dl->PopClipRect();
}

}  // namespace collide::render
