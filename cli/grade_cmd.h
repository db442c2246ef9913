// `collide grade KEY.json ANSWERS.csv [-o REPORT] [--force]`: a class's answers marked against
// a worksheet's key (docs/commands/grade.md; teach/grade.h marks, present/grade_report.h
// writes). The tables go to stdout; with -o, REPORT/marks.csv and REPORT/report.html, built
// beside REPORT and renamed into place (present/staged_dir.h): complete or untouched. Every
// answer is read and marked before anything is written: a bad row leaves nothing.
#pragma once

#include <iosfwd>
#include <string>

namespace collide {

struct GradeOptions {
    std::string key;      // key.json of `collide worksheet`
    std::string answers;  // CSV: student,question,answer
    std::string out_dir;  // -o REPORT, or "" for the tables alone
    bool force = false;   // replace a REPORT that is not empty
};

// Returns the exit code: 0 done, 2 bad input (nothing written), 1 any other failure.
int run_grade(const GradeOptions& options, std::ostream& out, std::ostream& err);

}  // namespace collide
