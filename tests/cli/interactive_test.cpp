// The interactive mode of `collide step`, driven by piped commands: every state it reports is
// checked against the closed form of the motion it should be in.
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/interactive.h"
#include "scenario/scene_file.h"

namespace collide {
namespace {

constexpr double g = 9.81;

// A disc thrown in 2D gravity with nothing to hit: x = x0 + v0 t + g t^2/2, angle = 0.25 - 2 t.
const char* kThrow2d = R"(
[scene]
dimension = 2
gravity = [0.0, -9.81]
duration = 1.0
output_dt = 0.125

[[body]]
name = "ball"
shape = "disc"
radius = 0.1
mass = 2.0
position = [0.5, 3.0]
angle = 0.25
v = [1.5, 4.0]
w = -2.0
)";

// Two discs head on (1 kg at 2 m/s, 2 kg at -1 m/s, e = 1): they touch at t = 0.8 / 3 and
// leave at -2 and 1 m/s.
const char* kHeadOn = R"(
[scene]
dimension = 2
duration = 0.5
output_dt = 0.1

[[body]]
name = "left"
shape = "disc"
radius = 0.1
mass = 1.0
position = [0.0, 0.0]
v = [2.0, 0.0]

[[body]]
name = "right"
shape = "disc"
radius = 0.1
mass = 2.0
position = [1.0, 0.0]
v = [-1.0, 0.0]
)";

const char* kSphere3d = R"(
[scene]
dimension = 3
gravity = [0.0, -9.81, 0.0]
duration = 0.5
output_dt = 0.1

[[body]]
name = "ground"
shape = "plane"
normal = [0.0, 1.0, 0.0]
offset = 0.0

[[body]]
name = "ball"
shape = "sphere"
radius = 0.1
mass = 1.0
position = [0.0, 1.0, 0.0]
)";

struct Reply {
    std::vector<std::string> lines;   // stdout
    std::vector<std::string> errors;  // stderr
};

std::vector<std::string> split_lines(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> v;
    for (std::string line; std::getline(in, line);) v.push_back(line);
    return v;
}

Reply run(const std::string& scene, const std::string& commands, bool json = true) {
    std::istringstream in(commands);
    std::ostringstream out, err;
    run_interactive(parse_scene_text(scene, "scene.toml"), {json, false}, in, out, err);
    return {split_lines(out.str()), split_lines(err.str())};
}

std::vector<nlohmann::json> parse(const std::vector<std::string>& lines) {
    std::vector<nlohmann::json> v;
    for (const std::string& line : lines) v.push_back(nlohmann::json::parse(line));
    return v;
}

std::vector<double> vec(const nlohmann::json& j) { return j.get<std::vector<double>>(); }

void expect_thrown(const nlohmann::json& state, double t) {
    EXPECT_NEAR(state["t"].get<double>(), t, 1e-15);
    const auto x = vec(state["bodies"]["ball"]["x"]);
    EXPECT_NEAR(x[0], 0.5 + 1.5 * t, 1e-12);
    EXPECT_NEAR(x[1], 3.0 + 4.0 * t - g * t * t / 2, 1e-12);
    EXPECT_NEAR(state["bodies"]["ball"]["angle"].get<double>(), 0.25 - 2.0 * t, 1e-12);
}

TEST(Interactive, StepShowBack) {
    const Reply r = run(kThrow2d, "step 3\nshow ball\nback 2\nshow ball\nquit\n");
    EXPECT_TRUE(r.errors.empty());
    const auto states = parse(r.lines);
    ASSERT_EQ(states.size(), 4u);
    for (std::size_t k = 0; k < 4; ++k) expect_thrown(states[k], k < 2 ? 0.375 : 0.125);
    EXPECT_EQ(states[1]["bodies"].size(), 1u);  // show ball: that body only
}

