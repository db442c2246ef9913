// The lesson file format, the pieces that scenario/lesson_*.cpp share: each reads its own
// tables of the file and needs these from the others. Not for use outside scenario/.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scenario/lesson.h"
#include "scenario/toml_reader.h"

namespace collide::lesson_parse {

// `key` as a list of strings (none when the key is absent); fails naming `what` otherwise.
std::vector<std::string> strings(const TableReader& t, const std::string& key, const std::string& what);

// One [[question]] table, by its kind, checked against the lesson read so far (its scene,
// [penalty] and [[figure]] roles) (scenario/lesson_question.cpp).
LessonQuestion parse_question(const TableReader& q, const Lesson& L);

// [[vary]]: the ranges a worksheet draws each student's values from, checked against the
// tables of the file they change (scenario/lesson_values.cpp).
void parse_vary(const TableReader& root, const toml::table& file, Lesson& L);

// [[plot]]: the lesson's plots, checked against its scene and [[mark]] list
// (scenario/lesson_plot.cpp).
void parse_plots(const TableReader& root, Lesson& L);

// [teacher]: the teacher's page's content (scenario/lesson_teacher.cpp); none when absent.
std::optional<LessonTeacher> parse_teacher(const TableReader& root);

}  // namespace collide::lesson_parse
