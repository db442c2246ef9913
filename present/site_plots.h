// A lesson's [[plot]] entries on its page (docs/commands/material.md, "Plots") and in its Try-it
// panel (wasm/module.cpp: the run with the panel's inputs): each drawn as ID/plot-K.svg, shown under "Watch" with its alt text (the title and what the run shows: the
// fitted slope with its unit, the ratio beside e) and a table of the numbers behind it.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "present/lesson_plots.h"

namespace collide {

// Each plot's file name ("plot-1.svg", ...) and SVG text.
std::vector<std::pair<std::string, std::string>> plot_svgs(const std::vector<PlotData>& plots);

// The plots' HTML for the "Watch" part of a lesson page (empty when there are none): each a
// heading (its title), the picture and plot_data_html.
std::string plots_html(const std::vector<PlotData>& plots);

// What a plot shows in numbers, folded: its summary, the table of the numbers behind it and the
// fitted line's equation (a <details>). The page and the Try-it panel (wasm/module.cpp) alike.
std::string plot_data_html(const PlotData& plot);

// A plot's alternative text: its summary (title, what it shows, the fit's numbers).
std::string plot_alt(const PlotData& plot);

}  // namespace collide
