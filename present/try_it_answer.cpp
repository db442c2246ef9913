// The Try-it panel's answer (present/try_it_answer.h): the lesson run once with the panel's
// values, and everything the panel shows of it, by the functions the command uses.
#include "present/try_it_answer.h"

#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/record.h"
#include "present/frame_times.h"
#include "present/lesson_plots.h"
#include "present/scene_run.h"
#include "present/shown_collision.h"
#include "present/site_plots.h"
#include "scenario/input_error.h"
#include "scenario/lesson.h"
#include "scenario/solve_problem.h"
#include "teach/event_problem.h"
#include "teach/html.h"
#include "teach/notation.h"
#include "teach/solve.h"
#include "teach/step_output.h"

namespace collide {
namespace {

using nlohmann::ordered_json;

// The name the reader is given; messages leave it out (the text came from no file).
const char* const kTextName = "<text>";

ordered_json xyz(const Vec3& v) { return ordered_json::array({v.x(), v.y(), v.z()}); }

// What the page draws of each body: its name, whether it is static, its shape (1D: a block of
// `length`; 2D: a disc's radius, a polygon's vertices in the body's frame, a half plane's
// normal and offset; 3D: a sphere's radius, a box's half extents along its own axes, a half
// space's normal and offset, its solid side normal . p <= offset: engine/shape3d.h Shape3).
ordered_json bodies_json(const Scene& scene) {
    ordered_json out = ordered_json::array();
    for (const SceneBody& b : scene.bodies) {
        ordered_json j{{"name", b.name}, {"static", b.is_static()}, {"shape", b.shape}};
        if (scene.dimension == 1) j["length"] = b.length;
        if (scene.dimension == 2) {
            const Shape2& s = b.shape2;
            if (s.kind == Shape2::Kind::disc) {
                j["kind"] = "disc";
                j["radius"] = s.radius;
            } else if (s.kind == Shape2::Kind::polygon) {
                j["kind"] = "polygon";
                ordered_json v = ordered_json::array();
                for (int k = 0; k < s.polygon.count; ++k)
                    v.push_back({s.polygon.vertices[k].x(), s.polygon.vertices[k].y()});
                j["vertices"] = v;
            } else {
                j["kind"] = "half_plane";
                j["normal"] = {s.normal.x(), s.normal.y()};
                j["offset"] = s.offset;
            }
        }
        if (scene.dimension == 3) switch (const Shape3& s = b.shape3; s.kind) {
                case Shape3::Kind::sphere: j.update({{"kind", "sphere"}, {"radius", s.radius}}); break;
                case Shape3::Kind::box: j.update({{"kind", "box"}, {"half", xyz(s.half)}}); break;
                case Shape3::Kind::half_space:
                    j.update({{"kind", "half_space"}, {"normal", xyz(s.normal)}, {"offset", s.offset}});
                    break;
            }
        out.push_back(j);
    }
    return out;
}

// The run's outcome of a collision where it differs from the two bodies alone (resolved_differs:
// other contacts at the same instant), in the solve JSON's shape and with its fields that the run
// gives: dimension, impulse, normal_impulse, a and b (v, w after), momentum, angular_momentum,
// kinetic_energy (before and after); "null" where the two alone are the run.
std::string run_json(const SolveProblem& problem, const Solution& alone, const Solution& run) {
    if (!resolved_differs(problem, alone, run)) return "null";
    std::ostringstream json;
    write_json(problem, run, json);
    const ordered_json full = ordered_json::parse(json.str());
    ordered_json out;
    for (const char* key :
         {"dimension", "impulse", "normal_impulse", "a", "b", "momentum", "angular_momentum", "kinetic_energy"})
        if (full.contains(key)) out[key] = full[key];
    return out.dump();
}

// The lesson's [[plot]]s of this run, as `collide material` draws them on the lesson page
// (plot-K.svg, its alt text, the folded table; present/site_plots.h), and their numbers: each
// series' points, the fitted line (slope, intercept, and along a chain the spacing and wave
// speed) or the ratios (each value over the one before, and the pair's e).
ordered_json plots_json(const Lesson& lesson, const SceneRun& run) {
    const std::vector<PlotData> plots = lesson_plots(lesson, lesson.scene, run);
    const std::vector<std::pair<std::string, std::string>> svgs = plot_svgs(plots);
    ordered_json out = ordered_json::array();
    // Numbers that are not finite (a ratio over a zero interval) as null.
    const auto finite = [](double x) { return std::isfinite(x) ? ordered_json(x) : ordered_json(nullptr); };
    for (std::size_t k = 0; k < plots.size(); ++k) {
        const PlotData& p = plots[k];
        ordered_json series = ordered_json::array();
        for (const PlotSeriesData& s : p.series)
            series.push_back({{"name", s.label}, {"words", s.words}, {"x", s.x}, {"y", s.y}, {"number", s.number}});
        ordered_json line = nullptr, ratio = nullptr;
        if (p.line) {
            line = {{"slope", p.line->slope},           {"intercept", p.line->intercept}, {"points", p.line->points},
                    {"slope_unit", p.line->slope_unit}, {"spacing", p.line->spacing},     {"speed", nullptr}};
            if (p.line->speed) line["speed"] = *p.line->speed;
        }
        if (p.ratio) {
            ordered_json ratios = ordered_json::array();
            for (double r : p.ratio->ratios) ratios.push_back(finite(r));
            ratio = {{"ratios", ratios}, {"mean", p.ratio->mean}, {"restitution", nullptr}};
            if (p.ratio->restitution) ratio["restitution"] = *p.ratio->restitution;
        }
        // What it plots, as the lesson file writes it: the panel's plot opens it to change an axis.
        const LessonPlot& L = lesson.plots[k];
        ordered_json ys = ordered_json::array();
        for (const PlotQuantity& y : L.y) ys.push_back(y.name);
        ordered_json spec{{"per", L.per == PlotPer::sample ? "sample" : "collision"}, {"x", L.x.name}, {"y", ys}};
        if (!L.pair.empty()) spec["pair"] = L.pair;
        if (!L.chain.empty()) spec["chain"] = L.chain;
        if (!L.instant.empty()) spec["instant"] = L.instant;
        if (L.counting != "collision") spec["counting"] = L.counting;
        if (L.fit != PlotFit::none) spec["fit"] = L.fit == PlotFit::line ? "line" : "ratio";
        if (L.fit == PlotFit::line && L.fit_from != 1) spec["fit_from"] = L.fit_from;
        out.push_back({{"file", svgs[k].first},
                       {"title", p.title},
                       {"spec", spec},
                       {"svg", svgs[k].second},
                       {"alt", plot_alt(p)},
                       {"data_html", plot_data_html(p)},
                       {"summary", p.summary},
                       {"missing", p.missing},
                       {"series", series},
                       {"line", line},
                       {"ratio", ratio}});
    }
    return out;
}

// What the panel's plot may put on an axis: every per-sample quantity of the lesson's scene
// (plot_quantities: the names a [[plot]] takes) and the per-collision ones, each with its words
// and unit as the plots write them.
ordered_json quantities_json(const Lesson& lesson) {
    ordered_json sample = ordered_json::array(), collision = ordered_json::array();
    for (const PlotQuantity& q : plot_quantities(lesson))
        sample.push_back(
            {{"name", q.name}, {"words", plot_quantity_words(q, lesson, false, "collision", false)}, {"unit", q.unit}});
    for (const PlotQuantity& q : plot_collision_quantities())
        collision.push_back({{"name", q.name},
                             {"words", plot_quantity_words(q, lesson, true, "collision", false)},
                             {"unit", q.unit},
                             {"x", q.name == "collision" || q.name == "t"},
                             {"y", q.name != "collision"}});
    return {{"sample", sample}, {"collision", collision}};
}

// The lesson of the text, read once per thread for the panel's answers to it (the page sends
// the same text with every move).
const Lesson& lesson_of(const std::string& text) {
    thread_local std::optional<Lesson> last;
    if (!last || last->source != text) {
        last.reset();  // (a text that fails to read leaves nothing kept)
        last = parse_lesson_text(text, kTextName, "");
    }
    return *last;
}

}  // namespace

std::string try_it_answer_json(const std::string& text, const std::string& values, double fps) {
    const Lesson& original = lesson_of(text);
    std::map<std::string, double> changed;
    const nlohmann::json v = nlohmann::json::parse(values.empty() ? "{}" : values);
    if (!v.is_object()) throw InputError("", {}, "values", "expected an object {\"A.mass\": 3, ...}");
    for (const auto& [name, x] : v.items()) {
        if (!x.is_number()) throw InputError("", {}, name, "expected a number");
        changed[name] = x.get<double>();
    }
    Lesson lesson = changed.empty() ? original : lesson_with_inputs(original, changed);
    lesson.scene.work_budget = kWasmWorkBudget;  // a page never waits long: refused beyond (RunError)
    lesson.scene.file.clear();
    const Scene& scene = lesson.scene;
    if (!(fps > 0 && fps <= 1000)) throw InputError("", {}, "fps", "expected 0 < fps <= 1000");
    // One run, as the site's (present/render_job.cpp run_stage): its frames for the plots too.
    const SceneRun ran = run_scene(scene, frame_times(scene, fps), nullptr, figure_keeps(&lesson));
    const AnyRecording& any = ran.record;

    std::string states = "[", events = "[";
    std::optional<CollisionInstant> collision;
    std::vector<CollisionInstant> figure_collisions;  // every [[figure]]'s, in order (as found)
    std::visit(
        [&](const auto& rec) {
            for (std::size_t k = 0; k < rec.times.size(); ++k)
                states += (k ? "," : "") + state_json(scene, rec.times[k], rec.states[k]);
            const std::vector<bool> gains = energy_gains(scene, rec.events);
            for (std::size_t k = 0; k < rec.events.size(); ++k)
                events += (k ? "," : "") + event_json(scene, rec.events[k], gains[k]);
            collision = page_collision(figure_picks(&lesson), rec);
            for (const CollisionPick& pick : figure_picks(&lesson))
                if (const std::optional<PairCollision> c = find_pick(rec, pick))
                    figure_collisions.push_back(with_roles(collision_instant(rec.events[c->first]), pick.a, pick.b));
        },
        any);
    states += "]";
    events += "]";

    ordered_json out;
    out["dimension"] = scene.dimension;
    out["duration"] = scene.duration;
    out["gravity"] = {scene.gravity.x(), scene.gravity.y(), scene.gravity.z()};
    out["bodies"] = bodies_json(scene);
    // The camera the lesson's [view] asks for (the 3D view starts there); null where unset.
    const auto opt = [](const auto& o) { return o ? ordered_json(*o) : ordered_json(nullptr); };
    const SceneView& sv = lesson.view;
    out["view"] = {{"azimuth", opt(sv.camera_azimuth)},
                   {"elevation", opt(sv.camera_elevation)},
                   {"target", sv.camera_target ? xyz(*sv.camera_target) : ordered_json(nullptr)},
                   {"distance", opt(sv.camera_distance)}};
    ordered_json vary = ordered_json::array();
    for (const LessonVary& w : original.vary)
        // (body, field and component tell the panel what a drag on the picture sets: "A", "v", 0
        // for A.v.x; -1 for a number that is no vector's component)
        vary.push_back({{"name", w.name()},
                        {"lo", w.lo},
                        {"hi", w.hi},
                        {"step", w.step},
                        {"value", w.lesson_value},
                        {"body", w.body},
                        {"field", w.field},
                        {"component", w.component},
                        {"in_proportion", w.in_proportion},
                        {"unit", html::vary_unit(w.field)}});
    out["vary"] = vary;
    out["values"] = changed;
    out["quantities"] = quantities_json(lesson);
    std::string worked = "null";
    if (collision) {
        const SolveProblem problem = collision_problem(scene, *collision);
        const Solution solution = solve(problem);
        const Solution run = as_resolved(problem, solution, *collision);
        std::ostringstream json;
        write_json(problem, solution, json);
        std::string html;
        {
            const notation::StudentNumbers student;  // as on the lesson page: 4 figures, no noise
            html = html::worked_html_beside_run(problem, solution, run, world_note(scene, *collision, solution.P));
        }
        ordered_json w{{"t", collision->t}, {"a", problem.a.name}, {"b", problem.b.name}, {"html", html}};
        // 3D: where the two are at the instant (the event's poses, between the page's frames),
        // with their velocities just before: the 3D view's "at" picture.
        if (scene.dimension == 3) {
            const auto pose = [](const CollisionInstant::Side& s) {
                return ordered_json{{"x", xyz(s.x)},
                                    {"v", xyz(s.v)},
                                    {"w", xyz(s.w)},
                                    {"orientation", {s.q.w(), s.q.x(), s.q.y(), s.q.z()}}};
            };
            w["at"] = {{problem.a.name, pose(collision->before_a)}, {problem.b.name, pose(collision->before_b)}};
        }
        // The solve JSON as `collide solve --format json` prints it, spliced in unchanged; and
        // where the run resolved the collision with other contacts of its instant, its outcome.
        worked = w.dump();
        worked.pop_back();
        worked += ",\"solve\":" + json.str() + ",\"run\":" + run_json(problem, solution, run) + "}";
    }
    // Each collision the lesson's figures show (a lesson of several, such as two bats hit at
    // two points): who, when, and `collide solve --format json`'s numbers for it.
    std::string figures = "[";
    for (std::size_t k = 0; k < figure_collisions.size(); ++k) {
        const SolveProblem problem = collision_problem(scene, figure_collisions[k]);
        const Solution solution = solve(problem);
        std::ostringstream json;
        write_json(problem, solution, json);
        std::string f =
            ordered_json{{"t", figure_collisions[k].t}, {"a", problem.a.name}, {"b", problem.b.name}}.dump();
        f.pop_back();
        figures += (k ? "," : "") + f + ",\"solve\":" + json.str() +
                   ",\"run\":" + run_json(problem, solution, as_resolved(problem, solution, figure_collisions[k])) +
                   "}";
    }
    figures += "]";
    std::string s = out.dump();
    s.pop_back();
    return s + ",\"worked\":" + worked + ",\"figures\":" + figures + ",\"plots\":" + plots_json(lesson, ran).dump() +
           ",\"states\":" + states + ",\"events\":" + events + "}";
}

}  // namespace collide
