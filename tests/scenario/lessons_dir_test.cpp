// Where the lessons are found (scenario/lesson.h lessons_dir): $COLLIDE_LESSONS, then the
// lessons installed beside the program, then the source tree's. (ctest runs every test in a
// process of its own, so changing the environment here touches no other test.)
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "scenario/lesson.h"

namespace collide {
namespace {

namespace fs = std::filesystem;

const std::string kSourceLessons = std::string(COLLIDE_SOURCE_DIR) + "/lessons";

TEST(LessonsDir, InstalledBesideTheProgramUnderShare) {
    // GNUInstallDirs' layout: bin/collide and share/collide/lessons under one prefix.
    EXPECT_EQ(installed_lessons_dir("/opt/collide/bin/collide"), "/opt/collide/share/collide/lessons");
    EXPECT_EQ(installed_lessons_dir("/usr/bin/collide"), "/usr/share/collide/lessons");
}

TEST(LessonsDir, TheInstalledOnesWhenTheyExist) {
    unsetenv("COLLIDE_LESSONS");
    const fs::path installed = fs::temp_directory_path() / ("collide-lessons-dir-" + std::to_string(getpid()));
    fs::create_directories(installed);
    EXPECT_EQ(lessons_dir(installed.string()), installed.string());
    fs::remove_all(installed);
    // Gone: the source tree's (a build tree's programs).
    EXPECT_EQ(lessons_dir(installed.string()), kSourceLessons);
    EXPECT_EQ(lessons_dir(""), kSourceLessons);
}

TEST(LessonsDir, TheEnvironmentOverridesBoth) {
    const std::string source = fs::path(kSourceLessons).parent_path().string();  // a directory that exists
    setenv("COLLIDE_LESSONS", "/somewhere/else", 1);
    EXPECT_EQ(lessons_dir(source), "/somewhere/else");
    EXPECT_EQ(lessons_dir(), "/somewhere/else");
    unsetenv("COLLIDE_LESSONS");
}

TEST(LessonsDir, ABuildTreeProgramFindsTheSourceTree) {
    // This test program lives in the build tree, where no share/collide/lessons lies beside it.
    unsetenv("COLLIDE_LESSONS");
    EXPECT_EQ(lessons_dir(), kSourceLessons);
}

}  // namespace
}  // namespace collide
