#include "render/draw2d.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/math.h"  // kPi

namespace collide::render {

namespace {

ImVec2 add(ImVec2 a, ImVec2 b) { return ImVec2(a.x + b.x, a.y + b.y); }
ImVec2 sub(ImVec2 a, ImVec2 b) { return ImVec2(a.x - b.x, a.y - b.y); }
ImVec2 mul(ImVec2 a, float s) { return ImVec2(a.x * s, a.y * s); }
float length(ImVec2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }

// The float nearest pi (collide::kPi rounded once), for angles on screen.
constexpr float kPiF = static_cast<float>(kPi);

// Splits rich text into runs: 0 normal, -1 subscript, +1 superscript.
struct Run {
    std::string text;
    int script;
};
std::vector<Run> runs_of(const std::string& s) {
    std::vector<Run> out;
    std::string cur;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if ((s[i] == '_' || s[i] == '^') && i + 1 < s.size() && s[i + 1] == '{') {
            const std::size_t close = s.find('}', i + 2);
            if (close != std::string::npos) {
                if (!cur.empty()) out.push_back({cur, 0});
                cur.clear();
                out.push_back({s.substr(i + 2, close - i - 2), s[i] == '_' ? -1 : 1});
                i = close;
                continue;
            }
        }
        cur += s[i];
    }
    if (!cur.empty()) out.push_back({cur, 0});
    return out;
}

}  // namespace

void draw_arrow(ImDrawList* dl, ImVec2 from, ImVec2 to, Colour colour, float thickness, float head_length,
                float head_width) {
    const ImVec2 d = sub(to, from);
    const float len = length(d);
    if (len < 0.5f) return;
    const float shrink = std::min(1.0f, len / (1.5f * head_length));
    head_length *= shrink;
    head_width *= shrink;
    const ImVec2 u = mul(d, 1.0f / len);
    const ImVec2 n(-u.y, u.x);
    // The shaft stops inside the head so that its square end does not show past the tip.
    const ImVec2 base = sub(to, mul(u, head_length));
    const ImVec2 shaft_end = sub(to, mul(u, head_length * 0.6f));
    if (len > head_length) dl->AddLine(from, shaft_end, colour, thickness);
    // A slightly swept-back head.
    const ImVec2 left = add(base, mul(n, 0.5f * head_width));
    const ImVec2 right = sub(base, mul(n, 0.5f * head_width));
    const ImVec2 notch = add(base, mul(u, head_length * 0.18f));
    // Clockwise on screen for ImGui's anti-aliased fill: tip, right, notch, left or the reverse.
    ImVec2 pts[4] = {to, right, notch, left};
    const float cross = (right.x - to.x) * (left.y - to.y) - (right.y - to.y) * (left.x - to.x);
    if (cross < 0) std::swap(pts[1], pts[3]);
    // A concave quad: two triangles.
    ImVec2 t1[3] = {pts[0], pts[1], pts[2]};
    ImVec2 t2[3] = {pts[0], pts[2], pts[3]};
    dl->AddConvexPolyFilled(t1, 3, colour);
    dl->AddConvexPolyFilled(t2, 3, colour);
}

void draw_curved_arrow(ImDrawList* dl, ImVec2 c, float r, float a0, float a1, Colour colour, float thickness,
                       float head_length, float head_width) {
    // World angles (y up) to screen (y down): negate.
    const float sweep = a1 - a0;
    if (std::abs(sweep) < 1e-3f || r < 1.0f) return;
    const float dir = sweep > 0 ? 1.0f : -1.0f;
    // Leave the head's length of arc for the head.
    const float head_angle = std::min(std::abs(sweep) * 0.6f, head_length / r);
    const float end = a1 - dir * head_angle * 0.75f;
    const int segments = std::max(8, static_cast<int>(std::abs(end - a0) * r / 3.0f));
    dl->PathClear();
    for (int k = 0; k <= segments; ++k) {
        const float a = a0 + (end - a0) * static_cast<float>(k) / static_cast<float>(segments);
        dl->PathLineTo(ImVec2(c.x + r * std::cos(a), c.y - r * std::sin(a)));
    }
    dl->PathStroke(colour, 0, thickness);
    // The head points along the tangent at a1, from the point one head length back on the arc.
    const float ab = a1 - dir * head_angle;
    const ImVec2 tip(c.x + r * std::cos(a1), c.y - r * std::sin(a1));
    const ImVec2 back(c.x + r * std::cos(ab), c.y - r * std::sin(ab));
    const ImVec2 d = sub(tip, back);
    const float len = length(d);
    if (len < 0.5f) return;
    // From 1.5 head lengths back along that chord: draw_arrow draws the head at full size
    // (it shrinks the heads of shorter arrows), 0.3 px off the arc at most for the radii used.
    draw_arrow(dl, sub(tip, mul(d, 1.5f * head_length / len)), tip, colour, thickness, head_length, head_width);
}

