// A run the engine cannot finish as its scene asks, because of what the scene asks: a body's
// state that is no longer finite (engine/world.h checks every body where its state is
// produced), or work beyond the scene's budget (engine/scene.h, RunBudget). Unlike a failure
// of the engine (std::runtime_error), it is the input's: the commands exit with code 2
// (cli/exit_code.h), the Python module raises ValueError, the WebAssembly module answers
// {ok: false}. The message names the instant and the body, or the estimate and the budget.
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>

namespace collide {

class RunError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A number in a RunError's message: 6 significant figures, as %g writes them (0.01, 2.5e+09).
inline std::string run_number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", x);
    return text;
}

}  // namespace collide
