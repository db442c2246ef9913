#include "teach/html.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "scenario/lesson.h"
#include "teach/event_problem.h"
#include "teach/notation.h"
#include "teach/solve.h"

namespace collide::html {

namespace {

// Plot labels are read by students: 4 significant figures, as their answers.
std::string n(double x) { return notation::num_answer(std::abs(x) < 1e-12 ? 0.0 : x); }

}  // namespace

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

// Text in our notation (v_pa, I_a⁻¹) as HTML: escaped, subscripts as <sub>, and the plain
// superscripts lesson texts write (I^-1, R^T) as <sup>.
namespace {

// math() with the markup of a superscript and a subscript given: HTML's <sup>/<sub>, or SVG's
// <tspan> (inside an SVG <text> an HTML element is not drawn: "p<sub>x</sub>" reads "p x").
struct SubSup {
    const char *sup_open, *sup_close, *sub_open, *sub_close;
};
std::string math_with(const std::string& text, const SubSup& m) {
    const std::string rich = notation::to_rich(text);  // v_{pa}
    std::string out;
    for (std::size_t i = 0; i < rich.size();) {
        if (rich[i] == '^' && i + 1 < rich.size()) {
            std::size_t j = i + 1;
            if (rich[j] == '-') ++j;
            while (j < rich.size() && std::isalnum(static_cast<unsigned char>(rich[j]))) ++j;
            if (j > i + 1 && std::isalnum(static_cast<unsigned char>(rich[j - 1]))) {
                std::string sup = rich.substr(i + 1, j - i - 1);
                if (sup[0] == '-') sup = "\u2212" + sup.substr(1);
                out += m.sup_open + escape(sup) + m.sup_close;
                i = j;
                continue;
            }
        }
        if (rich.compare(i, 2, "_{") == 0) {
            const std::size_t close = rich.find('}', i + 2);
            if (close != std::string::npos) {
                out += m.sub_open + escape(rich.substr(i + 2, close - i - 2)) + m.sub_close;
                i = close + 1;
                continue;
            }
        }
        out += escape(std::string(1, rich[i]));
        ++i;
    }
    return out;
}

}  // namespace

std::string math(const std::string& text) { return math_with(text, {"<sup>", "</sup>", "<sub>", "</sub>"}); }

std::string svg_math(const std::string& text) {
    return math_with(text, {"<tspan baseline-shift=\"super\" font-size=\"9\">", "</tspan>",
                            "<tspan baseline-shift=\"sub\" font-size=\"9\">", "</tspan>"});
}

// **bold** as <strong> in text math() has made (which leaves * alone).
std::string strong(const std::string& html) {
    std::string out;
    std::size_t at = 0;
    for (std::size_t open; (open = html.find("**", at)) != std::string::npos;) {
        const std::size_t close = html.find("**", open + 2);
        if (close == std::string::npos || close == open + 2) break;
        out += html.substr(at, open - at) + "<strong>" + html.substr(open + 2, close - open - 2) + "</strong>";
        at = close + 2;
    }
    return out + html.substr(at);
}

// A paragraph's text: `code` as it is written (commands, file names: no subscripts), the rest
// in our notation, **bold**.
std::string inline_text(const std::string& text) {
    std::string out;
    std::size_t at = 0;
    for (std::size_t open; (open = text.find('`', at)) != std::string::npos;) {
        const std::size_t close = text.find('`', open + 1);
        if (close == std::string::npos) break;
        out += strong(math(text.substr(at, open - at))) + "<code>" + escape(text.substr(open + 1, close - open - 1)) +
               "</code>";
        at = close + 1;
    }
    return out + strong(math(text.substr(at)));
}

// Paragraphs separated by blank lines; in a paragraph, lines that start with "- " are the items
// of a list (an item goes on over the lines after it that do not start one); **bold**, `code`.
std::string paragraphs(const std::string& text) {
    std::string out, para;
    std::vector<std::string> items;
    const auto flush = [&] {
        if (!para.empty()) out += "<p>" + inline_text(para) + "</p>\n";
        if (!items.empty()) {
            out += "<ul>\n";
            for (const std::string& item : items) out += "<li>" + inline_text(item) + "</li>\n";
            out += "</ul>\n";
        }
        para.clear();
        items.clear();
    };
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos) {
            flush();
        } else if (line.compare(first, 2, "- ") == 0) {
            items.push_back(line.substr(first + 2));
        } else if (!items.empty()) {
            items.back() += ' ' + line.substr(first);
        } else {
            if (!para.empty()) para += ' ';
            para += line;
        }
    }
    flush();
    return out;
}

