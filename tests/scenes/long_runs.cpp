// The long runs of tests/scenes/long_runs.h.
#include "tests/scenes/long_runs.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/diagnostics.h"
#include "engine/world.h"
#include "tests/scenes/world_scenes.h"

namespace collide::long_runs {

Scene tumble_scene(bool walls) {
    Scene s = scenes::empty_scene(3);
    const double L = 2.0;
    if (walls) scenes::add_walls3(&s, L);
    const Quat q(Eigen::AngleAxisd(0.7, Vec3(1, 2, -0.5).normalized()));
    s.bodies.push_back(scenes::box("box", Vec3(0.05, 0.1, 0.2), 3.0, Vec3(1.0, 1.0, 1.0), q, Vec3(0.7, 0.4, -0.3),
                                   Vec3(3.0, -2.0, 5.0)));
    return s;
}

Scene scene_named(const std::string& name) {
    if (name == "tumble3d") return tumble_scene(true);
    if (name == "free3d") return tumble_scene(false);
    scenes::GasSpec g;
    g.n = 100;
    g.seed = 2024;
    if (name == "gas2d") return scenes::gas(2, g);
    if (name == "gas3d") return scenes::gas(3, g);
    throw std::invalid_argument("no long-run scene '" + name + "' (tumble3d, free3d, gas2d, gas3d)");
}

double default_dt(const std::string& name) { return name.rfind("gas", 0) == 0 ? 1e-3 : 1e-2; }

template <int D>
LongRun run(const std::string& name, const Scene& given, long steps, double dt) {
    // A long run is 10^3 to 10^4 times its scene's duration: its work is the run's own (each
    // sample moves every body), not a runaway scene's; the budget is the scene's per second.
    Scene scene = given;
    scene.work_budget *= std::max(1.0, static_cast<double>(steps) * dt / scene.duration);
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
            if (free)
                r.max_momentum_drift = std::max(r.max_momentum_drift, (tot.angular_momentum - L0).norm() / L0.norm());
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

LongRun run(const std::string& name, long steps, double dt) {
    const Scene scene = scene_named(name);
    if (dt <= 0) dt = default_dt(name);
    return scene.dimension == 2 ? run<2>(name, scene, steps, dt) : run<3>(name, scene, steps, dt);
}

template LongRun run<2>(const std::string&, const Scene&, long, double);
template LongRun run<3>(const std::string&, const Scene&, long, double);

}  // namespace collide::long_runs
