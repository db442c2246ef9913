#include "teach/notation.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <utility>
#include <vector>

namespace collide::notation {

namespace {

// The end of the subscript that starts after the '_' at i: v_pa has the subscript "pa".
std::size_t subscript_end(const std::string& text, std::size_t i) {
    std::size_t j = i + 1;
    while (j < text.size() && std::isalnum(static_cast<unsigned char>(text[j]))) ++j;
    return j;
}

}  // namespace

std::string to_tex(const std::string& text) {
    static const std::vector<std::pair<std::string, std::string>> symbols = {
        {"ω", "\\omega "}, {"μ", "\\mu "},  {"Δ", "\\Delta "},      {"]×", "]_\\times "}, {"×", "\\times "},
        {"·", "\\cdot "},  {"⁻¹", "^{-1}"}, {"²", "^{2}"},          {"ᵀ", "^{T}"},        {"′", "'"},
        {"≥", "\\ge "},    {"≤", "\\le "},  {"→", "\\Rightarrow "}, {"−", "-"},           {"≈", "\\approx "},
        {"%", "\\%"},      {"‖", "\\|"},    {"✓", "\\checkmark "}};
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        bool matched = false;
        for (const auto& [from, to] : symbols) {
            if (text.compare(i, from.size(), from) == 0) {
                out += to;
                i += from.size();
                matched = true;
                break;
            }
        }
        if (matched) continue;
        // A wide gap between two formulas on one line ("M = 2 kg,  x_c = ...").
        if (text.compare(i, 2, "  ") == 0) {
            while (i < text.size() && text[i] == ' ') ++i;
            out += "\\quad ";
            continue;
        }
        // Subscripts: v_pa -> v_{pa}.
        if (text[i] == '_') {
            const std::size_t j = subscript_end(text, i);
            out += "_{" + text.substr(i + 1, j - i - 1) + "}";
            i = j;
            continue;
        }
        out += text[i++];
    }
    return out;
}

std::string to_rich(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t j = text[i] == '_' ? subscript_end(text, i) : i;
        out += j > i ? "_{" + text.substr(i + 1, j - i - 1) + "}" : std::string(1, text[i]);
        i = std::max(j, i + 1);
    }
    return out;
}

F words(const std::string& text) {
    // Text mode: escape what LaTeX would read as markup; keep wide gaps as \quad.
    std::string tex;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == ' ' && i + 1 < text.size() && text[i + 1] == ' ') {
            while (i + 1 < text.size() && text[i + 1] == ' ') ++i;
            tex += "\\quad ";
        } else if (std::string("_%&#$").find(c) != std::string::npos) {
            tex += std::string("\\") + c;
        } else if (c == '{' || c == '}') {
            tex += std::string("\\") + c;
        } else if (c == '^' || c == '~' || c == '\\') {
            tex += c == '^' ? "\\^{}" : c == '~' ? "\\~{}" : "\\textbackslash{}";
        } else {
            tex += c;
        }
    }
    return {text, "\\text{" + tex + "}"};
}

F unit(const std::string& u) {
    std::string tex;
    for (std::size_t i = 0; i < u.size();) {  // kg·m²/s -> kg\cdot m^{2}/s
        if (u.compare(i, 2, "·") == 0) {
            tex += "\\cdot ";
            i += 2;
        } else if (u.compare(i, 2, "²") == 0) {
            tex += "^{2}";
            i += 2;
        } else tex += u[i++];
    }
    return {" " + u, "\\,\\mathrm{" + tex + "}"};
}

namespace {
thread_local bool student = false;  // StudentNumbers
constexpr double kNoise = 1e-8;     // SI: shown as 0 for students
// Four significant digits of a vector's largest entry L place its last digit at L/1000 or
// L/10000 at the finest: an entry below 5e-5 L rounds to 0 at the vector's own precision.
constexpr double kRelativeNoise = 5e-5;

// A vector's or matrix's entries for students: those below 5e-5 of the largest set to 0.
double cleaned(double x, double largest) { return student && std::abs(x) < kRelativeNoise * largest ? 0.0 : x; }

// printf's %.Ng, but a number from 10 000 to under 1 000 000 written out ("20000", not
// "2e+04"): its rounded value has no more digits than its integer part.
std::string general(double x, int digits) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    const double rounded = std::strtod(buf, nullptr);
    if (std::abs(rounded) >= 1e4 && std::abs(rounded) < 1e6) std::snprintf(buf, sizeof buf, "%.0f", rounded);
    return buf;
}
}  // namespace

StudentNumbers::StudentNumbers() : was_(student) { student = true; }
StudentNumbers::~StudentNumbers() { student = was_; }

std::string num_text(double x) {
    if (student && std::abs(x) < kNoise) x = 0.0;
    if (x == 0.0) x = 0.0;  // no "-0"
    return general(x, student ? 4 : 6);
}

std::string num_answer(double x) {
    if (x == 0.0) x = 0.0;  // no "-0"
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", x);
    return buf;
}

std::string sig_text(double x, int digits) {
    if (std::abs(x) < 1e-12) return "0";
    return true_minus(general(x, digits));
}

std::string true_minus(std::string s) {
    if (!s.empty() && s[0] == '-') s = "\u2212" + s.substr(1);
    return s;
}

std::string components_text(const Vec3& v, int dim, std::string (*number)(double)) {
    if (dim == 1) return number(v.x());
    return "(" + number(v.x()) + ", " + number(v.y()) + (dim == 3 ? ", " + number(v.z()) : "") + ")";
}

std::string num_data(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", x);
    return buf;
}

F num(double x) {
    const std::string t = num_text(x);
    const std::size_t e = t.find('e');
    if (e == std::string::npos) return {t, t};
    const int exponent = std::atoi(t.c_str() + e + 1);
    return {t, t.substr(0, e) + "\\times 10^{" + std::to_string(exponent) + "}"};
}

F vec(const Vec3& v, int dim) {
    if (dim == 1) return num(v.x());
    F out{"(", "("};
    const double largest = v.head(dim).cwiseAbs().maxCoeff();
    for (int i = 0; i < dim; ++i) {
        if (i) out = out + F{", ", ",\\ "};
        out = out + num(cleaned(v[i], largest));
    }
    return out + F{")", ")"};
}

F spin(const Vec3& w, int dim) { return dim == 2 ? num(w.z()) : vec(w, 3); }

F mat(const Mat3& m, int dim) {
    const int n = dim == 3 ? 3 : dim == 2 ? 2 : 1;
    F out{"[", "\\begin{pmatrix}"};
    const double largest = m.topLeftCorner(n, n).cwiseAbs().maxCoeff();
    for (int i = 0; i < n; ++i) {
        out = out + F{i ? ", [" : "[", i ? " \\\\ " : ""};
        for (int j = 0; j < n; ++j) out = out + F{j ? ", " : "", j ? " & " : ""} + num(cleaned(m(i, j), largest));
        out = out + F{"]", ""};
    }
    return out + F{"]", "\\end{pmatrix}"};
}

}  // namespace collide::notation
