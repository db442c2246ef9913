#include "cli/render_cmd.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "teach/event_problem.h"
#include "scenario/input_error.h"
#include "teach/lesson.h"
#include "teach/lesson_penalty.h"
#include "cli/scene_run.h"
#include "teach/notation.h"
#include "scenario/scene_file.h"
#include "teach/solve.h"
#include "cli/step.h"
#include "render/context.h"
#include "render/frame_sink.h"
#include "render/frame_state.h"
#include "render/png.h"
#include "render/renderer.h"
#include "render/video.h"

namespace collide {

namespace fs = std::filesystem;
using render::FrameState;
using render::ImpactMark;

namespace {

constexpr int kBadInput = 2;
const char* const kCommand = "";  // option errors name the option, not a file

// ---- Stopping on SIGINT / SIGTERM ----

// Set by the signal handler; the render loop checks it between frames.
std::atomic<bool> g_interrupted{false};
extern "C" void on_signal(int) { g_interrupted.store(true); }
bool interrupted() { return g_interrupted.load(); }

// While alive, SIGINT and SIGTERM ask the render to stop between frames instead of killing
// the process in the middle of a file.
class SignalGuard {
public:
    SignalGuard() {
        g_interrupted.store(false);
        struct sigaction sa {};
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        sigaction(SIGINT, &sa, &old_int_);
        sigaction(SIGTERM, &sa, &old_term_);
    }
    ~SignalGuard() {
        sigaction(SIGINT, &old_int_, nullptr);
        sigaction(SIGTERM, &old_term_, nullptr);
    }
    SignalGuard(const SignalGuard&) = delete;
    SignalGuard& operator=(const SignalGuard&) = delete;

private:
    struct sigaction old_int_ {}, old_term_ {};
};

std::string num(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", x);
    return buf;
}

// ---- The worked example of the first collision ----

struct WorkedExample {
    SolveProblem problem;
    Solution solution;
    render::FormulaText formula;  // the overlay: the response model's formula and numbers
};

WorkedExample worked_example(const Scene& scene, const CollisionInstant& c) {
    WorkedExample w;
    w.problem = collision_problem(scene, c);
    w.solution = solve(w.problem);
    char heading[160];
    std::snprintf(heading, sizeof heading, "Collision of %s and %s  (%s, e = %s)",
                  scene.bodies[c.a].name.c_str(), scene.bodies[c.b].name.c_str(),
                  model_name(w.problem.model), notation::num_text(w.problem.restitution).c_str());
    w.formula.heading = heading;
    // The last two steps of the response model: a step's title carries its formula after two
    // spaces ("Impulse  j = ..."), its lines the numbers.
    const std::vector<WorkedStep> steps = worked_steps(w.problem, w.solution);
    std::vector<const WorkedStep*> response;
    for (const WorkedStep& st : steps)
        if (st.response) response.push_back(&st);
    if (response.size() > 2) response.erase(response.begin(), response.end() - 2);
    for (const WorkedStep* st : response) {
        const std::size_t gap = st->title.find("  ");
        if (gap != std::string::npos) w.formula.lines.push_back(notation::to_rich(st->title.substr(gap + 2)));
        for (const std::string& line : st->lines) w.formula.lines.push_back(notation::to_rich(line));
    }
    // The formula is for one contact point. When the world resolved several points at this
    // instant (a face on a face, a resting stack), its impulse differs: say so, with its value.
    const double scale = std::max({w.solution.P.norm(), c.impulse.norm(), 1e-300});
    // (The page's listing is left alone: its J is not what B receives, erratum 7, as its steps say.)
    if ((w.solution.P - c.impulse).norm() > 1e-6 * scale && scene.model != Model::page_listing) {
        const int d = scene.dimension;
        std::string P = d == 1 ? notation::num_text(c.impulse.x()) : notation::vec(c.impulse, d).txt;
        w.formula.note = "The world resolved several contact points here; its total impulse is P = " + P +
                         " N\u00B7s";
    }
    return w;
}

// ---- Output directory ----

void prepare_directory(const RenderRequest& rq) {
    std::error_code ec;
    const fs::path dir(rq.out_dir);
    if (fs::exists(dir, ec)) {
        if (!fs::is_directory(dir, ec))
            throw InputError(rq.out_dir, {}, "", "exists and is not a directory");
        if (!fs::is_empty(dir, ec) && !rq.force)
            throw InputError(rq.out_dir, {}, "",
                             "directory is not empty (use --force to write into it)");
    }
    fs::create_directories(dir / "frames", ec);
    if (ec) throw std::runtime_error(rq.out_dir + ": cannot create directory: " + ec.message());
    // --force: old frames would mix with the new ones; remove ours (and only ours).
    for (const fs::directory_entry& e : fs::directory_iterator(dir / "frames", ec)) {
        const std::string name = e.path().filename().string();
        if (name.rfind("frame_", 0) == 0 && e.path().extension() == ".png") fs::remove(e.path(), ec);
    }
    for (const char* name : {"before.png", "at.png", "after.png", "figure.png", "thumb.png", "variants.png", "worked-example.md",
                             "lesson.md", "penalty.svg", "penalty-overlap.svg", "penalty.csv", "animation.mp4", "animation.gif"})
        fs::remove(dir / name, ec);
}

std::string fixed_text(double x, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
    return buf;
}

// A lesson's variants side by side: variants.png and, per scene, the first collision's
// impulse, velocities after and kinetic energy lost.
std::string variants_markdown(const RenderReport& r) {
    if (r.variants.empty()) return "";
    const int d = r.scene.dimension;
    const auto V = [d](const Vec3& v) {
        if (d == 1) return notation::num_text(v.x());
        return notation::vec(v, d).txt;
    };
    std::ostringstream md;
    md << "\n## Side by side\n\n![the scene and its variants](variants.png)\n\n"
       << "| | impulse on b (N s) | a after (m/s) | b after (m/s) | kinetic energy lost (J) |\n"
       << "|---|---|---|---|---|\n";
    for (const RenderReport::Variant& v : r.variants) {
        if (!v.first) {
            md << "| " << v.label << " | no collision | | | |\n";
            continue;
        }
        const CollisionInstant& c = *v.first;
        md << "| " << v.label << " (" << r.scene.bodies[c.a].name << " on " << r.scene.bodies[c.b].name
           << ") | " << V(c.impulse) << " | " << V(c.va_after) << " | " << V(c.vb_after) << " | "
           << notation::num_text(v.ke_before - v.ke_after) << " |\n";
    }
    return md.str();
}

// The before / at / after panels of the first collision, framed on those three moments without
// the table (figure.png's panels), and the figure of the three with their captions.
struct Figure {
    std::vector<render::Image> panels;
    render::Image figure;
    render::RenderSettings panel;  // the panels' settings (variants.png uses them too)
};

Figure collision_figure(render::GlContext& context, const Scene& scene, const SceneView& view,
                        const render::RenderSettings& settings, const Moments& moments) {
    const int height = settings.height;
    const bool three_d = settings.view == render::ViewKind::perspective;
    Figure out;
    // The figure: three panels framed on these moments, without the table.
    render::RenderSettings panel = settings;
    panel.header = false;
    panel.table = false;
    panel.plots = false;
    panel.timeline = false;
    panel.formula = {};
    panel.directions = view.directions;
    panel.font_height = height;
    std::vector<FrameState> three(moments.states, moments.states + 3);
    // Panels of about the same area, shaped like what they show (the 3D view: 4:3).
    double aspect = 4.0 / 3.0;
    if (!three_d) {
        render::DiagramView probe(scene, render::Style::for_height(height));
        probe.fit(three, moments.states[1].impacts, ImVec4(0, 0, 1000, 1000));
        const Vec2 size = probe.box_hi() - probe.box_lo();
        if (size.x() > 0 && size.y() > 0) aspect = std::clamp(size.x() / size.y(), 0.8, 3.0);
    }
    const double area = 0.62 * 0.62 * 1.3 * height * height;
    panel.height = static_cast<int>(std::lround(std::sqrt(area / aspect)));
    panel.width = static_cast<int>(std::lround(std::sqrt(area * aspect)));
    render::Renderer panels_renderer(context, scene, panel);
    panels_renderer.prepare(three, moments.states[1].impacts);
    for (int k = 0; k < 3; ++k) {
        render::Decor d;
        d.velocities = k != 1;
        d.trails = false;
        out.panels.push_back(panels_renderer.render(moments.states[k], d));
    }
    const int decimals = settings.time_decimals + 1;
    std::vector<std::string> notes = {"t = " + fixed_text(moments.before, decimals) + " s",
                                      "t = " + fixed_text(moments.at, decimals) + " s",
                                      "t = " + fixed_text(moments.after, decimals) + " s"};
    if (view.directions && scene.dimension == 1) {
        // The page's captions: a (the left block) catches b before, and does not pass it
        // after. The arrows show the positive direction; the velocities may be negative.
        // With the bodies' names (the page's a and b are the left and the right block).
        const std::size_t a = moments.instant.a, b = moments.instant.b;
        const std::string A = scene.bodies[a].name, B = scene.bodies[b].name;
        const double va = moments.states[2].bodies[a].v.x(), vb = moments.states[2].bodies[b].v.x();
        notes[0] += "     v_{" + A + "i} > v_{" + B + "i}";
        notes[2] += "     v_{" + A + "f}" + (va <= vb ? " \u2264 " : " > ") + "v_{" + B + "f}";
    }
    out.figure = render::compose_figure(context, out.panels, {"before", "at collision", "after"}, notes, height);
    out.panel = panel;
    return out;
}

}  // namespace

std::optional<render::FormulaText> first_collision_formula(const Scene& scene, const SceneRun& run) {
    const std::optional<Moments> m = first_moments(scene, run);
    if (!m) return std::nullopt;
    return worked_example(scene, m->instant).formula;
}

std::optional<render::Image> first_collision_figure(render::GlContext& context, const Scene& scene,
                                                    const SceneView& view, const render::RenderSettings& settings,
                                                    const SceneRun& run) {
    const std::optional<Moments> m = first_moments(scene, run);
    if (!m) return std::nullopt;
    return collision_figure(context, scene, view, settings, *m).figure;
}

namespace {

double write_outputs(const RenderRequest& rq, const Scene& scene, const SceneView& view,
                     const std::vector<double>& times, const SceneRun& run, const Moments* moments,
                     const WorkedExample* worked, const Lesson* lesson,
                     std::vector<RenderReport::Variant>* variant_results, std::ostream& err) {
    const Quality& q = rq.frame.quality;
    const int width = rq.frame.width, height = rq.frame.height;

    std::unique_ptr<render::GlContext> context = render::create_gl_context(rq.backend);
    const render::RenderSettings settings = frame_settings(rq.frame, scene, view, worked ? &worked->formula : nullptr);
    render::Renderer renderer(*context, scene, settings);
    renderer.prepare(run.frames, run.impacts);

    // Frames: rendering here, PNG encoding beside it.
    const double trail = std::min(1.0, 0.3 * scene.duration);
    render::FrameSinkOptions sink_options;
    sink_options.dir = rq.out_dir + "/frames";
    sink_options.png = q.png;
    sink_options.threads = q.encoders;
    sink_options.buffers = q.encoders + 2;
    render::FrameSink sink(width, height, sink_options);
    const bool terminal = !rq.quiet && err.rdbuf() == std::cerr.rdbuf() && isatty(STDERR_FILENO);
    render::ProgressBar progress(err, static_cast<long>(times.size()), terminal, "rendering");
    std::size_t next_impact = 0;
    render::Decor decor;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < run.frames.size(); ++k) {
        if (interrupted()) {  // SIGINT / SIGTERM: the frames already handed over are finished
            sink.finish();
            progress.finish();
            throw Interrupted(sink.written());
        }
        FrameState f = run.frames[k];
        render::add_trails(run.frames, trail, &f);
        // A collision shows in the first frame at or after it.
        while (next_impact < run.impacts.size() && run.impacts[next_impact].t <= f.t)
            f.impacts.push_back(run.impacts[next_impact++]);
        render::FrameSink::Buffer* buffer = sink.acquire();
        renderer.render(f, decor, buffer->data());
        sink.submit(static_cast<long>(k), buffer);
        progress.update(sink.written());
    }
    sink.finish();
    progress.finish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    if (moments) {
        // The three moments at the frame size, as in the animation (with trails up to then).
        const char* names[3] = {"before.png", "at.png", "after.png"};
        std::vector<render::Image> panels;
        for (int k = 0; k < 3; ++k) {
            FrameState f = moments->states[k];
            render::add_trails(run.frames, trail, &f);
            render::Decor d;
            d.velocities = k != 1;  // at the instant: the impulse, not the velocities
            d.directions = view.directions;
            const render::Image image = renderer.render(f, d);
            render::write_png_atomic(rq.out_dir + "/" + names[k], image.width, image.height,
                                     image.rgba.data(), q.png);
        }
        Figure fig = collision_figure(*context, scene, view, settings, *moments);
        panels = std::move(fig.panels);
        const render::Image& figure = fig.figure;
        const render::RenderSettings& panel = fig.panel;
        const int decimals = settings.time_decimals + 1;
        // A thumbnail (lesson indexes): the collision panel, 480 pixels wide.
        const render::Image thumb = render::shrink(panels[1], 480);
        render::write_png_atomic(rq.out_dir + "/thumb.png", thumb.width, thumb.height, thumb.rgba.data(), q.png);
        render::write_png_atomic(rq.out_dir + "/figure.png", figure.width, figure.height,
                                 figure.rgba.data(), q.png);

        // A lesson's variants: the same three moments of each, one row per scene, framed
        // alike (the panels of the lesson's own scene set the size).
        if (lesson && !lesson->variants.empty()) {
            std::vector<render::Image> rows;
            std::vector<std::pair<std::string, const Scene*>> scenes = {
                {lesson->label.empty() ? "as above" : lesson->label, &scene}};
            for (const LessonVariant& v : lesson->variants) scenes.push_back({v.label, &v.scene});
            for (const auto& [label, s] : scenes) {
                RenderReport::Variant result{label, std::nullopt, 0.0, 0.0};
                // Each variant is run once, sampled as the lesson's own scene.
                const std::optional<Moments> m = s == &scene ? std::optional<Moments>(*moments)
                                                             : first_moments(*s, run_scene(*s, times));
                if (!m) {
                    variant_results->push_back(result);
                    continue;
                }
                result.first = m->instant;
                result.ke_before = pair_kinetic_energy(*s, m->instant, false);
                result.ke_after = pair_kinetic_energy(*s, m->instant, true);
                variant_results->push_back(result);
                std::vector<FrameState> three_v(m->states, m->states + 3);
                render::Renderer r(*context, *s, panel);
                r.prepare(three_v, m->states[1].impacts);
                std::vector<render::Image> row;
                for (int k = 0; k < 3; ++k) {
                    render::Decor d;
                    d.velocities = k != 1;
                    d.trails = false;
                    row.push_back(r.render(m->states[k], d));
                }
                rows.push_back(render::compose_figure(*context, row,
                                                      {label + ": before", "at collision", "after"},
                                                      {"t = " + fixed_text(m->before, decimals) + " s",
                                                       "t = " + fixed_text(m->at, decimals) + " s",
                                                       "t = " + fixed_text(m->after, decimals) + " s"},
                                                      height));
            }
            const render::Image all = render::stack_vertically(rows);
            render::write_png_atomic(rq.out_dir + "/variants.png", all.width, all.height, all.rgba.data(), q.png);
        }
    }
    return seconds;
}

}  // namespace