std::string svg_plot(const std::string& title, const std::vector<double>& t, const std::vector<Series>& series,
                     const std::vector<double>& collisions, double duration, const std::string& x_unit) {
    // The keys go right-aligned on the title line, or on a line of their own below it when
    // they do not fit there (the plot starts lower).
    const auto text_width = [](const std::string& text) {  // about 8 px a character (not a byte)
        double chars = 0;
        for (unsigned char c : text) chars += (c & 0xC0) != 0x80;
        return 8.0 * chars;
    };
    double keys_width = 0;
    for (const Series& s : series) keys_width += text_width(s.label) + 34;
    const double W = 560, left = 64, right = 16, bottom = 34;
    const bool keys_below = left + text_width(title) + 16 + keys_width > W - right;
    const double top = keys_below ? 52 : 34, H = keys_below ? 248 : 230;
    double lo = 0, hi = 0;
    bool first = true;
    for (const Series& s : series)
        for (double v : s.values) {
            lo = first ? v : std::min(lo, v);
            hi = first ? v : std::max(hi, v);
            first = false;
        }
    const double data_lo = lo, data_hi = hi;  // labelled where they are
    if (lo > 0 && lo < 0.5 * hi) lo = 0;
    if (hi < 0 && hi > 0.5 * lo) hi = 0;
    const double span = hi - lo;
    const double pad = span > 1e-12 * std::max(1.0, std::abs(hi)) ? 0.08 * span : std::max(0.05 * std::abs(hi), 1e-3);
    lo -= pad;
    hi += pad;
    const double T = duration > 0 ? duration : 1;
    const auto X = [&](double x) { return left + (W - left - right) * x / T; };
    const auto Y = [&](double y) { return top + (H - top - bottom) * (hi - y) / (hi - lo); };
    char buf[256];
    std::ostringstream o;
    o << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " << W << " " << H
      << "\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"12\" role=\"img\" aria-label=\"" << escape(title)
      << "\">\n";
    o << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
    o << "<text x=\"" << left << "\" y=\"18\" font-weight=\"bold\">" << escape(title) << "</text>\n";
    double kx = keys_below ? std::max(8.0, W - right - keys_width) : W - right - keys_width;
    const double ky = keys_below ? 38 : 18;
    for (const Series& key : series) {
        std::snprintf(buf, sizeof buf,
                      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"3\"/>", kx,
                      ky - 4, kx + 20, ky - 4, key.colour.c_str());
        o << buf << "<text x=\"" << kx + 25 << "\" y=\"" << ky << "\">" << svg_math(key.label) << "</text>\n";
        kx += text_width(key.label) + 34;
    }
    // Axes, zero, collisions.
    std::snprintf(buf, sizeof buf, "<path d=\"M%.1f %.1f V%.1f H%.1f\" fill=\"none\" stroke=\"#999\"/>\n", left, top,
                  H - bottom, W - right);
    o << buf;
    if (lo < 0 && hi > 0) {
        std::snprintf(
            buf, sizeof buf,
            "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ccc\" stroke-dasharray=\"4 4\"/>\n", left,
            Y(0), W - right, Y(0));
        o << buf;
    }
    for (double c : collisions) {
        std::snprintf(
            buf, sizeof buf,
            "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ce2029\" stroke-opacity=\"0.25\"/>\n",
            X(c), top, X(c), H - bottom);
        o << buf;
    }
    // The largest and smallest values, at their heights (one label when they are equal).
    o << "<text x=\"" << left - 6 << "\" y=\"" << Y(data_hi) + 4 << "\" text-anchor=\"end\" fill=\"#555\">"
      << escape(n(data_hi)) << "</text>\n";
    if (Y(data_lo) - Y(data_hi) > 14)
        o << "<text x=\"" << left - 6 << "\" y=\"" << Y(data_lo) + 4 << "\" text-anchor=\"end\" fill=\"#555\">"
          << escape(n(data_lo)) << "</text>\n";
    o << "<text x=\"" << left << "\" y=\"" << H - bottom + 18 << "\" fill=\"#555\">0</text>\n";
    o << "<text x=\"" << W - right << "\" y=\"" << H - bottom + 18 << "\" text-anchor=\"end\" fill=\"#555\">"
      << escape(n(T)) << " " << escape(x_unit) << "</text>\n";
    o << "<text x=\"" << 0.5 * (left + W - right) << "\" y=\"" << H - 6
      << "\" text-anchor=\"middle\" fill=\"#555\">time (" << escape(x_unit) << ")</text>\n";
    for (const Series& s : series) {
        o << "<polyline fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"2\" points=\"";
        const std::size_t stride = std::max<std::size_t>(1, t.size() / 600);
        for (std::size_t k = 0; k < t.size(); k += stride) {
            std::snprintf(buf, sizeof buf, "%.1f,%.1f ", X(t[k]), Y(s.values[k]));
            o << buf;
        }
        if (!t.empty()) {
            std::snprintf(buf, sizeof buf, "%.1f,%.1f", X(t.back()), Y(s.values.back()));
            o << buf;
        }
        o << "\"/>\n";
    }
    o << "</svg>\n";
    return o.str();
}

