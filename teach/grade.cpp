#include "teach/grade.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "engine/math.h"  // kPi
#include "scenario/input_error.h"
#include "teach/answers.h"
#include "teach/units.h"

namespace collide {

namespace {

using json = nlohmann::json;

std::string slurp(const std::string& path, const std::string& what) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw InputError(path, {}, "", "cannot read the " + what);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// A whole number as a CSV field holds it ("3", " 3 "), or none.
std::optional<int> whole(const std::string& text) {
    const std::string t = trim(text);
    if (t.empty() || t.size() > 9 || t.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    return std::stoi(t);
}

double length(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x * x;
    return std::sqrt(s);
}

double distance(const std::vector<double>& a, const std::vector<double>& b) {
    double s = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(s);
}

std::vector<double> scaled(const std::vector<double>& v, double k) {
    std::vector<double> out = v;
    for (double& x : out) x *= k;
    return out;
}

bool within(const std::vector<double>& got, const std::vector<double>& want, double tolerance) {
    return got.size() == want.size() && distance(got, want) <= marking_allowance(length(want), tolerance);
}

// key.json's fields, each refused by name when missing or of the wrong type.
const json& field(const json& j, const char* name, const std::string& file, const std::string& where) {
    if (!j.is_object() || !j.contains(name))
        throw InputError(file, {}, where + name,
                         std::string("missing") + (std::string(name) == "tolerance"
                                                       ? " (a key written before `collide grade` existed: write the "
                                                         "worksheets again with this version)"
                                                       : ""));
    return j.at(name);
}

double number_field(const json& j, const char* name, const std::string& file, const std::string& where) {
    const json& x = field(j, name, file, where);
    if (!x.is_number()) throw InputError(file, {}, where + name, "expected a number, got " + x.dump());
    return x.get<double>();
}

}  // namespace

const KeyStudent* AnswerKey::student(int number) const {
    for (const KeyStudent& s : students)
        if (s.student == number) return &s;
    return nullptr;
}

AnswerKey read_answer_key(const std::string& path) {
    const std::string text = slurp(path, "answer key");
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error& e) {
        throw InputError(path, {}, "", std::string("not JSON: ") + e.what());
    }
    AnswerKey key;
    key.file = path;
    const json& lesson = field(doc, "lesson", path, "");
    if (!lesson.is_string()) throw InputError(path, {}, "lesson", "expected a string");
    key.lesson = lesson.get<std::string>();
    const json& students = field(doc, "students", path, "");
    if (!students.is_array() || students.empty())
        throw InputError(path, {}, "students", "expected a list of students (a key.json of `collide worksheet`)");
    for (std::size_t i = 0; i < students.size(); ++i) {
        const json& sj = students[i];
        const std::string where = "students[" + std::to_string(i) + "].";
        KeyStudent s;
        s.student = static_cast<int>(number_field(sj, "student", path, where));
        if (key.student(s.student))
            throw InputError(path, {}, where + "student", "student " + std::to_string(s.student) + " twice");
        if (sj.contains("values") && sj["values"].is_object())
            for (const auto& [name, v] : sj["values"].items())
                if (v.is_number()) s.values[name] = v.get<double>();
        if (sj.contains("restitution") && sj["restitution"].is_number())
            s.restitution = sj["restitution"].get<double>();
        const json& answers = field(sj, "answers", path, where);
        if (!answers.is_array()) throw InputError(path, {}, where + "answers", "expected a list");
        for (std::size_t k = 0; k < answers.size(); ++k) {
            const json& aj = answers[k];
            const std::string at = where + "answers[" + std::to_string(k) + "].";
            KeyAnswer a;
            a.question = static_cast<int>(number_field(aj, "question", path, at));
            const json& q = field(aj, "quantity", path, at);
            const json& u = field(aj, "unit", path, at);
            if (!q.is_string() || !u.is_string()) throw InputError(path, {}, at + "unit", "expected strings");
            a.quantity = q.get<std::string>();
            a.unit = u.get<std::string>();
            if (aj.contains("text")) {  // (not in a key written before it was)
                if (!aj["text"].is_string()) throw InputError(path, {}, at + "text", "expected a string");
                a.text = aj["text"].get<std::string>();
            }
            a.tolerance = number_field(aj, "tolerance", path, at);
            const json& v = field(aj, "value", path, at);
            if (v.is_number()) {
                a.value = {v.get<double>()};
            } else if (v.is_array() && (v.size() == 2 || v.size() == 3) &&
                       std::all_of(v.begin(), v.end(), [](const json& x) { return x.is_number(); })) {
                for (const json& x : v) a.value.push_back(x.get<double>());
                a.is_vector = true;
            } else {
                throw InputError(path, {}, at + "value", "expected a number or 2 or 3 numbers, got " + v.dump());
            }
            s.answers.push_back(a);
        }
        key.students.push_back(std::move(s));
    }
    return key;
}

std::vector<Slip> likely_slips(const KeyAnswer& a, const KeyStudent& s) {
    std::vector<Slip> all;
    if (length(a.value) > 0) all.push_back({"the sign flipped", scaled(a.value, -1.0)});
    const bool impulse = a.quantity.rfind("impulse", 0) == 0 || a.quantity == "slip_stop_impulse";
    if (impulse && s.restitution && *s.restitution > -1.0) {
        const double e = *s.restitution;
        all.push_back({"without the factor (1 + e)", scaled(a.value, 1.0 / (1.0 + e))});
        all.push_back({"with 2 for (1 + e), as if the collision were elastic", scaled(a.value, 2.0 / (1.0 + e))});
        all.push_back({"without (1 + e) and with the sign flipped", scaled(a.value, -1.0 / (1.0 + e))});
    }
    if (a.unit == "J") all.push_back({"without the 1/2 of the kinetic energy", scaled(a.value, 2.0)});
    if (a.unit == "rad/s") {
        all.push_back({"in degrees per second, written as rad/s", scaled(a.value, 180.0 / kPi)});
        all.push_back({"in rpm, written as rad/s", scaled(a.value, 60.0 / (2.0 * kPi))});
    }
    // Only those a marker can tell from the right answer (e = 1 makes (1 + e) = 2 a non-slip).
    std::vector<Slip> out;
    for (Slip& sl : all)
        if (!within(sl.value, a.value, a.tolerance) &&
            std::none_of(out.begin(), out.end(), [&](const Slip& o) { return within(sl.value, o.value, a.tolerance); }))
            out.push_back(std::move(sl));
    return out;
}

std::vector<CsvRecord> parse_csv(const std::string& text, const std::string& name) {
    std::vector<CsvRecord> records;
    CsvRecord rec;
    std::string fieldtext;
    int line = 1;
    rec.line = 1;
    bool quoted = false, after_quote = false, any = false;
    int quote_line = 0;
    std::size_t i = 0;
    if (text.compare(0, 3, "\xef\xbb\xbf") == 0) i = 3;  // a spreadsheet's byte-order mark
    const auto end_record = [&] {
        rec.fields.push_back(fieldtext);
        fieldtext.clear();
        // A blank line is no record.
        if (!(rec.fields.size() == 1 && trim(rec.fields[0]).empty() && !any)) records.push_back(rec);
        rec = CsvRecord{};
        any = false;
        after_quote = false;
    };
    for (; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '"') {
                if (i + 1 < text.size() && text[i + 1] == '"') {
                    fieldtext += '"';
                    ++i;
                } else {
                    quoted = false;
                    after_quote = true;
                }
            } else {
                if (c == '\n') ++line;
                fieldtext += c;
            }
            continue;
        }
        if (c == '"') {
            if (!trim(fieldtext).empty() || after_quote)
                throw InputError(name, {line, 0}, "",
                                 "a double quote inside a field that is not quoted (RFC 4180: "
                                 "quote the whole field and double the quote)");
            fieldtext.clear();
            quoted = true;
            any = true;
            quote_line = line;
        } else if (c == ',') {
            rec.fields.push_back(fieldtext);
            fieldtext.clear();
            after_quote = false;
            any = true;
        } else if (c == '\n' || c == '\r') {
            if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
            end_record();
            ++line;
            rec.line = line;
        } else {
            if (after_quote && c != ' ' && c != '\t')
                throw InputError(name, {line, 0}, "", "text after a field's closing double quote");
            if (!after_quote) fieldtext += c;
        }
    }
    if (quoted) throw InputError(name, {quote_line, 0}, "", "a double quote opened here is never closed");
    if (!fieldtext.empty() || !rec.fields.empty() || any) end_record();
    return records;
}

