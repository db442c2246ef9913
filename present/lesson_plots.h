// A lesson's [[plot]] entries (scenario/lesson.h LessonPlot) evaluated on the run the page's
// figures show: the points of each series, the rows of its table, and the fit with its unit.
// The site draws them (present/site_pages.cpp, teach/html.h svg_xy_plot).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "present/scene_run.h"
#include "scenario/lesson.h"

namespace collide {

struct PlotSeriesData {
    std::string label;  // the quantity's name as written ("ball.position.y")
    std::string words;  // what it is, without its unit: its key and table heading (plot_quantity_words)
    std::vector<double> x, y;
    std::vector<int> number;  // per collision: each point's collision number (from 1)
};

struct PlotData {
    std::string title;
    std::string x_label, y_label;  // with units: "t (s)", "strike time (s)"
    std::string x_unit, y_unit;    // "s", "" (a count), "m/s"
    bool per_collision = false;
    // y on a logarithmic scale: fit = "ratio" with every value above 0 (a geometric sequence
    // is a straight line there; on a linear scale a bouncing ball's 40 intervals lie on 0).
    bool log_y = false;
    std::vector<PlotSeriesData> series;
    // Per collision: one row per collision shown, with its words ("domino 3 strikes domino 4").
    std::vector<std::string> row_names;
    std::vector<int> row_numbers;      // each row's number (x = "collision")
    std::vector<double> row_times;     // each row's instant (s)
    std::vector<std::string> missing;  // chain: the strikes the run does not have ("domino 9 -> 10")
    // fit = "line": y = intercept + slope x over the points from fit_from on.
    struct Line {
        double slope = 0, intercept = 0;
        double x0 = 0, x1 = 0;  // the fitted points' x range
        int points = 0;
        std::string slope_unit;       // "s per domino"
        std::optional<double> speed;  // chain along x = "collision" with y = "t": spacing / slope (m/s)
        double spacing = 0;           // m: the mean distance between neighbouring chain bodies at the start
    };
    std::optional<Line> line;
    // fit = "ratio": each value over the one before.
    struct Ratio {
        std::vector<double> ratios;
        double mean = 0, lo = 0, hi = 0;
        std::optional<double> restitution;  // pair: e of the pair (the scene's)
    };
    std::optional<Ratio> ratio;
    // One sentence of what the plot shows, for its alt text and caption (the fit's numbers).
    std::string summary;
};

// A plot quantity in words, with its unit, for keys, axes and tables: "ball: height of
// centre, y (m)", "B (e=1): velocity of touching point, x (m/s)", "total kinetic energy (J)";
// per collision "time since the previous bounce (s)" (`counting`: what one collision is).
// `with_unit` false: without " (unit)" (running text, where the unit follows each number).
std::string plot_quantity_words(const PlotQuantity& q, const Lesson& lesson, bool per_collision,
                                const std::string& counting = "collision", bool with_unit = true);

// Every [[plot]] of `lesson` on `run` (a run of `scene`: the lesson's own, or with other inputs).
std::vector<PlotData> lesson_plots(const Lesson& lesson, const Scene& scene, const SceneRun& run);

}  // namespace collide
