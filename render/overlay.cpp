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

// The background of an overlay: a white rounded panel with a thin border.
void draw_panel(ImDrawList* dl, const Style& style, ImVec2 at, ImVec2 size) {
    const Palette& c = style.colours;
    dl->AddRectFilled(at, ImVec2(at.x + size.x, at.y + size.y), c.panel, style.px(6.0f));
    dl->AddRect(at, ImVec2(at.x + size.x, at.y + size.y), c.panel_border, style.px(6.0f), 0, style.lw(1.0f));
}

}  // namespace

std::vector<DataTable::Cell> DataTable::cells(std::size_t i, const FrameState& f) const {
    const int d = scene_.dimension;
    const bool total = i >= scene_.bodies.size();
    std::vector<Cell> out;
    const auto dec = [this](std::size_t c) { return columns_[c].decimals; };
    const auto number = [&](double x) { return Cell{format_fixed(x, dec(out.size())), {x}}; };
    const auto vector = [&](const Vec3& v, int dims) {
        return Cell{vec_text(v, dims, dec(out.size())), components(v, dims)};
    };
    if (total) {
        double m = 0;
        for (std::size_t r : rows_) m += body_mass(scene_, r);
        const FrameTotals sums = frame_totals(scene_, f);
        // Every moving body's, also those without a row: said so when some have none.
        out.push_back({rows_.size() > capacity_ ? "all " + std::to_string(rows_.size()) : "total", {}});
        out.push_back(number(m));
        out.push_back({"", {}});
        if (d > 1) out.push_back({"", {}});
        out.push_back(vector(sums.momentum, d));
        out.push_back(number(sums.kinetic));
        return out;
    }
    const BodyState& s = f.bodies[i];
    const double m = body_mass(scene_, i);
    out.push_back({scene_.bodies[i].name, {}});
    out.push_back(number(m));
    out.push_back(vector(s.v, d));
    if (d == 2) out.push_back(number(s.w.z()));
    if (d == 3) out.push_back(vector(s.w, 3));
    out.push_back(vector(m * s.v, d));
    out.push_back(number(kinetic_energy(scene_, i, s)));
    return out;
}

TableRows DataTable::rows(const FrameState& f) const {
    std::vector<double> kinetic(scene_.bodies.size(), 0.0);
    if (rows_.size() > capacity_)
        for (std::size_t i : rows_) kinetic[i] = kinetic_energy(scene_, i, f.bodies[i]);
    return table_rows(rows_, kinetic, f, capacity_);
}

std::string DataTable::others_text(const TableRows& r) const {
    if (r.others == 0) return "";
    std::string s = "+ " + std::to_string(r.others) + " more";
    if (r.others_speed == 0 && r.others_spin == 0) return s + ", at rest";
    // Bounds rounded up at the columns' decimals, so that they stay true as printed.
    const auto up = [](double x, int decimals) {
        const double k = std::pow(10.0, decimals);
        return format_fixed(std::ceil(x * k - 1e-9) / k, decimals);
    };
    s += ": |v| ≤ " + up(r.others_speed, columns_[2].decimals) + " m/s";
    if (scene_.dimension > 1) s += ", |ω| ≤ " + up(r.others_spin, columns_[3].decimals) + " rad/s";
    return s;
}

