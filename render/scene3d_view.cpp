#include "render/scene3d_view.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "render/batch3d.h"
#include "render/camera.h"
#include "render/convex_hull.h"
#include "render/mesh.h"
#include "render/scale.h"
#include "render/scene3d_passes.h"
#include "render/solid.h"

namespace collide::render {

namespace {

// Distance (pixels) from p to a convex outline: 0 inside it.
float distance_to_outline(const std::vector<ImVec2>& poly, ImVec2 p) {
    if (poly.size() < 3) return std::numeric_limits<float>::max();
    bool inside = true;
    float best = std::numeric_limits<float>::max(), turn = 0.0f;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        const ImVec2 a = poly[k], b = poly[(k + 1) % poly.size()];
        const float ex = b.x - a.x, ey = b.y - a.y, px = p.x - a.x, py = p.y - a.y;
        const float c = ex * py - ey * px;
        if (c != 0.0f) {
            if (turn == 0.0f) turn = c;
            else if ((c > 0.0f) != (turn > 0.0f)) inside = false;
        }
        const float len2 = ex * ex + ey * ey;
        const float t = len2 > 0.0f ? std::clamp((px * ex + py * ey) / len2, 0.0f, 1.0f) : 0.0f;
        best = std::min(best, std::hypot(px - t * ex, py - t * ey));
    }
    return inside ? 0.0f : best;
}

// The body whose outline is nearest p (-1: none drawn); a tie goes to none.
int nearest_outline(const std::vector<std::vector<ImVec2>>& outlines, ImVec2 p) {
    int best = -1;
    float best_d = std::numeric_limits<float>::max();
    bool tie = false;
    for (std::size_t i = 0; i < outlines.size(); ++i) {
        if (outlines[i].empty()) continue;
        const float d = distance_to_outline(outlines[i], p);
        if (d < best_d) best = static_cast<int>(i), best_d = d, tie = false;
        else if (d == best_d) tie = true;
    }
    return tie ? -1 : best;
}

double norm_of(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x * x;
    return std::sqrt(s);
}

}  // namespace

struct Scene3dView::Impl {
    const Scene& scene;
    Style style;
    Solids solids;
    Batch3d batch;
    std::vector<Box3f> mesh_bounds;  // by mesh id (scene3d_passes.h), in the mesh's frame
    Camera camera;
    ArrowScales scales;
    Ground ground;
    Vec3 centre = Vec3::Zero();  // m: the framed region's centre
    double radius = 1.0;         // m: and its radius

    Impl(const Gl& gl, const Scene& s, const Style& st) : scene(s), style(st), solids(make_solids(s)), batch(gl) {
        add(arrow_shaft());                                        // kShaftMesh
        add(arrow_head());                                         // kHeadMesh
        for (const Solid& solid : solids.bodies) add(solid.mesh);  // body_mesh(i)
    }
    void add(const Mesh& mesh) {
        batch.add(mesh);
        mesh_bounds.push_back(bounds(mesh));
    }
    View3d view() const { return {scene, style, solids, scales, camera}; }

    // A legend for arrows of `metres_per_unit`: a round value about 70 px (at 720p) long at the
    // scene's centre, across the view.
    DiagramView::Legend legend_for(double metres_per_unit) const {
        if (!(metres_per_unit > 0)) return {};
        const Vec3 right = camera.right().cast<double>();
        const float ppm = std::abs(camera.project(centre + right).x - camera.project(centre).x);
        const double px_per_unit = metres_per_unit * ppm;
        const double value = round_value(style.px(70.0f) / px_per_unit);
        return {value, static_cast<float>(value * px_per_unit)};
    }

