// `collide step` output: the cradle lesson's states and events, and 2D and 3D flights and
// impacts, against the closed forms, in every format.
#include <cmath>
#include <sstream>
#include <utility>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scenario/scene_file.h"
#include "teach/step_output.h"

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

// step_json (the Python module's collide.run): the lines of --json and of --events --json,
// from one run, in 1D, 2D and 3D.
TEST(Step, StepJsonIsTheJsonAndEventsLines) {
    const std::string dir = std::string(COLLIDE_SOURCE_DIR) + "/lessons/scenes/";
    for (const char* file : {"cradle-1d.toml", "billiards-2d.toml", "dropped-box-3d.toml"}) {
        const Scene s = parse_scene_file(dir + file);
        const StepJson run = step_json(s);
        std::ostringstream states, events;
        write_steps(s, {true, false}, states);
        write_steps(s, {true, true}, events);
        std::string joined_states, joined_events;
        for (const std::string& line : run.states) joined_states += line + "\n";
        for (const std::string& line : run.events) joined_events += line + "\n";
        EXPECT_EQ(joined_states, states.str()) << file;
        EXPECT_EQ(joined_events, events.str()) << file;
        EXPECT_FALSE(run.events.empty()) << file;
    }
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
    const Scene s = parse_scene_file(std::string(COLLIDE_SOURCE_DIR) + "/lessons/scenes/bouncing-ball-1d.toml");
    const auto events = lines(s, {true, true});
    ASSERT_FALSE(events.empty());
    EXPECT_LT(events.size(), 100u);
    EXPECT_NEAR(events.back()["t"].get<double>(), std::sqrt(2.0 / 9.81) * 3.0, 1e-9);
    const auto states = lines(s, {true, false});
    for (const auto& st : states) {
        const double t = st["t"].get<double>();
        const auto& ball = st["bodies"]["ball"];
        if (t < std::sqrt(2.0 / 9.81)) {
            EXPECT_NEAR(st["kinetic_energy"].get<double>() + st["potential_energy"].get<double>(), 0.1 * 9.81 * 1.2,
                        1e-12);
        }
        if (t > 1.36) {
            EXPECT_EQ(ball["v"].get<double>(), 0.0);
            EXPECT_NEAR(ball["x"].get<double>(), 0.2, 1e-12);
        }
    }
}

// ---- 2D and 3D ----

// A disc thrown in 2D gravity with nothing to hit, m = 2 kg, r = 0.1 m (I = m r^2 / 2 = 0.01).
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

// Two discs head on along x (r = 0.1 m, 1 kg at 2 m/s and 2 kg at -1 m/s, centres 1 m apart):
// the 0.8 m gap closes at 3 m/s.
std::string head_on(double e) {
    return R"(
[scene]
dimension = 2
duration = 0.5
output_dt = 0.1
restitution = )" +
           std::to_string(e) + R"(

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
}

// A sphere (2 kg, r = 0.1 m) spinning about y, its bottom 1 m above the ground, e = 0.5.
const char* kDrop3d = R"(
[scene]
dimension = 3
gravity = [0.0, -9.81, 0.0]
duration = 1.0
output_dt = 0.05
restitution = 0.5

[[body]]
name = "ground"
shape = "plane"
normal = [0.0, 1.0, 0.0]
offset = 0.0

[[body]]
name = "ball"
shape = "sphere"
radius = 0.1
mass = 2.0
position = [0.0, 1.1, 0.0]
w = [0.0, 3.0, 0.0]
)";

std::vector<double> vec(const nlohmann::json& j) { return j.get<std::vector<double>>(); }

