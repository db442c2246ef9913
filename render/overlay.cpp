#include "render/overlay.h"

#include <algorithm>
#include <cmath>

#include "render/draw2d.h"

namespace collide::render {

namespace {

int decimals_for(double largest) {
    if (!(largest > 0)) return 2;
    return std::clamp(2 - static_cast<int>(std::floor(std::log10(largest))), 0, 4);
}

std::string vec_text(const Vec3& v, int dims, int decimals) {
    if (dims == 1) return format_fixed(v.x(), decimals);
    std::string s = "(" + format_fixed(v.x(), decimals) + ", " + format_fixed(v.y(), decimals);
    if (dims == 3) s += ", " + format_fixed(v.z(), decimals);
    return s + ")";
}

double mass_of(const Scene& s, std::size_t i) {
    const SceneBody& b = s.bodies[i];
    return s.dimension == 1 ? b.body1.mass : s.dimension == 2 ? b.body2.mass : b.body3.mass;
}

}  // namespace

std::vector<std::string> DataTable::cells(std::size_t i, const FrameState& f) const {
    const int d = scene_.dimension;
    const bool total = i >= scene_.bodies.size();
    std::vector<std::string> out;
    const auto dec = [this](std::size_t c) { return columns_[c].decimals; };
    if (total) {
        double m = 0, ke = 0;
        Vec3 p = Vec3::Zero();
        for (std::size_t r : rows_) {
            m += mass_of(scene_, r);
            p += mass_of(scene_, r) * f.bodies[r].v;
            ke += kinetic_energy(scene_, r, f.bodies[r]);
        }
        out = {"total", format_fixed(m, dec(1)), ""};
        if (d > 1) out.push_back("");
        out.push_back(vec_text(p, d, dec(out.size())));
        out.push_back(format_fixed(ke, dec(out.size())));
        return out;
    }
    const BodyState& s = f.bodies[i];
    const double m = mass_of(scene_, i);
    out = {scene_.bodies[i].name, format_fixed(m, dec(1)), vec_text(s.v, d, dec(2))};
    if (d == 2) out.push_back(format_fixed(s.w.z(), dec(3)));
    if (d == 3) out.push_back(vec_text(s.w, 3, dec(3)));
    out.push_back(vec_text(m * s.v, d, dec(out.size())));
    out.push_back(format_fixed(kinetic_energy(scene_, i, s), dec(out.size())));
    return out;
}

void DataTable::prepare(const FontSet& fonts, const std::vector<FrameState>& samples) {
    const int d = scene_.dimension;
    rows_.clear();
    for (std::size_t i = 0; i < scene_.bodies.size(); ++i)
        if (!scene_.bodies[i].is_static()) rows_.push_back(i);
    columns_ = {{"body"}, {"m (kg)"}, {"v (m s\u207B\u00B9)"}};
    if (d > 1) columns_.push_back({"\u03C9 (rad s\u207B\u00B9)"});
    columns_.push_back({"p (kg m s\u207B\u00B9)"});
    columns_.push_back({"E_{k} (J)"});

    // Decimals from the largest value each column takes over the run.
    std::vector<double> largest(columns_.size(), 0.0);
    double total_mass = 0;
    for (std::size_t r : rows_) total_mass += mass_of(scene_, r);
    largest[1] = total_mass;
    for (const FrameState& f : samples) {
        double ke = 0;
        Vec3 p = Vec3::Zero();
        for (std::size_t r : rows_) {
            const BodyState& s = f.bodies[r];
            std::size_t c = 2;
            largest[c] = std::max(largest[c], s.v.cwiseAbs().maxCoeff());
            if (d > 1) ++c, largest[c] = std::max(largest[c], s.w.cwiseAbs().maxCoeff());
            ++c;
            largest[c] = std::max(largest[c], (mass_of(scene_, r) * s.v).cwiseAbs().maxCoeff());
            p += mass_of(scene_, r) * s.v;
            const double e = kinetic_energy(scene_, r, s);
            ke += e;
        }
        largest[columns_.size() - 2] = std::max(largest[columns_.size() - 2], p.cwiseAbs().maxCoeff());
        largest.back() = std::max(largest.back(), ke);
    }
    for (std::size_t c = 1; c < columns_.size(); ++c) columns_[c].decimals = decimals_for(largest[c]);

    // Widths: the widest cell over the run (and the header).
    ImFont* font = fonts.table;
    for (Column& c : columns_) c.width = rich_text_size(fonts, font, c.header).x;
    const auto widen = [&](const FrameState& f) {
        std::vector<std::size_t> all = rows_;
        all.push_back(scene_.bodies.size());
        for (std::size_t r : all) {
            const std::vector<std::string> row = cells(r, f);
            for (std::size_t c = 0; c < row.size(); ++c)
                columns_[c].width = std::max(columns_[c].width, rich_text_size(fonts, font, row[c]).x);
        }
    };
    // Every sample would be exact; a few hundred spread over the run are plenty.
    const std::size_t step = std::max<std::size_t>(1, samples.size() / 300);
    for (std::size_t k = 0; k < samples.size(); k += step) widen(samples[k]);
    if (!samples.empty()) widen(samples.back());

    pad_ = style_.px(8.0f);
    swatch_ = std::round(font->FontSize * 0.7f);
    row_height_ = std::round(font->FontSize * 1.45f);
    float w = pad_ + swatch_ + style_.px(6.0f);
    for (const Column& c : columns_) w += c.width + style_.px(16.0f);
    w += pad_ - style_.px(16.0f);
    const float h = pad_ * 2 + row_height_ * static_cast<float>(rows_.size() + 2) + style_.px(4.0f);
    size_ = rows_.empty() ? ImVec2(0, 0) : ImVec2(std::ceil(w), std::ceil(h));
}

void DataTable::draw(ImDrawList* dl, const FontSet& fonts, ImVec2 at, const FrameState& f) const {
    if (rows_.empty()) return;
    const Palette& c = style_.colours;
    ImFont* font = fonts.table;
    dl->AddRectFilled(at, ImVec2(at.x + size_.x, at.y + size_.y), c.panel, style_.px(6.0f));
    dl->AddRect(at, ImVec2(at.x + size_.x, at.y + size_.y), c.panel_border, style_.px(6.0f), 0,
                style_.lw(1.0f));
    const float col_gap = style_.px(16.0f);
    const float text_dy = std::round(0.5f * (row_height_ - font->FontSize));
    const float x_first = at.x + pad_ + swatch_ + style_.px(6.0f);
    float y = at.y + pad_;

    // One row: the first column left-aligned, numbers right-aligned.
    const auto row = [&](const std::vector<std::string>& cells, Colour colour, float y0) {
        float x = x_first;
        for (std::size_t k = 0; k < columns_.size() && k < cells.size(); ++k) {
            const float tw = rich_text_size(fonts, font, cells[k]).x;
            const float tx = k == 0 ? x : x + columns_[k].width - tw;
            draw_rich_text(dl, fonts, font, ImVec2(std::round(tx), y0 + text_dy), colour, cells[k]);
            x += columns_[k].width + col_gap;
        }
    };
    std::vector<std::string> headers;
    for (const Column& col : columns_) headers.push_back(col.header);
    row(headers, c.muted, y);
    y += row_height_;
    dl->AddLine(ImVec2(at.x + pad_, y), ImVec2(at.x + size_.x - pad_, y), c.panel_border, style_.lw(1.0f));
    int order = 0;
    for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
        if (scene_.bodies[i].is_static()) continue;
        const float sy = y + 0.5f * (row_height_ - swatch_);
        dl->AddRectFilled(ImVec2(at.x + pad_, sy), ImVec2(at.x + pad_ + swatch_, sy + swatch_),
                          c.fills[order % Palette::kFills], style_.lw(2.0f));
        dl->AddRect(ImVec2(at.x + pad_, sy), ImVec2(at.x + pad_ + swatch_, sy + swatch_), c.ink,
                    style_.px(2.0f), 0, style_.lw(1.0f));
        row(cells(i, f), c.ink, y);
        y += row_height_;
        ++order;
    }
    y += style_.px(4.0f);
    dl->AddLine(ImVec2(at.x + pad_, y - style_.lw(2.0f)), ImVec2(at.x + size_.x - pad_, y - style_.lw(2.0f)),
                c.panel_border, style_.lw(1.0f));
    row(cells(scene_.bodies.size(), f), c.ink, y);
}

