// [[question]] kinds (scenario/lesson.h): each kind parses into its fields, every bundled lesson
// asks students to predict and to explain or choose, and lesson_with_values changes a scene
// as if its file had been written so.
#include "scenario/lesson.h"

#include <gtest/gtest.h>

namespace collide {
namespace {

const std::string kDir = std::string(COLLIDE_SOURCE_DIR) + "/lessons";

// A valid 1D lesson: A (2 kg, 1.5 m/s) catches B (1 kg, 0.3 m/s); questions are appended.
const char* kLesson = R"([lesson]
id = "kinds"
title = "Kinds of questions"
[scene]
dimension = 1
duration = 1.0
restitution = 0.5
[[body]]
name = "A"
shape = "block"
length = 0.3
mass = 2.0
position = -0.8
v = 1.5
[[body]]
name = "B"
shape = "block"
length = 0.3
mass = 1.0
v = 0.3
)";

Lesson parse(const std::string& questions) {
    return parse_lesson_text(kLesson + questions, "kinds.toml", "kinds.toml");
}

TEST(LessonQuestions, ANumericQuestionIsTheDefaultWithATwoPercentTolerance) {
    const Lesson L = parse(
        "[[question]]\ntext = \"J?\"\nquantity = \"impulse\"\n"
        "[[question]]\nkind = \"numeric\"\ntext = \"v?\"\nquantity = \"velocity_after\"\nbody = \"A\"\n"
        "tolerance = 0.05\n");
    ASSERT_EQ(L.questions.size(), 2u);
    EXPECT_EQ(L.questions[0].kind, QuestionKind::numeric);
    EXPECT_DOUBLE_EQ(L.questions[0].tolerance, 0.02);
    EXPECT_TRUE(L.questions[0].has_quantity());
    EXPECT_FALSE(L.questions[0].has_choices());
    EXPECT_EQ(L.questions[1].kind, QuestionKind::numeric);
    EXPECT_DOUBLE_EQ(L.questions[1].tolerance, 0.05);
    EXPECT_EQ(L.questions[1].body, "A");
}

TEST(LessonQuestions, APairNamesACollisionByItsBodiesInItsRoles) {
    const Lesson L = parse(
        "[[question]]\ntext = \"J?\"\nquantity = \"impulse\"\npair = [\"B\", \"A\"]\n"
        "[[question]]\ntext = \"v?\"\nquantity = \"velocity_after\"\nbody = \"A\"\n"
        "pair = [\"A\", \"B\"]\ncollision = 3\n");
    ASSERT_EQ(L.questions.size(), 2u);
    const LessonQuestion &q = L.questions[0], &r = L.questions[1];
    EXPECT_TRUE(q.has_pair());
    EXPECT_EQ(q.pair, (std::vector<std::string>{"B", "A"}));
    EXPECT_EQ(q.pair_a, 1u);  // B, the page's a
    EXPECT_EQ(q.pair_b, 0u);
    EXPECT_EQ(q.collision, 1);
    EXPECT_EQ(r.pair_a, 0u);
    EXPECT_EQ(r.collision, 3);
    EXPECT_FALSE(parse("[[question]]\ntext = \"J?\"\nquantity = \"impulse\"\n").questions[0].has_pair());
    // Not on a question about the whole run.
    EXPECT_THROW(parse("[[question]]\ntext = \"n?\"\nquantity = \"collisions\"\npair = [\"A\", \"B\"]\n"), InputError);
    EXPECT_THROW(parse("[[question]]\ntext = \"J?\"\nquantity = \"impulse\"\npair = [\"A\", \"C\"]\n"), InputError);
    EXPECT_THROW(parse("[[question]]\ntext = \"J?\"\nquantity = \"impulse\"\npair = [\"A\", \"B\"]\ncollision = 0\n"),
                 InputError);
}

TEST(LessonQuestions, AChoiceQuestionKeepsItsOptionsTheRightOneAndEveryReason) {
    const Lesson L = parse(
        "[[question]]\nkind = \"choice\"\ntext = \"Which way?\"\n"
        "choices = [\"forward\", \"backward\", \"stops\"]\ncorrect = 2\n"
        "reasons = [\"r1\", \"r2\", \"r3\"]\n");
    const LessonQuestion& q = L.questions.at(0);
    EXPECT_EQ(q.kind, QuestionKind::choice);
    EXPECT_EQ(q.choices, (std::vector<std::string>{"forward", "backward", "stops"}));
    EXPECT_EQ(q.correct, 2);
    EXPECT_EQ(q.reasons, (std::vector<std::string>{"r1", "r2", "r3"}));
    EXPECT_FALSE(q.has_quantity());
}

TEST(LessonQuestions, APredictQuestionHasChoicesOrAQuantityAndAlwaysWhy) {
    const Lesson L = parse(
        "[[question]]\nkind = \"predict\"\ntext = \"Which way?\"\nchoices = [\"f\", \"b\"]\n"
        "correct = 1\nreasons = [\"r1\", \"r2\"]\nexplain = \"why\"\n"
        "[[question]]\nkind = \"predict\"\ntext = \"How fast?\"\nquantity = \"velocity_after\"\n"
        "body = \"B\"\ntolerance = 0.1\nexplain = \"why\"\n");
    ASSERT_EQ(L.questions.size(), 2u);
    EXPECT_EQ(L.questions[0].kind, QuestionKind::predict);
    EXPECT_TRUE(L.questions[0].has_choices());
    EXPECT_FALSE(L.questions[0].has_quantity());
    EXPECT_EQ(L.questions[1].kind, QuestionKind::predict);
    EXPECT_EQ(L.questions[1].quantity, Quantity::velocity_after);
    EXPECT_DOUBLE_EQ(L.questions[1].tolerance, 0.1);
    EXPECT_EQ(L.questions[1].explain, "why");
}

TEST(LessonQuestions, AnExplainQuestionKeepsItsModelAnswer) {
    const Lesson L = parse("[[question]]\nkind = \"explain\"\ntext = \"Why is J > 0?\"\nanswer = \"A catches B.\"\n");
    EXPECT_EQ(L.questions.at(0).kind, QuestionKind::explain);
    EXPECT_EQ(L.questions.at(0).answer, "A catches B.");
    EXPECT_STREQ(question_kind_name(L.questions.at(0).kind), "explain");
}

TEST(LessonQuestions, AWhatIfQuestionKeepsItsValues) {
    const Lesson L = parse(
        "[[question]]\ntext = \"J?\"\nquantity = \"impulse\"\n"
        "what_if = { \"A.mass\" = 1.0, \"scene.restitution\" = 1.0 }\n");
    const std::map<std::string, double> expected = {{"A.mass", 1.0}, {"scene.restitution", 1.0}};
    EXPECT_EQ(L.questions.at(0).what_if, expected);
}

TEST(LessonQuestions, LessonWithValuesChangesOnlyTheNamedValues) {
    const Lesson L = parse("[[question]]\ntext = \"J?\"\nquantity = \"impulse\"\n");
    const Lesson same = lesson_with_values(L, {});
    ASSERT_EQ(same.scene.bodies.size(), 2u);
    EXPECT_EQ(same.scene.bodies[0].body1.mass, 2.0);  // a written number read back exactly
    EXPECT_EQ(same.scene.bodies[1].body1.v, 0.3);
    EXPECT_EQ(same.scene.restitution, 0.5);
    EXPECT_TRUE(same.questions.empty());
    const Lesson changed = lesson_with_values(L, {{"A.mass", 4.0}, {"B.v", -0.25}, {"scene.restitution", 1.0}});
    EXPECT_EQ(changed.scene.bodies[0].body1.mass, 4.0);
    EXPECT_EQ(changed.scene.bodies[0].body1.v, 1.5);
    EXPECT_EQ(changed.scene.bodies[1].body1.mass, 1.0);
    EXPECT_EQ(changed.scene.bodies[1].body1.v, -0.25);
    EXPECT_EQ(changed.scene.restitution, 1.0);
    EXPECT_EQ(changed.id, L.id);
}

TEST(LessonQuestions, LessonWithValuesRefusesWhatTheFileWouldRefuse) {
    const Lesson L = parse("");
    try {
        lesson_with_values(L, {{"C.mass", 1.0}});
        FAIL() << "accepted a body that does not exist";
    } catch (const InputError& e) {
        EXPECT_EQ(e.key(), "C.mass");
        EXPECT_NE(e.message().find("no body named 'C'"), std::string::npos) << e.what();
    }
    try {
        lesson_with_values(L, {{"A.mas", 1.0}});
        FAIL() << "accepted a misspelt key";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("did you mean 'mass'?"), std::string::npos) << e.what();
    }
    EXPECT_THROW(lesson_with_values(L, {{"scene.restitution", 1.5}}), InputError);
    EXPECT_THROW(lesson_with_values(L, {{"mass", 1.0}}), InputError);
}