TEST(Step, FreeFlight2dFollowsTheClosedForm) {
    const auto states = lines(parse_scene_text(kThrow2d, "throw.toml"), {true, false});
    ASSERT_EQ(states.size(), 9u);
    for (std::size_t k = 0; k < states.size(); ++k) {
        const auto& st = states[k];
        const double t = st["t"].get<double>();
        EXPECT_DOUBLE_EQ(t, 0.125 * static_cast<double>(k));
        const auto& ball = st["bodies"]["ball"];
        const auto x = vec(ball["x"]), v = vec(ball["v"]);
        ASSERT_EQ(x.size(), 2u);
        ASSERT_EQ(v.size(), 2u);
        EXPECT_NEAR(x[0], 0.5 + 1.5 * t, 1e-12);
        EXPECT_NEAR(x[1], 3.0 + 4.0 * t - 9.81 * t * t / 2, 1e-12);
        EXPECT_NEAR(v[0], 1.5, 1e-12);
        EXPECT_NEAR(v[1], 4.0 - 9.81 * t, 1e-12);
        EXPECT_DOUBLE_EQ(ball["w"].get<double>(), -2.0);
        EXPECT_NEAR(ball["angle"].get<double>(), 0.25 - 2.0 * t, 1e-12);
        const double ke = 0.5 * 2.0 * (v[0] * v[0] + v[1] * v[1]) + 0.5 * 0.01 * 4.0;
        EXPECT_NEAR(st["kinetic_energy"].get<double>(), ke, 1e-12);
        EXPECT_NEAR(st["potential_energy"].get<double>(), 2.0 * 9.81 * x[1], 1e-12);
        EXPECT_NEAR(vec(st["momentum"])[1], 2.0 * v[1], 1e-12);
        // About the origin: I w + m (x vy - y vx).
        EXPECT_NEAR(st["angular_momentum"].get<double>(), 0.01 * -2.0 + 2.0 * (x[0] * v[1] - x[1] * v[0]), 1e-12);
    }
}

// Impact at t = 0.8 / 3; the impulse on the right disc is (1 + e) mu u along +x with the reduced
// mass mu = 2/3 kg and u = 3 m/s; afterwards v_left = 2 - J, v_right = -1 + J / 2.
TEST(Step, HeadOnDiscsEventsJson) {
    for (double e : {1.0, 0.5}) {
        const Scene s = parse_scene_text(head_on(e), "head-on.toml");
        const auto events = lines(s, {true, true});
        ASSERT_EQ(events.size(), 1u);
        const auto& ev = events[0];
        const double t = 0.8 / 3.0, J = (1.0 + e) * 2.0 / 3.0 * 3.0;
        EXPECT_NEAR(ev["t"].get<double>(), t, 1e-9);
        EXPECT_EQ(ev["a"], "left");
        EXPECT_EQ(ev["b"], "right");
        EXPECT_NEAR(vec(ev["point"])[0], 0.1 + 2.0 * t, 1e-9);
        EXPECT_NEAR(vec(ev["point"])[1], 0.0, 1e-12);
        EXPECT_NEAR(vec(ev["normal"])[0], 1.0, 1e-12);
        EXPECT_NEAR(vec(ev["impulse"])[0], J, 1e-9);
        EXPECT_NEAR(vec(ev["impulse"])[1], 0.0, 1e-12);
        EXPECT_NEAR(vec(ev["before"]["left"]["v"])[0], 2.0, 1e-12);
        EXPECT_NEAR(vec(ev["before"]["right"]["v"])[0], -1.0, 1e-12);
        EXPECT_NEAR(vec(ev["after"]["left"]["v"])[0], 2.0 - J, 1e-9);
        EXPECT_NEAR(vec(ev["after"]["right"]["v"])[0], -1.0 + J / 2.0, 1e-9);
        EXPECT_EQ(ev["after"]["right"]["w"].get<double>(), 0.0);

        // The states: momentum 0 throughout; kinetic energy 3 J before, e^2 of the relative
        // part (mu u^2 / 2 = 3 J here, as the total momentum is 0) after.
        for (const auto& st : lines(s, {true, false})) {
            EXPECT_NEAR(vec(st["momentum"])[0], 0.0, 1e-9);
            const double ke = st["t"].get<double>() < t ? 3.0 : 3.0 * e * e;
            EXPECT_NEAR(st["kinetic_energy"].get<double>(), ke, 1e-9);
        }
    }
}

TEST(Step, EventText2dNamesBodiesAndVectors) {
    std::ostringstream out;
    write_steps(parse_scene_text(head_on(1.0), "head-on.toml"), {false, true}, out);
    const std::string text = out.str();
    for (const char* part :
         {"t = 0.266667 s: left hits right at (0.633333, ", "normal (1, 0)", "impulse on right (4, 0) N s",
          "left v (2, 0) -> (-2, 0) m/s, w 0 -> 0", "right v (-1, 0) -> (1, 0) m/s"})
        EXPECT_NE(text.find(part), std::string::npos) << part << " in " << text;
}