    // The projected outline of body i (screen points, convex), for label placement.
    std::vector<ImVec2> screen_outline(std::size_t i, const BodyState& s) const {
        const Solid& solid = solids.bodies[i];
        std::vector<ImVec2> pts;
        if (solid.kind == Solid::Kind::sphere) {
            const ImVec2 c = camera.project(s.x);
            const Vec3 right = camera.right().cast<double>();
            const ImVec2 e = camera.project(s.x + right * solid.radius);
            const float r = std::hypot(e.x - c.x, e.y - c.y);
            for (int k = 0; k < 16; ++k) {
                const float a = 2.0f * static_cast<float>(kPi) * static_cast<float>(k) / 16.0f;
                pts.push_back(ImVec2(c.x + r * std::cos(a), c.y + r * std::sin(a)));
            }
            return pts;
        }
        std::vector<Vec2> screen;
        for (const auto& [a, b] : solid.edges)
            for (const Vec3f& p : {a, b}) {
                const ImVec2 q = camera.project(s.x + s.q * p.cast<double>());
                screen.push_back(Vec2(q.x, q.y));
            }
        if (screen.size() < 3) return pts;
        for (const Vec2& p : convex_hull(screen))
            pts.push_back(ImVec2(static_cast<float>(p.x()), static_cast<float>(p.y())));
        return pts;
    }
};

Scene3dView::Scene3dView(const Gl& gl, const Scene& scene, const Style& style)
    : impl_(std::make_unique<Impl>(gl, scene, style)) {}

Scene3dView::~Scene3dView() = default;

void Scene3dView::fit(const std::vector<FrameState>& samples, const std::vector<ImpactMark>& impacts, ImVec4 viewport,
                      int frame_width, int frame_height) {
    Impl& I = *impl_;
    const std::vector<Solid>& solids = I.solids.bodies;
    I.camera.set_viewport(viewport, frame_width, frame_height);

    // 1. The box the bodies cover over the run (their bounding spheres), and how fast they move
    // and spin.
    const double inf = std::numeric_limits<double>::infinity();
    Vec3 lo(inf, inf, inf), hi(-inf, -inf, -inf);
    double max_speed = 0, max_impulse = 0;
    max_spin_ = 0;
    for (const FrameState& f : samples)
        for (std::size_t i = 0; i < f.bodies.size() && i < I.scene.bodies.size(); ++i) {
            if (solids[i].drawn()) {
                const double r = 0.5 * solids[i].size;
                lo = lo.cwiseMin(f.bodies[i].x - Vec3(r, r, r));
                hi = hi.cwiseMax(f.bodies[i].x + Vec3(r, r, r));
            }
            if (I.scene.bodies[i].is_static()) continue;
            max_speed = std::max(max_speed, f.bodies[i].v.norm());
            max_spin_ = std::max(max_spin_, f.bodies[i].w.norm());
        }
    for (const ImpactMark& im : impacts) max_impulse = std::max(max_impulse, im.impulse.norm());
    if (!(lo.x() < inf)) {
        lo = Vec3(-1, -1, -1);
        hi = Vec3(1, 1, 1);
    }

    // 2. The scales: the unit about the median moving body's size, the fastest velocity arrow
    // about a body long (between 12% and 35% of the box), impulses a little shorter and none
    // longer than half the smaller body it acts on.
    ArrowScales& k = I.scales;
    k.max_spin = max_spin_;
    std::vector<float> moving;
    for (std::size_t i = 0; i < solids.size(); ++i)
        if (!I.scene.bodies[i].is_static() && solids[i].size > 0) moving.push_back(solids[i].size);
    std::sort(moving.begin(), moving.end());
    const double body = moving.empty() ? 0.3 * (hi - lo).norm() : moving[moving.size() / 2];
    const double span = std::max(1e-6, (hi - lo).norm());
    k.unit = std::clamp(body, 0.05 * span, 0.4 * span);
    const double arrow_len = std::clamp(body * 1.1, 0.12 * span, 0.35 * span);
    k.k_velocity = max_speed > 0 ? arrow_len / max_speed : 0;
    k.k_impulse = max_impulse > 0 ? 0.9 * arrow_len / max_impulse : 0;
    for (const ImpactMark& im : impacts)
        for (std::size_t i : {im.a, im.b})
            if (i < solids.size() && solids[i].size > 0 && im.impulse.norm() > 0)
                k.k_impulse = std::min(k.k_impulse, 0.5 * solids[i].size / im.impulse.norm());
    k.k_spin = max_spin_ > 0 ? 0.8 * arrow_len / max_spin_ : 0;

    // 3. Room for the velocity arrows (their tips, from the bounding sphere).
    for (const FrameState& f : samples)
        for (std::size_t i = 0; i < f.bodies.size() && i < I.scene.bodies.size(); ++i) {
            if (I.scene.bodies[i].is_static() || !solids[i].drawn()) continue;
            const Vec3 tip = f.bodies[i].x + k.k_velocity * f.bodies[i].v +
                             (f.bodies[i].v.norm() > 0 ? Vec3(0.5 * solids[i].size * f.bodies[i].v.normalized())
                                                       : Vec3(Vec3::Zero()));
            lo = lo.cwiseMin(tip);
            hi = hi.cwiseMax(tip);
        }
    I.centre = 0.5 * (lo + hi);

    // 4. The ground under it all, its foot included in the framing; the grid a round step.
    I.ground = ground_under(I.solids.planes, I.centre, lo.y());
    lo = lo.cwiseMin(I.ground.origin);
    hi = hi.cwiseMax(I.ground.origin);
    I.centre = 0.5 * (lo + hi);
    I.radius = std::max(1e-3, 0.5 * (hi - lo).norm());
    I.ground.extent = 2.2 * I.radius;
    I.ground.spacing = round_value(I.radius / 5.0);

    // 5. The camera on the box.
    I.camera.frame(lo, hi, I.centre, I.radius, camera_, I.scene.dimension);
    I.batch.set_camera(I.camera);
}

