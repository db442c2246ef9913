#include "present/grade_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "teach/answers.h"
#include "teach/html.h"
#include "teach/notation.h"

namespace collide {

namespace {

using html::escape;

// The histogram's bins: multiples of the right value from kLo to kHi, kBin wide, and one bin
// each side for what lies beyond.
constexpr double kLo = -2.0, kHi = 3.0, kBin = 0.1;

std::string sig(double x, int n) { return notation::true_minus(notation::sig_text(x, n)); }

std::string value_text(const std::vector<double>& v) {
    if (v.size() == 1) return sig(v[0], 4);
    std::string s = "(";
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + sig(v[i], 4);
    return s + ")";
}

// For the CSV: full precision, a plain minus.
std::string csv_value(const std::vector<double>& v) {
    std::string s;
    char buf[40];
    for (std::size_t i = 0; i < v.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%.10g", v[i]);
        s += (i ? " " : "") + std::string(buf);
    }
    return v.size() > 1 ? "(" + s + ")" : s;
}

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string out = "\"";
    for (const char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

// The histogram of one question: stacked bars (right green, wrong red) over the multiples of
// the right value, the right band shaded.
std::string histogram_svg(const QuestionSummary& q, double tolerance) {
    const int n = static_cast<int>(std::lround((kHi - kLo) / kBin)) + 1;  // bins centred on kLo..kHi
    std::vector<int> right(static_cast<std::size_t>(n + 2)), wrong(static_cast<std::size_t>(n + 2));
    const auto bin = [&](double r) {
        if (r < kLo - kBin / 2) return 0;
        if (r >= kHi + kBin / 2) return n + 1;
        return 1 + static_cast<int>(std::floor((r - (kLo - kBin / 2)) / kBin));
    };
    for (double r : q.ratios_right) right[static_cast<std::size_t>(bin(r))]++;
    for (double r : q.ratios_wrong) wrong[static_cast<std::size_t>(bin(r))]++;
    int top = 1;
    for (int i = 0; i < n + 2; ++i)
        top = std::max(top, right[static_cast<std::size_t>(i)] + wrong[static_cast<std::size_t>(i)]);
    const double W = 640, H = 172, x0 = 40, y0 = 20, plot_h = 110, bw = (W - x0 - 10) / (n + 2);
    const auto xat = [&](int i) { return x0 + i * bw; };
    const auto xval = [&](double r) { return x0 + (1 + (r - (kLo - kBin / 2)) / kBin) * bw; };
    std::ostringstream o;
    char buf[400];
    o << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"histogram\" viewBox=\"0 0 " << W << " " << H
      << "\" width=\"" << W << "\" height=\"" << H << "\" role=\"img\" aria-label=\"answers to question " << q.question
      << " as multiples of the right value\">\n";
    // The band of right answers: 1 +- tolerance.
    std::snprintf(buf, sizeof buf, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#e3f4e3\"/>\n",
                  xval(1 - tolerance) - 1, y0, xval(1 + tolerance) - xval(1 - tolerance) + 2, plot_h);
    o << buf;
    for (int i = 0; i < n + 2; ++i) {
        const int r = right[static_cast<std::size_t>(i)], w = wrong[static_cast<std::size_t>(i)];
        const double hr = plot_h * r / top, hw = plot_h * w / top;
        if (r) {
            std::snprintf(buf, sizeof buf,
                          "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#2e8b3a\" data-bin=\"%d\" "
                          "data-right=\"%d\"/>\n",
                          xat(i) + 0.5, y0 + plot_h - hr, bw - 1, hr, i, r);
            o << buf;
        }
        if (w) {
            std::snprintf(buf, sizeof buf,
                          "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#c0392b\" data-bin=\"%d\" "
                          "data-wrong=\"%d\"/>\n",
                          xat(i) + 0.5, y0 + plot_h - hr - hw, bw - 1, hw, i, w);
            o << buf;
        }
    }
    // Axis, ticks at whole multiples, the overflow bins named.
    std::snprintf(buf, sizeof buf, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#333\"/>\n", x0,
                  y0 + plot_h, W - 10, y0 + plot_h);
    o << buf;
    for (int t = static_cast<int>(kLo); t <= static_cast<int>(kHi); ++t) {
        std::snprintf(buf, sizeof buf,
                      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#333\"/><text x=\"%.1f\" "
                      "y=\"%.1f\" font-size=\"11\" text-anchor=\"middle\">%s</text>\n",
                      xval(t), y0 + plot_h, xval(t), y0 + plot_h + 4, xval(t), y0 + plot_h + 16,
                      notation::true_minus(std::to_string(t)).c_str());
        o << buf;
    }
    std::snprintf(buf, sizeof buf,
                  "<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" text-anchor=\"middle\">less</text><text x=\"%.1f\" "
                  "y=\"%.1f\" font-size=\"10\" text-anchor=\"middle\">more</text>\n",
                  xat(0) + bw / 2, H - 6, xat(n + 1) + bw / 2, H - 6);
    o << buf;
    std::snprintf(buf, sizeof buf,
                  "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\" text-anchor=\"middle\">the answer as a multiple of "
                  "the student's right value (green band: right within %s)</text>\n",
                  (x0 + W) / 2, H - 6, tolerance_text(tolerance).c_str());
    o << buf;
    std::snprintf(buf, sizeof buf,
                  "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\" text-anchor=\"end\">%d</text><text x=\"%.1f\" "
                  "y=\"%.1f\" font-size=\"11\" text-anchor=\"end\">0</text>\n",
                  x0 - 4, y0 + 8, top, x0 - 4, y0 + plot_h);
    o << buf << "</svg>\n";
    return o.str();
}

}  // namespace

std::string question_words(const KeyAnswer& answer) { return answer.text.empty() ? answer.quantity : answer.text; }

double answer_ratio(const Mark& m) {
    if (!m.key || m.got.size() != m.key->value.size()) return std::numeric_limits<double>::quiet_NaN();
    double dot = 0, nn = 0;
    for (std::size_t i = 0; i < m.got.size(); ++i) {
        dot += m.got[i] * m.key->value[i];
        nn += m.key->value[i] * m.key->value[i];
    }
    return nn > 0 ? dot / nn : std::numeric_limits<double>::quiet_NaN();
}

std::vector<QuestionSummary> summarize_questions(const std::vector<Mark>& marks) {
    std::map<int, QuestionSummary> by;
    std::map<int, std::map<std::string, int>> slips;
    std::map<int, std::map<std::string, std::pair<double, int>>> ratios;
    for (const Mark& m : marks) {
        QuestionSummary& q = by[m.question];
        q.question = m.question;
        if (m.key) {
            q.words = question_words(*m.key);
            q.quantity = m.key->quantity;
            q.unit = m.key->unit;
        }
        q.students++;
        if (m.answered) q.answered++;
        if (m.right) q.right++;
        const double r = answer_ratio(m);
        if (!std::isnan(r)) (m.right ? q.ratios_right : q.ratios_wrong).push_back(r);
        if (m.answered && !m.right) {
            if (!m.slip.empty()) slips[m.question][m.slip]++;
            else if (!std::isnan(r)) {
                const std::string k = notation::sig_text(r, 2);
                auto& e = ratios[m.question][k];
                e.first = std::stod(k);
                e.second++;
            }
        }
    }
    std::vector<QuestionSummary> out;
    for (auto& [n, q] : by) {
        for (const auto& [name, count] : slips[n])
            if (count > q.common_count) {
                q.common_count = count;
                q.common_slip = name;
            }
        for (const auto& [k, e] : ratios[n])
            if (e.second > q.common_count) {
                q.common_count = e.second;
                q.common_slip.clear();
                q.common_ratio = e.first;
            }
        out.push_back(q);
    }
    return out;
}

std::string grade_tables(const AnswerKey& key, const std::vector<Mark>& marks) {
    std::ostringstream o;
    std::vector<int> questions;
    for (const Mark& m : marks)
        if (std::find(questions.begin(), questions.end(), m.question) == questions.end())
            questions.push_back(m.question);
    std::sort(questions.begin(), questions.end());
    const std::vector<QuestionSummary> summaries = summarize_questions(marks);
    o << "Lesson " << key.lesson << ": 1 mark per question (within its tolerance).\n\n";
    for (const QuestionSummary& q : summaries)
        o << "Q" << q.question << "  " << q.words << (q.unit.empty() ? "" : " (" + q.unit + ")") << "\n";
    o << "\nstudent";
    for (int q : questions) o << "  Q" << q;
    o << "  total\n";
    std::map<int, std::vector<const Mark*>> by;
    for (const Mark& m : marks) by[m.student].push_back(&m);
    char buf[64];
    for (const auto& [s, ms] : by) {
        std::snprintf(buf, sizeof buf, "%7d", s);
        o << buf;
        int total = 0;
        for (const Mark* m : ms) {
            std::snprintf(buf, sizeof buf, "  %*s", static_cast<int>(std::to_string(m->question).size()) + 1,
                          !m->answered ? "-"
                          : m->right   ? "1"
                                       : "0");
            o << buf;
            total += m->right ? 1 : 0;
        }
        std::snprintf(buf, sizeof buf, "  %d/%zu\n", total, ms.size());
        o << buf;
    }
    o << "(1 right, 0 wrong, - not answered)\n";
    // The key's students the answers do not name: said, not marked (a key may hold more sheets
    // than the class handed in).
    std::string absent;
    for (const KeyStudent& k : key.students)
        if (!by.count(k.student)) absent += (absent.empty() ? "" : ", ") + std::to_string(k.student);
    if (!absent.empty())
        o << "Not marked: the key's student" << (absent.find(',') == std::string::npos ? " " : "s ") << absent
          << ", with no row in the answers.\n";
    o << "\nquestion  right  answered  most common wrong answer\n";
    for (const QuestionSummary& q : summaries) {
        std::snprintf(buf, sizeof buf, "%8s  %5d  %8d  ", ("Q" + std::to_string(q.question)).c_str(), q.right,
                      q.answered);
        o << buf;
        if (q.common_count == 0) o << "-";
        else if (!q.common_slip.empty()) o << q.common_slip << " (" << q.common_count << ")";
        else o << notation::sig_text(q.common_ratio, 2) << " x the right value (" << q.common_count << ")";
        o << "\n";
    }
    return o.str();
}

std::string marks_csv(const std::vector<Mark>& marks) {
    std::ostringstream o;
    o << "student,question,quantity,answer,value,unit,right_value,mark,note,slip\n";
    for (const Mark& m : marks) {
        o << m.student << "," << m.question << "," << (m.key ? m.key->quantity : "") << "," << csv_field(m.given) << ","
          << csv_field(csv_value(m.got)) << "," << csv_field(m.key ? m.key->unit : "") << ","
          << csv_field(m.key ? csv_value(m.key->value) : "") << "," << (m.right ? 1 : 0) << "," << csv_field(m.note)
          << "," << csv_field(m.slip) << "\n";
    }
    return o.str();
}

std::string grade_report_html(const AnswerKey& key, const std::vector<Mark>& marks, const std::string& answers_name) {
    const std::vector<QuestionSummary> qs = summarize_questions(marks);
    std::set<int> students;
    for (const Mark& m : marks) students.insert(m.student);
    std::ostringstream o;
    o << "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Marks: " << escape(key.lesson)
      << "</title>\n<style>\nbody { font-family: \"DejaVu Sans\", Arial, sans-serif; font-size: 11pt; max-width: "
         "190mm; margin: 0 auto; padding: 8mm; color: #111; }\ntable { border-collapse: collapse; margin: 2mm 0; }\n"
         "th, td { border: 1px solid #999; padding: 1mm 2.5mm; text-align: left; }\nth { background: #eee; }\n"
         "td.num { text-align: right; }\n.low { background: #fde2df; }\n.q { break-inside: avoid; margin: 6mm 0; }\n"
         ".note { color: #444; font-size: 10pt; }\n.right { color: #2e8b3a; }\n.wrong { color: #c0392b; }\n"
         "</style>\n</head>\n<body>\n<h1>Marks: "
      << escape(key.lesson) << "</h1>\n<p class=\"note\">" << students.size() << " students from "
      << escape(answers_name) << ", marked against " << escape(key.file)
      << ": an answer is right within the question's tolerance of the engine's answer for that student's own "
         "numbers, after its unit is converted.</p>\n";
    // The questions the class got wrong: fewer than half of the answers right.
    std::vector<const QuestionSummary*> hard;
    for (const QuestionSummary& q : qs)
        if (q.answered > 0 && 2 * q.right < q.answered) hard.push_back(&q);
    o << "<h2>Questions the class got wrong</h2>\n";
    if (hard.empty()) o << "<p>None: every question was right in at least half of the answers.</p>\n";
    else {
        o << "<ul>\n";
        for (const QuestionSummary* q : hard) {
            o << "<li><a href=\"#q" << q->question << "\">Question " << q->question << "</a> (" << html::math(q->words)
              << "): " << q->right << " of " << q->answered << " right";
            if (!q->common_slip.empty()) o << "; most often " << escape(q->common_slip);
            o << "</li>\n";
        }
        o << "</ul>\n";
    }
    o << "<h2>Per question</h2>\n<table>\n<tr><th colspan=\"2\">question</th><th>right</th><th>answered</th>"
         "<th>most common wrong answer</th></tr>\n";
    for (const QuestionSummary& q : qs) {
        o << "<tr" << (q.answered > 0 && 2 * q.right < q.answered ? " class=\"low\"" : "") << "><td class=\"num\">"
          << q.question << "</td><td>" << html::math(q.words) << "&nbsp;("
          << escape(q.unit.empty() ? "a count" : q.unit) << ")</td><td class=\"num\">" << q.right
          << "</td><td class=\"num\">" << q.answered << " of " << q.students << "</td><td>";
        if (q.common_count == 0) o << "\u2013";
        else if (!q.common_slip.empty()) o << escape(q.common_slip) << " (" << q.common_count << ")";
        else o << sig(q.common_ratio, 2) << " \u00d7 the right value (" << q.common_count << "; no known slip)";
        o << "</td></tr>\n";
    }
    o << "</table>\n";
    for (const QuestionSummary& q : qs) {
        double tol = 0.0;
        for (const Mark& m : marks)
            if (m.question == q.question && m.key) tol = m.key->tolerance;
        o << "<div class=\"q\" id=\"q" << q.question << "\">\n<h3>Question " << q.question << ": "
          << html::math(q.words) << "</h3>\n<p><span class=\"right\">" << q.right
          << " right</span>, <span class=\"wrong\">" << q.answered - q.right << " wrong</span>, "
          << q.students - q.answered << " not answered.";
        if (q.common_count > 0) {
            o << " The most common wrong answer: ";
            if (!q.common_slip.empty()) o << "<b>" << escape(q.common_slip) << "</b>";
            else o << sig(q.common_ratio, 2) << " \u00d7 the right value (it matches no slip we know)";
            o << ", " << q.common_count << " time" << (q.common_count == 1 ? "" : "s") << ".";
        }
        o << "</p>\n" << histogram_svg(q, tol) << "</div>\n";
    }
    o << "<h2>Per student</h2>\n<table>\n<tr><th>student</th><th>question</th><th>answer</th><th>right value</th>"
         "<th>mark</th><th>note</th></tr>\n";
    for (const Mark& m : marks) {
        o << "<tr><td class=\"num\">" << m.student << "</td><td class=\"num\">" << m.question << "</td><td>"
          << escape(m.given) << "</td><td>" << (m.key ? value_text(m.key->value) + " " + escape(m.key->unit) : "")
          << "</td><td class=\"num " << (m.right ? "right" : "wrong") << "\">" << (m.right ? 1 : 0) << "</td><td>"
          << escape(m.note) << (m.slip.empty() ? "" : (m.note.empty() ? "" : "; ") + escape(m.slip)) << "</td></tr>\n";
    }
    o << "</table>\n</body>\n</html>\n";
    return o.str();
}

}  // namespace collide
