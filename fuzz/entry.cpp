#include "fuzz/entry.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "engine/run_error.h"
#include "scenario/input_error.h"
#include "teach/answers.h"
#include "scenario/scene_file.h"
#include "scenario/toml_reader.h"
#include "teach/solve.h"
#include "teach/step_output.h"

namespace collide::fuzz {

namespace {

constexpr const char* kName = "fuzz.toml";

// Thrown by the impact hook once a run has had kMaxEvents impacts: one advance may hold many
// (a bounce series), so the count is checked at each impact, not between advances.
struct EventBudgetSpent {};
constexpr double kChunk = 0.01;  // s
constexpr std::chrono::milliseconds kMaxTime{500};

template <int D>
void run(const Scene& scene) {
    typename Stepping<D>::World world(scene);
    std::vector<typename Stepping<D>::Event> events;
    const std::vector<double> times = output_times(scene);
    const std::size_t n = std::min(times.size(), kMaxOutputSteps + 1);
    std::size_t impacts = 0;
    const auto budget = [&impacts](double) {
        if (++impacts > kMaxEvents) throw EventBudgetSpent{};
    };
    bool spent = false;
    std::size_t chunks = 0;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < n && !spent; ++k) {
        // In steps of at most kChunk, so that the substeps can be counted on the way (a long
        // output step of a resting scene is thousands of substeps).
        while (world.time() < times[k] && !spent) {
            try {
                world.advance_to(std::min(times[k], world.time() + kChunk), &events, budget);
            } catch (const EventBudgetSpent&) {
                spent = true;  // the events so far are still formatted below
            }
            spent = spent || ++chunks > kMaxSubsteps;  // (1D: no substeps; a long run of chunks)
            if constexpr (D > 1) spent = spent || world.counters().substeps > kMaxSubsteps;
            // Last, the clock: some work is neither substeps nor impacts (a fast spin turns in
            // 0.005 rad steps, a resting box's contacts are solved each substep) and costs
            // a hundred times more under the sanitizers and coverage than in a release build.
            spent = spent || std::chrono::steady_clock::now() - start > kMaxTime;
        }
        for (const auto& b : world.bodies())
            if (!b.state_finite())
                throw std::logic_error("a body's state is not finite at t = " + std::to_string(times[k]) + " s");
        // What `collide step --json` prints of it (formatting reads every field).
        (void)state_json(scene, times[k], world.bodies());
    }
    const std::vector<bool> gains = energy_gains(scene, events);
    for (std::size_t k = 0; k < events.size(); ++k) (void)event_json(scene, events[k], gains[k]);
}

// The bytes read as the commands read a file, stdin or a FIFO (read_bounded: in chunks,
// refused at a NUL byte or beyond 1 MiB): what it accepts must be the bytes themselves. The
// entry points parse the bytes whatever it says (the Python and WebAssembly modules hand the
// parsers text from memory).
void read_as_the_commands_do(const std::string& bytes) {
    std::istringstream in(bytes);
    try {
        if (read_bounded(in, kName) != bytes) throw std::logic_error("read_bounded changed the bytes it accepted");
    } catch (const InputError&) {
        if (bytes.size() <= kMaxInputBytes && bytes.find('\0') == std::string::npos)
            throw std::logic_error("read_bounded refused a text file under the limit");
    }
}

}  // namespace

void scene(const std::string& text) {
    read_as_the_commands_do(text);
    try {
        SceneView view;
        (void)parse_scene_text(text, kName, &view);
    } catch (const InputError&) {
    }
}

void solve(const std::string& text) {
    read_as_the_commands_do(text);
    SolveProblem problem;
    try {
        problem = parse_solve_text(text, kName);
    } catch (const InputError&) {
        return;
    }
    const Solution solution = collide::solve(problem);
    std::ostringstream out;
    write_text(problem, solution, out);
    write_markdown(problem, solution, out);
    write_json(problem, solution, out);
}

void lesson(const std::string& text) {
    read_as_the_commands_do(text);
    try {
        (void)parse_lesson_text(text, kName, kName);
    } catch (const InputError&) {
    }
}

void step(const std::string& text) {
    Scene s;
    try {
        s = parse_scene_text(text, kName);
    } catch (const InputError&) {
        return;
    }
    if (s.bodies.size() > kMaxBodies) return;
    try {
        if (s.dimension == 1) run<1>(s);
        else if (s.dimension == 2) run<2>(s);
        else run<3>(s);
    } catch (const InputError&) {
    } catch (const RunError&) {
        // The scene's own: beyond its work budget, or a state no longer finite (named, exit 2).
    } catch (const std::runtime_error& e) {
        // The world's documented refusals (step.h): a run it cannot continue.
        const std::string what = e.what();
        if (what.find("stuck") == std::string::npos && what.find("more than") == std::string::npos &&
            what.find("did not settle") == std::string::npos)
            throw;
    }
}

EntryPoint entry_point(const std::string& name) {
    if (name == "scene") return &scene;
    if (name == "solve") return &solve;
    if (name == "lesson") return &lesson;
    if (name == "step") return &step;
    return nullptr;
}

}  // namespace collide::fuzz
