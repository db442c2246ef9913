// The options of `collide render` as users type them (RenderOptions), and the typed request
// they make (present/render_job.h RenderRequest). parse_render_request is the one place the
// strings are read: past it nothing looks at an option's text again, and no string option
// reaches past cli/.
#pragma once

#include <string>

#include "present/render_job.h"

namespace collide {

// The command line of `collide render`: names and defaults users script against.
struct RenderOptions {
    std::string scenario;       // a scenario file, a lesson file or a lesson id
    std::string out_dir;        // -o DIR
    std::string size = "720p";  // --size: WxH, or 480p, 720p, 1080p, 1440p
    double fps = 30.0;          // --fps: frames per simulated second
    // --quality: low: no anti-aliasing; medium: anti-aliased (2D: Dear ImGui's edges; 3D: 4x
    // MSAA), fast PNGs (zlib level 1, no filter); high: as medium, PNGs about 10-20% smaller
    // (level 6, adaptive filters) and 4x slower to encode (two encoder threads).
    std::string quality = "medium";
    std::string view;                // --view: 2d or 3d; empty: 2d for 1D and 2D scenes, 3d for 3D
    std::string format = "png";      // --format: png (frames only), mp4 or gif (also
                                     // DIR/animation.mp4 or .gif, through ffmpeg)
    bool quiet = false;              // --quiet: no progress bar, no summary
    bool force = false;              // --force: write into a non-empty DIR (replacing our files)
    std::string backend = "osmesa";  // OpenGL context: osmesa or egl
};

// The options turned into a request, in the order the command has always checked them
// (--size, --fps, --quality, --view, -o, --backend, --format, then ffmpeg for mp4 and gif).
// Throws InputError naming the first wrong option and what it accepts.
RenderRequest parse_render_request(const RenderOptions& options);

}  // namespace collide