std::optional<ReadAnswer> read_student_answer(const std::string& text) {
    const std::string t = trim(text);
    ReadAnswer r;
    std::string rest;
    if (!t.empty() && t[0] == '(') {
        const auto close = t.find(')');
        if (close == std::string::npos) return std::nullopt;
        const std::string inside = t.substr(1, close - 1);
        // Components apart by ';' (a decimal comma's), else by ','.
        const char sep = inside.find(';') != std::string::npos ? ';' : ',';
        std::stringstream parts(inside);
        std::string part;
        while (std::getline(parts, part, sep)) {
            const auto x = parse_student_number(trim(part));
            if (!x) return std::nullopt;
            r.numbers.push_back(*x);
        }
        if (r.numbers.size() < 2 || r.numbers.size() > 3) return std::nullopt;
        r.is_vector = true;
        rest = t.substr(close + 1);
    } else {
        // The number: sign, digits with '.' or ',', an exponent only when digits follow it
        // ("2e3"; "2 e" is no number, "3 J" the unit J).
        std::size_t i = 0;
        if (t.compare(0, 3, "\u2212") == 0) i = 3;
        else if (i < t.size() && (t[i] == '-' || t[i] == '+')) ++i;
        while (i < t.size() && (std::isdigit(static_cast<unsigned char>(t[i])) || t[i] == '.' || t[i] == ',')) ++i;
        if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
            std::size_t j = i + 1;
            if (j < t.size() && (t[j] == '+' || t[j] == '-')) ++j;
            if (j < t.size() && std::isdigit(static_cast<unsigned char>(t[j]))) {
                while (j < t.size() && std::isdigit(static_cast<unsigned char>(t[j]))) ++j;
                i = j;
            }
        }
        const auto x = parse_student_number(t.substr(0, i));
        if (!x) return std::nullopt;
        r.numbers = {*x};
        rest = t.substr(i);
    }
    r.unit = trim(rest);
    return r;
}