// An event flagged approximate by the world (a Routh answer that could not be finished) says
// so in its JSON and its text line; others carry no such key or note.
TEST(Step, AnApproximateEventSaysSo) {
    const Scene s = parse_scene_text(head_on(1.0), "head-on.toml");
    Event2 e;
    e.a = 0, e.b = 1;
    e.point = e.normal = e.impulse = Vec2(1, 0);
    e.before_a = e.before_b = e.after_a = e.after_b = {Vec2::Zero(), 0.0};
    EXPECT_FALSE(nlohmann::json::parse(event_json(s, e, false)).contains("approximate"));
    EXPECT_EQ(event_text(s, e, false).find("approximate"), std::string::npos);
    e.approximate = true;
    EXPECT_TRUE(nlohmann::json::parse(event_json(s, e, false)).contains("approximate"));
    EXPECT_NE(event_text(s, e, false).find("[approximate: "), std::string::npos);
}

// A rough rod struck at its lower end (1 kg, 1 m, 50 degrees above the ground, v = (-0.2, -1)
// m/s, w = 6 rad/s, mu = 0.5, e = 0.9): the one-step Coulomb model sticks the contact and then
// reverses u_n by e, which leaves the rod with more kinetic energy than it had (Kane's paradox).
// Computed here: KE before = 1/2 m |v|^2 + 1/2 (m L^2 / 12) w^2 = 0.52 + 1.5 J; after, from the
// event's velocities. The event is marked; the same rod without friction loses energy and is not.
TEST(Step, AnEventThatGainsEnergyIsMarked) {
    const auto rod = [](const char* model) {
        return std::string("[scene]\ndimension = 2\nduration = 0.1\noutput_dt = 0.1\nmodel = \"") + model +
               "\"\nrestitution = 0.9\nfriction = 0.5\n"
               "[[body]]\nname = \"ground\"\nshape = \"plane\"\nnormal = [0.0, 1.0]\noffset = 0.0\n"
               "[[body]]\nname = \"rod\"\nshape = \"rectangle\"\nsize = [1.0, 0.001]\nmass = 1.0\n"
               "angle = 0.8726646259971648\nposition = [0.3213938048432697, 0.4030222215594891]\n"
               "v = [-0.2, -1.0]\nw = 6.0\n";
    };
    for (const char* model : {"coulomb", "frictionless"}) {
        SCOPED_TRACE(model);
        const Scene s = parse_scene_text(rod(model), "rod.toml");
        const auto events = lines(s, {true, true});
        ASSERT_EQ(events.size(), 1u);
        const auto& ev = events[0];
        const std::vector<double> v = vec(ev["after"]["rod"]["v"]);
        const double w = ev["after"]["rod"]["w"].get<double>();
        const double I = 1.0 * (1.0 + 0.001 * 0.001) / 12.0;
        const double before = 0.5 * (0.04 + 1.0) + 0.5 * I * 36.0;
        const double after = 0.5 * (v[0] * v[0] + v[1] * v[1]) + 0.5 * I * w * w;
        const bool gains = std::string(model) == "coulomb";
        EXPECT_EQ(after > before, gains) << before << " J before, " << after << " J after";
        EXPECT_EQ(ev["energy_gain"].get<bool>(), gains);
        std::ostringstream text;
        write_steps(s, {false, true}, text);
        EXPECT_EQ(text.str().find("Kane's paradox") != std::string::npos, gains) << text.str();
    }
}

// The same rod under model = "routh", touching at t = 0 (a 1 micrometre thick rectangle with its
// lower corner on the ground, so the rod has not turned before the impact): the world's impact
// is Routh's, and its energy change is the issue's reference for each law (an exact piecewise
// integration checked against a fine numerical one): Newton +0.2754 J, Poisson -1.0606 J,
// Stronge -0.7527 J, to their 4 decimals. Only Newton's is marked as a gain.
TEST(Step, RouthImpactsInTheWorldGiveTheReferenceEnergies) {
    const std::pair<const char*, double> laws[] = {{"newton", 0.2754}, {"poisson", -1.0606}, {"stronge", -0.7527}};
    for (const auto& [law, dE] : laws) {
        SCOPED_TRACE(law);
        const Scene s =
            parse_scene_text(std::string("[scene]\ndimension = 2\nduration = 0.1\noutput_dt = 0.1\nmodel = \"routh\"\n"
                                         "restitution_law = \"") +
                                 law +
                                 "\"\nrestitution = 0.9\nfriction = 0.5\n"
                                 "[[body]]\nname = \"ground\"\nshape = \"plane\"\nnormal = [0.0, 1.0]\noffset = 0.0\n"
                                 "[[body]]\nname = \"rod\"\nshape = \"rectangle\"\nsize = [1.0, 1e-6]\nmass = 1.0\n"
                                 "angle = 0.8726646259971648\nposition = [0.32139342182104813, 0.38302254295429383]\n"
                                 "v = [-0.2, -1.0]\nw = 6.0\n",
                             "rod.toml");
        const auto events = lines(s, {true, true});
        ASSERT_EQ(events.size(), 1u);
        const auto& ev = events[0];
        EXPECT_LT(ev["t"].get<double>(), 1e-9);
        const std::vector<double> v = vec(ev["after"]["rod"]["v"]);
        const double w = ev["after"]["rod"]["w"].get<double>(), I = (1.0 + 1e-12) / 12.0;
        const double change = 0.5 * (v[0] * v[0] + v[1] * v[1]) + 0.5 * I * w * w - (0.5 * 1.04 + 0.5 * I * 36.0);
        EXPECT_NEAR(change, dE, 1e-4);
        EXPECT_EQ(ev["energy_gain"].get<bool>(), dE > 0);
    }
}

