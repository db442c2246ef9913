// The module's JavaScript face (appended to collide-engine.js by --post-js): the C++ functions
// of module.cpp return {ok, text}; these return the text or throw an Error whose message is the
// reader's located message ("LINE:COL: key: message", no file name).
function collideAnswer(answer) {
  if (!answer.ok) throw new Error(answer.text);
  return answer.text;
}
// solve(text): a collision file (TOML) -> the JSON of `collide solve --format json`.
Module['solve'] = function (text) { return collideAnswer(Module['solve_answer'](String(text))); };
// run(text): a scenario or lesson file (TOML) -> the run record as JSON: {"states": [the lines
// of `collide step --json`], "events": [the lines of `collide step --events --json`]}.
Module['run'] = function (text) { return collideAnswer(Module['run_answer'](String(text))); };
// lesson(text, values, fps): a lesson file and the Try-it panel's values ({"A.mass": 3, ...},
// the names of its [[vary]] entries) -> the lesson run once with them, sampled at fps, as JSON:
// {dimension, duration, gravity, bodies, vary, values, worked: {t, a, b, html, solve, run} (the
// page's collision worked out; null without one), figures: [{t, a, b, solve, run}] (every
// [[figure]]'s collision; empty without figures), plots: [{file, title, svg, alt, data_html,
// summary, missing, series, line, ratio}] (the lesson's [[plot]]s of this run as the page draws
// them; docs/wasm.md), states, events}.
Module['lesson'] = function (text, values, fps) {
  return collideAnswer(Module['lesson_answer'](String(text), JSON.stringify(values || {}), Number(fps) || 30));
};
