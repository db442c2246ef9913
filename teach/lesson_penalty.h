// A lesson's [penalty] table worked out (lesson 15, "the numerical approach"): the lesson's
// first collision (1D) again, with a penalty contact (engine/penalty.h) in place of the
// impulse. The spring is the table's stiffness k; its damping is matched to the pair's e (no
// pull), and each of the table's damping ratios is run too, with and without pull, beside
// the closed forms. Gravity is left out during the contact (it lasts milliseconds).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "engine/record.h"
#include "scenario/lesson.h"
#include "engine/penalty.h"

namespace collide {

struct PenaltyStudy {
    std::string a, b;                       // the two bodies (A on the left)
    double time = 0.0;                      // s, when they first touch
    double mass = 0.0;                      // m = 1 / (1/m_A + 1/m_B), kg
    double va = 0.0, vb = 0.0;              // just before, m/s
    double restitution = 0.0;               // the pair's e (the impulse model's)
    double impulse = 0.0;                   // the impulse model's P on B, N s
    double va_after = 0.0, vb_after = 0.0;  // and its velocities after, m/s
    double stiffness = 0.0;                 // k, N/m
    double zeta = 0.0, damping = 0.0;       // matched to e without pull
    PenaltyRun matched;                     // the penalty contact with them
    struct Row {
        double zeta = 0.0, damping = 0.0;
        double e_push = 0.0, e_pull = 0.0;  // the closed forms, without and with pull
        PenaltyRun push, pull;              // integrated
    };
    std::vector<Row> rows;  // the [penalty] damping ratios, in order
    struct Stiff {
        double stiffness = 0.0, damping = 0.0;  // the matched zeta: c = 2 zeta sqrt(k m)
        PenaltyRun run;                         // without pull
    };
    std::vector<Stiff> stiffer;  // the [penalty] stiffnesses (default k/4, k, 4k)
};

// The penalty contacts of the first collision of `run`, the lesson's recorded run. Throws
// InputError naming the lesson's file when it has no [penalty] table, the run no collision,
// or the collision an e the spring cannot match without pull (e <= exp(-2) = 0.135 needs an
// over-damped contact), or the contact cannot be integrated with its time step.
PenaltyStudy penalty_study(const Lesson& lesson, const AnyRecording& run);

// penalty.svg: the contact force against time (ms) for each damping ratio and the matched one.
std::string penalty_svg(const PenaltyStudy& s);
// penalty-overlap.svg: the overlap (mm) against time (ms), the same runs.
std::string penalty_overlap_svg(const PenaltyStudy& s);
// penalty.csv: every sample of every run (run: matched, damping or stiffness):
// run,k_N_per_m,zeta,pull,t_s,overlap_m,rate_m_per_s,force_N,impulse_N_s.
std::string penalty_csv(const PenaltyStudy& s);
// The matched contact and the table of damping ratios, as Markdown (lesson.md) and as HTML
// (the lesson's page of collide material).
void write_penalty_markdown(const PenaltyStudy& s, std::ostream& out);
std::string penalty_html(const PenaltyStudy& s);

}  // namespace collide
