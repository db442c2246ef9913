// The penalty (spring-damper) contact (engine/penalty.h) against the damped oscillator's closed
// form, written out here independently:
//   delta(t) = (v0/wd) exp(-zeta w0 t) sin(wd t),  w0 = sqrt(k/m),  wd = w0 sqrt(1 - zeta^2),
//   m = ma mb / (ma + mb),  zeta = c / (2 sqrt(k m)).
// The integration (RK4, 2000 steps per contact) must agree with it to 1e-9 relative, and the
// contact must conserve momentum to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "engine/math.h"
#include "engine/penalty.h"

namespace {

using namespace collide;

constexpr double kRtol = 1e-9;  // RK4 with 2000 steps per contact: (pi/2000)^4 ~ 6e-12 per unit

struct Oscillator {
    double m, k, zeta, v0;
    double w0() const { return std::sqrt(k / m); }
    double wd() const { return w0() * std::sqrt(1 - zeta * zeta); }
    double delta(double t) const { return v0 / wd() * std::exp(-zeta * w0() * t) * std::sin(wd() * t); }
    double rate(double t) const {
        return v0 * std::exp(-zeta * w0() * t) * (std::cos(wd() * t) - zeta * w0() / wd() * std::sin(wd() * t));
    }
    double force(double t) const { return k * delta(t) + 2 * zeta * std::sqrt(k * m) * rate(t); }
};

PenaltySetup setup(double ma, double mb, double va, double vb, double k, double zeta, bool pull) {
    PenaltySetup s;
    s.inv_mass_a = ma > 0 ? 1 / ma : 0;
    s.inv_mass_b = mb > 0 ? 1 / mb : 0;
    s.va = va;
    s.vb = vb;
    s.stiffness = k;
    s.damping = penalty_damping(penalty_effective_mass(s.inv_mass_a, s.inv_mass_b), k, zeta);
    s.pull = pull;
    return s;
}

TEST(Penalty, UndampedSpringIsElasticAndLastsHalfAPeriod) {
    // m = 2 * 1 / 3 kg, v0 = 3 m/s, k = 1e4 N/m: t_c = pi sqrt(m/k), F_max = v0 sqrt(k m),
    // delta_max = v0 / w0, and e = 1 (the undamped spring gives all its energy back).
    const PenaltyRun r = penalty_collision(setup(2.0, 1.0, 2.0, -1.0, 1e4, 0.0, false));
    const double m = 2.0 / 3.0;
    ASSERT_TRUE(r.separated);
    EXPECT_NEAR(r.contact_time, kPi * std::sqrt(m / 1e4), kRtol * r.contact_time);
    EXPECT_NEAR(r.peak_force, 3.0 * std::sqrt(1e4 * m), 1e-6 * r.peak_force);  // sampled maximum
    EXPECT_NEAR(r.max_overlap, 3.0 / std::sqrt(1e4 / m), 1e-6 * r.max_overlap);
    EXPECT_NEAR(r.restitution, 1.0, kRtol);
    // The elastic 1D result: va' = ((ma - mb) va + 2 mb vb) / (ma + mb), vb' = (2 ma va + (mb - ma) vb) / (ma + mb).
    EXPECT_NEAR(r.va_after, (1.0 * 2.0 + 2 * 1.0 * -1.0) / 3.0, kRtol);
    EXPECT_NEAR(r.vb_after, (2 * 2.0 * 2.0 + (1.0 - 2.0) * -1.0) / 3.0, kRtol);
}

TEST(Penalty, SpringThatMayPullFollowsTheHalfPeriodOfTheDampedOscillator) {
    for (double zeta : {0.05, 0.2, 0.5, 0.8}) {
        SCOPED_TRACE(zeta);
        const PenaltyRun r = penalty_collision(setup(1.0, 3.0, 1.5, 0.0, 2e4, zeta, true));
        const Oscillator o{0.75, 2e4, zeta, 1.5};
        const double tc = kPi / o.wd();  // delta returns to 0
        ASSERT_TRUE(r.separated);
        EXPECT_NEAR(r.contact_time, tc, kRtol * tc);
        EXPECT_NEAR(r.restitution, std::exp(-zeta * kPi / std::sqrt(1 - zeta * zeta)), kRtol);
        EXPECT_NEAR(r.restitution, -o.rate(tc) / o.v0, kRtol);
        EXPECT_NEAR(penalty_restitution(zeta, true), -o.rate(tc) / o.v0, 1e-14);
        EXPECT_NEAR(penalty_contact_time(0.75, 2e4, zeta, true), tc, 1e-14 * tc);
        // It pulled: the force was negative at the end.
        EXPECT_LT(r.samples.back().force, 0.0);
        // Along the way, the samples follow delta(t).
        for (const PenaltySample& p : r.samples) EXPECT_NEAR(p.overlap, o.delta(p.t), 1e-9 * r.max_overlap);
    }
}

TEST(Penalty, ContactThatOnlyPushesEndsWhereTheForceFallsToZero) {
    for (double zeta : {0.05, 0.2, 0.5, 0.8, 0.95}) {
        SCOPED_TRACE(zeta);
        const PenaltyRun r = penalty_collision(setup(1.0, 3.0, 1.5, 0.0, 2e4, zeta, false));
        const Oscillator o{0.75, 2e4, zeta, 1.5};
        // The library's closed forms: at t_c the oscillator's force is zero and its rate is -e v0.
        const double tc = penalty_contact_time(0.75, 2e4, zeta, false);
        const double e = penalty_restitution(zeta, false);
        EXPECT_NEAR(o.force(tc), 0.0, 1e-10 * o.v0 * std::sqrt(o.k * o.m));
        EXPECT_GT(o.delta(tc), 0.0);  // let go while still overlapping
        EXPECT_NEAR(-o.rate(tc) / o.v0, e, 1e-12);
        // ... and the force was positive all the way before it (the first zero).
        for (int i = 1; i < 1000; ++i) EXPECT_GT(o.force(tc * i / 1000.0), 0.0);
        // The integration agrees.
        ASSERT_TRUE(r.separated);
        EXPECT_NEAR(r.contact_time, tc, kRtol * tc);
        EXPECT_NEAR(r.restitution, e, kRtol);
        // Letting go early keeps more of the bounce than a spring that may pull.
        EXPECT_GT(e, penalty_restitution(zeta, true));
        for (const PenaltySample& p : r.samples) EXPECT_GE(p.force, 0.0);
    }
}

TEST(Penalty, RestitutionDependsOnTheDampingRatioAloneNotTheStiffness) {
    const double e_soft = penalty_collision(setup(1.0, 1.0, 1.0, 0.0, 1e3, 0.3, false)).restitution;
    const double e_hard = penalty_collision(setup(1.0, 1.0, 1.0, 0.0, 1e7, 0.3, false)).restitution;
    const double e_fast = penalty_collision(setup(1.0, 1.0, 25.0, 0.0, 1e3, 0.3, false)).restitution;
    EXPECT_NEAR(e_soft, e_hard, kRtol);
    EXPECT_NEAR(e_soft, e_fast, kRtol);
    // The stiffer spring: the same bounce in a shorter contact, t_c ~ 1/sqrt(k).
    const double t_soft = penalty_collision(setup(1.0, 1.0, 1.0, 0.0, 1e3, 0.3, false)).contact_time;
    const double t_hard = penalty_collision(setup(1.0, 1.0, 1.0, 0.0, 1e7, 0.3, false)).contact_time;
    EXPECT_NEAR(t_soft / t_hard, 100.0, 100.0 * kRtol);
}

TEST(Penalty, ConservesMomentumAndLosesTheEnergyThatRestitutionSays) {
    const double ma = 2.0, mb = 0.5, va = 0.7, vb = -1.1;
    const PenaltyRun r = penalty_collision(setup(ma, mb, va, vb, 5e4, 0.35, false));
    EXPECT_NEAR(ma * r.va_after + mb * r.vb_after, ma * va + mb * vb, 1e-14 * (ma * std::abs(va) + mb * std::abs(vb)));
    // The kinetic energy of the relative motion, m v0^2 / 2, is kept in the fraction e^2.
    const double m = ma * mb / (ma + mb), v0 = va - vb, e = r.restitution;
    const double ke = 0.5 * ma * va * va + 0.5 * mb * vb * vb;
    const double ke_after = 0.5 * ma * r.va_after * r.va_after + 0.5 * mb * r.vb_after * r.vb_after;
    EXPECT_NEAR(ke - ke_after, 0.5 * m * v0 * v0 * (1 - e * e), 1e-12 * ke);
    // The impulse is the impulse model's with the same e: (1 + e) m v0.
    EXPECT_NEAR(r.impulse, (1 + e) * m * v0, 1e-12 * r.impulse);
}

TEST(Penalty, StaticWallUsesTheMovingBlocksMass) {
    // A 0.2 kg block into a static wall: m = 0.2 kg.
    const PenaltyRun r = penalty_collision(setup(0.2, 0.0, 4.0, 0.0, 8e3, 0.1, true));
    EXPECT_NEAR(r.contact_time, kPi / (std::sqrt(8e3 / 0.2) * std::sqrt(1 - 0.01)), kRtol * r.contact_time);
    EXPECT_NEAR(r.vb_after, 0.0, 0.0);
    EXPECT_NEAR(r.va_after, -std::exp(-0.1 * kPi / std::sqrt(0.99)) * 4.0, 4.0 * kRtol);
}

TEST(Penalty, DampingRatioForARestitutionInvertsTheClosedForms) {
    for (double e : {1.0, 0.9, 0.5, 0.2, 0.14}) {
        SCOPED_TRACE(e);
        EXPECT_NEAR(penalty_restitution(penalty_damping_ratio_for(e, true), true), e, 1e-13);
        EXPECT_NEAR(penalty_restitution(penalty_damping_ratio_for(e, false), false), e, 1e-12);
    }
    // The textbook value: e = 0.5 with pull needs zeta = ln 2 / sqrt(pi^2 + ln^2 2) = 0.2155.
    EXPECT_NEAR(penalty_damping_ratio_for(0.5, true),
                std::log(2.0) / std::sqrt(kPi * kPi + std::log(2.0) * std::log(2.0)), 1e-15);
    // Without pull an under-damped contact cannot go below exp(-2).
    EXPECT_THROW(penalty_damping_ratio_for(0.1, false), std::invalid_argument);
    EXPECT_NEAR(penalty_restitution(0.999999, false), std::exp(-2.0), 1e-2);
    EXPECT_NO_THROW(penalty_damping_ratio_for(0.1, true));
}

TEST(Penalty, OverDampedContactWithoutPullStillLetsGo) {
    // zeta = 1.5: no closed form here, but the push ends while the blocks still overlap, with
    // less bounce than exp(-2); a spring that may pull never lets go (the overlap decays for ever).
    const PenaltyRun push = penalty_collision(setup(1.0, 1.0, 1.0, 0.0, 1e4, 1.5, false));
    EXPECT_TRUE(push.separated);
    EXPECT_GT(push.restitution, 0.0);
    EXPECT_LT(push.restitution, std::exp(-2.0));
    const PenaltyRun pull = penalty_collision(setup(1.0, 1.0, 1.0, 0.0, 1e4, 1.5, true));
    EXPECT_FALSE(pull.separated);
    EXPECT_THROW(penalty_restitution(1.5, false), std::invalid_argument);
}

TEST(Penalty, RefusesWhatIsNotAContact) {
    PenaltySetup s;
    s.stiffness = 0.0;
    EXPECT_THROW(penalty_collision(s), std::invalid_argument);
    s = PenaltySetup{};
    s.damping = -1.0;
    EXPECT_THROW(penalty_collision(s), std::invalid_argument);
    s = PenaltySetup{};
    s.va = 0.0;  // not approaching
    EXPECT_THROW(penalty_collision(s), std::invalid_argument);
    s = PenaltySetup{};
    s.inv_mass_a = s.inv_mass_b = 0.0;
    EXPECT_THROW(penalty_collision(s), std::invalid_argument);
    s = PenaltySetup{};
    s.va = std::nan("");
    EXPECT_THROW(penalty_collision(s), std::invalid_argument);
    s = PenaltySetup{};
    s.time_step = 1.0;  // longer than the contact
    EXPECT_THROW(penalty_collision(s), std::invalid_argument);
    s = PenaltySetup{};  // m = 1/2 kg, k = 1e4 N/m: pi sqrt(m/k) = 0.0222 s
    s.time_step = 1e-9;  // 22 million steps a contact: refused, not run
    EXPECT_THROW(penalty_collision(s), std::invalid_argument);
}

}  // namespace
