// Worked examples read as a student reads them: every equation "X = formula = numbers =
// result" of `collide solve`'s text and Markdown reports is parsed and recomputed here, with
// an evaluator of its own (nothing from teach/): each numeric substitution must give the
// printed result, and each formula, evaluated with the values the example gave before (its
// "Given" and earlier results), must give it too. So a wrong number, a wrong sign or a
// substituted value that is not the input fails, in every bundled example and format.
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "teach/html.h"
#include "teach/notation.h"
#include "teach/solve.h"

namespace collide {
namespace {

namespace fs = std::filesystem;

// A number or a vector.
struct Value {
    std::vector<double> x;
    bool vector = false;
    double scale() const {
        double s = 0;
        for (double v : x) s = std::max(s, std::abs(v));
        return s;
    }
};

// Recursive descent over one expression of the report's notation:
//   sum := product (("+" | "-" | "−") product)*
//   product := unary (("×" | "·" | "/") unary | unary)*     juxtaposition multiplies
//   unary := ("-" | "−") unary | primary
//   primary := number | identifier | "(" sum ("," sum)* ")"
// In 2D, "×" of a number and a vector is the page's ω × r = ω (−r_y, r_x); of two vectors,
// the scalar cross product. Fails (nullopt) on anything else: unknown names, matrices, |.|.
class Evaluator {
public:
    Evaluator(const std::map<std::string, Value>& names, int dimension) : names_(names), dim_(dimension) {}

    std::optional<Value> parse(const std::string& text, bool whole, double* largest) {
        s_ = text;
        i_ = 0;
        ok_ = true;
        largest_ = 0;
        // A result (not whole): one number or vector, its unit or remark after it.
        Value v = whole ? sum() : unary_literal();
        skip();
        if (!ok_ || (whole && i_ != s_.size())) return std::nullopt;
        if (largest) *largest = largest_;
        return v;
    }

private:
    void skip() {
        while (i_ < s_.size() && s_[i_] == ' ') ++i_;
    }
    bool take(const std::string& token) {
        skip();
        if (s_.compare(i_, token.size(), token) == 0) {
            i_ += token.size();
            return true;
        }
        return false;
    }
    bool starts_primary() {
        skip();
        if (i_ >= s_.size()) return false;
        const unsigned char c = static_cast<unsigned char>(s_[i_]);
        return std::isdigit(c) || c == '(' || std::isalpha(c) || s_.compare(i_, 2, "\u03C9") == 0 ||
               s_.compare(i_, 2, "\u03BC") == 0;
    }
    Value fail() {
        ok_ = false;
        return {};
    }
    Value sum() {
        Value v = product();
        while (ok_) {
            if (take("+")) v = add(v, product(), 1.0);
            else if (take("\u2212") || take("-")) v = add(v, product(), -1.0);
            else break;
        }
        return v;
    }
    Value product() {
        Value v = unary();
        while (ok_) {
            if (take("\u00D7")) v = cross(v, unary());
            else if (take("\u00B7")) v = dot(v, unary());
            else if (take("/")) v = divide(v, unary());
            else if (starts_primary()) v = scale(v, unary());
            else break;
        }
        return v;
    }
    Value unary() {
        if (take("\u2212") || take("-")) {
            Value v = unary();
            for (double& x : v.x) x = -x;
            return v;
        }
        return primary();
    }
    // A signed number, or a vector of them.
    Value unary_literal() {
        skip();
        const bool negative = take("\u2212") || take("-");
        skip();
        if (i_ >= s_.size()) return fail();
        const unsigned char c = static_cast<unsigned char>(s_[i_]);
        if (!std::isdigit(c) && c != '(') return fail();
        Value v = primary();
        if (negative)
            for (double& x : v.x) x = -x;
        return v;
    }
    Value primary() {
        skip();
        if (!ok_ || i_ >= s_.size()) return fail();
        if (take("(")) {
            std::vector<Value> parts{sum()};
            while (ok_ && take(",")) parts.push_back(sum());
            if (!take(")")) return fail();
            if (parts.size() == 1) return parts[0];
            Value v;
            v.vector = true;
            for (const Value& p : parts) {
                if (p.vector || p.x.size() != 1) return fail();
                v.x.push_back(p.x[0]);
            }
            return v;
        }
        const unsigned char c = static_cast<unsigned char>(s_[i_]);
        if (std::isdigit(c)) {
            std::size_t used = 0;
            const double x = std::stod(s_.substr(i_), &used);
            i_ += used;
            largest_ = std::max(largest_, std::abs(x));
            return Value{{x}, false};
        }
        // A name: letters, ω, μ, then letters, digits, '_' and primes.
        std::size_t j = i_;
        const auto name_char = [&](bool first) {
            if (j >= s_.size()) return std::size_t{0};
            const unsigned char d = static_cast<unsigned char>(s_[j]);
            if (std::isalpha(d)) return std::size_t{1};
            if (!first && (std::isdigit(d) || d == '_')) return std::size_t{1};
            for (const char* g : {"\u03C9", "\u03BC"})
                if (s_.compare(j, 2, g) == 0) return std::size_t{2};
            if (!first && s_.compare(j, 3, "\u2032") == 0) return std::size_t{3};
            return std::size_t{0};
        };
        for (bool first = true; std::size_t n = name_char(first); first = false) j += n;
        const std::string name = s_.substr(i_, j - i_);
        if (name.empty()) return fail();
        const auto found = names_.find(name);
        if (found == names_.end()) return fail();
        i_ = j;
        largest_ = std::max(largest_, found->second.scale());
        return found->second;
    }