TEST(Interactive, TextRepliesNameTheTime) {
    const Reply r = run(kThrow2d, "step 3\nshow ball\nback 2\nshow\n", false);
    EXPECT_TRUE(r.errors.empty());
    std::vector<std::string> times;
    for (const std::string& line : r.lines)
        if (line.rfind("t = ", 0) == 0) times.push_back(line);
    EXPECT_EQ(times, (std::vector<std::string>{"t = 0.375 s", "t = 0.375 s", "t = 0.125 s", "t = 0.125 s"}));
    EXPECT_NE(r.lines.back().find("kinetic"), std::string::npos);  // show: the totals last
}

// After `set ball.v` at t1 the disc flies from x(t1) with the new velocity.
TEST(Interactive, SetVelocityChangesTheTrajectory) {
    for (const char* value : {"1,2", "[1, 2]", "(1 2)"}) {
        const Reply r = run(kThrow2d, std::string("step 2\nset ball.v ") + value + "\nstep 2\n");
        EXPECT_TRUE(r.errors.empty()) << value;
        const auto states = parse(r.lines);
        ASSERT_EQ(states.size(), 3u);
        EXPECT_EQ(vec(states[1]["bodies"]["ball"]["v"]), (std::vector<double>{1.0, 2.0}));
        const double t1 = 0.25, dt = 0.25;
        const double x1 = 0.5 + 1.5 * t1, y1 = 3.0 + 4.0 * t1 - g * t1 * t1 / 2;
        const auto& ball = states[2]["bodies"]["ball"];
        EXPECT_NEAR(states[2]["t"].get<double>(), 0.5, 1e-15);
        EXPECT_NEAR(vec(ball["x"])[0], x1 + 1.0 * dt, 1e-12);
        EXPECT_NEAR(vec(ball["x"])[1], y1 + 2.0 * dt - g * dt * dt / 2, 1e-12);
        EXPECT_NEAR(vec(ball["v"])[1], 2.0 - g * dt, 1e-12);
    }
}

TEST(Interactive, SetPositionAngleAndSpin) {
    const Reply r = run(kThrow2d, "set ball.x 0,10\nset ball.angle 1\nset ball.w 5\nstep\n");
    EXPECT_TRUE(r.errors.empty());
    const auto states = parse(r.lines);
    ASSERT_EQ(states.size(), 4u);
    const auto& ball = states[3]["bodies"]["ball"];
    const double t = 0.125;
    EXPECT_NEAR(vec(ball["x"])[0], 1.5 * t, 1e-12);
    EXPECT_NEAR(vec(ball["x"])[1], 10.0 + 4.0 * t - g * t * t / 2, 1e-12);
    EXPECT_NEAR(ball["angle"].get<double>(), 1.0 + 5.0 * t, 1e-12);
    EXPECT_EQ(ball["w"].get<double>(), 5.0);
}

// `back` after `set` returns to the state before the change.
TEST(Interactive, BackUndoesSet) {
    const auto states = parse(run(kThrow2d, "step\nset ball.v 0,0\nback\n").lines);
    ASSERT_EQ(states.size(), 3u);
    expect_thrown(states[2], 0.125);
    EXPECT_NEAR(vec(states[2]["bodies"]["ball"]["v"])[0], 1.5, 1e-12);
}

TEST(Interactive, BadCommandsReportAndContinue) {
    const Reply r = run(kThrow2d,
                        "bogus\nstep x\nstep 0\nstep -1\nset ball.v 1\nset nobody.v 1,2\n"
                        "set ball.q 1\nset ball.v 1,nan\nset ball\nshow nobody\nnext now\nback\n"
                        "step\nquit\nstep\n");
    ASSERT_EQ(r.errors.size(), 12u);
    for (const std::string& e : r.errors) EXPECT_EQ(e.rfind("error: ", 0), 0u) << e;
    EXPECT_NE(r.errors[0].find("unknown command 'bogus'"), std::string::npos);
    EXPECT_NE(r.errors[5].find("no body named 'nobody'"), std::string::npos);
    // Only the one good step ran, and nothing after quit.
    const auto states = parse(r.lines);
    ASSERT_EQ(states.size(), 1u);
    expect_thrown(states[0], 0.125);
}

TEST(Interactive, EndOfInputEndsTheLoop) {
    const auto states = parse(run(kThrow2d, "step").lines);
    ASSERT_EQ(states.size(), 1u);
    expect_thrown(states[0], 0.125);
}

