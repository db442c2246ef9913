#include "render/annotation.h"

#include <cmath>
#include <cstdio>

namespace collide::render {

const char* mark_name(Mark kind) {
    switch (kind) {
        case Mark::body: return "body";
        case Mark::plane: return "plane";
        case Mark::velocity: return "velocity";
        case Mark::spin: return "spin";
        case Mark::impulse: return "impulse";
        case Mark::normal: return "normal";
        case Mark::lever_arm: return "lever_arm";
        case Mark::contact: return "contact";
        case Mark::direction: return "direction";
        case Mark::label: return "label";
        case Mark::point: return "point";
        case Mark::point_velocity: return "point_velocity";
        case Mark::table_cell: return "table_cell";
        case Mark::formula_line: return "formula_line";
        case Mark::plot_value: return "plot_value";
    }
    return "label";
}

std::vector<double> components(const Vec3& v, int dimension) {
    std::vector<double> out;
    for (int k = 0; k < dimension; ++k) out.push_back(v[k]);
    return out;
}

std::vector<double> pose_value(const BodyState& s, int dimension) {
    if (dimension == 1) return {s.x.x()};
    if (dimension == 2) return {s.x.x(), s.x.y(), s.angle};
    return {s.x.x(), s.x.y(), s.x.z(), s.q.w(), s.q.x(), s.q.y(), s.q.z()};
}

BodyState pose_of(const Annotation& body) {
    BodyState s;
    s.x = body.from;
    if (body.value.size() == 3) {  // 2D
        s.angle = body.value[2];
        s.q = lift_angle(s.angle);
    } else if (body.value.size() == 7) {  // 3D
        s.q = Quat(body.value[3], body.value[4], body.value[5], body.value[6]);
    }
    return s;
}

Annotation arrow_annotation(Mark kind, int body, const Vec3& from, const Vec3& to, std::vector<double> value,
                            Colour colour) {
    Annotation a;
    a.kind = kind;
    a.body = body;
    a.from = from;
    a.to = to;
    a.value = std::move(value);
    a.colour = colour;
    return a;
}

Annotation placed_label(const FontSet& fonts, LabelPlacer* placer, const Annotations& items,
                        const LabelRequest& request, float pad, float gap) {
    Annotation a;
    a.kind = Mark::label;
    a.of = request.of;
    a.body = request.of >= 0 ? items[static_cast<std::size_t>(request.of)].body : -1;
    a.text = request.text;
    a.value = request.value;
    a.colour = request.colour;
    a.small = request.small;
    a.anchor = request.anchor;
    ImFont* font = request.small ? fonts.small : fonts.text;
    a.font_px = font->FontSize;
    a.box = place_label_box(fonts, placer, font, request.anchor, request.direction, request.text, pad, gap);
    return a;
}

namespace {

// Full precision (the shortest text that reads back as the same double is not needed: 17
// significant digits always do).
std::string number(double x) {
    if (!std::isfinite(x)) return "null";
    if (x == 0.0) return "0";  // and no "-0"
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

// Pixels (floats): their own precision.
std::string pixels(float x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.7g", static_cast<double>(x));
    return buf;
}

std::string point(const Vec3& p, int dimension) {
    std::string s = "[";
    for (int k = 0; k < dimension; ++k) s += (k ? ", " : "") + number(p[k]);
    return s + "]";
}

std::string quoted(const std::string& text) {
    std::string s = "\"";
    for (const char c : text) {
        switch (c) {
            case '"': s += "\\\""; break;
            case '\\': s += "\\\\"; break;
            case '\n': s += "\\n"; break;
            case '\t': s += "\\t"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    s += buf;
                } else {
                    s += c;
                }
        }
    }
    return s + "\"";
}

}  // namespace

void write_annotations_json(std::ostream& out, const Annotations& items, int dimension,
                            const std::vector<std::string>& body_names, int indent) {
    const std::string pad(static_cast<std::size_t>(indent), ' ');
    out << "[";
    for (std::size_t k = 0; k < items.size(); ++k) {
        const Annotation& a = items[k];
        out << (k ? ",\n" : "\n") << pad << "  {\"kind\": \"" << mark_name(a.kind) << "\", \"body\": ";
        if (a.body >= 0 && static_cast<std::size_t>(a.body) < body_names.size())
            out << quoted(body_names[static_cast<std::size_t>(a.body)]);
        else out << "null";
        out << ", \"from\": " << point(a.from, dimension) << ", \"to\": " << point(a.to, dimension) << ", \"value\": ";
        if (a.value.empty()) {
            out << "null";
        } else if (a.value.size() == 1) {
            out << number(a.value[0]);
        } else {
            out << "[";
            for (std::size_t i = 0; i < a.value.size(); ++i) out << (i ? ", " : "") << number(a.value[i]);
            out << "]";
        }
        out << ", \"text\": " << quoted(a.text) << ", \"box\": [" << pixels(a.box.x) << ", " << pixels(a.box.y) << ", "
            << pixels(a.box.z) << ", " << pixels(a.box.w) << "]";
        if (a.kind == Mark::spin) out << ", \"sweep\": " << number(a.sweep);
        if (a.kind == Mark::label) out << ", \"of\": " << a.of << ", \"font_px\": " << pixels(a.font_px);
        if (!a.outline.empty()) {
            out << ", \"outline\": [";
            for (std::size_t i = 0; i < a.outline.size(); ++i)
                out << (i ? ", [" : "[") << pixels(a.outline[i].x) << ", " << pixels(a.outline[i].y) << "]";
            out << "]";
        }
        out << "}";
    }
    out << (items.empty() ? "]" : "\n" + pad + "]");
}

}  // namespace collide::render