void draw_dashed_line(ImDrawList* dl, ImVec2 a, ImVec2 b, Colour colour, float thickness, float dash, float gap) {
    const ImVec2 d = sub(b, a);
    const float len = length(d);
    if (len < 0.5f) return;
    const ImVec2 u = mul(d, 1.0f / len);
    for (float s = 0.0f; s < len; s += dash + gap)
        dl->AddLine(add(a, mul(u, s)), add(a, mul(u, std::min(len, s + dash))), colour, thickness);
}

void draw_com_marker(ImDrawList* dl, ImVec2 c, float r, Colour ink, Colour paper, float angle) {
    dl->AddCircleFilled(c, r, paper, 24);
    for (int q = 0; q < 2; ++q) {  // quarters 0 and 2, turning with the body
        const float a0 = angle + static_cast<float>(q) * kPiF;
        dl->PathClear();
        dl->PathLineTo(c);
        for (int k = 0; k <= 8; ++k) {
            const float a = a0 + 0.5f * kPiF * static_cast<float>(k) / 8.0f;
            dl->PathLineTo(ImVec2(c.x + r * std::cos(a), c.y - r * std::sin(a)));
        }
        // Screen-clockwise order for the fill: reverse (angles grow counter-clockwise on screen).
        std::reverse(dl->_Path.Data, dl->_Path.Data + dl->_Path.Size);
        dl->PathFillConvex(ink);
    }
    dl->AddCircle(c, r, ink, 24, std::max(1.0f, r * 0.22f));
}

ImVec2 rich_text_size(const FontSet& fonts, ImFont* font, const std::string& text) {
    float w = 0.0f;
    for (const Run& r : runs_of(text)) {
        ImFont* f = r.script == 0 ? font : fonts.small;
        w += f->CalcTextSizeA(f->FontSize, 1e9f, 0.0f, r.text.c_str()).x;
    }
    return ImVec2(w, font->FontSize);
}

void draw_rich_text(ImDrawList* dl, const FontSet& fonts, ImFont* font, ImVec2 top_left, Colour colour,
                    const std::string& text) {
    float x = top_left.x;
    for (const Run& r : runs_of(text)) {
        ImFont* f = r.script == 0 ? font : fonts.small;
        // Subscripts sit low (their baseline below the main one), superscripts high.
        float y = top_left.y;
        if (r.script < 0) y += font->FontSize - f->FontSize * 0.78f;
        if (r.script > 0) y -= f->FontSize * 0.12f;
        dl->AddText(f, f->FontSize, ImVec2(std::round(x), std::round(y)), colour, r.text.c_str());
        x += f->CalcTextSizeA(f->FontSize, 1e9f, 0.0f, r.text.c_str()).x;
    }
}

std::string format_fixed(double x, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(x));
    std::string s = buf;
    // "-0.00" is zero.
    bool zero = true;
    for (char c : s)
        if (c >= '1' && c <= '9') zero = false;
    if (x < 0 && !zero) s = "\u2212" + s;
    return s;
}

