#include "present/moodle_xml.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "present/platform_questions.h"
#include "present/worksheets.h"
#include "teach/answers.h"
#include "teach/html.h"
#include "teach/units.h"

namespace collide {

namespace {

using html::escape;

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
    return "<question type=\"category\">\n<category><text>" + xml_text(path) +
           "</text></category>\n<info format=\"html\"><text></text></info>\n</question>\n";
}

// What every question of a student's sheet shows first: the givens and the figure.
struct StudentPart {
    std::string html;  // the givens, the figure's <img>
    std::string file;  // the figure's <file> element, or ""
};

StudentPart student_part(const PlatformSheet& sheet) {
    StudentPart p{sheet.intro_html, ""};
    if (const auto& f = sheet.figure) {
        p.html += platform_figure_html(*f, "@@PLUGINFILE@@/" + f->file);
        p.file =
            "<file name=\"" + xml_text(f->file) + "\" path=\"/\" encoding=\"base64\">" + base64(f->svg) + "</file>\n";
    }
    return p;
}

std::string common_head(const std::string& type, const std::string& name, const std::string& text,
                        const std::string& file, const std::string& feedback, const std::string& idnumber) {
    return "<question type=\"" + type + "\">\n<name><text>" + xml_text(name) +
           "</text></name>\n<questiontext format=\"html\"><text>" + cdata(text) + "</text>\n" + file +
           "</questiontext>\n<generalfeedback format=\"html\"><text>" + cdata(feedback) +
           "</text></generalfeedback>\n<defaultgrade>1</defaultgrade>\n<penalty>0.3333333</penalty>\n<hidden>0</hidden>\n"
           "<idnumber>" +
           xml_text(idnumber) + "</idnumber>\n";
}

std::string question_xml_text(const PlatformQuestion& q, const StudentPart& part, const std::string& feedback) {
    std::ostringstream o;
    switch (q.kind) {
        case PlatformKind::number:
            o << common_head("numerical", q.name,
                             part.html + q.ask_html + "<p>Give the number and its unit (" + escape(q.unit) + ").</p>\n",
                             part.file, feedback, q.id)
              << "<answer fraction=\"100\" format=\"moodle_auto_format\">\n<text>" << full_number(q.want[0])
              << "</text>\n<feedback format=\"html\"><text></text></feedback>\n<tolerance>" << full_number(q.allowance)
              << "</tolerance>\n</answer>\n"
              << "<unitgradingtype>0</unitgradingtype>\n<unitpenalty>0.1000000</unitpenalty>\n"
              << "<showunits>" << (q.unit.empty() ? 3 : 0) << "</showunits>\n<unitsleft>0</unitsleft>\n";
            if (!q.unit.empty()) {
                o << "<units>\n";
                for (const AcceptedUnit& u : accepted_units(q.unit))
                    o << "<unit><multiplier>" << full_number(1.0 / u.factor) << "</multiplier><unit_name>"
                      << xml_text(u.name) << "</unit_name></unit>\n";
                o << "</units>\n";
            }
            break;
        case PlatformKind::vector: {
            // Moodle's numerical question holds one number: a vector is a cloze of its components,
            // each within the allowance over sqrt(components) (then the vector is within it).
            const double each = q.allowance / std::sqrt(static_cast<double>(q.want.size()));
            std::string fields = "<p>(";
            for (std::size_t c = 0; c < q.want.size(); ++c)
                fields += (c ? ", " : "") + std::string("{1:NUMERICAL:=") + full_number(q.want[c]) + ":" +
                          full_number(each) + "}";
            fields += ") " + escape(q.unit) + "</p>\n<p><small>Each component in " + escape(q.unit) + ".</small></p>\n";
            o << common_head("cloze", q.name, part.html + q.ask_html + fields, part.file, feedback, q.id);
            break;
        }
        case PlatformKind::choice:
            o << common_head("multichoice", q.name, part.html + q.ask_html, part.file, feedback, q.id)
              << "<single>true</single>\n<shuffleanswers>false</shuffleanswers>\n<answernumbering>123</answernumbering>\n";
            for (std::size_t c = 0; c < q.choices.size(); ++c)
                o << "<answer fraction=\"" << (c == q.correct ? 100 : 0) << "\" format=\"html\">\n<text>"
                  << cdata(q.choices[c]) << "</text>\n<feedback format=\"html\"><text>" << cdata(q.reasons[c])
                  << "</text></feedback>\n</answer>\n";
            break;
        case PlatformKind::explain:
            o << common_head("essay", q.name, part.html + q.ask_html, part.file, feedback, q.id)
              << "<responseformat>editor</responseformat>\n<responserequired>1</responserequired>\n"
                 "<responsefieldlines>10</responsefieldlines>\n<attachments>0</attachments>\n"
                 "<graderinfo format=\"html\"><text>"
              << cdata(q.model_answer)
              << "</text></graderinfo>\n<responsetemplate format=\"html\"><text></text></responsetemplate>\n";
            break;
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
        std::vector<PlatformSheet> sheet;
        std::vector<StudentPart> parts;
        for (const StudentSheet& s : ss) {
            sheet.push_back(platform_sheet(L, s));
            parts.push_back(student_part(sheet.back()));
        }
        o << category(top);
        if (ss.empty()) continue;
        for (std::size_t k = 0; k < ss.front().asked.size(); ++k) {
            o << category(top + "/Question " + std::to_string(question_number(L, ss.front().asked[k])));
            for (std::size_t j = 0; j < ss.size(); ++j)
                o << question_xml_text(sheet[j].questions[k], parts[j], sheet[j].worked_html);
        }
    }
    o << "</quiz>\n";
    return o.str();
}

}  // namespace collide
