// What `collide grade` prints and writes (docs/commands/grade.md) from the marks of
// teach/grade.h: the tables per student and per question (stdout), REPORT/marks.csv and
// REPORT/report.html (per question: how many right, a histogram of the answers as multiples of
// each student's right value, the most common wrong answer and the slip it matches).
#pragma once

#include <string>
#include <vector>

#include "teach/grade.h"

namespace collide {

// One question over the class.
struct QuestionSummary {
    int question = 0;
    std::string words;  // question_words of the key's answer
    std::string quantity, unit;
    int students = 0, answered = 0, right = 0;
    // The most common wrong answer: the slip it matches ("the sign flipped"), else "" and the
    // answer as a multiple of the right value (ratio, 2 significant figures); count: how many.
    std::string common_slip;
    double common_ratio = 0.0;
    int common_count = 0;
    std::vector<double> ratios_right, ratios_wrong;  // got / want (vectors: along want), comparable answers
};

std::vector<QuestionSummary> summarize_questions(const std::vector<Mark>& marks);

// How the tables and the report name a question: its words as key.json gives them ("What impulse
// J does B receive?"), or the quantity ("impulse") from a key written before it gave them.
std::string question_words(const KeyAnswer& answer);

// The answer as a multiple of the right one: got / want, for a vector its projection on want
// over |want|^2 (the sign flipped: -1). NaN when want is 0 or the answer not comparable.
double answer_ratio(const Mark& mark);

// stdout: the questions in words, then per student the marks of each question and the total;
// per question right / answered and the most common wrong answer.
std::string grade_tables(const AnswerKey& key, const std::vector<Mark>& marks);
// marks.csv: student,question,quantity,answer,value,unit,right_value,mark,note,slip.
std::string marks_csv(const std::vector<Mark>& marks);
// report.html: self-contained (inline SVG).
std::string grade_report_html(const AnswerKey& key, const std::vector<Mark>& marks, const std::string& answers_name);

}  // namespace collide
