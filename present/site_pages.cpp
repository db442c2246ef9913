#include "present/site_pages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "present/figures.h"  // kColumnWidth, kWideFigureWidth
#include "present/site_plots.h"
#include "present/site_questions.h"
#include "render/style.h"
#include "teach/html.h"
#include "teach/notation.h"

namespace collide {

namespace {

using namespace site;
using html::escape;
using html::math;
using html::paragraphs;
using html::Series;
using html::svg_plot;
using html::worked_html;

std::string n(double x) { return notation::num_text(std::abs(x) < 1e-12 ? 0.0 : x); }
// Noise below the vector's own precision shown as 0 (notation::StudentNumbers).
std::string vec(const Vec3& v, int dim) { return notation::vec(v, dim).txt; }
std::string spin(const Vec3& w, int dim) { return dim == 2 ? n(w.z()) : vec(w, 3); }

// Three significant figures, a true minus sign, no "-0": numbers in sentences.
std::string sig3(double x) { return notation::sig_text(x, 3); }

// How a body moves, in words: "moves at 1.5 m/s", "is at rest", "moves at 1.07 m/s and spins
// at 1.83 rad/s" (1D: the signed velocity along +x; 2D: ω about +z; 3D: |ω|).
std::string motion_words(const Vec3& v, const Vec3& w, int dim) {
    const double speed = dim == 1 ? v.x() : v.norm();
    const double turn = dim == 2 ? w.z() : w.norm();
    std::string s;
    if (std::abs(speed) < 1e-12) s = "is at rest";
    else s = "moves at " + sig3(speed) + " m/s" + (dim == 1 ? " along +x" : "");
    if (dim > 1 && std::abs(turn) > 1e-12)
        s += (std::abs(speed) < 1e-12 ? " but spins at " : " and spins at ") + sig3(turn) + " rad/s" +
             (dim == 2 ? (turn > 0 ? " counter-clockwise" : " clockwise") : "");
    return s;
}

// The figure's alternative text, from the collision it shows: who moves how before, the
// impulse, and how they move after.
std::string figure_alt(const SolveProblem& P, const Solution& S, double t) {
    const int d = P.dimension;
    const auto who = [&](const SolveBody& B) {
        return B.name + (B.b3.is_static ? " (static)" : " (" + sig3(B.b3.mass) + " kg)");
    };
    std::string s = "Before, at and after the collision at t = " + sig3(t) + " s. Before: " + who(P.a) + " " +
                    motion_words(P.a.b3.v, P.a.b3.w, d) + "; " + who(P.b) + " " + motion_words(P.b.b3.v, P.b.b3.w, d) +
                    ". At the collision the impulse on " + P.b.name + " is " +
                    (d == 1 ? sig3(S.P.x()) : sig3(S.P.norm())) + " N s" + (d == 1 ? " along +x" : "") + "; " +
                    P.a.name + " receives the opposite. After: " + P.a.name + " " + motion_words(S.va, S.wa, d) + "; " +
                    P.b.name + " " + motion_words(S.vb, S.wb, d) + ".";
    return s;
}

// Under the video (which has no controls of its own: the browser's would cover the bottom of the
// frame): play and pause (or click the video), a slider for the position, a frame back and
// forward (1/fps of simulated time: the video runs at the simulation's pace) and the speed, in
// the page's own script (no network).
const char* kPlayer = R"(<div class="player noprint" role="group" aria-label="Playback">
<button type="button" data-act="play">Play / pause</button>
<input type="range" class="seek" min="0" max="1000" step="1" value="0" aria-label="Position in the run">
<button type="button" data-act="back" aria-label="One frame back">&#9664; frame</button>
<button type="button" data-act="fwd" aria-label="One frame forward">frame &#9654;</button>
<span class="speeds">speed <button type="button" data-rate="0.25">0.25&times;</button>
<button type="button" data-rate="0.5">0.5&times;</button>
<button type="button" data-rate="1" aria-pressed="true">1&times;</button></span>
<span class="time" aria-live="off"></span>
</div>
<script>
(function () {
  var v = document.querySelector('video.lesson'), bar = document.querySelector('.player');
  if (!v || !bar) return;
  var dt = 1 / (parseFloat(v.dataset.fps) || 30), time = bar.querySelector('.time');
  bar.querySelectorAll('button').forEach(function (b) {
    b.addEventListener('click', function () {
      if (b.dataset.rate) {
        v.playbackRate = parseFloat(b.dataset.rate);
        bar.querySelectorAll('[data-rate]').forEach(function (o) { o.setAttribute('aria-pressed', o === b); });
      } else if (b.dataset.act === 'play') {
        if (v.paused) v.play(); else v.pause();
      } else {
        v.pause();
        var t = v.currentTime + (b.dataset.act === 'fwd' ? dt : -dt);
        v.currentTime = Math.max(0, Math.min(v.duration || 0, t));
      }
    });
  });
  var seek = bar.querySelector('.seek');
  var show = function () {
    time.textContent = 't = ' + v.currentTime.toFixed(3) + ' s';
    if (v.duration) seek.value = Math.round(1000 * v.currentTime / v.duration);
  };
  seek.addEventListener('input', function () { if (v.duration) v.currentTime = v.duration * seek.value / 1000; });
  v.addEventListener('click', function () { if (v.paused) v.play(); else v.pause(); });
  v.addEventListener('timeupdate', show);
  v.addEventListener('seeked', show);
})();
</script>
)";

// ---- Pages ----

// The stylesheet is assets/site/style.css, compiled in (cmake/embed.cmake).

std::string page_head(const std::string& title, const std::string& root, const std::string& body_class = "") {
    return "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
           "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
           escape(title) + "</title>\n<link rel=\"stylesheet\" href=\"" + root + "style.css\">\n</head>\n<body" +
           (body_class.empty() ? "" : " class=\"" + body_class + "\"") + ">\n<header class=\"site\"><a href=\"" + root +
           "index.html\">Collide: lessons on collisions with rotation</a></header>\n<main>\n";
}
const char* kPageTail = "</main>\n</body>\n</html>\n";

// What the pages show of a lesson's run: its figures, each collision worked out, the tables.
struct Shown {
    const SitePage& b;
    const notation::StudentNumbers student;  // every number on it: 4 figures, no noise

