// The contact-rich benchmarks (.../bin/N, .../tower/6 in world_bench.cpp, box2d_bench.cpp,
// bullet_bench.cpp): one simulated second run in 60 frames of 1/60 s, as a viewer shows it
// (collide's world is asked to stop at each frame, as `collide step` and `collide gui` ask it;
// Box2D's and Bullet's fixed steps are the same whether stopped or not), and counters measured
// alike for every engine: the poses and velocities are read back from the engine and judged by
// collide's own narrow phase (tests/scenes/world_scenes.h: deepest_overlap,
// fastest_surface_speed).
//   penetration_mm      the deepest overlap between any two bodies (or a body and a wall) at
//                       the end of the second, mm;
//   penetration_max_mm  the deepest overlap at the end of any of the 60 frames, mm, measured in
//                       one more run after the timed ones (untimed; the same frames, so the
//                       same run);
//   resting_speed       max over the bodies of |v| + |w| R at the end of the second, m/s (R the
//                       shape's bounding radius): zero when everything is still.
#pragma once

#include <algorithm>
#include <optional>

#include <benchmark/benchmark.h>

#include "engine/scene.h"
#include "tests/scenes/world_scenes.h"

namespace collide::bench {

constexpr int kFrames = 60;  // frames in the simulated second

// One simulated second: advance(t) moves the engine's world to t = k / kFrames, k = 1 .. kFrames.
template <class Advance>
void run_frames(Advance&& advance) {
    for (int k = 1; k <= kFrames; ++k) advance(k / double(kFrames));
}

// The deepest overlap (m) at the end of any frame of run_frames: `advance(t)` moves a fresh
// world of the engine to t and returns its bodies there.
template <class Advance>
double deepest_overlap_over_frames(const Scene& scene, Advance&& advance) {
    double deepest = 0.0;
    run_frames([&](double t) { deepest = std::max(deepest, scenes::deepest_overlap(scene, advance(t))); });
    return deepest;
}

// Sets penetration_mm and resting_speed from the bodies at the end of the second, and
// penetration_max_mm from deepest_overlap_over_frames (m).
template <class Bodies>
void settling_counters(benchmark::State& state, const Scene& scene, const Bodies& end, double deepest_over_frames) {
    state.counters["penetration_mm"] = 1e3 * scenes::deepest_overlap(scene, end);
    state.counters["penetration_max_mm"] = 1e3 * deepest_over_frames;
    state.counters["resting_speed"] = scenes::fastest_surface_speed(scene, end);
}

// Times `run(world)` on a fresh world each iteration: the world is built from `args` (and the
// previous one destroyed) with the timer paused, so only the run is measured. `world` is left
// holding the last iteration's world, for the counters.
template <class World, class Run, class... Args>
void time_fresh_worlds(benchmark::State& state, std::optional<World>* world, Run&& run, const Args&... args) {
    for (auto _ : state) {
        state.PauseTiming();
        world->reset();
        world->emplace(args...);
        state.ResumeTiming();
        run(**world);
        benchmark::ClobberMemory();
    }
}

// The settling benchmark of another engine's world (compare/): a fresh World(scene, settings)
// run through one second in 60 frames, timed; then "steps" and the settling counters from the
// last iteration's world and from one more, untimed run of the same frames. `advance(world, t)`
// moves a world to t (the fixed steps of Box2D and Bullet are the same as in one advance to 1 s).
template <class World, class Settings, class Advance>
void simulate_settling(benchmark::State& state, const Scene& scene, const Settings& settings, Advance&& advance) {
    std::optional<World> world;
    time_fresh_worlds(
        state, &world, [&](World& w) { run_frames([&](double t) { advance(w, t); }); }, scene, settings);
    if (!world) return;
    state.counters["steps"] = static_cast<double>(world->steps());
    World framed(scene, settings);
    const double deepest = deepest_overlap_over_frames(scene, [&](double t) {
        advance(framed, t);
        return framed.bodies();
    });
    settling_counters(state, scene, world->bodies(), deepest);
}

}  // namespace collide::bench
