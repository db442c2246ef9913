// How frames look (FrameSpec: size, frame rate, quality, view) and the readers of the names
// users type for them (--size, --fps, --quality, --view, --format, --backend), which the
// command line (cli/render_options.h) and the Python module share. Each reader throws
// InputError naming its option (key "--size", ...) and what it accepts.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/scene.h"
#include "render/context.h"
#include "render/png.h"
#include "render/renderer.h"
#include "render/video.h"
#include "scenario/scene_file.h"

namespace collide {

// What --quality means. The members' defaults are "medium".
struct Quality {
    // MSAA samples. The 2D diagram is anti-aliased by Dear ImGui itself (feathered edges):
    // multisampling adds nothing visible there and made frames several times slower on
    // llvmpipe, so the 2D view never uses it. The 3D view's shaded bodies need it.
    int samples_2d = 0;
    int samples_3d = 4;
    bool smooth = true;                      // ImGui edge anti-aliasing
    render::PngOptions png{1, true, false};  // zlib level 1, no filter
    int encoders = 1;                        // PNG threads

    static Quality low();
    static Quality medium();
    static Quality high();  // smaller files, slower
};

// How the frames look: what `collide render` and `collide gui` share.
struct FrameSpec {
    int width = 1280, height = 720;        // --size (pixels)
    double fps = 30.0;                     // --fps: frames per simulated second
    Quality quality;                       // --quality
    std::optional<render::ViewKind> view;  // --view; unset: the 2D diagram for 1D and 2D scenes, 3D for 3D
};

// --format mp4 or gif: the video ffmpeg makes of the frames.
struct VideoRequest {
    render::VideoFormat format = render::VideoFormat::mp4;
    std::string ffmpeg;             // its path, found on $PATH when the options were read
    std::string file_name() const;  // "animation.mp4" or "animation.gif"
};

// What --quality, --view, --format and --backend accept, in --help's order. cli/main.cpp gives
// these lists to CLI11 (its IsMember check lists them in --help and refuses other values first,
// in its own words); the readers below read the same names and is what the program does.
struct RenderChoices {
    std::vector<std::string> quality, view, format, backend;
};
const RenderChoices& render_choices();

// "1280x720" or a preset (480p: 854x480, 720p: 1280x720, 1080p: 1920x1080, 1440p: 2560x1440);
// false for anything else, or sizes outside 16..8192.
bool parse_render_size(const std::string& text, int* width, int* height);
// --fps: frames per simulated second in (0, 100000].
double read_fps(double fps);
// --size, --fps, --quality and --view, read in that order (the first wrong one is named): what
// `collide render` and the Python module's render_figure share.
FrameSpec read_frame_spec(const std::string& size, double fps, const std::string& quality, const std::string& view);
// --quality: low, medium or high.
Quality read_quality(const std::string& name);
// --backend: osmesa or egl (when built).
render::GlBackend read_backend(const std::string& name);
// --format: none for png; for mp4 and gif, the video and the ffmpeg that will make it
// (refused when ffmpeg is not installed).
std::optional<VideoRequest> read_format(const std::string& name);
// The same for the --size option: throws InputError naming --size and what it accepts.
void read_render_size(const std::string& text, int* width, int* height);
// The --view option: "2d", "3d", or "" (unset); throws InputError naming --view otherwise.
std::optional<render::ViewKind> read_view(const std::string& text);

// The frames' settings for a frame spec, a scene and its [view] table (and the first
// collision's formula overlay, when given): `collide render` and `collide gui` draw with these.
render::RenderSettings frame_settings(const FrameSpec& frame, const Scene& scene, const SceneView& view,
                                      const render::FormulaText* formula);

}  // namespace collide
