#include "present/render_job.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <variant>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "present/figures.h"
#include "present/frame_times.h"
#include "present/scene_run.h"
#include "teach/step_output.h"
#include "render/context.h"
#include "render/frame_sink.h"
#include "render/frame_state.h"
#include "render/png.h"
#include "render/renderer.h"
#include "render/video.h"
#include "scenario/input_error.h"
#include "scenario/scene_file.h"
#include "teach/event_problem.h"
#include "teach/answers.h"
#include "engine/diagnostics.h"
#include "teach/lesson_penalty.h"
#include "teach/notation.h"
#include "teach/solve.h"

namespace collide {

namespace fs = std::filesystem;
using render::FrameState;
using render::ImpactMark;

std::string energy_lost_text(double before, double after) {
    if (gains_energy(before, after)) return notation::num_text(after - before) + " gained (Kane's paradox)";
    return notation::num_text(before - after);
}

namespace {

const char* const kCommand = "";  // option errors name the option, not a file

std::string num(double x) { return notation::num_data(x); }

// ---- The worked example of the first collision ----

struct WorkedExample {
    SolveProblem problem;
    Solution solution;
    render::FormulaText formula;  // the overlay: the response model's formula and numbers
};

WorkedExample worked_example(const Scene& scene, const CollisionInstant& c) {
    const notation::StudentNumbers student;  // the frames' formula: 4 figures, no noise
    WorkedExample w;
    w.problem = collision_problem(scene, c);
    w.solution = solve(w.problem);
    std::string model = model_name(w.problem.model);
    if (w.problem.model == Model::routh)
        model += std::string(", ") + restitution_law_name(w.problem.restitution_law) + "'s law";
    char heading[200];
    std::snprintf(heading, sizeof heading, "Collision of %s and %s  (%s, e = %s)", scene.bodies[c.a].name.c_str(),
                  scene.bodies[c.b].name.c_str(), model.c_str(), notation::num_text(w.problem.restitution).c_str());
    w.formula.heading = heading;
    // The last two steps of the response model: each its formula, then its lines (the numbers).
    const std::vector<WorkedStep> steps = worked_steps(w.problem, w.solution);
    std::vector<const WorkedStep*> response;
    for (const WorkedStep& st : steps)
        if (st.response) response.push_back(&st);
    if (response.size() > 2) response.erase(response.begin(), response.end() - 2);
    for (const WorkedStep* st : response) {
        if (!st->formula.empty()) w.formula.lines.push_back(notation::to_rich(st->formula));
        for (const std::string& line : st->lines) w.formula.lines.push_back(notation::to_rich(line));
    }
    // The formula is for one contact point. When the world resolved several points at this
    // instant (a face on a face, a resting stack), its impulse differs: say so, with its value.
    w.formula.note = world_note(scene, c, w.solution.P);
    return w;
}

// ---- Output directory ----

void prepare_directory(const RenderRequest& rq) {
    std::error_code ec;
    const fs::path dir(rq.out_dir);
    if (fs::exists(dir, ec)) {
        if (!fs::is_directory(dir, ec)) throw InputError(rq.out_dir, {}, "", "exists and is not a directory");
        if (!fs::is_empty(dir, ec) && !rq.force)
            throw InputError(rq.out_dir, {}, "", "directory is not empty (use --force to write into it)");
    }
    fs::create_directories(dir / "frames", ec);
    if (ec) throw std::runtime_error(rq.out_dir + ": cannot create directory: " + ec.message());
    // --force: old frames would mix with the new ones; remove ours (and only ours).
    for (const fs::directory_entry& e : fs::directory_iterator(dir / "frames", ec)) {
        const std::string name = e.path().filename().string();
        if (name.rfind("frame_", 0) == 0 && e.path().extension() == ".png") fs::remove(e.path(), ec);
    }
    // A lesson's next figures (figure-2.png, annotations-2.json, ...) from an earlier render.
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
        const std::string name = e.path().filename().string();
        if ((name.rfind("figure-", 0) == 0 && e.path().extension() == ".png") ||
            (name.rfind("annotations-", 0) == 0 && e.path().extension() == ".json"))
            fs::remove(e.path(), ec);
    }
    for (const char* name :
         {"before.png", "at.png", "after.png", "figure.png", "thumb.png", "variants.png", "worked-example.md",
          "lesson.md", "penalty.svg", "penalty-overlap.svg", "penalty.csv", "animation.mp4", "animation.gif"})
        fs::remove(dir / name, ec);
}

// A lesson's variants side by side: variants.png and, per scene, the first collision's
// impulse, velocities after and kinetic energy lost.
std::string variants_markdown(const Scene& scene, const std::vector<RenderReport::Variant>& variants) {
    if (variants.empty()) return "";
    const int d = scene.dimension;
    const auto V = [d](const Vec3& v) {
        if (d == 1) return notation::num_text(v.x());
        return notation::vec(v, d).txt;
    };
    std::ostringstream md;
    md << "\n## Side by side\n\n![the scene and its variants](variants.png)\n\n"
       << "| | impulse on b (N s) | a after (m/s) | b after (m/s) | kinetic energy lost (J) |\n"
       << "|---|---|---|---|---|\n";
    for (const RenderReport::Variant& v : variants) {
        if (!v.first) {
            md << "| " << v.label << " | no collision | | | |\n";
            continue;
        }
        const CollisionInstant& c = *v.first;
        md << "| " << v.label << " (" << scene.bodies[c.a].name << " on " << scene.bodies[c.b].name << ") | "
           << V(c.impulse) << " | " << V(c.va_after) << " | " << V(c.vb_after) << " | "
           << energy_lost_text(v.ke_before, v.ke_after) << " |\n";
    }
    return md.str();
}

// ==== The stages of a render: load, run, analyse, write ====

// 1. Load: the scene, its [view] table and its lesson, and the times of the frames.
struct Loaded {
    Scene scene;
    SceneView view;
    std::optional<Lesson> lesson;
    std::vector<double> times;  // s: the scene sampled at the frame rate
};

Loaded loaded_from(const FrameSpec& frame, RenderSource source) {
    Loaded in{std::move(source.scene), std::move(source.view), std::move(source.lesson), {}};
    in.times = frame_times(in.scene, frame.fps);
    if (in.times.size() > 1000000)
        throw InputError(kCommand, {}, "--fps", "more than 10^6 frames: lower --fps or the duration");
    return in;
}

Loaded load_stage(const RenderRequest& rq) { return loaded_from(rq.frame, load_render_source(rq.scenario)); }

// 2. Run: the scene, once (everything below reads this run), and what a lesson computes from
// it: the answers to its questions (one the run cannot answer is bad input, found before
// anything is written) and its penalty study.
struct Ran {
    SceneRun run;
    std::vector<LessonAnswer> answers;
    std::optional<PenaltyStudy> penalty;
};

// The collisions a lesson's figures show, for the record to keep wherever they fall.
std::vector<RecordOptions::Keep> figure_keeps(const Loaded& in) {
    return figure_keeps(in.lesson ? &*in.lesson : nullptr);
}

Ran run_stage(const Loaded& in) {
    Ran out{run_scene(in.scene, in.times, nullptr, figure_keeps(in)), {}, std::nullopt};
    if (in.lesson && in.lesson->penalty) out.penalty = penalty_study(*in.lesson, out.run.record);
    if (in.lesson) out.answers = answer_questions(*in.lesson, out.run.record, out.penalty ? &*out.penalty : nullptr);
    return out;
}

// 3. Analyse: the collisions the figures show (a lesson's [[figure]] entries, else the run's
// first collision), their moments and worked examples, and a lesson's variants (each run once,
// sampled as the lesson's own scene). Nothing here without a collision.
struct Shot {
    Moments moments;
    WorkedExample worked;
    std::string caption;
};
struct Analysis {
    std::optional<Moments> moments;  // figure.png's collision
    std::optional<WorkedExample> worked;
    std::string caption;                          // its [[figure]] caption, if any
    std::vector<Shot> more;                       // figure-2.png, ...: the lesson's next figures
    std::vector<RenderReport::Variant> variants;  // the lesson's scene, then each variant
    std::vector<VariantRow> rows;                 // variants.png: those with a collision
};

// What a lesson's [[figure]] entries pick (none: the run's first collision).
std::vector<CollisionPick> lesson_picks(const Loaded& in) { return figure_picks(in.lesson ? &*in.lesson : nullptr); }

void analyse_variants(const Loaded& in, const Moments& moments, Analysis* out) {
    std::vector<std::pair<std::string, const Scene*>> scenes = {
        {in.lesson->label.empty() ? "as above" : in.lesson->label, &in.scene}};
    for (const LessonVariant& v : in.lesson->variants) scenes.push_back({v.label, &v.scene});
    const std::vector<CollisionPick> picks = lesson_picks(in);
    for (const auto& [label, s] : scenes) {
        // Each variant at its own collision: the one the lesson's first figure picks.
        const std::optional<Moments> m =
            s == &in.scene ? moments : page_moments(*s, run_scene(*s, in.times, nullptr, figure_keeps(in)), picks);
        RenderReport::Variant result{label, std::nullopt, 0.0, 0.0};
        if (m) {
            result.first = m->instant;
            result.ke_before = pair_kinetic_energy(*s, m->instant, false);
            result.ke_after = pair_kinetic_energy(*s, m->instant, true);
            out->rows.push_back({label, s, *m});
        }
        out->variants.push_back(result);
    }
}

// `variants`: also a lesson's variants (variants.png; each is run once more).
Analysis analyse_stage(const Loaded& in, const SceneRun& run, bool variants = true) {
    Analysis out;
    const std::vector<CollisionPick> picks = lesson_picks(in);
    if (picks.empty()) {
        out.moments = first_moments(in.scene, run);
    } else {
        // A figure whose collision the run does not have is a mistake in the lesson: said
        // before anything is written.
        for (std::size_t k = 0; k < picks.size(); ++k) {
            const LessonFigure& f = in.lesson->figures[k];
            std::optional<Moments> m = collision_moments(in.scene, run, picks[k]);
            if (!m) {
                const int n = pair_collisions(run, f.ia, f.ib);
                const std::string times = n == 0   ? "never collide"
                                          : n == 1 ? "collide only once"
                                                   : "collide only " + std::to_string(n) + " times";
                throw InputError(in.lesson->file, f.pos, f.key,
                                 "'" + f.a + "' and '" + f.b + "' " + times + " in the run, so there is no collision " +
                                     std::to_string(f.collision) + " to show");
            }
            if (k == 0) {
                out.moments = std::move(m);
                out.caption = f.caption;
            } else {
                out.more.push_back({*m, worked_example(in.scene, m->instant), f.caption});
            }
        }
    }
    if (!out.moments) return out;
    out.worked = worked_example(in.scene, out.moments->instant);
    if (variants && in.lesson && !in.lesson->variants.empty()) analyse_variants(in, *out.moments, &out);
    return out;
}

// 4. Write: every file, each under a temporary name renamed when complete.
struct Written {
    double seconds = 0.0;  // rendering and writing the frames
    std::string video;     // its file name, or ""
};

// data.csv, events.csv and data.json.
void write_data_files(const RenderRequest& rq, const Scene& scene, const SceneRun& run) {
    const DataFiles data = data_files(scene, run);
    render::write_file_atomic(rq.out_dir + "/data.csv", data.csv);
    render::write_file_atomic(rq.out_dir + "/events.csv", data.events_csv);
    std::ostringstream json;
    json << "{\"title\": " << nlohmann::json(scene.title).dump() << ", \"dimension\": " << scene.dimension
         << ", \"fps\": " << num(rq.frame.fps) << ",\n\"frames\": [\n"
         << data.json_frames << "\n],\n\"events\": [\n"
         << data.json_events << "\n]}\n";
    render::write_file_atomic(rq.out_dir + "/data.json", json.str());
}

// Where the run resolved the collision with other contacts of the same instant (`instant`: the
// collision as the run gave it), the calculation is labelled a simplified one and the run's
// results follow it (the site's page does the same).
void write_worked_example(const std::string& dir, const WorkedExample& worked, const CollisionInstant* instant) {
    const notation::StudentNumbers student;  // a lesson's: 4 figures, no floating-point noise
    std::ostringstream md;
    write_markdown(worked.problem, worked.solution, md);
    std::string text = md.str();
    const Solution run = instant ? as_resolved(worked.problem, worked.solution, *instant) : worked.solution;
    if (resolved_differs(worked.problem, worked.solution, run)) {
        // The label under the title, the table at the end.
        const SimplifiedLabel label = simplified_label(worked.problem);
        text.insert(text.find('\n') + 1, "\n**" + label.lead + "** " + label.rest + "\n");
        text += "\n## The two alone and the run\n\n| | the two alone (above) | the run |\n|---|---|---|\n";
        for (const ResultBeside& r : results_beside(worked.problem, worked.solution, run))
            text += "| " + r.what + " (" + r.unit + ") | " + r.alone + " | " + r.run + " |\n";
    }
    render::write_file_atomic(dir + "/worked-example.md", text);
}

// frames/frame_00000.png ...: rendering here, PNG encoding beside it. Returns the seconds it
// took; throws Interrupted when `stop` asks (the frames already handed over are finished).
double write_frames(render::Renderer& renderer, const SceneRun& run, const RenderRequest& rq, double trail,
                    const SceneView& view, std::ostream& err, const StopRequested& stop) {
    const Quality& q = rq.frame.quality;
    render::FrameSinkOptions sink_options;
    sink_options.dir = rq.out_dir + "/frames";
    sink_options.png = q.png;
    sink_options.threads = q.encoders;
    sink_options.buffers = q.encoders + 2;
    render::FrameSink sink(rq.frame.width, rq.frame.height, sink_options);
    render::ProgressBar progress(err, static_cast<long>(run.frames.size()), !rq.quiet, "rendering");
    std::size_t next_impact = 0;
    render::Decor decor;
    decor.points = points_of(view);
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < run.frames.size(); ++k) {
        if (stop && stop()) {
            sink.finish();
            progress.finish();
            throw Interrupted(sink.written());
        }
        FrameState f = run.frames[k];
        render::add_trails(run.frames, trail, &f);
        // A collision shows in the first frame at or after it (the ones that matter: see
        // render::shown_impacts).
        while (next_impact < run.impacts.size() && run.impacts[next_impact].t <= f.t)
            f.impacts.push_back(run.impacts[next_impact++]);
        f.impacts = render::shown_impacts(std::move(f.impacts));
        render::FrameSink::Buffer* buffer = sink.acquire();
        renderer.render(f, decor, buffer->data());
        sink.submit(static_cast<long>(k), buffer);
        progress.update(sink.written());
    }
    sink.finish();
    progress.finish();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The frames, then the first collision's stills, figure and thumbnail, and a lesson's
// variants.png, all in one GL context. Returns the seconds the frames took.
double write_pictures(const RenderRequest& rq, const Loaded& in, const SceneRun& run, const Analysis& a,
                      std::ostream& err, const StopRequested& stop) {
    std::unique_ptr<render::GlContext> context = render::create_gl_context(rq.backend);
    const render::RenderSettings settings =
        frame_settings(rq.frame, in.scene, in.view, a.worked ? &a.worked->formula : nullptr);
    render::Renderer renderer(*context, in.scene, settings);
    PlotTotals plot = plot_totals(in.scene, run);
    renderer.set_plot_totals(std::move(plot.t), std::move(plot.totals));
    renderer.prepare(run.frames, run.impacts);
    const double seconds = write_frames(renderer, run, rq, trail_seconds(in.scene), in.view, err, stop);
    if (a.moments) {
        const CollisionShots shots{in.scene, in.view, run, *a.moments};
        const PictureOut out{rq.out_dir, rq.frame.quality.png};
        write_stills(renderer, shots, out);
        const Figure figure = write_figure(*context, shots, settings, out);
        for (std::size_t k = 0; k < a.more.size(); ++k)
            write_figure(*context, CollisionShots{in.scene, in.view, run, a.more[k].moments}, settings, out,
                         static_cast<int>(k + 2));
        if (!a.rows.empty()) write_variants(*context, a.rows, settings, figure, out);
    } else {
        render::write_file_atomic(rq.out_dir + "/annotations.json", annotations_json(in.scene, nullptr));
    }
    return seconds;
}

// lesson.md: the lesson's text, its questions with the answers, its variants side by side and
// its penalty study (with penalty.svg, penalty-overlap.svg and penalty.csv).
void write_lesson(const std::string& dir, const Loaded& in, const Ran& ran, const Analysis& a) {
    const notation::StudentNumbers student;  // 4 figures, no floating-point noise
    std::ostringstream md;
    write_lesson_markdown(*in.lesson, ran.answers, md);
    md << variants_markdown(in.scene, a.variants);
    if (ran.penalty) {
        write_penalty_markdown(*ran.penalty, md);
        render::write_file_atomic(dir + "/penalty.svg", penalty_svg(*ran.penalty));
        render::write_file_atomic(dir + "/penalty-overlap.svg", penalty_overlap_svg(*ran.penalty));
        render::write_file_atomic(dir + "/penalty.csv", penalty_csv(*ran.penalty));
    }
    render::write_file_atomic(dir + "/lesson.md", md.str());
}

// animation.mp4 or .gif from the frames; returns its file name.
// Interrupted while ffmpeg runs: ffmpeg is ended with the command and no video is left (the
// frames are complete).
std::string write_video(const RenderRequest& rq, long frames, std::ostream& err, const StopRequested& stop) {
    const VideoRequest& video = *rq.video;
    const std::string name = video.file_name();
    if (!rq.quiet) err << "encoding " << name << " with ffmpeg ...\n";
    if (!render::encode_video(video.ffmpeg, rq.out_dir + "/frames", rq.frame.fps, video.format, rq.out_dir + "/" + name,
                              stop))
        throw Interrupted(frames);
    return name;
}

Written write_stage(const RenderRequest& rq, const Loaded& in, const Ran& ran, const Analysis& a, std::ostream& err,
                    const StopRequested& stop) {
    prepare_directory(rq);
    if (!a.moments)
        err << "collide render: no collision in " << in.scene.duration
            << " s: before.png, at.png, after.png, figure.png and worked-example.md are not written\n";
    write_data_files(rq, in.scene, ran.run);
    if (a.worked) write_worked_example(rq.out_dir, *a.worked, a.moments ? &a.moments->instant : nullptr);
    Written out;
    out.seconds = write_pictures(rq, in, ran.run, a, err, stop);
    if (in.lesson) write_lesson(rq.out_dir, in, ran, a);
    if (rq.video) out.video = write_video(rq, static_cast<long>(ran.run.frames.size()), err, stop);
    return out;
}

// What the stages made and computed, for the summary line and for `collide material`.
RenderReport report_of(const RenderRequest& rq, Loaded in, Ran ran, Analysis a, const Written& w) {
    RenderReport r;
    r.scene = std::move(in.scene);
    r.view = in.view;
    r.lesson = std::move(in.lesson);
    r.answers = std::move(ran.answers);
    r.penalty = std::move(ran.penalty);
    if (a.worked) {
        r.problem = a.worked->problem;
        r.solution = a.worked->solution;
        r.world_note = a.worked->formula.note;
    }
    if (a.moments) {
        r.first_collision = a.moments->instant;
        r.figures.push_back({a.moments->instant, r.problem ? *r.problem : SolveProblem{},
                             r.solution ? *r.solution : Solution{}, r.world_note, a.caption, "figure.png"});
    }
    std::vector<std::size_t> shown;  // the events the figures work out
    if (a.moments) shown.push_back(a.moments->event);
    for (std::size_t k = 0; k < a.more.size(); ++k) {
        const Shot& s = a.more[k];
        r.figures.push_back({s.moments.instant, s.worked.problem, s.worked.solution, s.worked.formula.note, s.caption,
                             "figure-" + std::to_string(k + 2) + ".png"});
        shown.push_back(s.moments.event);
    }
    std::visit(
        [&](const auto& rec) {
            for (std::size_t k = 0; k < rec.events.size() && r.later.size() < RenderReport::kLaterCollisions; ++k) {
                if (std::find(shown.begin(), shown.end(), k) != shown.end()) continue;
                // In the lesson's roles, as its figures name the pair.
                CollisionInstant c = collision_instant(rec.events[k]);
                if (r.lesson)
                    for (const LessonFigure& f : r.lesson->figures) c = with_roles(c, f.ia, f.ib);
                WorkedExample w = worked_example(r.scene, c);
                r.later.push_back({c, std::move(w.problem), std::move(w.solution), std::move(w.formula.note)});
            }
        },
        ran.run.record);
    r.variants = std::move(a.variants);
    for (const ImpactMark& im : ran.run.impacts) r.collision_times.push_back(im.t);
    for (const FrameState& f : ran.run.frames) {
        r.t.push_back(f.t);
        r.totals.push_back(render::frame_totals(r.scene, f));
    }
    PlotTotals plot = plot_totals(r.scene, ran.run);
    r.plot_t = std::move(plot.t);
    r.plot_totals = std::move(plot.totals);
    if (r.lesson) r.plots = lesson_plots(*r.lesson, r.scene, ran.run);
    r.frames = static_cast<long>(in.times.size());
    r.width = rq.frame.width;
    r.height = rq.frame.height;
    r.seconds = w.seconds;
    r.video = w.video;
    return r;
}

}  // namespace