void Header::prepare(const FontSet& fonts, std::string title, int time_decimals,
                     std::vector<LegendEntry> legend) {
    title_ = std::move(title);
    decimals_ = time_decimals;
    legend_ = std::move(legend);
    float w = 0, h = 0;
    if (!title_.empty()) {
        w = std::max(w, rich_text_size(fonts, fonts.bold, title_).x);
        h += fonts.bold->FontSize * 1.3f;
    }
    w = std::max(w, rich_text_size(fonts, fonts.text, "t = " + format_fixed(1e4, decimals_) + " s").x);
    h += fonts.text->FontSize * 1.5f;
    for (const LegendEntry& e : legend_) {
        const float mark = std::max(e.pixels, style_.px(30.0f));
        w = std::max(w, mark + style_.px(10.0f) + rich_text_size(fonts, fonts.small, e.text).x);
        h += fonts.small->FontSize * 1.6f;
    }
    size_ = ImVec2(std::ceil(w), std::ceil(h));
}

void Header::draw(ImDrawList* dl, const FontSet& fonts, ImVec2 at, double t) const {
    const Palette& c = style_.colours;
    float y = at.y;
    if (!title_.empty()) {
        draw_rich_text(dl, fonts, fonts.bold, ImVec2(at.x, y), c.ink, title_);
        y += fonts.bold->FontSize * 1.3f;
    }
    draw_rich_text(dl, fonts, fonts.text, ImVec2(at.x, y), c.ink, "t = " + format_fixed(t, decimals_) + " s");
    y += fonts.text->FontSize * 1.5f;
    for (const LegendEntry& e : legend_) {
        const float fh = fonts.small->FontSize;
        const float cy = std::round(y + 0.55f * fh);
        const float mark = std::max(e.pixels, style_.px(30.0f));
        switch (e.mark) {
        case LegendEntry::Mark::arrow:
            draw_arrow(dl, ImVec2(at.x, cy), ImVec2(at.x + e.pixels, cy), e.colour, style_.lw(style_.arrow),
                       style_.lw(style_.head_length), style_.lw(style_.head_width));
            break;
        case LegendEntry::Mark::curved_arrow:
            draw_curved_arrow(dl, ImVec2(at.x + 0.5f * mark, cy + fh * 0.9f), fh * 1.1f, 2.3f, 0.85f,
                              e.colour, style_.lw(2.5f), style_.lw(12.0f), style_.lw(10.0f));
            break;
        case LegendEntry::Mark::direction: {
            const float L = std::min(mark, style_.px(30.0f));
            const ImVec2 c0(at.x + 0.5f * mark, cy);
            const ImVec2 d(e.direction.x * 0.5f * L, e.direction.y * 0.5f * L);
            draw_arrow(dl, ImVec2(c0.x - d.x, c0.y - d.y), ImVec2(c0.x + d.x, c0.y + d.y), e.colour,
                       style_.lw(2.5f), style_.lw(10.0f), style_.lw(8.0f));
            break;
        }
        case LegendEntry::Mark::dot:
            dl->AddCircleFilled(ImVec2(at.x + 0.5f * mark, cy), style_.px(3.5f), e.colour);
            break;
        }
        draw_rich_text(dl, fonts, fonts.small, ImVec2(at.x + mark + style_.px(10.0f), y), c.ink, e.text);
        y += fh * 1.6f;
    }
}

}  // namespace collide::render
