// Printable worksheets where every student has their own numbers (`collide worksheet`,
// docs/commands/worksheet.md): one lesson's pages from its students' sheets (teach/worksheet.h
// draws and answers them).
//   sheets.html   one page per student: title, "Student K", name and class blanks, the givens
//                 with the student's numbers, the questions with a blank, unit and tolerance
//   key.html      the answer key: each student's values, answers and worked example
//   key.json      {"lesson": ID, "seed": S, "students": [{"student": 1, "values": {...},
//                 "answers": [{"question": 1, "quantity": .., "value": .., "unit": ..}]}]}
//   sheets.pdf, key.pdf   when weasyprint is given
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "present/stop.h"
#include "scenario/lesson.h"
#include "teach/worksheet.h"

namespace collide {

// One lesson's worksheets into `dir` (created); `weasyprint`: its path, or "" for no PDFs.
// `html` false (--format without html): key.json alone, the key `collide grade` reads.
// Returns the files written, for the summary. Throws std::runtime_error when a file cannot be
// written or weasyprint fails, and Interrupted when `stop` says so while weasyprint runs
// (weasyprint is ended first: render/video.h run_program).
std::vector<std::string> write_worksheets(const Lesson& lesson, const std::vector<StudentSheet>& sheets,
                                          std::uint64_t seed, const std::filesystem::path& dir,
                                          const std::string& weasyprint, const StopRequested& stop = nullptr,
                                          bool html = true);

// The givens of a student's lesson (lesson_with_inputs): a table of the bodies with their
// numbers, then e, mu and gravity (HTML). The sheets and Moodle's questions show it.
std::string worksheet_givens_html(const Lesson& lesson);

// DIR/index.html for several lessons: each lesson's sheets, key and key.json.
// `html` false: only the key.json of each.
void write_worksheet_index(const std::filesystem::path& dir, const std::vector<Lesson>& lessons, int students,
                           bool html = true);

// `text` into `path`; std::runtime_error naming it when it cannot be written.
void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace collide
