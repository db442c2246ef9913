// Stopping long work from outside (Ctrl-C in the command): a callback asked between frames,
// not a global flag, so that every face decides what stops it.
#pragma once

#include <functional>
#include <stdexcept>

namespace collide {

// Asked between frames: true stops the work (Interrupted). The command's is its SIGINT /
// SIGTERM flag (cli/signals.h); the tests' a counter.
using StopRequested = std::function<bool()>;

// Thrown when the stop callback stopped a render between frames: every file written is
// complete (the frames handed to the encoder were finished first).
struct Interrupted : std::runtime_error {
    explicit Interrupted(long frames_written) : std::runtime_error("interrupted"), frames(frames_written) {}
    long frames;
};

}  // namespace collide
