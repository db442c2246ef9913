// A lesson's answers and its Markdown (README.md, "Lessons"): each question answered from the
// lesson's run, a recording of its scene (engine/record.h), by the engine's own functions.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "engine/record.h"
#include "scenario/lesson.h"

namespace collide {

struct PenaltyStudy;

struct LessonAnswer {
    double value = 0.0;       // the number (a vector's: its length; see `vector`)
    Vec3 vector = Vec3::Zero();
    bool is_vector = false;   // 2D and 3D vectors and 3D spins
    std::string unit;         // "N s", "m/s", ...
    std::string text;         // "1.2 N s", "(0.9, 0.1) m/s"
};
// Answers every question from `run`, a recording of the lesson's scene whose last sample is
// at its duration (the run's end). Throws InputError (naming the question) when one asks for
// an event the run does not have or a body it lacks. `penalty`: the lesson's penalty study of
// this run (teach/lesson_penalty.h) when the caller has made it; else it is made here when a
// question asks for a penalty quantity.
std::vector<LessonAnswer> answer_questions(const Lesson& lesson, const AnyRecording& run,
                                          const PenaltyStudy* penalty = nullptr);
// The same from a run of the lesson's scene sampled at its end only.
std::vector<LessonAnswer> answer_questions(const Lesson& lesson);

// The lesson as Markdown: title, the page's section, goals, explanation, the questions with
// their answers (in <details>, opened on click), and a link to the worked example.
void write_lesson_markdown(const Lesson& lesson, const std::vector<LessonAnswer>& answers,
                           std::ostream& out);

}  // namespace collide
