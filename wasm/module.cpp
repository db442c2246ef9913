// collide-engine.js: the engine as WebAssembly (embind), for the site's lesson pages and Node.
// Each function calls what the command calls and returns what it prints, so the page and
// `collide` cannot disagree (the Python module, python/module.cpp, does the same):
//   solve_answer  collide solve --format json            (teach/solve.h write_json)
//   run_answer    collide step --json, --events --json   (teach/step_output.h step_json: one run)
//   lesson_answer a lesson page's Try-it panel: the lesson with the student's values, run once,
//                 and all the panel shows of it (present/try_it_answer.h, which `collide
//                 material` also calls for the page's first answer)
// Each returns {ok, text}: the JSON, or the reader's message without a file name
// ("LINE:COL: key: message"); api.js turns a refusal into a thrown Error. Each run has the
// work budget kWasmWorkBudget (engine/scene.h: a few seconds), beyond which it is refused with
// its estimate (engine/run_error.h) rather than freezing the page.
#include <exception>
#include <sstream>
#include <string>

#include <emscripten/bind.h>
#include <nlohmann/json.hpp>

#include "scenario/input_error.h"
#include "scenario/lesson.h"
#include "scenario/solve_problem.h"
#include "present/try_it_answer.h"
#include "teach/solve.h"
#include "teach/step_output.h"

namespace collide {
namespace {

struct Answer {
    bool ok = true;
    std::string text;
};

// The name the readers are given; messages leave it out (the text came from no file).
const char* const kTextName = "<text>";

// Runs f, turning a refusal into the message `collide` prints after its file name.
template <class F>
Answer answering(F f) {
    try {
        return {true, f()};
    } catch (const InputError& e) {
        return {false, InputError::format("", e.pos(), e.key(), e.message())};
    } catch (const std::exception& e) {
        return {false, e.what()};
    }
}

std::string join(const std::vector<std::string>& lines) {
    std::string s = "[";
    for (std::size_t k = 0; k < lines.size(); ++k) s += (k ? "," : "") + lines[k];
    return s + "]";
}

Answer solve_answer(const std::string& text) {
    return answering([&] {
        const SolveProblem problem = parse_solve_text(text, kTextName);
        std::ostringstream out;
        write_json(problem, solve(problem), out);
        return out.str();
    });
}

Answer run_answer(const std::string& text) {
    return answering([&] {
        Scene scene = parse_scenario_text(text, kTextName, "");
        scene.work_budget = kWasmWorkBudget;  // a page never waits long: refused beyond (RunError)
        scene.file.clear();                   // its refusals without a file name, as every other
        const StepJson run = step_json(scene);
        return "{\"states\":" + join(run.states) + ",\"events\":" + join(run.events) + "}";
    });
}

Answer lesson_answer(const std::string& text, const std::string& values, double fps) {
    return answering([&] { return try_it_answer_json(text, values, fps); });
}

}  // namespace
}  // namespace collide

EMSCRIPTEN_BINDINGS(collide_engine) {
    using namespace emscripten;
    value_object<collide::Answer>("Answer").field("ok", &collide::Answer::ok).field("text", &collide::Answer::text);
    function("solve_answer", &collide::solve_answer);
    function("run_answer", &collide::run_answer);
    function("lesson_answer", &collide::lesson_answer);
}