ImVec2 Scene3dView::to_screen(const Vec3& world) const { return impl_->camera.project(world); }

double Scene3dView::pixels_per_metre() const {
    const Impl& I = *impl_;
    const Vec3 right = I.camera.right().cast<double>();
    const ImVec2 a = I.camera.project(I.centre), b = I.camera.project(I.centre + right);
    return std::hypot(b.x - a.x, b.y - a.y);
}

DiagramView::Legend Scene3dView::velocity_legend() const { return impl_->legend_for(impl_->scales.k_velocity); }
DiagramView::Legend Scene3dView::impulse_legend() const { return impl_->legend_for(impl_->scales.k_impulse); }

void Scene3dView::draw(const FrameState& frame, const Decor& decor, const Annotations& items) {
    draw_ground(frame);
    draw_above(frame, decor, items);
}

bool Scene3dView::above_bounds(const FrameState& frame, const Decor& decor, const Annotations& items, ImVec4* rect) {
    const Impl& I = *impl_;
    return overlay_bounds(overlay(I.view(), frame, decor, items), I.camera, I.mesh_bounds, rect);
}

void Scene3dView::draw_ground(const FrameState& frame) {
    Impl& I = *impl_;
    I.batch.begin();
    I.batch.ground(ground_draw(I.ground, I.style), shadows(I.view(), I.ground, frame));
    I.batch.end("drawing the 3D view's ground");
}

void Scene3dView::draw_above(const FrameState& frame, const Decor& decor, const Annotations& items) {
    Impl& I = *impl_;
    const Overlay o = overlay(I.view(), frame, decor, items);
    Batch3d& b = I.batch;
    b.begin();
    b.meshes(o.bodies, MeshDepth::behind_lines);
    b.lines(o.lines, true, 0.0005f);
    // The arrows over every body (a body in front never hides another's velocity or spin),
    // shaded among themselves.
    b.clear_depth();
    b.meshes(o.arrows, MeshDepth::tested);
    b.meshes(o.curl_heads, MeshDepth::tested);
    b.lines(o.impact_lines, false, 0.0f);
    b.meshes(o.impact_arrows, MeshDepth::over);
    b.end("drawing the 3D view");
}

