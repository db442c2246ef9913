// "Check yourself" with other numbers (issue 33, "Ask before telling"): the lesson page's
// figures, animation and plots show the lesson's own run, so its numeric questions are asked of
// the same collision with other values from the lesson's [[vary]] ranges, drawn as a worksheet
// draws a student's (teach/worksheet.h), and chosen so that copying the watched run's number is
// marked wrong. The worked example of the lesson's run teaches the method; the student applies
// it to the new numbers and can check the run in the Try-it panel.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scenario/lesson.h"
#include "teach/answers.h"
#include "teach/worksheet.h"

namespace collide {

// The generator's seed for the check values (fixed: the page is the same on every build).
constexpr std::uint64_t kCheckSeed = 0x636865636bULL;  // "check"
// How many draws are tried for values whose every answer differs from the lesson's own.
constexpr int kCheckDraws = 8;

struct CheckVariant {
    StudentSheet sheet;  // the values, the lesson with them, the answers of worksheet_questions
    // Per question of the lesson (indexed as lesson.questions): the answer with the check
    // values, or none for a question asked of the lesson's own run (predictions, choices,
    // what-ifs).
    std::vector<std::optional<LessonAnswer>> answer;
    // The numeric questions whose answer is the lesson's own within its tolerance in every
    // draw tried (a count of collisions that no value in the ranges changes): their question
    // says so on the page.
    std::vector<std::size_t> same_as_watched;
};

// Whether the answer `copied` (the watched run's) would be marked right for `want` within
// `tolerance` (relative; 0: exactly), as the page's marking script marks a typed number.
bool marked_right(const LessonAnswer& copied, const LessonAnswer& want, double tolerance);

// The check values of `lesson` given `own`, the answers of its own run (answer_questions). Of
// the first kCheckDraws draws, the first whose every numeric answer differs from the lesson's
// own (marked_right false), else the one with the fewest equal. Throws InputError as
// draw_student does for the first draw (the lesson's ranges cannot answer); a later draw that
// cannot ends the search with the best so far. Callers ask only for a lesson with [[vary]] (without, every draw is the
// lesson's own values).
CheckVariant check_variant(const Lesson& lesson, const std::vector<LessonAnswer>& own);

}  // namespace collide