    const Lesson& L() const { return b.lesson; }
    const RenderReport& r() const { return b.report; }

    // One figure: the collision it shows, before, at and after.
    // `when`: its caption gives the collision's instant (the teacher's page; on the student's
    // the instant may be what a question asks).
    std::string figure(const RenderReport::Shown& f, bool when = false) const {
        std::ostringstream h;
        // Panels side by side are shown up to their own width, beyond the text column when the
        // window allows (style.css, figure.wide), so that their labels stay readable.
        const std::size_t k = static_cast<std::size_t>(&f - r().figures.data());
        const bool wide = k < b.figure_widths.size() && b.figure_widths[k] > kColumnWidth;
        const std::string alt = figure_alt(f.problem, as_resolved(f.problem, f.solution, f.instant), f.instant.t);
        const std::string what = f.caption.empty()
                                     ? (&f == &r().figures.front() && L().figures.empty()
                                            ? "Before, at and after the first collision"
                                            : "Before, at and after the collision of " + f.problem.a.name +
                                                  " (a) and " + f.problem.b.name + " (b)")
                                     : f.caption;
        h << "<figure" << (wide ? " class=\"wide\"" : "") << "><a href=\"" << f.file
          << "\" title=\"Open the figure at full size\"><img src=\"" << f.file << "\" alt=\"" << escape(alt)
          << "\"></a><figcaption>" << math(what) << (when ? " (t = " + escape(n(f.instant.t)) + " s)" : "")
          << ", from the simulation.";
        if (L().view.directions) h << " Grey arrows: the positive directions (velocities may be negative).";
        h << " Click it to see it at full size.</figcaption></figure>\n";
        return h.str();
    }

    std::string variants_figure(bool heading = true) const {
        if (r().variants.empty()) return "";
        return std::string(heading ? "<h3>Side by side</h3>\n" : "") + "<figure" +
               (b.variants_width > kColumnWidth ? " class=\"wide\"" : "") +
               "><a href=\"variants.png\" title=\"Open the figure at full size\"><img src=\"variants.png\" "
               "alt=\"" +
               escape(variants_alt()) + "\"></a></figure>\n";
    }

