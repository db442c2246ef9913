#include "present/site_pages.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "present/figures.h"  // kColumnWidth, kWideFigureWidth
#include "render/style.h"
#include "teach/html.h"
#include "teach/notation.h"

namespace collide {

namespace {

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

// Under the video: play and pause, a frame back and forward (1/fps of simulated time: the
// video runs at the simulation's pace) and the speed, in the page's own script (no network).
const char* kPlayer = R"(<div class="player noprint" role="group" aria-label="Playback">
<button type="button" data-act="play">Play / pause</button>
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
  var show = function () { time.textContent = 't = ' + v.currentTime.toFixed(3) + ' s'; };
  v.addEventListener('timeupdate', show);
  v.addEventListener('seeked', show);
})();
</script>
)";

// Printing the questions: for students (a space to write each answer in) or, ticked, the
// teacher's copy with the answers.
const char* kPrintChoice =
    R"(<p class="noprint print-choice"><label><input type="checkbox" id="print-answers"> Print with the answers (the teacher's copy)</label></p>
<script>
document.getElementById('print-answers').addEventListener('change', function (e) {
  document.body.classList.toggle('with-answers', e.target.checked);
});
</script>
)";

// ---- Pages ----

// The stylesheet is assets/site/style.css, compiled in (cmake/embed.cmake).

std::string page_head(const std::string& title, const std::string& root) {
    return "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
           "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
           escape(title) + "</title>\n<link rel=\"stylesheet\" href=\"" + root +
           "style.css\">\n</head>\n<body>\n<header class=\"site\"><a href=\"" + root +
           "index.html\">Collide: lessons on collisions with rotation</a></header>\n<main>\n";
}
const char* kPageTail = "</main>\n</body>\n</html>\n";

// ---- Questions ----

// The options of a choice (or predict) question: numbered, each a radio button on screen so a
// student can choose by keyboard; printed, the numbers stay for circling one.
std::string choices_html(const LessonQuestion& q, std::size_t qi) {
    std::ostringstream o;
    o << "<ul class=\"choices\">\n";
    for (std::size_t k = 0; k < q.choices.size(); ++k)
        o << "<li><label><input type=\"radio\" name=\"q" << qi + 1 << "\" value=\"" << option_number(k)
          << "\"> <span class=\"letter\">(" << option_number(k) << ")</span> " << math(q.choices[k])
          << "</label></li>\n";
    o << "</ul>\n";
    return o.str();
}

// A question's answer: the engine's number, the right option with every option's reason, or
// the model answer; then why.
std::string answer_html(const LessonQuestion& q, const LessonAnswer* a) {
    std::ostringstream o;
    if (q.has_choices()) {
        o << "<p><span class=\"answer\">Option " << option_number(static_cast<std::size_t>(q.correct - 1))
          << ".</span></p>\n<ul class=\"reasons\">\n";
        for (std::size_t k = 0; k < q.choices.size(); ++k) {
            const bool right = static_cast<int>(k) + 1 == q.correct;
            o << "<li class=\"" << (right ? "right" : "wrong") << "\"><span class=\"letter\">(" << option_number(k)
              << ")</span> <em>" << (right ? "Right" : "Wrong") << ":</em> " << math(q.reasons[k]) << "</li>\n";
        }
        o << "</ul>\n";
        if (!q.explain.empty()) o << "<p>" << math(q.explain) << "</p>\n";
    } else if (q.kind == QuestionKind::explain) {
        o << paragraphs(q.answer);
    } else {
        o << "<p><span class=\"answer\">" << math(a ? a->text : "?") << "</span>";
        if (!q.explain.empty()) o << "<br>" << math(q.explain);
        o << "</p>\n";
    }
    return o.str();
}

// The question as asked: its text, the tolerance a number is marked to, its options.
std::string question_html(const LessonQuestion& q, std::size_t qi) {
    std::string s = "<p class=\"ask\">" + math(q.text);
    if (shows_tolerance(q))
        s += " <span class=\"tolerance\">(to within " + escape(tolerance_text(q.tolerance)) + ")</span>";
    s += "</p>\n";
    if (q.has_choices()) s += choices_html(q, qi);
    return s;
}

