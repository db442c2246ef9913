// The teaching site's pages (`collide material`, docs/commands/material.md): a lesson's page
// and the index, as HTML (teach/html.h draws the pieces: worked examples, plots, the Try-it
// panel's markup), from what rendering each lesson made (present/render_job.h).
#pragma once

#include <string>
#include <vector>

#include "present/render_job.h"
#include "scenario/lesson.h"

namespace collide {

// A lesson as its page shows it: the lesson, its render, and the sizes of its pictures.
struct SitePage {
    Lesson lesson;
    bool try_it = false;  // the site has collide-engine.js: the page gets its Try-it panel
    RenderReport report;
    bool thumb = false;
    std::vector<int> figure_widths;  // pixels, of report.figures' PNG files
    int variants_width = 0;          // of variants.png
};

// ID/index.html: goals, explanation, predictions, the figures, the animation, the worked
// example, plots, questions with answers; `prev` and `next` for the pager (null at the ends).
std::string lesson_page(const SitePage& page, const SitePage* prev, const SitePage* next);

// index.html: every lesson with its thumbnail, section and dimension.
std::string index_page(const std::vector<SitePage>& all);

// The figures' colours (render/style.h) for the Try-it panel's canvas, as CSS colours in JSON.
std::string palette_json();

}  // namespace collide
