// The teaching site's pages (`collide material`, docs/commands/material.md): a lesson's page
// and the index, as HTML (teach/html.h draws the pieces: worked examples, plots, the Try-it
// panel's markup), from what rendering each lesson made (present/render_job.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "present/render_job.h"
#include "scenario/lesson.h"
#include "teach/check_variant.h"

namespace collide {

// A lesson as its page shows it: the lesson, its render, and the sizes of its pictures.
struct SitePage {
    Lesson lesson;
    bool try_it = false;  // the site has collide-engine.js: the page gets its Try-it panel
    RenderReport report;
    bool thumb = false;
    std::vector<int> figure_widths;  // pixels, of report.figures' PNG files
    int variants_width = 0;          // of variants.png
    // "Check yourself"'s other numbers (teach/check_variant.h); none for a lesson without [[vary]].
    std::optional<CheckVariant> check;
    // The page's frame rate: its render's (frames per simulated second; 30 with fewer than two).
    double fps() const {
        return report.t.size() > 1 && report.t[1] > report.t[0] ? 1.0 / (report.t[1] - report.t[0]) : 30.0;
    }
};

// ID/index.html, the student's page: goals, the set-up, predictions, the figures, animation and
// plots ("Watch"), the predictions checked, the explanation, the worked example (folded until
// every question below it is answered), "Check yourself" and "What if" (answers folded until
// the student commits one); `prev` and `next` for the pager (null at the ends). Its print has
// no answers.
std::string lesson_page(const SitePage& page, const SitePage* prev, const SitePage* next);

// ID/teacher.html: the teacher's page of a lesson: level, prerequisites, time, misconceptions
// with the lesson's evidence, questions for the class, how to run it live (the lesson's [[vary]]
// inputs), the notes for the teacher, every answer and every worked example, unfolded.
std::string teacher_page(const SitePage& page);

// index.html: every lesson with its thumbnail, section and dimension, and its teacher's page.
std::string index_page(const std::vector<SitePage>& all);

// The figures' colours (render/style.h) for the Try-it panel's canvas, as CSS colours in JSON.
std::string palette_json();

}  // namespace collide
