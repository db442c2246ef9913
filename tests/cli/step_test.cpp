// `collide step` output: the cradle lesson's states and events against the closed forms, in
// every format.
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

TEST(Step, OtherDimensionsSaySoClearly) {
    Scene s;
    s.dimension = 2;
    std::ostringstream out;
    EXPECT_THROW(write_steps(s, {}, out), std::runtime_error);
    EXPECT_TRUE(out.str().empty());
}

}  // namespace
}  // namespace collide