void DataTable::prepare(const FontSet& fonts, const std::vector<FrameState>& samples, float max_height) {
    const int d = scene_.dimension;
    rows_.clear();
    for (std::size_t i = 0; i < scene_.bodies.size(); ++i)
        if (!scene_.bodies[i].is_static()) rows_.push_back(i);
    columns_ = {{"body"}, {"m (kg)"}, {"v (m/s)"}};
    if (d > 1) columns_.push_back({"\u03C9 (rad/s)"});
    columns_.push_back({"p (kg m/s)"});
    columns_.push_back({"E_{k} (J)"});

    // Decimals from the largest value each column takes over the run.
    std::vector<double> largest(columns_.size(), 0.0);
    double total_mass = 0;
    for (std::size_t r : rows_) total_mass += body_mass(scene_, r);
    largest[1] = total_mass;
    for (const FrameState& f : samples) {
        for (std::size_t r : rows_) {
            const BodyState& s = f.bodies[r];
            std::size_t c = 2;
            largest[c] = std::max(largest[c], s.v.cwiseAbs().maxCoeff());
            if (d > 1) ++c, largest[c] = std::max(largest[c], s.w.cwiseAbs().maxCoeff());
            ++c;
            largest[c] = std::max(largest[c], (body_mass(scene_, r) * s.v).cwiseAbs().maxCoeff());
        }
        const FrameTotals sums = frame_totals(scene_, f);
        largest[columns_.size() - 2] = std::max(largest[columns_.size() - 2], sums.momentum.cwiseAbs().maxCoeff());
        largest.back() = std::max(largest.back(), sums.kinetic);
    }
    for (std::size_t c = 1; c < columns_.size(); ++c) columns_[c].decimals = decimals_for(largest[c]);

    // Rows: every moving body while kTableBodies and max_height allow, else as many as fit
    // beside a line for the others (table_rows picks them frame by frame).
    ImFont* font = fonts.table;
    pad_ = style_.px(8.0f);
    swatch_ = std::round(font->FontSize * 0.7f);
    row_height_ = std::round(font->FontSize * 1.45f);
    const float fixed = pad_ * 2 + row_height_ * 2 + style_.px(4.0f);  // header, totals
    const float fit = std::floor((max_height - fixed) / row_height_);
    capacity_ = std::min(kTableBodies, static_cast<std::size_t>(std::max(2.0f, fit)));
    if (rows_.size() <= capacity_) capacity_ = rows_.size();

    // Widths: the widest cell over the run (and the header).
    for (Column& c : columns_) c.width = rich_text_size(fonts, font, c.header).x;
    const auto widen = [&](const FrameState& f) {
        std::vector<std::size_t> all = rows_;
        all.push_back(scene_.bodies.size());
        for (std::size_t r : all) {
            const std::vector<Cell> row = cells(r, f);
            for (std::size_t c = 0; c < row.size(); ++c)
                columns_[c].width = std::max(columns_[c].width, rich_text_size(fonts, font, row[c].text).x);
        }
    };
    // Every sample would be exact; a few hundred spread over the run are plenty.
    const std::size_t step = std::max<std::size_t>(1, samples.size() / 300);
    for (std::size_t k = 0; k < samples.size(); k += step) widen(samples[k]);
    if (!samples.empty()) widen(samples.back());

    float w = pad_ + swatch_ + style_.px(6.0f);
    for (const Column& c : columns_) w += c.width + style_.px(16.0f);
    w += pad_ - style_.px(16.0f);
    if (rows_.size() > capacity_) {
        // The line for the others at its widest: all but the rows' bodies, at the run's top speeds.
        TableRows widest;
        widest.others = rows_.size() - (capacity_ - 1);
        for (const FrameState& f : samples)
            for (std::size_t r : rows_) {
                widest.others_speed = std::max(widest.others_speed, f.bodies[r].v.norm());
                widest.others_spin = std::max(widest.others_spin, f.bodies[r].w.norm());
            }
        w = std::max(w, pad_ * 2 + swatch_ + style_.px(6.0f) + rich_text_size(fonts, font, others_text(widest)).x);
    }
    const std::size_t lines = rows_.size() > capacity_ ? capacity_ : rows_.size();  // bodies, then the others' line
    const float h = pad_ * 2 + row_height_ * static_cast<float>(lines + 2) + style_.px(4.0f);
    size_ = rows_.empty() ? ImVec2(0, 0) : ImVec2(std::ceil(w), std::ceil(h));
}

