// collide-long-run: the robustness long runs (tests/scenes/long_runs.h), timed, with their
// figures printed: 10^6 output steps of each scene by default. It measures and reports; the
// test suite asserts the bounds on shorter runs (tests/engine/long_run_test.cpp).
//
//   collide-long-run                       # every scene, 10^6 steps each
//   collide-long-run --steps 100000 gas3d  # one scene, fewer steps
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/scenes/long_runs.h"

int main(int argc, char** argv) {
    using namespace collide::long_runs;
    long steps = 1000000;
    std::vector<std::string> names;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "-h" || a == "--help") {
            std::printf(
                "Usage: collide-long-run [--steps N] [SCENE...]\n"
                "Advances each scene N output steps (default 1000000), checks every body is finite\n"
                "after every step and prints the energy drift (e = 1, frictionless: 0 exactly).\n"
                "Scenes: tumble3d (a box tumbling in a cube of walls, dt 0.01 s), free3d (the box\n"
                "alone: also its angular momentum), gas2d, gas3d (100 bodies, dt 0.001 s).\n");
            return 0;
        }
        if (a == "--steps" && i + 1 < argc) {
            char* end = nullptr;
            steps = std::strtol(argv[++i], &end, 10);
            if (*end != '\0' || steps <= 0) {
                std::fprintf(stderr, "collide-long-run: --steps: expected a whole number > 0, got '%s'\n", argv[i]);
                return 2;
            }
        } else if (!a.empty() && a[0] == '-') {
            std::fprintf(stderr, "collide-long-run: unknown option '%s' (see --help)\n", a.c_str());
            return 2;
        } else {
            names.push_back(a);
        }
    }
    if (names.empty()) names = {"tumble3d", "free3d", "gas2d", "gas3d"};
    std::printf("%-9s %9s %7s %9s %9s %6s %13s %13s %11s %8s\n", "scene", "steps", "dt (s)", "sim (s)", "impacts",
                "finite", "max |dE|/E0", "end dE/E0", "max |dL|/L0", "wall (s)");
    int status = 0;
    for (const std::string& name : names) {
        try {
            const LongRun r = run(name, steps);
            char L[32] = "-";
            if (r.max_momentum_drift >= 0) std::snprintf(L, sizeof L, "%.2e", r.max_momentum_drift);
            std::printf("%-9s %9ld %7g %9g %9ld %6s %13.2e %13.2e %11s %8.1f\n", r.scene.c_str(), r.steps, r.dt,
                        static_cast<double>(r.steps) * r.dt, r.events, r.finite ? "yes" : "NO", r.max_energy_drift,
                        r.final_energy_drift, L, r.seconds);
            std::fflush(stdout);
            if (!r.finite) status = 1;
        } catch (const std::invalid_argument& e) {  // an unknown scene
            std::fprintf(stderr, "collide-long-run: %s\n", e.what());
            return 2;
        } catch (const std::exception& e) {  // the engine gave up (it never hangs)
            std::fprintf(stderr, "collide-long-run: %s: %s\n", name.c_str(), e.what());
            status = 1;
        }
    }
    return status;
}
