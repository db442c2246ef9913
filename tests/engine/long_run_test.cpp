// Long runs (tests/scenes/long_runs.h) cut to 10^5 output steps for the box and 2 x 10^4 for
// the gases (a few seconds in all); collide-long-run runs 10^6 and docs/tests.md gives its figures.
// e = 1, frictionless, no gravity: the kinetic energy is exactly conserved by the physics, and
// so is the free box's world angular momentum. Bounds: 1e-9 relative, where round-off grows
// by about 1e-14 per impact and per 10^4 steps of torque-free turning (the implicit midpoint
// rule keeps both invariants of the rotation to round-off whatever the step).
#include "tests/scenes/long_runs.h"

#include <cstdio>

#include <gtest/gtest.h>

namespace collide {
namespace {

// Under the sanitizers (COLLIDE_SANITIZE) the engine runs tens of times slower: there the runs
// are cut tenfold, and so are the impact counts they must reach. Every step is still checked.
#ifdef COLLIDE_SANITIZED
constexpr long kCut = 10;
#else
constexpr long kCut = 1;
#endif

void report(const long_runs::LongRun& r) {
    char text[160];
    std::snprintf(text, sizeof text, "%ld steps, %ld impacts, max |dE|/E0 %.2e, max |dL|/L0 %.2e", r.steps, r.events,
                  r.max_energy_drift, r.max_momentum_drift);
    ::testing::Test::RecordProperty("drift", text);
}

TEST(LongRun, TumblingBoxInACubeOfWallsStaysFiniteAndKeepsItsEnergy) {
    const long_runs::LongRun r = long_runs::run("tumble3d", 100000 / kCut);
    report(r);
    EXPECT_TRUE(r.finite);
    EXPECT_GT(r.events, 500 / kCut);  // it did hit the walls, corners first, turning
    EXPECT_LT(r.max_energy_drift, 1e-9);
}

TEST(LongRun, FreeTumblingBoxKeepsEnergyAndAngularMomentum) {
    const long_runs::LongRun r = long_runs::run("free3d", 100000 / kCut);
    report(r);
    EXPECT_TRUE(r.finite);
    EXPECT_EQ(r.events, 0);
    EXPECT_LT(r.max_energy_drift, 1e-9);
    EXPECT_LT(r.max_momentum_drift, 1e-9);
}

TEST(LongRun, ElasticGasesStayFiniteAndKeepTheirEnergy) {
    for (const char* name : {"gas2d", "gas3d"}) {
        SCOPED_TRACE(name);
        const long_runs::LongRun r = long_runs::run(name, 20000 / kCut);
        report(r);
        EXPECT_TRUE(r.finite);
        EXPECT_GT(r.events, 2000 / kCut);
        EXPECT_LT(r.max_energy_drift, 1e-9);
    }
}

}  // namespace
}  // namespace collide
