// The Try-it panel of a lesson page (teach/html.h try_it_html, try_it_data_js): its sliders,
// picture, plots and numbers' places, the scripts that fill them (assets/site/try-it*.js), and
// the data they need.
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scenario/lesson.h"
#include "teach/html.h"
#include "teach/notation.h"

namespace collide::html {

namespace {

// A [[vary]] input's symbol in our notation: "m", "v_x", "ω_z", "x" (a position's x), "e".
std::string vary_symbol(const LessonVary& v) {
    static const char* const symbols[][2] = {
        {"mass", "m"},     {"v", "v"},        {"w", "ω"},      {"angle", "θ"},  {"restitution", "e"},
        {"friction", "μ"}, {"position", "x"}, {"radius", "r"}, {"length", "L"}, {"gravity", "g"}};
    static const char* const edges[] = {"width", "height", "depth"};
    const char axis = static_cast<char>('x' + std::max(0, v.component));
    if (v.component >= 0 && v.field == "position") return std::string(1, axis);
    if (v.component >= 0 && v.field == "size") return edges[v.component];
    std::string symbol = v.field;
    for (const auto& s : symbols)
        if (v.field == s[0]) symbol = s[1];
    if (v.component >= 0) symbol += std::string("_") + axis;
    return symbol;
}

}  // namespace

// The unit of a [[vary]] key's field, as a slider's label shows it ("" for a pure number).
std::string vary_unit(const std::string& field) {
    if (field == "mass") return "kg";
    if (field == "v" || field == "speed") return "m/s";
    if (field == "w") return "rad/s";
    if (field == "angle") return "rad";
    if (field == "position" || field == "x" || field == "length" || field == "width" || field == "height" ||
        field == "radius" || field == "size" || field == "offset")
        return "m";
    if (field == "inertia") return "kg m^2";
    if (field == "duration" || field == "output_dt") return "s";
    if (field == "gravity") return "m/s^2";
    return "";
}

// A slider's label in our notation: "m of A (kg)", "v_x of ball (m/s)", "e (restitution)",
// "x of domino 2 (m), and of domino 3, …, domino 15 in proportion".
std::string vary_label(const LessonVary& v) {
    const std::string symbol = vary_symbol(v);
    const std::string unit = vary_unit(v.field);
    if (v.body == "scene")
        return symbol + (symbol == v.key ? "" : " (" + v.key + ")") + (unit.empty() ? "" : ", " + unit);
    std::string label = symbol + " of " + v.body + (unit.empty() ? "" : " (" + unit + ")");
    const std::vector<std::string>& others = v.in_proportion;
    if (others.size() == 1) label += ", and of " + others[0] + " in proportion";
    if (others.size() == 2) label += ", and of " + others[0] + " and " + others[1] + " in proportion";
    if (others.size() > 2) label += ", and of " + others.front() + ", …, " + others.back() + " in proportion";
    return label;
}

// A number as an HTML attribute: the shortest decimal that reads back as the same double
// ("0.1", not "0.10000000000000001": a browser would take the longer one at its word, and a
// slider from 0 to 1 in such steps would stop at 0.9), without an exponent where one of 17
// digits or fewer does without ("30", not "3e+01"; a page's address shows these values).
std::string number_attr(double x) {
    std::string shortest;
    for (int precision = 1; precision <= 17; ++precision) {
        std::ostringstream o;
        o.precision(precision);
        o << x;
        if (std::stod(o.str()) != x) continue;
        if (o.str().find('e') == std::string::npos) return o.str();
        if (shortest.empty()) shortest = o.str();
    }
    if (!shortest.empty()) return shortest;
    std::ostringstream o;
    o.precision(17);
    o << x;
    return o.str();
}

// A query string's name as a URL writes it: every byte but letters, digits and -_.~ as %XX
// ("A (e=0.1).mass" -> "A%20%28e%3D0.1%29.mass"), as the panel's URLSearchParams reads it back.
std::string percent_encoded(const std::string& text) {
    std::string out;
    for (unsigned char c : text) {
        if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
            out += static_cast<char>(c);
        } else {
            char hex[4];
            std::snprintf(hex, sizeof hex, "%%%02X", c);
            out += hex;
        }
    }
    return out;
}