std::vector<Mark> grade_answers(const AnswerKey& key, const std::string& csv_path) {
    return grade_answers_text(key, slurp(csv_path, "answers"), csv_path);
}

std::vector<Mark> grade_answers_text(const AnswerKey& key, const std::string& csv_text, const std::string& name) {
    std::vector<CsvRecord> records = parse_csv(csv_text, name);
    // An optional header: student,question,answer.
    if (!records.empty() && !records[0].fields.empty()) {
        std::string first = trim(records[0].fields[0]);
        std::transform(first.begin(), first.end(), first.begin(), [](unsigned char c) { return std::tolower(c); });
        if (first == "student") records.erase(records.begin());
    }
    if (records.empty()) throw InputError(name, {}, "", "no answers: expected rows of student,question,answer");
    std::map<std::pair<int, int>, Mark> marks;
    std::set<int> named;
    for (const CsvRecord& r : records) {
        const SourcePos at{r.line, 0};
        if (r.fields.size() != 3) {
            std::string hint;
            if (r.fields.size() == 4)
                hint = " (a decimal comma: put the answer in double quotes, \"1,25\"; or use a decimal point)";
            throw InputError(
                name, at, "",
                "expected 3 fields (student,question,answer), got " + std::to_string(r.fields.size()) + hint);
        }
        const auto sn = whole(r.fields[0]);
        if (!sn)
            throw InputError(name, at, "student", "expected a student's number, got '" + one_line(r.fields[0]) + "'");
        const KeyStudent* s = key.student(*sn);
        if (!s)
            throw InputError(name, at, "student",
                             "student " + std::to_string(*sn) + " is not in " + key.file + " (students " +
                                 std::to_string(key.students.front().student) + " to " +
                                 std::to_string(key.students.back().student) + ")");
        const auto qn = whole(r.fields[1]);
        if (!qn)
            throw InputError(name, at, "question", "expected a question's number, got '" + one_line(r.fields[1]) + "'");
        const KeyAnswer* a = nullptr;
        for (const KeyAnswer& k : s->answers)
            if (k.question == *qn) a = &k;
        if (!a) {
            std::string list;
            for (const KeyAnswer& k : s->answers) list += (list.empty() ? "" : ", ") + std::to_string(k.question);
            throw InputError(name, at, "question",
                             "question " + std::to_string(*qn) + " is not a numeric question of " + key.file +
                                 " (numeric questions: " + list + ")");
        }
        if (marks.count({*sn, *qn}))
            throw InputError(name, at, "",
                             "student " + std::to_string(*sn) + ", question " + std::to_string(*qn) +
                                 " is answered twice (first on line " + std::to_string(marks[{*sn, *qn}].line) + ")");
        Mark m;
        m.student = *sn;
        m.question = *qn;
        m.line = r.line;
        m.key = a;
        m.given = trim(r.fields[2]);
        m.answered = !m.given.empty();
        if (m.answered) {
            const auto read = read_student_answer(m.given);
            if (!read)
                throw InputError(name, at, "answer",
                                 "'" + one_line(m.given) +
                                     "' is not a number or vector with an optional unit (1.25, -0,5 m/s, 3 km/h, "
                                     "(0.9, 0.1) m/s)");
            double factor = 1.0;
            if (read->unit.empty()) {
                if (!a->unit.empty()) m.note = "no unit: taken as " + a->unit;
            } else if (const auto f = unit_factor(read->unit, a->unit)) {
                factor = *f;
                if (normalize_unit(read->unit) != normalize_unit(a->unit) && *f != 1.0)
                    m.note = read->unit + " converted to " + a->unit;
            } else {
                bool known = false;
                for (const char* base : {"m/s", "N s", "kg m/s", "kg m^2/s", "J", "rad/s", "s", "m", "N", "N s/m"})
                    known = known || unit_factor(read->unit, base).has_value();
                if (!known) {
                    std::string units;
                    for (const AcceptedUnit& u : accepted_units(a->unit)) units += (units.empty() ? "" : ", ") + u.name;
                    throw InputError(name, at, "answer",
                                     "unit '" + one_line(read->unit) + "' is not known (for question " +
                                         std::to_string(*qn) + ": " + (units.empty() ? "none" : units) + ")");
                }
                m.note = "the unit " + read->unit + " is not one of " + (a->unit.empty() ? "a count" : a->unit);
                factor = 0.0;  // not comparable: wrong
            }
            if (factor != 0.0) {
                if (read->is_vector != a->is_vector || read->numbers.size() != a->value.size()) {
                    m.note = a->is_vector ? "a vector of " + std::to_string(a->value.size()) + " components is asked"
                                          : "a number is asked, not a vector";
                } else {
                    m.got = scaled(read->numbers, factor);
                    m.right = within(m.got, a->value, a->tolerance);
                    if (!m.right)
                        for (const Slip& sl : likely_slips(*a, *s))
                            if (within(m.got, sl.value, a->tolerance)) {
                                m.slip = sl.name;
                                break;
                            }
                }
            }
        } else {
            m.note = "no answer";
        }
        named.insert(*sn);
        marks[{*sn, *qn}] = m;
    }
    // Every numeric question of every student named: those without a row are not answered.
    for (int sn : named)
        for (const KeyAnswer& a : key.student(sn)->answers)
            if (!marks.count({sn, a.question})) {
                Mark m;
                m.student = sn;
                m.question = a.question;
                m.key = &a;
                m.note = "no answer";
                marks[{sn, a.question}] = m;
            }
    std::vector<Mark> out;
    for (auto& [k, m] : marks) out.push_back(std::move(m));
    return out;
}

}  // namespace collide
