#include "present/gui_model.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "scenario/input_error.h"
#include "scenario/scene_file.h"
#include "present/frame_times.h"
#include "present/scene_run.h"
#include "teach/step_output.h"

namespace collide {

namespace {

// The trail behind each body: as `collide render` draws it.
double trail_span(const Scene& s) { return std::min(1.0, 0.3 * s.duration); }

}  // namespace

GuiModel::GuiModel(Scene scene, double fps, Rerun mode)
    : original_(scene), scene_(std::move(scene)), fps_(fps), mode_(mode) {
    rerun();
    finish();
    if (!error_.empty()) throw std::runtime_error(error_);
}

void GuiModel::rerun() {
    // The job owns copies of what it reads: the world it runs lives on the worker thread.
    runs_.start([scene = scene_, times = frame_times(scene_, fps_)](RunControl& control) {
        const double end = times.empty() ? 0.0 : times.back();
        SceneRun run = run_scene(scene, times, [&control, end](double t) {
            control.report(end > 0 ? t / end : 1.0);
            control.check();  // cancelled: stop at this frame's instant
        });
        return Run{scene, std::move(run)};
    });
    if (mode_ == Rerun::wait) finish();
}

bool GuiModel::poll() {
    std::optional<BackgroundRun<Run>::Outcome> out = runs_.take_result();
    if (!out) return false;
    if (out->result) {
        const double t = run_.frames.empty() ? 0.0 : time();
        shown_ = std::move(out->result->scene);
        run_ = std::move(out->result->run);
        error_.clear();
        seek_time(t);
    } else {
        error_ = out->error;
    }
    return true;
}

void GuiModel::finish() {
    runs_.wait();
    poll();
}

void GuiModel::set_restitution(double e) {
    scene_.restitution = e;
    for (SceneBody& b : scene_.bodies) b.restitution.reset();
    rerun();
}

void GuiModel::set_friction(double mu) {
    scene_.friction = mu;
    for (SceneBody& b : scene_.bodies) b.friction.reset();
    rerun();
}

void GuiModel::set_model(Model m) {
    scene_.model = m;
    rerun();
}

void GuiModel::set_policy(Policy p) {
    scene_.policy = p;
    rerun();
}

void GuiModel::set_mass(std::size_t i, double mass) {
    SceneBody& b = scene_.bodies.at(i);
    // The shape stays: the inertia scales with the mass (uniform density).
    const double k = mass / render::body_mass(scene_, i);
    b.body1.mass = b.body2.mass = b.body3.mass = mass;
    b.body2.inertia *= k;
    b.body3.inertia *= k;
    rerun();
}

void GuiModel::set_velocity(std::size_t i, const Vec3& v) {
    SceneBody& b = scene_.bodies.at(i);
    b.body1.v = v.x();
    b.body2.v = v.head<2>();
    b.body3.v = v;
    rerun();
}

void GuiModel::set_spin(std::size_t i, const Vec3& w) {
    SceneBody& b = scene_.bodies.at(i);
    b.body2.w = w.z();
    b.body3.w = w;
    rerun();
}

void GuiModel::scale_size(std::size_t i, double k) {
    SceneBody b = scene_.bodies.at(i);
    b.length *= k;
    b.shape2.radius *= k;
    for (int v = 0; v < b.shape2.polygon.count; ++v) b.shape2.polygon.vertices[static_cast<std::size_t>(v)] *= k;
    b.shape3.radius *= k;
    b.shape3.half *= k;
    b.body2.inertia *= k * k;  // the same mass spread k times wider
    b.body3.inertia *= k * k;
    for (std::size_t j = 0; j < scene_.bodies.size(); ++j)
        if (j != i && start_overlap(scene_, b, scene_.bodies[j]) > kOverlapTolerance) {
            error_ = "'" + b.name + "' would overlap '" + scene_.bodies[j].name + "' at the start";
            return;
        }
    scene_.bodies[i] = b;
    rerun();
}

void GuiModel::reset() {
    scene_ = original_;
    rerun();
}

void GuiModel::seek_index(std::size_t k) {
    index_ = std::min(k, run_.frames.size() - 1);
    clock_ = run_.frames[index_].t;
}

void GuiModel::seek_time(double t) {
    const auto it = std::upper_bound(run_.frames.begin(), run_.frames.end(), t + 1e-12,
                                     [](double x, const render::FrameState& f) { return x < f.t; });
    seek_index(it == run_.frames.begin() ? 0 : static_cast<std::size_t>(it - run_.frames.begin()) - 1);
}

void GuiModel::step(long n) {
    const long k = static_cast<long>(index_) + n;
    seek_index(static_cast<std::size_t>(std::max(0L, k)));
}

bool GuiModel::next_collision() {
    const double now = time();
    for (const render::ImpactMark& m : run_.impacts)
        if (m.t > now) {
            // The first frame at or after it: the frame that shows it.
            const auto it = std::lower_bound(run_.frames.begin(), run_.frames.end(), m.t,
                                             [](const render::FrameState& f, double x) { return f.t < x; });
            if (it == run_.frames.end()) return false;
            seek_index(static_cast<std::size_t>(it - run_.frames.begin()));
            return true;
        }
    return false;
}

void GuiModel::advance(double wall_seconds) {
    if (!playing) return;
    clock_ += wall_seconds * speed;
    while (index_ + 1 < run_.frames.size() && run_.frames[index_ + 1].t <= clock_) ++index_;
    if (index_ + 1 == run_.frames.size()) playing = false;
}

render::FrameState GuiModel::display_frame() const {
    render::FrameState f = run_.frames[index_];
    render::add_trails(run_.frames, trail_span(shown_), &f);
    const double from = index_ == 0 ? -1.0 : run_.frames[index_ - 1].t;
    for (const render::ImpactMark& m : run_.impacts)
        if (m.t > from && m.t <= f.t) f.impacts.push_back(m);
    f.impacts = render::shown_impacts(std::move(f.impacts));
    return f;
}

bool GuiToggles::toggle(const std::string& name) {
    bool* flag = name == "velocities"   ? &decor.velocities
                 : name == "impacts"    ? &decor.impacts
                 : name == "trails"     ? &decor.trails
                 : name == "labels"     ? &decor.labels
                 : name == "com"        ? &decor.com
                 : name == "directions" ? &decor.directions
                 : name == "header"     ? &header
                 : name == "table"      ? &table
                 : name == "plots"      ? &plots
                 : name == "timeline"   ? &timeline
                                        : nullptr;
    if (!flag) return false;
    *flag = !*flag;
    return true;
}

// ---- Scripts ----

namespace {

struct VerbRule {
    const char* verb;
    int min_args, max_args;
    const char* usage;
};

const VerbRule kVerbs[] = {
    {"set", 2, 5,
     "set e X | set mu X | set model NAME | set policy NAME | set BODY mass X | set BODY size FACTOR | set BODY v X [Y [Z]] | set BODY w W | set BODY w X Y Z"},
    {"play", 0, 0, "play"},
    {"pause", 0, 0, "pause"},
    {"step", 0, 1, "step [FRAMES]"},
    {"back", 0, 1, "back [FRAMES]"},
    {"next-collision", 0, 0, "next-collision"},
    {"time", 1, 1, "time SECONDS"},
    {"slow", 1, 1, "slow SPEED (1: real time, 0.25: a quarter)"},
    {"toggle", 1, 1, "toggle velocities|impacts|trails|labels|com|directions|header|table|plots|timeline"},
    {"reset", 0, 0, "reset"},
    {"screenshot", 1, 1, "screenshot FILE.png (the whole window)"},
    {"save-frame", 1, 1, "save-frame FILE.png (the frame alone)"},
    {"save-figure", 1, 1, "save-figure FILE.png (before / at / after the first collision)"},
    {"wait", 0, 1, "wait [WINDOW-FRAMES] (lets playback run)"},
    {"open", 1, 1, "open LESSON|SCENARIO (another scene: a lesson id or a file)"},
    {"orbit", 2, 2, "orbit DEGREES-RIGHT DEGREES-UP (the 3D view's camera)"},
    {"zoom", 1, 1, "zoom FACTOR (the 3D view: 2 is twice as close)"},
    {"quit", 0, 0, "quit"},
};

bool number(const std::string& s, double* out) {
    std::istringstream in(s);
    in >> *out;
    return !in.fail() && in.eof() && std::isfinite(*out);
}

}  // namespace

std::vector<GuiAction> parse_gui_script_text(const std::string& text, const std::string& name) {
    std::vector<GuiAction> actions;
    std::istringstream in(text);
    int line_no = 0;
    for (std::string line; std::getline(in, line);) {
        ++line_no;
        if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        std::istringstream words(line);
        GuiAction a;
        a.line = line_no;
        if (!(words >> a.verb)) continue;
        for (std::string w; words >> w;) a.args.push_back(w);
        const VerbRule* rule = nullptr;
        for (const VerbRule& r : kVerbs)
            if (a.verb == r.verb) rule = &r;
        if (!rule) {
            std::string verbs;
            for (const VerbRule& r : kVerbs) verbs += std::string(verbs.empty() ? "" : ", ") + r.verb;
            throw InputError(name, {line_no, 1}, a.verb, "unknown action; expected one of " + verbs);
        }
        const int n = static_cast<int>(a.args.size());
        if (n < rule->min_args || n > rule->max_args)
            throw InputError(name, {line_no, 1}, a.verb, std::string("expected: ") + rule->usage);
        // Numbers where the verb takes them.
        std::vector<std::size_t> numeric;
        if (a.verb == "step" || a.verb == "back" || a.verb == "time" || a.verb == "slow" || a.verb == "wait" ||
            a.verb == "orbit" || a.verb == "zoom")
            for (std::size_t k = 0; k < a.args.size(); ++k) numeric.push_back(k);
        if (a.verb == "set") {
            if (a.args[0] == "e" || a.args[0] == "mu") {
                if (n != 2)
                    throw InputError(name, {line_no, 1}, "set " + a.args[0], "expected: set " + a.args[0] + " X");
                numeric.push_back(1);
            } else if (a.args[0] == "model" || a.args[0] == "policy") {
                if (n != 2)
                    throw InputError(name, {line_no, 1}, "set " + a.args[0], "expected: set " + a.args[0] + " NAME");
                Model m;
                if (a.args[0] == "model" && !parse_model(a.args[1], &m))
                    throw InputError(name, {line_no, 1}, "set model",
                                     "expected frictionless, coulomb, matrix, stick, page-listing or routh, got '" +
                                         a.args[1] + "'");
                if (a.args[0] == "policy" && a.args[1] != "sequential" && a.args[1] != "simultaneous")
                    throw InputError(name, {line_no, 1}, "set policy",
                                     "expected sequential or simultaneous, got '" + a.args[1] + "'");
            } else {
                const std::string& what = a.args[1];
                if (what != "mass" && what != "v" && what != "w" && what != "size")
                    throw InputError(
                        name, {line_no, 1}, "set " + a.args[0],
                        "expected e, mu, model, policy, or a body's mass, size, v or w; got '" + what + "'");
                if ((what == "mass" || what == "size") && n != 3)
                    throw InputError(name, {line_no, 1}, "set " + a.args[0] + " " + what,
                                     "expected: set " + a.args[0] + " " + what + (what == "size" ? " FACTOR" : " X"));
                for (std::size_t k = 2; k < a.args.size(); ++k) numeric.push_back(k);
            }
        }
        for (std::size_t k : numeric) {
            double x = 0;
            if (!number(a.args[k], &x))
                throw InputError(name, {line_no, 1}, a.verb, "expected a finite number, got '" + a.args[k] + "'");
            if ((a.verb == "step" || a.verb == "back" || a.verb == "wait") && (x < 0 || x != std::floor(x)))
                throw InputError(name, {line_no, 1}, a.verb, "expected a whole number >= 0, got '" + a.args[k] + "'");
            if (a.verb == "zoom" && !(x >= 0.2 && x <= 8))
                throw InputError(name, {line_no, 1}, a.verb, "expected a factor in [0.2, 8], got '" + a.args[k] + "'");
            if (a.verb == "slow" && !(x > 0 && x <= 10))
                throw InputError(name, {line_no, 1}, a.verb, "expected a speed in (0, 10], got '" + a.args[k] + "'");
        }
        if (a.verb == "toggle") {
            GuiToggles probe;
            if (!probe.toggle(a.args[0]))
                throw InputError(name, {line_no, 1}, "toggle",
                                 std::string("expected: ") + rule->usage + ", got '" + a.args[0] + "'");
        }
        actions.push_back(std::move(a));
    }
    return actions;
}

std::vector<GuiAction> parse_gui_script(const std::string& path) {
    std::string name;
    const std::string text = read_input_file(path, &name);  // bounded as every input file
    return parse_gui_script_text(text, name);
}

bool run_script_action(const GuiAction& a, const std::string& file, GuiModel* model, GuiToggles* toggles) {
    const auto num = [&](std::size_t k) { return std::stod(a.args[k]); };
    const auto fail_if_refused = [&](const std::string& key) {
        if (!model->error().empty())
            throw InputError(file, {a.line, 1}, key, "the world refuses the run: " + model->error());
    };
    const std::string& v = a.verb;
    if (v == "set") {
        const std::string& what = a.args[0];
        if (what == "e") {
            const double e = num(1);
            if (e < 0 || e > 1) throw InputError(file, {a.line, 1}, "set e", "expected e in [0, 1], got " + a.args[1]);
            model->set_restitution(e);
        } else if (what == "mu") {
            if (num(1) < 0) throw InputError(file, {a.line, 1}, "set mu", "expected mu >= 0, got " + a.args[1]);
            model->set_friction(num(1));
        } else if (what == "model") {
            Model m;
            parse_model(a.args[1], &m);
            model->set_model(m);
        } else if (what == "policy") {
            model->set_policy(a.args[1] == "simultaneous" ? Policy::simultaneous : Policy::sequential);
        } else {
            const auto& bodies = model->scene().bodies;
            std::size_t i = 0;
            while (i < bodies.size() && bodies[i].name != what) ++i;
            if (i == bodies.size()) throw InputError(file, {a.line, 1}, "set", "no body named '" + what + "'");
            if (bodies[i].is_static())
                throw InputError(file, {a.line, 1}, "set " + what,
                                 "'" + what + "' is static: it has no mass or velocity to set");
            const int d = model->scene().dimension;
            const std::size_t n = a.args.size() - 2;
            if (a.args[1] == "mass") {
                if (!(num(2) > 0))
                    throw InputError(file, {a.line, 1}, "set " + what + " mass", "expected a mass > 0 kg");
                model->set_mass(i, num(2));
            } else if (a.args[1] == "size") {
                if (!(num(2) >= 0.1 && num(2) <= 10))
                    throw InputError(file, {a.line, 1}, "set " + what + " size", "expected a factor in [0.1, 10]");
                model->scale_size(i, num(2));
            } else if (a.args[1] == "v") {
                if (static_cast<int>(n) != d)
                    throw InputError(
                        file, {a.line, 1}, "set " + what + " v",
                        d == 1 ? std::string("expected one number in 1D (m/s along x)")
                               : "expected " + std::to_string(d) + " numbers in " + std::to_string(d) + "D (m/s)");
                Vec3 vel = Vec3::Zero();
                for (std::size_t k = 0; k < n; ++k) vel[static_cast<int>(k)] = num(2 + k);
                model->set_velocity(i, vel);
            } else {
                if (d == 1) throw InputError(file, {a.line, 1}, "set " + what + " w", "bodies on a line do not spin");
                if (static_cast<int>(n) != (d == 2 ? 1 : 3))
                    throw InputError(
                        file, {a.line, 1}, "set " + what + " w",
                        d == 2 ? "expected one number (rad/s, counter-clockwise)" : "expected 3 numbers (rad/s)");
                model->set_spin(i, d == 2 ? Vec3(0, 0, num(2)) : Vec3(num(2), num(3), num(4)));
            }
        }
        model->finish();  // a script's next action sees this edit's run
        fail_if_refused("set");
    } else if (v == "play") {
        model->playing = true;
    } else if (v == "pause") {
        model->playing = false;
    } else if (v == "step") {
        model->step(a.args.empty() ? 1 : static_cast<long>(num(0)));
    } else if (v == "back") {
        model->step(-(a.args.empty() ? 1 : static_cast<long>(num(0))));
    } else if (v == "next-collision") {
        if (!model->next_collision())
            throw InputError(file, {a.line, 1}, v, "no collision after t = " + std::to_string(model->time()) + " s");
    } else if (v == "time") {
        model->seek_time(num(0));
    } else if (v == "slow") {
        model->speed = num(0);
    } else if (v == "toggle") {
        toggles->toggle(a.args[0]);
    } else if (v == "reset") {
        model->reset();
        model->finish();
    } else {
        return false;
    }
    return true;
}

}  // namespace collide
