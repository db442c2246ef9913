// The one mapping from what a command throws to its exit code and its one line on stderr
// (every subcommand's --help and docs/commands/ list these codes):
//   InputError          2    "collide: error: FILE:LINE:COL: key: message"  (nothing written)
//   RunError            2    "collide: error: message" (a scene the engine cannot run as asked:
//                            a state no longer finite, work beyond the budget; engine/run_error.h)
//   Interrupted         130  "collide: interrupted: " and the command's note (complete files only)
//   std::runtime_error  1    "collide: message"
//   other exceptions    1    "collide: internal error: message"
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

#include "present/stop.h"

namespace collide::cli {

constexpr int kExitBadInput = 2;
constexpr int kExitInterrupted = 130;

// Runs a command's body and returns its exit code, or the code of what it threw (above), with
// the line on err. `interrupted_note`: what an interruption left, e.g. "DIR is untouched".
int run_command(std::ostream& err, const std::function<int()>& body,
                const std::function<std::string(const Interrupted&)>& interrupted_note = nullptr);

// run_command for a command that builds its output directory `dir` beside it and renames it
// into place when complete (present/staged_dir.h: material, worksheet): what the body throws
// leaves `dir` untouched, and an interruption says "DIR is untouched".
int run_staged_command(std::ostream& err, const std::string& dir, const std::function<int()>& body);

}  // namespace collide::cli