    // What variants.png shows, panel by panel, in the numbers of the table below it.
    std::string variants_alt() const {
        const int d = L().scene.dimension;
        std::string s =
            "The lesson's scene and its variants side by side, each before, at and after its first "
            "collision.";
        for (const RenderReport::Variant& v : r().variants) {
            s += " " + v.label + ": ";
            if (!v.first) {
                s += "no collision.";
                continue;
            }
            const CollisionInstant& c = *v.first;
            s += "impulse on " + L().scene.bodies[c.b].name + " " +
                 (d == 1 ? sig3(c.impulse.x()) : sig3(c.impulse.norm())) + " N s, kinetic energy lost (J) " +
                 energy_lost_text(v.ke_before, v.ke_after) + ".";
        }
        return s;
    }

    // The plots' alt texts: what each curve does from the start to the end, and the collisions.
    std::string totals_alt(bool energy) const {
        const std::vector<render::FrameTotals>& T = r().plot_totals;
        const std::size_t collisions = r().collision_times.size();
        std::string s =
            std::string(energy ? "Energy" : "Momentum") + " against time, from 0 to " + sig3(L().scene.duration) + " s";
        if (T.empty()) return s + ".";
        const auto from_to = [&](const std::string& what, double a, double b, const std::string& unit) {
            if (sig3(a) == sig3(b)) return what + " stays at " + sig3(a) + " " + unit;
            return what + " from " + sig3(a) + " " + unit + " at the start to " + sig3(b) + " " + unit + " at the end";
        };
        const render::FrameTotals &a = T.front(), &b = T.back();
        if (energy) {
            s += ": " + from_to("kinetic energy", a.kinetic, b.kinetic, "J");
            if (L().scene.gravity.norm() > 0)
                s += "; total energy (kinetic and potential) " +
                     from_to("", a.kinetic + a.potential, b.kinetic + b.potential, "J").substr(1);
        } else {
            const char* axis[] = {"x", "y", "z"};
            const int d = L().scene.dimension;
            s += ": ";
            for (int k = 0; k < d; ++k)
                s += (k ? "; " : "") +
                     from_to(d == 1 ? "p" : std::string("p along ") + axis[k], a.momentum[k], b.momentum[k], "kg m/s");
        }
        s += ". " + std::to_string(collisions) +
             (collisions == 1 ? " collision is marked by a red line" : " collisions are marked by red lines") +
             (collisions
                  ? (collisions == 1 ? ", at t = " : ", the first at t = ") + sig3(r().collision_times.front()) + " s."
                  : ".");
        return s;
    }

    std::string plots() const {
        return "<h3>Energy and momentum against time</h3>\n<div class=\"plots\">"
               "<img src=\"energy.svg\" alt=\"" +
               escape(totals_alt(true)) + "\"><img src=\"momentum.svg\" alt=\"" + escape(totals_alt(false)) +
               "\"></div>\n<p class=\"note\">Red lines: the collisions. Data: <a href=\"data.csv\">data.csv</a>, "
               "<a href=\"data.json\">data.json</a>, <a href=\"events.csv\">events.csv</a>.</p>\n";
    }

    std::string animation() const {
        std::ostringstream o;
        o << "<section class=\"animation noprint\">\n<h3>Animation</h3>\n";
        if (r().video == "animation.mp4") {
            const double fps = b.fps();
            // The page's own buttons play it: the browser's controls would cover the bottom of
            // the frame (the plots' axes, the last worked line).
            o << "<video class=\"lesson\" loop muted playsinline preload=\"metadata\" data-fps=\""
              << notation::num_data(fps) << "\" poster=\"frames/frame_00000.png\" src=\"animation.mp4\"></video>\n"
              << kPlayer;
        } else if (r().video == "animation.gif") {
            o << "<figure><img src=\"animation.gif\" alt=\"The animation of the run\"></figure>\n";
        } else {
            o << "<p class=\"note\">The frames are in <a href=\"frames/frame_00000.png\">frames/</a> (" << r().frames
              << " PNG files); install ffmpeg for a video.</p>\n";
        }
        o << "</section>\n";
        return o.str();
    }