// Each what-if reads the lesson again: their number is bounded, so a file's cost stays linear.
TEST(LessonQuestions, ALessonHasAtMostTwentyWhatIfQuestions) {
    std::string twenty, one_more;
    for (int i = 0; i < 20; ++i)
        twenty += "[[question]]\ntext = \"J?\"\nquantity = \"impulse\"\nwhat_if = { \"A.mass\" = 3.0 }\n";
    EXPECT_EQ(parse(twenty).questions.size(), 20u);
    try {
        parse(twenty + "[[question]]\ntext = \"J?\"\nquantity = \"impulse\"\nwhat_if = { \"A.mass\" = 3.0 }\n");
        FAIL() << "accepted 21";
    } catch (const InputError& e) {
        EXPECT_EQ(e.key(), "question[21].what_if");
        EXPECT_NE(e.message().find("at most 20 what-if questions"), std::string::npos) << e.what();
    }
}

// The content the issue asks for: every lesson makes students predict, and explain or choose.
TEST(LessonQuestions, EveryBundledLessonHasAPredictionAndAWhyOrChoiceQuestion) {
    const std::vector<Lesson> all = load_lessons(kDir);
    ASSERT_EQ(all.size(), 22u);
    for (const Lesson& L : all) {
        SCOPED_TRACE(L.id);
        int predict = 0, think = 0, numeric = 0;
        for (const LessonQuestion& q : L.questions) {
            predict += q.kind == QuestionKind::predict;
            think += q.kind == QuestionKind::explain || q.kind == QuestionKind::choice;
            numeric += q.kind == QuestionKind::numeric;
        }
        EXPECT_GE(predict, 1);
        EXPECT_GE(think, 1);
        EXPECT_GE(numeric, 1);  // the engine's numbers stay
    }
}

TEST(LessonQuestions, EveryBundledChoiceHasAReasonForEachOptionAndARightOneInRange) {
    int choices = 0;
    for (const Lesson& L : load_lessons(kDir))
        for (const LessonQuestion& q : L.questions) {
            SCOPED_TRACE(L.id + ": " + q.text);
            if (q.kind == QuestionKind::predict) {
                EXPECT_FALSE(q.explain.empty());
            }
            if (!q.has_choices()) continue;
            ++choices;
            EXPECT_GE(q.choices.size(), 2u);
            EXPECT_LE(q.choices.size(), 6u);
            EXPECT_EQ(q.reasons.size(), q.choices.size());
            EXPECT_GE(q.correct, 1);
            EXPECT_LE(q.correct, static_cast<int>(q.choices.size()));
            for (const std::string& r : q.reasons) EXPECT_FALSE(r.empty());
        }
    EXPECT_GE(choices, 19);
}

}  // namespace
}  // namespace collide
