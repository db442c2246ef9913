#include "fuzz/entry.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "scenario/input_error.h"
#include "teach/answers.h"
#include "scenario/scene_file.h"
#include "teach/solve.h"
#include "cli/step.h"

namespace collide::fuzz {

namespace {

constexpr const char* kName = "fuzz.toml";

template <int D>
void run(const Scene& scene) {
    typename Stepping<D>::World world(scene);
    std::vector<typename Stepping<D>::Event> events;
    const std::vector<double> times = output_times(scene);
    const std::size_t n = std::min(times.size(), kMaxOutputSteps + 1);
    for (std::size_t k = 0; k < n && events.size() <= kMaxEvents; ++k) {
        world.advance_to(times[k], &events);
        for (const auto& b : world.bodies())
            if (!b.state_finite())
                throw std::logic_error("a body's state is not finite at t = " +
                                       std::to_string(times[k]) + " s");
        // What `collide step --json` prints of it (formatting reads every field).
        (void)state_json(scene, times[k], world.bodies());
    }
    for (const auto& e : events) (void)event_json(scene, e);
}

}  // namespace

void scene(const std::string& text) {
    try {
        SceneView view;
        (void)parse_scene_text(text, kName, &view);
    } catch (const InputError&) {
    }
}

void solve(const std::string& text) {
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