    // Every collision of the lesson worked out: the figures' (the first, then the others with
    // their figures when `with_figures`), the run's later ones folded (printed: one line each),
    // the tables of the bodies before and after and of the variants.
    std::string worked(bool with_figures) const {
        std::ostringstream o;
        const RenderReport& R = r();
        const int d = L().scene.dimension;
        if (!R.problem || !R.solution) return "<p class=\"note\">The run has no collision to work out.</p>\n";
        const SolveProblem& P = *R.problem;
        const Solution& S = *R.solution;
        o << "<h3>"
          << (L().figures.empty() ? std::string("The first collision")
                                  : "The collision of " + escape(P.a.name) + " and " + escape(P.b.name))
          << "</h3>\n";
        if (with_figures && !R.figures.empty()) o << figure(R.figures.front(), true);
        // One notation on the page: our P is the page's J; j its size along n.
        o << "<p class=\"note\">Conventions: body a is " << escape(P.a.name) << " and body b is " << escape(P.b.name)
          << "; the normal n points from a into b; the impulse P (the page writes J) acts as +P on b and −P on a "
             "at the contact point, and j = P · n is its size along n; u = v<sub>pb</sub> − v<sub>pa</sub>; SI "
             "units. Model: "
          << escape(model_name(P.model)) << ".</p>\n";
        const Solution run = R.figures.empty() ? S : as_resolved(P, S, R.figures.front().instant);
        o << html::worked_html_beside_run(P, S, run, R.world_note);
        for (std::size_t k = 1; k < R.figures.size(); ++k) {
            const RenderReport::Shown& f = R.figures[k];
            o << "<h3>The collision of " << escape(f.problem.a.name) << " and " << escape(f.problem.b.name) << "</h3>\n"
              << (with_figures ? figure(f, true) : "")
              << html::worked_html_beside_run(f.problem, f.solution, as_resolved(f.problem, f.solution, f.instant),
                                              f.world_note);
        }
        if (!R.later.empty()) {
            const std::size_t worked = R.later.size() + R.figures.size();
            o << "<h3>" << (L().figures.empty() ? "The later collisions" : "The other collisions")
              << "</h3>\n<p class=\"note\">The run has " << R.collision_times.size() << " collisions"
              << (worked < R.collision_times.size() ? "; " + std::to_string(worked) + " are worked out here" : "")
              << ". Open one to see it step by step.</p>\n";
            for (const RenderReport::Later& c : R.later) {
                const int dc = c.problem.dimension;
                const Solution ran = as_resolved(c.problem, c.solution, c.instant);
                o << "<details class=\"later\"><summary>" << escape(c.problem.a.name) << " and "
                  << escape(c.problem.b.name) << " at t = " << escape(sig3(c.instant.t)) << " s, impulse on "
                  << escape(c.problem.b.name) << " " << escape(dc == 1 ? sig3(ran.P.x()) : sig3(ran.P.norm()))
                  << " N s in the run</summary>\n"
                  << html::worked_html_beside_run(c.problem, c.solution, ran, c.world_note) << "</details>\n";
            }
        }
        // The table: the two bodies before and after, as the run resolved them.
        o << "<h3>Before and after</h3>\n";
        if (resolved_differs(P, S, run))
            o << "<p class=\"note\">As the run resolved the collision, with the other contacts of the same instant "
                 "(the numbers the figure and the answers show).</p>\n";
        o << "<table>\n<tr><th>body</th><th>m (kg)</th><th>v before (m/s)</th>"
             "<th>v after (m/s)</th>";
        if (d > 1) o << "<th>ω before (rad/s)</th><th>ω after (rad/s)</th>";
        o << "</tr>\n";
        const auto row = [&](const SolveBody& B, const Vec3& v, const Vec3& w) {
            o << "<tr><td>" << escape(B.name) << "</td><td>" << (B.b3.is_static ? "static" : escape(n(B.b3.mass)))
              << "</td><td>" << escape(vec(B.b3.v, d)) << "</td><td>" << escape(vec(v, d)) << "</td>";
            if (d > 1) o << "<td>" << escape(spin(B.b3.w, d)) << "</td><td>" << escape(spin(w, d)) << "</td>";
            o << "</tr>\n";
        };
        row(P.a, run.va, run.wa);
        row(P.b, run.vb, run.wb);
        o << "</table>\n<table>\n<tr><th>totals of the two</th><th>before</th><th>after</th></tr>\n"
          << "<tr><td>momentum (kg m/s)</td><td>" << escape(vec(run.p_before, d)) << "</td><td>"
          << escape(vec(run.p_after, d)) << "</td></tr>\n";
        if (d > 1)
            o << "<tr><td>angular momentum about the origin (kg m²/s)</td><td>" << escape(spin(run.L_before, d))
              << "</td><td>" << escape(spin(run.L_after, d)) << "</td></tr>\n";
        o << "<tr><td>kinetic energy (J)</td><td>" << escape(n(run.ke_before)) << "</td><td>" << escape(n(run.ke_after))
          << "</td></tr>\n</table>\n";
        if (!R.variants.empty()) {
            o << "<h3>The panels side by side, in numbers</h3>\n"
              << (with_figures ? variants_figure(false) : "")
              << "<table>\n<tr><th></th><th>impulse on b (N s)</th>"
                 "<th>a after (m/s)</th><th>b after (m/s)</th><th>kinetic energy lost (J)</th></tr>\n";
            for (const RenderReport::Variant& v : R.variants) {
                if (!v.first) {
                    o << "<tr><td>" << math(v.label) << "</td><td colspan=\"4\">no collision</td></tr>\n";
                    continue;
                }
                const CollisionInstant& c = *v.first;
                o << "<tr><td>" << math(v.label) << " (" << escape(L().scene.bodies[c.a].name) << " on "
                  << escape(L().scene.bodies[c.b].name) << ")</td><td>" << escape(vec(c.impulse, d)) << "</td><td>"
                  << escape(vec(c.va_after, d)) << "</td><td>" << escape(vec(c.vb_after, d)) << "</td><td>"
                  << escape(energy_lost_text(v.ke_before, v.ke_after)) << "</td></tr>\n";
            }
            o << "</table>\n";
        }
        return o.str();
    }
};

// The lesson's [[vary]] inputs, from the lesson data (the Try-it sliders and the worksheets'
// ranges): the teacher's page lists them, so a lesson that gains one shows it.
std::string inputs_html(const Lesson& L) {
    std::ostringstream o;
    if (L.vary.empty()) {
        o << "<p class=\"warning\">This lesson declares no <code>[[vary]]</code> inputs: its Try-it panel has no "
             "sliders and worksheets give every student the same numbers. Change the values in the lesson file "
             "instead.</p>\n";
        return o.str();
    }
    o << "<table class=\"inputs\">\n<tr><th>input (slider, query string)</th><th>from</th><th>to</th><th>step</th>"
         "<th>the lesson's value</th></tr>\n";
    for (const LessonVary& v : L.vary)
        o << "<tr><td><code>" << escape(v.name()) << "</code></td><td>" << escape(notation::num_data(v.lo))
          << "</td><td>" << escape(notation::num_data(v.hi)) << "</td><td>" << escape(notation::num_data(v.step))
          << "</td><td>" << escape(notation::num_data(v.lesson_value)) << "</td></tr>\n";
    o << "</table>\n<p class=\"note\">Each is a slider of the Try-it panel on <a href=\"index.html#try-it\">the "
         "student's page</a>, and can be set from its address: <code>index.html?"
      << escape(L.vary.front().name()) << "=" << escape(notation::num_data(L.vary.front().hi))
      << "</code>. Worksheets draw each student's values from the same ranges.</p>\n";
    return o.str();
}

}  // namespace

