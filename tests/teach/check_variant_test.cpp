// "Check yourself" with other numbers (teach/check_variant.h): the answers are the closed form
// with the new values, and copying the watched run's number is marked wrong.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "teach/answers.h"
#include "teach/check_variant.h"

namespace collide {
namespace {

const Lesson& lesson(const std::string& id) {
    static const std::vector<Lesson> all = load_lessons(std::string(COLLIDE_SOURCE_DIR) + "/lessons");
    for (const Lesson& L : all)
        if (L.id == id) return L;
    throw std::runtime_error("no lesson " + id);
}

// Catch-up (1D, A behind B): J = (1 + e) m_a m_b (v_a - v_b) / (m_a + m_b), v_a' = v_a - J/m_a,
// v_b' = v_b + J/m_b, the energy lost (1 - e^2) m_a m_b (v_a - v_b)^2 / (2 (m_a + m_b)); with the
// check values, to 1e-9 relative (the run's instant is exact; the formulas are the page's).
TEST(CheckVariant, CatchUpsAnswersAreTheClosedFormWithTheOtherValues) {
    const Lesson& L = lesson("catch-up");
    const std::vector<LessonAnswer> own = answer_questions(L);
    const CheckVariant c = check_variant(L, own);
    const auto value = [&](const std::string& name) { return c.sheet.values.at(name); };
    const double ma = value("A.mass"), va = value("A.v"), mb = value("B.mass"), vb = value("B.v"),
                 e = value("scene.restitution");
    const double J = (1 + e) * ma * mb * (va - vb) / (ma + mb);
    const double want[] = {J, va - J / ma, vb + J / mb,
                           (1 - e * e) * ma * mb * (va - vb) * (va - vb) / (2 * (ma + mb))};
    for (std::size_t i = 0; i < 4; ++i) {
        SCOPED_TRACE(L.questions[i].text);
        ASSERT_TRUE(c.answer[i].has_value());
        EXPECT_NEAR(c.answer[i]->value, want[i], 1e-9 * std::max(1.0, std::abs(want[i])));
        // The watched run's answer (the page's figures show it) would be marked wrong.
        EXPECT_FALSE(marked_right(own[i], *c.answer[i], L.questions[i].tolerance)) << own[i].text;
    }
    EXPECT_TRUE(c.same_as_watched.empty());
    // Predictions and the what-if are asked of the lesson's own run.
    for (std::size_t i = 0; i < L.questions.size(); ++i) {
        if (L.questions[i].kind == QuestionKind::predict || !L.questions[i].what_if.empty()) {
            EXPECT_FALSE(c.answer[i].has_value()) << L.questions[i].text;
        }
    }
}

// marked_right is the page's marking rule: |got - want| <= tolerance |want| + 1e-9, vectors by
// their difference's length.
TEST(CheckVariant, MarkedRightIsThePagesRule) {
    LessonAnswer want, got;
    want.value = 2.0;
    got.value = 2.039;
    EXPECT_TRUE(marked_right(got, want, 0.02));
    got.value = 2.041;
    EXPECT_FALSE(marked_right(got, want, 0.02));
    want.is_vector = got.is_vector = true;
    want.vector = Vec3(3, 4, 0);       // length 5: 2 % is 0.1
    got.vector = Vec3(3.06, 4.08, 0);  // 0.1 away
    EXPECT_TRUE(marked_right(got, want, 0.02));
    got.vector = Vec3(3.07, 4.08, 0);
    EXPECT_FALSE(marked_right(got, want, 0.02));
}

// Newton's cradle of equal blocks: whatever the first block's speed and the blocks' mass, the
// first two stop and it takes 2 collisions; the check values cannot change those answers, and
// the page is told which (same_as_watched), while the impulse and the last block's speed change.
TEST(CheckVariant, AnswersNoValueChangesAreNamed) {
    const Lesson& L = lesson("newtons-cradle");
    const CheckVariant c = check_variant(L, answer_questions(L));
    std::vector<std::string> same;
    for (std::size_t i : c.same_as_watched) same.push_back(L.questions[i].text);
    EXPECT_EQ(same, (std::vector<std::string>{L.questions[1].text, L.questions[2].text, L.questions[3].text}));
    const double m = c.sheet.values.at("first.mass"), v = c.sheet.values.at("first.v");
    EXPECT_NEAR(c.answer[0]->value, m * v, 1e-9);  // e = 1, equal masses: j = m v
    EXPECT_NEAR(c.answer[4]->value, v, 1e-9);      // the last leaves at the first one's speed
}

}  // namespace
}  // namespace collide