TEST(Interactive, StepStopsAtTheEnd) {
    const Reply r = run(kThrow2d, "step 100\nstep\n");
    const auto states = parse(r.lines);
    ASSERT_EQ(states.size(), 1u);
    expect_thrown(states[0], 1.0);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_NE(r.errors[0].find("ends"), std::string::npos);
}

// A count above the 9 digits once read was refused as "not a whole number" (issue 34): any
// whole number goes to the end (step) or the start (back), however many digits it has.
TEST(Interactive, AnyWholeNumberOfStepsGoesToTheEndOrTheStart) {
    const Reply r = run(kThrow2d, "step 2000000000\nback 99999999999999999999999\nstep 0002\nstep 00\n");
    const auto states = parse(r.lines);
    ASSERT_EQ(states.size(), 3u);
    expect_thrown(states[0], 1.0);
    expect_thrown(states[1], 0.0);
    expect_thrown(states[2], 0.25);
    ASSERT_EQ(r.errors.size(), 1u);  // 00 is not >= 1
    EXPECT_NE(r.errors[0].find("n must be a whole number >= 1, not '00'"), std::string::npos) << r.errors[0];
}

TEST(Interactive, NextShowsBeforeAtAndAfter) {
    const double te = 0.8 / 3.0;
    const Reply r = run(kHeadOn, "next\nevents\nstep\nback\nevents\n");
    EXPECT_TRUE(r.errors.empty());
    ASSERT_EQ(r.lines.size(), 4u);  // next, events, step, back (the last events lists none)
    const auto next = nlohmann::json::parse(r.lines[0]);
    // Before: the last output step before the impact, still approaching.
    EXPECT_NEAR(next["before"]["t"].get<double>(), 0.2, 1e-15);
    EXPECT_NEAR(vec(next["before"]["bodies"]["left"]["x"])[0], 2.0 * 0.2, 1e-12);
    EXPECT_NEAR(vec(next["before"]["bodies"]["left"]["v"])[0], 2.0, 1e-12);
    ASSERT_EQ(next["at"].size(), 1u);
    EXPECT_NEAR(next["at"][0]["t"].get<double>(), te, 1e-9);
    EXPECT_NEAR(vec(next["at"][0]["impulse"])[0], 4.0, 1e-9);
    // After: at the instant, touching, with the velocities after the impulse.
    EXPECT_NEAR(next["after"]["t"].get<double>(), te, 1e-9);
    const auto& after = next["after"]["bodies"];
    EXPECT_NEAR(vec(after["right"]["x"])[0] - vec(after["left"]["x"])[0], 0.2, 1e-9);
    EXPECT_NEAR(vec(after["left"]["v"])[0], -2.0, 1e-9);
    EXPECT_NEAR(vec(after["right"]["v"])[0], 1.0, 1e-9);

    const auto listed = nlohmann::json::parse(r.lines[1]);
    EXPECT_NEAR(listed["t"].get<double>(), te, 1e-9);
    EXPECT_EQ(listed["b"], "right");
    // step: to t = 0.3, the discs separating since te.
    const auto stepped = nlohmann::json::parse(r.lines[2]);
    EXPECT_NEAR(stepped["t"].get<double>(), 0.3, 1e-15);
    EXPECT_NEAR(vec(stepped["bodies"]["left"]["x"])[0], 2.0 * te - 2.0 * (0.3 - te), 1e-9);
    EXPECT_NEAR(vec(stepped["bodies"]["right"]["x"])[0], 1.0 - te + (0.3 - te), 1e-9);
    // back: to t = 0.2, before the impact again, which is then no longer among the events.
    const auto back = nlohmann::json::parse(r.lines[3]);
    EXPECT_NEAR(back["t"].get<double>(), 0.2, 1e-15);
    EXPECT_NEAR(vec(back["bodies"]["right"]["v"])[0], -1.0, 1e-12);
}

