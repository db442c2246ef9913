// Every bundled lesson is an experiment (docs/formats/lesson-files.md, "The lesson's inputs"):
// it declares [[vary]] inputs; a worksheet of five students draws five different sets of
// values from them; and the lesson still runs and answers every one of its questions at the
// ends of each range (each input at lo and at hi with the others at the lesson's values, and
// every corner: each input at lo or hi), its variants included. Whether the lesson's point still holds there
// is checked by reading these answers: COLLIDE_SHOW_ENDS=1 prints them
//   COLLIDE_SHOW_ENDS=1 build/tests/teach/collide_teach_tests --gtest_filter='LessonInputs.*Ends*'
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "engine/record.h"
#include "teach/answers.h"
#include "teach/html.h"
#include "teach/worksheet.h"

namespace collide {
namespace {

const std::string kDir = std::string(COLLIDE_SOURCE_DIR) + "/lessons";

const std::vector<Lesson>& bundled() {
    static const std::vector<Lesson> all = load_lessons(kDir);
    return all;
}

std::string describe(const std::map<std::string, double>& values) {
    std::ostringstream s;
    for (const auto& [k, v] : values) s << (s.tellp() > 0 ? ", " : "") << k << " = " << v;
    return values.empty() ? "the lesson's values" : s.str();
}

TEST(LessonInputs, EveryBundledLessonDeclaresItsInputs) {
    ASSERT_EQ(bundled().size(), 22u);
    for (const Lesson& L : bundled()) EXPECT_FALSE(L.vary.empty()) << L.file << " declares no [[vary]] inputs";
}

TEST(LessonInputs, FiveStudentsGetFiveDifferentSetsOfValues) {
    for (const Lesson& L : bundled()) {
        std::set<std::map<std::string, double>> distinct;
        for (int s = 1; s <= 5; ++s) {
            const StudentSheet sheet = draw_student(L, 1, s);  // the command's default seed
            EXPECT_EQ(sheet.values.size(), L.vary.size()) << L.id;
            distinct.insert(sheet.values);
        }
        EXPECT_EQ(distinct.size(), 5u) << L.id << ": two of five students have the same numbers";
    }
}

// The value sets a lesson is checked at: each input at its lo and hi alone (the others at the
// lesson's values), then every corner of the ranges (each input at lo or hi: 2^n sets).
std::vector<std::map<std::string, double>> ends(const Lesson& L) {
    std::vector<std::map<std::string, double>> out;
    for (const LessonVary& v : L.vary) {
        out.push_back({{v.name(), v.lo}});
        out.push_back({{v.name(), v.hi}});
    }
    const std::size_t n = L.vary.size();
    for (std::size_t corner = 0; corner < (std::size_t{1} << n); ++corner) {
        std::map<std::string, double> values;
        for (std::size_t k = 0; k < n; ++k) values[L.vary[k].name()] = (corner >> k) & 1 ? L.vary[k].hi : L.vary[k].lo;
        out.push_back(values);
    }
    return out;
}

TEST(LessonInputs, AtTheEndsOfEveryRangeTheLessonAnswersEveryQuestion) {
    const bool show = std::getenv("COLLIDE_SHOW_ENDS") != nullptr;
    for (const Lesson& L : bundled()) {
        ASSERT_LE(L.vary.size(), 6u) << L.id << ": the corners of more inputs would take long to run";
        if (show) std::cout << "\n=== " << L.id << "\n";
        for (const std::map<std::string, double>& values : ends(L)) {
            try {
                Lesson changed = lesson_with_inputs(L, values);
                changed.questions = L.questions;  // lesson_with_values leaves them out
                const std::vector<LessonAnswer> answers = answer_questions(changed);
                ASSERT_EQ(answers.size(), L.questions.size());
                if (show) {
                    std::cout << "  with " << describe(values) << ":\n";
                    for (std::size_t i = 0; i < answers.size(); ++i)
                        if (L.questions[i].has_quantity())
                            std::cout << "    " << i + 1 << ". " << L.questions[i].text.substr(0, 60) << " -> "
                                      << answers[i].text << "\n";
                }
                // Each variant runs too, and has its first collision (its panel shows it).
                for (const LessonVariant& variant : changed.variants) {
                    Lesson alone = changed;
                    alone.scene = variant.scene;
                    LessonQuestion lost;
                    lost.quantity = Quantity::energy_lost;
                    lost.text = "energy lost";
                    alone.questions = {lost};
                    const std::vector<LessonAnswer> a = answer_questions(alone);
                    if (show) std::cout << "    variant " << variant.label << ": energy lost " << a.at(0).text << "\n";
                }
            } catch (const std::exception& e) {
                ADD_FAILURE() << L.id << " with " << describe(values) << ": " << e.what();
            }
        }
    }
}

// An attribute's value in `html` after `from`: name="value".
std::string attribute(const std::string& html, std::size_t from, const std::string& name) {
    const std::size_t at = html.find(" " + name + "=\"", from);
    if (at == std::string::npos) return "";
    const std::size_t start = at + name.size() + 3;
    return html.substr(start, html.find('"', start) - start);
}

// A decimal as a browser reads a slider's attribute: digits scaled by 10^decimals (exact).
long long scaled(const std::string& decimal, int decimals) {
    const std::size_t dot = decimal.find('.');
    const std::string digits = dot == std::string::npos ? decimal : decimal.substr(0, dot) + decimal.substr(dot + 1);
    const int have = dot == std::string::npos ? 0 : static_cast<int>(decimal.size() - dot - 1);
    long long x = std::stoll(digits);
    for (int k = have; k < decimals; ++k) x *= 10;
    return x;
}
int decimals(const std::string& s) {
    const std::size_t dot = s.find('.');
    return dot == std::string::npos ? 0 : static_cast<int>(s.size() - dot - 1);
}

// Every input of every bundled lesson has its slider, whose max is on its decimal grid (a
// browser snaps a range input to min + k step computed in decimal: a step written as
// 0.10000000000000001 stopped [0, 1] at 0.9) and whose numbers read back as the lesson's.
TEST(LessonInputs, EveryInputHasASliderThatReachesItsMax) {
    for (const Lesson& L : bundled()) {
        const std::string html = html::try_it_html(L, 30, "../");
        EXPECT_EQ(html.find("tryit-novary"), std::string::npos) << L.id;
        EXPECT_NE(html.find("class=\"tryit-query\""), std::string::npos) << L.id;
        for (const LessonVary& v : L.vary) {
            const std::size_t at = html.find("data-name=\"" + html::escape(v.name()) + "\"");
            ASSERT_NE(at, std::string::npos) << L.id << ": no slider for " << v.name();
            const std::string lo = attribute(html, at, "min"), hi = attribute(html, at, "max"),
                              step = attribute(html, at, "step"), value = attribute(html, at, "value");
            EXPECT_EQ(std::stod(lo), v.lo) << L.id << " " << v.name();
            EXPECT_EQ(std::stod(hi), v.hi) << L.id << " " << v.name();
            EXPECT_EQ(std::stod(step), v.step) << L.id << " " << v.name();
            EXPECT_EQ(std::stod(value), v.lesson_value) << L.id << " " << v.name();
            const int d = std::max({decimals(lo), decimals(hi), decimals(step), decimals(value)});
            ASSERT_LE(d, 12) << L.id << " " << v.name() << ": " << lo << " " << hi << " " << step;
            const long long s = scaled(step, d);
            EXPECT_EQ((scaled(hi, d) - scaled(lo, d)) % s, 0)
                << L.id << " " << v.name() << ": max " << hi << " is not min + k step";
            EXPECT_EQ((scaled(value, d) - scaled(lo, d)) % s, 0) << L.id << " " << v.name();
        }
        std::size_t sliders = 0;
        for (std::size_t at = html.find("type=\"range\""); at != std::string::npos;
             at = html.find("type=\"range\"", at + 1))
            ++sliders;
        EXPECT_EQ(sliders, L.vary.size()) << L.id;
    }
}

// A user's lesson without [[vary]]: its panel says so on the page.
TEST(LessonInputs, APanelWithoutInputsSaysSo) {
    const Lesson L = parse_lesson_text(R"([lesson]
id = "mine"
title = "Mine"
[scene]
dimension = 1
duration = 1.0
[[body]]
name = "A"
shape = "block"
length = 0.3
mass = 1.0
position = -0.8
v = 1.0
[[body]]
name = "B"
shape = "block"
length = 0.3
mass = 1.0
)",
                                       "mine.toml", "mine.toml");
    const std::string html = html::try_it_html(L, 30, "../");
    EXPECT_NE(html.find("<p class=\"tryit-novary\">This lesson has no inputs to change"), std::string::npos) << html;
    EXPECT_EQ(html.find("type=\"range\""), std::string::npos);
}

}  // namespace
}  // namespace collide
