// world2d/..., world3d/...: one second of simulated time per iteration in the event-driven
// worlds (engine/world.h):
//   gas/N:  N = 100, 1000, 10000 discs / spheres (r = 0.05 m) at 5% area / volume fraction in a
//           box of static planes, e = 1, no gravity, random directions at 0.5 .. 1.5 m/s (fixed
//           seed);
//   pile/N: N = 100, 1000, 10000 discs / spheres dropped in columns of 5 (0.01 m gaps) onto a
//           ground plane, columns 3 radii apart, e = 0.5, gravity -9.81 m/s^2;
//   world2d/gas/5000 and world2d/pyramid20 (20 rows of boxes at rest): beside Box2D's
//           (bench/box2d_bench.cpp);
//   bin/N:  boxes of random sizes (0.2 to 0.3 m) and angles (3D: orientations) dropped from a
//           grid into a walled bin, Coulomb 0.5, e = 0.2, simultaneous, gravity -9.81 m/s^2:
//           world2d/bin/100 and /400 beside box2d/bin/N (600 Hz) and box2d-60hz/bin/100,
//           world3d/bin/100 beside bullet/bin/100 (600 Hz);
//   world3d/tower/6: six 1 kg boxes stacked on the ground knocked over by a 2 kg ball thrown at
//           4 m/s, Coulomb 0.5, e = 0.3, beside bullet/tower/6.
// The scenes are built by tests/scenes/world_scenes.h (the peers use the same builders). Each
// iteration starts from a copy of the same prepared world (copied with the timer paused).
// Counters: "events" (collisions in the second); gas and pile "energy_drift"
// ((E(1 s) - E(0)) / E(0); kinetic for the gas, kinetic plus potential for the pile). Bin and
// tower run their second in 60 frames, as their peers do, and count "penetration_mm",
// "penetration_max_mm" and "resting_speed" (bench/settling.h: the same measures for every
// engine). Benchmarks measure; they assert nothing.
#include <optional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/settling.h"
#include "engine/world.h"
#include "tests/scenes/world_scenes.h"

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

// 20 rows of boxes (210) resting on the ground (tests/scenes/world_scenes.h, as Box2D's
// pyramid benchmark), Coulomb friction 0.6, e = 0.
void pyramid20(benchmark::State& state) { simulate_one_second<2>(state, scenes::pyramid({}), true); }

// One second of a contact-rich scene in 60 frames (bench/settling.h: where advance_to is asked
// to stop shapes its substeps, so the frames are part of what is timed), from a copy of the
// prepared world; then the settling counters from the last iteration's world and from one more,
// untimed run of the same frames.
template <int D>
void simulate_settling(benchmark::State& state, const Scene& scene) {
    const World<D> prepared(scene);
    std::optional<World<D>> world;
    std::vector<Event<D>> events;
    for (auto _ : state) {
        state.PauseTiming();
        world.emplace(prepared);
        events.clear();
        state.ResumeTiming();
        bench::run_frames([&](double t) { world->advance_to(t, &events); });
        benchmark::DoNotOptimize(events.data());
    }
    if (!world) return;
    state.counters["events"] = static_cast<double>(events.size());
    World<D> framed(prepared);
    const double deepest = bench::deepest_overlap_over_frames(scene, [&](double t) {
        framed.advance_to(t, nullptr);
        return framed.bodies();
    });
    bench::settling_counters(state, scene, world->bodies(), deepest);
}

// The bin's boxes: the same seed as box2d/bin/N and bullet/bin/N.
template <int D>
void bin(benchmark::State& state) {
    scenes::BinSpec b;
    b.n = static_cast<int>(state.range(0));
    b.seed = 2024;
    simulate_settling<D>(state, scenes::bin(D, b));
}

void tower(benchmark::State& state) {
    scenes::TowerSpec t;
    t.levels = static_cast<int>(state.range(0));
    simulate_settling<3>(state, scenes::tower3d(t));
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
    benchmark::RegisterBenchmark("world2d/pyramid20", pyramid20)->Iterations(1)->Unit(benchmark::kMillisecond);
    for (const auto& [name, fn] : std::vector<std::pair<std::string, void (*)(benchmark::State&)>>{
             {"world2d/pile", pile<2>}, {"world3d/pile", pile<3>}})
        benchmark::RegisterBenchmark(name.c_str(), fn)
            ->Arg(100)
            ->Arg(1000)
            ->Arg(10000)
            ->Iterations(1)
            ->Unit(benchmark::kMillisecond);
    // Beside box2d/bin/N and bullet/bin/100, bullet/tower/6.
    benchmark::RegisterBenchmark("world2d/bin", bin<2>)->Arg(100)->Arg(400)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("world3d/bin", bin<3>)->Arg(100)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("world3d/tower", tower)->Arg(6)->Unit(benchmark::kMillisecond);
    return true;
}();

}  // namespace