std::string try_it_html(const Lesson& L, double fps, const std::string& root) {
    const int d = L.scene.dimension;
    std::ostringstream o;
    o << "<section class=\"tryit noprint\" id=\"try-it\" aria-labelledby=\"tryit-heading\" data-fps=\""
      << number_attr(fps) << "\" data-dimension=\"" << d << "\">\n<h2 id=\"tryit-heading\">Try it</h2>\n"
      << "<p class=\"note\">The same engine as the figures, compiled to WebAssembly and running in this page: "
      << (L.vary.empty() ? "play the run frame by frame"
                         : "move a slider and it runs the lesson again with your numbers")
      << ", and works out the collision " << (L.figures.empty() ? "of the first impact" : "of the figure above")
      << " step by step. Nothing is sent anywhere.</p>\n";
    o << "<p class=\"tryit-status note\" role=\"status\">Loading the engine…</p>\n";
    if (L.vary.empty())
        o << "<p class=\"tryit-novary\">This lesson has no inputs to change: its file declares no [[vary]] ranges "
             "(docs/formats/lesson-files.md, \"The lesson's inputs\"), so the panel plays the lesson's own run.</p>\n";
    // Lines about the page's address (?A.mass=3): a name the lesson has no input for, a value
    // outside its range (try-it.js fills it in).
    o << "<ul class=\"tryit-query\" hidden></ul>\n";
    if (!L.vary.empty()) {
        o << "<div class=\"tryit-inputs\" role=\"group\" aria-label=\"The lesson's inputs\">\n";
        for (std::size_t k = 0; k < L.vary.size(); ++k) {
            const LessonVary& v = L.vary[k];
            const std::string id = "tryit-in-" + std::to_string(k + 1);
            o << "<div class=\"tryit-input\"><label for=\"" << id << "\">" << math(vary_label(v)) << "</label>"
              << "<input type=\"range\" id=\"" << id << "\" data-name=\"" << escape(v.name()) << "\" min=\""
              << number_attr(v.lo) << "\" max=\"" << number_attr(v.hi) << "\" step=\"" << number_attr(v.step)
              << "\" value=\"" << number_attr(v.lesson_value) << "\" data-lesson=\"" << number_attr(v.lesson_value)
              << "\"><output for=\"" << id << "\">" << escape(notation::num_text(v.lesson_value))
              << "</output></div>\n";
        }
        o << "<button type=\"button\" class=\"tryit-reset\">The lesson's values</button>\n</div>\n";
        std::string names;
        for (const LessonVary& v : L.vary) names += (names.empty() ? "" : ", ") + v.name();
        o << "<p class=\"tryit-names note\">The page's address sets them too: index.html?"
          << percent_encoded(L.vary[0].name()) << "=" << number_attr(L.vary[0].hi)
          << " (the inputs' names: " << escape(names) << ").</p>\n";
    }
    // The picture (3D: three.js draws on the first canvas, the labels and knobs go on the one over
    // it; try-it-3d.js), over it the handles a drag or the keyboard sets inputs with (try-it.js
    // puts them in: a focusable element at each handle, the picture draws them), what can be
    // dragged, and the last value a drag or a key set (read out by screen readers).
    o << (d == 3 ? "<div class=\"tryit-stage tryit-stage-3d\">\n" : "<div class=\"tryit-stage\">\n")
      << (d == 3 ? "<canvas class=\"tryit-scene3d\" width=\"960\" height=\"540\" aria-hidden=\"true\"></canvas>\n" : "")
      << "<canvas class=\"tryit-scene\" width=\"960\" height=\"" << std::array{0, 300, 480, 540}.at(d)
      << "\" role=\"img\" aria-label=\"The run with these inputs\"></canvas>\n<div class=\"tryit-handles\"></div>\n</div>\n";
    if (!L.vary.empty())
        o << "<p class=\"tryit-drag-help note\" hidden></p>\n<p class=\"tryit-drag-said\" aria-live=\"polite\"></p>\n";
    o << "<div class=\"player tryit-player\" role=\"group\" aria-label=\"Try-it playback\">\n"
         "<button type=\"button\" data-act=\"start\" aria-label=\"Back to the start, t = 0\">&#9664;&#9664; t = 0</button>\n"
         "<button type=\"button\" data-act=\"play\">Play / pause</button>\n"
         "<button type=\"button\" data-act=\"step\" aria-label=\"One frame forward\">step &#9654;</button>\n"
         "<span class=\"speeds\">speed <button type=\"button\" data-rate=\"0.25\" aria-pressed=\"false\">0.25&times;</button>\n"
         "<button type=\"button\" data-rate=\"1\" aria-pressed=\"true\">1&times;</button></span>\n"
         "<span class=\"time\" aria-live=\"off\"></span>\n</div>\n";
    o << "<canvas class=\"tryit-plot\" width=\"960\" height=\"220\" role=\"img\" aria-label=\"Energy against time\"></canvas>\n";
    // The lesson's [[plot]]s of the run with these inputs (try-it.js puts in what the engine draws).
    if (!L.plots.empty()) o << "<div class=\"tryit-lesson-plots\" data-plots=\"" << L.plots.size() << "\"></div>\n";
    // Any quantity against any other: a [[plot]] made with the selects, drawn by the engine
    // (try-it-plot.js fills the selects with the quantities the engine offers).
    o << "<section class=\"tryit-free-plot\" aria-label=\"Plot any quantity\">\n<h3>Plot any quantity</h3>\n"
         "<form class=\"tryit-free-plot-form\">\n"
         "<label>per <select name=\"per\"><option value=\"sample\">sample (every frame)</option>"
         "<option value=\"collision\">collision</option></select></label>\n"
         "<label>x <select name=\"x\"></select></label>\n<label>y <select name=\"y0\"></select></label>\n"
         "<label>and <select name=\"y1\"></select></label>\n<label>and <select name=\"y2\"></select></label>\n"
         "</form>\n<p class=\"tryit-free-plot-from note\" hidden></p>\n<div class=\"tryit-free-plot-out\"></div>\n"
         "<details class=\"tryit-free-plot-file\"><summary>This plot as a [[plot]] of a lesson file (to keep it on "
         "the lesson's page)</summary><pre class=\"tryit-free-plot-toml\"></pre></details>\n</section>\n";
    o << "<div class=\"tryit-numbers\" aria-live=\"polite\"></div>\n";
    o << "<details class=\"tryit-worked-box\" open><summary>The collision worked out with these numbers</summary>\n"
         "<div class=\"tryit-worked\"></div></details>\n";
    // (collide-engine.js and, in 3D, three.min.js, Debian's libjs-three, are not among them:
    // try-it.js loads them once the page's first answer is shown, so that their 2 MB and 850 KB
    // do not hold the page up)
    std::vector<std::string> scripts = {"try-it-picture.js", "try-it-drag.js", "try-it-plot.js", "try-it.js"};
    if (d == 3) scripts.insert(scripts.begin(), "try-it-3d.js");
    o << "<script src=\"try-it-lesson.js\"></script>\n";
    for (const std::string& js : scripts) o << "<script src=\"" << root << js << "\"></script>\n";
    o << "</section>\n";
    return o.str();
}

std::string try_it_data_js(const Lesson& L, const std::string& palette, const std::string& first) {
    return "// The Try-it panel's data (teach/html.h try_it_data_js): the lesson's file, the figures' colours\n"
           "// and the engine's answer for the lesson's own values.\n"
           "window.collideTryIt = {\"lesson\": " +
           nlohmann::json(L.source).dump() + ",\n\"palette\": " + palette +
           ",\n\"first\": " + (first.empty() ? std::string("null") : first) + "};\n";
}

}  // namespace collide::html
