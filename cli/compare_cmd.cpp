#include "cli/compare_cmd.h"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "scenario/input_error.h"
#include "scenario/lesson.h"
#include "teach/notation.h"
#include "scenario/scene_file.h"
#include "teach/step_output.h"
#include "scenario/toml_reader.h"
#include "compare/box2d_world.h"
#include "compare/match.h"
#include "cli/exit_code.h"
#include "engine/world.h"

namespace collide {

namespace {

using compare::Box2DEvent;
using compare::Comparison;
using nlohmann::ordered_json;
using Velocity = Event2::Velocity;

constexpr int kBadInput = cli::kExitBadInput;
constexpr double kMaxSteps = 1e8;  // Box2D steps a run may take

// ---- Input ----

// Reads the scenario and refuses, at the offending key, what Box2D cannot run.
Scene read_scene(const std::string& file) {
    // A scenario file, a lesson file or a lesson id (`collide compare box2d`).
    const std::string path = file == "-" ? file : resolve_lesson(file, lessons_dir());
    std::string name;
    const std::string text = read_input_file(path, &name);
    Scene scene = parse_scene_text(text, name, nullptr, lesson_tables());
    if (scene.title.empty() && path != "-" && parse_toml_text(text, name).contains("lesson"))
        scene.title = load_lesson(path).title;
    const auto why = compare::box2d_unsupported(scene);
    if (!why) return scene;
    const toml::table table = parse_toml_text(text, name);
    const TableReader root(table, name, "");
    if (why->body.empty()) root.table("scene")->fail(why->key, why->message);
    const toml::array* bodies = root.node("body")->as_array();
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        if (scene.bodies[i].name == why->body)
            TableReader(*bodies->get(i)->as_table(), name, "body[" + std::to_string(i + 1) + "]")
                .fail(why->key, why->message + " ('" + why->body + "')");
    throw InputError(name, {}, why->key, why->message);
}

// ---- The two runs ----

struct Sample {
    double t = 0.0;        // s: the output instant (collide's state)
    double t_box2d = 0.0;  // s: Box2D's state, at its last step at or before t
    std::vector<Body2> ours, theirs;
};

struct Run {
    Scene scene;
    compare::Box2DSettings settings;
    std::vector<Event2> ours;
    std::vector<Box2DEvent> theirs;
    std::vector<Sample> samples;
    std::vector<Comparison> matched;
};

Run run_both(const Scene& scene, const compare::Box2DSettings& settings, bool samples) {
    Run run;
    run.scene = scene;
    run.settings = settings;
    World2 world(scene);
    compare::Box2DWorld box(scene, settings);
    if (samples) {
        for (double t : output_times(scene)) {
            world.advance_to(t, &run.ours);
            box.advance_to(t, &run.theirs);
            run.samples.push_back({t, box.time(), world.bodies(), box.bodies()});
        }
    } else {
        world.advance_to(scene.duration, &run.ours);
        box.advance_to(scene.duration, &run.theirs);
    }
    run.matched = compare::match_events(scene, settings, run.ours, run.theirs);
    return run;
}

// ---- Numbers ----

std::string num(double x) { return notation::num_text(x); }
std::string num(const Vec2& v) { return "(" + num(v.x()) + ", " + num(v.y()) + ")"; }
ordered_json arr(const Vec2& v) { return ordered_json::array({v.x(), v.y()}); }
ordered_json velocity_json(const Velocity& u) { return {{"v", arr(u.v)}, {"w", u.w}}; }
ordered_json pair_json(const Velocity& a, const Velocity& b) {
    return {{"a", velocity_json(a)}, {"b", velocity_json(b)}};
}
template <class T>
ordered_json or_null(const std::optional<T>& x) {
    return x ? ordered_json(*x) : ordered_json(nullptr);
}

std::string materials(const compare::Box2DSettings& s) {
    return s.box2d_defaults ? "Box2D's defaults (restitution threshold 1 m/s, e = max(ea, eb), "
                              "mu = sqrt(mua mub))"
                            : "matched to collide (e = min(ea, eb), mu = sqrt(mua mub) set per contact in "
                              "PreSolve, restitution threshold 0)";
}

struct Summary {
    std::size_t matched = 0, agree = 0;
    double largest = 0.0;
};
Summary summarise(const Run& run) {
    Summary s;
    for (const Comparison& c : run.matched) {
        if (!c.difference) continue;
        ++s.matched;
        if (*c.difference <= compare::kAgree) ++s.agree;
        s.largest = std::max(s.largest, *c.difference);
    }
    return s;
}

// ---- Text ----

// Rows of cells written in left-aligned columns two spaces apart.
void write_columns(const std::vector<std::vector<std::string>>& rows, const std::string& indent, std::ostream& out) {
    std::vector<std::size_t> width;
    for (const auto& r : rows)
        for (std::size_t c = 0; c < r.size(); ++c) {
            if (width.size() <= c) width.push_back(0);
            width[c] = std::max(width[c], r[c].size());
        }
    for (const auto& r : rows) {
        std::string line = indent;
        for (std::size_t c = 0; c < r.size(); ++c)
            line += r[c] + (c + 1 < r.size() ? std::string(width[c] - r[c].size() + 2, ' ') : "");
        while (!line.empty() && line.back() == ' ') line.pop_back();
        out << line << "\n";
    }
}

void write_header(const Run& run, const std::string& file, std::ostream& out) {
    const compare::Box2DSettings& s = run.settings;
    out << "collide compare " << file << (run.scene.title.empty() ? "" : ": " + run.scene.title) << "\n";
    out << "Box2D 2.4.1 (float): dt = " << num(s.dt) << " s (" << num(1.0 / s.dt) << " Hz), " << s.velocity_iterations
        << " velocity and " << s.position_iterations << " position iterations\n";
    out << "materials: " << materials(s) << "\n";
    out << "collide: model " << model_name(run.scene.model) << ", policy " << policy_name(run.scene.policy)
        << ", exact impact times\n";
    if (run.scene.model == Model::matrix || run.scene.model == Model::stick)
        out << "note: Box2D has no " << model_name(run.scene.model)
            << " model; it uses Coulomb friction with the scene's mu\n";
    out << "difference: the largest |v1 - v2| or R |w1 - w2| between the engines' velocities after\n"
           "  the event (R: the body's bounding radius), divided by the pair's largest |v| or R |w|\n"
           "  before or after in either engine; they agree up to "
        << num(compare::kAgree) << "\n";
}

void write_event(const Run& run, std::size_t k, const Comparison& c, std::ostream& out) {
    const Scene& s = run.scene;
    out << "\nevent " << k + 1 << ": " << s.bodies[c.a].name << " - " << s.bodies[c.b].name << "   t: collide "
        << (c.collide ? num(c.collide->t) + " s" : "-") << ", box2d "
        << (c.box2d ? num(c.box2d->t) + " s (step " + std::to_string(c.box2d->step) +
                          (c.box2d->continuous ? ", continuous" : "") + ")"
                    : "-")
        << "\n";
    std::vector<std::vector<std::string>> rows{{"", "", "v before", "w before", "v after", "w after"}};
    for (int side = 0; side < 2; ++side) {
        const std::size_t i = side == 0 ? c.a : c.b;
        if (s.bodies[i].is_static()) continue;
        std::string name = s.bodies[i].name;
        auto row = [&](const std::string& engine, const Velocity& b, const Velocity& a) {
            rows.push_back({name, engine, num(b.v), num(b.w), num(a.v), num(a.w)});
            name.clear();
        };
        if (c.collide)
            row("collide", side == 0 ? c.collide->before_a : c.collide->before_b,
                side == 0 ? c.collide->after_a : c.collide->after_b);
        if (c.box2d)
            row("box2d", side == 0 ? c.box2d->before_a : c.box2d->before_b,
                side == 0 ? c.box2d->after_a : c.box2d->after_b);
    }
    write_columns(rows, "  ", out);
    if (c.collide && c.box2d)
        out << "  normal: collide " << num(c.collide->normal) << ", box2d " << num(c.box2d->normal) << " ("
            << c.box2d->points << (c.box2d->points == 1 ? " point" : " points")
            << (c.box2d->others > 0 ? ", " + std::to_string(c.box2d->others) + " other contact" +
                                          (c.box2d->others == 1 ? "" : "s") + " in its step"
                                    : "")
            << ")\n";
    out << "  difference " << (c.difference ? num(*c.difference) : "-") << ": "
        << (c.reason.empty() ? "agree" : c.reason) << "\n";
}

void write_samples_text(const Run& run, std::ostream& out) {
    out << "\nsamples (collide at t; Box2D at its last step at or before t)\n";
    std::vector<std::vector<std::string>> rows{
        {"t (s)", "body", "engine", "x (m)", "angle (rad)", "v (m/s)", "w (rad/s)"}};
    for (const Sample& p : run.samples)
        for (std::size_t i = 0; i < run.scene.bodies.size(); ++i) {
            if (run.scene.bodies[i].is_static()) continue;
            const Body2 &x = p.ours[i], &y = p.theirs[i];
            rows.push_back(
                {num(p.t), run.scene.bodies[i].name, "collide", num(x.position), num(x.angle), num(x.v), num(x.w)});
            rows.push_back({"", "", "box2d", num(y.position), num(y.angle), num(y.v), num(y.w)});
        }
    write_columns(rows, "", out);
}

void write_text(const Run& run, const std::string& file, std::ostream& out) {
    write_header(run, file, out);
    for (std::size_t k = 0; k < run.matched.size(); ++k) write_event(run, k, run.matched[k], out);
    if (!run.samples.empty()) write_samples_text(run, out);
    const Summary sum = summarise(run);
    out << "\nsummary: " << run.ours.size() << " events in collide, " << run.theirs.size() << " in Box2D; "
        << sum.matched << " matched, " << sum.agree << " agree";
    if (sum.matched > 0) out << "; largest difference " << num(sum.largest);
    out << "\n";
}

// ---- JSON ----

ordered_json event_json(const Run& run, const Comparison& c) {
    const Scene& s = run.scene;
    ordered_json j;
    j["a"] = s.bodies[c.a].name;
    j["b"] = s.bodies[c.b].name;
    j["t"] = {{"collide", c.collide ? ordered_json(c.collide->t) : ordered_json(nullptr)},
              {"box2d", c.box2d ? ordered_json(c.box2d->t) : ordered_json(nullptr)}};
    j["collide"] = c.collide ? pair_json(c.collide->after_a, c.collide->after_b) : ordered_json(nullptr);
    j["box2d"] = c.box2d ? pair_json(c.box2d->after_a, c.box2d->after_b) : ordered_json(nullptr);
    j["difference"] = or_null(c.difference);
    j["reason"] = c.reason;
    // Beyond the documented fields: the state before, the normals and Box2D's contact.
    j["before"] = {{"collide", c.collide ? pair_json(c.collide->before_a, c.collide->before_b) : ordered_json(nullptr)},
                   {"box2d", c.box2d ? pair_json(c.box2d->before_a, c.box2d->before_b) : ordered_json(nullptr)}};
    j["difference_before"] = or_null(c.difference_before);
    j["normal"] = {{"collide", c.collide ? arr(c.collide->normal) : ordered_json(nullptr)},
                   {"box2d", c.box2d ? arr(c.box2d->normal) : ordered_json(nullptr)}};
    j["normal_degrees"] = or_null(c.normal_degrees);
    j["impulse"] = {{"collide", c.collide ? arr(c.collide->impulse) : ordered_json(nullptr)},
                    {"box2d", c.box2d ? arr(c.box2d->impulse) : ordered_json(nullptr)}};
    if (c.box2d)
        j["box2d_contact"] = {{"step", c.box2d->step},         {"continuous", c.box2d->continuous},
                              {"points", c.box2d->points},     {"other_contacts", c.box2d->others},
                              {"approach", c.box2d->approach}, {"restitution", c.box2d->restitution},
                              {"friction", c.box2d->friction}, {"threshold", c.box2d->threshold}};
    return j;
}

ordered_json bodies_json(const Scene& s, const std::vector<Body2>& bodies) {
    ordered_json j = ordered_json::object();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (s.bodies[i].is_static()) continue;
        const Body2& b = bodies[i];
        j[s.bodies[i].name] = {{"x", arr(b.position)}, {"v", arr(b.v)}, {"w", b.w}, {"angle", b.angle}};
    }
    return j;
}

void write_json(const Run& run, std::ostream& out) {
    ordered_json j;
    j["events"] = ordered_json::array();
    for (const Comparison& c : run.matched) j["events"].push_back(event_json(run, c));
    const compare::Box2DSettings& s = run.settings;
    j["settings"] = {{"box2d", "2.4.1"},
                     {"dt", s.dt},
                     {"velocity_iterations", s.velocity_iterations},
                     {"position_iterations", s.position_iterations},
                     {"materials", s.box2d_defaults ? "box2d-defaults" : "matched"},
                     {"model", model_name(run.scene.model)},
                     {"policy", policy_name(run.scene.policy)},
                     {"agree", compare::kAgree}};
    const Summary sum = summarise(run);
    j["summary"] = {{"collide_events", run.ours.size()},
                    {"box2d_events", run.theirs.size()},
                    {"matched", sum.matched},
                    {"agree", sum.agree},
                    {"largest_difference", sum.matched ? ordered_json(sum.largest) : ordered_json(nullptr)}};
    if (!run.samples.empty()) {
        j["samples"] = ordered_json::array();
        for (const Sample& p : run.samples)
            j["samples"].push_back({{"t", p.t},
                                    {"t_box2d", p.t_box2d},
                                    {"collide", bodies_json(run.scene, p.ours)},
                                    {"box2d", bodies_json(run.scene, p.theirs)}});
    }
    out << j.dump() << "\n";
}

// An option out of range: "collide: error: --dt: ..." (exit 2).
std::string check_options(const CompareOptions& o, const Scene& scene) {
    if (!(o.dt > 0.0) || !std::isfinite(o.dt)) return "--dt: expected a time step > 0 (s)";
    if (scene.duration / o.dt > kMaxSteps) return "--dt: the scene's duration / dt gives more than 10^8 Box2D steps";
    if (o.velocity_iterations < 1 || o.velocity_iterations > 10000) return "--velocity-iterations: expected 1 to 10000";
    if (o.position_iterations < 0 || o.position_iterations > 10000) return "--position-iterations: expected 0 to 10000";
    return "";
}

}  // namespace

int run_compare(const CompareOptions& options, std::ostream& out, std::ostream& err) {
    return cli::run_command(err, [&] {
        const Scene scene = read_scene(options.file);
        const std::string bad = check_options(options, scene);
        if (!bad.empty()) {
            err << "collide: error: " << bad << "\n";
            return kBadInput;
        }
        compare::Box2DSettings settings;
        settings.dt = options.dt;
        settings.velocity_iterations = options.velocity_iterations;
        settings.position_iterations = options.position_iterations;
        settings.box2d_defaults = options.box2d_defaults;
        const Run run = run_both(scene, settings, options.samples);
        // Write to memory first: on any failure nothing half-written reaches out.
        std::ostringstream text;
        if (options.json) write_json(run, text);
        else write_text(run, options.file, text);
        out << text.str() << std::flush;
        return 0;
    });
}

}  // namespace collide