RenderReport render_scenario(const RenderRequest& rq, std::ostream& err) {
    const SignalGuard signals;
    RenderReport report;
    report.scene = load_scenario(rq.scenario, &report.view, &report.lesson);
    const Scene& scene = report.scene;
    Scene timing = scene;
    timing.output_dt = 1.0 / rq.frame.fps;
    const std::vector<double> times = output_times(timing);
    if (times.size() > 1000000)
        throw InputError(kCommand, {}, "--fps", "more than 10^6 frames: lower --fps or the duration");
    // The scene is run once; everything below reads this run.
    const SceneRun run = run_scene(scene, times);
    // A lesson's answers come first: a question the run cannot answer is bad input.
    if (report.lesson) report.answers = answer_questions(*report.lesson, run.record);
    if (report.lesson && report.lesson->penalty) report.penalty = penalty_study(*report.lesson);
    prepare_directory(rq);

    std::unique_ptr<Moments> moments;
    if (std::optional<Moments> m = first_moments(scene, run)) {
        moments = std::make_unique<Moments>(std::move(*m));
    } else {
        err << "collide render: no collision in " << scene.duration
            << " s: before.png, at.png, after.png, figure.png and worked-example.md are not written\n";
    }
    const DataFiles data = data_files(scene, run);
    render::write_file_atomic(rq.out_dir + "/data.csv", data.csv);
    render::write_file_atomic(rq.out_dir + "/events.csv", data.events_csv);
    std::ostringstream json;
    json << "{\"title\": " << nlohmann::json(scene.title).dump()
         << ", \"dimension\": " << scene.dimension << ", \"fps\": " << num(rq.frame.fps)
         << ",\n\"frames\": [\n" << data.json_frames << "\n],\n\"events\": [\n" << data.json_events
         << "\n]}\n";
    render::write_file_atomic(rq.out_dir + "/data.json", json.str());
    std::unique_ptr<WorkedExample> worked;
    if (moments) {
        worked = std::make_unique<WorkedExample>(worked_example(scene, moments->instant));
        std::ostringstream md;
        write_markdown(worked->problem, worked->solution, md);
        render::write_file_atomic(rq.out_dir + "/worked-example.md", md.str());
        report.problem = worked->problem;
        report.solution = worked->solution;
        report.first_collision = moments->instant;
        report.world_note = worked->formula.note;
    }
    report.seconds = write_outputs(rq, scene, report.view, times, run, moments.get(), worked.get(),
                                   report.lesson ? &*report.lesson : nullptr, &report.variants, err);
    if (report.lesson) {
        std::ostringstream md;
        write_lesson_markdown(*report.lesson, report.answers, md);
        md << variants_markdown(report);
        if (report.penalty) {
            write_penalty_markdown(*report.penalty, md);
            render::write_file_atomic(rq.out_dir + "/penalty.svg", penalty_svg(*report.penalty));
            render::write_file_atomic(rq.out_dir + "/penalty-overlap.svg", penalty_overlap_svg(*report.penalty));
            render::write_file_atomic(rq.out_dir + "/penalty.csv", penalty_csv(*report.penalty));
        }
        render::write_file_atomic(rq.out_dir + "/lesson.md", md.str());
    }
    report.frames = static_cast<long>(times.size());
    report.width = rq.frame.width;
    report.height = rq.frame.height;
    for (const ImpactMark& im : run.impacts) report.collision_times.push_back(im.t);
    for (const FrameState& f : run.frames) {
        report.t.push_back(f.t);
        report.totals.push_back(render::frame_totals(scene, f));
    }
    if (rq.video) {
        report.video = rq.video->file_name();
        const bool terminal = !rq.quiet && err.rdbuf() == std::cerr.rdbuf() && isatty(STDERR_FILENO);
        if (terminal) err << "encoding " << report.video << " with ffmpeg ...\n";
        render::encode_video(rq.video->ffmpeg, rq.out_dir + "/frames", rq.frame.fps, rq.video->format,
                             rq.out_dir + "/" + report.video);
    }
    return report;
}