std::string format_number(double x, int digits) {
    if (x == 0.0 || !std::isfinite(x)) return x == 0.0 ? "0" : "?";
    const double a = std::abs(x);
    if (a >= 1e5 || a < 1e-3) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.*e", digits - 1, a);
        std::string s = buf;  // 1.23e-05 -> 1.23×10⁻⁵
        const std::size_t e = s.find('e');
        const int exponent = std::atoi(s.c_str() + e + 1);
        std::string mant = s.substr(0, e);
        static const char* sup[] = {"\u2070", "\u00B9", "\u00B2", "\u00B3", "\u2074",
                                    "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
        std::string ex = exponent < 0 ? "\u207B" : "";
        const std::string digits_text = std::to_string(std::abs(exponent));
        for (char c : digits_text) ex += sup[c - '0'];
        return (x < 0 ? "\u2212" : "") + mant + "\u00D710" + ex;
    }
    const int magnitude = static_cast<int>(std::floor(std::log10(a)));
    const int decimals = std::max(0, digits - 1 - magnitude);
    return format_fixed(x, decimals);
}

ImVec4 bounds_of(const std::vector<ImVec2>& poly) {
    ImVec4 box(1e30f, 1e30f, -1e30f, -1e30f);
    for (const ImVec2& p : poly) {
        box.x = std::min(box.x, p.x);
        box.y = std::min(box.y, p.y);
        box.z = std::max(box.z, p.x);
        box.w = std::max(box.w, p.y);
    }
    return box;
}

namespace {

// Separating axes: does the rectangle overlap the convex polygon?
bool overlaps(const ImVec4& r, const std::vector<ImVec2>& poly) {
    if (poly.size() < 3) return false;
    const ImVec4 box = bounds_of(poly);
    const float x0 = box.x, y0 = box.y, x1 = box.z, y1 = box.w;
    if (r.x >= x1 || r.z <= x0 || r.y >= y1 || r.w <= y0) return false;
    const ImVec2 corners[4] = {{r.x, r.y}, {r.z, r.y}, {r.z, r.w}, {r.x, r.w}};
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const ImVec2 a = poly[i], b = poly[(i + 1) % poly.size()];
        const ImVec2 n(-(b.y - a.y), b.x - a.x);
        float pmin = 1e30f, pmax = -1e30f, rmin = 1e30f, rmax = -1e30f;
        for (const ImVec2& p : poly) {
            const float d = n.x * p.x + n.y * p.y;
            pmin = std::min(pmin, d);
            pmax = std::max(pmax, d);
        }
        for (const ImVec2& p : corners) {
            const float d = n.x * p.x + n.y * p.y;
            rmin = std::min(rmin, d);
            rmax = std::max(rmax, d);
        }
        if (rmin >= pmax || rmax <= pmin) return false;
    }
    return true;
}

}  // namespace

std::string format_compact(double x) {
    std::string s = format_number(x, 3);
    if (s.find('.') != std::string::npos && s.find("\u00D7") == std::string::npos) {
        while (!s.empty() && s.back() == '0') s.pop_back();
        if (!s.empty() && s.back() == '.') s.pop_back();
    }
    return s;
}

bool LabelPlacer::free(const ImVec4& r, bool strict) const {
    if (r.x < bounds_.x || r.y < bounds_.y || r.z > bounds_.z || r.w > bounds_.w) return false;
    for (const ImVec4& t : taken_)
        if (r.x < t.z && r.z > t.x && r.y < t.w && r.w > t.y) return false;
    if (strict)
        for (const auto& poly : soft_)
            if (overlaps(r, poly)) return false;
    return true;
}

