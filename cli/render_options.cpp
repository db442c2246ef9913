#include "cli/render_options.h"

#include "scenario/input_error.h"

namespace collide {

RenderRequest parse_render_request(const RenderOptions& o) {
    RenderRequest r;
    r.scenario = o.scenario;
    read_render_size(o.size, &r.frame.width, &r.frame.height);
    r.frame.fps = read_fps(o.fps);
    r.frame.quality = read_quality(o.quality);
    r.frame.view = read_view(o.view);
    if (o.out_dir.empty()) throw InputError("", {}, "-o", "the output directory is required");
    r.out_dir = o.out_dir;
    r.backend = read_backend(o.backend);
    r.video = read_format(o.format);
    r.quiet = o.quiet;
    r.force = o.force;
    return r;
}

}  // namespace collide
