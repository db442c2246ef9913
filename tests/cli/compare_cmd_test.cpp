// `collide compare` as a user runs it: the real binary, its JSON parsed and checked against
// closed forms, and bad input refused with exit code 2 and a located message.
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

using nlohmann::json;

struct Result {
    int code = -1;
    std::string out, err;
};

std::string temp_path(const std::string& name) { return ::testing::TempDir() + "collide_compare_" + name; }

std::string slurp(const std::string& path) {
    std::ifstream f(path);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

Result run(const std::string& args) {
    const std::string err_file = temp_path("stderr.txt");
    const std::string cmd = std::string(COLLIDE_BINARY) + " compare " + args + " 2>" + err_file;
    Result r;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return r;
    char buf[4096];
    std::size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
    const int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.err = slurp(err_file);
    return r;
}

std::string scene(const std::string& name) { return std::string(COLLIDE_SOURCE_DIR) + "/lessons/scenes/" + name; }

std::string write_file(const std::string& name, const std::string& text) {
    const std::string path = temp_path(name);
    std::ofstream(path) << text;
    return path;
}

// The slow elastic bounce (e = 1, landing at sqrt(2 g h) = 0.8 m/s) with Box2D's defaults:
// collide bounces at +0.8 m/s; Box2D stops the ball, and says why.
TEST(CompareCommand, JsonHasTheDocumentedFields) {
    const Result r = run(scene("compare-slow-bounce.toml") + " --json --box2d-defaults");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    const json j = json::parse(r.out);
    ASSERT_TRUE(j.contains("events"));
    const json& events = j["events"];
    ASSERT_GE(events.size(), 2u);
    const double v_land = std::sqrt(2.0 * 9.81 * 0.03262);
    for (const json& e : events) {
        for (const char* key : {"a", "b", "t", "collide", "box2d", "difference", "reason"})
            EXPECT_TRUE(e.contains(key)) << key;
        EXPECT_EQ(e["a"], "ground");
        EXPECT_EQ(e["b"], "ball");
        EXPECT_TRUE(e["reason"].is_string());
        ASSERT_TRUE(e["t"].contains("collide") && e["t"].contains("box2d"));
        ASSERT_TRUE(e["collide"].is_object());  // collide bounces every time
        const json& ball = e["collide"]["b"];
        ASSERT_EQ(ball["v"].size(), 2u);
        EXPECT_TRUE(ball["w"].is_number());
        EXPECT_NEAR(ball["v"][1].get<double>(), v_land, 1e-4);
    }
    // The first landing: Box2D's ball stays down (threshold 1 m/s > 0.8 m/s).
    const json& first = events[0];
    ASSERT_TRUE(first["box2d"].is_object());
    EXPECT_NEAR(first["box2d"]["b"]["v"][1].get<double>(), 0.0, 1e-3);
    EXPECT_NEAR(first["t"]["collide"].get<double>(), std::sqrt(2.0 * 0.03262 / 9.81), 1e-6);
    EXPECT_NEAR(first["t"]["box2d"].get<double>(), first["t"]["collide"].get<double>(), 1.0 / 600);
    EXPECT_GT(first["difference"].get<double>(), 0.5);
    EXPECT_EQ(first["reason"].get<std::string>().rfind("restitution threshold", 0), 0u);
    // Later bounces exist only in collide.
    const json& last = events.back();
    EXPECT_TRUE(last["box2d"].is_null());
    EXPECT_TRUE(last["t"]["box2d"].is_null());
    EXPECT_TRUE(last["difference"].is_null());
    EXPECT_EQ(last["reason"], "no matching event");
    EXPECT_EQ(j["settings"]["materials"], "box2d-defaults");
}

TEST(CompareCommand, OptionsReachBox2DAndSamplesAreSideBySide) {
    const Result r = run(scene("compare-box-landing.toml") +
                         " --json --samples --dt 0.005 --velocity-iterations 12 "
                         "--position-iterations 4");
    ASSERT_EQ(r.code, 0) << r.err;
    const json j = json::parse(r.out);
    EXPECT_DOUBLE_EQ(j["settings"]["dt"].get<double>(), 0.005);
    EXPECT_EQ(j["settings"]["velocity_iterations"], 12);
    EXPECT_EQ(j["settings"]["position_iterations"], 4);
    EXPECT_EQ(j["settings"]["materials"], "matched");
    ASSERT_EQ(j["samples"].size(), 51u);  // 0.5 s every 0.01 s, both ends
    const json& s0 = j["samples"][0];
    for (int k = 0; k < 2; ++k)  // the same start, to float
        EXPECT_NEAR(s0["collide"]["box"]["x"][k].get<double>(), s0["box2d"]["box"]["x"][k].get<double>(), 1e-7);
    EXPECT_NEAR(s0["box2d"]["box"]["angle"].get<double>(), -0.6, 1e-6);
    // The box lands flat at t = 0.3 s in collide (both corners at once).
    ASSERT_GE(j["events"].size(), 1u);
    EXPECT_NEAR(j["events"][0]["t"]["collide"].get<double>(), 0.3, 1e-6);
}

TEST(CompareCommand, TextNamesTheSettingsAndEveryEvent) {
    const Result r = run(scene("compare-disc-pair.toml"));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("Box2D 2.4.1"), std::string::npos);
    EXPECT_NE(r.out.find("8 velocity and 3 position iterations"), std::string::npos);
    EXPECT_NE(r.out.find("event 1: striker - target"), std::string::npos);
    EXPECT_NE(r.out.find("normal off by"), std::string::npos);
    EXPECT_NE(r.out.find("summary: 1 events in collide, 1 in Box2D"), std::string::npos);
}

