// try_it/<lesson>: the Try-it panel's answer (present/try_it_answer.h) to a bundled lesson with
// its own values at the pages' 30 frames/s (try_it_move/<lesson>: with its first input moved to
// its lowest value, as after a slider move): the run, the collision worked out, the plots and the
// JSON, natively. The WebAssembly module computes the same at every slider move; the browser's
// figures are scripts/browser-speed.sh's (docs/wasm.md, "Speed"). Benchmarks measure; they
// assert nothing.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "present/try_it_answer.h"
#include "scenario/lesson.h"

namespace {

namespace fs = std::filesystem;

void answer(benchmark::State& state, const std::string& text, const std::string& values) {
    std::size_t bytes = 0;
    for (auto _ : state) {
        const std::string json = collide::try_it_answer_json(text, values, 30.0);
        bytes = json.size();
        benchmark::DoNotOptimize(json.data());
    }
    state.counters["json_bytes"] = static_cast<double>(bytes);
}

// One benchmark per lesson file, named by its file name without the number and ".toml".
const int registered = [] {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(fs::path(COLLIDE_SOURCE_DIR) / "lessons"))
        if (entry.path().extension() == ".toml") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
        std::ifstream in(file);
        std::ostringstream text;
        text << in.rdbuf();
        std::string name = file.stem().string();
        name = name.substr(name.find('-') + 1);  // "06-general-2d" -> "general-2d"
        benchmark::RegisterBenchmark(("try_it/" + name).c_str(), answer, text.str(), "{}")
            ->Unit(benchmark::kMillisecond);
        // A slider moved: the first input at its lowest value, as the panel sends it.
        const collide::Lesson lesson = collide::parse_lesson_text(text.str(), file.string(), file.string());
        if (!lesson.vary.empty()) {
            const collide::LessonVary& v = lesson.vary.front();
            std::ostringstream values;
            values.precision(17);
            values << "{\"" << v.name() << "\": " << v.lo << "}";
            benchmark::RegisterBenchmark(("try_it_move/" + name).c_str(), answer, text.str(), values.str())
                ->Unit(benchmark::kMillisecond);
        }
    }
    return static_cast<int>(files.size());
}();

}  // namespace
