// A lesson's answers and its Markdown (docs/formats/lesson-files.md, "Quantities"): each question answered from the
// lesson's run, a recording of its scene (engine/record.h), by the engine's own functions.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "engine/record.h"
#include "scenario/input_error.h"
#include "scenario/lesson.h"

namespace collide {

struct PenaltyStudy;

struct LessonAnswer {
    double value = 0.0;  // the number (a vector's: its length; see `vector`)
    Vec3 vector = Vec3::Zero();
    bool is_vector = false;  // 2D and 3D vectors and 3D spins
    std::string unit;        // "N s", "m/s", ...
    std::string text;        // "1.2 N s", "(0.9, 0.1) m/s"; without a quantity: "option 2"
                             // (choices) or the model answer (explain)
    bool computed = true;    // the engine's number (false: the lesson's written answer)
};
// An option's number in a list of choices: 0 -> "1", 1 -> "2", ... (numbers, not letters:
// "option B" would read as body B). Lists show it as "(1)", answers as "option 1".
std::string option_number(std::size_t index);
// Whether a question's answer is a measured number, marked within its tolerance (a count of
// collisions is exact: no tolerance is shown for it).
bool shows_tolerance(const LessonQuestion& q);
// A relative tolerance as a percentage for the student: 0.02 -> "2 %", 0.005 -> "0.5 %".
std::string tolerance_text(double tolerance);
// The marking rule of every face (the lesson page's script, `collide grade`, Moodle's absolute
// tolerance): an answer is right when it is within this of the engine's, |got - want| <=
// tolerance |want| + 1e-9 (for a vector, the length of the difference against |want|).
double marking_allowance(double want_size, double tolerance);
// The run's collision a question asks about, as an index into `events` (the run's, in time
// order): its `event`-th, or the first event of the `collision`-th instant at which its `pair`
// collides (either body first; as a [[figure]] counts them). Throws InputError naming the
// question (`where`, e.g. "question[3]") when the run has no such one.
template <class Event>
std::size_t question_event(const Lesson& L, const LessonQuestion& q, const std::string& where,
                           const std::vector<Event>& events) {
    if (!q.has_pair()) {
        if (static_cast<std::size_t>(q.event) > events.size())
            throw InputError(
                L.file, {}, where + ".event",
                "asks for collision " + std::to_string(q.event) + " but the run has " + std::to_string(events.size()));
        return static_cast<std::size_t>(q.event - 1);
    }
    int seen = 0;
    bool any = false;
    double last = 0.0;  // s: the latest instant of the pair
    for (std::size_t k = 0; k < events.size(); ++k) {
        const Event& e = events[k];
        if ((e.a != q.pair_a || e.b != q.pair_b) && (e.a != q.pair_b || e.b != q.pair_a)) continue;
        if (any && e.t == last) continue;  // more of the same instant
        any = true;
        last = e.t;
        if (++seen == q.collision) return k;
    }
    const std::string times = seen == 0   ? "never collide"
                              : seen == 1 ? "collide only once"
                                          : "collide only " + std::to_string(seen) + " times";
    throw InputError(L.file, {}, where + (q.collision > 1 ? ".collision" : ".pair"),
                     "asks for collision " + std::to_string(q.collision) + " of '" + q.pair[0] + "' and '" + q.pair[1] +
                         "', but they " + times + " in the run");
}

// Answers every question (one answer each, in order) from `run`, a recording of the lesson's
// scene whose last sample is
// at its duration (the run's end). Throws InputError (naming the question) when one asks for
// an event the run does not have or a body it lacks. `penalty`: the lesson's penalty study of
// this run (teach/lesson_penalty.h) when the caller has made it; else it is made here when a
// question asks for a penalty quantity. A question with `what_if` is answered from a run of
// lesson_with_values (its own scene); one without a quantity gets the lesson's written answer.
std::vector<LessonAnswer> answer_questions(const Lesson& lesson, const AnyRecording& run,
                                           const PenaltyStudy* penalty = nullptr);
// The same from a run of the lesson's scene sampled at its end only.
std::vector<LessonAnswer> answer_questions(const Lesson& lesson);

// The lesson as Markdown: title, the page's section, goals, the set-up, the predictions
// ("Before you watch", before the figure), the figure, the predictions checked, the
// explanation, the questions
// with their answers (in <details>, opened on click), and a link to the worked example.
void write_lesson_markdown(const Lesson& lesson, const std::vector<LessonAnswer>& answers, std::ostream& out);

}  // namespace collide
