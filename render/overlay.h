// Overlays drawn with Dear ImGui into the frame: the header (title, time, arrow legends) and
// the data table (per moving body: m, v, w, p, kinetic energy; then the totals).
//
// Both are laid out once for a run (prepare), so that they keep their size and their columns
// keep their widths and decimals from frame to frame.
#pragma once

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
    void prepare(const FontSet& fonts, const std::vector<FrameState>& samples);
    ImVec2 size() const { return size_; }
    void draw(ImDrawList* dl, const FontSet& fonts, ImVec2 top_left, const FrameState& frame) const;

private:
    struct Column {
        std::string header;  // rich text
        int decimals = 2;
        float width = 0;
    };
    // The cells of one row (moving body i, or the totals when i is the body count).
    std::vector<std::string> cells(std::size_t i, const FrameState& frame) const;

    const Scene& scene_;
    Style style_;
    std::vector<Column> columns_;
    std::vector<std::size_t> rows_;  // moving bodies
    float row_height_ = 0, pad_ = 0, swatch_ = 0;
    ImVec2 size_{0, 0};
};

struct LegendEntry {
    enum class Mark { arrow, curved_arrow, dot, direction } mark = Mark::arrow;
    Colour colour = 0;
    float pixels = 0;    // arrow length
    std::string text;    // rich text
    ImVec2 direction{1, 0};  // Mark::direction: where a short arrow points (screen, unit)
};

class Header {
public:
    explicit Header(const Style& style) : style_(style) {}
    // title: bold first line (may be empty); time_decimals: for "t = 0.350 s".
    void prepare(const FontSet& fonts, std::string title, int time_decimals,
                 std::vector<LegendEntry> legend);
    ImVec2 size() const { return size_; }
    void draw(ImDrawList* dl, const FontSet& fonts, ImVec2 top_left, double t) const;

private:
    Style style_;
    std::string title_;
    int decimals_ = 3;
    std::vector<LegendEntry> legend_;
    ImVec2 size_{0, 0};
};

}  // namespace collide::render
