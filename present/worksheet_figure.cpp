#include "present/worksheet_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "engine/shape2d.h"
#include "render/style.h"
#include "teach/html.h"

namespace collide {

namespace {

// Drawing units: px_per_mm of them to a printed millimetre; the text sizes are in them.
constexpr double kPxPerMm = 3.5;
constexpr double kFont = 12.0;      // labels (8.6 pt printed); subscripts 9 (html::svg_math)
constexpr double kMargin = 30.0;    // round the scene: room for labels and the normal's arrow
constexpr double kNormalPx = 42.0;  // the unit normal's arrow
constexpr double kSpinPx = 13.0;    // a spin arc's radius

const render::Palette kColours;

Vec2 flat(const Vec3& v) { return Vec2(v.x(), v.y()); }

std::string css(render::Colour c) { return render::css_colour(c); }

// Full precision for the data- attributes (a test reads them back).
std::string full(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", x == 0.0 ? 0.0 : x);
    return buf;
}
std::string px(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", std::abs(x) < 0.05 ? 0.0 : x);
    return buf;
}

struct Box {
    double x0, y0, x1, y1;
    bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// Does the segment (a, b) cross the box? (Liang-Barsky clipping.)
bool crosses(const Box& r, Vec2 a, Vec2 b) {
    double t0 = 0, t1 = 1;
    const Vec2 d = b - a;
    const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
    const double q[4] = {a.x() - r.x0, r.x1 - a.x(), a.y() - r.y0, r.y1 - a.y()};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0) {
            if (q[i] < 0) return false;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    return true;
}

// A label's width in drawing units: its characters, a subscript's smaller (html::svg_math).
double text_width(const std::string& text) {
    double w = 0;
    bool sub = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '_') {
            sub = true;
            continue;
        }
        if (c == '{' || c == '}') continue;
        if ((c & 0xC0) == 0x80) continue;  // a UTF-8 continuation byte
        w += (sub ? 9.0 : kFont) * 0.62;
    }
    return w;
}

// The labels, placed one after another where they cover no label placed before, no mark
// (arrows, points) and stay inside the figure: the first free place of a ring of candidates
// round each anchor, nearest first.
class Labels {
public:
    Labels(double w, double h) : w_(w), h_(h) {}
    void avoid_segment(Vec2 a, Vec2 b) { segments_.push_back({a, b}); }
    void avoid_box(const Box& b) { boxes_.push_back(b); }
    // Places `text` near `anchor`, preferring `dir` (a unit vector, screen) from it; returns
    // the SVG text element.
    std::string place(const std::string& text, Vec2 anchor, Vec2 dir, render::Colour colour, bool bold = false) {
        const double tw = text_width(text), th = kFont;
        Box best{};
        bool found = false;
        const double base = std::atan2(dir.y(), dir.x());
        for (double dist : {7.0, 12.0, 18.0, 26.0, 36.0, 48.0}) {
            for (int k = 0; k < 16 && !found; ++k) {
                // Round the preferred direction: 0, +1, -1, +2, -2 ... sixteenths of a turn.
                const int step = (k + 1) / 2 * (k % 2 ? 1 : -1);
                const double a = base + step * kPi / 8;
                const Vec2 c = anchor + dist * Vec2(std::cos(a), std::sin(a));
                // The box's side towards the anchor at distance `dist`.
                const double cx = c.x() + std::cos(a) * tw / 2, cy = c.y() + std::sin(a) * th / 2;
                const Box b{cx - tw / 2, cy - th / 2, cx + tw / 2, cy + th / 2};
                if (free(b)) {
                    best = b;
                    found = true;
                }
            }
            if (found) break;
        }
        if (!found) {  // nowhere free: beside the anchor, said in the element (a test fails on it)
            best = {anchor.x() + 4, anchor.y() - th, anchor.x() + 4 + tw, anchor.y()};
        }
        boxes_.push_back(best);
        std::ostringstream o;
        o << "<text x=\"" << px(best.x0) << "\" y=\"" << px(best.y1 - 2.5) << "\" fill=\"" << css(colour) << "\""
          << (bold ? " font-weight=\"bold\"" : "") << " data-label=\"" << html::escape(text) << "\" data-box=\""
          << px(best.x0) << " " << px(best.y0) << " " << px(best.x1) << " " << px(best.y1) << "\""
          << (found ? "" : " data-crowded=\"true\"") << ">" << html::svg_math(text) << "</text>\n";
        return o.str();
    }

private:
    bool free(const Box& b) const {
        if (b.x0 < 1 || b.y0 < 1 || b.x1 > w_ - 1 || b.y1 > h_ - 1) return false;
        for (const Box& o : boxes_)
            if (b.overlaps(o)) return false;
        const Box grown{b.x0 - 1.5, b.y0 - 1.5, b.x1 + 1.5, b.y1 + 1.5};
        for (const auto& [p, q] : segments_)
            if (crosses(grown, p, q)) return false;
        return true;
    }
    double w_, h_;
    std::vector<Box> boxes_;
    std::vector<std::pair<Vec2, Vec2>> segments_;
};

// A body's outline in world coordinates at a pose: a polygon's corners, a disc's centre and
// radius; a half-plane has none (drawn across the figure).
struct Outline {
    std::vector<Vec2> corners;
    double radius = 0.0;  // a disc
    Vec2 centre = Vec2::Zero();
    double angle = 0.0;
};
Outline outline(const Shape2& s, const Vec2& x, double angle) {
    Outline o;
    o.centre = x;
    o.angle = angle;
    const Pose2 pose{x, angle};
    if (s.kind == Shape2::Kind::polygon)
        for (int i = 0; i < s.polygon.count; ++i) o.corners.push_back(pose.apply(s.polygon.vertices[i]));
    else if (s.kind == Shape2::Kind::disc) o.radius = s.radius;
    return o;
}

// The length of the scale bar: 1, 2 or 5 times a power of ten, near a fifth of `extent`.
double nice_length(double extent) {
    const double target = extent / 5;
    const double p = std::pow(10.0, std::floor(std::log10(target)));
    for (double m : {5.0, 2.0, 1.0})
        if (m * p <= target * 1.5) return m * p;
    return p;
}

// "A", "B": a body's name as a subscript when it is short; else none ("v", "ω").
std::string with_name(const std::string& symbol, const std::string& name) {
    if (name.size() <= 2 && name.find_first_of(" _{}") == std::string::npos) return symbol + "_" + name;
    return symbol;
}

}  // namespace

