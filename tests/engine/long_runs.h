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
//   gas2d, gas3d: 100 discs / spheres in a box of planes (tests/engine/world_scenes.h).
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/diagnostics.h"
#include "engine/world.h"
#include "tests/engine/world_scenes.h"

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

inline Scene tumble_scene(bool walls) {
    Scene s = scenes::empty_scene(3);
    const double L = 2.0;
    if (walls) scenes::add_walls3(&s, L);
    const Quat q(Eigen::AngleAxisd(0.7, Vec3(1, 2, -0.5).normalized()));
    s.bodies.push_back(scenes::box("box", Vec3(0.05, 0.1, 0.2), 3.0, Vec3(1.0, 1.0, 1.0), q, Vec3(0.7, 0.4, -0.3),
                                   Vec3(3.0, -2.0, 5.0)));
    return s;
}

inline Scene scene_named(const std::string& name) {
    if (name == "tumble3d") return tumble_scene(true);
    if (name == "free3d") return tumble_scene(false);
    scenes::GasSpec g;
    g.n = 100;
    g.seed = 2024;
    if (name == "gas2d") return scenes::gas(2, g);
    if (name == "gas3d") return scenes::gas(3, g);
    throw std::invalid_argument("no long-run scene '" + name + "' (tumble3d, free3d, gas2d, gas3d)");
}

// The default output step of each scene: 0.01 s for the box (10^6 steps: 10^4 s), 0.001 s for
// the gases (10^6 steps: 1000 s, about 10^5 to 10^6 collisions).
inline double default_dt(const std::string& name) { return name.rfind("gas", 0) == 0 ? 1e-3 : 1e-2; }

template <int D>
LongRun run(const std::string& name, const Scene& scene, long steps, double dt) {
    LongRun r;
    r.scene = name;
    r.steps = steps;
    r.dt = dt;
    const auto t0 = std::chrono::steady_clock::now();
    World<D> world(scene);
    r.energy0 = totals(world.bodies()).kinetic_energy;
    Vec3 L0 = Vec3::Zero();
    if constexpr (D == 3) L0 = totals(world.bodies()).angular_momentum;
    const bool free = name == "free3d";
    if (free) r.max_momentum_drift = 0.0;
    std::vector<Event<D>> events;
    for (long i = 1; i <= steps; ++i) {
        events.clear();
        world.advance_to(static_cast<double>(i) * dt, &events);
        r.events += static_cast<long>(events.size());
        for (const auto& b : world.bodies())
            if (!b.state_finite()) r.finite = false;
        if (!r.finite) break;
        const auto tot = totals(world.bodies());
        const double drift = (tot.kinetic_energy - r.energy0) / r.energy0;
        r.max_energy_drift = std::max(r.max_energy_drift, std::abs(drift));
        r.final_energy_drift = drift;
        if constexpr (D == 3)
            if (free) r.max_momentum_drift = std::max(r.max_momentum_drift, (tot.angular_momentum - L0).norm() / L0.norm());
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

inline LongRun run(const std::string& name, long steps, double dt = 0.0) {
    const Scene scene = scene_named(name);
    if (dt <= 0) dt = default_dt(name);
    return scene.dimension == 2 ? run<2>(name, scene, steps, dt) : run<3>(name, scene, steps, dt);
}

}  // namespace collide::long_runs
