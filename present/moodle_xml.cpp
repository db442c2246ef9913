#include "present/moodle_xml.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "present/worksheet_figure.h"
#include "present/worksheets.h"
#include "teach/answers.h"
#include "teach/html.h"
#include "teach/units.h"

namespace collide {

namespace {

using html::escape;
using html::math;

// The figure in the question: at most this tall on the screen (mm at 96 dpi, as printed).
constexpr double kMoodleFigureMm = 80.0;

// Text in an XML element (the same escapes as HTML's, and ' for attributes).
std::string xml(const std::string& s) {
    std::string out;
    for (const char c : escape(s)) out += c == '\'' ? std::string("&apos;") : std::string(1, c);
    return out;
}

// HTML in CDATA: a "]]>" inside is split over two sections.
std::string cdata(const std::string& s) {
    std::string out = "<![CDATA[";
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s.compare(i, 3, "]]>") == 0) {
            out += "]]]]><![CDATA[>";
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out + "]]>";
}

// A number at full precision (17 significant digits): Moodle compares with it.
std::string full(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", std::abs(x) < 1e-300 ? 0.0 : x);
    return buf;
}

std::string base64(const std::string& in) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        const unsigned v = (static_cast<unsigned char>(in[i]) << 16) | (static_cast<unsigned char>(in[i + 1]) << 8) |
                           static_cast<unsigned char>(in[i + 2]);
        out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], t[v & 63]};
    }
    if (i + 1 == in.size()) {
        const unsigned v = static_cast<unsigned char>(in[i]) << 16;
        out += {t[v >> 18], t[(v >> 12) & 63], '=', '='};
    } else if (i + 2 == in.size()) {
        const unsigned v = (static_cast<unsigned char>(in[i]) << 16) | (static_cast<unsigned char>(in[i + 1]) << 8);
        out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], '='};
    }
    return out;
}

// A category path's segment: Moodle reads "/" as the separator and "//" as a slash.
std::string segment(const std::string& name) {
    std::string out;
    for (const char c : name) out += c == '/' ? std::string("//") : std::string(1, c);
    return out;
}

std::string category(const std::string& path) {
    return "<question type=\"category\">\n<category><text>" + xml(path) +
           "</text></category>\n<info format=\"html\"><text></text></info>\n</question>\n";
}

// What every question of a student's sheet shows first: the givens and the figure.
struct StudentPart {
    std::string html;  // the givens, the figure's <img>
    std::string file;  // the figure's <file> element, or ""
};

