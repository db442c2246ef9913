// world2d/..., world3d/...: one second of simulated time per iteration in the event-driven
// worlds (engine/world.h), for N = 100, 1000, 10000 bodies.
//   gas/N:  discs / spheres (r = 0.05 m) at 5% area / volume fraction in a box of static planes,
//           e = 1, no gravity, random directions at 0.5 .. 1.5 m/s (fixed seed);
//   pile/N: discs / spheres dropped in columns of 5 (0.01 m gaps) onto a ground plane, columns
//           3 radii apart, e = 0.5, gravity -9.81 m/s^2;
//   world2d/gas/5000 and world2d/pyramid20 (20 rows of boxes at rest): beside Box2D's
//           (bench/box2d_bench.cpp).
// The scenes are built by tests/engine/world_scenes.h. Each iteration starts from a copy of the
// same prepared world (copied with the timer paused). Counters: "events" (collisions in the
// second) and "energy_drift" ((E(1 s) - E(0)) / E(0); kinetic for the gas, kinetic plus
// potential for the pile). Benchmarks measure; they assert nothing.
#include <optional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/world.h"
#include "tests/engine/world_scenes.h"

namespace {

using namespace collide;

template <int D>
double energy(const World<D>& w, bool potential) {
    double e = scenes::kinetic_energy(w.bodies());
    if (potential) e += scenes::potential_energy(w.bodies(), w.scene().gravity);
    return e;
}

template <int D>
void simulate_one_second(benchmark::State& state, const Scene& scene, bool potential) {
    const World<D> prepared(scene);
    const double e0 = energy(prepared, potential);
    std::optional<World<D>> world;
    std::vector<Event<D>> events;
    for (auto _ : state) {
        state.PauseTiming();
        world.emplace(prepared);  // the previous iteration's world is destroyed here, untimed
        events.clear();
        state.ResumeTiming();
        world->advance_to(1.0, &events);
        benchmark::DoNotOptimize(events.data());
    }
    if (world) {
        state.counters["events"] = static_cast<double>(events.size());
        state.counters["energy_drift"] = (energy(*world, potential) - e0) / e0;
    }
}

template <int D>
void gas(benchmark::State& state) {
    scenes::GasSpec g;
    g.n = static_cast<int>(state.range(0));
    g.seed = 2024;
    simulate_one_second<D>(state, scenes::gas(D, g), false);
}

template <int D>
void pile(benchmark::State& state) {
    scenes::PileSpec p;
    p.n = static_cast<int>(state.range(0));
    simulate_one_second<D>(state, scenes::pile(D, p), true);
}

// 20 rows of boxes (210) resting on the ground (tests/engine/world_scenes.h, as Box2D's
// pyramid benchmark), Coulomb friction 0.6, e = 0.
void pyramid20(benchmark::State& state) {
    simulate_one_second<2>(state, scenes::pyramid({}), true);
}

// Names "world2d/gas/100" etc.: the base name plus Google Benchmark's "/<arg>". The piles run
// one iteration each (most of their time is the columns' landing: about 113 collisions per
// body; once at rest the islands sleep and cost nothing).
[[maybe_unused]] const bool registered = [] {
    // 2D also at N = 5000, beside box2d/gas/N (bench/box2d_bench.cpp).
    for (int n : {100, 1000, 5000, 10000})
        benchmark::RegisterBenchmark("world2d/gas", gas<2>)->Arg(n)->Unit(benchmark::kMillisecond);
    for (int n : {100, 1000, 10000})
        benchmark::RegisterBenchmark("world3d/gas", gas<3>)->Arg(n)->Unit(benchmark::kMillisecond);
    // Beside box2d/pyramid20: one iteration (the pyramid settles in one island solve and sleeps).
    benchmark::RegisterBenchmark("world2d/pyramid20", pyramid20)
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
    for (const auto& [name, fn] :
         std::vector<std::pair<std::string, void (*)(benchmark::State&)>>{{"world2d/pile", pile<2>},
                                                                          {"world3d/pile", pile<3>}})
        benchmark::RegisterBenchmark(name.c_str(), fn)
            ->Arg(100)
            ->Arg(1000)
            ->Arg(10000)
            ->Iterations(1)
            ->Unit(benchmark::kMillisecond);
    return true;
}();

}  // namespace
