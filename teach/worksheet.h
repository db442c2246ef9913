// Worksheets (`collide worksheet`, docs/commands/worksheet.md): each student gets the lesson's scene with their
// own values, drawn from its [[vary]] grids by a generator whose output is fixed by its
// definition (the same numbers from every compiler and standard library), and the engine
// answers each student's questions from a run of that scene.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "scenario/lesson.h"
#include "scenario/solve_problem.h"
#include "teach/answers.h"
#include "teach/solve.h"

namespace collide {

// How many draws a student gets before the lesson's ranges are refused.
constexpr int kWorksheetTries = 50;

// splitmix64 (Steele, Lea, Flood 2014): the next 64-bit number of the sequence, advancing
// `state`. Used instead of std::uniform_*_distribution, whose output differs between
// standard libraries, so that a seed gives the same sheets everywhere.
std::uint64_t splitmix64(std::uint64_t& state);

// The questions a worksheet asks, as indices into lesson.questions: the numeric ones without
// what_if (the engine answers them for each student's numbers), and the choice and explain
// questions whose text has no digit (they do not quote the lesson's own numbers). Predictions
// are left out: their answer is the lesson's, which a student's numbers may change.
std::vector<std::size_t> worksheet_questions(const Lesson& lesson);

// The number the lesson page gives question `index` (1-based): predictions are numbered on
// their own under "Before you watch", the other questions in file order under "Questions".
int question_number(const Lesson& lesson, std::size_t index);

// A collision a student's questions ask about, worked out (teach/solve.h).
struct WorkedCollision {
    int event = 1;             // which collision of the run, from 1
    std::size_t a = 0, b = 0;  // the scene's indices of problem.a and problem.b
    double t = 0.0;            // s, when it happens
    SolveProblem problem;      // the bodies as they are at it: the worksheet's figure draws them there
    Solution solution;
};

// One student's sheet: the values drawn, the lesson with them, the answers.
struct StudentSheet {
    int student = 1;                       // from 1
    std::map<std::string, double> values;  // every [[vary]] name ("A.mass") -> its value
    Lesson lesson;                         // lesson_with_inputs(lesson, values)
    std::vector<std::size_t> asked;        // worksheet_questions(lesson), into the original's questions
    std::vector<LessonAnswer> answers;     // one for each of `asked`
    std::vector<WorkedCollision> worked;   // the collisions the answers come from, in order
    int tries = 1;                         // draws needed (the earlier ones could not answer)
};

// Draws student `student`'s values (from the lesson's [[vary]] grids, with a generator seeded
// from `seed`, the lesson id and the student number), runs the scene once and answers the
// worksheet's questions. A draw whose run cannot answer (start overlap, no collision, fewer
// collisions than a question asks) is drawn again, up to kWorksheetTries times; then throws
// InputError naming the lesson file, the [[vary]] keys and the last values tried. A lesson
// without [[vary]] gives every student its own numbers.
StudentSheet draw_student(const Lesson& lesson, std::uint64_t seed, int student);

}  // namespace collide
