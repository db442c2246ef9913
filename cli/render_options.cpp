#include "cli/render_options.h"

#include "scenario/input_error.h"

namespace collide {

RenderRequest parse_render_request(const RenderOptions& o) {
    RenderRequest r;
    r.scenario = o.scenario;
    r.frame = read_frame_spec(o.size, o.fps, o.quality, o.view);
    if (o.out_dir.empty()) throw InputError("", {}, "-o", "the output directory is required");
    r.out_dir = o.out_dir;
    r.backend = read_backend(o.backend);
    r.video = read_format(o.format);
    r.quiet = o.quiet;
    r.force = o.force;
    return r;
}

}  // namespace collide
