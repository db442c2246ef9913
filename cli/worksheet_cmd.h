// `collide worksheet LESSON... -o DIR [--students N] [--seed S] [--force]`: printable
// worksheets where every student has their own numbers (docs/commands/worksheet.md).
// For one lesson, in DIR (for several, in DIR/ID/ each, with DIR/index.html linking them):
//   sheets.html   one page per student: title, "Student K", name and class blanks, the givens
//                 with the student's numbers, the questions with a blank, unit and tolerance
//   key.html      the answer key: each student's values, answers and worked example
//   key.json      {"lesson": ID, "seed": S, "students": [{"student": 1, "values": {...},
//                 "answers": [{"question": 1, "quantity": .., "value": .., "unit": ..}]}]}
//   sheets.pdf, key.pdf   when weasyprint is on $PATH
// The same seed gives byte-identical HTML and JSON. Built beside DIR and renamed into place:
// DIR is complete or untouched.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace collide {

struct WorksheetOptions {
    std::vector<std::string> lessons;  // lesson ids or files (at least one)
    std::string out_dir;               // -o DIR
    int students = 30;                 // --students N, 1 to 1000
    std::uint64_t seed = 1;            // --seed S
    bool force = false;                // replace a DIR that is not empty
};

// Returns the exit code: 0 done, 2 bad input (nothing written), 1 any other failure.
int run_worksheet(const WorksheetOptions& options, std::ostream& out, std::ostream& err);

}  // namespace collide
