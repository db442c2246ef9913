// DiagramView::annotate: what a 2D frame shows, as a list (render/annotation.h): bodies at
// their poses, arrows with the quantities they stand for, contact points, labels with their text
// and placed boxes. diagram_draw.cpp draws that list and nothing else.
#include "render/diagram_view.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "render/screen_vec.h"

namespace collide::render {

namespace {

using namespace screen;

// Whether the segment p-q passes through the box (x0, y0, x1, y1): Liang-Barsky clipping.
bool segment_hits_box(ImVec2 p, ImVec2 q, ImVec4 box) {
    const float dx = q.x - p.x, dy = q.y - p.y;
    float t0 = 0.0f, t1 = 1.0f;
    const float edges[4][2] = {{-dx, p.x - box.x}, {dx, box.z - p.x}, {-dy, p.y - box.y}, {dy, box.w - p.y}};
    for (const auto& e : edges) {
        if (e[0] == 0.0f) {
            if (e[1] < 0.0f) return false;
        } else {
            const float r = e[1] / e[0];
            if (e[0] < 0.0f) t0 = std::max(t0, r);
            else t1 = std::min(t1, r);
        }
    }
    return t0 < t1;
}

}  // namespace

Annotations DiagramView::annotate(const FontSet& fonts, const FrameState& frame, const Decor& decor,
                                  LabelPlacer* labels) const {
    const Palette& c = style_.colours;
    const int dim = scene_.dimension;
    const std::size_t n = std::min(frame.bodies.size(), scene_.bodies.size());
    Annotations items;
    const auto add = [&items](Annotation a) {
        items.push_back(std::move(a));
        return static_cast<int>(items.size()) - 1;
    };
    const auto arrow_item = [&](Mark kind, int body, const Vec3& from, const Vec3& to, std::vector<double> value,
                                Colour colour) {
        Annotation a = arrow_annotation(kind, body, from, to, std::move(value), colour);
        const ImVec2 p = to_screen(from), q = to_screen(to);
        a.box = ImVec4(std::min(p.x, q.x), std::min(p.y, q.y), std::max(p.x, q.x), std::max(p.y, q.y));
        return add(std::move(a));
    };

    // Ground and walls (drawn first, from the scene), then the bodies: static first.
    for (std::size_t i = 0; i < n; ++i) {
        if (kind(i) != Kind::plane) continue;
        Vec2 nrm;
        double offset;
        plane_of(i, &nrm, &offset);
        Annotation a;
        a.kind = Mark::plane;
        a.body = static_cast<int>(i);
        a.from = a.to = Vec3(nrm.x() * offset, nrm.y() * offset, 0.0);
        a.value = components(Vec3(nrm.x(), nrm.y(), 0.0), std::max(dim, 2));
        a.value.resize(static_cast<std::size_t>(dim));
        add(std::move(a));
    }
    std::vector<int> body_item(n, -1);
    for (int pass = 0; pass < 2; ++pass)
        for (std::size_t i = 0; i < n; ++i) {
            if (scene_.bodies[i].is_static() != (pass == 0) || kind(i) == Kind::plane) continue;
            const BodyState& s = frame.bodies[i];
            Annotation a;
            a.kind = Mark::body;
            a.body = static_cast<int>(i);
            a.from = a.to = s.x;
            a.value = pose_value(s, dim);
            a.small = decor.com;  // bodies: whether the centre-of-mass marker is drawn
            if (kind(i) != Kind::none) {
                Vec2 l(1e300, 1e300), h(-1e300, -1e300);
                extent(i, s, &l, &h);
                const ImVec2 p = to_screen(Vec3(l.x(), h.y(), 0)), q = to_screen(Vec3(h.x(), l.y(), 0));
                a.box = ImVec4(p.x, p.y, q.x, q.y);
            }
            body_item[i] = add(std::move(a));
        }

    // Label requests, placed at the end in this order (most important first).
    std::vector<LabelRequest> pending;
    std::vector<LabelRequest> normal_labels;

    // Collisions: r vectors, the normal, the impulses, the contact point.
    std::vector<std::size_t> role_a, role_b;
    std::vector<bool> labelled(n, false);  // bodies with a velocity, spin or impulse label
    if (decor.impacts) {
        for (const ImpactMark& im : frame.impacts) {
            if (im.a >= n || im.b >= n) continue;
            const ImVec2 p = to_screen(im.point);
            if (!im.detailed) {  // the impulse arrow only (render::shown_impacts)
                const Vec3 kP = im.impulse * k_impulse_;
                if (norm(to_screen(im.point + Vec3(kP.x(), kP.y(), 0)) - p) > 1.0f)
                    arrow_item(Mark::impulse, static_cast<int>(im.b), im.point, im.point + Vec3(kP.x(), kP.y(), 0),
                               components(im.impulse, dim), c.impulse);
                continue;
            }
            role_a.push_back(im.a);
            role_b.push_back(im.b);
            // r vectors (not in 1D, where every lever arm is along the line of impact).
            if (dim > 1) {
                const std::pair<std::size_t, const char*> ends[2] = {{im.a, "r_{a}"}, {im.b, "r_{b}"}};
                for (const auto& [i, name] : ends) {
                    if (kind(i) == Kind::plane || kind(i) == Kind::none) continue;
                    const Vec3& x = frame.bodies[i].x;
                    const ImVec2 from = to_screen(x);
                    if (norm(p - from) < 4.0f) continue;
                    const int k = arrow_item(Mark::lever_arm, static_cast<int>(i), x, im.point,
                                             components(im.point - x, dim), c.lever);
                    const ImVec2 d = unit(p - from);
                    pending.push_back({k, (from + p) * 0.5f, ImVec2(-d.y, d.x), name, {}, c.lever, false});
                }
            }
            // The unit normal n, drawn beside the impulse (they are parallel without
            // friction), with the tangent line through the point. In 1D n is +x, the axis.
            if (dim > 1) {
                const Vec3 nw = im.normal.normalized();
                const Vec3 tip = im.point + nw * (style_.px(style_.normal_length) / scale_);
                const int k = arrow_item(Mark::normal, -1, im.point, tip, components(nw, dim), c.normal);
                const ImVec2 nd = unit(to_screen(tip) - p);
                const ImVec2 td(-nd.y, nd.x);
                const ImVec2 n0 = p + td * style_.px(18.0f);
                normal_labels.push_back({k, n0 + nd * style_.px(style_.normal_length), nd, "n", {}, c.normal, false});
            }
            // The impulse on b, and its reaction on a when a moves.
            const Vec3 kP = im.impulse * k_impulse_;
            const ImVec2 tip = to_screen(im.point + Vec3(kP.x(), kP.y(), 0));
            if (norm(tip - p) > 1.0f) {
                const Vec3 on_b = im.impulse;
                // The number printed: in 1D the signed impulse along +x (the page's J), else |P|.
                const double shown = dim == 1 ? on_b.x() : Vec2(on_b.x(), on_b.y()).norm();
                if (!scene_.bodies[im.a].is_static()) {
                    const int k = arrow_item(Mark::impulse, static_cast<int>(im.a), im.point,
                                             im.point - Vec3(kP.x(), kP.y(), 0), components(-on_b, dim), c.impulse);
                    items[static_cast<std::size_t>(k)].faint = true;
                    const ImVec2 rtip = p - (tip - p);
                    pending.push_back({k, rtip, unit(p - tip), "\u2212P", {}, c.impulse, false});
                }
                const int k = arrow_item(Mark::impulse, static_cast<int>(im.b), im.point,
                                         im.point + Vec3(kP.x(), kP.y(), 0), components(on_b, dim), c.impulse);
                pending.insert(
                    pending.begin(),
                    {k, tip, unit(tip - p), "P = " + format_number(shown) + " N s", {shown}, c.impulse, false});
                labelled[im.a] = labelled[im.b] = true;
            }
            Annotation dot;
            dot.kind = Mark::contact;
            dot.from = dot.to = im.point;
            dot.value = components(im.point, dim);
            dot.colour = c.impulse;
            dot.box =
                ImVec4(p.x - style_.px(4.5f), p.y - style_.px(4.5f), p.x + style_.px(4.5f), p.y + style_.px(4.5f));
            add(std::move(dot));
        }
    }

    // Velocities and spins (labelled as motion_labels() says).
    if (decor.velocities) {
        // (A 2D body's |v| and |ω| are those of its 3D form: z and the in-plane spin are 0.)
        std::vector<bool> counted(n, false);
        for (std::size_t i = 0; i < n; ++i) counted[i] = !scene_.bodies[i].is_static() && decor.in_focus(i);
        const FrameMotionLabels labels_of = motion_labels(frame, counted);
        for (std::size_t i = 0; i < n; ++i) {
            if (!counted[i]) continue;
            const BodyState& s = frame.bodies[i];
            const ImVec2 from = to_screen(s.x);
            const ImVec2 tip = to_screen(s.x + k_velocity_ * s.v);
            if (norm(tip - from) > 1.0f) {
                const int k = arrow_item(Mark::velocity, static_cast<int>(i), s.x, s.x + k_velocity_ * s.v,
                                         components(s.v, dim), c.velocity);
                // 1D: the signed velocity along +x; else the speed.
                const double shown = dim == 1 ? s.v.x() : xy(s.v).norm();
                if (labels_of.speed[i]) {
                    pending.push_back(
                        {k, tip, unit(tip - from), "v = " + format_number(shown) + " m/s", {shown}, c.velocity, false});
                    labelled[i] = true;
                }
            }
            const double w = s.w.z();
            if (max_spin_ > 0 && std::abs(w) > 1e-9 * max_spin_ && std::abs(w) > 1e-9) {
                const float r = spin_radius(i, scale_);
                const double sweep = std::max(35.0, 240.0 * std::abs(w) / max_spin_) * kPi / 180.0;
                Annotation a;
                a.kind = Mark::spin;
                a.body = static_cast<int>(i);
                a.from = a.to = s.x;
                a.value = dim == 3 ? components(s.w, 3) : std::vector<double>{w};
                a.sweep = w > 0 ? sweep : -sweep;
                a.radius = r;
                a.colour = c.spin;
                a.box = ImVec4(from.x - r, from.y - r, from.x + r, from.y + r);
                const int k = add(std::move(a));
                if (labels_of.spin[i]) {
                    pending.push_back({k,
                                       from - ImVec2(0, r),
                                       ImVec2(0, -1),
                                       "\u03C9 = " + format_number(w) + " rad/s",
                                       {w},
                                       c.spin,
                                       false});
                    labelled[i] = true;
                }
            }
        }
    }

    // Marked points of bodies (a handle, a sweet spot): a ring and its name, and where the
    // velocities are drawn the point's own velocity v + ω × r: "at rest" below 1/1000 of the
    // frame's largest speed (a sweet spot given to 5 digits leaves its handle 10^-4 of that).
    double fastest = 0;
    for (const BodyState& s : frame.bodies) fastest = std::max(fastest, s.v.norm());
    for (const PointMark& m : decor.points) {
        if (m.body >= n || !decor.in_focus(m.body)) continue;  // a figure about another pair
        if (m.velocity && !decor.velocities) continue;         // a point shown for its velocity
        const BodyState& s = frame.bodies[m.body];
        const Vec3 p = point_position(m, s, dim);
        Annotation a;
        a.kind = Mark::point;
        a.body = static_cast<int>(m.body);
        a.from = a.to = p;
        a.value = components(p, dim);
        a.text = m.name;
        a.colour = c.ink;
        const ImVec2 at = to_screen(p);
        a.box = ImVec4(at.x - style_.px(5), at.y - style_.px(5), at.x + style_.px(5), at.y + style_.px(5));
        const int k = add(std::move(a));
        const bool moving = m.velocity && decor.velocities;
        const Vec3 vp = point_velocity(m, s, dim);
        const ImVec2 tip = to_screen(p + k_velocity_ * vp);
        if (moving && vp.norm() > 1e-3 * fastest) {
            const int kv = arrow_item(Mark::point_velocity, static_cast<int>(m.body), p, p + k_velocity_ * vp,
                                      components(vp, dim), c.velocity);
            const double shown = dim == 1 ? vp.x() : xy(vp).norm();
            pending.push_back({kv,
                               tip,
                               unit(tip - at),
                               m.name + ": v = " + format_number(shown) + " m/s",
                               {shown},
                               c.velocity,
                               true});
        } else {
            pending.push_back({k, at, ImVec2(0, 1), moving ? m.name + ": at rest" : m.name, {}, c.ink, true});
        }
    }

    // Positive directions. 1D: an arrow along +x above each moving block ("+v"), as in the
    // page's figure. 2D: one glyph in the view's lower left corner: +x, +y and the
    // counter-clockwise sense of +ω (velocities and spins are measured that way).
    std::vector<std::pair<ImVec2, std::string>> direction_labels;  // top-left, text
    std::vector<int> direction_items;
    const auto direction_item = [&](ImVec2 a0, ImVec2 a1, std::vector<double> value) {
        Annotation a;
        a.kind = Mark::direction;
        a.from = to_world(a0);
        a.to = to_world(a1);
        a.value = std::move(value);
        a.colour = c.muted;
        a.box = ImVec4(std::min(a0.x, a1.x), std::min(a0.y, a1.y), std::max(a0.x, a1.x), std::max(a0.y, a1.y));
        return add(std::move(a));
    };
    if (decor.directions && dim == 1) {
        for (std::size_t i = 0; i < n; ++i) {
            if (scene_.bodies[i].is_static() || kind(i) == Kind::none) continue;
            const BodyState& s = frame.bodies[i];
            Vec2 l(1e300, 1e300), h(-1e300, -1e300);
            extent(i, s, &l, &h);
            const ImVec2 top = to_screen(Vec3(s.x.x(), h.y(), 0));
            const float len = style_.px(56.0f);
            const ImVec2 a0(top.x - 0.5f * len, top.y - style_.px(34.0f));
            const int k = direction_item(a0, a0 + ImVec2(len, 0), {1.0});
            items[static_cast<std::size_t>(k)].body = static_cast<int>(i);
            pending.push_back({k, a0 + ImVec2(len, 0), ImVec2(1, 0), "+v", {}, c.muted, false});
        }
    }
    if (decor.directions && dim == 2) {
        const float L = style_.px(46.0f), r = style_.px(13.0f);
        const ImVec2 o(viewport_.x + style_.px(36.0f), viewport_.w - style_.px(36.0f));
        direction_items.push_back(direction_item(o, o + ImVec2(L, 0), {1.0, 0.0}));
        direction_items.push_back(direction_item(o, o - ImVec2(0, L), {0.0, 1.0}));
        const ImVec2 arc = o + ImVec2(0.55f * L, -0.55f * L);
        Annotation a;
        a.kind = Mark::direction;
        a.from = a.to = to_world(arc);
        a.value = {1.0};  // counter-clockwise
        a.sweep = 1.5 * kPi;
        a.radius = r;
        a.colour = c.muted;
        a.box = ImVec4(arc.x - r, arc.y - r, arc.x + r, arc.y + r);
        direction_items.push_back(add(std::move(a)));
        const float fh = fonts.text->FontSize;
        direction_labels.push_back({o + ImVec2(L + style_.px(6.0f), -0.5f * fh), "+x"});
        direction_labels.push_back(
            {o + ImVec2(-0.5f * rich_text_size(fonts, fonts.text, "+y").x, -L - fh - style_.px(4.0f)), "+y"});
        direction_labels.push_back({arc + ImVec2(r + style_.px(5.0f), -r - 0.3f * fh), "+\u03C9"});
    }
    // Labels drawn where they are, without a backing.
    const auto fixed_label = [&](int of, ImVec2 at, const std::string& text, Colour colour, bool small) {
        ImFont* font = small ? fonts.small : fonts.text;
        const ImVec2 size = rich_text_size(fonts, font, text);
        Annotation a;
        a.kind = Mark::label;
        a.of = of;
        a.text = text;
        a.colour = colour;
        a.small = small;
        a.font_px = font->FontSize;
        a.faint = true;  // labels: no backing
        a.anchor = at;
        a.from = a.to = to_world(at);
        a.box = ImVec4(at.x, at.y, at.x + size.x, at.y + size.y);
        if (of >= 0) a.body = items[static_cast<std::size_t>(of)].body;
        if (labels) labels->reserve(a.box);
        return add(std::move(a));
    };
    for (std::size_t k = 0; k < direction_labels.size(); ++k) {
        const auto& [at, text] = direction_labels[k];
        fixed_label(direction_items[k], ImVec2(std::round(at.x), std::round(at.y)), text, c.muted, false);
    }

    if (!decor.labels || !labels) return items;
    if (dim == 1) {
        const float y = to_screen(Vec3::Zero()).y;
        const float x1 = viewport_.z - style_.px(8);
        const ImVec2 size = rich_text_size(fonts, fonts.text, "+x");
        fixed_label(-1, ImVec2(x1 - size.x, y + style_.px(6)), "+x", c.ink, false);
    }
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
    // Whether an arrow's shaft (velocity, impulse, a point's velocity) passes through a box.
    const auto crosses_arrow = [&](const Annotations& all, ImVec4 box) {
        for (const Annotation& a : all) {
            if (a.kind != Mark::velocity && a.kind != Mark::impulse && a.kind != Mark::point_velocity) continue;
            if (segment_hits_box(to_screen(a.from), to_screen(a.to), box)) return true;
        }
        return false;
    };
    // Arrows too (the 1D "+v" arrows included): a label goes over one only when no free place is near.
    for (const Annotation& a : items) {
        if (a.kind != Mark::velocity && a.kind != Mark::impulse && a.kind != Mark::point_velocity &&
            a.kind != Mark::direction)
            continue;
        const ImVec2 p = to_screen(a.from), q = to_screen(a.to);
        if (norm(q - p) < 1.0f) continue;
        const ImVec2 d = unit(q - p), side = ImVec2(-d.y, d.x) * style_.px(4.0f);
        labels->avoid({p + side, q + side, q - side, p - side});
    }
    // Body names: inside the body when they fit, else above it (with many bodies only on those
    // with a label: kManyBodies).
    std::size_t moving = 0;
    for (std::size_t i = 0; i < n; ++i) moving += !scene_.bodies[i].is_static() && decor.in_focus(i);
    const bool many = moving > kManyBodies;
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
        // A body outside the view (a figure framed on another pair) gets no name; one cut by
        // the view's edge (a long cushion) has its name in the part that shows.
        const ImVec2 s_lo = to_screen(Vec3(l.x(), h.y(), 0)), s_hi = to_screen(Vec3(h.x(), l.y(), 0));
        const float vx0 = std::max(s_lo.x, viewport_.x), vx1 = std::min(s_hi.x, viewport_.z);
        const float vy0 = std::max(s_lo.y, viewport_.y), vy1 = std::min(s_hi.y, viewport_.w);
        if (vx0 >= vx1 || vy0 >= vy1) continue;
        ImVec2 centre = to_screen(frame.bodies[i].x);
        if (centre.x < viewport_.x || centre.x > viewport_.z) centre.x = 0.5f * (vx0 + vx1);
        if (centre.y < viewport_.y || centre.y > viewport_.w) centre.y = 0.5f * (vy0 + vy1);
        if (size.x < 0.75f * w_px && size.y < 0.4f * h_px) {
            // Below the centre marker, inside; above it when the body's velocity arrow points
            // down from the centre (a falling ball), so that the arrow does not cross its name.
            const float below = centre.y + style_.lw(style_.com) + style_.px(4);
            const float above = centre.y - style_.lw(style_.com) - style_.px(4) - size.y;
            const float x0 = centre.x - 0.5f * size.x;
            const bool crossed = crosses_arrow(items, ImVec4(x0, below, x0 + size.x, below + size.y));
            const ImVec2 at(
                x0, crossed && !crosses_arrow(items, ImVec4(x0, above, x0 + size.x, above + size.y)) ? above : below);
            fixed_label(body_item[i], ImVec2(std::round(at.x), std::round(at.y)), name, c.ink, true);
        } else if (!many || labelled[i]) {
            pending.push_back({body_item[i], ImVec2(centre.x, s_lo.y), ImVec2(0, -1), name, {}, c.ink, true});
        }
    }
    const float pad = style_.px(3.0f), gap = style_.px(6.0f);
    for (const LabelRequest& p : pending) {
        Annotation a = placed_label(fonts, labels, items, p, pad, gap);
        if (!labels->last_free()) continue;  // no free place near: left out, never overlapping
        a.from = a.to = to_world(p.anchor);
        add(std::move(a));
    }
    return items;
}

}  // namespace collide::render
