// Helpers shared by the renderer tests: a fresh temporary directory, and image comparisons.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "render/png.h"

namespace collide::render::test {

// A new empty directory under the system's temporary directory, removed at the end.
class TempDir {
public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = std::filesystem::temp_directory_path() /
                ("collide-render-" + std::string(info ? info->name() : "test") + "-" + std::to_string(::getpid()));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    std::string str() const { return path_.string(); }
    std::string operator/(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

inline bool near_colour(const std::uint8_t* px, std::uint32_t abgr, int tolerance) {
    for (int c = 0; c < 3; ++c) {
        const int want = static_cast<int>((abgr >> (8 * c)) & 0xFF);
        if (std::abs(static_cast<int>(px[c]) - want) > tolerance) return false;
    }
    return true;
}

}  // namespace collide::render::test
