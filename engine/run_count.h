// How many worlds were run: every World1, World<2> and World<3> constructed or copied counts
// one. The teaching code promises to run a scene once (engine/record.h); its tests count.
#pragma once

#include <atomic>
#include <cstdint>

namespace collide {

class RunCount {
public:
    RunCount() { ++total_; }
    RunCount(const RunCount&) { ++total_; }
    RunCount& operator=(const RunCount&) {
        ++total_;
        return *this;
    }
    // Worlds made since the program started (all threads).
    static std::uint64_t total() { return total_.load(); }

private:
    static inline std::atomic<std::uint64_t> total_{0};
};

}  // namespace collide
