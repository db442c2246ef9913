#include "present/site.h"

#include <algorithm>
#include <chrono>
#include <sstream>

#include "assets/site.h"
#include "present/site_pages.h"
#include "present/try_it_answer.h"
#include "present/site_plots.h"
#include "render/png.h"
#include "teach/html.h"

namespace collide {

namespace fs = std::filesystem;

void build_site(const SiteRequest& rq, const fs::path& dir, const std::function<void(const SiteProgress&)>& progress,
                const StopRequested& stop) {
    using html::Series;
    using html::svg_plot;
    RenderRequest request = rq.render;
    std::vector<SitePage> built;
    for (std::size_t k = 0; k < rq.lessons.size(); ++k) {
        const Lesson& L = rq.lessons[k];
        const auto t0 = std::chrono::steady_clock::now();
        request.scenario = L.file;
        request.out_dir = (dir / L.id).string();
        std::ostringstream notes;  // "no collision" notes: not an error for a lesson page
        SitePage b{L, !rq.engine_js.empty(), render_scenario(request, notes, stop), false, {}, 0, std::nullopt};
        // "Check yourself" asks the lesson's numeric questions with other numbers than the run
        // its figures show (teach/check_variant.h).
        if (!L.vary.empty()) b.check = check_variant(L, b.report.answers);
        // The thumbnail: the figure's collision panel (collide render writes it), else the
        // first frame.
        const fs::path lesson_dir = dir / L.id;
        if (!fs::exists(lesson_dir / "thumb.png") && fs::exists(lesson_dir / "frames/frame_00000.png")) {
            const render::Image thumb =
                render::shrink(render::read_png((lesson_dir / "frames/frame_00000.png").string()), 480);
            render::write_png_atomic((lesson_dir / "thumb.png").string(), thumb.width, thumb.height, thumb.rgba.data());
        }
        b.thumb = fs::exists(lesson_dir / "thumb.png");
        for (const RenderReport::Shown& f : b.report.figures)
            b.figure_widths.push_back(render::read_png((lesson_dir / f.file).string()).width);
        if (fs::exists(lesson_dir / "variants.png"))
            b.variants_width = render::read_png((lesson_dir / "variants.png").string()).width;
        // Plots.
        const RenderReport& r = b.report;
        const render::TotalsColumns col = render::totals_columns(r.plot_totals);
        std::vector<Series> energy = {{"kinetic", "#1d4ed8", col.kinetic}};
        if (L.scene.gravity.norm() > 0) {
            energy.push_back({"potential", "#0f766e", col.potential});
            energy.push_back({"total", "#1c1c1e", col.total});
        }
        std::vector<Series> momentum;
        if (L.scene.dimension == 1) {
            momentum.push_back({"p", "#1d4ed8", col.px});
        } else {
            momentum.push_back({"p_x", "#1d4ed8", col.px});
            momentum.push_back({"p_y", "#ce2029", col.py});
            if (L.scene.dimension == 3) momentum.push_back({"p_z", "#0f766e", col.pz});
        }
        render::write_file_atomic((lesson_dir / "energy.svg").string(),
                                  svg_plot("Energy (J)", r.plot_t, energy, r.collision_times, L.scene.duration));
        render::write_file_atomic(
            (lesson_dir / "momentum.svg").string(),
            svg_plot("Momentum (kg m/s)", r.plot_t, momentum, r.collision_times, L.scene.duration));
        // The lesson's own [[plot]] entries (present/site_plots.h).
        for (const auto& [file, svg] : plot_svgs(r.plots)) render::write_file_atomic((lesson_dir / file).string(), svg);
        built.push_back(std::move(b));
        // Between lessons too: an interrupt during a lesson's figures or plots (no frame left
        // to ask) is honoured here, not lost.
        if (stop && stop()) throw Interrupted(0);
        if (progress)
            progress({k + 1, rq.lessons.size(), L.id,
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()});
    }
    for (std::size_t k = 0; k < built.size(); ++k) {
        if (built[k].try_it) {
            // The panel's answer for the lesson's own values, as its module gives it: shown at
            // once, before the module has started. A lesson it cannot answer gets none, and the
            // command says so: its page waits for the module, which says why.
            std::string first;
            try {
                first = try_it_answer_json(built[k].lesson.source, "{}", built[k].fps());
            } catch (const std::exception& e) {
                first.clear();
                if (rq.notes)
                    *rq.notes << built[k].lesson.id << ": the Try-it panel opens without the command's answer ("
                              << e.what() << "): the engine in the page answers when it has started\n";
            }
            render::write_file_atomic((dir / built[k].lesson.id / "try-it-lesson.js").string(),
                                      html::try_it_data_js(built[k].lesson, palette_json(), first));
        }
        render::write_file_atomic(
            (dir / built[k].lesson.id / "index.html").string(),
            lesson_page(built[k], k > 0 ? &built[k - 1] : nullptr, k + 1 < built.size() ? &built[k + 1] : nullptr));
        render::write_file_atomic((dir / built[k].lesson.id / "teacher.html").string(), teacher_page(built[k]));
    }
    render::write_file_atomic((dir / "index.html").string(), index_page(built));
    render::write_file_atomic((dir / "style.css").string(), std::string(assets::site_style_css));
    if (!rq.engine_js.empty()) {
        fs::copy_file(rq.engine_js, dir / "collide-engine.js", fs::copy_options::overwrite_existing);
        render::write_file_atomic((dir / "try-it.js").string(), std::string(assets::site_try_it_js));
        render::write_file_atomic((dir / "try-it-picture.js").string(), std::string(assets::site_try_it_picture_js));
        render::write_file_atomic((dir / "try-it-drag.js").string(), std::string(assets::site_try_it_drag_js));
        render::write_file_atomic((dir / "try-it-plot.js").string(), std::string(assets::site_try_it_plot_js));
        const bool any3d =
            std::any_of(rq.lessons.begin(), rq.lessons.end(), [](const Lesson& L) { return L.scene.dimension == 3; });
        if (any3d) {
            render::write_file_atomic((dir / "try-it-3d.js").string(), std::string(assets::site_try_it_3d_js));
            if (!rq.three_js.empty())
                fs::copy_file(rq.three_js, dir / "three.min.js", fs::copy_options::overwrite_existing);
        }
    }
    if (stop && stop()) throw Interrupted(0);  // the last chance before the command renames it into place
}

}  // namespace collide
