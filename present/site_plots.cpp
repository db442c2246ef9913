#include "present/site_plots.h"

#include <cmath>
#include <sstream>

#include "teach/html.h"
#include "teach/notation.h"

namespace collide {

namespace {

using html::escape;

// Colours that stay apart under colour-blindness (Okabe and Ito).
const char* const kColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9"};

std::string num(double x) { return notation::sig_text(x, 4); }

}  // namespace

std::string plot_alt(const PlotData& p) { return p.summary; }

std::vector<std::pair<std::string, std::string>> plot_svgs(const std::vector<PlotData>& plots) {
    std::vector<std::pair<std::string, std::string>> out;
    for (std::size_t k = 0; k < plots.size(); ++k) {
        const PlotData& p = plots[k];
        std::vector<html::XYSeries> series;
        for (std::size_t s = 0; s < p.series.size(); ++s)
            series.push_back({p.series[s].words, kColours[s % 6], p.series[s].x, p.series[s].y, p.per_collision});
        std::optional<html::XYLine> line;
        if (p.line)
            line = html::XYLine{p.line->slope, p.line->intercept, p.line->x0, p.line->x1,
                                "fit: slope " + notation::sig_text(p.line->slope, 3) + " " + p.line->slope_unit};
        out.emplace_back("plot-" + std::to_string(k + 1) + ".svg",
                         html::svg_xy_plot(p.title, p.x_label, p.y_label, series, line, p.log_y));
    }
    return out;
}

std::string plots_html(const std::vector<PlotData>& plots) {
    std::ostringstream o;
    for (std::size_t k = 0; k < plots.size(); ++k) {
        const PlotData& p = plots[k];
        const std::string file = "plot-" + std::to_string(k + 1) + ".svg";
        o << "<section class=\"lesson-plot\" id=\"plot-" << k + 1 << "\">\n<h3>" << escape(p.title)
          << "</h3>\n<figure><img src=\"" << file << "\" alt=\"" << escape(plot_alt(p))
          << "\"><figcaption>From the simulation: the run the figures above "
          << "show.</figcaption></figure>\n"
          << plot_data_html(p) << "</section>\n";
    }
    return o.str();
}

std::string plot_data_html(const PlotData& p) {
    std::ostringstream o;
    // What it shows in numbers stays folded with the table: the questions below ask them.
    o << "<details class=\"plot-data\"><summary>What the plot shows, and the numbers behind it</summary>\n<p>"
      << escape(p.summary) << "</p>\n<table>\n<thead><tr>";
    if (p.per_collision) {
        o << "<th>" << escape(p.x_unit.empty() ? p.x_label : std::string("number"))
          << "</th><th>collision</th><th>t (s)</th>";
        for (const PlotSeriesData& s : p.series)
            if (s.label != "t")
                o << "<th>" << escape(s.words + (p.y_unit.empty() ? "" : " (" + p.y_unit + ")")) << "</th>";
        if (p.ratio) o << "<th>ratio to the one before</th>";
        o << "</tr></thead>\n<tbody>\n";
        // One row per collision shown: its number, its words, its instant and each y.
        for (std::size_t r = 0; r < p.row_names.size(); ++r) {
            const int number = r < p.row_numbers.size() ? p.row_numbers[r] : static_cast<int>(r + 1);
            o << "<tr><td>" << number << "</td><td>" << escape(p.row_names[r]) << "</td><td>"
              << escape(num(p.row_times[r])) << "</td>";
            for (const PlotSeriesData& s : p.series) {
                if (s.label == "t") continue;
                std::string cell = "—";
                for (std::size_t i = 0; i < s.number.size(); ++i)
                    if (s.number[i] == number) cell = num(s.y[i]);
                o << "<td>" << escape(cell) << "</td>";
            }
            if (p.ratio) {
                // ratios[i - 1]: the first series' point i over point i - 1.
                std::string cell = "—";
                const PlotSeriesData& s = p.series.front();
                for (std::size_t i = 1; i < s.number.size() && i - 1 < p.ratio->ratios.size(); ++i)
                    if (s.number[i] == number && std::isfinite(p.ratio->ratios[i - 1]))
                        cell = num(p.ratio->ratios[i - 1]);
                o << "<td>" << escape(cell) << "</td>";
            }
            o << "</tr>\n";
        }
    } else {
        o << "<th>" << escape(p.x_label) << "</th>";
        for (const PlotSeriesData& s : p.series)
            o << "<th>" << escape(s.words + (p.y_unit.empty() ? "" : " (" + p.y_unit + ")")) << "</th>";
        o << "</tr></thead>\n<tbody>\n";
        const std::size_t rows = p.series.empty() ? 0 : p.series.front().x.size();
        for (std::size_t r = 0; r < rows; ++r) {
            o << "<tr><td>" << escape(num(p.series.front().x[r])) << "</td>";
            for (const PlotSeriesData& s : p.series) o << "<td>" << escape(num(s.y[r])) << "</td>";
            o << "</tr>\n";
        }
    }
    o << "</tbody>\n</table>\n";
    if (p.line)
        o << "<p class=\"note\">The dashed line: least squares over " << p.line->points
          << " points, y = " << escape(num(p.line->intercept)) << " + " << escape(num(p.line->slope)) << " x; slope "
          << escape(num(p.line->slope) + " " + p.line->slope_unit) << ".</p>\n";
    o << "</details>\n";
    return o.str();
}

}  // namespace collide
