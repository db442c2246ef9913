// bullet/...: the 3D contact-rich scenes of world3d/... (tests/scenes/world_scenes.h, the same
// builders) run by Bullet 3.24's btDiscreteDynamicsWorld through compare/bullet_world.h (the same
// masses, principal inertia, initial state, pair friction and restitution; no restitution
// threshold, as collide), at a fixed 600 Hz step, one second of simulated time per iteration in
// 60 frames (bench/settling.h), to set beside bench/world_bench.cpp:
//   bullet/bin/100   100 boxes of random sizes (0.2 to 0.3 m) and orientations dropped into a
//                    walled bin (scenes::bin, seed 2024: Coulomb 0.5, e = 0.2), beside
//                    world3d/bin/100;
//   bullet/tower/6   six 1 kg boxes stacked on the ground knocked over by a 2 kg ball thrown at
//                    4 m/s (scenes::tower3d: Coulomb 0.5, e = 0.3), beside world3d/tower/6.
// Built only when CMake finds Bullet (compare/CMakeLists.txt). Each iteration builds a fresh
// world with the timer paused. Counters: "steps", and "penetration_mm", "penetration_max_mm"
// and "resting_speed" (bench/settling.h: measured with collide's narrow phase on the poses
// Bullet ends with, as for collide's world). Benchmarks measure; they assert nothing.
#include <benchmark/benchmark.h>

#include "bench/settling.h"
#include "compare/bullet_world.h"
#include "tests/scenes/world_scenes.h"

namespace {

using namespace collide;

// Bullet's world at its default 600 Hz (compare::BulletSettings), through bench/settling.h.
void bullet_settling(benchmark::State& state, const Scene& scene) {
    bench::simulate_settling<compare::BulletWorld>(state, scene, compare::BulletSettings(),
                                                   [](compare::BulletWorld& w, double t) { w.advance_to(t); });
}

// The same seed as world3d/bin/N.
void bin(benchmark::State& state) {
    scenes::BinSpec b;
    b.n = static_cast<int>(state.range(0));
    b.seed = 2024;
    bullet_settling(state, scenes::bin(3, b));
}

void tower(benchmark::State& state) {
    scenes::TowerSpec t;
    t.levels = static_cast<int>(state.range(0));
    bullet_settling(state, scenes::tower3d(t));
}

[[maybe_unused]] const bool registered = [] {
    benchmark::RegisterBenchmark("bullet/bin", bin)->Arg(100)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("bullet/tower", tower)->Arg(6)->Unit(benchmark::kMillisecond);
    return true;
}();

}  // namespace
