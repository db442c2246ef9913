#include "cli/worksheet_cmd.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <optional>

#include "cli/exit_code.h"
#include "cli/signals.h"
#include "cli/terminal.h"
#include "present/moodle_xml.h"
#include "present/qti_package.h"
#include "present/staged_dir.h"
#include "present/worksheets.h"
#include "render/video.h"
#include "scenario/input_error.h"
#include "teach/worksheet.h"

namespace collide {

namespace fs = std::filesystem;

namespace {

// The lessons of the command line, each a lesson (not a bare scenario), each id once.
std::vector<Lesson> load_worksheet_lessons(const std::vector<std::string>& args) {
    std::vector<Lesson> lessons;
    for (const std::string& arg : args) {
        std::optional<Lesson> lesson;
        load_scenario(arg, nullptr, &lesson);
        if (!lesson) throw InputError(arg, {}, "", "is a scenario, not a lesson (it has no [lesson] table)");
        for (const Lesson& other : lessons)
            if (other.id == lesson->id) throw InputError(arg, {}, "", "the lesson '" + lesson->id + "' is given twice");
        lessons.push_back(std::move(*lesson));
    }
    return lessons;
}

}  // namespace

std::vector<std::string> worksheet_formats(const std::string& text) {
    std::vector<std::string> out;
    std::size_t at = 0;
    while (true) {
        const std::size_t comma = text.find(',', at);
        const std::string f = text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
        if (f != "html" && f != "moodle" && f != "qti")
            throw InputError("", {}, "--format",
                             "unknown format '" + one_line(f) +
                                 "': expected html, moodle or qti, comma-separated (html,moodle,qti)");
        if (std::find(out.begin(), out.end(), f) != out.end())
            throw InputError("", {}, "--format", "'" + f + "' is given twice");
        out.push_back(f);
        if (comma == std::string::npos) break;
        at = comma + 1;
    }
    return out;
}

int run_worksheet(const WorksheetOptions& opt, std::ostream& out, std::ostream& err) {
    const auto start = std::chrono::steady_clock::now();
    // The staged directory is gone with the body's scope when it throws: DIR is untouched.
    // Ctrl-C (SIGINT, SIGTERM) is honoured between students and while weasyprint runs (it is
    // ended with the command): exit 130, DIR untouched, no DIR.tmp-PID left.
    return cli::run_staged_command(err, opt.out_dir, [&] {
        if (opt.lessons.empty()) throw InputError("", {}, "LESSON", "give at least one lesson id or lesson file");
        if (opt.out_dir.empty()) throw InputError("", {}, "-o", "the output directory is required");
        if (opt.students < 1 || opt.students > 1000)
            throw InputError("", {}, "--students", "expected 1 to 1000 students, got " + std::to_string(opt.students));
        const std::vector<std::string> formats = worksheet_formats(opt.format);
        const bool html = std::find(formats.begin(), formats.end(), "html") != formats.end();
        const bool moodle = std::find(formats.begin(), formats.end(), "moodle") != formats.end();
        const bool qti = std::find(formats.begin(), formats.end(), "qti") != formats.end();
        const std::vector<Lesson> lessons = load_worksheet_lessons(opt.lessons);
        const cli::SignalGuard signals;  // (held until the staging directory is removed again)
        StagedDirectory staged(opt.out_dir, opt.force);
        const bool terminal = cli::progress_watched(err);
        // Every student of every lesson is drawn and answered before anything is written: a
        // range that cannot be answered leaves no directory behind.
        std::vector<std::vector<StudentSheet>> all;
        for (std::size_t k = 0; k < lessons.size(); ++k) {
            const auto t0 = std::chrono::steady_clock::now();
            std::vector<StudentSheet> sheets;
            for (int s = 1; s <= opt.students; ++s) {
                if (cli::stop_requested()) throw Interrupted(0);
                sheets.push_back(draw_student(lessons[k], opt.seed, s));
            }
            all.push_back(std::move(sheets));
            if (terminal) {
                char line[200];
                std::snprintf(line, sizeof line, "[%zu/%zu] %-24s %d students %5.1f s\n", k + 1, lessons.size(),
                              lessons[k].id.c_str(), opt.students, cli::seconds_since(t0));
                err << line << std::flush;
            }
        }
        const std::string weasyprint = html ? render::find_program("weasyprint") : std::string();
        const fs::path& tmp = staged.begin();
        std::vector<std::string> files;
        if (lessons.size() == 1) {
            files = write_worksheets(lessons[0], all[0], opt.seed, tmp, weasyprint, cli::stop_requested, html);
        } else {
            for (std::size_t k = 0; k < lessons.size(); ++k)
                files = write_worksheets(lessons[k], all[k], opt.seed, tmp / lessons[k].id, weasyprint,
                                         cli::stop_requested, html);
            write_worksheet_index(tmp, lessons, opt.students, html);
        }
        // One file for every lesson: a category each (present/moodle_xml.h).
        if (moodle) write_text_file(tmp / "moodle.xml", moodle_xml(lessons, all, opt.seed));
        // And one IMS QTI 2.1 package (present/qti_package.h).
        if (qti) write_text_file(tmp / "qti.zip", qti_package(lessons, all, opt.seed));
        if (cli::stop_requested()) throw Interrupted(0);
        staged.commit();
        if (html && weasyprint.empty())
            err << "collide: note: PDFs skipped: weasyprint is not installed (Debian: apt-get install weasyprint); "
                   "print the HTML from a browser instead\n";
        std::string ids, list;
        for (const Lesson& L : lessons) ids += (ids.empty() ? "" : ", ") + L.id;
        for (const std::string& f : files) list += (list.empty() ? "" : ", ") + f;
        char secs[32];
        std::snprintf(secs, sizeof secs, "%.1f", cli::seconds_since(start));
        out << "wrote " << opt.students << " worksheets of " << ids << " to " << opt.out_dir
            << (lessons.size() > 1 ? "/ID" : "") << " (" << list << (lessons.size() > 1 ? "; index.html" : "")
            << (moodle ? "; moodle.xml" : "") << (qti ? "; qti.zip" : "") << ") in " << secs << " s\n";
        // Not an error (a sheet of the lesson's own numbers is still a sheet), but rarely meant:
        // said in the summary, where the teacher reads what was written.
        for (const Lesson& L : lessons)
            if (L.vary.empty())
                out << "note: " << L.id
                    << " has no [[vary]] ranges: every student's sheet has the lesson's own numbers\n";
        return 0;
    });
}

}  // namespace collide
