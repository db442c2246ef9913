// The questions of a lesson's pages (present/site_pages.h): where each goes on the student's
// page, how it is asked and committed, and its answer, folded until the student commits one.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "scenario/lesson.h"
#include "teach/answers.h"
#include "teach/check_variant.h"

namespace collide::site {

// The script that marks a committed answer and opens it (and the worked example once every
// question of "Check yourself" has one); without scripts each opens with one click.
extern const char* kQuestionScript;

// Where a question goes on the student's page: a prediction before the figures, "Check
// yourself" after the worked example, "What if" last.
enum class Place { predict, check, what_if };
Place place_of(const LessonQuestion& q);

// A choice question's options as radio buttons to commit one (question `qi` of the page).
std::string choices_html(const LessonQuestion& q, std::size_t qi);
// The options, numbered, as printed.
std::string options_html(const LessonQuestion& q);
// The answer (and each option's reason), as its folded box shows it; `a` null: none computed.
// `own`: `a` is the answer with "Check yourself"'s other numbers (teach/check_variant.h), and
// `own` the lesson's, whose working the question's explanation gives.
std::string answer_html(const LessonQuestion& q, const LessonAnswer* a, const LessonAnswer* own = nullptr);
// The question as asked, with its tolerance.
std::string ask_html(const LessonQuestion& q);
// Room to write the answer, in print.
std::string write_space(const LessonQuestion& q);
// How the student commits an answer: the options, or a field and "Check".
std::string commit_html(const LessonQuestion& q, const LessonAnswer* a, bool prediction, int dim);
// The engine's answer and tolerance on a numeric question's element, for the marking script.
std::string marking_attributes(const LessonQuestion& q, const LessonAnswer* a, int dim);

// "Before you watch": the predictions (indices into L.questions), no answers.
std::string predict_html(const Lesson& L, const std::vector<LessonAnswer>& answers,
                         const std::vector<std::size_t>& predict);
// "Check your predictions": after the animation, each prediction's answer, folded.
std::string check_html(const Lesson& L, const std::vector<LessonAnswer>& answers,
                       const std::vector<std::size_t>& predict);
// Questions the student answers on the page, each with its answer folded below it. `check`:
// the numeric ones are asked with its values (their answers from it, the lesson's own beside).
std::string questions_html(const Lesson& L, const std::vector<LessonAnswer>& answers,
                           const std::vector<std::size_t>& asked, const CheckVariant* check = nullptr);

// "Check yourself"'s other numbers: the inputs that differ from the lesson's own, a link that
// sets them in the Try-it panel (`try_it`), and on the teacher's page (`teacher`) the questions
// whose answer no draw changed.
std::string new_numbers_html(const Lesson& L, const CheckVariant& c, bool try_it, bool teacher);

}  // namespace collide::site
