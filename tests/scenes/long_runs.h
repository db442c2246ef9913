// Long runs (robustness): a scene advanced in many equal output steps, watching every step for
// a non-finite state and measuring how far the conserved quantities wander. Shared by the test
// suite (tests/engine/long_run_test.cpp, 10^4 to 10^5 steps) and the timed command
// collide-long-run (bench/long_run.cpp, 10^6 steps, its figures in docs/tests.md).
//
// The scenes, all frictionless with e = 1 and no gravity, so the kinetic energy is conserved
// exactly by the physics and any change is the engine's error:
//   tumble3d: an asymmetric box (0.1 x 0.2 x 0.4 m, 3 kg) spinning about all three axes inside a
//             cube of static planes (2 m): torque-free turning with the gyroscopic term between
//             impacts of its corners with the walls;
//   free3d:   the same box with no walls: its world angular momentum is conserved too (vector);
//   gas2d, gas3d: 100 discs / spheres in a box of planes (tests/scenes/world_scenes.h).
#pragma once

#include <string>

#include "engine/scene.h"

namespace collide::long_runs {

struct LongRun {
    std::string scene;
    long steps = 0;
    double dt = 0.0;                  // s, each output step
    long events = 0;                  // impacts resolved
    bool finite = true;               // every body's state finite after every step
    double energy0 = 0.0;             // J
    double max_energy_drift = 0.0;    // max over the steps of |E - E0| / E0
    double final_energy_drift = 0.0;  // (E_end - E0) / E0
    double max_momentum_drift = -1;   // free3d only: max |L - L0| / |L0| (world, about the origin)
    double seconds = 0.0;             // wall time
};

// The box tumbling inside its cube of walls (tumble3d), or alone (free3d).
Scene tumble_scene(bool walls);
// The scene of a name: tumble3d, free3d, gas2d or gas3d (std::invalid_argument otherwise).
Scene scene_named(const std::string& name);

// The default output step of each scene: 0.01 s for the box (10^6 steps: 10^4 s), 0.001 s for
// the gases (10^6 steps: 1000 s, about 10^5 to 10^6 collisions).
double default_dt(const std::string& name);

// `steps` output steps of dt of the scene, watched and measured (D: the scene's dimension).
template <int D>
LongRun run(const std::string& name, const Scene& scene, long steps, double dt);
// The scene of a name, at its default step unless dt > 0.
LongRun run(const std::string& name, long steps, double dt = 0.0);

}  // namespace collide::long_runs
