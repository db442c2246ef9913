#include "present/platform_questions.h"

#include <cmath>
#include <cstdio>

#include "present/worksheet_figure.h"
#include "present/worksheets.h"
#include "teach/answers.h"
#include "teach/html.h"

namespace collide {

namespace {

using html::escape;
using html::math;

// The figure in the question: at most this tall on the screen (mm at 96 dpi, as printed).
constexpr double kPlatformFigureMm = 80.0;

int px(double mm) { return static_cast<int>(mm * 96.0 / 25.4 + 0.5); }

// The worked example of each collision the sheet asks about.
std::string worked_feedback(const StudentSheet& s) {
    std::string o;
    for (const WorkedCollision& w : s.worked)
        o += "<h4>Collision " + std::to_string(w.event) + " (" + escape(w.problem.a.name) + " and " +
             escape(w.problem.b.name) + "), worked out</h4>\n<p>The normal n points from " + escape(w.problem.a.name) +
             " into " + escape(w.problem.b.name) + "; the impulse P acts as +P on " + escape(w.problem.b.name) +
             " and \u2212P on " + escape(w.problem.a.name) + "; SI units.</p>\n" +
             html::worked_html(w.problem, w.solution, "");
    return o;
}

PlatformQuestion question(const Lesson& L, const StudentSheet& s, std::size_t k) {
    const std::size_t i = s.asked[k];
    const LessonQuestion& q = L.questions[i];
    const LessonAnswer& a = s.answers[k];
    PlatformQuestion p;
    p.number = question_number(L, i);
    char nm[200];
    std::snprintf(nm, sizeof nm, "%s: question %d, student %03d", L.id.c_str(), p.number, s.student);
    p.name = nm;
    p.id = "collide-" + L.id + "-q" + std::to_string(p.number) + "-s" + std::to_string(s.student);
    p.ask_html = "<h4>Question " + std::to_string(p.number) + "</h4>\n<p>" + math(q.text);
    if (shows_tolerance(q)) p.ask_html += " <small>(to within " + escape(tolerance_text(q.tolerance)) + ")</small>";
    p.ask_html += "</p>\n";
    if (q.has_quantity()) {
        p.unit = a.unit;
        if (a.is_vector) {
            p.kind = PlatformKind::vector;
            for (int c = 0; c < (L.scene.dimension == 3 ? 3 : 2); ++c) p.want.push_back(a.vector[c]);
            p.allowance = marking_allowance(a.vector.norm(), q.tolerance);
        } else {
            p.kind = PlatformKind::number;
            p.want = {a.value};
            p.allowance = marking_allowance(a.value, q.tolerance);
        }
    } else if (q.has_choices()) {
        p.kind = PlatformKind::choice;
        for (std::size_t c = 0; c < q.choices.size(); ++c) {
            p.choices.push_back(math(q.choices[c]));
            p.reasons.push_back(math(q.reasons[c]));
        }
        p.correct = static_cast<std::size_t>(q.correct - 1);
    } else {
        p.kind = PlatformKind::explain;
        p.model_answer = html::paragraphs(q.answer);
    }
    return p;
}

}  // namespace

std::string xml_text(const std::string& s) {
    std::string out;
    for (const char c : escape(s)) out += c == '\'' ? std::string("&apos;") : std::string(1, c);
    return out;
}

std::string full_number(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", std::abs(x) < 1e-300 ? 0.0 : x);
    return buf;
}

PlatformSheet platform_sheet(const Lesson& L, const StudentSheet& s) {
    PlatformSheet p;
    p.student = s.student;
    p.intro_html = "<p><b>Student " + std::to_string(s.student) + "</b>: your own numbers.</p>\n<h4>Given</h4>\n" +
                   worksheet_givens_html(s.lesson);
    const WorksheetFigure f = worksheet_figure(s, kPlatformFigureMm, L.id + "-" + std::to_string(s.student));
    if (!f.svg.empty())
        p.figure =
            PlatformFigure{L.id + "-student-" + std::to_string(s.student) + ".svg",
                           "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + f.svg, px(f.width_mm), px(f.height_mm)};
    p.worked_html = worked_feedback(s);
    for (std::size_t k = 0; k < s.asked.size(); ++k) p.questions.push_back(question(L, s, k));
    return p;
}

std::string platform_figure_html(const PlatformFigure& f, const std::string& src) {
    return "<p><img src=\"" + escape(src) + "\" alt=\"Your set-up at the start, to scale\" width=\"" +
           std::to_string(f.width_px) + "\" height=\"" + std::to_string(f.height_px) +
           "\"></p>\n<p><small>Your set-up at the start, to scale (dashed: where the bodies collide; n: the "
           "unit normal from a into b; p: the contact point).</small></p>\n";
}

}  // namespace collide