WorksheetFigure worksheet_figure(const StudentSheet& s, double max_height_mm, const std::string& id) {
    WorksheetFigure fig;
    const Scene& sc = s.lesson.scene;
    if (sc.dimension != 2) return fig;
    const std::size_t n = sc.bodies.size();

    // ---- What is drawn, in world coordinates ----
    std::vector<Outline> start(n);
    for (std::size_t i = 0; i < n; ++i)
        start[i] = outline(sc.bodies[i].shape2, sc.bodies[i].body2.position, sc.bodies[i].body2.angle);
    struct Hit {
        const WorkedCollision* w;
        Outline a, b;
        bool a_moved, b_moved;
    };
    std::vector<Hit> hits;
    for (const WorkedCollision& w : s.worked) {
        Hit h{&w, outline(sc.bodies[w.a].shape2, w.problem.a.b2.position, w.problem.a.b2.angle),
              outline(sc.bodies[w.b].shape2, w.problem.b.b2.position, w.problem.b.b2.angle), false, false};
        const auto moved = [&](std::size_t i, const Body2& at) {
            const Body2& b0 = sc.bodies[i].body2;
            return !sc.bodies[i].is_static() && sc.bodies[i].shape2.kind != Shape2::Kind::half_plane &&
                   ((at.position - b0.position).norm() > 1e-9 || std::abs(at.angle - b0.angle) > 1e-9);
        };
        h.a_moved = moved(w.a, w.problem.a.b2);
        h.b_moved = moved(w.b, w.problem.b.b2);
        hits.push_back(h);
    }

    // The bounding box: the bodies (at the start and at each hit), the contact points and the
    // origin (the givens' positions are measured from it).
    Vec2 lo(0, 0), hi(0, 0);
    const auto grow = [&](const Vec2& p) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    };
    const auto grow_outline = [&](const Outline& o) {
        for (const Vec2& c : o.corners) grow(c);
        if (o.radius > 0) {
            grow(o.centre - Vec2(o.radius, o.radius));
            grow(o.centre + Vec2(o.radius, o.radius));
        }
        if (o.corners.empty() && o.radius == 0) grow(o.centre);
    };
    for (std::size_t i = 0; i < n; ++i)
        if (sc.bodies[i].shape2.kind != Shape2::Kind::half_plane) grow_outline(start[i]);
    for (const Hit& h : hits) {
        if (sc.bodies[h.w->a].shape2.kind != Shape2::Kind::half_plane) grow_outline(h.a);
        if (sc.bodies[h.w->b].shape2.kind != Shape2::Kind::half_plane) grow_outline(h.b);
        grow(flat(h.w->problem.point));
    }
    // Velocities: one scale, the fastest a fifth of the scene's larger side (short of the body it will hit).
    double vmax = 0, wmax = 0;
    for (const SceneBody& b : sc.bodies)
        if (!b.is_static()) {
            vmax = std::max(vmax, b.body2.v.norm());
            wmax = std::max(wmax, std::abs(b.body2.w));
        }
    const double extent0 = std::max({hi.x() - lo.x(), hi.y() - lo.y(), 1e-3});
    const double kv = vmax > 0 ? extent0 / 5 / vmax : 0.0;  // m per (m/s)
    for (const SceneBody& b : sc.bodies)
        if (!b.is_static()) grow(b.body2.position + kv * b.body2.v);
    // A half-plane: the scene's nearest point of its edge, and a strip of its solid side.
    for (const SceneBody& b : sc.bodies)
        if (b.shape2.kind == Shape2::Kind::half_plane) {
            const Vec2 c = 0.5 * (lo + hi);
            const Vec2 nrm = b.shape2.normal;
            grow(c - (nrm.dot(c) - b.shape2.offset) * nrm);
        }

    // ---- World to drawing units ----
    const double max_w = kWorksheetFigureWidthMm * kPxPerMm, max_h = max_height_mm * kPxPerMm;
    const double ext_x = std::max(hi.x() - lo.x(), 1e-3), ext_y = std::max(hi.y() - lo.y(), 1e-3);
    const double scale = std::min((max_w - 2 * kMargin) / ext_x, (max_h - 2 * kMargin - 16) / ext_y);  // px per m
    const double W = ext_x * scale + 2 * kMargin, H = ext_y * scale + 2 * kMargin + 16;  // 16: the scale bar's row
    const auto X = [&](double x) { return kMargin + (x - lo.x()) * scale; };
    const auto Y = [&](double y) { return kMargin + (hi.y() - y) * scale; };
    const auto P = [&](const Vec2& p) { return Vec2(X(p.x()), Y(p.y())); };
    fig.width_mm = W / kPxPerMm;
    fig.height_mm = H / kPxPerMm;

    std::ostringstream o, marks;
    Labels labels(W, H);
    const std::string clip = "ws-clip-" + id;
    o << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"setup-figure\" viewBox=\"0 0 " << px(W) << " " << px(H)
      << "\" width=\"" << px(fig.width_mm) << "mm\" height=\"" << px(fig.height_mm)
      << "mm\" font-family=\"DejaVu Sans, Arial, sans-serif\" font-size=\"" << kFont
      << "\" role=\"img\" aria-label=\"This student's set-up\">\n<defs><clipPath id=\"" << clip
      << "\"><rect x=\"0\" y=\"0\" width=\"" << px(W) << "\" height=\"" << px(H - 16) << "\"/></clipPath></defs>\n";

    const auto arrow = [&](Vec2 a, Vec2 b, render::Colour colour, double width, bool dashed) {
        const Vec2 d = b - a;
        const double len = d.norm();
        std::ostringstream g;
        if (len < 1.0) return g.str();
        const Vec2 u = d / len, nrm(-u.y(), u.x());
        const double head = std::min(9.0, 0.5 * len), half = 0.4 * head + width * 0.5;
        const Vec2 base = b - head * u;
        g << "<line x1=\"" << px(a.x()) << "\" y1=\"" << px(a.y()) << "\" x2=\"" << px(base.x()) << "\" y2=\""
          << px(base.y()) << "\" stroke=\"" << css(colour) << "\" stroke-width=\"" << width << "\""
          << (dashed ? " stroke-dasharray=\"5 3\"" : "") << "/>\n<polygon points=\"" << px(b.x()) << "," << px(b.y())
          << " " << px(base.x() + half * nrm.x()) << "," << px(base.y() + half * nrm.y()) << " "
          << px(base.x() - half * nrm.x()) << "," << px(base.y() - half * nrm.y()) << "\" fill=\"" << css(colour)
          << "\"/>\n";
        labels.avoid_segment(a, b);
        return g.str();
    };
    const auto vector_data = [](const std::string& name, const Vec2& from, const Vec2& d) {
        return " data-vector=\"" + name + "\" data-x=\"" + full(from.x()) + "\" data-y=\"" + full(from.y()) +
               "\" data-dx=\"" + full(d.x()) + "\" data-dy=\"" + full(d.y()) + "\"";
    };
    const auto shape_svg = [&](const Outline& ol, const std::string& fill, render::Colour stroke, bool dashed) {
        std::ostringstream g;
        const std::string style = " fill=\"" + fill + "\" stroke=\"" + css(stroke) + "\" stroke-width=\"1.6\"" +
                                  (dashed ? " stroke-dasharray=\"5 3\"" : "");
        if (!ol.corners.empty()) {
            g << "<polygon points=\"";
            for (std::size_t k = 0; k < ol.corners.size(); ++k)
                g << (k ? " " : "") << px(X(ol.corners[k].x())) << "," << px(Y(ol.corners[k].y()));
            g << "\"" << style << "/>\n";
        } else if (ol.radius > 0) {
            const Vec2 c = P(ol.centre), rim = P(ol.centre + ol.radius * Vec2(std::cos(ol.angle), std::sin(ol.angle)));
            g << "<circle cx=\"" << px(c.x()) << "\" cy=\"" << px(c.y()) << "\" r=\"" << px(ol.radius * scale) << "\""
              << style << "/>\n<line x1=\"" << px(c.x()) << "\" y1=\"" << px(c.y()) << "\" x2=\"" << px(rim.x())
              << "\" y2=\"" << px(rim.y()) << "\" stroke=\"" << css(stroke) << "\" stroke-width=\"1\"/>\n";
        }
        // The outline, for the labels to keep off.
        for (std::size_t k = 0; k < ol.corners.size(); ++k)
            labels.avoid_segment(P(ol.corners[k]), P(ol.corners[(k + 1) % ol.corners.size()]));
        for (int k = 0; ol.radius > 0 && k < 24; ++k) {
            const double t0 = 2 * kPi * k / 24, t1 = 2 * kPi * (k + 1) / 24;
            labels.avoid_segment(P(ol.centre + ol.radius * Vec2(std::cos(t0), std::sin(t0))),
                                 P(ol.centre + ol.radius * Vec2(std::cos(t1), std::sin(t1))));
        }
        const Vec2 c = P(ol.centre);
        g << "<circle cx=\"" << px(c.x()) << "\" cy=\"" << px(c.y()) << "\" r=\"2.6\" fill=\"" << css(stroke)
          << "\"/>\n";
        labels.avoid_box({c.x() - 3, c.y() - 3, c.x() + 3, c.y() + 3});
        return g.str();
    };

    // ---- Axes through the origin, and the scale bar ----
    {
        const Vec2 origin = P(Vec2(0, 0));
        const double ax0 = 4, ax1 = W - 4, ay0 = 4, ay1 = H - 20;
        o << "<g data-axes=\"origin\" stroke=\"" << css(kColours.muted) << "\" stroke-width=\"0.8\">\n";
        o << "<line x1=\"" << px(ax0) << "\" y1=\"" << px(origin.y()) << "\" x2=\"" << px(ax1 - 6) << "\" y2=\""
          << px(origin.y()) << "\"/>\n<line x1=\"" << px(origin.x()) << "\" y1=\"" << px(ay1) << "\" x2=\""
          << px(origin.x()) << "\" y2=\"" << px(ay0 + 6) << "\"/>\n</g>\n";
        o << "<polygon points=\"" << px(ax1) << "," << px(origin.y()) << " " << px(ax1 - 7) << "," << px(origin.y() - 3)
          << " " << px(ax1 - 7) << "," << px(origin.y() + 3) << "\" fill=\"" << css(kColours.muted)
          << "\"/>\n<polygon points=\"" << px(origin.x()) << "," << px(ay0) << " " << px(origin.x() - 3) << ","
          << px(ay0 + 7) << " " << px(origin.x() + 3) << "," << px(ay0 + 7) << "\" fill=\"" << css(kColours.muted)
          << "\"/>\n";
        labels.avoid_segment(Vec2(ax0, origin.y()), Vec2(ax1, origin.y()));
        labels.avoid_segment(Vec2(origin.x(), ay0), Vec2(origin.x(), ay1));
        marks << labels.place("x", Vec2(ax1 - 4, origin.y()), Vec2(0, 1), kColours.muted);
        marks << labels.place("y", Vec2(origin.x(), ay0 + 4), Vec2(1, 0), kColours.muted);
        const double bar = nice_length(std::max(ext_x, ext_y));
        const double bx = 6, by = H - 8, bw = bar * scale;
        o << "<g data-scale-bar=\"" << full(bar) << "\" stroke=\"" << css(kColours.ink) << "\" stroke-width=\"1.4\">\n"
          << "<line x1=\"" << px(bx) << "\" y1=\"" << px(by) << "\" x2=\"" << px(bx + bw) << "\" y2=\"" << px(by)
          << "\"/>\n<line x1=\"" << px(bx) << "\" y1=\"" << px(by - 4) << "\" x2=\"" << px(bx) << "\" y2=\""
          << px(by + 3) << "\"/>\n<line x1=\"" << px(bx + bw) << "\" y1=\"" << px(by - 4) << "\" x2=\"" << px(bx + bw)
          << "\" y2=\"" << px(by + 3) << "\"/>\n</g>\n";
        char text[48];
        std::snprintf(text, sizeof text, "%g m", bar);
        o << "<text x=\"" << px(bx + bw + 5) << "\" y=\"" << px(by + 4) << "\" fill=\"" << css(kColours.ink) << "\">"
          << text << "</text>\n";
        labels.avoid_box({bx, by - 6, bx + bw + 5 + text_width(text), by + 6});
    }

    // ---- The bodies at the start ----
    o << "<g clip-path=\"url(#" << clip << ")\">\n";
    int moving = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const SceneBody& b = sc.bodies[i];
        const Body2& b2 = b.body2;
        o << "<g data-body=\"" << html::escape(b.name) << "\" data-x=\"" << full(b2.position.x()) << "\" data-y=\""
          << full(b2.position.y()) << "\" data-angle=\"" << full(b2.angle) << "\">\n";
        if (b.shape2.kind == Shape2::Kind::half_plane) {
            // The edge across the figure, the solid side shaded.
            const Vec2 nrm = b.shape2.normal, t(-nrm.y(), nrm.x());
            const Vec2 c = 0.5 * (lo + hi);
            const Vec2 on = c - (nrm.dot(c) - b.shape2.offset) * nrm;
            const double L = 4 * (ext_x + ext_y) + 1, depth = 1.5 * (ext_x + ext_y) + 1;
            const Vec2 p0 = on - L * t, p1 = on + L * t, p2 = p1 - depth * nrm, p3 = p0 - depth * nrm;
            o << "<polygon points=\"" << px(X(p0.x())) << "," << px(Y(p0.y())) << " " << px(X(p1.x())) << ","
              << px(Y(p1.y())) << " " << px(X(p2.x())) << "," << px(Y(p2.y())) << " " << px(X(p3.x())) << ","
              << px(Y(p3.y())) << "\" fill=\"" << css(kColours.static_fill) << "\" stroke=\"" << css(kColours.ink)
              << "\" stroke-width=\"1.6\"/>\n</g>\n";
            continue;
        }
        const std::string fill =
            b.is_static() ? css(kColours.static_fill) : css(kColours.fills[moving % render::Palette::kFills]);
        if (!b.is_static()) ++moving;
        o << shape_svg(start[i], fill, kColours.ink, false) << "</g>\n";
    }
    // The bodies where they touch, dashed, in their own colour's dark.
    for (std::size_t k = 0; k < hits.size(); ++k) {
        const Hit& h = hits[k];
        for (int side = 0; side < 2; ++side) {
            const bool moved = side ? h.b_moved : h.a_moved;
            if (!moved) continue;
            const std::size_t i = side ? h.w->b : h.w->a;
            const Body2& at = side ? h.w->problem.b.b2 : h.w->problem.a.b2;
            int m = 0;
            for (std::size_t j = 0; j < i; ++j) m += !sc.bodies[j].is_static();
            o << "<g data-body-at-hit=\"" << html::escape(sc.bodies[i].name) << "\" data-collision=\"" << h.w->event
              << "\" data-x=\"" << full(at.position.x()) << "\" data-y=\"" << full(at.position.y())
              << "\" data-angle=\"" << full(at.angle) << "\">\n"
              << shape_svg(side ? h.b : h.a, "none", kColours.darks[m % render::Palette::kFills], true) << "</g>\n";
        }
    }
    o << "</g>\n";

    // ---- Each collision: r_a, r_b, n, p ----
    const bool several = hits.size() > 1;
    for (const Hit& h : hits) {
        const WorkedCollision& w = *h.w;
        const std::string k = several ? std::to_string(w.event) : "";
        const Vec2 p = flat(w.problem.point), nrm = flat(w.problem.normal);
        const Vec2 pp = P(p);
        for (int side = 0; side < 2; ++side) {
            const std::size_t i = side ? w.b : w.a;
            if (sc.bodies[i].shape2.kind == Shape2::Kind::half_plane) continue;  // no centre
            const Vec2 x = side ? w.problem.b.b2.position : w.problem.a.b2.position;
            const std::string name = std::string("r_") + (side ? "b" : "a");
            marks << "<g" << vector_data(name, x, p - x) << " data-collision=\"" << w.event << "\">\n"
                  << arrow(P(x), pp, kColours.lever, 1.4, true) << "</g>\n";
        }
        const Vec2 tip = pp + kNormalPx * Vec2(nrm.x(), -nrm.y());
        marks << "<g" << vector_data("n", p, nrm) << " data-collision=\"" << w.event << "\">\n"
              << arrow(pp, tip, kColours.normal, 2.0, false) << "</g>\n";
        marks << "<circle cx=\"" << px(pp.x()) << "\" cy=\"" << px(pp.y()) << "\" r=\"3.2\" fill=\""
              << css(kColours.impulse) << "\" data-point=\"p\" data-collision=\"" << w.event << "\" data-x=\""
              << full(p.x()) << "\" data-y=\"" << full(p.y()) << "\"/>\n";
        labels.avoid_box({pp.x() - 3.5, pp.y() - 3.5, pp.x() + 3.5, pp.y() + 3.5});
    }
    // ---- Velocities and spins at the start ----
    // Each moving body's centre and velocity arrow's tip in the drawing (its labels follow below).
    struct Start {
        const SceneBody* b;
        Vec2 c, tip;
    };
    std::vector<Start> starts;
    for (std::size_t i = 0; i < n; ++i)
        if (!sc.bodies[i].is_static())
            starts.push_back({&sc.bodies[i], P(sc.bodies[i].body2.position),
                              P(sc.bodies[i].body2.position + kv * sc.bodies[i].body2.v)});
    for (const auto& [bp, c, tip] : starts) {
        const SceneBody& b = *bp;
        if (b.body2.v.norm() > 0) {
            marks << "<g" << vector_data("v", b.body2.position, b.body2.v) << " data-body=\"" << html::escape(b.name)
                  << "\">\n"
                  << arrow(c, tip, kColours.velocity, 2.2, false) << "</g>\n";
        }
        if (b.body2.w != 0) {
            const double w = b.body2.w;
            const double sweep = std::max(60.0, 270.0 * std::abs(w) / wmax) * kPi / 180.0;
            // From the top of the circle round the way it turns (counter-clockwise: w > 0;
            // the drawing's y points down, so its angle runs the other way).
            const double a0 = -kPi / 2, a1 = a0 - (w > 0 ? sweep : -sweep);
            const Vec2 s0 = c + kSpinPx * Vec2(std::cos(a0), std::sin(a0)),
                       s1 = c + kSpinPx * Vec2(std::cos(a1), std::sin(a1));
            const Vec2 tangent = (w > 0 ? 1.0 : -1.0) * Vec2(std::sin(a1), -std::cos(a1));
            marks << "<g data-spin=\"" << html::escape(b.name) << "\" data-w=\"" << full(w) << "\">\n<path d=\"M "
                  << px(s0.x()) << " " << px(s0.y()) << " A " << kSpinPx << " " << kSpinPx << " 0 "
                  << (sweep > kPi ? 1 : 0) << " " << (w > 0 ? 0 : 1) << " " << px(s1.x()) << " " << px(s1.y())
                  << "\" fill=\"none\" stroke=\"" << css(kColours.spin) << "\" stroke-width=\"2\"/>\n"
                  << arrow(s1 - 6.0 * tangent, s1 + 3.0 * tangent, kColours.spin, 2.0, false) << "</g>\n";
            for (int k = 0; k < 12; ++k) {  // the arc, for the labels
                const double t0 = a0 + (a1 - a0) * k / 12.0, t1 = a0 + (a1 - a0) * (k + 1) / 12.0;
                labels.avoid_segment(c + kSpinPx * Vec2(std::cos(t0), std::sin(t0)),
                                     c + kSpinPx * Vec2(std::cos(t1), std::sin(t1)));
            }
        }
    }

    // ---- Labels, the most important first ----
    for (std::size_t i = 0; i < n; ++i) {
        const SceneBody& b = sc.bodies[i];
        if (b.shape2.kind == Shape2::Kind::half_plane) {
            const Vec2 nrm = b.shape2.normal;
            const Vec2 c = 0.5 * (lo + hi);
            const Vec2 on = c - (nrm.dot(c) - b.shape2.offset) * nrm;
            // On its solid side, at the end of its edge nearest the figure's lower right.
            const Vec2 t(-nrm.y(), nrm.x()), e = P(on), ts(t.x(), -t.y()), ns(nrm.x(), -nrm.y());
            const Vec2 corner(W - kMargin, H - 20);
            const double reach = std::clamp((corner - e).dot(ts), -0.5 * W, 0.5 * W);
            marks << labels.place(b.name, e + reach * ts - 10.0 * ns, -ns, kColours.ink, true);
            continue;
        }
        // Away from where it moves.
        Vec2 away(0, -1);
        if (b.body2.v.norm() > 0) away = -Vec2(b.body2.v.x(), -b.body2.v.y()).normalized();
        marks << labels.place(b.name, P(b.body2.position), away, kColours.ink, true);
    }
    for (const Hit& h : hits) {
        const WorkedCollision& w = *h.w;
        const std::string k = several ? std::to_string(w.event) : "";
        const Vec2 p = flat(w.problem.point), nrm = flat(w.problem.normal);
        const Vec2 pp = P(p), nd(nrm.x(), -nrm.y());
        marks << labels.place("p" + std::string(k.empty() ? "" : "_" + k), pp, -nd, kColours.impulse);
        marks << labels.place("n" + std::string(k.empty() ? "" : "_" + k), pp + kNormalPx * nd, nd, kColours.normal);
        for (int side = 0; side < 2; ++side) {
            const std::size_t i = side ? w.b : w.a;
            if (sc.bodies[i].shape2.kind == Shape2::Kind::half_plane) continue;
            const Vec2 x = P(side ? w.problem.b.b2.position : w.problem.a.b2.position);
            const Vec2 d = (pp - x).norm() > 0 ? Vec2((pp - x).normalized()) : Vec2(1, 0);
            marks << labels.place(std::string("r_") + (side ? "b" : "a") + k, 0.5 * (x + pp), Vec2(-d.y(), d.x()),
                                  kColours.lever);
        }
    }
    for (const auto& [bp, c, tip] : starts) {
        const SceneBody& b = *bp;
        if (b.body2.v.norm() > 0)
            marks << labels.place(with_name("v", b.name), tip, (tip - c).normalized(), kColours.velocity);
        if (b.body2.w != 0)
            marks << labels.place(with_name("\u03c9", b.name), c + Vec2(0, -kSpinPx), Vec2(0, -1), kColours.spin);
    }
    o << marks.str() << "</svg>\n";
    fig.svg = o.str();
    return fig;
}

}  // namespace collide