    Value add(const Value& a, const Value& b, double sign) {
        if (!ok_ || a.vector != b.vector || a.x.size() != b.x.size()) return fail();
        Value v = a;
        for (std::size_t k = 0; k < v.x.size(); ++k) v.x[k] += sign * b.x[k];
        return v;
    }
    Value scale(const Value& a, const Value& b) {
        if (!ok_) return fail();
        if (!a.vector && !b.vector) return Value{{a.x[0] * b.x[0]}, false};
        if (a.vector && b.vector) return fail();
        const Value& s = a.vector ? b : a;
        Value v = a.vector ? a : b;
        for (double& x : v.x) x *= s.x[0];
        return v;
    }
    Value cross(const Value& a, const Value& b) {
        if (!ok_) return fail();
        if (!a.vector && !b.vector) return scale(a, b);
        if (dim_ == 2) {
            if (!a.vector && b.x.size() == 2) return Value{{-a.x[0] * b.x[1], a.x[0] * b.x[0]}, true};
            if (a.vector && b.vector && a.x.size() == 2 && b.x.size() == 2)
                return Value{{a.x[0] * b.x[1] - a.x[1] * b.x[0]}, false};
            return fail();
        }
        if (a.vector && b.vector && a.x.size() == 3 && b.x.size() == 3)
            return Value{{a.x[1] * b.x[2] - a.x[2] * b.x[1], a.x[2] * b.x[0] - a.x[0] * b.x[2],
                          a.x[0] * b.x[1] - a.x[1] * b.x[0]},
                         true};
        return scale(a, b);
    }
    Value dot(const Value& a, const Value& b) {
        if (!ok_ || a.x.size() != b.x.size()) return fail();
        double s = 0;
        for (std::size_t k = 0; k < a.x.size(); ++k) s += a.x[k] * b.x[k];
        return Value{{s}, false};
    }
    Value divide(const Value& a, const Value& b) {
        if (!ok_ || b.vector || b.x[0] == 0) return fail();
        Value v = a;
        for (double& x : v.x) x /= b.x[0];
        return v;
    }

