#include "cli/signals.h"

#include <atomic>
#include <csignal>

namespace collide::cli {

namespace {

// Set by the signal handler; the work checks it between frames.
std::atomic<bool> g_interrupted{false};
extern "C" void on_signal(int) { g_interrupted.store(true); }

}  // namespace

struct SignalGuard::Saved {
    struct sigaction old_int {
    }, old_term{};
};

SignalGuard::SignalGuard() : saved_(std::make_unique<Saved>()) {
    g_interrupted.store(false);
    struct sigaction sa {};
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &saved_->old_int);
    sigaction(SIGTERM, &sa, &saved_->old_term);
}

SignalGuard::~SignalGuard() {
    sigaction(SIGINT, &saved_->old_int, nullptr);
    sigaction(SIGTERM, &saved_->old_term, nullptr);
}

bool stop_requested() { return g_interrupted.load(); }

}  // namespace collide::cli
