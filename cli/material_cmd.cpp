#include "cli/material_cmd.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <string>

#include "cli/exit_code.h"
#include "cli/terminal.h"
#include "cli/render_options.h"
#include "cli/signals.h"
#include "present/site.h"
#include "present/staged_dir.h"
#include "render/video.h"
#include "scenario/input_error.h"

namespace collide {

namespace fs = std::filesystem;

std::string engine_js_path(const std::string& installed) {
    std::error_code ec;
    if (const char* env = std::getenv("COLLIDE_ENGINE_JS"); env && *env) {
        if (!fs::is_regular_file(env, ec))
            throw InputError("", {}, "COLLIDE_ENGINE_JS",
                             std::string("'") + env +
                                 "' is not a file (the WebAssembly "
                                 "module collide-engine.js: scripts/build-wasm.sh builds it)");
        return env;
    }
    if (!installed.empty() && fs::is_regular_file(installed, ec)) return installed;
    if (fs::is_regular_file(COLLIDE_ENGINE_JS_BUILD, ec)) return COLLIDE_ENGINE_JS_BUILD;
    return "";
}

std::string engine_js_path() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);  // Linux: the running program
    return engine_js_path(ec ? std::string()
                             : (exe.parent_path() / COLLIDE_ENGINE_JS_FROM_BINDIR).lexically_normal().string());
}

std::string three_js_path(std::string* looked) {
    const char* env = std::getenv("COLLIDE_THREE_JS");
    const std::string path = env && *env ? env : COLLIDE_THREE_JS_PATH;
    if (looked) *looked = path;
    std::error_code ec;
    return fs::is_regular_file(path, ec) ? path : std::string();
}

int run_material(const MaterialOptions& opt, std::ostream& out, std::ostream& err) {
    const auto start = std::chrono::steady_clock::now();
    // The staged directory is gone with the body's scope when it throws: DIR is untouched.
    return cli::run_staged_command(err, opt.out_dir, [&] {
        if (opt.out_dir.empty()) throw InputError("", {}, "-o", "the output directory is required");
        // The lessons first: nothing is written when one is wrong.
        std::vector<Lesson> lessons;
        if (opt.lessons.empty()) {
            lessons = load_lessons(lessons_dir());
        } else {
            for (const std::string& arg : opt.lessons) {
                const std::string file = resolve_lesson(arg, lessons_dir());
                SceneView view;
                std::optional<Lesson> lesson;
                load_scenario(file, &view, &lesson);
                if (!lesson) throw InputError(file, {}, "", "is a scenario, not a lesson (it has no [lesson] table)");
                lessons.push_back(*lesson);
            }
        }
        if (lessons.empty()) throw InputError(lessons_dir(), {}, "", "no lessons found");
        // The WebAssembly module, for the pages' Try-it panels (docs/commands/material.md, "The Try-it panel").
        const std::string engine_js = engine_js_path();
        // three.js for the 3D lessons' panels: without it they say so on the page, and here.
        std::string three_js, three_looked;
        if (!engine_js.empty() &&
            std::any_of(lessons.begin(), lessons.end(), [](const Lesson& L) { return L.scene.dimension == 3; })) {
            three_js = three_js_path(&three_looked);
            if (three_js.empty())
                err << "collide material: note: no 3D view in the 3D lessons' Try-it panels: three.js is not at "
                    << three_looked
                    << " (Debian: apt-get install libjs-three; or set COLLIDE_THREE_JS); those panels say so "
                       "and show their numbers and plots\n";
        }
        // Ctrl-C from here on is one flag for the whole command (lessons, frames, ffmpeg),
        // held until the staging directory is removed again.
        const cli::SignalGuard signals;
        StagedDirectory staged(opt.out_dir, opt.force);
        // The options, read once as collide render reads them: every lesson renders with them,
        // and with an MP4 when ffmpeg is installed.
        RenderOptions ro;
        ro.out_dir = opt.out_dir;
        ro.size = opt.size;
        ro.fps = opt.fps;
        ro.quality = opt.quality;
        ro.quiet = true;
        RenderRequest request = parse_render_request(ro);
        if (const std::string ffmpeg = render::find_program("ffmpeg"); !ffmpeg.empty())
            request.video = VideoRequest{render::VideoFormat::mp4, ffmpeg};
        const bool video = request.video.has_value();
        // Build beside DIR, rename at the end.
        const fs::path& tmp = staged.begin();
        const bool terminal = !opt.quiet && cli::progress_watched(err);

        const auto progress = [&](const SiteProgress& p) {
            if (!terminal) return;
            char line[200];
            std::snprintf(line, sizeof line, "[%zu/%zu] %-24s %5.1f s\n", p.done, p.total, p.id.c_str(), p.seconds);
            err << line << std::flush;
        };
        std::ostringstream notes;  // what a page lacks, and why: said even with --quiet
        build_site(SiteRequest{lessons, request, engine_js, three_js, &notes}, tmp, progress, cli::stop_requested);
        staged.commit();
        std::istringstream said(notes.str());
        for (std::string line; std::getline(said, line);) err << "collide material: note: " << line << "\n";
        if (!opt.quiet) {
            char line[200];
            std::snprintf(line, sizeof line, "wrote %zu lessons to %s/index.html in %.1f s%s\n", lessons.size(),
                          opt.out_dir.c_str(), cli::seconds_since(start),
                          video ? "" : " (no ffmpeg: pages link the PNG frames instead of a video)");
            out << line;
            if (engine_js.empty())
                out << "no Try-it panels: the WebAssembly module collide-engine.js is not built (scripts/build-wasm.sh "
                       "builds it where this command finds it, " COLLIDE_ENGINE_JS_BUILD
                       "; or set COLLIDE_ENGINE_JS)\n";
        }
        return 0;
    });
}

}  // namespace collide
