#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "render/imgui_layer.h"
#include "render/overlay.h"
#include "render/scene3d_view.h"
#include "render/target.h"

namespace collide::render {

namespace {

void clear(const Gl& gl, Colour c) {
    const auto ch = [c](int shift) { return static_cast<float>((c >> shift) & 0xFF) / 255.0f; };
    gl.ClearColor(ch(0), ch(8), ch(16), 1.0f);
    gl.ClearDepth(1.0);
    gl.DepthMask(GL_TRUE);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

}  // namespace

Renderer::Renderer(GlContext& context, const Scene& scene, const RenderSettings& settings)
    : context_(context),
      scene_(scene),
      settings_(settings),
      style_(Style::for_height(settings.font_height > 0 ? settings.font_height : settings.height)) {
    const Gl& gl = context_.gl();
    target_ = std::make_unique<RenderTarget>(gl, settings_.width, settings_.height, settings_.samples);
    imgui_ = std::make_unique<ImGuiLayer>(
        gl, settings_.width, settings_.height,
        FontSizes::for_height(settings.font_height > 0 ? settings.font_height : settings.height), settings_.font_dir);
    diagram_ = std::make_unique<DiagramView>(scene_, style_);
    diagram_->reserve_directions(settings_.directions);
    diagram_->frame_only(settings_.frame_bodies);
    diagram_->frame_points(settings_.points);
    if (settings_.view == ViewKind::perspective) {
        view3d_ = std::make_unique<Scene3dView>(gl, scene_, style_);
        view3d_->set_camera(settings_.camera);
    }
    table_ = std::make_unique<DataTable>(scene_, style_);
    header_ = std::make_unique<Header>(style_);
    formula_ = std::make_unique<FormulaBox>(style_);
    energy_plot_ = std::make_unique<Plot>(style_);
    momentum_plot_ = std::make_unique<Plot>(style_);
    timeline_ = std::make_unique<TimeLine>(style_);
}

Renderer::~Renderer() = default;

ImVec2 Renderer::to_screen(const Vec3& world) const {
    return view3d_ ? view3d_->to_screen(world) : diagram_->to_screen(world);
}

bool Renderer::has_glyphs(const std::string& utf8) const { return imgui_->has_glyphs(utf8); }

void Renderer::set_camera(const CameraRequest& camera) {
    settings_.camera = camera;
    if (view3d_) view3d_->set_camera(camera);
}

void Renderer::prepare(const std::vector<FrameState>& samples, const std::vector<ImpactMark>& impacts) {
    const FontSet& fonts = imgui_->fonts();
    const float W = static_cast<float>(settings_.width), H = static_cast<float>(settings_.height);
    const float m = style_.px(style_.margin);
    const float gap = style_.px(16.0f);
    const Palette& c = style_.colours;

    bool any_spin = false, any_impulse = false;
    for (const FrameState& f : samples)
        for (std::size_t i = 0; i < f.bodies.size(); ++i)
            any_spin = any_spin || (!scene_.bodies[i].is_static() && f.bodies[i].w.norm() > 0);
    for (const ImpactMark& im : impacts) any_impulse = any_impulse || im.impulse.norm() > 0;

    // The legend, with arrows at their longest for the layout (the final ones are shorter).
    const auto legend = [&](float v_px, double v_value, float p_px, double p_value) {
        std::vector<LegendEntry> entries;
        entries.push_back(
            {LegendEntry::Mark::arrow, c.velocity, v_px, "velocity  " + format_compact(v_value) + " m/s", {1, 0}});
        if (any_spin)
            entries.push_back({LegendEntry::Mark::curved_arrow,
                               c.spin,
                               0.0f,
                               view3d_ ? "angular velocity \u03C9 (right-hand rule)"
                                       : "angular velocity \u03C9 (+: counter-clockwise)",
                               {1, 0}});
        if (any_impulse)
            entries.push_back(
                {LegendEntry::Mark::arrow, c.impulse, p_px, "impulse  " + format_compact(p_value) + " N s", {1, 0}});
        const Vec3 g = scene_.gravity;
        if (g.norm() > 0) {
            // Where gravity points on the screen (the 3D view: about down).
            ImVec2 d(static_cast<float>(g.x()), static_cast<float>(-g.y()));
            const float len = std::sqrt(d.x * d.x + d.y * d.y);
            d = len > 1e-6f ? ImVec2(d.x / len, d.y / len) : ImVec2(0, 1);
            entries.push_back({LegendEntry::Mark::direction, c.muted, 0.0f,
                               "gravity  g = " + format_compact(g.norm()) + " m/s\u00B2", d});
        }
        return entries;
    };
    const float longest = style_.px(110.0f);
    if (settings_.header)
        header_->prepare(fonts, scene_.title, settings_.time_decimals, legend(longest, 5.0, longest, 5.0));
    const ImVec2 hs = settings_.header ? header_->size() : ImVec2(0, 0);

    // The bottom strip: the time line across the frame; above it the plots and the formula.
    float strip = 0;  // its height, margin included
    if (settings_.timeline) {
        std::vector<double> times;
        for (const ImpactMark& im : impacts) times.push_back(im.t);
        timeline_->prepare(fonts, scene_.duration, times, W - 2 * m);
        strip += timeline_->size().y;
        timeline_at_ = ImVec2(m, H - m - strip);
    }
    const bool formula = !settings_.formula.empty();
    if (settings_.plots || formula) {
        if (formula) formula_->prepare(fonts, settings_.formula, 0.6f * W);
        const ImVec2 fs = formula ? formula_->size() : ImVec2(0, 0);
        const float row_h = std::max(fs.y, style_.px(120.0f));
        float plot_w = 0;
        if (settings_.plots) {
            const float room = W - 2 * m - (formula ? fs.x + gap : 0.0f) - gap;
            plot_w = std::min(style_.px(340.0f), 0.5f * room);
            if (plot_w < style_.px(160.0f)) plot_w = 0;  // no room: no plots
        }
        const float y = H - m - strip - (strip > 0 ? gap * 0.5f : 0.0f) - row_h;
        if (plot_w > 0) {
            std::vector<double> t = plot_t_;
            std::vector<FrameTotals> sums = plot_totals_;
            if (t.empty() || t.size() != sums.size()) {
                t.clear();
                sums.clear();
                for (const FrameState& f : samples) {
                    t.push_back(f.t);
                    sums.push_back(frame_totals(scene_, f));
                }
            }
            const TotalsColumns col = totals_columns(sums);
            std::vector<Plot::Series> energy = {{"E_{k}", c.velocity, col.kinetic}};
            if (scene_.gravity.norm() > 0) {
                energy.push_back({"E_{p}", c.normal, col.potential});
                energy.push_back({"E", c.ink, col.total});
            }
            energy_plot_->prepare(fonts, "energy (J)", t, energy, ImVec2(plot_w, row_h));
            std::vector<Plot::Series> momentum;
            if (scene_.dimension == 1) {
                momentum.push_back({"p", c.velocity, col.px});
            } else {
                momentum.push_back({"p_{x}", c.velocity, col.px});
                momentum.push_back({"p_{y}", c.impulse, col.py});
                if (scene_.dimension == 3) momentum.push_back({"p_{z}", c.normal, col.pz});
            }
            momentum_plot_->prepare(fonts, "momentum (kg m/s)", t, momentum, ImVec2(plot_w, row_h));
            energy_at_ = ImVec2(m, y);
            momentum_at_ = ImVec2(m + plot_w + gap, y);
        } else {
            energy_plot_->prepare(fonts, "", {}, {}, ImVec2(0, 0));
            momentum_plot_->prepare(fonts, "", {}, {}, ImVec2(0, 0));
        }
        formula_at_ = ImVec2(W - m - fs.x, y + row_h - fs.y);
        strip += row_h + (strip > 0 ? gap * 0.5f : 0.0f);
    }
    if (strip > 0) strip += gap;
    const float bottom = H - strip;  // the views end here

    // The table: as tall as the room under the header allows (a scene of many bodies gets a
    // row for the few that matter in each frame, and a line for the others).
    if (settings_.table) table_->prepare(fonts, samples, bottom - m - (hs.y > 0 ? hs.y + gap : 0.0f));
    const ImVec2 ts = settings_.table ? table_->size() : ImVec2(0, 0);

    // Two layouts: overlays in a band across the top, or in a column on the right.
    struct Layout {
        ImVec4 view;
        ImVec2 header_at, table_at;
    };
    std::vector<Layout> layouts;
    if (hs.x + ts.x == 0) {
        layouts.push_back({ImVec4(0, 0, W, bottom), {m, m}, {W - m, m}});
    } else {
        // Band: header left, table right (stacked if they do not fit side by side).
        Layout band;
        float band_h;
        if (hs.x + ts.x + 2 * m + gap <= W) {
            band.header_at = ImVec2(m, m);
            band.table_at = ImVec2(W - m - ts.x, m);
            band_h = std::max(hs.y, ts.y);
        } else {
            band.header_at = ImVec2(m, m);
            band.table_at = ImVec2(m, m + hs.y + gap);
            band_h = hs.y + gap + ts.y;
        }
        band.view = ImVec4(0, m + band_h, W, bottom);
        layouts.push_back(band);
        // Column on the right: header above the table.
        const float col_w = std::max(hs.x, ts.x);
        Layout column;
        column.header_at = ImVec2(W - m - col_w, m);
        column.table_at = ImVec2(W - m - ts.x, m + hs.y + (hs.y > 0 ? gap : 0));
        column.view = ImVec4(0, 0, W - m - col_w - gap, bottom);
        if (column.view.z > 0.3f * W) layouts.push_back(column);
    }
    double best = -1;
    for (const Layout& L : layouts) {
        double score;
        if (view3d_) {
            view3d_->fit(samples, impacts, L.view, settings_.width, settings_.height);
            score = view3d_->pixels_per_metre();
        } else {
            diagram_->fit(samples, impacts, L.view);
            score = diagram_->pixels_per_metre();
        }
        if (score > best * 1.02) {  // ties go to the first (the band)
            best = score;
            view_rect_ = L.view;
            header_at_ = L.header_at;
            table_at_ = L.table_at;
        }
    }
    DiagramView::Legend vl, pl;
    if (view3d_) {
        view3d_->fit(samples, impacts, view_rect_, settings_.width, settings_.height);
        vl = view3d_->velocity_legend();
        pl = view3d_->impulse_legend();
    } else {
        diagram_->fit(samples, impacts, view_rect_);
        vl = diagram_->velocity_legend();
        pl = diagram_->impulse_legend();
    }
    if (settings_.header) {
        std::vector<LegendEntry> entries = legend(vl.pixels, vl.value, pl.pixels, pl.value);
        if (vl.value == 0) entries.erase(entries.begin());  // nothing moves
        header_->prepare(fonts, scene_.title, settings_.time_decimals, entries);
    }
}

void Renderer::draw(const FrameState& frame, const Decor& decor) {
    const Gl& gl = context_.gl();
    const FontSet& fonts = imgui_->fonts();
    // First the list of what the view shows, its labels placed around the overlays; then the
    // GL pass and ImGui draw it.
    LabelPlacer labels(view_rect_);
    if (settings_.header) {
        const ImVec2 s = header_->size();
        labels.reserve(ImVec4(header_at_.x, header_at_.y, header_at_.x + s.x, header_at_.y + s.y));
    }
    if (settings_.table) {
        const ImVec2 s = table_->size();
        labels.reserve(ImVec4(table_at_.x, table_at_.y, table_at_.x + s.x, table_at_.y + s.y));
    }
    if (!energy_plot_->empty()) {
        const ImVec2 s = energy_plot_->size();
        labels.reserve(ImVec4(energy_at_.x, energy_at_.y, momentum_at_.x + s.x, energy_at_.y + s.y));
    }
    if (!settings_.formula.empty()) {
        const ImVec2 s = formula_->size();
        labels.reserve(ImVec4(formula_at_.x, formula_at_.y, formula_at_.x + s.x, formula_at_.y + s.y));
    }
    annotations_ =
        view3d_ ? view3d_->annotate(fonts, frame, decor, &labels) : diagram_->annotate(fonts, frame, decor, &labels);

    if (view3d_ && target_->samples() > 0 && settings_.msaa_region) {
        // The ground everywhere without MSAA; then, in the rectangle the bodies, arrows and
        // lines cover, the ground again and those with MSAA, resolved over it. The ground's
        // pixels are the same both ways (its shader runs once per pixel, at the centre).
        target_->bind_resolved();
        clear(gl, style_.colours.background);
        view3d_->draw_ground(frame);
        ImVec4 r;
        if (view3d_->above_bounds(frame, decor, annotations_, &r)) {
            const int W = settings_.width, H = settings_.height;
            const int x0 = std::clamp(static_cast<int>(std::floor(r.x)), 0, W);
            const int x1 = std::clamp(static_cast<int>(std::ceil(r.z)), 0, W);
            const int y0 = std::clamp(static_cast<int>(std::floor(r.y)), 0, H);
            const int y1 = std::clamp(static_cast<int>(std::ceil(r.w)), 0, H);
            if (x1 > x0 && y1 > y0) {
                target_->bind();
                gl.Enable(GL_SCISSOR_TEST);
                gl.Scissor(x0, H - y1, x1 - x0, y1 - y0);
                clear(gl, style_.colours.background);
                view3d_->draw(frame, decor, annotations_);
                gl.Disable(GL_SCISSOR_TEST);
                target_->resolve(x0, H - y1, x1 - x0, y1 - y0);
            }
        }
        target_->bind_resolved();  // the overlays go on the resolved frame
    } else {
        target_->bind();
        clear(gl, style_.colours.background);
        if (view3d_) {
            view3d_->draw(frame, decor, annotations_);
            target_->resolve();  // the overlays go on the resolved frame: see RenderTarget::resolve
        }
    }
    imgui_->begin(settings_.smooth);
    ImDrawList* dl = imgui_->draw_list();
    if (view3d_) view3d_->draw_labels(dl, fonts, annotations_);
    else diagram_->draw(dl, fonts, frame, decor, annotations_);
    if (settings_.header) header_->draw(dl, fonts, header_at_, frame.t);
    if (settings_.table) table_->draw(dl, fonts, table_at_, frame);
    if (!energy_plot_->empty()) {
        energy_plot_->draw(dl, fonts, energy_at_, frame.t);
        momentum_plot_->draw(dl, fonts, momentum_at_, frame.t);
    }
    if (!settings_.formula.empty()) formula_->draw(dl, fonts, formula_at_);
    if (settings_.timeline) timeline_->draw(dl, fonts, timeline_at_, frame.t);
    imgui_->end();
    // The overlays' items after the view's (each overlay drew what it lists).
    const auto append = [&](Annotations items) {
        for (Annotation& a : items) annotations_.push_back(std::move(a));
    };
    if (settings_.table) append(table_->annotate(fonts, table_at_, frame));
    if (!energy_plot_->empty()) {
        append(energy_plot_->annotate(fonts, energy_at_, frame.t));
        append(momentum_plot_->annotate(fonts, momentum_at_, frame.t));
    }
    if (!settings_.formula.empty()) append(formula_->annotate(fonts, formula_at_));
}

void Renderer::render(const FrameState& frame, const Decor& decor, std::uint8_t* rgba) {
    Decor d = decor;
    d.directions = d.directions || settings_.directions;
    draw(frame, d);
    target_->read_rgba(rgba);
}

Image Renderer::render(const FrameState& frame, const Decor& decor) {
    Image image;
    image.width = settings_.width;
    image.height = settings_.height;
    image.rgba.resize(static_cast<std::size_t>(image.width) * image.height * 4);
    render(frame, decor, image.rgba.data());
    return image;
}

Image compose_figure(GlContext& context, const std::vector<Image>& panels, const std::vector<std::string>& captions,
                     const std::vector<std::string>& notes, int font_height, bool stacked,
                     const std::string& font_dir) {
    if (panels.empty()) throw std::invalid_argument("compose_figure: no panels");
    const Gl& gl = context.gl();
    const Style style = Style::for_height(font_height);
    const FontSizes sizes = FontSizes::for_height(font_height);
    const int pw = panels[0].width, ph = panels[0].height;
    const float g = style.px(20.0f);
    const int n = static_cast<int>(panels.size());
    const float caption_h = sizes.bold * 1.5f + (notes.empty() ? 0.0f : sizes.small * 1.5f);
    const int across = stacked ? 1 : n, down = stacked ? n : 1;
    const int width = static_cast<int>(std::ceil(static_cast<float>(across * pw) + g * static_cast<float>(across + 1)));
    const int height =
        static_cast<int>(std::ceil(static_cast<float>(down) * (static_cast<float>(ph) + g + caption_h) + g));

    RenderTarget target(gl, width, height, 0);  // panels are already anti-aliased
    ImGuiLayer imgui(gl, width, height, sizes, font_dir);
    std::vector<GLuint> textures(panels.size());
    gl.GenTextures(static_cast<GLsizei>(textures.size()), textures.data());
    for (std::size_t k = 0; k < panels.size(); ++k) {
        if (panels[k].width != pw || panels[k].height != ph)
            throw std::invalid_argument("compose_figure: panels differ in size");
        gl.BindTexture(GL_TEXTURE_2D, textures[k]);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // 1:1, no filtering
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
        gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, pw, ph, 0, GL_RGBA, GL_UNSIGNED_BYTE, panels[k].rgba.data());
    }
    target.bind();
    clear(gl, style.colours.background);
    imgui.begin(true);
    ImDrawList* dl = imgui.draw_list();
    const FontSet& fonts = imgui.fonts();
    for (int k = 0; k < n; ++k) {
        const float x = g + static_cast<float>(stacked ? 0 : k) * (static_cast<float>(pw) + g);
        const float top = g + static_cast<float>(stacked ? k : 0) * (static_cast<float>(ph) + g + caption_h);
        const ImVec2 p0(x, top), p1(x + static_cast<float>(pw), top + static_cast<float>(ph));
        dl->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(textures[static_cast<std::size_t>(k)])),
                     p0, p1);
        dl->AddRect(ImVec2(p0.x - 0.5f, p0.y - 0.5f), ImVec2(p1.x + 0.5f, p1.y + 0.5f), style.colours.panel_border,
                    0.0f, 0, style.px(1.0f));
        float y = p1.y + g * 0.6f;
        if (static_cast<std::size_t>(k) < captions.size()) {
            const ImVec2 s = rich_text_size(fonts, fonts.bold, captions[static_cast<std::size_t>(k)]);
            draw_rich_text(dl, fonts, fonts.bold, ImVec2(std::round(x + 0.5f * (static_cast<float>(pw) - s.x)), y),
                           style.colours.ink, captions[static_cast<std::size_t>(k)]);
            y += sizes.bold * 1.5f;
        }
        if (static_cast<std::size_t>(k) < notes.size()) {
            const ImVec2 s = rich_text_size(fonts, fonts.small, notes[static_cast<std::size_t>(k)]);
            draw_rich_text(dl, fonts, fonts.small, ImVec2(std::round(x + 0.5f * (static_cast<float>(pw) - s.x)), y),
                           style.colours.muted, notes[static_cast<std::size_t>(k)]);
        }
    }
    imgui.end();
    Image out;
    out.width = width;
    out.height = height;
    out.rgba.resize(static_cast<std::size_t>(width) * height * 4);
    target.read_rgba(out.rgba.data());
    gl.DeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
    return out;
}

}  // namespace collide::render