    const std::map<std::string, Value>& names_;
    int dim_;
    std::string s_;
    std::size_t i_ = 0;
    bool ok_ = true;
    double largest_ = 0;
};

// The Markdown report's LaTeX back in the text report's notation.
std::string from_latex(std::string s) {
    const std::pair<std::regex, std::string> rules[] = {
        {std::regex(R"(\$\$)"), ""},
        {std::regex(R"(\\,\\mathrm\{[^}]*(\{[^}]*\})?[^}]*\})"), " "},
        {std::regex(R"(\\text\{[^}]*\})"), " "},
        {std::regex(R"(,\\quad)"), ",  "},
        {std::regex(R"(\\quad)"), "  "},
        {std::regex(R"(,\\ )"), ", "},
        {std::regex(R"(\\times)"), "\u00D7"},
        {std::regex(R"(\\cdot)"), "\u00B7"},
        {std::regex(R"(\\omega ?)"), "\u03C9"},
        {std::regex(R"(\\mu ?)"), "\u03BC"},
        {std::regex(R"(_\{([^}]*)\})"), "_$1"},
        {std::regex(R"(')"), "\u2032"},
    };
    for (const auto& [re, with] : rules) s = std::regex_replace(s, re, with);
    return s;
}

std::vector<std::string> split(const std::string& s, const std::string& by) {
    std::vector<std::string> out;
    std::size_t from = 0;
    for (std::size_t at; (at = s.find(by, from)) != std::string::npos; from = at + by.size())
        out.push_back(s.substr(from, at - from));
    out.push_back(s.substr(from));
    return out;
}

std::string trim(const std::string& s) {
    const std::size_t a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// What reading a report found: how many values it recomputed, and the ones that disagree.
struct Reading {
    int checked = 0;
    std::vector<std::string> wrong;
    std::map<std::string, Value> names;  // every value the report gave a name
};

// `digits`: the significant digits the report prints (6; 4 for students).
Reading check_report(const std::string& report, int dimension, bool latex, int digits = 6) {
    Reading out;
    std::map<std::string, Value>& names = out.names;
    Evaluator eval(names, dimension);
    int& checked = out.checked;
    std::istringstream in(report);
    for (std::string line; std::getline(in, line);) {
        if (latex) line = from_latex(line);
        for (const std::string& equation : split(line, ",  ")) {
            const std::vector<std::string> parts = split(equation, " = ");
            if (parts.size() < 2) continue;
            // The result: the number or vector the last part starts with (a unit may follow).
            double largest = 0;
            const std::optional<Value> result = eval.parse(trim(parts.back()), false, &largest);
            if (!result) continue;
            for (std::size_t k = 1; k + 1 < parts.size(); ++k) {
                double operands = 0;
                const std::optional<Value> v = eval.parse(trim(parts[k]), true, &operands);
                if (!v) continue;
                ++checked;
                // The printed numbers have 6 significant digits: each step agrees to about 1e-5
                // of the largest number in it (differences of nearly equal numbers included);
                // with 4, to about 1e-3.
                const double unit = std::pow(10.0, 6 - digits);
                const double tolerance =
                    unit * (1e-4 * std::max(result->scale(), v->scale()) + 2e-5 * operands) + 1e-12;
                bool same = v->x.size() == result->x.size();
                for (std::size_t c = 0; same && c < v->x.size(); ++c)
                    same = std::abs(v->x[c] - result->x[c]) <= tolerance;
                if (!same)
                    out.wrong.push_back("\"" + trim(parts[k]) + "\" is not \"" + trim(parts.back()) + "\" in: " + line);
            }
            // A name given or worked out ("A (box): m_a = 2 kg", "r_a = ... = (0.1, 0.3) m").
            std::string name = trim(parts.front());
            if (const std::size_t colon = name.rfind(": "); colon != std::string::npos) name = name.substr(colon + 2);
            if (std::regex_match(name, std::regex(R"(([A-Za-z]|\xCF\x89|\xCE\xBC)[A-Za-z0-9_]*(\xE2\x80\xB2)?)")))
                names[name] = *result;
        }
    }
    return out;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const std::string& l : lines) s += l + "\n";
    return s;
}

std::vector<std::string> bundled_examples() {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(fs::path(COLLIDE_SOURCE_DIR) / "lessons/solve"))
        if (e.path().extension() == ".toml") out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

TEST(WorkedText, EveryStepOfEveryBundledExampleFollowsFromTheOneBefore) {
    for (const std::string& path : bundled_examples()) {
        SCOPED_TRACE(path);
        const SolveProblem problem = parse_solve_file(path);
        const Solution solution = solve(problem);
        std::ostringstream text, markdown;
        write_text(problem, solution, text);
        write_markdown(problem, solution, markdown);
        // At least the lever arms (2D, 3D), the contact velocities or u_n, the impulse and the
        // final velocities are recomputed: a report this checker could not read would fail.
        for (const bool latex : {false, true}) {
            const Reading r = check_report(latex ? markdown.str() : text.str(), problem.dimension, latex);
            EXPECT_GE(r.checked, 8) << (latex ? "markdown" : "text");
            EXPECT_TRUE(r.wrong.empty()) << (latex ? "markdown" : "text") << ":\n" << joined(r.wrong);
        }
    }
}

// The same for the numbers students read (the site, worksheets): 4 significant figures and
// no floating-point noise still give every step from the one before, to their precision.
TEST(WorkedText, StudentNumbersStillFollowStepByStep) {
    int shorter = 0;  // reports whose numbers the student's precision changed
    for (const std::string& path : bundled_examples()) {
        SCOPED_TRACE(path);
        const SolveProblem problem = parse_solve_file(path);
        const Solution solution = solve(problem);
        std::ostringstream text, six;
        write_text(problem, solution, six);
        {
            const notation::StudentNumbers student;
            write_text(problem, solution, text);
        }
        shorter += text.str() != six.str();
        const Reading r = check_report(text.str(), problem.dimension, false, 4);
        EXPECT_GE(r.checked, 8);
        EXPECT_TRUE(r.wrong.empty()) << joined(r.wrong);
    }
    EXPECT_GE(shorter, 3);
}

// The site's worked example (HTML, students' numbers) read the same way: its headings and math
// lines, tags undone (<sub>pa</sub> back to _pa, entities back to characters), follow step by
// step at 4 digits.
TEST(WorkedText, TheSitesHtmlWorkedExampleFollowsStepByStepToo) {
    for (const std::string& path : bundled_examples()) {
        SCOPED_TRACE(path);
        const SolveProblem problem = parse_solve_file(path);
        const std::string html = html::worked_html(problem, solve(problem), "");
        std::string text;
        const std::regex line(R"re(<(h3|div class="math[^"]*")>(.*?)</(h3|div)>)re");
        for (std::sregex_iterator m(html.begin(), html.end(), line), end; m != end; ++m) {
            std::string l = (*m)[2];
            l = std::regex_replace(l, std::regex("<sub>"), "_");
            l = std::regex_replace(l, std::regex("<sup>"), "^");
            l = std::regex_replace(l, std::regex("</?[a-z]+>"), "");
            l = std::regex_replace(l, std::regex("&amp;"), "&");
            l = std::regex_replace(l, std::regex("&lt;"), "<");
            l = std::regex_replace(l, std::regex("&gt;"), ">");
            text += l + "\n";
        }
        const Reading r = check_report(text, problem.dimension, false, 4);
        EXPECT_GE(r.checked, 8) << text;
        EXPECT_TRUE(r.wrong.empty()) << joined(r.wrong);
    }
}

// Noise of an exact event is 0 for students; a small value that is the whole vector is not.
TEST(WorkedText, StudentNumbersDropFloatingPointNoiseOnly) {
    const notation::StudentNumbers student;
    EXPECT_EQ(notation::vec(Vec3(0, -5.55112e-17, 0), 2).txt, "(0, 0)");
    EXPECT_EQ(notation::vec(Vec3(0.477912, 1.35083e-11, 0), 2).txt, "(0.4779, 0)");
    EXPECT_EQ(notation::vec(Vec3(2e-3, -1.5e-3, 0), 2).txt, "(0.002, -0.0015)");
    EXPECT_EQ(notation::num(-0.800003).txt, "-0.8");
    EXPECT_EQ(notation::num(1.23456e-4).tex, "0.0001235");
    // The island solver's residue on a box at rest (tower: 4.11e-10 m/s) is 0; a domino's real
    // 1.6e-6 N s impulse is not.
    EXPECT_EQ(notation::vec(Vec3(4.11e-10, 1.481e-10, -2.026e-10), 3).txt, "(0, 0, 0)");
    EXPECT_EQ(notation::num_text(-3.887e-9), "0");
    EXPECT_EQ(notation::vec(Vec3(-1.659e-6, 1.596e-5, 0), 2).txt, "(-1.659e-06, 1.596e-05)");
}

// The carts of lessons/solve/carts-1d.toml against the closed form of a 1D impact:
// P = (1 + e) m_a m_b / (m_a + m_b) (v_a - v_b), v_a' = v_a - P/m_a, v_b' = v_b + P/m_b.
TEST(WorkedText, TheCartsExampleEndsInTheClosedForm) {
    const SolveProblem problem = parse_solve_file(std::string(COLLIDE_SOURCE_DIR) + "/lessons/solve/carts-1d.toml");
    std::ostringstream text;
    write_text(problem, solve(problem), text);
    const Reading r = check_report(text.str(), 1, false);
    EXPECT_TRUE(r.wrong.empty()) << joined(r.wrong);
    std::map<std::string, Value> names = r.names;
    ASSERT_TRUE(names.count("m_a") && names.count("m_b") && names.count("v_a") && names.count("v_b") &&
                names.count("e"));
    const double ma = names["m_a"].x[0], mb = names["m_b"].x[0], va = names["v_a"].x[0], vb = names["v_b"].x[0];
    const double e = names["e"].x[0];
    const double P = (1 + e) * ma * mb / (ma + mb) * (va - vb);
    ASSERT_TRUE(names.count("P") && names.count("v_a\u2032") && names.count("v_b\u2032"));
    EXPECT_NEAR(names["P"].x[0], P, 1e-9);
    EXPECT_NEAR(names["v_a\u2032"].x[0], va - P / ma, 1e-9);
    EXPECT_NEAR(names["v_b\u2032"].x[0], vb + P / mb, 1e-9);
}

// The checker itself finds the mistake the issue names: j printed as 6 where the numbers give 3.
TEST(WorkedText, AWrongResultIsFound) {
    const std::string good = "4. Impulse\n   j = \u2212(1 + 0.5) \u00D7 (-3) / 1.5 = 3 N\u00B7s\n";
    const std::string bad = "4. Impulse\n   j = \u2212(1 + 0.5) \u00D7 (-3) / 1.5 = 6 N\u00B7s\n";
    const Reading g = check_report(good, 1, false), b = check_report(bad, 1, false);
    EXPECT_EQ(g.checked, 1);
    EXPECT_TRUE(g.wrong.empty());
    EXPECT_EQ(b.checked, 1);
    EXPECT_EQ(b.wrong.size(), 1u);
}

}  // namespace
}  // namespace collide
