#include "present/background_run.h"

#include <algorithm>

namespace collide {

void RunControl::report(double fraction) {
    const double f = std::clamp(fraction, 0.0, 1.0);  // NaN stays where it was (the compare fails)
    double now = progress_.load(std::memory_order_relaxed);
    while (f > now && !progress_.compare_exchange_weak(now, f, std::memory_order_release, std::memory_order_relaxed)) {
    }
}

}  // namespace collide