// Printed, a space to write in (choices: the student circles a number instead).
std::string write_space(const LessonQuestion& q) {
    if (q.has_choices()) return "";
    return std::string("<div class=\"write-here") + (q.kind == QuestionKind::explain ? " tall" : "") +
           "\" aria-hidden=\"true\"></div>\n";
}

// An answer that opens on click on screen; printed, only in the teacher's copy.
std::string folded_answer(const LessonQuestion& q, const LessonAnswer* a, const char* summary) {
    const std::string body = answer_html(q, a);
    return std::string("<details><summary>") + summary + "</summary>\n" + body +
           "</details>\n<div class=\"printed-answer\"><p class=\"label\">Answer:</p>\n" + body + "</div>\n";
}

// "Before you watch": the predictions, asked before the figure and the animation show what
// happens; a space to write each (or the options to choose from), no answers.
std::string predict_html(const Lesson& L, const std::vector<std::size_t>& predict) {
    std::ostringstream o;
    o << "<section class=\"predict\" aria-labelledby=\"predict-heading\">\n<h2 id=\"predict-heading\">Before you watch"
         "</h2>\n"
      << kPrintChoice
      << "<p class=\"note\">Predict first: write down or choose what you expect, then look at the figure "
         "and the animation, and check your prediction below them.</p>\n<ol class=\"predictions\">\n";
    for (std::size_t i : predict) {
        const LessonQuestion& q = L.questions[i];
        o << "<li>" << question_html(q, i);
        if (!q.has_choices())
            o << "<p class=\"noprint\"><label>My prediction: <input type=\"text\" class=\"prediction\" size=\"24\">"
                 "</label></p>\n";
        o << write_space(q) << "</li>\n";
    }
    o << "</ol>\n</section>\n";
    return o.str();
}

// "Check your prediction": after the animation, each prediction's answer, folded.
std::string check_html(const Lesson& L, const std::vector<LessonAnswer>& answers,
                       const std::vector<std::size_t>& predict) {
    std::ostringstream o;
    o << "<section class=\"check\">\n<h2>Check your predictions</h2>\n<ol class=\"predictions\">\n";
    for (std::size_t i : predict)
        o << "<li><p class=\"ask\">" << math(L.questions[i].text) << "</p>\n"
          << folded_answer(L.questions[i], i < answers.size() ? &answers[i] : nullptr, "Check your prediction")
          << "</li>\n";
    o << "</ol>\n</section>\n";
    return o.str();
}

// The questions after the worked example: numbers, choices and explanations, each answer
// folded on screen; printed, a space to write in or, ticked, the teacher's copy.
std::string questions_html(const Lesson& L, const std::vector<LessonAnswer>& answers,
                           const std::vector<std::size_t>& asked, bool print_choice) {
    std::ostringstream o;
    o << "<h2>Questions</h2>\n" << (print_choice ? kPrintChoice : "") << "<ol class=\"questions\">\n";
    for (std::size_t i : asked) {
        const LessonQuestion& q = L.questions[i];
        o << "<li class=\"" << question_kind_name(q.kind) << "\">" << question_html(q, i)
          << folded_answer(q, i < answers.size() ? &answers[i] : nullptr, "Answer") << write_space(q) << "</li>\n";
    }
    o << "</ol>\n";
    return o.str();
}

}  // namespace