Annotations DataTable::annotate(const FontSet& fonts, ImVec2 at, const FrameState& f) const {
    Annotations out;
    if (rows_.empty()) return out;
    const Palette& c = style_.colours;
    ImFont* font = fonts.table;
    const float col_gap = style_.px(16.0f);
    const float text_dy = std::round(0.5f * (row_height_ - font->FontSize));
    const float x_first = at.x + pad_ + swatch_ + style_.px(6.0f);
    // One row: the first column left-aligned, numbers right-aligned.
    const auto row = [&](const std::vector<Cell>& cells, int body, Colour colour, float y0) {
        float x = x_first;
        for (std::size_t k = 0; k < columns_.size() && k < cells.size(); ++k) {
            const float tw = rich_text_size(fonts, font, cells[k].text).x;
            const float tx = std::round(k == 0 ? x : x + columns_[k].width - tw);
            Annotation a;
            a.kind = Mark::table_cell;
            a.body = body;
            a.of = static_cast<int>(k);
            a.text = cells[k].text;
            a.value = cells[k].value;
            a.box = ImVec4(tx, y0 + text_dy, tx + tw, y0 + text_dy + font->FontSize);
            a.font_px = font->FontSize;
            a.colour = colour;
            if (!a.text.empty()) out.push_back(std::move(a));
            x += columns_[k].width + col_gap;
        }
    };
    float y = at.y + pad_;
    std::vector<Cell> header;
    for (const Column& col : columns_) header.push_back({col.header, {}});
    row(header, -1, c.muted, y);
    y += row_height_;
    const TableRows shown = rows(f);
    for (std::size_t i : shown.shown) {
        row(cells(i, f), static_cast<int>(i), c.ink, y);
        y += row_height_;
    }
    if (shown.others > 0) {  // one cell across the row
        Annotation a;
        a.kind = Mark::table_cell;
        a.body = -1;
        a.of = 0;
        a.text = others_text(shown);
        const float tw = rich_text_size(fonts, font, a.text).x;
        a.box = ImVec4(x_first, y + text_dy, x_first + tw, y + text_dy + font->FontSize);
        a.font_px = font->FontSize;
        a.colour = c.muted;
        out.push_back(std::move(a));
        y += row_height_;
    }
    row(cells(scene_.bodies.size(), f), -1, c.ink, y + style_.px(4.0f));
    return out;
}

void DataTable::draw(ImDrawList* dl, const FontSet& fonts, ImVec2 at, const FrameState& f) const {
    if (rows_.empty()) return;
    const Palette& c = style_.colours;
    draw_panel(dl, style_, at, size_);
    float y = at.y + pad_ + row_height_;
    dl->AddLine(ImVec2(at.x + pad_, y), ImVec2(at.x + size_.x - pad_, y), c.panel_border, style_.lw(1.0f));
    const TableRows shown = rows(f);
    for (std::size_t i : shown.shown) {
        // A body's swatch has its colour in the view: its place among the moving bodies.
        const std::size_t order = static_cast<std::size_t>(std::find(rows_.begin(), rows_.end(), i) - rows_.begin());
        const float sy = y + 0.5f * (row_height_ - swatch_);
        dl->AddRectFilled(ImVec2(at.x + pad_, sy), ImVec2(at.x + pad_ + swatch_, sy + swatch_),
                          c.fills[order % Palette::kFills], style_.lw(2.0f));
        dl->AddRect(ImVec2(at.x + pad_, sy), ImVec2(at.x + pad_ + swatch_, sy + swatch_), c.ink, style_.px(2.0f), 0,
                    style_.lw(1.0f));
        y += row_height_;
    }
    if (shown.others > 0) y += row_height_;
    y += style_.px(4.0f);
    dl->AddLine(ImVec2(at.x + pad_, y - style_.lw(2.0f)), ImVec2(at.x + size_.x - pad_, y - style_.lw(2.0f)),
                c.panel_border, style_.lw(1.0f));
    for (const Annotation& a : annotate(fonts, at, f))
        draw_rich_text(dl, fonts, fonts.table, ImVec2(a.box.x, a.box.y), a.colour, a.text);
}

std::vector<std::vector<std::string>> DataTable::text(const FrameState& f) const {
    std::vector<std::vector<std::string>> lines(1);
    for (const Column& col : columns_) lines[0].push_back(col.header);
    const auto texts = [](const std::vector<Cell>& cells) {
        std::vector<std::string> out;
        for (const Cell& c : cells) out.push_back(c.text);
        return out;
    };
    const TableRows shown = rows(f);
    for (std::size_t i : shown.shown) lines.push_back(texts(cells(i, f)));
    if (shown.others > 0) lines.push_back({others_text(shown)});
    lines.push_back(texts(cells(scene_.bodies.size(), f)));
    return lines;
}