// Exit code 2, one "collide: error:" line naming the file (and line) on stderr, nothing on
// stdout.
void expect_refused(const Result& r, const std::string& mention) {
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err.rfind("collide: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(CompareCommand, BadInputExitsWithCode2) {
    // A 3D scene: refused at its dimension key (line 7 of dropped-box-3d.toml's [scene]).
    const std::string three_d = scene("dropped-box-3d.toml");
    const Result r3 = run(three_d);
    expect_refused(r3, "dimension: Box2D is a 2D engine");
    EXPECT_NE(r3.err.find(three_d + ":"), std::string::npos) << r3.err;

    // A nine-sided polygon: Box2D allows 8 vertices; refused at the body's key with its line.
    std::string nine =
        "[scene]\ndimension = 2\nduration = 1.0\n\n[[body]]\nname = \"nonagon\"\n"
        "shape = \"polygon\"\nmass = 1.0\nvertices = [";
    for (int k = 0; k < 9; ++k) {
        const double a = 2.0 * 3.14159265358979 * k / 9;
        nine += (k ? ", [" : "[") + std::to_string(std::cos(a)) + ", " + std::to_string(std::sin(a)) + "]";
    }
    nine += "]\n";
    const std::string nine_file = write_file("nonagon.toml", nine);
    const Result r9 = run(nine_file);
    expect_refused(r9, nine_file + ":9:");
    EXPECT_NE(r9.err.find("body[1].vertices: Box2D polygons have at most 8 vertices"), std::string::npos) << r9.err;

    // A malformed scenario, as `collide step` refuses it.
    const std::string bad = write_file("bad.toml", "[scene]\ndimension = 2\nduration = -1.0\n");
    expect_refused(run(bad), bad + ":3:");

    expect_refused(run(temp_path("no-such-file.toml")), "no-such-file.toml");
    expect_refused(run(scene("compare-disc-pair.toml") + " --dt -0.01"), "--dt");
    expect_refused(run(scene("compare-disc-pair.toml") + " --velocity-iterations 0"), "--velocity-iterations");
    expect_refused(run(scene("compare-disc-pair.toml") + " --dt 1e-12"), "10^8 Box2D steps");
}

}  // namespace
