// A lesson's [[plot]] entries on its page (docs/commands/material.md, "Plots"): each drawn as
// ID/plot-K.svg, shown under "Watch" with its alt text (the title and what the run shows: the
// fitted slope with its unit, the ratio beside e) and a table of the numbers behind it.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "present/lesson_plots.h"

namespace collide {

// Each plot's file name ("plot-1.svg", ...) and SVG text.
std::vector<std::pair<std::string, std::string>> plot_svgs(const std::vector<PlotData>& plots);

// The plots' HTML for the "Watch" part of a lesson page (empty when there are none).
std::string plots_html(const std::vector<PlotData>& plots);

// A plot's alternative text: its summary (title, what it shows, the fit's numbers).
std::string plot_alt(const PlotData& plot);

}  // namespace collide