int run_render(const RenderOptions& o, std::ostream& out, std::ostream& err) {
    try {
        const RenderReport r = render_scenario(parse_render_request(o), err);
        if (!o.quiet) {
            char rate[64];
            std::snprintf(rate, sizeof rate, " in %.2f s (%.1f frames/s)", r.seconds,
                          r.seconds > 0 ? static_cast<double>(r.frames) / r.seconds : 0.0);
            out << "wrote " << r.frames << " frames (" << r.width << "x" << r.height << ")" << rate
                << " to " << o.out_dir << "/frames";
            if (r.problem) out << ", before.png, at.png, after.png, figure.png, thumb.png, worked-example.md";
            out << ", data.csv, data.json, events.csv";
            if (r.lesson) out << ", lesson.md";
            if (!r.variants.empty()) out << ", variants.png";
            if (r.penalty) out << ", penalty.svg, penalty-overlap.svg, penalty.csv";
            if (!r.video.empty()) out << ", " << r.video;
            // Peak resident memory of the whole process (Linux: kilobytes).
            rusage usage{};
            if (getrusage(RUSAGE_SELF, &usage) == 0)
                out << "; peak memory " << (usage.ru_maxrss + 512) / 1024 << " MB";
            out << "\n";
        }
        return 0;
    } catch (const Interrupted& e) {
        err << "collide: interrupted: " << e.frames << " complete frames written to " << o.out_dir
            << "/frames (no partial file is left)\n";
        return 130;
    } catch (const InputError& e) {
        err << "collide: error: " << e.what() << "\n";
        return kBadInput;
    } catch (const std::exception& e) {
        err << "collide: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace collide