TEST(Interactive, NextWithNoCollisionLeftChangesNothing) {
    const Reply r = run(kHeadOn, "next\nnext\nshow\n");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_NE(r.errors[0].find("no collision"), std::string::npos);
    const auto states = parse(r.lines);
    ASSERT_EQ(states.size(), 2u);
    EXPECT_NEAR(states[1]["t"].get<double>(), 0.8 / 3.0, 1e-9);
}

// 1D has no setter in its world; `set` restarts it from the changed state at the current time.
// The cradle's first block, slowed to 1 m/s at t = 0.1 s (x = -0.3 m, 0.1 m from the second),
// arrives at t = 0.2 s.
TEST(Interactive, Set1dRestartsAtTheCurrentTime) {
    const std::string cradle = R"(
[scene]
dimension = 1
duration = 0.5
output_dt = 0.05

[[body]]
name = "first"
shape = "block"
length = 0.2
mass = 1.0
position = -0.5
v = 2.0

[[body]]
name = "second"
shape = "block"
length = 0.2
mass = 1.0
position = 0.0

[[body]]
name = "third"
shape = "block"
length = 0.2
mass = 1.0
position = 0.2
)";
    // next passes the output step t = 0.15 s; 7 more reach the end.
    const Reply r = run(cradle, "step 2\nset first.v 1\nnext\nstep 7\nevents\n");
    EXPECT_TRUE(r.errors.empty());
    ASSERT_EQ(r.lines.size(), 6u);  // step, set, next, step, the 2 events
    const auto next = nlohmann::json::parse(r.lines[2]);
    ASSERT_EQ(next["at"].size(), 2u);  // sequential: first -> second, then second -> third
    EXPECT_NEAR(next["at"][0]["t"].get<double>(), 0.2, 1e-12);
    EXPECT_EQ(next["at"][0]["a"], "first");
    EXPECT_NEAR(next["at"][1]["after"]["third"]["v"].get<double>(), 1.0, 1e-14);
    const auto last = nlohmann::json::parse(r.lines[3]);
    EXPECT_NEAR(last["t"].get<double>(), 0.5, 1e-12);
    EXPECT_NEAR(last["bodies"]["third"]["x"].get<double>(), 0.2 + 1.0 * 0.3, 1e-12);
    EXPECT_NEAR(nlohmann::json::parse(r.lines[4])["t"].get<double>(), 0.2, 1e-12);
    EXPECT_EQ(nlohmann::json::parse(r.lines[5])["b"], "third");
}

TEST(Interactive, Sphere3dOrientationAndRefusals) {
    const Reply r = run(kSphere3d,
                        "show ball\nset ball.orientation 2,0,0,0\nset ball.orientation 0,0,0,0\n"
                        "set ball.x 0,0.05,0\nset ground.v 0,1,0\nset ball.w 1,2\nset ball.angle 1\n"
                        "set ball.w 0,3,0\nshow ball\n");
    ASSERT_EQ(r.errors.size(), 5u);
    EXPECT_NE(r.errors[1].find("overlap"), std::string::npos);
    EXPECT_NE(r.errors[2].find("static"), std::string::npos);
    const auto states = parse(r.lines);
    ASSERT_EQ(states.size(), 4u);
    EXPECT_EQ(vec(states[0]["bodies"]["ball"]["orientation"]), (std::vector<double>{1, 0, 0, 0}));
    EXPECT_EQ(vec(states[1]["bodies"]["ball"]["orientation"]), (std::vector<double>{1, 0, 0, 0}));
    EXPECT_EQ(vec(states[3]["bodies"]["ball"]["w"]), (std::vector<double>{0, 3, 0}));
    EXPECT_EQ(vec(states[3]["bodies"]["ball"]["x"]), (std::vector<double>{0, 1, 0}));  // unmoved
}

TEST(Interactive, HelpListsTheCommands) {
    const Reply r = run(kThrow2d, "help\n", false);
    std::string all;
    for (const std::string& line : r.lines) all += line + "\n";
    for (const char* c : {"step [n]", "next", "back [n]", "show [body]", "set BODY.FIELD", "events", "help", "quit"})
        EXPECT_NE(all.find(c), std::string::npos) << c;
}

}  // namespace
}  // namespace collide
