// The `collide` command.
#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "cli/input_error.h"
#include "cli/scene_file.h"
#include "cli/solve.h"
#include "cli/step.h"

namespace {

constexpr int kBadInput = 2;

int run_solve(const std::string& file, const std::string& format, const std::string& model) {
    collide::SolveProblem problem = collide::parse_solve_file(file);
    if (!model.empty()) collide::parse_model(model, &problem.model);
    const collide::Solution solution = collide::solve(problem);
    // Write to memory first: on any failure nothing half-written reaches stdout.
    std::ostringstream out;
    if (format == "json") collide::write_json(problem, solution, out);
    else if (format == "markdown") collide::write_markdown(problem, solution, out);
    else collide::write_text(problem, solution, out);
    std::cout << out.str() << std::flush;
    return 0;
}

int run_step(const std::string& file, const collide::StepOptions& options) {
    const collide::Scene scene = collide::parse_scene_file(file);
    std::ostringstream out;
    collide::write_steps(scene, options, out);
    std::cout << out.str() << std::flush;
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"collide: an educational rigid-body collision simulator (1D, 2D, 3D).\n"
                 "Conventions: SI units; the contact normal n points from body A into body B;\n"
                 "the impulse P acts as +P on B and -P on A."};
    app.name("collide");
    app.set_version_flag("--version", std::string("collide ") + COLLIDE_VERSION);
    app.require_subcommand(1);

    std::string file, format = "text", model;
    CLI::App* solve = app.add_subcommand(
        "solve", "Solve one collision from a TOML file and show the worked example");
    solve->add_option("FILE", file, "collision description (TOML); - reads stdin")->required();
    solve->add_option("--format", format, "text (worked example), markdown (with LaTeX) or json")
        ->check(CLI::IsMember({"text", "markdown", "json"}))
        ->capture_default_str();
    solve->add_option("--model", model,
                      "use this response model instead of the file's: frictionless, coulomb, "
                      "matrix, stick or page-listing")
        ->check(CLI::IsMember({"frictionless", "coulomb", "matrix", "stick", "page-listing"}));
    solve->footer(
        "Example: collide solve lessons/solve/rod-on-ground.toml --format markdown\n"
        "File format: see README.md, section 'collide solve'.");

    if (argc == 1) {  // bare `collide`: show what it can do
        std::cout << app.help();
        return 0;
    }
    std::string scene_file;
    collide::StepOptions step_options;
    CLI::App* step = app.add_subcommand(
        "step", "Run a scenario file and print its state at every output step (or its events)");
    step->add_option("FILE", scene_file, "scenario (TOML); - reads stdin")->required();
    step->add_flag("--json", step_options.json, "one JSON object per line");
    step->add_flag("--events", step_options.events,
                   "only the collision events: time, bodies, point, normal, impulse, velocities "
                   "before and after");
    step->footer("Today 1D scenes step (exact impact times; Newton's cradle under both policies).\n"
                 "Scenario format: see README.md, section 'Scenario files'.");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : kBadInput;
    }
    try {
        if (*solve) return run_solve(file, format, model);
        if (*step) return run_step(scene_file, step_options);
    } catch (const collide::InputError& e) {
        std::cerr << "collide: error: " << e.what() << "\n";
        return kBadInput;
    } catch (const std::runtime_error& e) {
        std::cerr << "collide: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "collide: internal error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
