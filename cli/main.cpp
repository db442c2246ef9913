// The `collide` command.
#include <unistd.h>

#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "cli/compare_cmd.h"
#include "cli/input_error.h"
#include "cli/interactive.h"
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

int run_step(const std::string& file, const collide::StepOptions& options, bool interactive) {
    const collide::Scene scene = collide::parse_scene_file(file);
    if (interactive) {
        collide::run_interactive(scene, {options.json, isatty(0) != 0}, std::cin, std::cout,
                                 std::cerr);
        return 0;
    }
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
    CLI::Option* events = step->add_flag(
        "--events", step_options.events,
        "only the collision events: time, bodies, point, normal, impulse, velocities before and "
        "after");
    bool interactive = false, no_interactive = false;
    CLI::Option* interactive_flag = step->add_flag(
        "--interactive", interactive,
        "read commands from stdin (step, next, back, show, set, events, help, quit); the default "
        "when stdin and stdout are terminals and neither --json nor --events is given");
    step->add_flag("--no-interactive", no_interactive, "print the table even in a terminal")
        ->excludes(interactive_flag);
    interactive_flag->excludes(events);
    step->footer("Steps 1D, 2D and 3D scenes from impact to impact at the exact instants.\n"
                 "Scenario format and commands: see README.md, section 'Scenario files'.");

    collide::CompareOptions compare_options;
    CLI::App* compare = app.add_subcommand(
        "compare", "Run a 2D scenario through collide and through Box2D 2.4.1 and compare their "
                   "collisions");
    compare->add_option("FILE", compare_options.file, "scenario (TOML), 2D; - reads stdin")
        ->required();
    compare->add_flag("--json", compare_options.json,
                      "one JSON object: {\"events\": [{\"a\", \"b\", \"t\", \"collide\", "
                      "\"box2d\", \"difference\", \"reason\"}, ..]}, velocities after each event");
    compare->add_flag("--samples", compare_options.samples,
                      "also both trajectories side by side at the scene's output_dt");
    compare->add_flag("--box2d-defaults", compare_options.box2d_defaults,
                      "Box2D's own material rules: restitution threshold 1 m/s, e = max(ea, eb), "
                      "mu = sqrt(mua mub) (default: collide's rules, e = min(ea, eb), threshold 0, "
                      "set per contact)");
    compare->add_option("--dt", compare_options.dt, "Box2D's time step (s), > 0")
        ->capture_default_str();
    compare->add_option("--velocity-iterations", compare_options.velocity_iterations,
                        "Box2D's velocity iterations per step, >= 1")
        ->capture_default_str();
    compare->add_option("--position-iterations", compare_options.position_iterations,
                        "Box2D's position iterations per step, >= 0")
        ->capture_default_str();
    compare->footer(
        "Events are matched by their pair of bodies and their order for that pair. difference:\n"
        "the largest |v1 - v2| or R |w1 - w2| between the two engines' velocities after the\n"
        "event (R: the body's bounding radius, so a spin counts as its rim speed), divided by\n"
        "the pair's largest |v| or R |w| before or after in either engine; below 1e-4 they\n"
        "agree. Otherwise the reasons that apply: speed cap, model, two-point contact,\n"
        "restitution threshold, restitution mixing, step gravity, velocities before differ,\n"
        "normal off by N degrees, other contacts in the same step, friction; or no matching\n"
        "event.\n"
        "Example: collide compare lessons/scenes/compare-slow-bounce.toml --box2d-defaults\n"
        "See README.md, section 'collide compare'.");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : kBadInput;
    }
    try {
        if (*solve) return run_solve(file, format, model);
        if (*compare) return collide::run_compare(compare_options, std::cout, std::cerr);
        if (*step) {
            if (interactive && scene_file == "-") {
                std::cerr << "collide: error: --interactive reads its commands from stdin; give "
                             "the scenario as a file\n";
                return kBadInput;
            }
            // In a terminal `collide step FILE` starts the command loop; a run that asks for a
            // format, or writes into a pipe or a file, stays plain, so scripts never wait for
            // input.
            const bool loop = interactive ||
                              (!no_interactive && !step_options.json && !step_options.events &&
                               scene_file != "-" && isatty(0) && isatty(1));
            return run_step(scene_file, step_options, loop);
        }
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
