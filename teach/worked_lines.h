// The worked example's steps with every line in both notations, text and LaTeX (notation::F):
// what write_text and worked_steps (text) and write_markdown (LaTeX) print. One step per
// stage of the page's method: given, kinematics, the response model's own steps (marked
// `response`), the final velocities, the restitution check, the checks.
#pragma once

#include <string>
#include <vector>

#include "teach/notation.h"
#include "teach/solve.h"

namespace collide {

struct WorkedLines {
    std::string name;                // "Impulse"
    std::string formula;             // "j = −(1 + e) u_n / D,  P = j n", or "" (a step without one)
    std::vector<notation::F> lines;  // the formula, then the numbers substituted
    std::vector<std::string> notes;  // prose after the lines
    bool response = false;           // a step of the response model itself
    std::string title() const;       // name, and the formula after two spaces
};

std::vector<WorkedLines> worked_lines(const SolveProblem& problem, const Solution& s);

}  // namespace collide
