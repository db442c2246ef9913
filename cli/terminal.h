// Whether progress written to `err` is watched: err is the process's stderr and a terminal
// (render's progress bar, material's and worksheet's lesson lines). Piped or captured, a
// command writes no progress.
#pragma once

#include <unistd.h>

#include <chrono>
#include <iostream>

namespace collide::cli {

inline bool progress_watched(const std::ostream& err) {
    return err.rdbuf() == std::cerr.rdbuf() && isatty(STDERR_FILENO);
}

// Wall-clock seconds since `start`, for the progress and summary lines.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace collide::cli
