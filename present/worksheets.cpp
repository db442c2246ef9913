#include "present/worksheets.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "render/video.h"
#include "scenario/toml_reader.h"
#include "teach/html.h"
#include "engine/math.h"  // kPi
#include "teach/notation.h"
#include "present/worksheet_figure.h"

namespace collide {

namespace fs = std::filesystem;

namespace {

using html::escape;
using html::math;

// ---- Numbers ----

// A number as given to a student: up to 6 significant digits, "-0" as "0", a true minus.
std::string given(double x) { return notation::true_minus(notation::num_text(std::abs(x) < 1e-12 ? 0.0 : x)); }

// An answer in the key: 4 significant figures, a true minus.
std::string sig4(double x) { return notation::sig_text(x, 4); }

std::string vec_text(const Vec3& v, int dim) { return notation::components_text(v, dim, given); }

// A 2D body's angle in degrees (4 figures), with the radians the lesson file gives after it:
// "34.38° (0.6 rad)"; 0 alone.
std::string angle_text(double rad) {
    if (std::abs(rad) < 1e-12) return "0";
    return notation::true_minus(notation::sig_text(rad * 180.0 / kPi, 4)) + "\u00b0 (" + given(rad) + " rad)";
}

// A key answer: the number or vector to 4 significant figures, with its unit.
std::string answer_text(const LessonAnswer& a, int dim) {
    std::string s;
    if (a.is_vector)
        s = "(" + sig4(a.vector.x()) + ", " + sig4(a.vector.y()) + (dim == 3 ? ", " + sig4(a.vector.z()) : "") + ")";
    else s = sig4(a.value);
    return a.unit.empty() ? s : s + " " + a.unit;
}

// ---- Pages ----

// Self-contained pages (a PDF converter needs no other file), written for paper: A4, one
// sheet per page, blanks tall enough to write in by hand.
const char* kStyle = R"(<style>
@page { size: A4; margin: 12mm 15mm; }
body { font-family: "DejaVu Sans", Arial, sans-serif; font-size: 10pt; line-height: 1.3; color: #111; max-width: 180mm; margin: 0 auto; }
.sheet { break-after: page; page-break-after: always; }
.sheet:last-of-type { break-after: auto; page-break-after: auto; }
h1 { font-size: 15pt; margin: 0 0 1mm; }
h2 { font-size: 11pt; margin: 4mm 0 1.5mm; border-bottom: 1px solid #999; }
h3 { font-size: 10pt; margin: 2.5mm 0 1mm; }
.student { font-weight: bold; font-size: 11pt; margin: 1mm 0; }
.fill { display: inline-block; width: 75mm; border-bottom: 1px solid #000; margin-right: 8mm; }
table { border-collapse: collapse; margin: 1.5mm 0; }
th, td { border: 1px solid #888; padding: 0.8mm 2mm; text-align: left; }
th { background: #eee; }
.q { margin: 3mm 0; break-inside: avoid; page-break-inside: avoid; }
.q .ask { margin: 0 0 1mm; }
.tolerance { color: #444; font-size: 9pt; }
.work { height: 9mm; }
.fill.short { width: 35mm; }
.blank { margin: 0; }
.line { display: inline-block; width: 55mm; border-bottom: 1px solid #000; margin: 0 2mm; }
.tall { height: 28mm; border-bottom: 1px solid #000; }
ul.choices { list-style: none; padding-left: 4mm; margin: 1mm 0; }
.math { white-space: normal; overflow-wrap: anywhere; font-family: "DejaVu Serif", serif; margin: 1mm 0 1mm 4mm; }
.math.result { font-weight: bold; }
.note { color: #444; font-size: 9pt; margin: 1mm 0; }
.answer { font-weight: bold; }
.setup { display: flex; align-items: flex-start; gap: 4mm; margin: 2mm 0 0; break-inside: avoid; page-break-inside: avoid; }
.setup svg { flex: none; }
.setup .legend { margin: 0; }
@media screen { body { padding: 8mm; } .sheet { border-bottom: 2px dashed #bbb; padding-bottom: 8mm; margin-bottom: 8mm; } }
</style>
)";

std::string page_head(const std::string& title) {
    return "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + escape(title) +
           "</title>\n" + kStyle + "</head>\n<body>\n";
}
const char* kPageTail = "</body>\n</html>\n";

// A body's size as its file gives it: a block's length, a disc's or sphere's radius, a
// rectangle's or box's sides.
std::string size_text(const toml::table& body) {
    if (const auto x = body["length"].value<double>()) return "length " + given(*x) + " m";
    if (const auto x = body["radius"].value<double>()) return "radius " + given(*x) + " m";
    if (const toml::array* a = body["size"].as_array()) {
        std::string s;
        for (const toml::node& n : *a) s += (s.empty() ? "" : " \u00d7 ") + given(n.value<double>().value_or(0.0));
        return s + " m";
    }
    return "";
}

}  // namespace

// The givens: a table of the bodies with this student's numbers, then the scene's settings.
std::string worksheet_givens_html(const Lesson& L) {
    const Scene& sc = L.scene;
    const int d = sc.dimension;
    const toml::table file = parse_toml_text(L.source, L.source_name);
    const toml::array* bodies = file["body"].as_array();
    std::ostringstream o;
    o << "<table class=\"givens\">\n<tr><th>body</th><th>shape</th><th>mass (kg)</th><th>position (m)</th>";
    if (d == 2) o << "<th>angle</th>";
    o << "<th>velocity (m/s)</th>";
    if (d > 1) o << "<th>spin \u03c9 (rad/s)</th>";
    o << "<th>size</th></tr>\n";
    for (std::size_t i = 0; i < sc.bodies.size(); ++i) {
        const SceneBody& b = sc.bodies[i];
        const bool fixed = b.is_static();
        o << "<tr><td>" << escape(b.name) << "</td><td>" << escape(b.shape) << "</td><td>";
        if (d == 1) {
            o << (fixed ? "fixed" : given(b.body1.mass)) << "</td><td>" << given(b.body1.position) << "</td><td>"
              << given(b.body1.v);
        } else if (d == 2) {
            o << (fixed ? "fixed" : given(b.body2.mass)) << "</td><td>" << vec_text(lift(b.body2.position), 2)
              << "</td><td>" << angle_text(b.body2.angle) << "</td><td>" << vec_text(lift(b.body2.v), 2) << "</td><td>"
              << given(b.body2.w);
        } else {
            o << (fixed ? "fixed" : given(b.body3.mass)) << "</td><td>" << vec_text(b.body3.position, 3) << "</td><td>"
              << vec_text(b.body3.v, 3) << "</td><td>" << vec_text(b.body3.w, 3);
        }
        const toml::table* t = bodies && i < bodies->size() ? bodies->get(i)->as_table() : nullptr;
        o << "</td><td>" << (t ? size_text(*t) : "") << "</td></tr>\n";
    }
    o << "</table>\n<p>Coefficient of restitution e = " << given(sc.restitution)
      << "; friction coefficient \u03bc = " << given(sc.friction);
    for (const SceneBody& b : sc.bodies) {
        if (b.restitution) o << "; " << escape(b.name) << "'s own e = " << given(*b.restitution);
        if (b.friction) o << "; " << escape(b.name) << "'s own \u03bc = " << given(*b.friction);
    }
    o << ".";
    if (sc.gravity.norm() > 0) o << " Gravity g = " << vec_text(sc.gravity, d) << " m/s\u00b2.";
    else o << " No gravity.";
    if (d > 1) o << " Angles and spins are counter-clockwise positive.";
    o << "</p>\n";
    return o.str();
}

namespace {

// A question as the student sees it: number, text, tolerance; a blank with the unit, room
// to work, or the options to circle.
std::string sheet_question(const Lesson& L, std::size_t i, const LessonAnswer& a, double work_mm) {
    const LessonQuestion& q = L.questions[i];
    std::ostringstream o;
    o << "<div class=\"q\"><p class=\"ask\"><b>" << question_number(L, i) << ".</b> " << math(q.text);
    if (shows_tolerance(q))
        o << " <span class=\"tolerance\">(to within " << escape(tolerance_text(q.tolerance)) << ")</span>";
    o << "</p>\n";
    if (q.has_choices()) {
        o << "<p class=\"note\">Circle one number.</p>\n<ul class=\"choices\">\n";
        for (std::size_t k = 0; k < q.choices.size(); ++k)
            o << "<li>(" << option_number(k) << ") " << math(q.choices[k]) << "</li>\n";
        o << "</ul>\n";
    } else if (q.has_quantity()) {
        char style[48];
        std::snprintf(style, sizeof style, " style=\"height: %.0fmm\"", work_mm);
        o << "<div class=\"work\"" << style << "></div>\n<p class=\"blank\">Answer:<span class=\"line\"></span>"
          << math(a.unit) << "</p>\n";
    } else {
        o << "<div class=\"tall\"></div>\n";
    }
    o << "</div>\n";
    return o.str();
}

constexpr double kFigureGapMm = 6.0;  // the figure's margins on the page

// The room to work each numeric question gets (mm): the page's space for questions shared
// out, so that a sheet of few questions has room to write and one of many still fits on its
// page. Measured on A4 PDFs (weasyprint): about 180 mm below the givens, 17 mm for a numeric
// question's text and answer line, 30 mm for a choice or explain question.
// `figure_mm`: the height a 2D sheet's figure of the set-up takes (0 without one).
constexpr double kQuestionsRoom = 180.0, kNumericMm = 17.0, kOtherMm = 30.0, kWorkMin = 8.0;
double work_height(const Lesson& L, const std::vector<std::size_t>& asked, double figure_mm) {
    int numeric = 0, other = 0;
    for (std::size_t i : asked) (L.questions[i].has_quantity() ? numeric : other)++;
    if (numeric == 0) return 0.0;
    const double room = (kQuestionsRoom - figure_mm - kOtherMm * other - kNumericMm * numeric) / numeric;
    return std::clamp(room, kWorkMin, 35.0);
}

// A 2D sheet's figure is at most kFigureMm tall (its labels readable in print). It takes its
// height from the questions' room when the sheet still fits on one page with at least
// kWorkMin to work each numeric question; else the sheet runs onto a second page (the figure
// and each question are never split) and the questions keep the room they have without it.
constexpr double kFigureMm = 70.0;
double sheet_work_height(const Lesson& L, const std::vector<std::size_t>& asked, double figure_mm) {
    int numeric = 0, other = 0;
    for (std::size_t i : asked) (L.questions[i].has_quantity() ? numeric : other)++;
    const bool fits = kQuestionsRoom - figure_mm - kOtherMm * other - (kNumericMm + kWorkMin) * numeric >= 0;
    return work_height(L, asked, fits ? figure_mm : 0.0);
}

// A 2D sheet's figure of this student's set-up, and beside it what its marks mean.
std::string figure_html(const StudentSheet& s, const WorksheetFigure& f) {
    const Scene& sc = s.lesson.scene;
    std::ostringstream o;
    o << "<div class=\"setup\">\n" << f.svg << "<p class=\"note legend\">Your set-up at the start, to scale. ";
    // Dashed bodies: as the figure draws them.
    if (f.svg.find("data-body-at-hit=") != std::string::npos) o << "Dashed: where the bodies are when they collide. ";
    const bool several = s.worked.size() > 1;
    for (const WorkedCollision& w : s.worked) {
        const std::string k = several ? "<sub>" + std::to_string(w.event) + "</sub>" : "";
        o << (several ? "Collision " + std::to_string(w.event) + ": " : std::string()) << "p" << k
          << ", the contact point; n" << k << ", the unit normal from " << escape(sc.bodies[w.a].name) << " (a) into "
          << escape(sc.bodies[w.b].name) << " (b); ";
        const std::string ek = several ? std::to_string(w.event) : "";
        std::string rs;  // a half-plane (ground, wall) has no centre: no r
        if (sc.bodies[w.a].shape2.kind != Shape2::Kind::half_plane) rs = "r<sub>a" + ek + "</sub>";
        if (sc.bodies[w.b].shape2.kind != Shape2::Kind::half_plane)
            rs += (rs.empty() ? "" : ", ") + std::string("r<sub>b") + ek + "</sub>";
        if (!rs.empty()) o << rs << ": from the body's centre to p" << k << ". ";
    }
    o << "v: the velocities at the start (one scale for all); \u03c9: the spins (counter-clockwise positive).</p>\n"
      << "</div>\n";
    return o.str();
}

std::string sheets_page(const Lesson& L, const std::vector<StudentSheet>& sheets) {
    std::ostringstream o;
    o << page_head(L.title + ": worksheets");
    for (const StudentSheet& s : sheets) {
        o << "<section class=\"sheet\">\n<h1>" << math(L.title) << "</h1>\n<p class=\"student\">Student " << s.student
          << "</p>\n<p>Name: <span class=\"fill\"></span> Class: <span class=\"fill short\"></span></p>\n<h2>Given</h2>\n"
          << worksheet_givens_html(s.lesson);
        const WorksheetFigure f = worksheet_figure(s, kFigureMm, L.id + "-" + std::to_string(s.student));
        if (!f.svg.empty()) o << figure_html(s, f);
        o << "<h2>Questions</h2>\n<p class=\"note\">Use the numbers above; give each answer with its sign and unit.</p>\n";
        const double work = sheet_work_height(L, s.asked, f.svg.empty() ? 0.0 : f.height_mm + kFigureGapMm);
        for (std::size_t k = 0; k < s.asked.size(); ++k) o << sheet_question(L, s.asked[k], s.answers[k], work);
        o << "</section>\n";
    }
    o << kPageTail;
    return o.str();
}

// A question's answer in the key: the engine's number, or the right option with its
// reasons, or the model answer.
std::string key_answer(const Lesson& L, std::size_t i, const LessonAnswer& a) {
    const LessonQuestion& q = L.questions[i];
    std::ostringstream o;
    o << "<div class=\"q\"><p class=\"ask\"><b>" << question_number(L, i) << ".</b> " << math(q.text) << "</p>\n";
    if (q.has_quantity()) {
        o << "<p><span class=\"answer\">" << math(answer_text(a, L.scene.dimension)) << "</span>";
        if (shows_tolerance(q))
            o << " <span class=\"tolerance\">(right within " << escape(tolerance_text(q.tolerance)) << ")</span>";
        o << "</p>\n";
    } else if (q.has_choices()) {
        o << "<p><span class=\"answer\">Option " << option_number(static_cast<std::size_t>(q.correct - 1))
          << ".</span></p>\n<ul>\n";
        for (std::size_t k = 0; k < q.choices.size(); ++k)
            o << "<li>(" << option_number(k) << ") " << (static_cast<int>(k) + 1 == q.correct ? "Right: " : "Wrong: ")
              << math(q.reasons[k]) << "</li>\n";
        o << "</ul>\n";
    } else {
        o << html::paragraphs(q.answer);
    }
    o << "</div>\n";
    return o.str();
}

std::string key_page(const Lesson& L, const std::vector<StudentSheet>& sheets, std::uint64_t seed) {
    std::ostringstream o;
    o << page_head(L.title + ": answer key");
    for (const StudentSheet& s : sheets) {
        o << "<section class=\"sheet\">\n<h1>" << math(L.title) << ": answer key</h1>\n<p class=\"student\">Student "
          << s.student << "</p>\n<p class=\"note\">Lesson " << escape(L.id) << ", seed " << seed << ".</p>\n";
        if (!s.values.empty()) {
            o << "<h2>This student's values</h2>\n<table>\n";
            for (const auto& [key, value] : s.values)
                o << "<tr><td>" << escape(key) << "</td><td>" << given(value) << "</td></tr>\n";
            o << "</table>\n";
        } else {
            o << "<p class=\"note\">This lesson declares no [[vary]] ranges: every student has the lesson's own "
                 "numbers.</p>\n";
        }
        o << "<h2>Answers</h2>\n";
        for (std::size_t k = 0; k < s.asked.size(); ++k) o << key_answer(L, s.asked[k], s.answers[k]);
        for (const WorkedCollision& w : s.worked) {
            o << "<h2>Collision " << w.event << " (" << escape(w.problem.a.name) << " and " << escape(w.problem.b.name)
              << "), worked out</h2>\n<p class=\"note\">The normal n points from " << escape(w.problem.a.name)
              << " into " << escape(w.problem.b.name) << "; the impulse P acts as +P on " << escape(w.problem.b.name)
              << " and \u2212P on " << escape(w.problem.a.name) << "; SI units.</p>\n"
              << html::worked_html(w.problem, w.solution, "");
        }
        o << "</section>\n";
    }
    o << kPageTail;
    return o.str();
}

// key.json (docs/commands/worksheet.md): the values drawn and the engine's answers at full precision.
std::string key_json(const Lesson& L, const std::vector<StudentSheet>& sheets, std::uint64_t seed) {
    nlohmann::ordered_json students = nlohmann::ordered_json::array();
    for (const StudentSheet& s : sheets) {
        nlohmann::ordered_json values = nlohmann::ordered_json::object();
        for (const auto& [key, value] : s.values) values[key] = value;
        nlohmann::ordered_json answers = nlohmann::ordered_json::array();
        for (std::size_t k = 0; k < s.asked.size(); ++k) {
            const LessonQuestion& q = L.questions[s.asked[k]];
            if (!q.has_quantity()) continue;
            const LessonAnswer& a = s.answers[k];
            nlohmann::ordered_json value;
            if (a.is_vector) {
                value = nlohmann::ordered_json::array({a.vector.x(), a.vector.y()});
                if (L.scene.dimension == 3) value.push_back(a.vector.z());
            } else {
                value = a.value;
            }
            answers.push_back({{"question", question_number(L, s.asked[k])},
                               {"text", q.text},
                               {"quantity", quantity_name(*q.quantity)},
                               {"value", value},
                               {"unit", a.unit},
                               {"tolerance", q.tolerance}});
        }
        nlohmann::ordered_json student = {{"student", s.student}, {"values", values}};
        // e, when one e holds for every collision (no body has its own): `collide grade`
        // names the impulse without (1 + e) from it.
        const Scene& sc = s.lesson.scene;
        if (std::none_of(sc.bodies.begin(), sc.bodies.end(),
                         [](const SceneBody& b) { return b.restitution.has_value(); }))
            student["restitution"] = sc.restitution;
        student["answers"] = answers;
        students.push_back(student);
    }
    const nlohmann::ordered_json doc = {{"lesson", L.id}, {"seed", seed}, {"students", students}};
    return doc.dump(2) + "\n";
}

void write_file(const fs::path& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary);
    f << text;
    if (!f.flush()) throw std::runtime_error(path.string() + ": cannot write");
}

// `weasyprint IN.html OUT.pdf`, its messages in a log kept only when it fails.
void to_pdf(const std::string& weasyprint, const fs::path& html_file, const fs::path& pdf, const StopRequested& stop) {
    const std::string log = pdf.string() + ".log";
    const render::ProgramRun run =
        render::run_program({weasyprint, "--quiet", html_file.string(), pdf.string()}, log, stop);
    if (run.stopped) throw Interrupted(0);
    if (!run.ok()) {
        std::ifstream in(log);
        std::string first;
        std::getline(in, first);
        throw std::runtime_error(pdf.string() + ": weasyprint failed" + (first.empty() ? "" : ": " + first));
    }
    std::error_code ec;
    fs::remove(log, ec);
}

std::string index_page(const std::vector<Lesson>& lessons, int students, bool html) {
    std::ostringstream o;
    o << page_head("Worksheets") << "<h1>Worksheets</h1>\n<p>" << students << " students each.</p>\n<ul>\n";
    for (const Lesson& L : lessons) {
        o << "<li>" << math(L.title) << ": ";
        if (html)
            o << "<a href=\"" << escape(L.id) << "/sheets.html\">sheets</a>, <a href=\"" << escape(L.id)
              << "/key.html\">answer key</a>, ";
        o << "<a href=\"" << escape(L.id) << "/key.json\">key.json</a></li>\n";
    }
    o << "</ul>\n" << kPageTail;
    return o.str();
}

}  // namespace

std::vector<std::string> write_worksheets(const Lesson& L, const std::vector<StudentSheet>& sheets, std::uint64_t seed,
                                          const fs::path& dir, const std::string& weasyprint, const StopRequested& stop,
                                          bool html) {
    fs::create_directories(dir);
    if (!html) {
        write_file(dir / "key.json", key_json(L, sheets, seed));
        return {"key.json"};
    }
    write_file(dir / "sheets.html", sheets_page(L, sheets));
    write_file(dir / "key.html", key_page(L, sheets, seed));
    write_file(dir / "key.json", key_json(L, sheets, seed));
    std::vector<std::string> files = {"sheets.html", "key.html", "key.json"};
    if (!weasyprint.empty()) {
        to_pdf(weasyprint, dir / "sheets.html", dir / "sheets.pdf", stop);
        to_pdf(weasyprint, dir / "key.html", dir / "key.pdf", stop);
        files.insert(files.end(), {"sheets.pdf", "key.pdf"});
    }
    return files;
}

void write_worksheet_index(const fs::path& dir, const std::vector<Lesson>& lessons, int students, bool html) {
    write_file(dir / "index.html", index_page(lessons, students, html));
}

void write_text_file(const fs::path& path, const std::string& text) { write_file(path, text); }

}  // namespace collide