// The figures' colours (render/style.h) for the panel's canvas, as CSS colours in JSON.
std::string palette_json() {
    const render::Palette c;
    const auto css = [](render::Colour x) { return "\"" + render::css_colour(x) + "\""; };
    std::string fills, darks;
    for (int k = 0; k < render::Palette::kFills; ++k) {
        fills += (k ? "," : "") + css(c.fills[k]);
        darks += (k ? "," : "") + css(c.darks[k]);
    }
    return "{\"background\":" + css(c.background) + ",\"ink\":" + css(c.ink) + ",\"muted\":" + css(c.muted) +
           ",\"grid\":" + css(c.grid) + ",\"static_fill\":" + css(c.static_fill) + ",\"hatch\":" + css(c.hatch) +
           ",\"velocity\":" + css(c.velocity) + ",\"spin\":" + css(c.spin) + ",\"impulse\":" + css(c.impulse) +
           ",\"normal\":" + css(c.normal) + ",\"fills\":[" + fills + "],\"darks\":[" + darks + "]}";
}

std::string lesson_page(const SitePage& b, const SitePage* prev, const SitePage* next) {
    const Shown shown{b, {}};  // every number on it: 4 figures, no noise
    const Lesson& L = b.lesson;
    const RenderReport& r = b.report;
    const int d = L.scene.dimension;
    std::vector<std::size_t> predict, check, what_if;
    for (std::size_t i = 0; i < L.questions.size(); ++i) switch (place_of(L.questions[i])) {
            case Place::predict: predict.push_back(i); break;
            case Place::check: check.push_back(i); break;
            case Place::what_if: what_if.push_back(i); break;
        }
    std::ostringstream o;
    o << page_head(L.title, "../", "student");
    o << "<p class=\"section\">Lesson " << L.order << " · " << d << "D"
      << (L.section.empty() ? "" : " · the page's section <em>" + escape(L.section) + "</em>") << "</p>\n";
    o << "<h1>" << math(L.title) << "</h1>\n";
    // The student's page: its print has no answers. Every answer is on the teacher's page.
    o << "<p class=\"audience noprint\">For the teacher: <a href=\"teacher.html\">the teacher's page</a> (level, "
         "time, misconceptions, questions for the class, how to run it live, every answer and the worked example; "
         "print it for the teacher's copy).</p>\n";
    if (!L.goals.empty()) {
        o << "<h2>Learning goals</h2>\n<ul>\n";
        for (const std::string& g : L.goals) o << "<li>" << math(g) << "</li>\n";
        o << "</ul>\n";
    }
    if (!L.setup.empty())
        o << "<section class=\"setup\">\n<h2>The set-up</h2>\n" << paragraphs(L.setup) << "</section>\n";
    if (!predict.empty()) o << predict_html(L, r.answers, predict);
    // Watch: what the run shows (screen only: the figures and plots carry the run's numbers,
    // the answers of the questions below; the student's print leaves them out).
    o << "<section class=\"watch\">\n<h2>Watch</h2>\n<div class=\"noprint\">\n";
    for (const RenderReport::Shown& f : r.figures) o << shown.figure(f);
    o << shown.animation() << plots_html(r.plots) << shown.variants_figure() << shown.plots() << "</div>\n"
      << "<p class=\"printonly\">Watch the figures and the animation of this lesson on its page before you go "
         "on.</p>\n</section>\n";
    if (!predict.empty()) o << check_html(L, r.answers, predict);
    if (!L.explanation.empty())
        o << "<section class=\"explain\">\n<h2>Explanation</h2>\n" << paragraphs(L.explanation) << "</section>\n";
    // The worked example gives the numbers of the questions below it: folded until the student
    // has answered them (the script opens it), or opened by hand.
    o << "<section class=\"worked\">\n<h2>The worked example</h2>\n<details class=\"worked\" id=\"worked\"><summary>"
      << (check.empty() ? "Show the worked example"
                        : "Show the worked example (it opens by itself once you have checked your answer to every "
                          "question of “Check yourself” below)")
      << "</summary>\n"
      << shown.worked(false) << "</details>\n</section>\n";
    if (!check.empty()) {
        o << "<section class=\"check-yourself\">\n<h2>Check yourself</h2>\n";
        const bool numeric =
            std::any_of(check.begin(), check.end(), [&](std::size_t i) { return L.questions[i].has_quantity(); });
        if (b.check && numeric) o << new_numbers_html(L, *b.check, b.try_it, false);
        else if (numeric)
            o << "<p class=\"note\">This lesson declares no <code>[[vary]]</code> inputs: the questions below are "
                 "about the run you watched, whose numbers the figures above show.</p>\n";
        o << questions_html(L, r.answers, check, b.check ? &*b.check : nullptr) << "</section>\n";
    }
    if (!what_if.empty() || b.try_it || r.penalty) {
        // Without what-if questions it holds only the panels, which do not print: nor does it.
        o << "<section class=\"what-if" << (what_if.empty() ? " noprint" : "") << "\">\n<h2>What if</h2>\n";
        if (!what_if.empty()) o << questions_html(L, r.answers, what_if);
        if (b.try_it) o << html::try_it_html(L, b.fps(), "../");
        if (r.penalty) o << "<div class=\"penalty noprint\">\n" << penalty_html(*r.penalty) << "</div>\n";
        o << "</section>\n";
    }
    o << kQuestionScript;
    o << "<nav class=\"pager\">";
    o << (prev ? "<a href=\"../" + prev->lesson.id + "/index.html\">← " + math(prev->lesson.title) + "</a>"
               : "<span></span>");
    o << "<a href=\"../index.html\">All lessons</a>";
    o << (next ? "<a href=\"../" + next->lesson.id + "/index.html\">" + math(next->lesson.title) + " →</a>"
               : "<span></span>");
    o << "</nav>\n" << kPageTail;
    return o.str();
}

