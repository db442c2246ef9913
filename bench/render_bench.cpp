// render/..., encode/...: the frame pipeline of `collide render`, per frame.
//   render/<size>/aa, render/<size>/plain: end to end as the command runs it: draw a frame
//     of the bundled billiards scene (2D diagram with the table, plots, formula and time
//     line), read it back, PNG-encode it on the encoder thread beside rendering and write it
//     to a temporary directory. "aa" is --quality medium (Dear ImGui's anti-aliased edges;
//     the 2D view needs no MSAA), "plain" is --quality low.
//   render3d/<size>/aa, render3d/<size>/plain: the same for the 3D view (dropped-box-3d),
//     "aa" with 4x multisampling of the rectangle the bodies and arrows cover (msaa_region);
//     render3d/720p/aa-whole multisamples the whole frame instead: what "aa" costs when the
//     bodies fill the frame (the worst case).
//   encode/720p: PNG encoding alone (zlib level 1, no filter: --quality medium) of the same
//     720p frames, already in memory.
// items_per_second is frames per second. Each run renders a fixed 120 frames, the last ones
// waited for inside the timing. Benchmarks measure; they assert nothing.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <unistd.h>

#include "scenario/scene_file.h"
#include "engine/world.h"
#include "render/context.h"
#include "render/frame_sink.h"
#include "render/frame_state.h"
#include "render/png.h"
#include "render/renderer.h"

namespace {

using namespace collide;
namespace fs = std::filesystem;

constexpr int kFrames = 120;

struct Run {
    Scene scene;
    std::vector<render::FrameState> frames;
    std::vector<render::ImpactMark> impacts;
};

// The scene's frames at 60 per simulated second, with trails and the collisions marked.
template <int D>
Run simulate(const std::string& file) {
    Run run{parse_scene_file(std::string(COLLIDE_SOURCE_DIR) + "/" + file), {}, {}};
    World<D> world(run.scene);
    std::vector<Event<D>> events;
    for (double t = 0; t <= run.scene.duration; t += 1.0 / 60.0) {
        const std::size_t first = events.size();
        world.advance_to(t, &events);
        for (std::size_t k = first; k < events.size(); ++k)
            run.impacts.push_back(render::impact_mark(run.scene, events[k]));
        run.frames.push_back(render::frame_state(run.scene, t, world.bodies()));
    }
    for (render::FrameState& f : run.frames) render::add_trails(run.frames, 0.5, &f);
    return run;
}

const Run& billiards() {
    static const Run run = simulate<2>("lessons/scenes/billiards-2d.toml");
    return run;
}
const Run& dropped_box() {
    static const Run run = simulate<3>("lessons/scenes/dropped-box-3d.toml");
    return run;
}

render::GlContext& context() {
    static std::unique_ptr<render::GlContext> c = render::create_gl_context(render::GlBackend::osmesa);
    return *c;
}

render::RenderSettings settings(int w, int h, bool aa, bool view3d, bool region = true) {
    render::RenderSettings s;
    s.msaa_region = region;
    s.width = w;
    s.height = h;
    s.samples = aa && view3d ? 4 : 0;
    s.smooth = aa;
    s.view = view3d ? render::ViewKind::perspective : render::ViewKind::diagram;
    s.formula = {"Collision of cue and ball1  (frictionless, e = 1)",
                 {"D = 1/m_{a} + 1/m_{b} + (r_{a} \u00D7 n)\u00B2/I_{a} + (r_{b} \u00D7 n)\u00B2/I_{b}",
                  "j = \u2212(1 + e) u_{n} / D", "P = j n = (0.338, \u22120.024) N\u00B7s"},
                 ""};
    return s;
}

void end_to_end(benchmark::State& state, const Run& run, int w, int h, bool aa, bool view3d, bool region) {
    render::Renderer renderer(context(), run.scene, settings(w, h, aa, view3d, region));
    renderer.prepare(run.frames, run.impacts);
    const fs::path dir = fs::temp_directory_path() / ("collide-bench-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    {
        render::FrameSinkOptions o;
        o.dir = dir.string();
        o.png = render::PngOptions{1, true, false};
        o.threads = 1;
        o.buffers = 3;
        render::FrameSink sink(w, h, o);
        long k = 0;
        for (auto _ : state) {
            render::FrameState f = run.frames[static_cast<std::size_t>(k) % run.frames.size()];
            for (const render::ImpactMark& im : run.impacts)
                if (std::abs(im.t - f.t) < 0.5 / 60.0) f.impacts.push_back(im);
            render::FrameSink::Buffer* buffer = sink.acquire();
            renderer.render(f, render::Decor{}, buffer->data());
            sink.submit(k, buffer);
            if (++k == static_cast<long>(state.max_iterations)) sink.finish();  // timed
        }
        state.SetItemsProcessed(k);
    }
    fs::remove_all(dir);
}

void encode_only(benchmark::State& state, int w, int h) {
    const Run& run = billiards();
    render::Renderer renderer(context(), run.scene, settings(w, h, true, false));
    renderer.prepare(run.frames, run.impacts);
    std::vector<render::Image> images;
    for (std::size_t k = 0; k < 30 && k < run.frames.size(); ++k)
        images.push_back(renderer.render(run.frames[k * run.frames.size() / 30], render::Decor{}));
    long k = 0;
    std::size_t bytes = 0;
    for (auto _ : state) {
        const render::Image& im = images[static_cast<std::size_t>(k++) % images.size()];
        const std::vector<std::uint8_t> png =
            render::encode_png(im.width, im.height, im.rgba.data(), render::PngOptions{1, true, false});
        bytes += png.size();
        benchmark::DoNotOptimize(png.data());
    }
    state.SetItemsProcessed(k);
    state.counters["png_kB"] = static_cast<double>(bytes) / static_cast<double>(k) / 1000.0;
}

// Every benchmark: kFrames frames, timed on the wall clock (the encoder thread works beside the
// timed one).
void per_frame(benchmark::internal::Benchmark* b) {
    b->Iterations(kFrames)->Unit(benchmark::kMillisecond)->UseRealTime();
}

[[maybe_unused]] const bool registered = [] {
    struct EndToEnd {
        const char* name;
        const Run& (*run)();  // the frames, simulated at the benchmark's first run
        int w, h;
        bool aa, view3d, region;
    };
    const EndToEnd runs[] = {
        {"render/720p/aa", billiards, 1280, 720, true, false, true},
        {"render/720p/plain", billiards, 1280, 720, false, false, true},
        {"render/1080p/aa", billiards, 1920, 1080, true, false, true},
        {"render3d/720p/aa", dropped_box, 1280, 720, true, true, true},
        {"render3d/720p/plain", dropped_box, 1280, 720, false, true, true},
        {"render3d/720p/aa-whole", dropped_box, 1280, 720, true, true, false},
    };
    for (const EndToEnd& r : runs)
        per_frame(benchmark::RegisterBenchmark(
            r.name, [r](benchmark::State& state) { end_to_end(state, r.run(), r.w, r.h, r.aa, r.view3d, r.region); }));
    per_frame(benchmark::RegisterBenchmark("encode/720p", encode_only, 1280, 720));
    return true;
}();

}  // namespace
