// `collide worksheet LESSON... -o DIR [--students N] [--seed S] [--force]`: printable
// worksheets where every student has their own numbers (docs/commands/worksheet.md). For one
// lesson the files of present/worksheets.h in DIR; for several, in DIR/ID/ each, with
// DIR/index.html linking them. The same seed gives byte-identical HTML and JSON. Built beside
// DIR and renamed into place: DIR is complete or untouched.
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
    std::string format = "html";       // --format: html, moodle (DIR/moodle.xml), qti (DIR/qti.zip),
                                       // comma-separated
};

// The formats of --format, each once, in the order given ("html,moodle" -> {"html", "moodle"}).
// Throws InputError naming --format for an unknown or repeated one.
std::vector<std::string> worksheet_formats(const std::string& text);

// Returns the exit code: 0 done, 2 bad input (nothing written), 1 any other failure.
int run_worksheet(const WorksheetOptions& options, std::ostream& out, std::ostream& err);

}  // namespace collide