namespace {
// Tick marks at 1, 2 or 5 times a power of ten, about five across [lo, hi].
std::vector<double> ticks(double lo, double hi) {
    std::vector<double> out;
    const double span = hi - lo;
    if (!(span > 0)) return out;
    const double raw = span / 5, p = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = raw / p < 1.5 ? p : raw / p < 3.5 ? 2 * p : raw / p < 7.5 ? 5 * p : 10 * p;
    for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step)
        out.push_back(std::abs(v) < 1e-9 * step ? 0.0 : v);
    return out;
}
std::string tick_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return notation::true_minus(buf);
}
// 10 to a whole power, its exponent in superscript digits: "10⁻⁶".
std::string power_of_ten(int d) {
    static const char* const digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    std::string e;
    for (int a = std::abs(d); a > 0 || e.empty(); a /= 10) e = digits[a % 10] + e;
    return "10" + std::string(d < 0 ? "⁻" : "") + e;
}
}  // namespace

std::string svg_xy_plot(const std::string& title, const std::string& x_label, const std::string& y_label,
                        const std::vector<XYSeries>& series, const std::optional<XYLine>& line, bool log_y) {
    const double W = 560, H = 280, left = 72, right = 16, bottom = 46;
    // The keys (several series, or a fitted line beside its points), in rows that wrap at the
    // plot's width; the plot starts below them. The title is the page's heading, not drawn
    // here (it is the SVG's <title> and label).
    const auto text_width = [](const std::string& text) {  // about 7 px a character (not a byte) at 12 px
        double chars = 0;
        for (unsigned char c : text) chars += (c & 0xC0) != 0x80;
        return 7.0 * chars;
    };
    struct Key {
        std::string label, colour;
        bool dashed = false;
        double x = 0, y = 0;
    };
    std::vector<Key> keys;
    if (series.size() > 1 || line) {
        for (const XYSeries& s : series) keys.push_back({s.label, s.colour});
        if (line) keys.push_back({line->label, "#555", true});
    }
    // The y axis's label reads across, above the axis (a rotated one of 40 characters does not
    // fit beside it); the keys' rows below it.
    double kx = left, ky = 38;
    for (Key& k : keys) {
        const double w = 30 + text_width(k.label);
        if (kx > left && kx + w > W - right) {
            kx = left;
            ky += 17;
        }
        k.x = kx;
        k.y = ky;
        kx += w + 14;
    }
    const double top = keys.empty() ? 30 : ky + 12;
    double xlo = 0, xhi = 0, ylo = 0, yhi = 0;
    bool first = true;
    for (const XYSeries& s : series)
        for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
            if (log_y && !(s.y[k] > 0)) continue;  // not on a log scale (said by the caller)
            xlo = first ? s.x[k] : std::min(xlo, s.x[k]);
            xhi = first ? s.x[k] : std::max(xhi, s.x[k]);
            ylo = first ? s.y[k] : std::min(ylo, s.y[k]);
            yhi = first ? s.y[k] : std::max(yhi, s.y[k]);
            first = false;
        }
    // A log scale: y as its power of ten, from a whole decade below to one above.
    const auto ly = [&](double y) { return log_y ? std::log10(y) : y; };
    if (log_y) {
        if (first) ylo = yhi = 1;
        ylo = std::floor(std::log10(ylo));
        yhi = std::ceil(std::log10(yhi));
        if (yhi <= ylo) yhi = ylo + 1;
    } else {
        if (ylo > 0 && ylo < 0.5 * yhi) ylo = 0;
        if (yhi < 0 && yhi > 0.5 * ylo) yhi = 0;
    }
    if (xlo > 0 && xlo < 0.5 * xhi) xlo = 0;
    const auto widen = [](double& lo, double& hi) {
        const double span = hi - lo;
        const double pad =
            span > 1e-12 * std::max(1.0, std::abs(hi)) ? 0.06 * span : std::max(0.05 * std::abs(hi), 1e-3);
        lo -= pad;
        hi += pad;
    };
    widen(xlo, xhi);
    if (!log_y) widen(ylo, yhi);
    const auto X = [&](double x) { return left + (W - left - right) * (x - xlo) / (xhi - xlo); };
    const auto Y = [&](double y) { return top + (H - top - bottom) * (yhi - ly(y)) / (yhi - ylo); };
    char buf[256];
    std::ostringstream o;
    o << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " << W << " " << H
      << "\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"12\" role=\"img\" aria-label=\"" << escape(title)
      << "\">\n<title>" << escape(title) << "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
    // Keys (plain text: no HTML inside SVG text).
    for (const Key& k : keys) {
        std::snprintf(buf, sizeof buf,
                      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"%s\"%s/>",
                      k.x, k.y - 4, k.x + 22, k.y - 4, k.colour.c_str(), k.dashed ? "1.5" : "3",
                      k.dashed ? " stroke-dasharray=\"6 4\"" : "");
        o << buf << "<text x=\"" << k.x + 28 << "\" y=\"" << k.y << "\">" << escape(k.label) << "</text>\n";
    }
    // Grid, ticks and axes. On a log scale: every whole decade, labelled at most six times
    // (10⁻³ rather than 0.001 below 0.01).
    std::vector<std::pair<double, std::string>> yticks;
    if (log_y) {
        const int d0 = static_cast<int>(ylo), d1 = static_cast<int>(yhi);
        const int every = std::max(1, (d1 - d0 + 5) / 6);
        for (int d = d1; d >= d0; d -= every) {
            yticks.emplace_back(std::pow(10.0, d), d >= -2 && d <= 3 ? tick_text(std::pow(10.0, d)) : power_of_ten(d));
        }
    } else {
        for (double v : ticks(ylo, yhi)) yticks.emplace_back(v, tick_text(v));
    }
    for (const auto& [v, text] : yticks) {
        std::snprintf(buf, sizeof buf, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#e5e5e5\"/>",
                      left, Y(v), W - right, Y(v));
        o << buf << "<text x=\"" << left - 6 << "\" y=\"" << Y(v) + 4 << "\" text-anchor=\"end\" fill=\"#555\">"
          << escape(text) << "</text>\n";
    }
    for (double v : ticks(xlo, xhi)) {
        std::snprintf(buf, sizeof buf, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#e5e5e5\"/>",
                      X(v), top, X(v), H - bottom);
        o << buf << "<text x=\"" << X(v) << "\" y=\"" << H - bottom + 16 << "\" text-anchor=\"middle\" fill=\"#555\">"
          << escape(tick_text(v)) << "</text>\n";
    }
    std::snprintf(buf, sizeof buf, "<path d=\"M%.1f %.1f V%.1f H%.1f\" fill=\"none\" stroke=\"#777\"/>\n", left, top,
                  H - bottom, W - right);
    o << buf;
    o << "<text x=\"" << 0.5 * (left + W - right) << "\" y=\"" << H - 8 << "\" text-anchor=\"middle\" fill=\"#333\">"
      << escape(x_label) << "</text>\n";
    o << "<text x=\"8\" y=\"16\" fill=\"#333\">" << escape(y_label) << "</text>\n";
    if (line && !log_y) {
        std::snprintf(buf, sizeof buf,
                      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#555\" stroke-width=\"1.5\" "
                      "stroke-dasharray=\"6 4\"/>\n",
                      X(line->x0), Y(line->intercept + line->slope * line->x0), X(line->x1),
                      Y(line->intercept + line->slope * line->x1));
        o << buf;
    }
    for (const XYSeries& s : series) {
        const std::size_t n = std::min(s.x.size(), s.y.size());
        if (s.points) {
            for (std::size_t k = 0; k < n; ++k) {
                if (log_y && !(s.y[k] > 0)) continue;
                std::snprintf(buf, sizeof buf, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\" fill=\"%s\"/>\n", X(s.x[k]),
                              Y(s.y[k]), s.colour.c_str());
                o << buf;
            }
        } else {
            o << "<polyline fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"2\" points=\"";
            for (std::size_t k = 0; k < n; ++k) {
                if (log_y && !(s.y[k] > 0)) continue;
                std::snprintf(buf, sizeof buf, "%.1f,%.1f ", X(s.x[k]), Y(s.y[k]));
                o << buf;
            }
            o << "\"/>\n";
        }
    }
    o << "</svg>\n";
    return o.str();
}