// The figures' colours (render/style.h) for the panel's canvas, as CSS colours in JSON.
std::string palette_json() {
    const render::Palette c;
    const auto css = [](render::Colour x) {
        char buf[16];
        std::snprintf(buf, sizeof buf, "#%02x%02x%02x", x & 0xFFu, (x >> 8) & 0xFFu, (x >> 16) & 0xFFu);
        return std::string("\"") + buf + "\"";
    };
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
    const notation::StudentNumbers student;  // every number on it: 4 figures, no noise
    const Lesson& L = b.lesson;
    const RenderReport& r = b.report;
    const int d = L.scene.dimension;
    std::ostringstream o;
    o << page_head(L.title, "../");
    o << "<p class=\"section\">Lesson " << L.order << " · " << d << "D"
      << (L.section.empty() ? "" : " · the page's section <em>" + escape(L.section) + "</em>") << "</p>\n";
    o << "<h1>" << math(L.title) << "</h1>\n";
    if (!L.goals.empty()) {
        o << "<h2>Learning goals</h2>\n<ul>\n";
        for (const std::string& g : L.goals) o << "<li>" << math(g) << "</li>\n";
        o << "</ul>\n";
    }
    o << "<h2>Explanation</h2>\n" << paragraphs(L.explanation);
    // The figures: the collision each shows, before, at and after; the first above the
    // animation, the next ones with their worked examples below it.
    const auto figure_html = [&](const RenderReport::Shown& f) {
        std::ostringstream h;
        // Panels side by side are shown up to their own width, beyond the text column when the
        // window allows (style.css, figure.wide), so that their labels stay readable.
        const std::size_t k = static_cast<std::size_t>(&f - r.figures.data());
        const bool wide = k < b.figure_widths.size() && b.figure_widths[k] > kColumnWidth;
        const std::string alt = figure_alt(f.problem, f.solution, f.instant.t);
        const std::string what = f.caption.empty()
                                     ? (&f == &r.figures.front() && L.figures.empty()
                                            ? "Before, at and after the first collision"
                                            : "Before, at and after the collision of " + f.problem.a.name +
                                                  " (a) and " + f.problem.b.name + " (b)")
                                     : f.caption;
        h << "<figure" << (wide ? " class=\"wide\"" : "") << "><a href=\"" << f.file
          << "\" title=\"Open the figure at full size\"><img src=\"" << f.file << "\" alt=\"" << escape(alt)
          << "\"></a><figcaption>" << math(what) << " (t = " << escape(n(f.instant.t)) << " s), from the simulation.";
        if (L.view.directions) h << " Grey arrows: the positive directions (velocities may be negative).";
        h << " Click it to see it at full size.</figcaption></figure>\n";
        return h.str();
    };
    std::vector<std::size_t> predict, asked;
    for (std::size_t i = 0; i < L.questions.size(); ++i)
        (L.questions[i].kind == QuestionKind::predict ? predict : asked).push_back(i);
    // The predictions before the figure: it shows what happens. The print choice goes with the
    // first questions of the page: it decides how every one prints.
    if (!predict.empty()) o << predict_html(L, predict);
    if (!r.figures.empty()) o << figure_html(r.figures.front());
    // The animation is for the screen: a printed page leaves the section out.
    o << "<section class=\"animation noprint\">\n<h2>Animation</h2>\n";
    if (r.video == "animation.mp4") {
        const double fps = r.t.size() > 1 && r.t[1] > r.t[0] ? 1.0 / (r.t[1] - r.t[0]) : 30.0;
        o << "<video class=\"lesson\" controls loop muted playsinline preload=\"metadata\" data-fps=\""
          << notation::num_data(fps) << "\" poster=\"frames/frame_00000.png\" src=\"animation.mp4\"></video>\n"
          << kPlayer;
    } else if (r.video == "animation.gif") {
        o << "<figure><img src=\"animation.gif\" alt=\"The animation of the run\"></figure>\n";
    } else {
        o << "<p class=\"note\">The frames are in <a href=\"frames/frame_00000.png\">frames/</a> (" << r.frames
          << " PNG files); install ffmpeg for a video.</p>\n";
    }
    o << "</section>\n";
    if (!predict.empty()) o << check_html(L, r.answers, predict);
    if (r.problem && r.solution) {
        const SolveProblem& P = *r.problem;
        const Solution& S = *r.solution;
        o << "<h2>"
          << (L.figures.empty() ? std::string("The first collision, worked out")
                                : "The collision of " + escape(P.a.name) + " and " + escape(P.b.name) + ", worked out")
          << "</h2>\n";
        // One notation on the page: our P is the page's J; j its size along n.
        o << "<p class=\"note\">Conventions: body a is " << escape(P.a.name) << " and body b is " << escape(P.b.name)
          << "; the normal n points from a into b; the impulse P (the page writes J) acts as +P on b and −P on a "
             "at the contact point, and j = P · n is its size along n; u = v<sub>pb</sub> − v<sub>pa</sub>; SI "
             "units. Model: "
          << escape(model_name(P.model)) << ".</p>\n";
        o << worked_html(P, S, r.world_note);
        // The lesson's next figures, each with its collision worked out.
        for (std::size_t k = 1; k < r.figures.size(); ++k) {
            const RenderReport::Shown& f = r.figures[k];
            o << "<h2>The collision of " << escape(f.problem.a.name) << " and " << escape(f.problem.b.name)
              << ", worked out</h2>\n"
              << figure_html(f) << worked_html(f.problem, f.solution, f.world_note);
        }
        if (!r.later.empty()) {
            // The run's later collisions, each worked out the same way, folded.
            const std::size_t worked = r.later.size() + r.figures.size();
            o << "<h2>" << (L.figures.empty() ? "The later collisions" : "The other collisions")
              << ", worked out</h2>\n<p class=\"note\">The run has " << r.collision_times.size() << " collisions"
              << (worked < r.collision_times.size() ? "; " + std::to_string(worked) + " are worked out here" : "")
              << ". Open one to see it step by step.</p>\n";
            for (std::size_t i = 0; i < r.later.size(); ++i) {
                const RenderReport::Later& c = r.later[i];
                const int dc = c.problem.dimension;
                o << "<details class=\"later\"><summary>" << escape(c.problem.a.name) << " and "
                  << escape(c.problem.b.name) << " at t = " << escape(sig3(c.instant.t)) << " s, impulse on "
                  << escape(c.problem.b.name) << " "
                  << escape(dc == 1 ? sig3(c.solution.P.x()) : sig3(c.solution.P.norm())) << " N s</summary>\n";
                o << worked_html(c.problem, c.solution, c.world_note) << "</details>\n";
            }
        }
        // The table: the two bodies before and after.
        o << "<h2>Before and after</h2>\n<table>\n<tr><th>body</th><th>m (kg)</th><th>v before (m/s)</th>"
             "<th>v after (m/s)</th>";
        if (d > 1) o << "<th>ω before (rad/s)</th><th>ω after (rad/s)</th>";
        o << "</tr>\n";
        const auto row = [&](const SolveBody& B, const Vec3& v, const Vec3& w) {
            o << "<tr><td>" << escape(B.name) << "</td><td>" << (B.b3.is_static ? "static" : escape(n(B.b3.mass)))
              << "</td><td>" << escape(vec(B.b3.v, d)) << "</td><td>" << escape(vec(v, d)) << "</td>";
            if (d > 1) o << "<td>" << escape(spin(B.b3.w, d)) << "</td><td>" << escape(spin(w, d)) << "</td>";
            o << "</tr>\n";
        };
        row(P.a, S.va, S.wa);
        row(P.b, S.vb, S.wb);
        o << "</table>\n<table>\n<tr><th>totals</th><th>before</th><th>after</th></tr>\n"
          << "<tr><td>momentum (kg m/s)</td><td>" << escape(vec(S.p_before, d)) << "</td><td>"
          << escape(vec(S.p_after, d)) << "</td></tr>\n";
        if (d > 1)
            o << "<tr><td>angular momentum about the origin (kg m²/s)</td><td>" << escape(spin(S.L_before, d))
              << "</td><td>" << escape(spin(S.L_after, d)) << "</td></tr>\n";
        o << "<tr><td>kinetic energy (J)</td><td>" << escape(n(S.ke_before)) << "</td><td>" << escape(n(S.ke_after))
          << "</td></tr>\n</table>\n";
    }
    if (!r.variants.empty()) {
        o << "<h2>Side by side</h2>\n<figure" << (b.variants_width > kColumnWidth ? " class=\"wide\"" : "")
          << "><a href=\"variants.png\" title=\"Open the figure at full size\"><img src=\"variants.png\" "
             "alt=\"The scene and its variants, before, at and after the collision\"></a></figure>\n<table>\n<tr><th></th><th>impulse on b (N s)</th>"
             "<th>a after (m/s)</th><th>b after (m/s)</th><th>kinetic energy lost (J)</th></tr>\n";
        for (const RenderReport::Variant& v : r.variants) {
            if (!v.first) {
                o << "<tr><td>" << math(v.label) << "</td><td colspan=\"4\">no collision</td></tr>\n";
                continue;
            }
            const CollisionInstant& c = *v.first;
            o << "<tr><td>" << math(v.label) << " (" << escape(L.scene.bodies[c.a].name) << " on "
              << escape(L.scene.bodies[c.b].name) << ")</td><td>" << escape(vec(c.impulse, d)) << "</td><td>"
              << escape(vec(c.va_after, d)) << "</td><td>" << escape(vec(c.vb_after, d)) << "</td><td>"
              << escape(energy_lost_text(v.ke_before, v.ke_after)) << "</td></tr>\n";
        }
        o << "</table>\n";
    }
    if (b.try_it) {
        const double fps = r.t.size() > 1 && r.t[1] > r.t[0] ? 1.0 / (r.t[1] - r.t[0]) : 30.0;
        o << html::try_it_html(L, fps, "../");
    }
    if (r.penalty) o << penalty_html(*r.penalty);
    if (!L.teacher_notes.empty())
        o << "<section class=\"teacher\">\n<h2>For the teacher</h2>\n" << paragraphs(L.teacher_notes) << "</section>\n";
    o << "<h2>Energy and momentum against time</h2>\n<div class=\"plots\">"
         "<img src=\"energy.svg\" alt=\"Energy against time\"><img src=\"momentum.svg\" alt=\"Momentum against time\"></div>\n"
         "<p class=\"note\">Red lines: the collisions. Data: <a href=\"data.csv\">data.csv</a>, "
         "<a href=\"data.json\">data.json</a>, <a href=\"events.csv\">events.csv</a>.</p>\n";
    if (!asked.empty()) o << questions_html(L, r.answers, asked, predict.empty());
    o << "<nav class=\"pager\">";
    o << (prev ? "<a href=\"../" + prev->lesson.id + "/index.html\">← " + math(prev->lesson.title) + "</a>"
               : "<span></span>");
    o << "<a href=\"../index.html\">All lessons</a>";
    o << (next ? "<a href=\"../" + next->lesson.id + "/index.html\">" + math(next->lesson.title) + " →</a>"
               : "<span></span>");
    o << "</nav>\n" << kPageTail;
    return o.str();
}

std::string index_page(const std::vector<SitePage>& all) {
    std::ostringstream o;
    o << page_head("Collide: lessons", "");
    o << "<h1>Collisions with rotation: lessons</h1>\n<p>Each lesson is a simulation you can trust: "
         "the exact instant of contact, the impulse from the page's formulas, and the checks "
         "(momentum, angular momentum, energy). Open one for its explanation, figure, animation, "
         "worked example, plots and questions.</p>\n<ul class=\"grid\">\n";
    for (const SitePage& b : all) {
        const Lesson& L = b.lesson;
        o << "<li class=\"card\"><a href=\"" << L.id << "/index.html\">";
        if (b.thumb) o << "<img src=\"" << L.id << "/thumb.png\" alt=\"\">";
        o << "<div class=\"text\"><div class=\"num\">Lesson " << L.order << " · " << L.scene.dimension << "D"
          << (L.section.empty() ? "" : " · " + escape(L.section)) << "</div><h2>" << math(L.title)
          << "</h2></div></a></li>\n";
    }
    o << "</ul>\n" << kPageTail;
    return o.str();
}

}  // namespace collide
