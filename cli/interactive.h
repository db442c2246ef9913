// `collide step --interactive`: a command loop over a running scene (step, next, back, show,
// set, events, help, quit). Commands: docs/commands/step.md and the `help` command.
#pragma once

#include <iosfwd>

#include "engine/scene.h"

namespace collide {

struct InteractiveOptions {
    bool json = false;    // states and events as the JSON lines of `collide step --json`
    bool prompt = false;  // print a banner and a prompt (stdin is a terminal)
};

// Reads commands from in until `quit` or the end of input. Replies go to out, errors in
// commands to err; a failed command changes nothing and the loop goes on. Input that is not
// commands (a NUL byte, a line longer than 1 MiB) ends it with InputError (exit 2), read no
// further than that.
void run_interactive(const Scene& scene, const InteractiveOptions& options, std::istream& in, std::ostream& out,
                     std::ostream& err);

}  // namespace collide
