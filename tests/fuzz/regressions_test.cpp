// Every input a fuzzer once failed on (tests/fuzz-regressions/TARGET/), replayed through the
// same entry point (fuzz/entry.h) in every build, so the fix stays. Each must now be refused
// with an InputError or run cleanly; under COLLIDE_SANITIZE the sanitizers watch as well.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fuzz/entry.h"

namespace fs = std::filesystem;

namespace {

const fs::path kDir = fs::path(COLLIDE_SOURCE_DIR) / "tests" / "fuzz-regressions";

std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(FuzzRegressions, EveryDirectoryNamesAnEntryPoint) {
    ASSERT_TRUE(fs::is_directory(kDir)) << kDir;
    for (const auto& d : fs::directory_iterator(kDir)) {
        if (d.is_directory()) {
            EXPECT_NE(collide::fuzz::entry_point(d.path().filename().string()), nullptr)
                << d.path() << ": not scene, solve, lesson or step";
        }
    }
}

TEST(FuzzRegressions, EveryInputIsRefusedOrRunsCleanly) {
    std::vector<fs::path> files;
    for (const auto& f : fs::recursive_directory_iterator(kDir))
        if (f.is_regular_file() && f.path().filename() != "README.md") files.push_back(f.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
        const auto entry = collide::fuzz::entry_point(f.parent_path().filename().string());
        ASSERT_NE(entry, nullptr) << f;
        SCOPED_TRACE(f.string());
        EXPECT_NO_THROW(entry(read(f)));
    }
    RecordProperty("inputs", static_cast<int>(files.size()));
}

// The entry points refuse bad input quietly and run good input: a bundled scene steps.
TEST(FuzzRegressions, EntryPointsAcceptABundledScene) {
    const std::string scene = read(fs::path(COLLIDE_SOURCE_DIR) / "lessons/scenes/cradle-1d.toml");
    ASSERT_FALSE(scene.empty());
    EXPECT_NO_THROW(collide::fuzz::step(scene));
    EXPECT_NO_THROW(collide::fuzz::scene("[scene]\nduration = -1\n"));
    EXPECT_NO_THROW(collide::fuzz::solve("not toml ["));
    EXPECT_NO_THROW(collide::fuzz::lesson(scene));  // no [lesson] table: an InputError
}