Annotations Scene3dView::annotate(const FontSet& fonts, const FrameState& frame, const Decor& decor,
                                  LabelPlacer* labels) const {
    const Impl& I = *impl_;
    const Camera& cam = I.camera;
    const Palette& c = I.style.colours;
    Annotations items = annotations3d(I.view(), frame, decor);
    if (!decor.labels || !labels) return items;
    const std::size_t n = std::min(frame.bodies.size(), I.scene.bodies.size());
    for (std::size_t i = 0; i < n; ++i)
        if (I.solids.bodies[i].drawn()) labels->avoid(I.screen_outline(i, frame.bodies[i]));
    std::vector<LabelRequest> pending;
    const auto screen = [&cam](const Vec3& p) { return cam.project(p); };
    const auto toward = [](ImVec2 from, ImVec2 to) { return ImVec2(to.x - from.x, to.y - from.y); };
    // Impacts first (each impulse, its normal, its r vectors), then velocities and spins, then
    // the names, as before the list existed.
    std::vector<LabelRequest> impacts, motion;
    // Velocity and spin labels as motion_labels() says.
    std::vector<bool> counted(n, false);
    for (std::size_t i = 0; i < n; ++i)
        counted[i] = !I.scene.bodies[i].is_static() && I.solids.bodies[i].drawn() && decor.in_focus(i);
    const FrameMotionLabels labels_of = motion_labels(frame, counted);
    const auto gets = [&](const std::vector<bool>& label, int body) {
        return body >= 0 && static_cast<std::size_t>(body) < label.size() && label[static_cast<std::size_t>(body)];
    };
    std::vector<bool> labelled(n, false);  // bodies with a velocity, spin or impulse label
    const auto label_body = [&](int body) {
        if (body >= 0 && static_cast<std::size_t>(body) < n) labelled[static_cast<std::size_t>(body)] = true;
    };
    // A velocity or spin arrow's label, "symbol = |value| unit", pointing from the body's centre
    // toward the arrow's tip, where motion_labels() gives the body one (`shown`).
    const auto motion_label = [&](const Annotation& a, int of, ImVec2 tip, const std::vector<bool>& shown,
                                  const char* symbol, const char* unit, Colour colour) {
        if (!gets(shown, a.body)) return;
        const ImVec2 from = screen(frame.bodies[static_cast<std::size_t>(a.body)].x);
        const double size = norm_of(a.value);
        motion.push_back({of,
                          tip,
                          toward(from, tip),
                          std::string(symbol) + " = " + format_number(size) + " " + unit,
                          {size},
                          colour,
                          false});
        label_body(a.body);
    };
    for (std::size_t k = 0; k < items.size(); ++k) {
        const Annotation& a = items[k];
        const int of = static_cast<int>(k);
        const ImVec2 p = screen(a.from), tip = screen(a.to);
        switch (a.kind) {
            case Mark::impulse:
                if (!a.faint) {
                    const double P = norm_of(a.value);
                    impacts.push_back(
                        {of, tip, toward(p, tip), "P = " + format_number(P) + " N s", {P}, c.impulse, false});
                    label_body(a.body);
                }
                break;
            case Mark::normal: impacts.push_back({of, tip, toward(p, tip), "n", {}, c.normal, false}); break;
            case Mark::lever_arm:
                impacts.push_back({of,
                                   ImVec2(0.5f * (p.x + tip.x), 0.5f * (p.y + tip.y)),
                                   ImVec2(-(tip.y - p.y), tip.x - p.x),
                                   a.text,
                                   {},
                                   c.lever,
                                   false});
                break;
            case Mark::velocity: motion_label(a, of, tip, labels_of.speed, "v", "m/s", c.velocity); break;
            case Mark::spin: motion_label(a, of, tip, labels_of.spin, "\u03C9", "rad/s", c.spin); break;
            default: break;
        }
    }
    pending = impacts;
    pending.insert(pending.end(), motion.begin(), motion.end());
    // Names beside their bodies, at the height of their centres, on the side away from the
    // other bodies (left of the group's middle: to the left): in a stack each name stands by its
    // own box, where a name above a box would land on the box above it and be pushed anywhere.
    float middle = 0;
    int named = 0;
    for (const Annotation& a : items)
        if (a.kind == Mark::body) middle += cam.project(a.from).x, ++named;
    if (named > 0) middle /= static_cast<float>(named);
    const bool many = labels_of.count > kManyBodies;  // names only on labelled bodies (kManyBodies)
    for (std::size_t k = 0; k < items.size(); ++k) {
        const Annotation& a = items[k];
        if (a.kind != Mark::body) continue;
        const std::size_t i = static_cast<std::size_t>(a.body);
        if (many && !labelled[i]) continue;
        const ImVec2 centre = cam.project(a.from);
        const float side = centre.x < middle - 0.5f ? -1.0f : 1.0f;
        ImVec2 edge = centre;  // the outline's extreme point on that side, at the centre's height
        for (const ImVec2& q : I.screen_outline(i, frame.bodies[i]))
            if (side * (q.x - edge.x) > 0) edge.x = q.x;
        pending.push_back({static_cast<int>(k), edge, ImVec2(side, 0), I.scene.bodies[i].name, {}, c.ink, true});
    }
    // Each body's screen outline, on its item too (annotations.json: tests check the labels
    // against them).
    std::vector<std::vector<ImVec2>> outlines(n);
    for (std::size_t i = 0; i < n; ++i)
        if (I.solids.bodies[i].drawn()) outlines[i] = I.screen_outline(i, frame.bodies[i]);
    for (Annotation& a : items)
        if (a.kind == Mark::body && a.body >= 0 && static_cast<std::size_t>(a.body) < n)
            a.outline = outlines[static_cast<std::size_t>(a.body)];
    const float pad = I.style.px(3.0f), gap = I.style.px(6.0f);
    for (const LabelRequest& p : pending) {
        if (p.text.empty()) continue;
        const int body = p.of >= 0 ? items[static_cast<std::size_t>(p.of)].body : -1;
        if (body < 0 || static_cast<std::size_t>(body) >= n || outlines[static_cast<std::size_t>(body)].empty()) {
            Annotation a = placed_label(fonts, labels, items, p, pad, gap);
            if (labels->last_free()) items.push_back(std::move(a));  // else left out
            continue;
        }
        // A body's label stands nearer that body than any other: at its arrow's tip where that
        // holds, else further back along the arrow towards the body (a leader line joins it).
        labels->require([&outlines, body](const ImVec4& r) {
            return nearest_outline(outlines, ImVec2(0.5f * (r.x + r.z), 0.5f * (r.y + r.w))) == body;
        });
        const ImVec2 centre = screen(frame.bodies[static_cast<std::size_t>(body)].x);
        for (const float along : {1.0f, 0.6f, 0.3f, 0.0f}) {
            LabelRequest q = p;
            q.anchor = ImVec2(centre.x + along * (p.anchor.x - centre.x), centre.y + along * (p.anchor.y - centre.y));
            Annotation a = placed_label(fonts, labels, items, q, pad, gap);
            if (labels->last_free()) {
                items.push_back(std::move(a));
                break;
            }  // else further back, or left out
        }
        labels->require(nullptr);
    }
    return items;
}

