// try_it/<lesson>: the Try-it panel's answer (present/try_it_answer.h) to a bundled lesson with
// its own values at the pages' 30 frames/s: the run, the collision worked out, the plots and the
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

namespace {

namespace fs = std::filesystem;

void answer(benchmark::State& state, const std::string& text) {
    std::size_t bytes = 0;
    for (auto _ : state) {
        const std::string json = collide::try_it_answer_json(text, "{}", 30.0);
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
        benchmark::RegisterBenchmark(("try_it/" + name).c_str(), answer, text.str())->Unit(benchmark::kMillisecond);
    }
    return static_cast<int>(files.size());
}();

}  // namespace
