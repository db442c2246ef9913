// [[vary]] (scenario/lesson_values.cpp, docs/formats/lesson-files.md "The lesson's inputs"): the
// grid from lo to hi reaches hi (the step must divide the range), holds at most a million
// values, starts from the lesson's own value; a key may name one component of a vector
// ("v.x"), and in_proportion changes other bodies' key by the same factor (lesson_with_inputs);
// lesson_with_values takes the same names. Each refusal names the file, the line and the key.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "scenario/lesson.h"

namespace collide {
namespace {

// A 2D lesson: A (2 kg at (-0.6, 0), moving (1.5, 0)) and B (1 kg at rest at (0.3, 0.25)),
// a row C, D whose x are 0.6 and 0.9; the [[vary]] tables are appended (from line 40 on).
const char* kLesson = R"([lesson]
id = "values"
title = "Inputs"
[scene]
dimension = 2
duration = 1.0
restitution = 0.5
[[body]]
name = "A"
shape = "disc"
radius = 0.1
mass = 2
position = [-0.6, 0.0]
v = [1.5, 0.0]
[[body]]
name = "B"
shape = "disc"
radius = 0.1
mass = 1.0
position = [0.3, 0.0]
[[body]]
name = "C"
shape = "disc"
radius = 0.1
mass = 1.0
position = [0.6, 0.5]
[[body]]
name = "D"
shape = "disc"
radius = 0.1
mass = 1.0
position = [0.9, 0.5]
[[question]]
text = "J?"
quantity = "impulse"
)";

constexpr int kFirstVaryLine = 36;  // the line of the first appended [[vary]]

Lesson parse(const std::string& vary) { return parse_lesson_text(kLesson + vary, "values.toml", "values.toml"); }

std::string vary(const std::string& body, const std::string& key, const std::string& range, const std::string& step,
                 const std::string& more = "") {
    return "[[vary]]\nbody = \"" + body + "\"\nkey = \"" + key + "\"\nrange = " + range + "\nstep = " + step + "\n" +
           more;
}

// The refusal of `text`: its message, which must name the file, `line` and `key`.
std::string refusal(const std::string& text, int line, const std::string& key) {
    try {
        parse(text);
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("values.toml:" + std::to_string(line) + ":"), std::string::npos) << what;
        EXPECT_EQ(e.key(), key) << what;
        return what;
    }
    ADD_FAILURE() << "accepted:\n" << text;
    return "";
}

TEST(LessonValues, TheGridReachesHi) {
    // 0.1 does not divide 1 exactly in doubles (1 / 0.1 = 10.000000000000002 is fine, but
    // 0.3 / 0.1 = 2.9999999999999996): both grids end at hi.
    const Lesson L = parse(vary("scene", "restitution", "[0.0, 1.0]", "0.1") + vary("A", "mass", "[1.0, 4.0]", "0.1") +
                           vary("B", "mass", "[0.7, 1.0]", "0.1"));
    ASSERT_EQ(L.vary.size(), 3u);
    EXPECT_EQ(L.vary[0].count(), 11u);
    EXPECT_EQ(L.vary[0].value(10), 1.0);
    EXPECT_EQ(L.vary[0].value(3), 0.3);  // printed as written, not 0.30000000000000004
    EXPECT_EQ(L.vary[1].count(), 31u);
    EXPECT_EQ(L.vary[1].value(30), 4.0);
    EXPECT_EQ(L.vary[2].count(), 4u);
    EXPECT_EQ(L.vary[2].value(3), 1.0);
    for (const LessonVary& v : L.vary)
        for (std::size_t k = 0; k < v.count(); ++k) {
            EXPECT_LE(v.value(k), v.hi) << v.name() << " " << k;
            EXPECT_NEAR(v.value(k), v.lo + static_cast<double>(k) * v.step, 1e-9) << v.name() << " " << k;
        }
}

