#include "present/qti_package.h"

#include <cctype>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "present/platform_questions.h"

namespace collide {

namespace {

constexpr const char* kQtiNamespace = "http://www.imsglobal.org/xsd/imsqti_v2p1";
constexpr const char* kQtiSchema = "http://www.imsglobal.org/xsd/qti/qtiv2p1/imsqti_v2p1.xsd";
constexpr const char* kXsi = "http://www.w3.org/2001/XMLSchema-instance";

std::string root_attributes() {
    return std::string(" xmlns=\"") + kQtiNamespace + "\" xmlns:xsi=\"" + kXsi + "\" xsi:schemaLocation=\"" +
           kQtiNamespace + " " + kQtiSchema + "\"";
}

std::string float_value(double x) { return "<baseValue baseType=\"float\">" + full_number(x) + "</baseValue>"; }

std::string set_outcome(const std::string& id, const std::string& value) {
    return "<setOutcomeValue identifier=\"" + id + "\">" + value + "</setOutcomeValue>\n";
}

// The response variables: RESPONSE, or RESPONSE_X, _Y, _Z for a vector's components.
std::vector<std::string> responses(const PlatformQuestion& q) {
    if (q.kind != PlatformKind::vector) return {"RESPONSE"};
    std::vector<std::string> r;
    for (std::size_t c = 0; c < q.want.size(); ++c) r.push_back(std::string("RESPONSE_") + "XYZ"[c]);
    return r;
}

std::string option_id(std::size_t c) { return "OPTION_" + std::to_string(c + 1); }

std::string declarations(const PlatformQuestion& q, bool worked) {
    std::ostringstream o;
    const std::vector<std::string> r = responses(q);
    for (std::size_t c = 0; c < r.size(); ++c) {
        o << "<responseDeclaration identifier=\"" << r[c] << "\" cardinality=\"single\" baseType=\"";
        if (q.kind == PlatformKind::number || q.kind == PlatformKind::vector)
            o << "float\">\n<correctResponse><value>" << full_number(q.want[c]) << "</value></correctResponse>\n";
        else if (q.kind == PlatformKind::choice)
            o << "identifier\">\n<correctResponse><value>" << option_id(q.correct) << "</value></correctResponse>\n";
        else o << "string\">\n";
        o << "</responseDeclaration>\n";
    }
    o << "<outcomeDeclaration identifier=\"SCORE\" cardinality=\"single\" baseType=\"float\" normalMinimum=\"0\" "
         "normalMaximum=\"1\">\n<defaultValue><value>0</value></defaultValue>\n</outcomeDeclaration>\n"
         "<outcomeDeclaration identifier=\"MAXSCORE\" cardinality=\"single\" baseType=\"float\">\n"
         "<defaultValue><value>1</value></defaultValue>\n</outcomeDeclaration>\n";
    if (q.kind == PlatformKind::choice)
        o << "<outcomeDeclaration identifier=\"FEEDBACK\" cardinality=\"single\" baseType=\"identifier\"/>\n";
    if (worked) o << "<outcomeDeclaration identifier=\"SOLUTION\" cardinality=\"single\" baseType=\"identifier\"/>\n";
    return o.str();
}

// Where the student answers.
std::string interaction(const PlatformQuestion& q) {
    const std::string unit = q.unit.empty() ? "" : " " + xml_text(q.unit);
    switch (q.kind) {
        case PlatformKind::number:
            return "<p>Your answer: <textEntryInteraction responseIdentifier=\"RESPONSE\" expectedLength=\"12\"/>" +
                   unit + "</p>\n" +
                   (q.unit.empty() ? std::string("<p><small>A whole number.</small></p>\n")
                                   : "<p><small>The number in " + xml_text(q.unit) +
                                         ", with a decimal point (1.25), without the unit.</small></p>\n");
        case PlatformKind::vector: {
            std::string o = "<p>Your answer: (";
            for (const std::string& r : responses(q))
                o += (r == "RESPONSE_X" ? "" : ", ") + std::string("<textEntryInteraction responseIdentifier=\"") + r +
                     "\" expectedLength=\"10\"/>";
            return o + ")" + unit + "</p>\n<p><small>Each component in " + xml_text(q.unit) +
                   ", with a decimal point (1.25).</small></p>\n";
        }
        case PlatformKind::choice: {
            std::string o = "<choiceInteraction responseIdentifier=\"RESPONSE\" shuffle=\"false\" maxChoices=\"1\">\n";
            for (std::size_t c = 0; c < q.choices.size(); ++c)
                o += "<simpleChoice identifier=\"" + option_id(c) + "\">" + qti_xhtml(q.choices[c]) +
                     "</simpleChoice>\n";
            return o + "</choiceInteraction>\n";
        }
        case PlatformKind::explain:
            return "<extendedTextInteraction responseIdentifier=\"RESPONSE\" expectedLines=\"10\"/>\n"
                   "<rubricBlock view=\"scorer\">\n<p><b>Model answer</b> (for the grader; 1 mark):</p>\n" +
                   qti_xhtml(q.model_answer) + "</rubricBlock>\n";
    }
    return "";
}

// Every response given: QTI's operators make a NULL (no answer) NULL and the test false, but a
// player that reads an empty field as 0 would find a 0 component right without it.
std::string answered(const PlatformQuestion& q) {
    std::string o;
    for (const std::string& r : responses(q)) o += "<not><isNull><variable identifier=\"" + r + "\"/></isNull></not>";
    return o;
}

// SCORE 1 when `right`, else 0.
std::string score_if(const std::string& right) {
    return "<responseCondition>\n<responseIf>\n" + right + set_outcome("SCORE", float_value(1)) +
           "</responseIf>\n<responseElse>\n" + set_outcome("SCORE", float_value(0)) +
           "</responseElse>\n</responseCondition>\n";
}

std::string processing(const PlatformQuestion& q, bool worked) {
    std::string o = "<responseProcessing>\n";
    switch (q.kind) {
        case PlatformKind::number:
            o += score_if("<and>\n" + answered(q) + "\n<equal toleranceMode=\"absolute\" tolerance=\"" +
                          full_number(q.allowance) + "\">\n<variable identifier=\"RESPONSE\"/>\n" +
                          float_value(q.want[0]) + "\n</equal>\n</and>\n");
            break;
        case PlatformKind::vector: {
            // |got - want|^2 <= allowance^2: the length of the difference, without a square root.
            std::string sum = "<sum>\n";
            const std::vector<std::string> r = responses(q);
            for (std::size_t c = 0; c < r.size(); ++c) {
                const std::string d =
                    "<subtract><variable identifier=\"" + r[c] + "\"/>" + float_value(q.want[c]) + "</subtract>";
                sum += "<product>" + d + d + "</product>\n";
            }
            o += score_if("<and>\n" + answered(q) + "\n<lte>\n" + sum + "</sum>\n" +
                          float_value(q.allowance * q.allowance) + "\n</lte>\n</and>\n");
            break;
        }
        case PlatformKind::choice:
            o += score_if("<match><variable identifier=\"RESPONSE\"/><correct identifier=\"RESPONSE\"/></match>\n") +
                 set_outcome("FEEDBACK", "<variable identifier=\"RESPONSE\"/>");
            break;
        case PlatformKind::explain: break;  // marked by a grader, from the rubric
    }
    if (worked) o += set_outcome("SOLUTION", "<baseValue baseType=\"identifier\">WORKED</baseValue>");
    return o + "</responseProcessing>\n";
}

std::string item_xml(const PlatformSheet& sheet, const PlatformQuestion& q) {
    const bool worked = !sheet.worked_html.empty();
    std::ostringstream o;
    o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<assessmentItem" << root_attributes() << " identifier=\"" << q.id
      << "\" title=\"" << xml_text(q.name) << "\" adaptive=\"false\" timeDependent=\"false\">\n"
      << declarations(q, worked) << "<itemBody>\n"
      << qti_xhtml(sheet.intro_html + (sheet.figure ? platform_figure_html(*sheet.figure, sheet.figure->file) : "") +
                   q.ask_html)
      << interaction(q) << "</itemBody>\n"
      << processing(q, worked);
    if (q.kind == PlatformKind::choice)
        for (std::size_t c = 0; c < q.choices.size(); ++c)
            o << "<modalFeedback outcomeIdentifier=\"FEEDBACK\" identifier=\"" << option_id(c)
              << "\" showHide=\"show\" title=\"Option " << c + 1 << "\">\n<p><b>"
              << (c == q.correct ? "Right" : "Not right") << ".</b> " << qti_xhtml(q.reasons[c])
              << "</p>\n</modalFeedback>\n";
    if (worked)
        o << "<modalFeedback outcomeIdentifier=\"SOLUTION\" identifier=\"WORKED\" showHide=\"show\" title=\"Worked "
             "out\">\n"
          << qti_xhtml(sheet.worked_html) << "</modalFeedback>\n";
    o << "</assessmentItem>\n";
    return o.str();
}

// The lesson as a test: a section per question, each drawing one of the students' variants.
std::string test_xml(const Lesson& L, const std::vector<PlatformSheet>& sheets) {
    std::ostringstream o;
    o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<assessmentTest" << root_attributes() << " identifier=\"collide-"
      << L.id << "-test\" title=\"" << xml_text(L.title) << "\">\n"
      << "<outcomeDeclaration identifier=\"SCORE\" cardinality=\"single\" baseType=\"float\">\n"
         "<defaultValue><value>0</value></defaultValue>\n</outcomeDeclaration>\n"
      << "<testPart identifier=\"collide-" << L.id
      << "-part\" navigationMode=\"nonlinear\" submissionMode=\"individual\">\n"
         "<itemSessionControl maxAttempts=\"1\" showFeedback=\"true\" allowReview=\"true\" showSolution=\"false\"/>\n";
    for (std::size_t k = 0; k < sheets.front().questions.size(); ++k) {
        const int number = sheets.front().questions[k].number;
        o << "<assessmentSection identifier=\"collide-" << L.id << "-q" << number << "\" title=\"Question " << number
          << "\" visible=\"true\">\n<selection select=\"1\"/>\n";
        for (const PlatformSheet& s : sheets)
            o << "<assessmentItemRef identifier=\"" << s.questions[k].id << "\" href=\"q" << number << "-s" << s.student
              << ".xml\"/>\n";
        o << "</assessmentSection>\n";
    }
    o << "</testPart>\n<outcomeProcessing>\n"
      << set_outcome("SCORE", "<sum><testVariables variableIdentifier=\"SCORE\"/></sum>")
      << "</outcomeProcessing>\n</assessmentTest>\n";
    return o.str();
}

struct Resource {
    std::string id, type, href;
    std::vector<std::string> depends;
};

std::string manifest_xml(const std::vector<Resource>& resources, std::uint64_t seed) {
    std::ostringstream o;
    o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- collide worksheet, seed " << seed
      << ": an IMS QTI 2.1 package; import it as one (docs/commands/worksheet.md, \"QTI\") -->\n"
      << "<manifest xmlns=\"http://www.imsglobal.org/xsd/imscp_v1p1\" xmlns:xsi=\"" << kXsi
      << "\" identifier=\"collide-worksheets-seed-" << seed
      << "\" xsi:schemaLocation=\"http://www.imsglobal.org/xsd/imscp_v1p1 "
         "http://www.imsglobal.org/xsd/qti/qtiv2p1/qtiv2p1_imscpv1p2_v1p0.xsd\">\n"
      << "<metadata>\n<schema>QTIv2.1 Package</schema>\n<schemaversion>1.0.0</schemaversion>\n</metadata>\n"
      << "<organizations/>\n<resources>\n";
    for (const Resource& r : resources) {
        o << "<resource identifier=\"" << r.id << "\" type=\"" << r.type << "\" href=\"" << xml_text(r.href)
          << "\">\n<file href=\"" << xml_text(r.href) << "\"/>\n";
        for (const std::string& d : r.depends) o << "<dependency identifierref=\"" << d << "\"/>\n";
        o << "</resource>\n";
    }
    o << "</resources>\n</manifest>\n";
    return o.str();
}

}  // namespace

std::vector<ZipEntry> qti_package_files(const std::vector<Lesson>& lessons,
                                        const std::vector<std::vector<StudentSheet>>& sheets, std::uint64_t seed) {
    std::vector<ZipEntry> files = {{"imsmanifest.xml", ""}};
    std::vector<Resource> resources;
    for (std::size_t l = 0; l < lessons.size(); ++l) {
        const Lesson& L = lessons[l];
        std::vector<PlatformSheet> ps;
        for (const StudentSheet& s : sheets[l]) ps.push_back(platform_sheet(L, s));
        const std::string dir = L.id + "/";
        // A test needs a section: none for a lesson whose sheet asks nothing (nor any item).
        if (ps.empty() || ps.front().questions.empty()) continue;
        Resource test{"collide-" + L.id + "-test", "imsqti_test_xmlv2p1", dir + "test.xml", {}};
        files.push_back({test.href, test_xml(L, ps)});
        const std::size_t test_at = resources.size();
        resources.push_back(test);
        const auto figure_id = [&](const PlatformSheet& s) {
            return "collide-" + L.id + "-figure-s" + std::to_string(s.student);
        };
        for (std::size_t k = 0; !ps.empty() && k < ps.front().questions.size(); ++k)
            for (const PlatformSheet& s : ps) {
                const PlatformQuestion& q = s.questions[k];
                Resource r{q.id,
                           "imsqti_item_xmlv2p1",
                           dir + "q" + std::to_string(q.number) + "-s" + std::to_string(s.student) + ".xml",
                           {}};
                if (s.figure) r.depends.push_back(figure_id(s));
                files.push_back({r.href, item_xml(s, q)});
                resources[test_at].depends.push_back(r.id);
                resources.push_back(r);
            }
        for (const PlatformSheet& s : ps)
            if (s.figure) {
                files.push_back({dir + s.figure->file, s.figure->svg});
                resources.push_back({figure_id(s), "webcontent", dir + s.figure->file, {}});
            }
    }
    files.front().data = manifest_xml(resources, seed);
    return files;
}

std::string qti_package(const std::vector<Lesson>& lessons, const std::vector<std::vector<StudentSheet>>& sheets,
                        std::uint64_t seed) {
    return stored_zip(qti_package_files(lessons, sheets, seed));
}

std::string qti_xhtml(const std::string& html) {
    // QTI 2.1's XHTML elements (its "content model" module), and the attributes each may have
    // besides class, id, label and xml:lang.
    static const std::set<std::string> elements = {
        "a",     "abbr",  "acronym",  "address", "b",    "big",   "blockquote", "br",     "caption", "cite",
        "code",  "col",   "colgroup", "dd",      "dfn",  "div",   "dl",         "dt",     "em",      "h1",
        "h2",    "h3",    "h4",       "h5",      "h6",   "hr",    "i",          "img",    "kbd",     "li",
        "ol",    "p",     "pre",      "q",       "samp", "small", "span",       "strong", "sub",     "sup",
        "table", "tbody", "td",       "tfoot",   "th",   "thead", "tr",         "tt",     "ul",      "var"};
    static const std::set<std::string> empty = {"br", "col", "hr", "img"};
    static const std::map<std::string, std::set<std::string>> own = {
        {"a", {"href", "type"}},
        {"blockquote", {"cite"}},
        {"col", {"span"}},
        {"colgroup", {"span"}},
        {"img", {"src", "alt", "longdesc", "height", "width"}},
        {"q", {"cite"}},
        {"table", {"summary"}},
        {"td", {"headers", "scope", "abbr", "axis", "rowspan", "colspan", "align", "valign"}},
        {"th", {"headers", "scope", "abbr", "axis", "rowspan", "colspan", "align", "valign"}}};
    const auto fail = [&](const std::string& why) { throw std::logic_error("HTML for QTI: " + why); };
    const auto check_references = [&](const std::string& text) {
        for (std::size_t at = text.find('&'); at != std::string::npos; at = text.find('&', at + 1)) {
            const std::size_t end = text.find(';', at);
            const std::string ref = end == std::string::npos ? text.substr(at) : text.substr(at, end - at + 1);
            const bool numeric = ref.size() > 3 && ref[1] == '#';
            if (!numeric && ref != "&amp;" && ref != "&lt;" && ref != "&gt;" && ref != "&quot;" && ref != "&apos;")
                fail("the reference " + ref + " is not XML's");
        }
    };
    std::string out;
    std::vector<std::string> open;  // "tbody*": a <tbody> this function opened
    std::size_t i = 0;
    while (i < html.size()) {
        const std::size_t lt = html.find('<', i);
        const std::string text = html.substr(i, lt == std::string::npos ? std::string::npos : lt - i);
        check_references(text);
        out += text;
        if (lt == std::string::npos) break;
        const std::size_t gt = html.find('>', lt);
        if (gt == std::string::npos) fail("a tag left open");
        std::string tag = html.substr(lt + 1, gt - lt - 1);
        i = gt + 1;
        if (tag.rfind("!--", 0) == 0) {  // a comment: left out
            const std::size_t end = html.find("-->", lt);
            if (end == std::string::npos) fail("a comment left open");
            i = end + 3;
            continue;
        }
        if (!tag.empty() && tag[0] == '/') {
            const std::string name = tag.substr(1);
            if (!open.empty() && open.back() == "tbody*" && name == "table") {
                out += "</tbody>";
                open.pop_back();
            }
            if (open.empty() || open.back() != name) fail("</" + name + "> closes nothing open");
            open.pop_back();
            out += "</" + name + ">";
            continue;
        }
        const bool closed = !tag.empty() && tag.back() == '/';
        if (closed) tag.pop_back();
        std::size_t n = 0;
        while (n < tag.size() && std::isalnum(static_cast<unsigned char>(tag[n]))) ++n;
        const std::string name = tag.substr(0, n);
        if (!elements.count(name)) fail("<" + name + "> is not an element of QTI 2.1's XHTML");
        if (closed && !empty.count(name)) fail("<" + name + "/> is not an empty element");
        std::string attributes;
        while (n < tag.size()) {
            while (n < tag.size() && tag[n] == ' ') ++n;
            if (n == tag.size()) break;
            const std::size_t eq = tag.find('=', n);
            if (eq == std::string::npos || eq + 1 >= tag.size() || tag[eq + 1] != '"')
                fail("<" + name + ">: an attribute without a value in double quotes");
            const std::string attribute = tag.substr(n, eq - n);
            const std::size_t close = tag.find('"', eq + 2);
            if (close == std::string::npos) fail("<" + name + ">: a value left open");
            const std::string value = tag.substr(eq + 2, close - eq - 2);
            const auto it = own.find(name);
            if (attribute != "class" && attribute != "id" && attribute != "label" && attribute != "xml:lang" &&
                (it == own.end() || !it->second.count(attribute)))
                fail("<" + name + "> has no attribute " + attribute + " in QTI 2.1");
            check_references(value);
            if (value.find('<') != std::string::npos) fail("<" + name + ">: '<' in " + attribute);
            attributes += " " + attribute + "=\"" + value + "\"";
            n = close + 1;
        }
        if (name == "img" &&
            (attributes.find(" src=\"") == std::string::npos || attributes.find(" alt=\"") == std::string::npos))
            fail("<img> without src or alt");
        if (name == "tr" && !open.empty() && open.back() == "table") {
            out += "<tbody>";
            open.push_back("tbody*");
        }
        if (empty.count(name)) {
            out += "<" + name + attributes + "/>";
        } else {
            out += "<" + name + attributes + ">";
            open.push_back(name);
        }
    }
    if (!open.empty()) fail("<" + open.back() + "> left open");
    return out;
}

}  // namespace collide
