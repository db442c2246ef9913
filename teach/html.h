// HTML and SVG for the teaching material (collide material) and the files collide render
// writes beside the frames: text in our notation as HTML, and line plots as SVG.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace collide {
struct SolveProblem;
struct Solution;
struct Lesson;
struct LessonVary;
}  // namespace collide

namespace collide::html {

// &, <, >, " escaped.
std::string escape(const std::string& s);
// Text in our notation (v_pa, I_a⁻¹) as HTML: escaped, subscripts as <sub>, and the plain
// superscripts lesson texts write (I^-1, R^T) as <sup>.
std::string math(const std::string& text);
// The same inside an SVG <text>: the subscripts and superscripts as <tspan> (an HTML element
// there is not drawn: p<sub>x</sub> reads "p x").
std::string svg_math(const std::string& text);
// Paragraphs separated by blank lines, each as <p> (math()); lines that start with "- " as the
// items of a list (<ul>), **bold** as <strong> and `code` as <code> (as written, no subscripts).
std::string paragraphs(const std::string& text);

// A collision worked out (the lesson pages of collide material, the answer key of collide
// worksheet): each step's formula, then its numbers (the response's last line marked as the
// result), its notes, and `world_note` (the world's note when it resolved several points; ""
// for none).
std::string worked_html(const SolveProblem& problem, const Solution& solution, const std::string& world_note);
// One collision worked out where the run may have resolved it with other contacts of the same
// instant: `alone` is solve()'s (the two bodies alone), `run` the run's outcome (as_resolved in
// teach/event_problem.h). Where they differ (resolved_differs), the calculation is labelled "A
// simplified calculation: a and b alone" and a table sets its results beside the run's; else
// worked_html(problem, alone, world_note). The site's pages and the Try-it panel show it.
std::string worked_html_beside_run(const SolveProblem& problem, const Solution& alone, const Solution& run,
                                   const std::string& world_note);

struct Series {
    std::string label;           // in our notation (p_x)
    std::string colour;          // CSS colour
    std::vector<double> values;  // one per time
};
// A line plot (560 x 230, white): the series against t from 0 to `duration` (in x_unit),
// faint red vertical lines at `collisions`, the largest and smallest values labelled.
std::string svg_plot(const std::string& title, const std::vector<double>& t, const std::vector<Series>& series,
                     const std::vector<double>& collisions, double duration, const std::string& x_unit = "s");

// A plot of y against x (560 x 280, white): a lesson's [[plot]] (present/lesson_plots.h). Each
// series as a line (per sample) or as points (per collision); `line`, when given, the fitted
// straight line, dashed, over its x range. Ticks at round numbers; the axes' labels carry the
// units ("t (s)"; y's across, above the axis). Labels are plain text. The title is the SVG's <title> and aria-label, not
// drawn (the page's heading shows it); keys only for several series or a fitted line, in rows
// that wrap. `log_y`: y on a logarithmic scale (whole decades; a geometric sequence, such as a
// bouncing ball's intervals, as a straight line); values not above 0 are left out of it (the
// caller says so), and so is `line`.
struct XYSeries {
    std::string label;
    std::string colour;
    std::vector<double> x, y;
    bool points = false;
};
struct XYLine {
    double slope = 0, intercept = 0, x0 = 0, x1 = 0;
    std::string label;  // its key: "fit: 0.0378 s per domino"
};
std::string svg_xy_plot(const std::string& title, const std::string& x_label, const std::string& y_label,
                        const std::vector<XYSeries>& series, const std::optional<XYLine>& line, bool log_y = false);

// The "Try it" panel of a lesson page (collide material, when the site has the WebAssembly
// module collide-engine.js; docs/commands/material.md, "The Try-it panel"): a slider for each of the lesson's
// [[vary]] inputs (its range and step, set at the lesson's own value), a canvas that plays the
// run (3D: with three.js, `root`three.min.js and try-it-3d.js), play / pause / 0.25x / step, the
// impulse, energy and momentum of the page's collision and its worked example, all recomputed
// by the engine in the page (assets/site/try-it.js, with `root`collide-engine.js); `fps` is the
// frames' rate. The data the script needs is try_it_data_js's, in the page's folder as
// try-it-lesson.js. A query string such as ?A.mass=3 sets the inputs; what it asks and the
// panel cannot do (a name the lesson has no input for, a value outside the range) is said in
// a line of the panel (.tryit-query), and a lesson without [[vary]] says that it has no inputs.
// The slider's numbers are written as the shortest decimals that read back exactly, so that a
// browser's decimal step reaches max.
std::string try_it_html(const Lesson& lesson, double fps, const std::string& root);
// A [[vary]] input as a slider labels it, in our notation: "m of A (kg)", "v_x of ball (m/s)",
// "e (restitution)", "x of domino 2 (m), and of domino 3, …, domino 15 in proportion".
std::string vary_label(const LessonVary& v);
// The unit of a [[vary]] key's field ("kg", "m/s", "kg m^2"; "" for a pure number).
std::string vary_unit(const std::string& field);
// A number as an HTML attribute or a query string's value: the shortest decimal that reads
// back as the same double.
std::string number_attr(double x);
// A query string's name as a URL writes it: every byte but letters, digits and -_.~ as %XX
// ("A (e=0.1).mass" -> "A%20%28e%3D0.1%29.mass"), as the panel's URLSearchParams reads it back.
std::string percent_encoded(const std::string& text);
// try-it-lesson.js: the lesson's file as text (the engine reads it as `collide` does), the
// figures' colours (`palette`, a JSON object: render/style.h) and `first`, the panel's answer
// for the lesson's own values (present/try_it_answer.h, computed by the command: the page shows
// it before its module has started; empty: null, the page waits for the module), as
// `window.collideTryIt`. A script rather than text in the page: a page opened from file://
// cannot fetch a file.
std::string try_it_data_js(const Lesson& lesson, const std::string& palette, const std::string& first);

}  // namespace collide::html
