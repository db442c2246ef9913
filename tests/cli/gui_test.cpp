// `collide gui` in a real window under Xvfb (xvfb-run): a script changes e and steps to the
// collision, and the window's frame is the offscreen render of the same state (the lesson with
// that e, rendered by `collide render`), pixel for pixel within a small tolerance. Also: the
// script's and the options' mistakes are refused before a window opens, and without a display
// the command says what to do.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "cli/render_cmd.h"
#include "render/png.h"
#include "tests/render/test_util.h"

namespace collide {
namespace {

namespace fs = std::filesystem;

const std::string kCollide = COLLIDE_BIN;
const std::string kLessons = std::string(COLLIDE_SOURCE_DIR) + "/lessons";

std::string read(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

bool have_xvfb() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

// Runs a shell command; its exit code.
int run(const std::string& command) {
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string gui(const std::string& args, const std::string& log) {
#ifdef COLLIDE_SANITIZED
    // glvnd unloads Mesa's GLX driver at exit and LeakSanitizer then reports the driver's own
    // allocations from an unnamed module, which no suppression can match (as with EGL in
    // diagram_test.cpp): no leak check for this one child; ASan and UBSan stay on.
    const std::string env = "ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:detect_leaks=0\" ";
#else
    const std::string env;
#endif
    return env + "xvfb-run -a -s '-screen 0 1600x900x24' " + kCollide + " gui " + args + " >" + log + " 2>&1";
}

// The share of pixels of `a` (cropped to b's size at the top left) whose channels all lie
// within `tolerance` of b's.
double matching(const render::Image& a, const render::Image& b, int tolerance) {
    long same = 0;
    for (int y = 0; y < b.height; ++y)
        for (int x = 0; x < b.width; ++x) {
            const std::uint8_t *p = a.pixel(x, y), *q = b.pixel(x, y);
            bool ok = true;
            for (int c = 0; c < 3; ++c) ok = ok && std::abs(int(p[c]) - int(q[c])) <= tolerance;
            same += ok;
        }
    return static_cast<double>(same) / (static_cast<double>(b.width) * b.height);
}

TEST(Gui, ScriptSetsEStepsToTheCollisionAndTheWindowShowsTheOffscreenFrame) {
#ifndef COLLIDE_HAVE_GLFW
    GTEST_SKIP() << "built without GLFW: no window to test (WithoutGlfwItSaysWhatToInstall runs instead)";
#endif
    if (!have_xvfb()) GTEST_SKIP() << "xvfb-run is not installed (Debian: apt-get install xvfb xauth)";
    render::test::TempDir dir;
    // The lesson with e = 1 instead of its 0.5 (the scene's own line, the first one).
    std::string lesson = read(kLessons + "/01-catch-up.toml");
    const std::string from = "\nrestitution = 0.5\n";
    ASSERT_NE(lesson.find(from), std::string::npos);
    lesson.replace(lesson.find(from), from.size(), "\nrestitution = 1.0\n");
    std::ofstream(dir / "elastic.toml") << lesson;
    RenderOptions ro;
    ro.scenario = dir / "elastic.toml";
    ro.out_dir = dir / "offscreen";
    ro.size = "960x540";
    ro.fps = 30;
    ro.quiet = true;
    std::ostringstream out, err;
    ASSERT_EQ(run_render(ro, out, err), 0) << err.str();
    // The first collision, and the first frame at or after it: the one next-collision shows.
    std::istringstream events(read(dir / "offscreen/events.csv"));
    std::string header, first;
    std::getline(events, header);
    std::getline(events, first);
    const double t = std::stod(first.substr(0, first.find(',')));
    const int index = static_cast<int>(std::ceil(t * 30 - 1e-9));
    char name[64];
    std::snprintf(name, sizeof name, "offscreen/frames/frame_%05d.png", index);

    std::ofstream(dir / "script.txt") << "# e from 0.5 to 1, then to the collision\n"
                                         "set e 1\nnext-collision\nwait 2\n"
                                      << "screenshot " << (dir / "shot.png") << "\n"
                                      << "save-frame " << (dir / "frame.png") << "\nquit\n";
    ASSERT_EQ(run(gui("catch-up --size 960x540 --script " + (dir / "script.txt"), dir / "log.txt")), 0)
        << read(dir / "log.txt");
    const render::Image shot = render::read_png(dir / "shot.png");
    const render::Image window_frame = render::read_png(dir / "frame.png");
    const render::Image offscreen = render::read_png(dir / name);
    const render::Image unchanged =  // the lesson as it is (e = 0.5), same frame
        [&] {
            RenderOptions o = ro;
            o.scenario = "catch-up";
            o.out_dir = dir / "as-is";
            EXPECT_EQ(run_render(o, out, err), 0);
            return render::read_png(dir / ("as-is/frames/" + fs::path(name).filename().string()));
        }();
    EXPECT_GE(shot.width, 960);
    EXPECT_GE(shot.height, 540);
    EXPECT_EQ(matching(window_frame, offscreen, 0), 1.0);  // the saved frame: exactly the render's
    EXPECT_GE(matching(shot, offscreen, 2), 0.999);        // the window shows it pixel for pixel
    EXPECT_LT(matching(shot, unchanged, 2), 0.99);         // and e = 1 did change it
}

TEST(Gui, MistakesAreRefusedBeforeAWindowOpens) {
    render::test::TempDir dir;
    std::ofstream(dir / "bad.txt") << "set e 1\nnext-colision\n";
    // No display needed: the script is read first (exit 2, file and line named).
    EXPECT_EQ(
        run("env -u DISPLAY " + kCollide + " gui catch-up --script " + (dir / "bad.txt") + " 2>" + (dir / "err.txt")),
        2);
    EXPECT_NE(read(dir / "err.txt").find("bad.txt:2:1: next-colision: unknown action"), std::string::npos)
        << read(dir / "err.txt");
    EXPECT_EQ(run("env -u DISPLAY " + kCollide + " gui no-such-lesson 2>" + (dir / "err2.txt")), 2);
    EXPECT_EQ(run("env -u DISPLAY " + kCollide + " gui catch-up --size 0x0 2>" + (dir / "err3.txt")), 2);
    EXPECT_NE(read(dir / "err3.txt").find("collide: error: --size: expected WxH"), std::string::npos)
        << read(dir / "err3.txt");  // an option has no file: no empty location before it
}

TEST(Gui, WithoutADisplayItSaysWhatToDo) {
#ifndef COLLIDE_HAVE_GLFW
    GTEST_SKIP() << "built without GLFW: WithoutGlfwItSaysWhatToInstall runs instead";
#endif
    render::test::TempDir dir;
    EXPECT_EQ(run("env -u DISPLAY -u WAYLAND_DISPLAY " + kCollide + " gui catch-up 2>" + (dir / "err.txt")), 1);
    EXPECT_NE(read(dir / "err.txt").find("xvfb-run"), std::string::npos) << read(dir / "err.txt");
}

#ifndef COLLIDE_HAVE_GLFW
TEST(Gui, WithoutGlfwItSaysWhatToInstall) {
    render::test::TempDir dir;
    EXPECT_EQ(run(kCollide + " gui catch-up 2>" + (dir / "err.txt")), 1);
    EXPECT_NE(read(dir / "err.txt").find("apt-get install libglfw3-dev"), std::string::npos) << read(dir / "err.txt");
}
#endif

}  // namespace
}  // namespace collide