std::string teacher_page(const SitePage& b) {
    const Shown shown{b, {}};  // every number on it: 4 figures, no noise
    const Lesson& L = b.lesson;
    const RenderReport& r = b.report;
    std::ostringstream o;
    o << page_head("Teacher's page: " + L.title, "../", "teacher");
    o << "<p class=\"section\">Lesson " << L.order << " · " << L.scene.dimension << "D"
      << (L.section.empty() ? "" : " · the page's section <em>" + escape(L.section) + "</em>")
      << " · <a href=\"index.html\">the student's page</a></p>\n";
    o << "<h1>Teacher's page: " << math(L.title) << "</h1>\n";
    if (L.teacher) {
        const LessonTeacher& T = *L.teacher;
        o << "<table class=\"facts\">\n<tr><th>Level</th><td>" << math(T.level)
          << "</td></tr>\n<tr><th>Prerequisites</th><td><ul>\n";
        for (const std::string& p : T.prerequisites) o << "<li>" << math(p) << "</li>\n";
        o << "</ul></td></tr>\n<tr><th>Time needed</th><td>about " << T.minutes << " minutes</td></tr>\n";
        if (!L.goals.empty()) {
            o << "<tr><th>Goals</th><td><ul>\n";
            for (const std::string& g : L.goals) o << "<li>" << math(g) << "</li>\n";
            o << "</ul></td></tr>\n";
        }
        o << "</table>\n";
        o << "<section class=\"misconceptions\">\n<h2>The misconceptions it targets</h2>\n<ul>\n";
        for (const LessonMisconception& m : T.misconceptions)
            o << "<li><p><strong>“" << math(m.belief) << "”</strong></p><p><em>What the lesson shows:</em> "
              << math(m.evidence) << "</p></li>\n";
        o << "</ul>\n</section>\n<section class=\"ask-class\">\n<h2>Questions to ask in class</h2>\n<ol>\n";
        for (const LessonClassQuestion& q : T.ask) {
            o << "<li><p>" << math(q.question) << "</p>";
            if (!q.listen_for.empty()) o << "<p><em>Listen for:</em> " << math(q.listen_for) << "</p>";
            o << "</li>\n";
        }
        o << "</ol>\n</section>\n<section class=\"live\">\n<h2>Running it live</h2>\n" << paragraphs(T.live);
    } else {
        o << "<p class=\"warning\">This lesson has no <code>[teacher]</code> table: no level, prerequisites, time, "
             "misconceptions or questions for the class are given (docs/formats/lesson-files.md, “The teacher's "
             "page”). Its answers and worked example follow.</p>\n<section class=\"live\">\n<h2>Running it "
             "live</h2>\n";
    }
    o << "<h3>The lesson's inputs</h3>\n" << inputs_html(L) << "</section>\n";
    if (!L.teacher_notes.empty())
        o << "<section class=\"notes\">\n<h2>Notes for the teacher</h2>\n"
          << paragraphs(L.teacher_notes) << "</section>\n";
    if (!L.setup.empty())
        o << "<section class=\"setup\">\n<h2>The set-up</h2>\n" << paragraphs(L.setup) << "</section>\n";
    // Every answer, in the order the student's page asks the questions.
    o << "<section class=\"answers\">\n<h2>Every answer</h2>\n";
    const std::pair<Place, const char*> places[] = {{Place::predict, "Before you watch (predictions)"},
                                                    {Place::check, "Check yourself"},
                                                    {Place::what_if, "What if"}};
    for (const auto& [place, heading] : places) {
        std::ostringstream list;
        bool numeric = false;
        for (std::size_t i = 0; i < L.questions.size(); ++i) {
            const LessonQuestion& q = L.questions[i];
            if (place_of(q) != place) continue;
            const LessonAnswer* own = i < r.answers.size() ? &r.answers[i] : nullptr;
            const bool checked = place == Place::check && b.check && b.check->answer[i];
            numeric = numeric || (checked && q.has_quantity());
            list << "<li>" << ask_html(q) << (q.has_choices() ? options_html(q) : "") << "<div class=\"key\">"
                 << (checked ? answer_html(q, &*b.check->answer[i], own) : answer_html(q, own)) << "</div></li>\n";
        }
        if (list.str().empty()) continue;
        o << "<h3>" << heading << "</h3>\n";
        if (numeric) o << new_numbers_html(L, *b.check, false, true);
        o << "<ol class=\"answers\">\n" << list.str() << "</ol>\n";
    }
    o << "</section>\n";
    if (!L.explanation.empty())
        o << "<section class=\"explain\">\n<h2>The explanation (as the students read it)</h2>\n"
          << paragraphs(L.explanation) << "</section>\n";
    o << "<section class=\"worked\">\n<h2>The worked example</h2>\n" << shown.worked(true) << "</section>\n";
    // The lesson's plots, with their numbers (the student's page shows them under "Watch").
    if (!r.plots.empty())
        o << "<section class=\"plots\">\n<h2>The lesson's plots</h2>\n" << plots_html(r.plots) << "</section>\n";
    o << "<nav class=\"pager\"><a href=\"index.html\">The student's page</a><a href=\"../index.html\">All "
         "lessons</a><span></span></nav>\n"
      << kPageTail;
    return o.str();
}

