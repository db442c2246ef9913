// DiagramView's drawing: ground and walls, trails, bodies, arrows and the collision's vectors,
// the positive directions, then the labels (render/diagram_view.h lists them bottom to top).
// Where things go (body outlines, the frame and the arrow scales) is diagram_view.cpp's.
#include "render/diagram_view.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace collide::render {

namespace {

// The front view of a world point or vector (m): its x and y.
Vec2 xy(const Vec3& v) { return Vec2(v.x(), v.y()); }

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
void hatch_convex(ImDrawList* dl, const std::vector<ImVec2>& poly, float step, Colour colour,
                  float thickness) {
    if (poly.empty()) return;
    const ImVec4 box = bounds_of(poly);
    const float x0 = box.x, y0 = box.y, x1 = box.z, y1 = box.w;
    // Lines x - y = c.
    for (float c = x0 - y1; c <= x1 - y0; c += step) {
        ImVec2 a(c + y0, y0), b(c + y1, y1);
        if (clip_to_convex(poly, &a, &b)) dl->AddLine(a, b, colour, thickness);
    }
}

// Screen vector arithmetic (pixels).
float dot(ImVec2 a, ImVec2 b) { return a.x * b.x + a.y * b.y; }
ImVec2 operator+(ImVec2 a, ImVec2 b) { return ImVec2(a.x + b.x, a.y + b.y); }
ImVec2 operator-(ImVec2 a, ImVec2 b) { return ImVec2(a.x - b.x, a.y - b.y); }
ImVec2 operator*(ImVec2 a, float s) { return ImVec2(a.x * s, a.y * s); }
float norm(ImVec2 a) { return std::sqrt(dot(a, a)); }
ImVec2 unit(ImVec2 a) {
    const float n = norm(a);
    return n > 1e-6f ? a * (1.0f / n) : ImVec2(0.0f, -1.0f);
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
    draw_arrow(dl, ImVec2(x1 - style_.px(30), y), ImVec2(x1, y), c.ink, style_.lw(style_.outline),
               style_.lw(12), style_.lw(9));
}

void DiagramView::label_axis_1d(ImDrawList* dl, const FontSet& fonts, LabelPlacer* labels) const {
    const float y = to_screen(Vec3::Zero()).y;
    const float x1 = viewport_.z - style_.px(8);
    const ImVec2 size = rich_text_size(fonts, fonts.text, "+x");
    const ImVec2 at(x1 - size.x, y + style_.px(6));
    draw_rich_text(dl, fonts, fonts.text, at, style_.colours.ink, "+x");
    labels->reserve(ImVec4(at.x, at.y, at.x + size.x, at.y + size.y));
}

void DiagramView::draw_body(ImDrawList* dl, std::size_t i, const BodyState& s,
                            const Decor& decor) const {
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
    if (decor.com && !body.is_static() && kind(i) != Kind::plane && kind(i) != Kind::none)
        draw_com_marker(dl, centre, style_.lw(style_.com), c.ink, c.background, angle);
}

void DiagramView::draw(ImDrawList* dl, const FontSet& fonts, const FrameState& frame,
                       const Decor& decor, LabelPlacer* labels) const {
    const Palette& c = style_.colours;
    const std::size_t n = std::min(frame.bodies.size(), scene_.bodies.size());
    dl->PushClipRect(ImVec2(viewport_.x, viewport_.y), ImVec2(viewport_.z, viewport_.w), true);
    draw_planes(dl);
    if (scene_.dimension == 1) draw_axis_1d(dl);

    // Trails: the path of each centre over the last moments, fading with age.
    if (decor.trails && !frame.trails.empty()) {
        for (std::size_t i = 0; i < n && i < frame.trails.size(); ++i) {
            const auto& trail = frame.trails[i];
            if (scene_.bodies[i].is_static() || trail.size() < 2) continue;
            int order = 0;
            for (std::size_t j = 0; j < i; ++j) order += scene_.bodies[j].is_static() ? 0 : 1;
            const double span = std::max(1e-9, trail.back().t - trail.front().t);
            for (std::size_t k = 1; k < trail.size(); ++k) {
                const double age = (frame.t - trail[k].t) / span;
                const float alpha = static_cast<float>(0.55 * std::clamp(1.0 - age, 0.0, 1.0));
                dl->AddLine(to_screen(trail[k - 1].x), to_screen(trail[k].x),
                            with_alpha(c.darks[order % Palette::kFills], alpha),
                            style_.lw(2.0f));
            }
        }
    }

    // Bodies: static first, then moving ones.
    for (int pass = 0; pass < 2; ++pass)
        for (std::size_t i = 0; i < n; ++i)
            if (scene_.bodies[i].is_static() == (pass == 0)) draw_body(dl, i, frame.bodies[i], decor);

    const float arrow = style_.lw(style_.arrow);
    const float hl = style_.lw(style_.head_length), hw = style_.lw(style_.head_width);
    const float gap = style_.px(6.0f);
    struct Pending {
        ImVec2 anchor, direction;
        std::string text;
        Colour colour;
        ImFont* font;
    };
    std::vector<Pending> pending;  // labels, placed in this order (most important first)
    std::vector<Pending> normal_labels;

    // Collisions: r vectors, the normal, the impulses, the contact point.
    std::vector<std::size_t> role_a, role_b;
    if (decor.impacts) {
        for (const ImpactMark& im : frame.impacts) {
            if (im.a >= n || im.b >= n) continue;
            role_a.push_back(im.a);
            role_b.push_back(im.b);
            const ImVec2 p = to_screen(im.point);
            // r vectors (not in 1D, where every lever arm is along the line of impact).
            if (scene_.dimension > 1) {
                const std::pair<std::size_t, const char*> ends[2] = {{im.a, "r_{a}"}, {im.b, "r_{b}"}};
                for (const auto& [i, name] : ends) {
                    if (kind(i) == Kind::plane || kind(i) == Kind::none) continue;
                    const ImVec2 from = to_screen(frame.bodies[i].x);
                    if (norm(p - from) < 4.0f) continue;
                    draw_dashed_line(dl, from, p - unit(p - from) * style_.px(9), c.lever,
                                     style_.lw(style_.thin), style_.px(6), style_.px(4));
                    draw_arrow(dl, p - unit(p - from) * style_.px(11), p, c.lever,
                               style_.lw(style_.thin), style_.lw(9), style_.lw(7));
                    const ImVec2 d = unit(p - from);
                    pending.push_back({(from + p) * 0.5f, ImVec2(-d.y, d.x), name, c.lever, fonts.text});
                }
            }
            // The contact: the tangent line through the point, and the unit normal n drawn beside
            // the impulse (they are parallel without friction). In 1D n is +x, the axis.
            const ImVec2 nd = unit(ImVec2(static_cast<float>(im.normal.x()), static_cast<float>(-im.normal.y())));
            const ImVec2 td(-nd.y, nd.x);
            const float nl = style_.px(style_.normal_length);
            if (scene_.dimension > 1) {
                draw_dashed_line(dl, p - td * (0.9f * nl), p + td * (0.9f * nl), with_alpha(c.normal, 0.8f),
                                 style_.lw(style_.thin), style_.px(7), style_.px(4));
                const ImVec2 n0 = p + td * style_.px(18.0f);
                draw_arrow(dl, n0, n0 + nd * nl, c.normal, style_.lw(2.0f), hl * 0.85f, hw * 0.85f);
                normal_labels.push_back({n0 + nd * nl, nd, "n", c.normal, fonts.text});
            }
            // The impulse on b, and its reaction on a when a moves.
            const Vec2 P = xy(im.impulse) * k_impulse_;
            const ImVec2 tip = to_screen(im.point + Vec3(P.x(), P.y(), 0));
            const std::string value = format_number(xy(im.impulse).norm()) + " N s";
            if (norm(tip - p) > 1.0f) {
                if (!scene_.bodies[im.a].is_static()) {
                    const ImVec2 rtip = p - (tip - p);
                    draw_arrow(dl, p, rtip, with_alpha(c.impulse, 0.75f), arrow, hl, hw);
                    pending.push_back({rtip, unit(p - tip), "\u2212P", c.impulse, fonts.text});
                }
                draw_arrow(dl, p, tip, c.impulse, arrow, hl, hw);
                pending.insert(pending.begin(), {tip, unit(tip - p), "P = " + value, c.impulse, fonts.text});
            }
            dl->AddCircleFilled(p, style_.px(4.5f), c.background);
            dl->AddCircleFilled(p, style_.px(3.2f), c.impulse);
        }
    }

    // Velocities and spins.
    if (decor.velocities) {
        for (std::size_t i = 0; i < n; ++i) {
            if (scene_.bodies[i].is_static()) continue;
            const BodyState& s = frame.bodies[i];
            const ImVec2 from = to_screen(s.x);
            const ImVec2 tip = to_screen(s.x + k_velocity_ * s.v);
            const double speed = xy(s.v).norm();
            if (norm(tip - from) > 1.0f) {
                draw_arrow(dl, from, tip, c.velocity, arrow, hl, hw);
                const std::string v = scene_.dimension == 1 ? format_number(s.v.x()) : format_number(speed);
                pending.push_back({tip, unit(tip - from), "v = " + v + " m s\u207B\u00B9", c.velocity, fonts.text});
            }
            const double w = s.w.z();
            if (max_spin_ > 0 && std::abs(w) > 1e-9 * max_spin_ && std::abs(w) > 1e-9) {
                Vec2 l(1e300, 1e300), h(-1e300, -1e300);
                extent(i, s, &l, &h);
                const float r = spin_radius(i, scale_);
                const double sweep = std::max(35.0, 240.0 * std::abs(w) / max_spin_) * kPi / 180.0;
                const double mid = 0.5 * kPi;  // centred above the body
                const double sign = w > 0 ? 1.0 : -1.0;
                const float a0 = static_cast<float>(mid - sign * sweep / 2);
                const float a1 = static_cast<float>(mid + sign * sweep / 2);
                draw_curved_arrow(dl, from, r, a0, a1, c.spin, style_.lw(2.5f), hl * 0.85f, hw * 0.85f);
                pending.push_back({from - ImVec2(0, r), ImVec2(0, -1),
                                   "\u03C9 = " + format_number(w) + " rad s\u207B\u00B9", c.spin, fonts.text});
            }
        }
    }
    // Positive directions. 1D: an arrow along +x above each moving block ("+v"), as in the
    // page's figure. 2D: one glyph in the view's lower left corner: +x, +y and the
    // counter-clockwise sense of +ω (velocities and spins are measured that way).
    std::vector<std::pair<ImVec2, std::string>> direction_labels;  // top-left, text
    if (decor.directions && scene_.dimension == 1) {
        for (std::size_t i = 0; i < n; ++i) {
            if (scene_.bodies[i].is_static() || kind(i) == Kind::none) continue;
            const BodyState& s = frame.bodies[i];
            Vec2 l(1e300, 1e300), h(-1e300, -1e300);
            extent(i, s, &l, &h);
            const ImVec2 top = to_screen(Vec3(s.x.x(), h.y(), 0));
            const float len = style_.px(56.0f);
            const ImVec2 a0(top.x - 0.5f * len, top.y - style_.px(34.0f));
            draw_arrow(dl, a0, a0 + ImVec2(len, 0), c.muted, style_.lw(2.0f), hl * 0.8f, hw * 0.8f);
            pending.push_back({a0 + ImVec2(len, 0), ImVec2(1, 0), "+v", c.muted, fonts.text});
        }
    }
    if (decor.directions && scene_.dimension == 2) {
        const float L = style_.px(46.0f), r = style_.px(13.0f);
        const ImVec2 o(viewport_.x + style_.px(36.0f), viewport_.w - style_.px(36.0f));
        draw_arrow(dl, o, o + ImVec2(L, 0), c.muted, style_.lw(2.0f), hl * 0.75f, hw * 0.75f);
        draw_arrow(dl, o, o - ImVec2(0, L), c.muted, style_.lw(2.0f), hl * 0.75f, hw * 0.75f);
        const ImVec2 arc = o + ImVec2(0.55f * L, -0.55f * L);
        draw_curved_arrow(dl, arc, r, static_cast<float>(-0.6 * kPi), static_cast<float>(0.9 * kPi), c.muted,
                          style_.lw(1.8f), hl * 0.6f, hw * 0.6f);
        const float fh = fonts.text->FontSize;
        direction_labels.push_back({o + ImVec2(L + style_.px(6.0f), -0.5f * fh), "+x"});
        direction_labels.push_back({o + ImVec2(-0.5f * rich_text_size(fonts, fonts.text, "+y").x, -L - fh - style_.px(4.0f)), "+y"});
        direction_labels.push_back({arc + ImVec2(r + style_.px(5.0f), -r - 0.3f * fh), "+\u03C9"});
    }
    for (const auto& [at, text] : direction_labels) {
        draw_rich_text(dl, fonts, fonts.text, ImVec2(std::round(at.x), std::round(at.y)), c.muted, text);
        if (labels) {
            const ImVec2 sz = rich_text_size(fonts, fonts.text, text);
            labels->reserve(ImVec4(at.x, at.y, at.x + sz.x, at.y + sz.y));
        }
    }
    dl->PopClipRect();

    if (!decor.labels || !labels) return;
    if (scene_.dimension == 1) label_axis_1d(dl, fonts, labels);
    pending.insert(pending.begin() + std::min<std::ptrdiff_t>(1, static_cast<std::ptrdiff_t>(pending.size())),
                   normal_labels.begin(), normal_labels.end());
    // Labels keep off the bodies where they can.
    for (std::size_t i = 0; i < n; ++i) {
        if (kind(i) == Kind::round) {
            const ImVec2 c0 = to_screen(frame.bodies[i].x);
            const float r = static_cast<float>(radius(i) * scale_);
            std::vector<ImVec2> poly;
            for (int k = 0; k < 20; ++k) {
                const float a = 2.0f * static_cast<float>(kPi) * static_cast<float>(k) / 20.0f;
                poly.push_back(ImVec2(c0.x + r * std::cos(a), c0.y + r * std::sin(a)));
            }
            labels->avoid(std::move(poly));
        } else if (kind(i) == Kind::polygon) {
            std::vector<ImVec2> poly;
            for (const Vec2& p : outline(i, frame.bodies[i])) poly.push_back(to_screen(Vec3(p.x(), p.y(), 0)));
            labels->avoid(std::move(poly));
        }
    }
    // Body names: inside the body when they fit, else above it.
    for (std::size_t i = 0; i < n; ++i) {
        if (kind(i) == Kind::plane || kind(i) == Kind::none) continue;
        // At a single collision the bodies are tagged a and b, as in the formulas.
        std::string name = scene_.bodies[i].name;
        if (role_a.size() == 1 && role_a[0] == i) name += " (a)";
        if (role_b.size() == 1 && role_b[0] == i) name += " (b)";
        const ImVec2 size = rich_text_size(fonts, fonts.small, name);
        Vec2 l(1e300, 1e300), h(-1e300, -1e300);
        extent(i, frame.bodies[i], &l, &h);
        const float w_px = static_cast<float>((h - l).x() * scale_);
        const float h_px = static_cast<float>((h - l).y() * scale_);
        const ImVec2 centre = to_screen(frame.bodies[i].x);
        if (size.x < 0.75f * w_px && size.y < 0.4f * h_px) {
            // Below the centre marker, inside.
            const ImVec2 at(centre.x - 0.5f * size.x, centre.y + style_.lw(style_.com) + style_.px(4));
            dl->AddText(fonts.small, fonts.small->FontSize, ImVec2(std::round(at.x), std::round(at.y)),
                        c.ink, name.c_str());
            labels->reserve(ImVec4(at.x, at.y, at.x + size.x, at.y + size.y));
        } else {
            pending.push_back({to_screen(Vec3(frame.bodies[i].x.x(), h.y(), 0)), ImVec2(0, -1), name,
                               c.ink, fonts.small});
        }
    }
    const float pad = style_.px(3.0f);
    for (const Pending& p : pending) {
        place_label(dl, fonts, labels, p.font, p.anchor, p.direction, p.text, p.colour,
                    with_alpha(c.background, 0.85f), pad, gap);
    }
}

}  // namespace collide::render
