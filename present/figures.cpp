#include "present/figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "render/frame_state.h"
#include "teach/notation.h"

namespace collide {

using render::FrameState;

namespace {

std::string fixed_text(double x, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
    return buf;
}

// The captions under the three panels: the moments' times, and that before and after show
// the velocities of the instant (drawn where the bodies were a moment earlier or later).
std::vector<std::string> time_notes(const Moments& moments, int decimals) {
    // Drawn at the instant itself (no sample between, or a contact among others at that
    // instant): the velocities just before or after it, where the bodies touch.
    const auto note = [&](double t, const char* when) {
        return (t == moments.at ? "where they touch" : "pose at t = " + fixed_text(t, decimals) + " s") +
               ", velocities just " + when;
    };
    return {note(moments.before, "before"), "t = " + fixed_text(moments.at, decimals) + " s",
            note(moments.after, "after")};
}

// The three moments drawn by a renderer framed on them: no trails, at the instant the impulse
// instead of the velocities.
// What each panel drew goes to `annotations` when given.
std::vector<render::Image> three_panels(render::Renderer& renderer, const Moments& moments,
                                        const std::vector<render::PointMark>& points,
                                        std::vector<render::Annotations>* annotations = nullptr) {
    std::vector<render::Image> panels;
    for (int k = 0; k < 3; ++k) {
        render::Decor d;
        d.velocities = k != 1;
        d.focus = moments.focus;
        d.points = points;
        d.trails = false;
        panels.push_back(renderer.render(moments.states[k], d));
        if (annotations) annotations->push_back(renderer.annotations());
    }
    return panels;
}

void write_png(const PictureOut& out, const std::string& name, const render::Image& image) {
    render::write_png_atomic(out.dir + "/" + name, image.width, image.height, image.rgba.data(), out.png);
}

// The before / at / after panels of the first collision, framed on those three moments without
// the table (figure.png's panels), and the figure of the three with their captions.
Figure collision_figure(render::GlContext& context, const Scene& scene, const SceneView& view,
                        const render::RenderSettings& settings, const Moments& moments) {
    const int height = settings.height;
    const bool three_d = settings.view == render::ViewKind::perspective;
    Figure out;
    out.points = points_of(view);
    // The figure: three panels framed on these moments, without the table.
    render::RenderSettings panel = settings;
    panel.points = out.points;
    panel.header = false;
    panel.table = false;
    panel.plots = false;
    panel.timeline = false;
    panel.formula = {};
    panel.directions = view.directions;
    panel.font_height = height;
    // A 2D figure about one pair: that pair, at its size. (A 1D row stays whole: its blocks
    // stand side by side, and the row is the context of each contact.)
    if (scene.dimension == 2) panel.frame_bodies = moments.focus;
    std::vector<FrameState> three(moments.states, moments.states + 3);
    // Panels of about the same area, shaped like what they show (the 3D view: 4:3).
    double aspect = 4.0 / 3.0;
    if (!three_d) {
        render::DiagramView probe(scene, render::Style::for_height(height));
        probe.frame_only(panel.frame_bodies);
        probe.frame_points(out.points);
        probe.fit(three, moments.states[1].impacts, ImVec4(0, 0, 1000, 1000));
        const Vec2 size = probe.box_hi() - probe.box_lo();
        if (size.x() > 0 && size.y() > 0) aspect = std::clamp(size.x() / size.y(), 0.8, 3.0);
    }
    // Laid out for the page (kColumnWidth, kWideFigureWidth at 720p; scaled with the size):
    // wide strips stacked, the others side by side.
    const double scale = height / 720.0;
    const double gap = 20.0;  // compose_figure's margin at 720p
    out.stacked = aspect >= 2.0;
    const double width = out.stacked ? kColumnWidth - 2 * gap : (kWideFigureWidth - 4 * gap) / 3;
    panel.width = static_cast<int>(std::lround(scale * width));
    panel.height = static_cast<int>(std::lround(scale * width / aspect));
    render::Renderer panels_renderer(context, scene, panel);
    panels_renderer.prepare(three, moments.states[1].impacts);
    out.panels = three_panels(panels_renderer, moments, out.points, &out.annotations);
    out.times[0] = moments.before;
    out.times[1] = moments.at;
    out.times[2] = moments.after;
    std::vector<std::string> notes = time_notes(moments, settings.time_decimals + 1);
    if (view.directions && scene.dimension == 1) {
        // The page's captions: the left block catches the right one before, and does not pass
        // it after. The arrows show the positive direction; the velocities may be negative.
        // With the bodies' names, whichever of them the lesson calls a.
        std::size_t left = moments.instant.a, right = moments.instant.b;
        if (moments.states[1].bodies[left].x.x() > moments.states[1].bodies[right].x.x()) std::swap(left, right);
        const std::string L = scene.bodies[left].name, R = scene.bodies[right].name;
        const double vl = moments.states[2].bodies[left].v.x(), vr = moments.states[2].bodies[right].v.x();
        notes[0] += "     v_{" + L + "i} > v_{" + R + "i}";
        notes[2] += "     v_{" + L + "f}" + (vl <= vr ? " \u2264 " : " > ") + "v_{" + R + "f}";
    }
    out.figure =
        render::compose_figure(context, out.panels, {"before", "at collision", "after"}, notes, height, out.stacked);
    out.panel = panel;
    return out;
}

}  // namespace

double trail_seconds(const Scene& scene) { return std::min(1.0, 0.3 * scene.duration); }

std::vector<render::PointMark> points_of(const SceneView& view) {
    std::vector<render::PointMark> out;
    for (const ViewMark& m : view.marks) out.push_back({m.body, m.at, m.name, m.velocity});
    return out;
}

void write_stills(render::Renderer& frames, const CollisionShots& shots, const PictureOut& out) {
    const char* names[3] = {"before.png", "at.png", "after.png"};
    for (int k = 0; k < 3; ++k) {
        FrameState f = shots.moments.states[k];
        render::add_trails(shots.run.frames, trail_seconds(shots.scene), &f);
        render::Decor d;
        d.velocities = k != 1;  // at the instant: the impulse, not the velocities
        d.focus = shots.moments.focus;
        d.points = points_of(shots.view);
        d.directions = shots.view.directions;
        write_png(out, names[k], frames.render(f, d));
    }
}

std::string annotations_json(const Scene& scene, const Figure* figure) {
    std::vector<std::string> names;
    for (const SceneBody& b : scene.bodies) names.push_back(b.name);
    std::ostringstream out;
    out << "{\n  \"dimension\": " << scene.dimension << ",\n";
    if (!figure || figure->annotations.size() != 3) {
        out << "  \"panels\": {}\n}\n";  // no collision: no figure
        return out.str();
    }
    const char* keys[3] = {"before", "at", "after"};
    out << "  \"view\": \"" << (figure->panel.view == render::ViewKind::perspective ? "3d" : "2d") << "\",\n";
    out << "  \"panel_size\": [" << figure->panel.width << ", " << figure->panel.height << "],\n";
    out << "  \"times\": {";
    for (int k = 0; k < 3; ++k)
        out << (k ? ", " : "") << "\"" << keys[k] << "\": " << notation::num_data(figure->times[k]);
    out << "},\n  \"panels\": {";
    for (int k = 0; k < 3; ++k) {
        out << (k ? ",\n" : "\n") << "    \"" << keys[k] << "\": ";
        render::write_annotations_json(out, figure->annotations[static_cast<std::size_t>(k)], scene.dimension, names,
                                       4);
    }
    out << "\n  }\n}\n";
    return out.str();
}

Figure make_figure(render::GlContext& context, const CollisionShots& shots, const render::RenderSettings& settings) {
    return collision_figure(context, shots.scene, shots.view, settings, shots.moments);
}

Figure write_figure(render::GlContext& context, const CollisionShots& shots, const render::RenderSettings& settings,
                    const PictureOut& out, int number) {
    Figure fig = make_figure(context, shots, settings);
    const std::string suffix = number > 1 ? "-" + std::to_string(number) : "";
    render::write_file_atomic(out.dir + "/annotations" + suffix + ".json", annotations_json(shots.scene, &fig));
    // A thumbnail (lesson indexes): the first figure's collision panel, 480 pixels wide.
    if (number <= 1) write_png(out, "thumb.png", render::shrink(fig.panels[1], 480));
    write_png(out, "figure" + suffix + ".png", fig.figure);
    return fig;
}

void write_variants(render::GlContext& context, const std::vector<VariantRow>& rows,
                    const render::RenderSettings& settings, const Figure& figure, const PictureOut& out) {
    std::vector<render::Image> images;
    for (const VariantRow& row : rows) {
        const Moments& m = row.moments;
        std::vector<FrameState> three(m.states, m.states + 3);
        render::RenderSettings panel = figure.panel;
        if (!panel.frame_bodies.empty()) panel.frame_bodies = m.focus;
        render::Renderer r(context, *row.scene, panel);
        r.prepare(three, m.states[1].impacts);
        images.push_back(render::compose_figure(
            context, three_panels(r, m, figure.points), {row.label + ": before", "at collision", "after"},
            time_notes(m, settings.time_decimals + 1), settings.height, figure.stacked));
    }
    write_png(out, "variants.png", render::stack_vertically(images));
}

std::optional<render::Image> first_collision_figure(render::GlContext& context, const Scene& scene,
                                                    const SceneView& view, const render::RenderSettings& settings,
                                                    const SceneRun& run) {
    const std::optional<Moments> m = first_moments(scene, run);
    if (!m) return std::nullopt;
    return collision_figure(context, scene, view, settings, *m).figure;
}

}  // namespace collide