// First impact after a 1 m fall: t = sqrt(2 / g) at v = sqrt(2 g); the ground gives the ball
// m (1 + e) v upwards. The spin about y is untouched: orientation (cos 1.5t, 0, sin 1.5t, 0).
TEST(Step, DroppedSphere3d) {
    const Scene s = parse_scene_text(kDrop3d, "drop.toml");
    const double t1 = std::sqrt(2.0 / 9.81), v1 = std::sqrt(2.0 * 9.81);
    const auto events = lines(s, {true, true});
    ASSERT_FALSE(events.empty());
    const auto& ev = events[0];
    EXPECT_NEAR(ev["t"].get<double>(), t1, 1e-9);
    EXPECT_EQ(ev["a"], "ground");
    EXPECT_EQ(ev["b"], "ball");
    ASSERT_EQ(vec(ev["impulse"]).size(), 3u);
    EXPECT_NEAR(vec(ev["impulse"])[1], 2.0 * 1.5 * v1, 1e-8);
    EXPECT_NEAR(vec(ev["after"]["ball"]["v"])[1], 0.5 * v1, 1e-8);
    EXPECT_EQ(vec(ev["after"]["ball"]["w"]), (std::vector<double>{0.0, 3.0, 0.0}));

    for (const auto& st : lines(s, {true, false})) {
        const auto& ball = st["bodies"]["ball"];
        EXPECT_FALSE(ball.contains("angle"));
        const auto q = vec(ball["orientation"]);
        ASSERT_EQ(q.size(), 4u);
        ASSERT_EQ(vec(ball["w"]).size(), 3u);
        ASSERT_EQ(vec(st["angular_momentum"]).size(), 3u);
        const double t = st["t"].get<double>();
        EXPECT_NEAR(q[0], std::cos(1.5 * t), 1e-9);
        EXPECT_NEAR(q[2], std::sin(1.5 * t), 1e-9);
        if (t < t1) {
            EXPECT_NEAR(vec(ball["x"])[1], 1.1 - 9.81 * t * t / 2, 1e-12);
        }
    }
}

// One row per output step under one header; the moving bodies have a column group each, the
// static ground none, and the columns line up (every line equally long).
TEST(Step, Table2dAnd3d) {
    using Columns = std::vector<std::string>;
    for (const auto& [text, columns] :
         {std::pair<std::string, Columns>{kThrow2d, {"ball.x", "ball.v", "ball.angle", "ball.w"}},
          {kDrop3d, {"ball.x", "ball.v", "ball.w"}}}) {
        const Scene s = parse_scene_text(text, "scene.toml");
        std::ostringstream out;
        write_steps(s, {}, out);
        std::istringstream in(out.str());
        std::vector<std::string> rows;
        for (std::string line; std::getline(in, line);) rows.push_back(line);
        ASSERT_EQ(rows.size(), output_times(s).size() + 1);
        for (const std::string& c : columns) EXPECT_NE(rows[0].find(c), std::string::npos) << c;
        EXPECT_EQ(rows[0].find("ground"), std::string::npos);
        EXPECT_EQ(rows[0].find("angle") != std::string::npos, s.dimension == 2);
        for (const std::string& r : rows) EXPECT_EQ(r.size(), rows[0].size()) << r;
    }
}

}  // namespace
}  // namespace collide