RenderReport render_scenario(const RenderRequest& rq, std::ostream& err, const StopRequested& stop) {
    Loaded in = load_stage(rq);
    Ran ran = run_stage(in);
    Analysis analysis = analyse_stage(in, ran.run);
    const Written written = write_stage(rq, in, ran, analysis, err, stop);
    return report_of(rq, std::move(in), std::move(ran), std::move(analysis), written);
}

RenderSource load_render_source(const std::string& scenario) {
    RenderSource source;
    source.scene = load_scenario(scenario, &source.view, &source.lesson);
    return source;
}

std::optional<std::vector<std::uint8_t>> figure_png(const FrameSpec& frame, render::GlBackend backend,
                                                    RenderSource source) {
    const Loaded in = loaded_from(frame, std::move(source));
    const SceneRun run = run_scene(in.scene, in.times, nullptr, figure_keeps(in));
    const Analysis a = analyse_stage(in, run, false);
    if (!a.moments) return std::nullopt;
    std::unique_ptr<render::GlContext> context = render::create_gl_context(backend);
    const render::RenderSettings settings = frame_settings(frame, in.scene, in.view, &a.worked->formula);
    const Figure figure = make_figure(*context, CollisionShots{in.scene, in.view, run, *a.moments}, settings);
    return render::encode_png(figure.figure.width, figure.figure.height, figure.figure.rgba.data(), frame.quality.png);
}

std::optional<render::FormulaText> first_collision_formula(const Scene& scene, const SceneRun& run) {
    const std::optional<Moments> m = first_moments(scene, run);
    if (!m) return std::nullopt;
    return worked_example(scene, m->instant).formula;
}

}  // namespace collide
