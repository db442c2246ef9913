#include "render/scene3d_passes.h"

#include <algorithm>
#include <cmath>

namespace collide::render {

namespace {

Vec3f f3(const Vec3& v) { return v.cast<float>(); }

// Body i's place among the moving bodies: its fill and trail colours.
int colour_index(const Scene& scene, std::size_t i) {
    int k = 0;
    for (std::size_t j = 0; j < i; ++j) k += scene.bodies[j].is_static() ? 0 : 1;
    return k;
}

// A shaded arrow from p along d (world, m): a shaft of radius `thickness` (m) and a head 4.5
// thicknesses long, 2.2 wide in radius; on arrows shorter than 1.5 heads the head shrinks and
// there is no shaft.
void arrow(std::vector<MeshDraw>* out, const Vec3& p, const Vec3& d, Colour colour, double thickness) {
    const double len = d.norm();
    if (len < 1e-9) return;
    double head = 4.5 * thickness, head_r = 2.2 * thickness;
    if (len < 1.5 * head) {
        head_r *= len / (1.5 * head);
        head = len / 1.5;
    }
    const Mat3f R = rotation_from_y(f3(d / len));
    // The unit part scaled to radius rx and length ly, its base at `at`.
    const auto model = [&](const Vec3& at, float rx, float ly) {
        Mat4f m = Mat4f::Identity();
        m.block<3, 3>(0, 0) = R * Eigen::DiagonalMatrix<float, 3>(rx, ly, rx);
        m.block<3, 1>(0, 3) = f3(at);
        return m;
    };
    const double shaft = len - head;
    if (shaft > 0)
        out->push_back({kShaftMesh, model(p, static_cast<float>(thickness), static_cast<float>(shaft)), R, colour, 0});
    out->push_back(
        {kHeadMesh, model(p + d / len * shaft, static_cast<float>(head_r), static_cast<float>(head)), R, colour, 0});
}

// The arrows' thickness (m).
double thickness(const View3d& view) { return 0.03 * view.scales.unit; }

// The bodies, shaded (a sphere with wedges, so that its spin shows); static ones grey.
void body_pass(const View3d& view, const Annotations& items, Overlay* out) {
    const Palette& pal = view.style.colours;
    for (const Annotation& a : items) {
        if (a.kind != Mark::body) continue;
        const std::size_t i = static_cast<std::size_t>(a.body);
        const bool is_static = view.scene.bodies[i].is_static();
        const BodyState s = pose_of(a);
        const Mat3f R = s.q.cast<float>().toRotationMatrix();
        Mat4f model = Mat4f::Identity();
        model.block<3, 3>(0, 0) = R;
        model.block<3, 1>(0, 3) = f3(s.x);
        const Colour fill = is_static ? pal.static_fill : pal.fills[colour_index(view.scene, i) % Palette::kFills];
        const int pattern = view.solids.bodies[i].kind == Solid::Kind::sphere ? 1 : 0;
        out->bodies.push_back({body_mesh(i), model, R, fill, pattern});
    }
}

// Velocity arrows (from the surface) and spin arrows (on the axis), one scale each.
void arrow_pass(const View3d& view, const Annotations& items, Overlay* out) {
    for (const Annotation& a : items)
        if (a.kind == Mark::velocity) arrow(&out->arrows, a.from, a.to - a.from, a.colour, thickness(view));
        else if (a.kind == Mark::spin) arrow(&out->arrows, a.from, a.to - a.from, a.colour, thickness(view) * 0.8);
}

// Outlines: box and prism edges, and the silhouettes of spheres and cylinders as seen from the
// eye.
void outline_pass(const View3d& view, const Annotations& items, Overlay* out) {
    const Palette& pal = view.style.colours;
    const float outline = view.style.lw(view.style.outline);
    std::vector<Segment>& lines = out->lines;
    for (const Annotation& item : items) {
        if (item.kind != Mark::body) continue;
        const Solid& solid = view.solids.bodies[static_cast<std::size_t>(item.body)];
        const BodyState s = pose_of(item);
        for (const auto& [a, b] : solid.edges)
            lines.push_back({s.x + s.q * a.cast<double>(), s.x + s.q * b.cast<double>(), pal.ink, outline});
        const Vec3 to_eye = view.camera.eye().cast<double>() - s.x;
        const double d = to_eye.norm();
        const double r = solid.radius;
        if (solid.kind == Solid::Kind::sphere && d > r) {
            // The silhouette: the circle where the cone from the eye touches the sphere (centre
            // c towards the eye, radius rs), in the plane of e1, e2.
            const Vec3 u = to_eye / d;
            const Vec3 c = s.x + u * (r * r / d);
            const double rs = r * std::sqrt(1.0 - r * r / (d * d));
            Vec3 e1 = u.cross(Vec3::UnitY());
            if (e1.norm() < 1e-6) e1 = u.cross(Vec3::UnitX());
            e1.normalize();
            const Vec3 e2 = u.cross(e1);
            const int segs = 96;
            for (int k = 0; k < segs; ++k) {
                const double a0 = 2 * kPi * k / segs, a1 = 2 * kPi * (k + 1) / segs;
                lines.push_back({c + rs * (std::cos(a0) * e1 + std::sin(a0) * e2),
                                 c + rs * (std::cos(a1) * e1 + std::sin(a1) * e2), pal.ink, outline});
            }
            // The equator (body frame y = 0), so that spin shows in the outline too.
            for (int k = 0; k < segs; ++k) {
                const double a0 = 2 * kPi * k / segs, a1 = 2 * kPi * (k + 1) / segs;
                const Vec3 p0 = s.x + s.q * Vec3(r * std::cos(a0), 0, r * std::sin(a0));
                const Vec3 p1 = s.x + s.q * Vec3(r * std::cos(a1), 0, r * std::sin(a1));
                lines.push_back({p0, p1, with_alpha(pal.ink, 0.45f), outline * 0.6f});
            }
        } else if (solid.kind == Solid::Kind::cylinder) {
            // A cylinder (body z axis): its two side silhouette lines.
            const Vec3 axis = s.q * Vec3::UnitZ();
            Vec3 side = axis.cross(to_eye);
            if (side.norm() > 1e-9) {
                side.normalize();
                const double h = 0.5 * view.solids.extrude;
                for (double sg : {-1.0, 1.0})
                    lines.push_back({s.x + sg * r * side - h * axis, s.x + sg * r * side + h * axis, pal.ink, outline});
            }
        }
    }
}

// Trails: the path of each moving centre, fading with age.
void trail_pass(const View3d& view, const FrameState& frame, std::size_t n, Overlay* out) {
    const Palette& pal = view.style.colours;
    for (std::size_t i = 0; i < n && i < frame.trails.size(); ++i) {
        const auto& trail = frame.trails[i];
        if (view.scene.bodies[i].is_static() || trail.size() < 2) continue;
        const Colour dark = pal.darks[colour_index(view.scene, i) % Palette::kFills];
        const double span = std::max(1e-9, trail.back().t - trail.front().t);
        for (std::size_t k = 1; k < trail.size(); ++k) {
            const double age = (frame.t - trail[k].t) / span;
            out->lines.push_back({trail[k - 1].x, trail[k].x,
                                  with_alpha(dark, static_cast<float>(0.55 * std::clamp(1.0 - age, 0.0, 1.0))),
                                  view.style.lw(2.0f)});
        }
    }
}

// Spin curls: three quarters of a circle of radius 0.22 units around the spin arrow, near its
// tip, in the plane of e1, e2 (counter-clockwise about the arrow), with a small shaded head.
void curl_pass(const View3d& view, const Annotations& items, Overlay* out) {
    const ArrowScales& k = view.scales;
    for (const Annotation& a : items) {
        if (a.kind != Mark::spin) continue;
        // Centred on the spin arrow, 0.6 of the way from its start to its tip.
        const Vec3 axis = (a.to - a.from).normalized();
        const Vec3 centre = a.from + 0.6 * (a.to - a.from);
        Vec3 e1 = axis.cross(Vec3::UnitY());
        if (e1.norm() < 1e-6) e1 = axis.cross(Vec3::UnitX());
        e1.normalize();
        const Vec3 e2 = axis.cross(e1);
        const double rc = 0.22 * k.unit;
        const int segs = 40;
        for (int j = 0; j < segs; ++j) {
            const double a0 = a.sweep * j / segs, a1 = a.sweep * (j + 1) / segs;
            out->lines.push_back({centre + rc * (std::cos(a0) * e1 + std::sin(a0) * e2),
                                  centre + rc * (std::cos(a1) * e1 + std::sin(a1) * e2), a.colour,
                                  view.style.lw(2.5f)});
        }
        const double end_angle = a.sweep;
        const Vec3 end = centre + rc * (std::cos(end_angle) * e1 + std::sin(end_angle) * e2);
        const Vec3 tangent = (a.sweep > 0 ? 1.0 : -1.0) * (-std::sin(end_angle) * e1 + std::cos(end_angle) * e2);
        arrow(&out->curl_heads, end - tangent * (0.12 * k.unit), tangent * (0.16 * k.unit), a.colour,
              thickness(view) * 0.6);
    }
}

// At a collision, over everything (they start inside the bodies): the r vectors, the normal
// (a line for its first 0.75 units and a head), the impulse +P on b and -P on a when a moves.
void impact_pass(const View3d& view, const Annotations& items, Overlay* out) {
    for (const Annotation& a : items) {
        if (a.kind == Mark::lever_arm)
            out->impact_lines.push_back({a.from, a.to, with_alpha(a.colour, 0.9f), view.style.lw(view.style.thin)});
        else if (a.kind == Mark::normal)
            out->impact_lines.push_back(
                {a.from, a.from + (0.75 / 0.95) * (a.to - a.from), a.colour, view.style.lw(2.0f)});
    }
    for (const Annotation& a : items) {
        if (a.kind == Mark::impulse)
            arrow(&out->impact_arrows, a.from, a.to - a.from, a.colour, thickness(view) * (a.faint ? 1.0 : 1.2));
        else if (a.kind == Mark::normal)
            arrow(&out->impact_arrows, a.from + (0.75 / 0.95) * (a.to - a.from), (0.2 / 0.95) * (a.to - a.from),
                  a.colour, thickness(view) * 0.6);
    }
}

// The screen box of a set of world points, each with a margin (pixels).
struct ScreenBox {
    float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
    bool everywhere = false;  // a point behind the eye: take the whole frame
    void add(const Camera& camera, const Vec3f& p, float pad) {
        if (!camera.in_front(p)) {
            everywhere = true;
            return;
        }
        const ImVec2 q = camera.project(p.cast<double>());
        x0 = std::min(x0, q.x - pad);
        y0 = std::min(y0, q.y - pad);
        x1 = std::max(x1, q.x + pad);
        y1 = std::max(y1, q.y + pad);
    }
};

}  // namespace

Ground ground_under(const std::vector<Plane>& planes, const Vec3& centre, double floor) {
    Ground g;
    bool found = false;
    for (const auto& [n, offset] : planes) {
        if (n.y() < 0.7) continue;
        const double nn = n.norm();
        g.normal = n / nn;
        const double o = offset / nn;
        g.origin = centre - (g.normal.dot(centre) - o) * g.normal;
        found = true;
        break;
    }
    if (!found) {
        g.normal = Vec3::UnitY();
        g.origin = Vec3(centre.x(), floor, centre.z());
    }
    // Plane coordinates: u along x where possible (else along z), v = n x u.
    g.u = Vec3::UnitX() - Vec3::UnitX().dot(g.normal) * g.normal;
    if (g.u.norm() < 0.3) g.u = Vec3::UnitZ() - Vec3::UnitZ().dot(g.normal) * g.normal;
    g.u.normalize();
    g.v = g.normal.cross(g.u);
    return g;
}

GroundDraw ground_draw(const Ground& g, const Style& style) {
    return {g.origin,
            g.u,
            g.v,
            static_cast<float>(g.extent),
            static_cast<float>(g.spacing),
            style.colours.background,
            rgb(238, 238, 233),
            rgb(168, 170, 174)};
}

std::vector<Shadow> shadows(const View3d& view, const Ground& ground, const FrameState& frame) {
    std::vector<Shadow> out;
    const std::size_t n = std::min(frame.bodies.size(), view.scene.bodies.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (!view.solids.bodies[i].drawn()) continue;
        const double height = (frame.bodies[i].x - ground.origin).dot(ground.normal);
        const double r = 0.5 * view.solids.bodies[i].size;
        if (height < -0.5 * r) continue;
        const double radius = r * (1.0 + 0.25 * std::max(0.0, height) / std::max(r, 1e-9));
        const double strength = 0.30 * std::exp(-std::max(0.0, height - r) / (3 * r));
        out.push_back(
            {frame.bodies[i].x - height * ground.normal, static_cast<float>(radius), static_cast<float>(strength)});
    }
    return out;
}

Annotations annotations3d(const View3d& view, const FrameState& frame, const Decor& decor) {
    const Palette& pal = view.style.colours;
    const ArrowScales& k = view.scales;
    const double unit = k.unit;
    const int dim = view.scene.dimension;
    const std::size_t n = std::min(frame.bodies.size(), view.scene.bodies.size());
    Annotations items;
    const auto value = [dim](const Vec3& v) { return components(v, dim); };
    const auto item = [&](Mark kind, int body, const Vec3& from, const Vec3& to, std::vector<double> v,
                          Colour colour) -> Annotation& {
        items.push_back(arrow_annotation(kind, body, from, to, std::move(v), colour));
        return items.back();
    };
    for (std::size_t i = 0; i < n; ++i) {
        if (!view.solids.bodies[i].drawn()) continue;
        const BodyState& s = frame.bodies[i];
        item(Mark::body, static_cast<int>(i), s.x, s.x, pose_value(s, dim), 0).small = decor.com;
    }
    if (decor.impacts)
        for (const ImpactMark& im : frame.impacts) {
            if (!im.detailed) {  // the impulse arrow only (render::shown_impacts)
                item(Mark::impulse, static_cast<int>(im.b), im.point, im.point + k.k_impulse * im.impulse,
                     value(im.impulse), pal.impulse)
                    .faint = true;
                continue;
            }
            const std::pair<std::size_t, const char*> ends[2] = {{im.a, "r_{a}"}, {im.b, "r_{b}"}};
            for (const auto& [i, name] : ends)
                if (i < n && view.solids.bodies[i].drawn())
                    item(Mark::lever_arm, static_cast<int>(i), frame.bodies[i].x, im.point,
                         value(im.point - frame.bodies[i].x), pal.lever)
                        .text = name;
            const Vec3 nu = im.normal.normalized();
            item(Mark::normal, -1, im.point, im.point + 0.95 * unit * nu, value(nu), pal.normal);
            item(Mark::impulse, static_cast<int>(im.b), im.point, im.point + k.k_impulse * im.impulse,
                 value(im.impulse), pal.impulse);
            if (im.a < n && !view.scene.bodies[im.a].is_static())
                item(Mark::impulse, static_cast<int>(im.a), im.point, im.point - k.k_impulse * im.impulse,
                     value(-im.impulse), pal.impulse)
                    .faint = true;
            item(Mark::contact, -1, im.point, im.point, value(im.point), pal.impulse);
        }
    if (decor.velocities)
        for (std::size_t i = 0; i < n; ++i) {
            const Solid& solid = view.solids.bodies[i];
            if (view.scene.bodies[i].is_static() || !solid.drawn() || !decor.in_focus(i)) continue;
            const BodyState& s = frame.bodies[i];
            if (s.v.norm() * k.k_velocity > 1e-3 * unit) {
                const Vec3 start = velocity_start(solid, s);
                item(Mark::velocity, static_cast<int>(i), start, start + k.k_velocity * s.v, value(s.v), pal.velocity);
            }
            if (shows_spin(k, s)) {
                const Vec3 start = spin_start(solid, s);
                // An arrow along w and a curl three quarters round it, counter-clockwise seen
                // from its tip (the right-hand rule).
                Annotation& a = item(Mark::spin, static_cast<int>(i), start, start + k.k_spin * s.w,
                                     dim == 3 ? value(s.w) : std::vector<double>{s.w.z()}, pal.spin);
                a.sweep = 1.5 * kPi;
            }
        }
    return items;
}

Overlay overlay(const View3d& view, const FrameState& frame, const Decor& decor, const Annotations& items) {
    Overlay out;
    const std::size_t n = std::min(frame.bodies.size(), view.scene.bodies.size());
    body_pass(view, items, &out);
    arrow_pass(view, items, &out);
    outline_pass(view, items, &out);
    if (decor.trails) trail_pass(view, frame, n, &out);
    curl_pass(view, items, &out);
    impact_pass(view, items, &out);
    return out;
}

bool overlay_bounds(const Overlay& overlay, const Camera& camera, const std::vector<Box3f>& mesh_bounds, ImVec4* rect) {
    ScreenBox box;
    for (const auto* draws : {&overlay.bodies, &overlay.arrows, &overlay.curl_heads, &overlay.impact_arrows})
        for (const MeshDraw& d : *draws) {
            const Box3f& b = mesh_bounds[static_cast<std::size_t>(d.mesh)];
            for (int k = 0; k < 8; ++k) {
                const Vec3f local((k & 1) ? b.hi.x() : b.lo.x(), (k & 2) ? b.hi.y() : b.lo.y(),
                                  (k & 4) ? b.hi.z() : b.lo.z());
                box.add(camera, (d.model * local.homogeneous()).head<3>(), 2.0f);
            }
        }
    for (const auto* segments : {&overlay.lines, &overlay.impact_lines})
        for (const Segment& s : *segments) {
            box.add(camera, f3(s.a), 0.5f * s.width + 2.0f);
            box.add(camera, f3(s.b), 0.5f * s.width + 2.0f);
        }
    if (box.everywhere) {
        *rect = ImVec4(0, 0, static_cast<float>(camera.frame_width()), static_cast<float>(camera.frame_height()));
        return true;
    }
    if (!(box.x0 <= box.x1)) return false;
    *rect = ImVec4(box.x0, box.y0, box.x1, box.y1);
    return true;
}

Vec3 velocity_start(const Solid& solid, const BodyState& s) {
    const double v = s.v.norm();
    return v > 0 ? s.x + s.v / v * exit_distance(solid, s.q, s.v / v) : s.x;
}

bool shows_spin(const ArrowScales& scales, const BodyState& s) {
    const double w = s.w.norm();
    return scales.k_spin > 0 && w > 1e-9 * scales.max_spin && w > 1e-12;
}

Vec3 spin_start(const Solid& solid, const BodyState& s) { return s.x + s.w.normalized() * (0.5 * solid.size * 0.9); }

}  // namespace collide::render