TEST(LessonValues, AStepThatDoesNotDivideTheRangeIsRefused) {
    const std::string e = refusal(vary("A", "mass", "[1.0, 4.0]", "0.7"), kFirstVaryLine + 4, "vary[1].step");
    EXPECT_NE(e.find("does not divide the range [1, 4]"), std::string::npos) << e;
    EXPECT_NE(e.find("the last would be 3.8"), std::string::npos) << e;
    EXPECT_NE(e.find("hi = 3.8 or 4.5"), std::string::npos) << e;
    refusal(vary("scene", "restitution", "[0.0, 0.5]", "1"), kFirstVaryLine + 4, "vary[1].step");
}

TEST(LessonValues, AMillionValuesPassAndOneMoreIsRefused) {
    // [0, 999999] in steps of 1: 1 000 000 values, the documented limit.
    const Lesson L = parse(vary("A", "mass", "[1.0, 1000000.0]", "1"));
    EXPECT_EQ(L.vary.at(0).count(), kMaxVaryValues);
    EXPECT_EQ(L.vary.at(0).value(kMaxVaryValues - 1), 1000000.0);
    const std::string e = refusal(vary("A", "mass", "[1.0, 1000001.0]", "1"), kFirstVaryLine + 4, "vary[1].step");
    EXPECT_NE(e.find("1000001 values, more than 1000000"), std::string::npos) << e;
    refusal(vary("A", "mass", "[0.0, 1.0]", "1e-6"), kFirstVaryLine + 4, "vary[1].step");
}

TEST(LessonValues, TheLessonsOwnValueIsOnTheGrid) {
    const std::string e = refusal(vary("A", "mass", "[2.5, 4.0]", "0.5"), kFirstVaryLine + 3, "vary[1].range");
    EXPECT_NE(e.find("the lesson's own A.mass = 2 is not one of the values"), std::string::npos) << e;
    refusal(vary("A", "mass", "[1.0, 4.0]", "1.5"), kFirstVaryLine + 3, "vary[1].range");  // 1, 2.5, 4
}

TEST(LessonValues, AKeyMayNameOneComponentOfAVector) {
    const Lesson L = parse(vary("A", "v.x", "[1.0, 2.5]", "0.25") + vary("B", "position.y", "[-0.1, 0.1]", "0.05"));
    ASSERT_EQ(L.vary.size(), 2u);
    EXPECT_EQ(L.vary[0].name(), "A.v.x");
    EXPECT_EQ(L.vary[0].field, "v");
    EXPECT_EQ(L.vary[0].component, 0);
    EXPECT_EQ(L.vary[0].lesson_value, 1.5);
    EXPECT_EQ(L.vary[1].name(), "B.position.y");
    EXPECT_EQ(L.vary[1].component, 1);
    EXPECT_EQ(L.vary[1].lesson_value, 0.0);
    // The same names in lesson_with_values: only that component changes.
    const Lesson changed = lesson_with_values(L, {{"A.v.x", 2.0}, {"B.position.y", 0.05}, {"A.mass", 3.0}});
    EXPECT_EQ(changed.scene.bodies[0].body2.v, Vec2(2.0, 0.0));
    EXPECT_EQ(changed.scene.bodies[0].body2.mass, 3.0);  // written as an integer, changed as one
    EXPECT_EQ(changed.scene.bodies[1].body2.position, Vec2(0.3, 0.05));
    // The whole vector is not a number; a component the vector lacks, or not x, y, z.
    refusal(vary("A", "v", "[1.0, 2.0]", "0.5"), kFirstVaryLine + 2, "vary[1].key");
    refusal(vary("A", "v.z", "[1.0, 2.0]", "0.5"), kFirstVaryLine + 2, "vary[1].key");
    const std::string e = refusal(vary("A", "v.speed", "[1.0, 2.0]", "0.5"), kFirstVaryLine + 2, "vary[1].key");
    EXPECT_NE(e.find("a component x, y or z"), std::string::npos) << e;
    refusal(vary("A", "mass.x", "[1.0, 2.0]", "0.5"), kFirstVaryLine + 2, "vary[1].key");
    refusal(vary("B", "v.x", "[1.0, 2.0]", "0.5"), kFirstVaryLine + 2, "vary[1].key");  // B writes no v
    try {
        lesson_with_values(L, {{"A.v.w", 1.0}});
        FAIL() << "accepted A.v.w";
    } catch (const InputError& err) {
        EXPECT_EQ(err.key(), "A.v.w");
    }
}

