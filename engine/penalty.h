// The penalty contact: "the numerical approach to collisions" the page ends with.
//
// Instead of an impulse at one instant, two blocks on a line (A on the left, B on the right,
// the normal +x from A into B as everywhere in Collide) are let overlap by delta > 0 (m) and
// pushed apart by a spring-damper in between (Kelvin-Voigt):
//     F = k delta + c delta'        (N; +F on B, -F on A)
// with stiffness k (N/m) and damping c (N s/m); delta' = v_A - v_B is the approach speed.
// With the effective mass m = 1 / (1/m_A + 1/m_B) (1/m = 0 for a static block) the overlap
// obeys  m delta'' + c delta' + k delta = 0,  delta(0) = 0, delta'(0) = v0 > 0:  a damped
// oscillator with  w0 = sqrt(k/m),  zeta = c / (2 sqrt(k m)),  wd = w0 sqrt(1 - zeta^2), and
// for zeta < 1
//     delta(t) = (v0 / wd) exp(-zeta w0 t) sin(wd t).
// The contact ends when the blocks let go of each other, and v_after = -e v0 with:
//   - the spring may pull (it ends when delta returns to 0, at wd t = pi):
//         e = exp(-zeta pi / sqrt(1 - zeta^2)),             t_c = pi / wd;
//   - no pull (a real contact only pushes: it ends when F = k delta + c delta' falls to 0,
//     while delta is still > 0; with zeta = sin(phi) that is at wd t = pi - 2 phi, where
//     delta' = -v0 exp(-zeta w0 t) exactly):
//         e = exp(-zeta (pi - 2 asin zeta) / sqrt(1 - zeta^2)),   t_c = (pi - 2 asin zeta) / wd.
// So e depends on zeta alone: the stiffness sets how long the contact lasts (t_c ~ 1/w0) and
// how deep it goes (v0 / w0 when undamped), not how much it bounces. Without pull, zeta -> 1
// gives e -> exp(-2) = 0.135: a smaller e needs an over-damped contact (zeta > 1). The damper
// also makes F jump to c v0 at the first touch, a known flaw of the linear model.
//
// penalty_collision() integrates the same contact numerically (classical Runge-Kutta, the end
// of contact found inside its step by bisection), as a game engine's penalty method would,
// but with steps small enough to agree with the closed forms: the tests compare them.
#pragma once

#include <vector>

namespace collide {

// m = 1 / (1/m_A + 1/m_B), from the inverse masses (0: static). kg.
double penalty_effective_mass(double inv_mass_a, double inv_mass_b);
// zeta = c / (2 sqrt(k m)), and back: c = 2 zeta sqrt(k m).
double penalty_damping_ratio(double m, double k, double c);
double penalty_damping(double m, double k, double zeta);
// The coefficient of restitution of the contact (zeta in [0, 1)), with or without pull.
double penalty_restitution(double zeta, bool pull);
// How long the contact lasts (s; zeta in [0, 1)), with or without pull.
double penalty_contact_time(double m, double k, double zeta, bool pull);
// The damping ratio that gives restitution e (in (0, 1]); pull: zeta = -ln e / sqrt(pi^2 +
// ln^2 e); no pull: solved by bisection, and e <= exp(-2) throws std::invalid_argument (it needs
// zeta >= 1).
double penalty_damping_ratio_for(double e, bool pull);

struct PenaltySetup {
    double inv_mass_a = 1.0, inv_mass_b = 1.0;  // 1/kg (0: static)
    double va = 1.0, vb = 0.0;                  // m/s along +x; va > vb (they approach)
    double stiffness = 1e4;                     // k, N/m
    double damping = 0.0;                       // c, N s/m
    bool pull = false;                          // may the spring pull the blocks together?
    double time_step = 0.0;                     // s; 0: pi sqrt(m/k) / 2000 (in [1e-5, 1] of it)
};

struct PenaltySample {
    double t = 0.0;        // s since the first touch
    double overlap = 0.0;  // delta, m
    double rate = 0.0;     // delta', m/s
    double force = 0.0;    // F on B, N
    double impulse = 0.0;  // integral of F dt so far, N s
};

struct PenaltyRun {
    std::vector<PenaltySample> samples;     // every step, from the first touch to the last
    bool separated = false;                 // false: still touching after 100 undamped contact times
    double contact_time = 0.0;              // s
    double impulse = 0.0;                   // N s on B over the contact
    double va_after = 0.0, vb_after = 0.0;  // m/s
    double restitution = 0.0;               // (vb_after - va_after) / (va - vb)
    double peak_force = 0.0;                // N
    double max_overlap = 0.0;               // m
    int steps = 0;
};

// Integrates the contact from the first touch (delta = 0) until the blocks let go. Throws
// std::invalid_argument for a non-finite or out-of-range setup (k <= 0, c < 0, both blocks
// static, no approach).
PenaltyRun penalty_collision(const PenaltySetup& setup);

}  // namespace collide
