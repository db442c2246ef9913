// Whether progress written to `err` is watched: err is the process's stderr and a terminal
// (render's progress bar, material's and worksheet's lesson lines). Piped or captured, a
// command writes no progress.
#pragma once

#include <unistd.h>

#include <iostream>

namespace collide::cli {

inline bool progress_watched(const std::ostream& err) {
    return err.rdbuf() == std::cerr.rdbuf() && isatty(STDERR_FILENO);
}

}  // namespace collide::cli