std::string index_page(const std::vector<SitePage>& all) {
    std::ostringstream o;
    o << page_head("Collide: lessons", "");
    o << "<h1>Collisions with rotation: lessons</h1>\n<p>Each lesson is a simulation you can trust: "
         "the exact instant of contact, the impulse from the page's formulas, and the checks "
         "(momentum, angular momentum, energy). Open one to predict, watch, follow the explanation and "
         "the worked example, and check yourself. Each lesson also has a teacher's page: level, time, "
         "the misconceptions it targets, questions for the class, how to run it live, and every answer.</p>\n"
         "<ul class=\"grid\">\n";
    for (const SitePage& b : all) {
        const Lesson& L = b.lesson;
        o << "<li class=\"card\"><a href=\"" << L.id << "/index.html\">";
        if (b.thumb) o << "<img src=\"" << L.id << "/thumb.png\" alt=\"\">";
        o << "<div class=\"text\"><div class=\"num\">Lesson " << L.order << " · " << L.scene.dimension << "D"
          << (L.section.empty() ? "" : " · " + escape(L.section)) << "</div><h2>" << math(L.title)
          << "</h2></div></a><a class=\"teacher-link\" href=\"" << L.id << "/teacher.html\">Teacher's page</a></li>\n";
    }
    o << "</ul>\n" << kPageTail;
    return o.str();
}

}  // namespace collide
