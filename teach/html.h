// HTML and SVG for the teaching material (collide material) and the files collide render
// writes beside the frames: text in our notation as HTML, and line plots as SVG.
#pragma once

#include <string>
#include <vector>

namespace collide {
struct SolveProblem;
struct Solution;
}  // namespace collide

namespace collide::html {

// &, <, >, " escaped.
std::string escape(const std::string& s);
// Text in our notation (v_pa, I_a⁻¹) as HTML: escaped, subscripts as <sub>, and the plain
// superscripts lesson texts write (I^-1, R^T) as <sup>.
std::string math(const std::string& text);
// Paragraphs separated by blank lines, each as <p> (math()).
std::string paragraphs(const std::string& text);

// A collision worked out (the lesson pages of collide material, the answer key of collide
// worksheet): each step's formula, then its numbers (the response's last line marked as the
// result), its notes, and `world_note` (the world's note when it resolved several points; ""
// for none).
std::string worked_html(const SolveProblem& problem, const Solution& solution, const std::string& world_note);

struct Series {
    std::string label;   // in our notation (p_x)
    std::string colour;  // CSS colour
    std::vector<double> values;  // one per time
};
// A line plot (560 x 230, white): the series against t from 0 to `duration` (in x_unit),
// faint red vertical lines at `collisions`, the largest and smallest values labelled.
std::string svg_plot(const std::string& title, const std::vector<double>& t, const std::vector<Series>& series,
                     const std::vector<double>& collisions, double duration, const std::string& x_unit = "s");

}  // namespace collide::html
