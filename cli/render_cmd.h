// `collide render SCENARIO -o DIR`: runs a scenario and writes its pictures, data and text
// (present/render_job.h lists the files; docs/commands/render.md).
#pragma once

#include <iosfwd>

#include "cli/render_options.h"

namespace collide {

// Runs the command: reads the options (parse_render_request), renders, prints the summary.
// Returns the exit code: 0 done, 130 interrupted (SIGINT / SIGTERM: the
// files written are complete), 2 bad input (one "collide: error: ..."
// line on err: the scenario file, an option, or an output directory that is not empty),
// 1 any other failure. Progress goes to err when it is the process's stderr and a terminal.
int run_render(const RenderOptions& options, std::ostream& out, std::ostream& err);

}  // namespace collide
