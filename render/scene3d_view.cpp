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

    Impl(const Gl& gl, const Scene& s, const Style& st)
        : scene(s), style(st), solids(make_solids(s)), batch(gl) {
        add(arrow_shaft());  // kShaftMesh
        add(arrow_head());   // kHeadMesh
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

void Scene3dView::fit(const std::vector<FrameState>& samples, const std::vector<ImpactMark>& impacts,
                      ImVec4 viewport, int frame_width, int frame_height) {
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
                             (f.bodies[i].v.norm() > 0 ? Vec3(0.5 * solids[i].size * f.bodies[i].v.normalized()) : Vec3(Vec3::Zero()));
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

void Scene3dView::draw(const FrameState& frame, const Decor& decor) {
    draw_ground(frame);
    draw_above(frame, decor);
}

bool Scene3dView::above_bounds(const FrameState& frame, const Decor& decor, ImVec4* rect) {
    const Impl& I = *impl_;
    return overlay_bounds(overlay(I.view(), frame, decor), I.camera, I.mesh_bounds, rect);
}

void Scene3dView::draw_ground(const FrameState& frame) {
    Impl& I = *impl_;
    I.batch.begin();
    I.batch.ground(ground_draw(I.ground, I.style), shadows(I.view(), I.ground, frame));
    I.batch.end("drawing the 3D view's ground");
}

void Scene3dView::draw_above(const FrameState& frame, const Decor& decor) {
    Impl& I = *impl_;
    const Overlay o = overlay(I.view(), frame, decor);
    Batch3d& b = I.batch;
    b.begin();
    b.meshes(o.bodies, MeshDepth::behind_lines);
    b.meshes(o.arrows, MeshDepth::tested);
    b.lines(o.lines, true, 0.0005f);
    b.meshes(o.curl_heads, MeshDepth::tested);
    b.lines(o.impact_lines, false, 0.0f);
    b.meshes(o.impact_arrows, MeshDepth::over);
    b.end("drawing the 3D view");
}

void Scene3dView::annotate(ImDrawList* dl, const FontSet& fonts, const FrameState& frame,
                           const Decor& decor, LabelPlacer* labels) const {
    const Impl& I = *impl_;
    const Camera& cam = I.camera;
    const ArrowScales& k = I.scales;
    const Palette& c = I.style.colours;
    const std::size_t n = std::min(frame.bodies.size(), I.scene.bodies.size());
    // Centre-of-mass markers, seen through the bodies.
    if (decor.com)
        for (std::size_t i = 0; i < n; ++i)
            if (!I.scene.bodies[i].is_static() && I.solids.bodies[i].drawn())
                draw_com_marker(dl, cam.project(frame.bodies[i].x), I.style.lw(I.style.com * 0.85f), c.ink,
                                c.background, 0.0f);
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
    if (!decor.labels || !labels) return;
    for (std::size_t i = 0; i < n; ++i)
        if (I.solids.bodies[i].drawn()) labels->avoid(I.screen_outline(i, frame.bodies[i]));
    struct Pending {
        ImVec2 anchor, direction;
        std::string text;
        Colour colour;
        ImFont* font;
    };
    std::vector<Pending> pending;
    if (decor.impacts)
        for (const ImpactMark& im : frame.impacts) {
            const ImVec2 p = cam.project(im.point);
            const ImVec2 tip = cam.project(im.point + k.k_impulse * im.impulse);
            pending.push_back({tip, ImVec2(tip.x - p.x, tip.y - p.y),
                               "P = " + format_number(im.impulse.norm()) + " N s", c.impulse, fonts.text});
            const ImVec2 nt = cam.project(im.point + 0.95 * k.unit * im.normal);
            pending.push_back({nt, ImVec2(nt.x - p.x, nt.y - p.y), "n", c.normal, fonts.text});
            const std::pair<std::size_t, const char*> ends[2] = {{im.a, "r_{a}"}, {im.b, "r_{b}"}};
            for (const auto& [i, name] : ends) {
                if (i >= n || !I.solids.bodies[i].drawn()) continue;
                const ImVec2 from = cam.project(frame.bodies[i].x);
                pending.push_back({ImVec2(0.5f * (from.x + p.x), 0.5f * (from.y + p.y)),
                                   ImVec2(-(p.y - from.y), p.x - from.x), name, c.lever, fonts.text});
            }
        }
    if (decor.velocities)
        for (std::size_t i = 0; i < n; ++i) {
            const Solid& solid = I.solids.bodies[i];
            if (I.scene.bodies[i].is_static() || !solid.drawn()) continue;
            const BodyState& s = frame.bodies[i];
            const ImVec2 from = cam.project(s.x);
            if (s.v.norm() * k.k_velocity > 1e-3 * k.unit) {
                const ImVec2 tip = cam.project(velocity_start(solid, s) + k.k_velocity * s.v);
                pending.push_back({tip, ImVec2(tip.x - from.x, tip.y - from.y),
                                   "v = " + format_number(s.v.norm()) + " m s\u207B\u00B9", c.velocity, fonts.text});
            }
            if (shows_spin(k, s)) {
                const ImVec2 tip = cam.project(spin_start(solid, s) + k.k_spin * s.w);
                pending.push_back({tip, ImVec2(tip.x - from.x, tip.y - from.y),
                                   "\u03C9 = " + format_number(s.w.norm()) + " rad s\u207B\u00B9", c.spin, fonts.text});
            }
        }
    for (std::size_t i = 0; i < n; ++i) {
        if (!I.solids.bodies[i].drawn()) continue;
        const ImVec2 top = cam.project(frame.bodies[i].x + Vec3(0, 0.5 * I.solids.bodies[i].size, 0));
        pending.push_back({top, ImVec2(0, -1), I.scene.bodies[i].name, c.ink, fonts.small});
    }
    const float pad = I.style.px(3.0f);
    for (const Pending& p : pending) {
        place_label(dl, fonts, labels, p.font, p.anchor, p.direction, p.text, p.colour,
                    with_alpha(c.background, 0.85f), pad, I.style.px(6.0f));
    }
}

}  // namespace collide::render