std::string worked_html(const SolveProblem& P, const Solution& S, const std::string& world_note) {
    const notation::StudentNumbers student;  // 4 figures, no floating-point noise
    std::ostringstream o;
    int k = 0;
    for (const WorkedStep& st : worked_steps(P, S)) {
        o << "<h3>" << ++k << ". " << math(st.title) << "</h3>\n";
        for (std::size_t i = 0; i < st.lines.size(); ++i)
            o << "<div class=\"math" << (st.response && i + 1 == st.lines.size() ? " result" : "") << "\">"
              << math(st.lines[i]) << "</div>\n";
        for (const std::string& note : st.notes) o << "<p class=\"note\">" << math(note) << "</p>\n";
    }
    if (!world_note.empty()) o << "<p class=\"note\">" << math(world_note) << "</p>\n";
    return o.str();
}

std::string worked_html_beside_run(const SolveProblem& P, const Solution& alone, const Solution& run,
                                   const std::string& world_note) {
    if (!resolved_differs(P, alone, run)) return worked_html(P, alone, world_note);
    std::ostringstream o;
    const SimplifiedLabel label = simplified_label(P);
    o << "<p class=\"simplified\"><strong>" << escape(label.lead) << "</strong> " << escape(label.rest) << "</p>\n"
      << worked_html(P, alone, "");
    o << "<table class=\"beside\">\n<tr><th></th><th>the two alone (above)</th><th>the run</th></tr>\n";
    for (const ResultBeside& r : results_beside(P, alone, run))
        o << "<tr><td>" << escape(r.what) << " (" << escape(r.unit) << ")</td><td>" << escape(r.alone) << "</td><td>"
          << escape(r.run) << "</td></tr>\n";
    o << "</table>\n";
    return o.str();
}

}  // namespace collide::html
