// The teaching site (`collide material`, docs/commands/material.md): every lesson rendered
// (present/render_job.h) into DIR/ID/, its plots, its page and its Try-it data, then the index,
// the stylesheet and the WebAssembly module:
//   DIR/index.html             every lesson with a thumbnail, its section and dimension
//   DIR/style.css              one stylesheet, with print rules
//   DIR/ID/index.html          a lesson, the student's page (present/site_pages.h)
//   DIR/ID/teacher.html        its teacher's page
//   DIR/ID/...                 everything `collide render ID` writes (frames, data, Markdown),
//                              energy.svg and momentum.svg
//   DIR/collide-engine.js      the WebAssembly module, and the panels' scripts
//   DIR/try-it*.js             (assets/site/try-it.js and its parts), DIR/ID/try-it-lesson.js the
//                              lesson for them (teach/html.h try_it_data_js): only with a module
//   DIR/three.min.js           three.js, which draws the 3D lessons' panels (Debian's libjs-three):
//                              with a module, a 3D lesson and the file found (else those panels
//                              say that it is missing)
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "present/render_job.h"
#include "present/stop.h"
#include "scenario/lesson.h"

namespace collide {

struct SiteRequest {
    std::vector<Lesson> lessons;  // in the site's order
    RenderRequest render;         // how each lesson renders (its scenario and out_dir are set per lesson)
    std::string engine_js;        // collide-engine.js to copy in; "": pages without a Try-it panel
    std::string three_js;         // three.min.js to copy in beside it for the 3D lessons; "": none
    // Where a page lacks something asked for (a Try-it panel without the command's first
    // answer), a line each, "ID: what and why" (the command prints them on stderr); nullptr: none.
    std::ostream* notes = nullptr;
};

// One lesson done: the k-th (from 1) of `total`, and the seconds it took.
struct SiteProgress {
    std::size_t done = 0, total = 0;
    std::string id;
    double seconds = 0.0;
};

// Writes the site into `dir` (an empty directory: the command stages it, present/staged_dir.h).
// `progress` (if given) after each lesson; `stop` between frames, while ffmpeg runs, between
// lessons and once at the end (Interrupted: nothing asked after is lost). Throws
// InputError for a lesson that cannot be rendered as written, std::runtime_error otherwise.
void build_site(const SiteRequest& request, const std::filesystem::path& dir,
                const std::function<void(const SiteProgress&)>& progress = nullptr,
                const StopRequested& stop = nullptr);

}  // namespace collide
