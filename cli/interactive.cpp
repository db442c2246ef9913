#include "cli/interactive.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "teach/step_output.h"
#include "scenario/input_error.h"
#include "scenario/scene_file.h"
#include "scenario/toml_reader.h"
#include "teach/notation.h"

namespace collide {

namespace {

constexpr double kMaxMagnitude = 1e12;  // as in scenario files

const char* const kHelp[] = {
    "commands:",
    "  step [n]           advance n output steps (default 1), show the collisions and the state",
    ("  next               run to the next collision: the state before it, the collision, the "
     "state just after"),
    "  back [n]           go back n output steps (default 1)",
    "  show [body]        the current state, of all bodies or of one",
    "  set BODY.FIELD V   change a body now, e.g. set ball.v 1,2 or set ball.v [1, 2]",
    "                     (fields: 1D x, v; 2D x, v, w, angle; 3D x, v, w, orientation)",
    "  events             every collision so far",
    "  help               this list",
    "  quit               leave (so does the end of the input)",
};

using Words = std::vector<std::string>;

Words split(const std::string& line) {
    std::istringstream in(line);
    Words words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

std::string join(const Words& words, std::size_t from) {
    std::string out;
    for (std::size_t k = from; k < words.size(); ++k) out += (k > from ? " " : "") + words[k];
    return out;
}

std::string num(double x) { return notation::num_text(x); }

// The optional count of `step [n]` and `back [n]`.
std::size_t count(const Words& words) {
    if (words.size() == 1) return 1;
    if (words.size() > 2) throw std::runtime_error(words[0] + " takes at most one number: " + words[0] + " [n]");
    const std::string& w = words[1];
    if (w.empty() || w.find_first_not_of("0123456789") != std::string::npos ||
        w.find_first_not_of('0') == std::string::npos)
        throw std::runtime_error("n must be a whole number >= 1, not '" + w + "'");
    // Any whole number: beyond the steps the scene has, it goes to the end (or the start).
    const std::string digits = w.substr(w.find_first_not_of('0'));
    return digits.size() > 18 ? std::numeric_limits<std::size_t>::max() / 2 : std::stoull(digits);
}

// The numbers of a value written "1,2", "1 2", "[1, 2]" or "(1, 2)".
std::vector<double> numbers(std::string text) {
    for (char& c : text)
        if (c == ',' || c == '[' || c == ']' || c == '(' || c == ')') c = ' ';
    std::istringstream in(text);
    std::vector<double> values;
    for (std::string w; in >> w;) {
        char* end = nullptr;
        const double x = std::strtod(w.c_str(), &end);
        if (end != w.c_str() + w.size() || !std::isfinite(x)) throw std::runtime_error("'" + w + "' is not a number");
        if (std::abs(x) > kMaxMagnitude) throw std::runtime_error(w + " is larger than 1e12");
        values.push_back(x);
    }
    return values;
}

void need(const std::vector<double>& values, std::size_t n, const std::string& field, const std::string& example) {
    if (values.size() != n)
        throw std::runtime_error(field + " takes " + (n == 1 ? "one number" : std::to_string(n) + " numbers") +
                                 ", e.g. " + example + "; got " + std::to_string(values.size()));
}

// ---- set: one field of one body ----

void set_field(Body1* b, const std::string& field, const std::vector<double>& x) {
    if (field != "x" && field != "v") throw std::runtime_error("no field '" + field + "': 1D bodies have x and v");
    need(x, 1, field, field == "x" ? "0.5" : "-2");
    (field == "x" ? b->position : b->v) = x[0];
}

void set_field(Body2* b, const std::string& field, const std::vector<double>& x) {
    if (field == "x" || field == "v") {
        need(x, 2, field, "1,2");
        (field == "x" ? b->position : b->v) = Vec2(x[0], x[1]);
    } else if (field == "w" || field == "angle") {
        need(x, 1, field, "0.5");
        (field == "w" ? b->w : b->angle) = x[0];
    } else {
        throw std::runtime_error("no field '" + field + "': 2D bodies have x, v, w and angle");
    }
}

void set_field(Body3* b, const std::string& field, const std::vector<double>& x) {
    if (field == "x" || field == "v" || field == "w") {
        need(x, 3, field, "1,2,0");
        (field == "x" ? b->position : field == "v" ? b->v : b->w) = Vec3(x[0], x[1], x[2]);
    } else if (field == "orientation") {
        need(x, 4, "orientation", "[1, 0, 0, 0] (w, x, y, z)");
        const Quat q(x[0], x[1], x[2], x[3]);
        if (q.norm() == 0.0) throw std::runtime_error("the orientation quaternion must not be zero");
        b->orientation = q.normalized();
    } else {
        throw std::runtime_error("no field '" + field + "': 3D bodies have x, v, w and orientation");
    }
}

// How far body i in state bi overlaps body j in state bj (m; <= 0: apart or touching).
double overlap(const Scene& s, std::size_t i, const Body1& bi, std::size_t j, const Body1& bj) {
    return 0.5 * (s.bodies[i].length + s.bodies[j].length) - std::abs(bi.position - bj.position);
}
double overlap(const Scene& s, std::size_t i, const Body2& bi, std::size_t j, const Body2& bj) {
    return -collide(s.bodies[i].shape2, Pose2{bi.position, bi.angle}, s.bodies[j].shape2, Pose2{bj.position, bj.angle})
                .separation;
}
double overlap(const Scene& s, std::size_t i, const Body3& bi, std::size_t j, const Body3& bj) {
    return -collide(s.bodies[i].shape3, Pose3{bi.position, bi.orientation}, s.bodies[j].shape3,
                    Pose3{bj.position, bj.orientation})
                .separation;
}

// ---- The session ----

template <int D>
class Session {
public:
    using World = typename Stepping<D>::World;
    using Event = typename Stepping<D>::Event;

    Session(const Scene& scene, bool json, std::ostream& out)
        : scene_(scene), times_(output_times(scene)), json_(json), out_(out), now_(scene) {
        past_.push_back({now_, 0});
    }

    // Runs one command; throws std::runtime_error (or the world's errors) without changing
    // anything when it cannot.
    void run(const Words& words) {
        const std::string& c = words[0];
        const bool bare = words.size() == 1;
        if (c == "step") step(count(words));
        else if (c == "back") back(count(words));
        else if (c == "show") show(words);
        else if (c == "set") set(words);
        else if ((c == "next" || c == "events" || c == "help") && !bare)
            throw std::runtime_error(c + " takes no arguments");
        else if (c == "next") next();
        else if (c == "events") list_events();
        else if (c == "help") help();
        else throw std::runtime_error("unknown command '" + c + "'; help lists the commands");
    }

    void print(const World& w, std::size_t only = kAllBodies) {
        if (json_) out_ << state_json(scene_, w.time(), w.bodies(), only) << "\n";
        else out_ << state_text(scene_, w.time(), w.bodies(), only);
    }
    const World& now() const { return now_; }

private:
    struct Snapshot {
        World world;         // at times_[k] for the k-th snapshot
        std::size_t events;  // how many events had happened by then
    };

    // Events of whole instants, each marked when its instant gained energy (energy_gains).
    void print(const std::vector<Event>& events) {
        const std::vector<bool> gains = energy_gains(scene_, events);
        for (std::size_t k = 0; k < events.size(); ++k)
            out_ << (json_ ? event_json(scene_, events[k], gains[k]) : event_text(scene_, events[k], gains[k])) << "\n";
    }

    // past_ holds the output steps 0 .. k up to now; now_ is the k-th, or a later state (after
    // `next`, or changed by `set`) short of the next step.
    std::size_t k() const { return past_.size() - 1; }

    void step(std::size_t n) {
        const std::size_t last = times_.size() - 1;
        if (k() == last)
            throw std::runtime_error("the scene ends at t = " + num(times_.back()) +
                                     " s; back goes to an earlier step");
        const std::size_t target = std::min(k() + n, last);
        World w = now_;
        std::vector<Event> fresh;
        std::vector<Snapshot> passed;
        for (std::size_t j = k() + 1; j <= target; ++j) {
            w.advance_to(times_[j], &fresh);
            passed.push_back({w, events_.size() + fresh.size()});
        }
        commit(w, passed, fresh, true);
        print(fresh);
        print(now_);
        if (!json_ && k() == last) out_ << "(the end of the scene)\n";
    }

    void back(std::size_t n) {
        if (on_grid_ && k() == 0) throw std::runtime_error("already at t = 0");
        // Off the output steps (after next or set) the first step back is to the last one passed.
        const std::size_t steps = on_grid_ ? n : n - 1;
        const std::size_t to = steps > k() ? 0 : k() - steps;
        now_ = past_[to].world;
        events_.erase(events_.begin() + static_cast<std::ptrdiff_t>(past_[to].events), events_.end());
        past_.erase(past_.begin() + static_cast<std::ptrdiff_t>(to) + 1, past_.end());
        on_grid_ = true;
        print(now_);
    }

    // Probes output step by output step for the first collision, then replays the world from
    // the last state before it up to the collision's instant.
    void next() {
        World w = now_, before = now_;
        std::vector<Event> fresh;
        std::vector<Snapshot> passed;
        for (std::size_t j = k() + 1; j < times_.size(); ++j) {
            w.advance_to(times_[j], &fresh);
            if (!fresh.empty()) break;
            passed.push_back({w, events_.size()});
            before = w;
        }
        if (fresh.empty())
            throw std::runtime_error("no collision from t = " + num(now_.time()) +
                                     " s to the end of the scene (t = " + num(times_.back()) + " s)");
        const double t = fresh.front().t;
        World at = before;
        std::vector<Event> hit;
        at.advance_to(t, &hit);
        // Replayed up to t, the impact may still lie ahead: t = t0 + dt was rounded, and the world
        // then sees t - t0 < dt. Go on by the least time there is until it is behind.
        double after = t;
        for (int tries = 0; hit.empty() && tries < 4; ++tries) {
            after = std::nextafter(after, std::numeric_limits<double>::infinity());
            at.advance_to(after, &hit);
        }
        if (hit.empty()) throw std::runtime_error("the collision at t = " + num(t) + " s did not recur when replayed");
        commit(at, passed, hit, false);
        if (json_) {
            out_ << "{\"before\":" << state_json(scene_, before.time(), before.bodies()) << ",\"at\":[";
            const std::vector<bool> gains = energy_gains(scene_, hit);
            for (std::size_t e = 0; e < hit.size(); ++e) out_ << (e ? "," : "") << event_json(scene_, hit[e], gains[e]);
            out_ << "],\"after\":" << state_json(scene_, at.time(), at.bodies()) << "}\n";
            return;
        }
        out_ << "before:\n";
        print(before);
        out_ << "at:\n";
        print(hit);
        out_ << "after:\n";
        print(now_);
    }

    void show(const Words& words) {
        if (words.size() > 2) throw std::runtime_error("show takes at most one body name");
        print(now_, words.size() == 2 ? body(words[1]) : kAllBodies);
    }

    void set(const Words& words) {
        const std::string example = D == 1 ? "set ball.v -2" : D == 2 ? "set ball.v 1,2" : "set ball.v 1,2,0";
        if (words.size() < 3) throw std::runtime_error("write set BODY.FIELD VALUE, e.g. " + example);
        const std::size_t dot = words[1].rfind('.');
        if (dot == std::string::npos)
            throw std::runtime_error("'" + words[1] + "' names no field; write BODY.FIELD, e.g. " + example);
        const std::size_t i = body(words[1].substr(0, dot));
        if (scene_.bodies[i].is_static())
            throw std::runtime_error("'" + scene_.bodies[i].name + "' is static and stays where it is");
        auto b = now_.bodies()[i];
        set_field(&b, words[1].substr(dot + 1), numbers(join(words, 2)));
        for (std::size_t j = 0; j < scene_.bodies.size(); ++j) {
            if (j == i) continue;
            const double depth = overlap(scene_, i, b, j, now_.bodies()[j]);
            if (depth > kOverlapTolerance)
                throw std::runtime_error("'" + scene_.bodies[i].name + "' would overlap '" + scene_.bodies[j].name +
                                         "' by " + num(depth) + " m");
        }
        World w = now_;
        w.set_body(i, b);
        commit(w, {}, {}, false);
        print(now_, i);
    }

    void list_events() {
        if (events_.empty() && !json_) out_ << "no collisions so far\n";
        print(events_);
    }

    void help() {
        for (const char* line : kHelp) out_ << line << "\n";
    }

    std::size_t body(const std::string& name) const {
        std::string names;
        for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
            if (scene_.bodies[i].name == name) return i;
            names += (i ? ", " : "") + scene_.bodies[i].name;
        }
        throw std::runtime_error("no body named '" + name + "'; the bodies are " + names);
    }

    void commit(const World& w, const std::vector<Snapshot>& passed, const std::vector<Event>& fresh, bool on_grid) {
        now_ = w;
        past_.insert(past_.end(), passed.begin(), passed.end());
        events_.insert(events_.end(), fresh.begin(), fresh.end());
        on_grid_ = on_grid;
    }

    const Scene scene_;
    const std::vector<double> times_;
    const bool json_;
    std::ostream& out_;
    World now_;
    std::vector<Snapshot> past_;  // the state at each output step up to now
    bool on_grid_ = true;         // now_ is past_.back()
    std::vector<Event> events_;   // every collision up to now
};

// One command line of at most kMaxInputBytes, read up to that many bytes (a stream without
// line breaks, /dev/zero, is not read whole): false at the end of the input. A longer line or
// a NUL byte (not text) ends the session with InputError (exit 2).
bool read_command(std::istream& in, std::string* line, int number) {
    line->clear();
    for (;;) {
        const int c = in.get();
        if (c == std::char_traits<char>::eof()) return !line->empty();
        if (c == '\n') return true;
        if (c == '\0')
            throw InputError("<stdin>", {number, static_cast<int>(line->size()) + 1}, "",
                             "not text (a NUL byte); expected commands, one a line");
        if (line->size() == kMaxInputBytes)
            throw InputError(
                "<stdin>", {number, 1}, "",
                "a command line longer than 1 MiB (stopped reading there); commands are one short line each");
        line->push_back(static_cast<char>(c));
    }
}

template <int D>
void loop(const Scene& scene, const InteractiveOptions& options, std::istream& in, std::ostream& out,
          std::ostream& err) {
    Session<D> session(scene, options.json, out);
    if (options.prompt) {
        out << (scene.title.empty() ? "Scene" : scene.title) << " (" << D << "D, " << scene.bodies.size()
            << " bodies): t = 0 to " << num(scene.duration) << " s in steps of " << num(scene.output_dt)
            << " s. help lists the commands.\n";
        session.print(session.now());
    }
    int number = 0;
    for (std::string line;;) {
        if (options.prompt) out << "collide> " << std::flush;
        if (!read_command(in, &line, ++number)) break;
        const Words words = split(line);
        if (words.empty()) continue;
        if (words[0] == "quit" || words[0] == "exit") return;
        try {
            session.run(words);
        } catch (const std::exception& e) {
            out << std::flush;  // the reply so far first, where both go to one terminal
            err << "error: " << e.what() << "\n";
        }
        out << std::flush;
    }
    if (options.prompt) out << "\n";  // after the prompt, so the shell's starts on its own line
}

}  // namespace

void run_interactive(const Scene& scene, const InteractiveOptions& options, std::istream& in, std::ostream& out,
                     std::ostream& err) {
    if (scene.dimension == 1) loop<1>(scene, options, in, out, err);
    else if (scene.dimension == 2) loop<2>(scene, options, in, out, err);
    else loop<3>(scene, options, in, out, err);
}

}  // namespace collide