StudentPart student_part(const Lesson& L, const StudentSheet& s) {
    StudentPart p;
    p.html = "<p><b>Student " + std::to_string(s.student) + "</b>: your own numbers.</p>\n<h4>Given</h4>\n" +
             worksheet_givens_html(s.lesson);
    const WorksheetFigure f = worksheet_figure(s, kMoodleFigureMm, L.id + "-" + std::to_string(s.student));
    if (!f.svg.empty()) {
        const std::string name = L.id + "-student-" + std::to_string(s.student) + ".svg";
        char size[80];
        std::snprintf(size, sizeof size, " width=\"%.0f\" height=\"%.0f\"", f.width_mm * 96.0 / 25.4,
                      f.height_mm * 96.0 / 25.4);
        p.html += "<p><img src=\"@@PLUGINFILE@@/" + name + "\" alt=\"Your set-up at the start, to scale\"" + size +
                  "></p>\n<p><small>Your set-up at the start, to scale (dashed: where the bodies collide; n: the "
                  "unit normal from a into b; p: the contact point).</small></p>\n";
        p.file = "<file name=\"" + xml(name) + "\" path=\"/\" encoding=\"base64\">" +
                 base64("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + f.svg) + "</file>\n";
    }
    return p;
}

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

std::string common_head(const std::string& type, const std::string& name, const std::string& text,
                        const std::string& file, const std::string& feedback, const std::string& idnumber) {
    return "<question type=\"" + type + "\">\n<name><text>" + xml(name) +
           "</text></name>\n<questiontext format=\"html\"><text>" + cdata(text) + "</text>\n" + file +
           "</questiontext>\n<generalfeedback format=\"html\"><text>" + cdata(feedback) +
           "</text></generalfeedback>\n<defaultgrade>1</defaultgrade>\n<penalty>0.3333333</penalty>\n<hidden>0</hidden>\n"
           "<idnumber>" +
           xml(idnumber) + "</idnumber>\n";
}

std::string question_xml(const Lesson& L, const StudentSheet& s, std::size_t k, const StudentPart& part,
                         const std::string& feedback) {
    const std::size_t i = s.asked[k];
    const LessonQuestion& q = L.questions[i];
    const LessonAnswer& a = s.answers[k];
    const int number = question_number(L, i);
    char nm[200];
    std::snprintf(nm, sizeof nm, "%s: question %d, student %03d", L.id.c_str(), number, s.student);
    const std::string id = "collide-" + L.id + "-q" + std::to_string(number) + "-s" + std::to_string(s.student);
    std::string ask = "<h4>Question " + std::to_string(number) + "</h4>\n<p>" + math(q.text);
    if (shows_tolerance(q)) ask += " <small>(to within " + escape(tolerance_text(q.tolerance)) + ")</small>";
    ask += "</p>\n";
    std::ostringstream o;
    if (q.has_quantity() && !a.is_vector) {
        o << common_head("numerical", nm,
                         part.html + ask + "<p>Give the number and its unit (" + escape(a.unit) + ").</p>\n", part.file,
                         feedback, id)
          << "<answer fraction=\"100\" format=\"moodle_auto_format\">\n<text>" << full(a.value)
          << "</text>\n<feedback format=\"html\"><text></text></feedback>\n<tolerance>"
          << full(marking_allowance(a.value, q.tolerance)) << "</tolerance>\n</answer>\n"
          << "<unitgradingtype>0</unitgradingtype>\n<unitpenalty>0.1000000</unitpenalty>\n"
          << "<showunits>" << (a.unit.empty() ? 3 : 0) << "</showunits>\n<unitsleft>0</unitsleft>\n";
        if (!a.unit.empty()) {
            o << "<units>\n";
            for (const AcceptedUnit& u : accepted_units(a.unit))
                o << "<unit><multiplier>" << full(1.0 / u.factor) << "</multiplier><unit_name>" << xml(u.name)
                  << "</unit_name></unit>\n";
            o << "</units>\n";
        }
    } else if (q.has_quantity()) {
        // Moodle's numerical question holds one number: a vector is a cloze of its components.
        const int n = L.scene.dimension == 3 ? 3 : 2;
        const double each = marking_allowance(a.vector.norm(), q.tolerance) / std::sqrt(static_cast<double>(n));
        std::string fields = "<p>(";
        for (int c = 0; c < n; ++c)
            fields += (c ? ", " : "") + std::string("{1:NUMERICAL:=") + full(a.vector[c]) + ":" + full(each) + "}";
        fields += ") " + escape(a.unit) + "</p>\n<p><small>Each component in " + escape(a.unit) + ".</small></p>\n";
        o << common_head("cloze", nm, part.html + ask + fields, part.file, feedback, id);
    } else if (q.has_choices()) {
        o << common_head("multichoice", nm, part.html + ask, part.file, feedback, id)
          << "<single>true</single>\n<shuffleanswers>false</shuffleanswers>\n<answernumbering>123</answernumbering>\n";
        for (std::size_t c = 0; c < q.choices.size(); ++c)
            o << "<answer fraction=\"" << (static_cast<int>(c) + 1 == q.correct ? 100 : 0)
              << "\" format=\"html\">\n<text>" << cdata(math(q.choices[c]))
              << "</text>\n<feedback format=\"html\"><text>" << cdata(math(q.reasons[c]))
              << "</text></feedback>\n</answer>\n";
    } else {
        o << common_head("essay", nm, part.html + ask, part.file, feedback, id)
          << "<responseformat>editor</responseformat>\n<responserequired>1</responserequired>\n"
             "<responsefieldlines>10</responsefieldlines>\n<attachments>0</attachments>\n"
             "<graderinfo format=\"html\"><text>"
          << cdata(html::paragraphs(q.answer))
          << "</text></graderinfo>\n<responsetemplate format=\"html\"><text></text></responsetemplate>\n";
    }
    o << "</question>\n";
    return o.str();
}

}  // namespace

std::string moodle_xml(const std::vector<Lesson>& lessons, const std::vector<std::vector<StudentSheet>>& sheets,
                       std::uint64_t seed) {
    std::ostringstream o;
    o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- collide worksheet, seed " << seed
      << ": import in Moodle's question bank (Import, Moodle XML format). docs/commands/worksheet.md -->\n<quiz>\n";
    for (std::size_t l = 0; l < lessons.size(); ++l) {
        const Lesson& L = lessons[l];
        const std::vector<StudentSheet>& ss = sheets[l];
        const std::string top = "$course$/top/Collide worksheets/" + segment(L.title + " (" + L.id + ")");
        std::vector<StudentPart> parts;
        std::vector<std::string> feedback;
        for (const StudentSheet& s : ss) {
            parts.push_back(student_part(L, s));
            feedback.push_back(worked_feedback(s));
        }
        o << category(top);
        if (ss.empty()) continue;
        for (std::size_t k = 0; k < ss.front().asked.size(); ++k) {
            o << category(top + "/Question " + std::to_string(question_number(L, ss.front().asked[k])));
            for (std::size_t j = 0; j < ss.size(); ++j) o << question_xml(L, ss[j], k, parts[j], feedback[j]);
        }
    }
    o << "</quiz>\n";
    return o.str();
}

}  // namespace collide
