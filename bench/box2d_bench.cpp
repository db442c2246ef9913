// box2d/...: the 2D scenes of world2d/... (tests/scenes/world_scenes.h, the same builders) run by
// Box2D 2.4.1 through collide compare's adapter (compare/box2d_world.h: the same masses,
// inertia, initial state, and collide's material rules with no restitution threshold), one
// second of simulated time per iteration, to set beside bench/world_bench.cpp:
//   box2d/gas/N          N = 100, 1000, 5000 discs (r = 0.05 m, 5% area, e = 1, no gravity) at
//                        Box2D's usual 60 Hz with 8 velocity and 3 position iterations;
//   box2d/gas-600hz/N    the same at 600 Hz, `collide compare`'s default step (a disc moves at
//                        most 2.5 mm per step: contacts found closer to the instant of impact);
//   box2d/pyramid20      210 boxes in 20 rows resting on the ground (Coulomb 0.6, e = 0), 60 Hz,
//                        Box2D's defaults otherwise: bodies at rest for 0.5 s fall asleep;
//   box2d/pyramid20-awake  the same with sleeping off (collide has no sleeping);
//   box2d/bin/N          N = 100, 400 boxes of random sizes (0.2 to 0.3 m) and angles dropped
//                        into a walled bin (scenes::bin, seed 2024: Coulomb 0.5, e = 0.2), at
//                        600 Hz, beside world2d/bin/N;
//   box2d-60hz/bin/100   the same 100 boxes at 60 Hz.
//   (The bins run their second in 60 frames, as world2d/bin/N: bench/settling.h.)
// Each iteration builds a fresh world with the timer paused. Counter "energy_drift":
// (E(1 s) - E(0)) / E(0), kinetic energy for the gas, kinetic plus potential for the pyramid;
// the bins instead "penetration_mm", "penetration_max_mm" and "resting_speed" (bench/settling.h,
// measured with collide's narrow phase on the poses Box2D ends with, as for collide's world).
// All count Box2D's "steps". Benchmarks measure; they assert nothing.
#include <optional>
#include <string>

#include <benchmark/benchmark.h>

#include "bench/settling.h"
#include "compare/box2d_world.h"
#include "tests/scenes/world_scenes.h"

namespace {

using namespace collide;

double energy(const std::vector<Body2>& bodies, const Scene& scene, bool potential) {
    double e = scenes::kinetic_energy(bodies);
    if (potential) e += scenes::potential_energy(bodies, scene.gravity);
    return e;
}

void simulate_one_second(benchmark::State& state, const Scene& scene, const compare::Box2DSettings& settings,
                         bool potential) {
    std::vector<Body2> start;
    for (const SceneBody& b : scene.bodies) start.push_back(b.body2);
    const double e0 = energy(start, scene, potential);
    std::optional<compare::Box2DWorld> world;
    bench::time_fresh_worlds(
        state, &world, [](compare::Box2DWorld& w) { w.advance_to(1.0, nullptr); }, scene, settings);
    if (world) {
        state.counters["steps"] = static_cast<double>(world->steps());
        state.counters["energy_drift"] = (energy(world->bodies(), scene, potential) - e0) / e0;
    }
}

compare::Box2DSettings at(double hz, bool sleep = true) {
    compare::Box2DSettings s;
    s.dt = 1.0 / hz;
    s.record_events = false;
    s.allow_sleep = sleep;
    return s;
}

// The same gas as world2d/gas/N (the same seed).
Scene gas_scene(int n) {
    scenes::GasSpec g;
    g.n = n;
    g.seed = 2024;
    return scenes::gas(2, g);
}

void gas60(benchmark::State& state) {
    simulate_one_second(state, gas_scene(static_cast<int>(state.range(0))), at(60.0), false);
}
void gas600(benchmark::State& state) {
    simulate_one_second(state, gas_scene(static_cast<int>(state.range(0))), at(600.0), false);
}
void pyramid20(benchmark::State& state) { simulate_one_second(state, scenes::pyramid({}), at(60.0), true); }
void pyramid20_awake(benchmark::State& state) {
    simulate_one_second(state, scenes::pyramid({}), at(60.0, false), true);
}

// The bin (the same seed as world2d/bin/N), through bench/settling.h.
void simulate_bin(benchmark::State& state, double hz) {
    scenes::BinSpec b;
    b.n = static_cast<int>(state.range(0));
    b.seed = 2024;
    bench::simulate_settling<compare::Box2DWorld>(state, scenes::bin(2, b), at(hz),
                                                  [](compare::Box2DWorld& w, double t) { w.advance_to(t, nullptr); });
}
void bin600(benchmark::State& state) { simulate_bin(state, 600.0); }
void bin60(benchmark::State& state) { simulate_bin(state, 60.0); }

[[maybe_unused]] const bool registered = [] {
    for (int n : {100, 1000, 5000}) {
        benchmark::RegisterBenchmark("box2d/gas", gas60)->Arg(n)->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark("box2d/gas-600hz", gas600)->Arg(n)->Unit(benchmark::kMillisecond);
    }
    benchmark::RegisterBenchmark("box2d/pyramid20", pyramid20)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("box2d/pyramid20-awake", pyramid20_awake)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("box2d/bin", bin600)->Arg(100)->Arg(400)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("box2d-60hz/bin", bin60)->Arg(100)->Unit(benchmark::kMillisecond);
    return true;
}();

}  // namespace