TEST(LessonValues, InProportionScalesTheOtherBodiesKey) {
    // C at x 0.6 and D at 0.9, both rows of 0.3: C.position.x = 0.8 puts D at 1.2.
    const Lesson L = parse(vary("C", "position.x", "[0.4, 0.8]", "0.1", "in_proportion = [\"D\"]\n"));
    ASSERT_EQ(L.vary.size(), 1u);
    EXPECT_EQ(L.vary[0].in_proportion, std::vector<std::string>{"D"});
    const Lesson changed = lesson_with_inputs(L, {{"C.position.x", 0.8}});
    EXPECT_NEAR(changed.scene.bodies[2].body2.position.x(), 0.8, 1e-15);
    EXPECT_NEAR(changed.scene.bodies[3].body2.position.x(), 1.2, 1e-15);
    EXPECT_EQ(changed.scene.bodies[3].body2.position.y(), 0.5);
    // lesson_with_values (a question's what_if) changes only the number it names.
    const Lesson alone = lesson_with_values(L, {{"C.position.x", 0.5}});
    EXPECT_EQ(alone.scene.bodies[3].body2.position.x(), 0.9);
    // Given both, the values would disagree: refused, naming the body's key.
    try {
        lesson_with_inputs(L, {{"C.position.x", 0.8}, {"D.position.x", 1.0}});
        FAIL() << "accepted D.position.x beside the input that scales it";
    } catch (const InputError& err) {
        EXPECT_EQ(err.key(), "D.position.x");
    }
    refusal(vary("C", "position.x", "[0.4, 0.8]", "0.1", "in_proportion = [\"E\"]\n"), kFirstVaryLine + 5,
            "vary[1].in_proportion");
    refusal(vary("C", "position.x", "[0.4, 0.8]", "0.1", "in_proportion = [\"C\"]\n"), kFirstVaryLine + 5,
            "vary[1].in_proportion");
    refusal(vary("B", "position.x", "[0.3, 0.8]", "0.1", "in_proportion = [\"B\"]\n"), kFirstVaryLine + 5,
            "vary[1].in_proportion");
    // A's position.y is 0: nothing is in proportion to it.
    refusal(vary("A", "position.y", "[0.0, 0.5]", "0.1", "in_proportion = [\"B\"]\n"), kFirstVaryLine + 5,
            "vary[1].in_proportion");
    // D's x already changes with C's.
    refusal(vary("C", "position.x", "[0.4, 0.8]", "0.1", "in_proportion = [\"D\"]\n") +
                vary("D", "position.x", "[0.9, 1.2]", "0.1"),
            kFirstVaryLine + 8, "vary[2].key");
}

TEST(LessonValues, ABodyNameWithADotIsFound) {
    std::string text = kLesson;
    text.replace(text.find("name = \"B\""), 10, "name = \"B.1\"");
    const Lesson L = parse_lesson_text(text, "values.toml", "values.toml");
    const Lesson changed = lesson_with_values(L, {{"B.1.position.x", 0.4}, {"B.1.mass", 2.0}});
    EXPECT_EQ(changed.scene.bodies[1].body2.position.x(), 0.4);
    EXPECT_EQ(changed.scene.bodies[1].body2.mass, 2.0);
}

}  // namespace
}  // namespace collide