ImVec2 LabelPlacer::place(ImVec2 anchor, ImVec2 size, ImVec2 direction, float gap) {
    const float dl = length(direction);
    ImVec2 d = dl > 1e-6f ? mul(direction, 1.0f / dl) : ImVec2(0.0f, -1.0f);
    // Candidate directions: the preferred one, then turning away from it both ways.
    const float base = std::atan2(d.y, d.x);
    const float turns[] = {0.0f, 0.6f, -0.6f, 1.2f, -1.2f, 1.8f, -1.8f, 2.4f, -2.4f, kPiF};
    ImVec2 best(anchor.x - 0.5f * size.x, anchor.y - 0.5f * size.y);
    // Nearest first: at each distance every direction, then further away. Off the bodies if
    // that can be had within a few label heights, else anywhere free.
    const float h = std::max(size.y, 1.0f);
    const float steps[] = {0.0f, 0.5f, 1.2f, 2.0f, 3.0f, 4.5f, 6.5f};
    for (int strict = 1; strict >= 0; --strict)
        for (float step : steps) {
            for (float turn : turns) {
                const float a = base + turn;
                const ImVec2 u(std::cos(a), std::sin(a));
                // The box centre sits `gap` beyond the anchor, further by half the box's
                // extent along u so that the box never covers the anchor.
                const float reach = gap + step * h + 0.5f * (std::abs(u.x) * size.x + std::abs(u.y) * size.y);
                const ImVec2 centre = add(anchor, mul(u, reach));
                const ImVec4 r(centre.x - 0.5f * size.x, centre.y - 0.5f * size.y, centre.x + 0.5f * size.x,
                               centre.y + 0.5f * size.y);
                if (free(r, strict == 1) && (!acceptable_ || acceptable_(r))) {
                    taken_.push_back(r);
                    last_free_ = true;
                    return ImVec2(r.x, r.y);
                }
                if (step == 0.0f && turn == 0.0f) best = ImVec2(r.x, r.y);
            }
            // Near the anchor, or not at all; off bodies and arrows a little further.
            if (step >= (strict ? 3.0f : 2.0f)) break;
        }
    // Nowhere free: the preferred spot, clamped into the bounds, not reserved.
    best.x = std::clamp(best.x, bounds_.x, std::max(bounds_.x, bounds_.z - size.x));
    best.y = std::clamp(best.y, bounds_.y, std::max(bounds_.y, bounds_.w - size.y));
    last_free_ = false;
    return best;
}

void draw_label(ImDrawList* dl, const FontSet& fonts, ImFont* font, ImVec2 top_left, const std::string& text,
                Colour colour, Colour backing, float pad) {
    const ImVec2 size = rich_text_size(fonts, font, text);
    dl->AddRectFilled(ImVec2(top_left.x - pad, top_left.y - pad * 0.5f),
                      ImVec2(top_left.x + size.x + pad, top_left.y + size.y + pad * 0.5f), backing, pad);
    draw_rich_text(dl, fonts, font, top_left, colour, text);
}

ImVec4 place_label_box(const FontSet& fonts, LabelPlacer* placer, ImFont* font, ImVec2 anchor, ImVec2 direction,
                       const std::string& text, float pad, float gap) {
    const ImVec2 size = rich_text_size(fonts, font, text);
    const ImVec2 box(size.x + 2 * pad, size.y + pad);
    const ImVec2 at = placer->place(anchor, box, direction, gap);
    return ImVec4(at.x, at.y, at.x + box.x, at.y + box.y);
}

void draw_placed_label(ImDrawList* dl, const FontSet& fonts, ImFont* font, ImVec4 box, ImVec2 anchor,
                       const std::string& text, Colour colour, Colour backing, float pad, float gap) {
    const float text_h = box.w - box.y - pad;
    // The nearest point of the label's box to the anchor.
    const ImVec2 near(std::clamp(anchor.x, box.x, box.z), std::clamp(anchor.y, box.y, box.w));
    const float d = length(sub(near, anchor));
    if (d > gap + 1.2f * text_h) {
        const ImVec2 u = mul(sub(near, anchor), 1.0f / d);
        dl->AddLine(add(anchor, mul(u, 0.35f * gap)), sub(near, mul(u, 0.35f * gap)), with_alpha(colour, 0.55f),
                    std::max(1.0f, 0.06f * text_h));
    }
    draw_label(dl, fonts, font, ImVec2(box.x + pad, box.y + 0.5f * pad), text, colour, backing, pad);
}

void place_label(ImDrawList* dl, const FontSet& fonts, LabelPlacer* placer, ImFont* font, ImVec2 anchor,
                 ImVec2 direction, const std::string& text, Colour colour, Colour backing, float pad, float gap) {
    const ImVec4 box = place_label_box(fonts, placer, font, anchor, direction, text, pad, gap);
    draw_placed_label(dl, fonts, font, box, anchor, text, colour, backing, pad, gap);
}

}  // namespace collide::render