void Scene3dView::draw_labels(ImDrawList* dl, const FontSet& fonts, const Annotations& items) const {
    const Impl& I = *impl_;
    const Camera& cam = I.camera;
    const Palette& c = I.style.colours;
    // Centre-of-mass markers, seen through the bodies.
    for (const Annotation& a : items)
        if (a.kind == Mark::body && a.small && !I.scene.bodies[static_cast<std::size_t>(a.body)].is_static())
            draw_com_marker(dl, cam.project(a.from), I.style.lw(I.style.com * 0.85f), c.ink, c.background, 0.0f);
    // Axes: where x, y and z point, in the view's lower left corner.
    {
        const ImVec4& vp = cam.viewport();
        const ImVec2 o(vp.x + I.style.px(50.0f), vp.w - I.style.px(50.0f));
        const Vec3f right = cam.right(), up = cam.up();
        const Colour axis_colours[3] = {rgb(200, 50, 50), rgb(40, 150, 60), rgb(40, 90, 200)};
        const char* names[3] = {"x", "y", "z"};
        for (int a = 0; a < 3; ++a) {
            Vec3f e = Vec3f::Zero();
            e[a] = 1.0f;
            const ImVec2 d(e.dot(right), -e.dot(up));
            const float L = I.style.px(34.0f);
            const ImVec2 tip(o.x + d.x * L, o.y + d.y * L);
            draw_arrow(dl, o, tip, axis_colours[a], I.style.px(2.0f), I.style.px(9.0f), I.style.px(7.0f));
            dl->AddText(fonts.small, fonts.small->FontSize,
                        ImVec2(tip.x + d.x * I.style.px(8.0f) - 0.3f * fonts.small->FontSize,
                               tip.y + d.y * I.style.px(8.0f) - 0.5f * fonts.small->FontSize),
                        axis_colours[a], names[a]);
        }
    }
    const float pad = I.style.px(3.0f), gap = I.style.px(6.0f);
    for (const Annotation& a : items)
        if (a.kind == Mark::label)
            draw_placed_label(dl, fonts, a.small ? fonts.small : fonts.text, a.box, a.anchor, a.text, a.colour,
                              with_alpha(c.background, 0.85f), pad, gap);
}

}  // namespace collide::render
