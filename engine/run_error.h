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

// What a RunError's message starts with: "FILE: " (Scene::file), or nothing.
inline std::string run_source(const std::string& file) { return file.empty() ? std::string() : file + ": "; }

// A number in a RunError's message: 6 significant figures (an estimate: fewer), as %g writes
// them (0.01, 2.5e+09).
inline std::string run_number(double x, int figures = 6) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", figures, x);
    return text;
}

// How long `units` of work take (engine/scene.h, Scene::work_budget: 0.1 to 1 us each), for a
// refusal's message: "1.2 s to 12 s", "2 min to 20 min", "3 h to 28 h", "12 days to 116 days".
inline std::string run_duration(double units) {
    const auto one = [](double s) {
        const auto shown = [](double v, const char* unit) {
            char text[48];
            std::snprintf(text, sizeof text, v >= 10 ? "%.0f %s" : "%.2g %s", v, unit);
            return std::string(text);
        };
        if (s < 120) return shown(s, "s");
        if (s < 7200) return shown(s / 60, "min");
        if (s < 172800) return shown(s / 3600, "h");
        return shown(s / 86400, "days");
    };
    return one(units * 1e-7) + " to " + one(units * 1e-6);
}

}  // namespace collide
