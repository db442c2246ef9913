// Overlays drawn with Dear ImGui into the frame: the header (title, time, arrow legends), the
// data table (per moving body: m, v, w, p, kinetic energy; then the totals), the formula of
// the first collision with its numbers, plots of energy and momentum against time, and a
// time line marking the collisions.
//
// Both are laid out once for a run (prepare), so that they keep their size and their columns
// keep their widths and decimals from frame to frame.
#pragma once

#include "render/annotation.h"

#include <string>
#include <vector>

#include <imgui.h>

#include "engine/scene.h"
#include "render/frame_state.h"
#include "render/imgui_layer.h"
#include "render/style.h"

namespace collide::render {

class DataTable {
public:
    DataTable(const Scene& scene, const Style& style) : scene_(scene), style_(style) {}
    // Lays the table out for the run's frames, at most `max_height` pixels tall: beyond
    // kTableBodies moving bodies, or as many as fit, the rows go to the bodies table_rows()
    // picks in each frame and one line sums up the others (render/frame_state.h).
    void prepare(const FontSet& fonts, const std::vector<FrameState>& samples, float max_height = 1e9f);
    ImVec2 size() const { return size_; }
    // Draws the panel, the swatches and rules, and the cells annotate() lists.
    void draw(ImDrawList* dl, const FontSet& fonts, ImVec2 top_left, const FrameState& frame) const;
    // Its cells as Mark::table_cell items where draw() writes them (after prepare).
    Annotations annotate(const FontSet& fonts, ImVec2 top_left, const FrameState& frame) const;
    // What draw() writes, cell by cell (after prepare): the header row, a row per moving body
    // (name, m, v, ω in 2D and 3D, p, E_k), or per body table_rows() picks and then a line for
    // the others ("+ 8 more: |v| ≤ 0.004 m/s, |ω| ≤ 0.2 rad/s"), and the totals (m, p, E_k).
    std::vector<std::vector<std::string>> text(const FrameState& frame) const;
    // The bodies with a row in this frame, and the others (after prepare).
    TableRows rows(const FrameState& frame) const;

private:
    struct Column {
        std::string header;  // rich text
        int decimals = 2;
        float width = 0;
    };
    struct Cell {
        std::string text;
        std::vector<double> value;  // the quantity (empty: a name)
    };
    // The cells of one row (moving body i, or the totals when i is the body count).
    std::vector<Cell> cells(std::size_t i, const FrameState& frame) const;
    // The line for the bodies without a row ("" when every body has one).
    std::string others_text(const TableRows& rows) const;

    const Scene& scene_;
    Style style_;
    std::vector<Column> columns_;
    std::vector<std::size_t> rows_;  // moving bodies
    std::size_t capacity_ = 0;       // body rows the table has (a line for the others besides
                                     // when rows_ has more)
    float row_height_ = 0, pad_ = 0, swatch_ = 0;
    ImVec2 size_{0, 0};
};

struct LegendEntry {
    enum class Mark { arrow, curved_arrow, dot, direction } mark = Mark::arrow;
    Colour colour = 0;
    float pixels = 0;        // arrow length
    std::string text;        // rich text
    ImVec2 direction{1, 0};  // Mark::direction: where a short arrow points (screen, unit)
};

class Header {
public:
    explicit Header(const Style& style) : style_(style) {}
    // title: bold first line (may be empty); time_decimals: for "t = 0.350 s".
    void prepare(const FontSet& fonts, std::string title, int time_decimals, std::vector<LegendEntry> legend);
    ImVec2 size() const { return size_; }
    void draw(ImDrawList* dl, const FontSet& fonts, ImVec2 top_left, double t) const;

private:
    Style style_;
    std::string title_;
    int decimals_ = 3;
    std::vector<LegendEntry> legend_;
    ImVec2 size_{0, 0};
};

// The formula of a collision with its numbers substituted (rich text, see draw2d.h): a
// heading, then lines; a muted note under them (may be empty).
struct FormulaText {
    std::string heading;
    std::vector<std::string> lines;
    std::string note;
    bool empty() const { return lines.empty(); }
};

class FormulaBox {
public:
    explicit FormulaBox(const Style& style) : style_(style) {}
    // Lines wider than max_width are dropped from the top (the last line, the result, stays).
    void prepare(const FontSet& fonts, FormulaText text, float max_width);
    ImVec2 size() const { return size_; }
    // Draws the panel and the lines annotate() lists.
    void draw(ImDrawList* dl, const FontSet& fonts, ImVec2 top_left) const;
    // The heading, the lines and the note as Mark::formula_line items, top to bottom, where
    // draw() writes them (`small`: the note's font).
    Annotations annotate(const FontSet& fonts, ImVec2 top_left) const;

private:
    Style style_;
    FormulaText text_;
    ImVec2 size_{0, 0};
};

// A small plot of quantities against time: each series over the whole run faint, up to the
// current time solid, with a dot at the current value; zero marked when in range.
class Plot {
public:
    struct Series {
        std::string label;  // rich text
        Colour colour = 0;
        std::vector<double> values;  // one per time
    };
    explicit Plot(const Style& style) : style_(style) {}
    void prepare(const FontSet& fonts, std::string title, std::vector<double> times, std::vector<Series> series,
                 ImVec2 size);
    ImVec2 size() const { return size_; }
    bool empty() const { return series_.empty(); }
    // Draws the axes, the series, and a dot where annotate() puts each series' value.
    void draw(ImDrawList* dl, const FontSet& fonts, ImVec2 top_left, double t) const;
    // Each series at time t as a Mark::plot_value item (after prepare).
    Annotations annotate(const FontSet& fonts, ImVec2 top_left, double t) const;

private:
    // The plotting area (pixels: x0, y0, x1, y1) of the plot drawn at top_left.
    ImVec4 area(const FontSet& fonts, ImVec2 top_left) const;
    Style style_;
    std::string title_;
    std::vector<double> times_;
    std::vector<Series> series_;
    double lo_ = 0, hi_ = 1;
    ImVec2 size_{0, 0};
};

// The run from 0 to its duration as a bar across the frame: a tick at every collision (a
// triangle for the first, whose before / at / after figure is made), the time so far filled.
// Beyond 40 collisions, their density instead: bars a few pixels wide, rising with the
// logarithm of the count in each.
class TimeLine {
public:
    explicit TimeLine(const Style& style) : style_(style) {}
    void prepare(const FontSet& fonts, double duration, std::vector<double> collisions, float width);
    ImVec2 size() const { return size_; }
    void draw(ImDrawList* dl, const FontSet& fonts, ImVec2 top_left, double t) const;

private:
    Style style_;
    double duration_ = 1;
    std::vector<double> collisions_;
    ImVec2 size_{0, 0};
};

}  // namespace collide::render
