// The options of `collide render` as users type them (RenderOptions), and the typed request
// they make (RenderRequest). parse_render_request is the one place the strings are read: past
// it nothing looks at an option's text again, and no string option reaches past cli/.
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

// The command line of `collide render`: names and defaults users script against.
struct RenderOptions {
    std::string scenario;          // a scenario file, a lesson file or a lesson id
    std::string out_dir;           // -o DIR
    std::string size = "720p";     // --size: WxH, or 480p, 720p, 1080p, 1440p
    double fps = 30.0;             // --fps: frames per simulated second
    // --quality: low: no anti-aliasing; medium: anti-aliased (2D: Dear ImGui's edges; 3D: 4x
    // MSAA), fast PNGs (zlib level 1, no filter); high: as medium, PNGs about 10-20% smaller
    // (level 6, adaptive filters) and 4x slower to encode (two encoder threads).
    std::string quality = "medium";
    std::string view;              // --view: 2d or 3d; empty: 2d for 1D and 2D scenes, 3d for 3D
    std::string format = "png";    // --format: png (frames only), mp4 or gif (also
                                   // DIR/animation.mp4 or .gif, through ffmpeg)
    bool quiet = false;            // --quiet: no progress bar, no summary
    bool force = false;            // --force: write into a non-empty DIR (replacing our files)
    std::string backend = "osmesa";  // OpenGL context: osmesa or egl
};

// What --quality means. The members' defaults are "medium".
struct Quality {
    // MSAA samples. The 2D diagram is anti-aliased by Dear ImGui itself (feathered edges):
    // multisampling adds nothing visible there and made frames several times slower on
    // llvmpipe, so the 2D view never uses it. The 3D view's shaded bodies need it.
    int samples_2d = 0;
    int samples_3d = 4;
    bool smooth = true;                        // ImGui edge anti-aliasing
    render::PngOptions png{1, true, false};    // zlib level 1, no filter
    int encoders = 1;                          // PNG threads

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
    std::string ffmpeg;  // its path, found on $PATH when the options were read
    std::string file_name() const;  // "animation.mp4" or "animation.gif"
};

// A render, every option read and checked.
struct RenderRequest {
    std::string scenario;  // a scenario file, a lesson file or a lesson id (load_scenario reads it)
    std::string out_dir;
    FrameSpec frame;
    std::optional<VideoRequest> video;  // unset: --format png, the frames alone
    render::GlBackend backend = render::GlBackend::osmesa;
    bool quiet = false;  // no progress bar
    bool force = false;  // write into a directory that is not empty
};

// The options turned into a request, in the order the command has always checked them
// (--size, --fps, --quality, --view, -o, --backend, --format, then ffmpeg for mp4 and gif).
// Throws InputError naming the first wrong option and what it accepts.
RenderRequest parse_render_request(const RenderOptions& options);

// What --quality, --view, --format and --backend accept, in --help's order. cli/main.cpp gives
// these lists to CLI11 (its IsMember check lists them in --help and refuses other values first,
// in its own words); parse_render_request reads the same names and is what the program does.
struct RenderChoices {
    std::vector<std::string> quality, view, format, backend;
};
const RenderChoices& render_choices();

// "1280x720" or a preset (480p: 854x480, 720p: 1280x720, 1080p: 1920x1080, 1440p: 2560x1440);
// false for anything else, or sizes outside 16..8192.
bool parse_render_size(const std::string& text, int* width, int* height);
// The same for the --size option: throws InputError naming --size and what it accepts.
void read_render_size(const std::string& text, int* width, int* height);
// The --view option: "2d", "3d", or "" (unset); throws InputError naming --view otherwise.
std::optional<render::ViewKind> read_view(const std::string& text);

// The frames' settings for a frame spec, a scene and its [view] table (and the first
// collision's formula overlay, when given): `collide render` and `collide gui` draw with these.
render::RenderSettings frame_settings(const FrameSpec& frame, const Scene& scene, const SceneView& view,
                                      const render::FormulaText* formula);

}  // namespace collide
