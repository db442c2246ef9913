#include "cli/render_cmd.h"

#include <sys/resource.h>

#include <cstdio>
#include <ostream>

#include "cli/exit_code.h"
#include "cli/signals.h"
#include "cli/terminal.h"

namespace collide {

namespace {

void print_summary(const RenderRequest& rq, const RenderReport& r, std::ostream& out) {
    char rate[64];
    std::snprintf(rate, sizeof rate, " in %.2f s (%.1f frames/s)", r.seconds,
                  r.seconds > 0 ? static_cast<double>(r.frames) / r.seconds : 0.0);
    out << "wrote " << r.frames << " frames (" << r.width << "x" << r.height << ")" << rate << " to " << rq.out_dir
        << "/frames";
    if (r.problem) out << ", before.png, at.png, after.png, figure.png, thumb.png, worked-example.md";
    out << ", data.csv, data.json, events.csv";
    if (r.lesson) out << ", lesson.md";
    if (!r.variants.empty()) out << ", variants.png";
    if (r.penalty) out << ", penalty.svg, penalty-overlap.svg, penalty.csv";
    if (!r.video.empty()) out << ", " << r.video;
    // Peak resident memory of the whole process (Linux: kilobytes).
    rusage usage{};
    if (getrusage(RUSAGE_SELF, &usage) == 0) out << "; peak memory " << (usage.ru_maxrss + 512) / 1024 << " MB";
    out << "\n";
}
}  // namespace

int run_render(const RenderOptions& o, std::ostream& out, std::ostream& err) {
    const auto interrupted = [&o](const Interrupted& e) {
        return std::to_string(e.frames) + " complete frames written to " + o.out_dir +
               "/frames (no partial file is left)";
    };
    return cli::run_command(
        err,
        [&] {
            RenderRequest request = parse_render_request(o);
            // Progress only where someone watches it: the process's stderr, a terminal.
            const bool shown = !request.quiet && cli::progress_watched(err);
            const cli::SignalGuard signals;
            const bool summary = !request.quiet;
            request.quiet = !shown;
            const RenderReport r = render_scenario(request, err, cli::stop_requested);
            if (summary) print_summary(request, r, out);
            return 0;
        },
        interrupted);
}

}  // namespace collide