void Header::prepare(const FontSet& fonts, std::string title, int time_decimals, std::vector<LegendEntry> legend) {
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
                draw_curved_arrow(dl, ImVec2(at.x + 0.5f * mark, cy + fh * 0.9f), fh * 1.1f, 2.3f, 0.85f, e.colour,
                                  style_.lw(2.5f), style_.lw(12.0f), style_.lw(10.0f));
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

// ---- Formula ----

void FormulaBox::prepare(const FontSet& fonts, FormulaText text, float max_width) {
    text_ = std::move(text);
    size_ = ImVec2(0, 0);
    if (text_.empty()) return;
    const float pad = style_.px(10.0f);
    const auto width_of = [&]() {
        float w = rich_text_size(fonts, fonts.bold, text_.heading).x;
        for (const std::string& line : text_.lines) w = std::max(w, rich_text_size(fonts, fonts.table, line).x);
        if (!text_.note.empty()) w = std::max(w, rich_text_size(fonts, fonts.small, text_.note).x);
        return w + 2 * pad;
    };
    while (text_.lines.size() > 1 && width_of() > max_width) {
        // The widest line goes first, never the last one (the result).
        std::size_t widest = 0;
        float wmax = -1;
        for (std::size_t k = 0; k + 1 < text_.lines.size(); ++k) {
            const float w = rich_text_size(fonts, fonts.table, text_.lines[k]).x;
            if (w > wmax) wmax = w, widest = k;
        }
        text_.lines.erase(text_.lines.begin() + static_cast<long>(widest));
    }
    if (!text_.note.empty() && width_of() > max_width) text_.note.clear();
    float h =
        2 * pad + fonts.bold->FontSize * 1.4f + static_cast<float>(text_.lines.size()) * fonts.table->FontSize * 1.45f;
    if (!text_.note.empty()) h += fonts.small->FontSize * 1.5f;
    size_ = ImVec2(std::ceil(std::min(width_of(), max_width)), std::ceil(h));
}

Annotations FormulaBox::annotate(const FontSet& fonts, ImVec2 at) const {
    Annotations out;
    if (text_.empty()) return out;
    const Palette& c = style_.colours;
    const float pad = style_.px(10.0f);
    const auto line = [&](ImFont* font, const std::string& text, Colour colour, float y) {
        Annotation a;
        a.kind = Mark::formula_line;
        a.of = static_cast<int>(out.size());
        a.text = text;
        const ImVec2 size = rich_text_size(fonts, font, text);
        a.box = ImVec4(at.x + pad, y, at.x + pad + size.x, y + font->FontSize);
        a.font_px = font->FontSize;
        a.colour = colour;
        a.small = font == fonts.small;
        out.push_back(std::move(a));
    };
    float y = at.y + pad;
    line(fonts.bold, text_.heading, c.ink, y);
    y += fonts.bold->FontSize * 1.4f;
    for (std::size_t k = 0; k < text_.lines.size(); ++k) {
        // The last line is the result: in the impulse's colour.
        line(fonts.table, text_.lines[k], k + 1 == text_.lines.size() ? c.impulse : c.ink, y);
        y += fonts.table->FontSize * 1.45f;
    }
    if (!text_.note.empty()) line(fonts.small, text_.note, c.muted, y + style_.px(2.0f));
    return out;
}

void FormulaBox::draw(ImDrawList* dl, const FontSet& fonts, ImVec2 at) const {
    if (text_.empty()) return;
    draw_panel(dl, style_, at, size_);
    const Annotations lines = annotate(fonts, at);
    for (std::size_t k = 0; k < lines.size(); ++k) {
        ImFont* font = k == 0 ? fonts.bold : lines[k].small ? fonts.small : fonts.table;
        draw_rich_text(dl, fonts, font, ImVec2(lines[k].box.x, lines[k].box.y), lines[k].colour, lines[k].text);
    }
}

// ---- Plot ----

void Plot::prepare(const FontSet& fonts, std::string title, std::vector<double> times, std::vector<Series> series,
                   ImVec2 size) {
    (void)fonts;
    title_ = std::move(title);
    times_ = std::move(times);
    series_ = std::move(series);
    size_ = size;
    lo_ = 0;
    hi_ = 0;
    bool first = true;
    for (const Series& s : series_)
        for (double v : s.values) {
            if (!std::isfinite(v)) continue;
            lo_ = first ? v : std::min(lo_, v);
            hi_ = first ? v : std::max(hi_, v);
            first = false;
        }
    // Zero in range when it is near, and some room above and below.
    if (lo_ > 0 && lo_ < 0.5 * hi_) lo_ = 0;
    if (hi_ < 0 && hi_ > 0.5 * lo_) hi_ = 0;
    const double span = hi_ - lo_;
    const double pad = span > 1e-12 * std::max(std::abs(hi_), 1.0) ? 0.08 * span : std::max(0.05 * std::abs(hi_), 1e-3);
    lo_ -= pad;
    hi_ += pad;
}

void Plot::draw(ImDrawList* dl, const FontSet& fonts, ImVec2 at, double t) const {
    if (series_.empty() || times_.empty()) return;
    const Palette& c = style_.colours;
    const float pad = style_.px(8.0f);
    draw_panel(dl, style_, at, size_);
    // Title and the series' keys on the first line.
    float x = at.x + pad;
    const float y0 = at.y + pad * 0.6f;
    draw_rich_text(dl, fonts, fonts.small, ImVec2(x, y0), c.ink, title_);
    x += rich_text_size(fonts, fonts.small, title_).x + style_.px(12.0f);
    for (const Series& s : series_) {
        const float cy = y0 + 0.55f * fonts.small->FontSize;
        dl->AddLine(ImVec2(x, cy), ImVec2(x + style_.px(14.0f), cy), s.colour, style_.lw(2.5f));
        x += style_.px(18.0f);
        draw_rich_text(dl, fonts, fonts.small, ImVec2(x, y0), c.ink, s.label);
        x += rich_text_size(fonts, fonts.small, s.label).x + style_.px(10.0f);
    }
    // The plotting area; the value range at its left edge.
    const std::string hi_text = format_number(hi_, 3), lo_text = format_number(lo_, 3);
    const ImVec4 r = area(fonts, at);
    const ImVec2 p0(r.x, r.y), p1(r.z, r.w);
    if (p1.x - p0.x < 10 || p1.y - p0.y < 10) return;
    draw_rich_text(dl, fonts, fonts.small,
                   ImVec2(p0.x - style_.px(6.0f) - rich_text_size(fonts, fonts.small, hi_text).x,
                          p0.y - 0.5f * fonts.small->FontSize),
                   c.muted, hi_text);
    draw_rich_text(dl, fonts, fonts.small,
                   ImVec2(p0.x - style_.px(6.0f) - rich_text_size(fonts, fonts.small, lo_text).x,
                          p1.y - 0.5f * fonts.small->FontSize),
                   c.muted, lo_text);
    const double t0 = times_.front(), t1 = std::max(times_.back(), t0 + 1e-12);
    const auto X = [&](double tt) { return p0.x + static_cast<float>((tt - t0) / (t1 - t0)) * (p1.x - p0.x); };
    const auto Y = [&](double v) { return p1.y - static_cast<float>((v - lo_) / (hi_ - lo_)) * (p1.y - p0.y); };
    dl->AddLine(ImVec2(p0.x, p1.y), ImVec2(p1.x, p1.y), c.panel_border, style_.lw(1.0f));
    dl->AddLine(ImVec2(p0.x, p0.y), ImVec2(p0.x, p1.y), c.panel_border, style_.lw(1.0f));
    if (lo_ < 0 && hi_ > 0)
        draw_dashed_line(dl, ImVec2(p0.x, Y(0)), ImVec2(p1.x, Y(0)), c.grid, style_.lw(1.0f), style_.px(4.0f),
                         style_.px(4.0f));
    // At most one point per pixel column.
    const std::size_t n = times_.size();
    const std::size_t stride = std::max<std::size_t>(1, n / static_cast<std::size_t>(std::max(1.0f, p1.x - p0.x)));
    for (const Series& s : series_) {
        std::vector<ImVec2> past, all;
        // (A point on the one before it, as at an instant that leaves the value alone, would
        // draw a spike: ImGui's polyline has no direction for a segment of no length.)
        const auto add = [](std::vector<ImVec2>& line, ImVec2 q) {
            if (line.empty() || std::abs(line.back().x - q.x) + std::abs(line.back().y - q.y) > 0.01f)
                line.push_back(q);
        };
        for (std::size_t k = 0; k < n; k += stride) {
            const ImVec2 q(X(times_[k]), Y(s.values[k]));
            add(all, q);
            if (times_[k] <= t) add(past, q);
        }
        if (all.size() >= 2)
            dl->AddPolyline(all.data(), static_cast<int>(all.size()), with_alpha(s.colour, 0.25f), 0, style_.lw(1.5f));
        if (past.size() >= 2) dl->AddPolyline(past.data(), static_cast<int>(past.size()), s.colour, 0, style_.lw(2.0f));
    }
    for (const Annotation& a : annotate(fonts, at, t)) dl->AddCircleFilled(a.anchor, style_.px(3.5f), a.colour);
}

ImVec4 Plot::area(const FontSet& fonts, ImVec2 at) const {
    const float pad = style_.px(8.0f);
    const float y0 = at.y + pad * 0.6f;
    const float label_w = std::max(rich_text_size(fonts, fonts.small, format_number(hi_, 3)).x,
                                   rich_text_size(fonts, fonts.small, format_number(lo_, 3)).x);
    return ImVec4(at.x + pad + label_w + style_.px(6.0f), y0 + fonts.small->FontSize * 1.5f, at.x + size_.x - pad,
                  at.y + size_.y - pad);
}

Annotations Plot::annotate(const FontSet& fonts, ImVec2 at, double t) const {
    Annotations out;
    if (series_.empty() || times_.empty()) return out;
    const ImVec4 r = area(fonts, at);
    if (r.z - r.x < 10 || r.w - r.y < 10) return out;
    const double t0 = times_.front(), t1 = std::max(times_.back(), t0 + 1e-12);
    const std::size_t n = times_.size();
    for (const Series& s : series_) {
        // The value at t, interpolated between samples.
        const auto it = std::upper_bound(times_.begin(), times_.end(), t);
        const std::size_t k = it == times_.begin() ? 0 : static_cast<std::size_t>(it - times_.begin()) - 1;
        double v = s.values[k];
        if (k + 1 < n && times_[k + 1] > times_[k]) {
            const double u = std::clamp((t - times_[k]) / (times_[k + 1] - times_[k]), 0.0, 1.0);
            v = s.values[k] + u * (s.values[k + 1] - s.values[k]);
        }
        Annotation a;
        a.kind = Mark::plot_value;
        a.text = s.label;
        a.value = {v};
        a.colour = s.colour;
        a.anchor = ImVec2(r.x + static_cast<float>((std::clamp(t, t0, t1) - t0) / (t1 - t0)) * (r.z - r.x),
                          r.w - static_cast<float>((v - lo_) / (hi_ - lo_)) * (r.w - r.y));
        a.box = ImVec4(at.x, at.y, at.x + size_.x, at.y + size_.y);
        out.push_back(std::move(a));
    }
    return out;
}

// ---- Time line ----

void TimeLine::prepare(const FontSet& fonts, double duration, std::vector<double> collisions, float width) {
    duration_ = duration > 0 ? duration : 1.0;
    collisions_ = std::move(collisions);
    size_ = ImVec2(width, std::ceil(fonts.small->FontSize * 1.3f + style_.px(12.0f)));
}

void TimeLine::draw(ImDrawList* dl, const FontSet& fonts, ImVec2 at, double t) const {
    const Palette& c = style_.colours;
    const std::string end = format_compact(duration_) + " s";
    const float end_w = rich_text_size(fonts, fonts.small, end).x;
    const float zero_w = rich_text_size(fonts, fonts.small, "0").x;
    const float x0 = at.x + zero_w + style_.px(8.0f);
    const float x1 = at.x + size_.x - end_w - style_.px(8.0f);
    const float cy = std::round(at.y + style_.px(8.0f));
    const float bar = style_.px(3.0f);
    const auto X = [&](double tt) { return x0 + static_cast<float>(std::clamp(tt / duration_, 0.0, 1.0)) * (x1 - x0); };
    draw_rich_text(dl, fonts, fonts.small, ImVec2(at.x, cy - 0.55f * fonts.small->FontSize), c.muted, "0");
    draw_rich_text(dl, fonts, fonts.small, ImVec2(x1 + style_.px(8.0f), cy - 0.55f * fonts.small->FontSize), c.muted,
                   end);
    dl->AddRectFilled(ImVec2(x0, cy - bar), ImVec2(x1, cy + bar), c.grid, bar);
    dl->AddRectFilled(ImVec2(x0, cy - bar), ImVec2(X(t), cy + bar), with_alpha(c.velocity, 0.55f), bar);
    // Collisions: ticks across the bar (the first one a triangle below it). Many collisions
    // (a pile settling: thousands) would merge into one bar; beyond kTicks they are counted in
    // bins a few pixels wide instead, each a bar rising as the logarithm of its count (the
    // fullest bin the tallest): where the collisions crowd, and when.
    constexpr std::size_t kTicks = 40;
    if (collisions_.size() > kTicks) {
        const int bins = std::max(1, static_cast<int>((x1 - x0) / style_.px(3.0f)));
        std::vector<int> count(static_cast<std::size_t>(bins), 0);
        for (double tc : collisions_) {
            const int b = std::clamp(static_cast<int>(std::clamp(tc / duration_, 0.0, 1.0) * bins), 0, bins - 1);
            ++count[static_cast<std::size_t>(b)];
        }
        const int most = *std::max_element(count.begin(), count.end());
        const float w = (x1 - x0) / static_cast<float>(bins);
        for (int b = 0; b < bins; ++b) {
            const int nb = count[static_cast<std::size_t>(b)];
            if (nb == 0) continue;
            const float h = bar * (1.0f + 1.6f * static_cast<float>(std::log1p(nb) / std::log1p(most)));
            const float xb = x0 + w * static_cast<float>(b);
            const Colour colour = duration_ * (b + 0.5) / bins <= t ? c.impulse : with_alpha(c.impulse, 0.45f);
            dl->AddRectFilled(ImVec2(xb, cy - h), ImVec2(xb + std::max(1.0f, 0.8f * w), cy + bar), colour);
        }
    } else {
        for (std::size_t k = 0; k < collisions_.size(); ++k) {
            const float x = std::round(X(collisions_[k]));
            const Colour colour = collisions_[k] <= t ? c.impulse : with_alpha(c.impulse, 0.45f);
            dl->AddLine(ImVec2(x, cy - 2.2f * bar), ImVec2(x, cy + 2.2f * bar), colour, style_.lw(1.5f));
            if (k == 0) {
                const float s = style_.px(5.0f);
                dl->AddTriangleFilled(ImVec2(x, cy + 2.4f * bar), ImVec2(x - s, cy + 2.4f * bar + 1.4f * s),
                                      ImVec2(x + s, cy + 2.4f * bar + 1.4f * s), colour);
            }
        }
    }
    dl->AddCircleFilled(ImVec2(X(t), cy), style_.px(6.0f), c.velocity);
    dl->AddCircle(ImVec2(X(t), cy), style_.px(6.0f), c.background, 0, style_.lw(1.5f));
    // "collision" under the first tick.
    if (!collisions_.empty()) {
        const std::string label = "collisions (" + std::to_string(collisions_.size()) + ")";
        const float lw = rich_text_size(fonts, fonts.small, label).x;
        const float lx = std::clamp(X(collisions_.front()) + style_.px(9.0f), x0, x1 - lw);
        draw_rich_text(dl, fonts, fonts.small, ImVec2(lx, cy + 1.4f * bar), c.muted, label);
    }
}

}  // namespace collide::render
