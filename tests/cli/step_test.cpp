// `collide step` output: the cradle lesson's states and events against the closed forms, in
// every format.
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/scene_file.h"
#include "cli/step.h"

namespace collide {
namespace {

Scene cradle(const std::string& policy) {
    Scene s = parse_scene_file(std::string(COLLIDE_SOURCE_DIR) + "/lessons/scenes/cradle-1d.toml");
    s.policy = policy == "sequential" ? Policy::sequential : Policy::simultaneous;
    return s;
}

std::vector<nlohmann::json> lines(const Scene& s, StepOptions o) {
    std::ostringstream out;
    write_steps(s, o, out);
    std::istringstream in(out.str());
    std::vector<nlohmann::json> v;
    for (std::string line; std::getline(in, line);) v.push_back(nlohmann::json::parse(line));
    return v;
}

// t = 0, 0.05, ..., 0.5 inclusive: 11 states. The first block (2 m/s, 0.3 m gap) arrives at
// 0.15 s; afterwards sequential gives (0, 0, 2), simultaneous (-2/3, 4/3, 4/3) m/s; momentum
// 2 N s and energy 2 J throughout.
TEST(Step, CradleStatesBothPolicies) {
    for (const char* policy : {"sequential", "simultaneous"}) {
        const auto states = lines(cradle(policy), {true, false});
        ASSERT_EQ(states.size(), 11u);
        EXPECT_DOUBLE_EQ(states.front()["t"].get<double>(), 0.0);
        EXPECT_DOUBLE_EQ(states.back()["t"].get<double>(), 0.5);
        const auto& last = states.back()["bodies"];
        const bool seq = std::string(policy) == "sequential";
        EXPECT_NEAR(last["first"]["v"].get<double>(), seq ? 0.0 : -2.0 / 3.0, 1e-14);
        EXPECT_NEAR(last["second"]["v"].get<double>(), seq ? 0.0 : 4.0 / 3.0, 1e-14);
        EXPECT_NEAR(last["third"]["v"].get<double>(), seq ? 2.0 : 4.0 / 3.0, 1e-14);
        for (const auto& st : states) {
            EXPECT_NEAR(st["momentum"].get<double>(), 2.0, 1e-14);
            EXPECT_NEAR(st["kinetic_energy"].get<double>(), 2.0, 1e-14);
        }
        // x of the third block at the end: 0.2 + v3 (0.5 - 0.15).
        EXPECT_NEAR(last["third"]["x"].get<double>(), 0.2 + (seq ? 2.0 : 4.0 / 3.0) * 0.35, 1e-12);
    }
}

TEST(Step, CradleEventsJson) {
    const auto events = lines(cradle("sequential"), {true, true});
    ASSERT_EQ(events.size(), 2u);
    EXPECT_NEAR(events[0]["t"].get<double>(), 0.15, 1e-12);
    EXPECT_EQ(events[0]["a"], "first");
    EXPECT_EQ(events[0]["b"], "second");
    EXPECT_NEAR(events[0]["impulse"].get<double>(), 2.0, 1e-14);
    EXPECT_NEAR(events[0]["before"]["first"]["v"].get<double>(), 2.0, 1e-14);
    EXPECT_NEAR(events[0]["after"]["second"]["v"].get<double>(), 2.0, 1e-14);
    EXPECT_EQ(events[1]["b"], "third");
}

TEST(Step, TableHasOneRowPerOutputStep) {
    std::ostringstream out;
    write_steps(cradle("sequential"), {}, out);
    std::istringstream in(out.str());
    std::string header;
    std::getline(in, header);
    EXPECT_NE(header.find("first.x"), std::string::npos);
    int rows = 0;
    for (std::string line; std::getline(in, line);) ++rows;
    EXPECT_EQ(rows, 11);
}

TEST(Step, SameFileSameBytes) {
    std::ostringstream a, b;
    write_steps(cradle("simultaneous"), {true, false}, a);
    write_steps(cradle("simultaneous"), {true, false}, b);
    EXPECT_EQ(a.str(), b.str());
}

// The bouncing-ball lesson: H = 1 m, e = 0.5, g = 9.81: the bounces end at
// sqrt(2H/g)(1+e)/(1-e) = 1.3546 s and the ball then rests on the floor (x = 0.2 m); before the
// first landing the total energy m g x stays m g 1.2 m.
TEST(Step, BouncingBallLessonComesToRest) {
    const Scene s = parse_scene_file(std::string(COLLIDE_SOURCE_DIR) +
                                     "/lessons/scenes/bouncing-ball-1d.toml");
    const auto events = lines(s, {true, true});
    ASSERT_FALSE(events.empty());
    EXPECT_LT(events.size(), 100u);
    EXPECT_NEAR(events.back()["t"].get<double>(), std::sqrt(2.0 / 9.81) * 3.0, 1e-9);
    const auto states = lines(s, {true, false});
    for (const auto& st : states) {
        const double t = st["t"].get<double>();
        const auto& ball = st["bodies"]["ball"];
        if (t < std::sqrt(2.0 / 9.81)) {
            EXPECT_NEAR(st["kinetic_energy"].get<double>() + st["potential_energy"].get<double>(),
                        0.1 * 9.81 * 1.2, 1e-12);
        }
        if (t > 1.36) {
            EXPECT_EQ(ball["v"].get<double>(), 0.0);
            EXPECT_NEAR(ball["x"].get<double>(), 0.2, 1e-12);
        }
    }
}

TEST(Step, OtherDimensionsSaySoClearly) {
    Scene s;
    s.dimension = 2;
    std::ostringstream out;
    EXPECT_THROW(write_steps(s, {}, out), std::runtime_error);
    EXPECT_TRUE(out.str().empty());
}

}  // namespace
}  // namespace collide
