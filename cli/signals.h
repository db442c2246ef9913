// Ctrl-C in a command: while a SignalGuard lives, SIGINT and SIGTERM set a flag instead of
// killing the process in the middle of a file; the work asks stop_requested() between frames
// (present/stop.h) and ends with only complete files.
#pragma once

#include <memory>

namespace collide::cli {

class SignalGuard {
public:
    SignalGuard();   // clears the flag and installs the handlers
    ~SignalGuard();  // restores the handlers that were there before
    SignalGuard(const SignalGuard&) = delete;
    SignalGuard& operator=(const SignalGuard&) = delete;

private:
    struct Saved;
    std::unique_ptr<Saved> saved_;
};

// True once SIGINT or SIGTERM arrived while a guard was alive.
bool stop_requested();

}  // namespace collide::cli
