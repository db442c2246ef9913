// The Try-it panel's answer: a lesson (its file's text) with the panel's values, run once
// (engine/record.h) at the page's frame rate (present/frame_times.h, as the site's frames), as
// JSON: its states and events as `collide step --json` prints them, the collision the page
// shows (present/shown_collision.h, as `collide render` picks it) worked out (teach/
// event_problem.h, solve.h, html.h worked_html) as `collide material` and `collide solve
// --format json` show it, every [[figure]]'s collision, what the page needs to draw the bodies,
// the lesson's [[plot]]s of this run as `collide material` draws them (present/lesson_plots.h,
// site_plots.h) and the quantities a plot may take. The fields: docs/wasm.md, lesson().
// The WebAssembly module answers the panel with it (wasm/module.cpp lesson_answer), and
// `collide material` writes its answer for the lesson's own values into the page's data
// (try-it-lesson.js), so that the page shows it before the module has started.
#pragma once

#include <string>

namespace collide {

// `values`: a JSON object {"A.mass": 3, ...} (the [[vary]] inputs' names, lesson_with_inputs);
// `fps`: the page's frame rate (the states are sampled at 1/fps). The run has the work budget
// kWasmWorkBudget (engine/scene.h), beyond which it is refused (RunError). Throws InputError
// (without a file name: "LINE:COL: key: message") for a text or values it cannot take.
std::string try_it_answer_json(const std::string& text, const std::string& values, double fps);

}  // namespace collide
