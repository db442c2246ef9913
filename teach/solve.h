// `collide solve`: one collision, every quantity of the worked example, and its three outputs
// (text worked example, Markdown with LaTeX, JSON). Formats: docs/commands/solve.md.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "scenario/solve_problem.h"
#include "engine/page.h"

namespace collide {

// Everything the worked example shows, embedded in 3D whatever the dimension
// (1D: along x; 2D: the xy plane, spins and 2D cross products along z).
struct Solution {
    int dim = 3;
    Vec3 n = Vec3::UnitX();
    // Contact kinematics before the impulse.
    Vec3 ra = Vec3::Zero(), rb = Vec3::Zero();    // lever arms p - x
    Vec3 vpa = Vec3::Zero(), vpb = Vec3::Zero();  // contact-point velocities
    Vec3 u = Vec3::Zero();                        // vpb - vpa
    double un = 0.0;
    // Frictionless denominator: 1/ma + 1/mb + rot_a + rot_b.
    double inv_ma = 0.0, inv_mb = 0.0, rot_a = 0.0, rot_b = 0.0;
    Mat3 inv_Ia = Mat3::Zero(), inv_Ib = Mat3::Zero();  // world; 2D: zz
    Mat3 Ia = Mat3::Zero(), Ib = Mat3::Zero();
    Mat3 K = Mat3::Zero();                 // collision matrix (2D: 2x2 block)
    Vec3 P_stick = Vec3::Zero();           // coulomb: sticking impulse
    Vec3 slip = Vec3::Zero();              // coulomb: sliding direction t
    double slide_denominator = 0.0;        // n . K (n - mu t)
    RouthDetail routh;                     // routh: its phases, impulses and works
    Combined3 combined;                    // stick: the combined body (xc relative to the contact point)
    double newton_euler_difference = 0.0;  // |6x6 result - direct result|, m/s and rad/s
    page::Listing3 listing;                // page-listing (1D: rotational parts zero)
    // The outcome.
    bool separating = false, sliding = false, painleve = false;
    bool approximate = false;  // routh: Response3::approximate (the JSON's "approximate", a line in the text)
    Vec3 P = Vec3::Zero(), couple = Vec3::Zero();
    Vec3 va = Vec3::Zero(), wa = Vec3::Zero(), vb = Vec3::Zero(), wb = Vec3::Zero();
    Vec3 u_after = Vec3::Zero();
    double un_after = 0.0;
    // Checks: totals of the dynamic bodies, before and after.
    Vec3 p_before = Vec3::Zero(), p_after = Vec3::Zero();
    Vec3 L_before = Vec3::Zero(), L_after = Vec3::Zero();    // about problem.about
    Vec3 Lp_before = Vec3::Zero(), Lp_after = Vec3::Zero();  // about the contact point
    double ke_before = 0.0, ke_after = 0.0;
};

Solution solve(const SolveProblem& problem);

// `s` (solve(problem)'s) with the outcome another solver gave the same two bodies: the
// impulse on b, the velocities just after, and the relative velocity and the checks
// (momentum, angular momentum, kinetic energy) recomputed from them. A world that resolved
// other contacts at the same instant gives another outcome than the two bodies alone; the
// site's "Before and after" shows the run's.
Solution with_outcome(const SolveProblem& problem, Solution s, const Vec3& P, const Vec3& va, const Vec3& wa,
                      const Vec3& vb, const Vec3& wb);

// The worked example as steps in the text notation (what `collide solve` prints): a title
// (a name, often with the formula), the formula as its own field (a figure's overlay shows it), lines (formula, then the numbers substituted), notes (prose).
// `response` marks the steps of the response model itself (denominator and impulse, the
// friction cone, ...), which a figure can show alone.
struct WorkedStep {
    std::string title;    // its name, then its formula after two spaces when it has one
    std::string formula;  // that formula alone ("j = ..."), or ""
    std::vector<std::string> lines;
    std::vector<std::string> notes;
    bool response = false;
};
std::vector<WorkedStep> worked_steps(const SolveProblem& problem, const Solution& s);

void write_text(const SolveProblem& problem, const Solution& s, std::ostream& out);
void write_markdown(const SolveProblem& problem, const Solution& s, std::ostream& out);
void write_json(const SolveProblem& problem, const Solution& s, std::ostream& out);

// The line the worked example adds when a model left the pair with more kinetic energy than
// it had (engine/diagnostics.h gains_energy): it names Kane's paradox and what avoids it.
std::string energy_gain_note(Model model);

// What an approximate routh answer (Solution::approximate) did instead of the integration:
// the JSON's "approximate" and a note of the text.
std::string routh_approximation(const Solution& s);

}  // namespace collide
