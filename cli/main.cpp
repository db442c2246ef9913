// The `collide` command.
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "cli/compare_cmd.h"
#include "cli/exit_code.h"
#include "cli/grade_cmd.h"
#include "cli/gui_cmd.h"
#include "scenario/input_error.h"
#include "cli/interactive.h"
#include "scenario/lesson.h"
#include "cli/material_cmd.h"
#include "cli/worksheet_cmd.h"
#include "cli/render_cmd.h"
#include "scenario/scene_file.h"
#include "teach/solve.h"
#include "teach/step_output.h"

namespace {

constexpr int kBadInput = collide::cli::kExitBadInput;

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
    const collide::Scene scene = collide::load_scenario(file);
    if (interactive) {
        collide::run_interactive(scene, {options.json, isatty(0) != 0}, std::cin, std::cout, std::cerr);
        return 0;
    }
    std::ostringstream out;
    collide::write_steps(scene, options, out);
    std::cout << out.str() << std::flush;
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "collide: an educational rigid-body collision simulator (1D, 2D, 3D).\n"
        "Conventions: SI units; the contact normal n points from body A into body B;\n"
        "the impulse P acts as +P on B and -P on A."};
    app.name("collide");
    app.set_version_flag("--version", std::string("collide ") + COLLIDE_VERSION);
    app.require_subcommand(1);

    std::string file, format = "text", model;
    CLI::App* solve = app.add_subcommand("solve", "Solve one collision from a TOML file and show the worked example");
    solve->add_option("FILE", file, "collision description (TOML); - reads stdin")->required();
    solve->add_option("--format", format, "text (worked example), markdown (with LaTeX) or json")
        ->check(CLI::IsMember({"text", "markdown", "json"}))
        ->capture_default_str();
    solve
        ->add_option("--model", model,
                     "use this response model instead of the file's: frictionless, coulomb, "
                     "matrix, stick, page-listing or routh (Stronge's law unless the file names one)")
        ->check(CLI::IsMember({"frictionless", "coulomb", "matrix", "stick", "page-listing", "routh"}));
    solve->footer(
        "Example: collide solve lessons/solve/rod-on-ground.toml --format markdown\n"
        "File format and output: docs/formats/collision-files.md, docs/commands/solve.md.");

    std::string scene_file;
    collide::StepOptions step_options;
    CLI::App* step =
        app.add_subcommand("step", "Run a scenario file and print its state at every output step (or its events)");
    step->add_option("FILE", scene_file, "scenario (TOML) or lesson id; - reads stdin")->required();
    step->add_flag("--json", step_options.json, "one JSON object per line");
    CLI::Option* events =
        step->add_flag("--events", step_options.events,
                       "only the collision events: time, bodies, point, normal, impulse, velocities before and "
                       "after");
    bool interactive = false, no_interactive = false;
    CLI::Option* interactive_flag =
        step->add_flag("--interactive", interactive,
                       "read commands from stdin (step, next, back, show, set, events, help, quit); the default "
                       "when stdin and stdout are terminals and neither --json nor --events is given");
    step->add_flag("--no-interactive", no_interactive, "print the table even in a terminal")
        ->excludes(interactive_flag);
    interactive_flag->excludes(events);
    step->footer(
        "Steps 1D, 2D and 3D scenes from impact to impact at the exact instants.\n"
        "Scenario format and commands: docs/formats/scenario-files.md, docs/commands/step.md.");

    collide::RenderOptions render_options;
    CLI::App* render =
        app.add_subcommand("render", "Render a scenario headless: PNG frames, the before / at / after figure, data");
    render
        ->add_option("SCENARIO", render_options.scenario,
                     "a scenario file (TOML), a lesson file, or a lesson id (collide lessons)")
        ->required();
    render->add_option("-o,--output", render_options.out_dir, "output directory (created)")->required();
    render->add_option("--size", render_options.size, "WxH, or 480p, 720p, 1080p, 1440p")->capture_default_str();
    render->add_option("--fps", render_options.fps, "frames per simulated second")->capture_default_str();
    // CLI11's IsMember checks below list the values in --help and refuse others in CLI11's own
    // words; they are handed the lists of collide::render_choices(), the names that the readers
    // of present/frame_spec.h read. parse_render_request (cli/render_options.h) is the one place
    // the options are turned into what the render does: run_render calls it.
    const collide::RenderChoices& choices = collide::render_choices();
    // An option taking one of `values` (its default in --help unless `shown_default` is false).
    const auto choice = [](CLI::App* cmd, const std::string& name, std::string& value, const std::string& help,
                           const std::vector<std::string>& values, bool shown_default = true) {
        CLI::Option* o = cmd->add_option(name, value, help)->check(CLI::IsMember(values));
        if (shown_default) o->capture_default_str();
    };
    choice(render, "--quality", render_options.quality,
           "low (no anti-aliasing), medium (anti-aliased, fast PNGs) or high (anti-aliased, smaller PNGs)",
           choices.quality);
    choice(render, "--view", render_options.view,
           "2d (textbook diagram) or 3d (shaded); default: 2d for 1D and 2D scenes, 3d for 3D", choices.view, false);
    choice(render, "--format", render_options.format,
           "png (the frames), or also DIR/animation.mp4 or DIR/animation.gif (needs ffmpeg)", choices.format);
    choice(render, "--backend", render_options.backend,
           "OpenGL context: osmesa, or egl (surfaceless; uses a GPU where one exists)", choices.backend);
    render->add_flag("--quiet", render_options.quiet, "no progress bar and no summary");
    render->add_flag("--force", render_options.force, "write into a directory that is not empty (replacing our files)");
    render->footer(
        "Writes DIR/frames/frame_00000.png ..., DIR/before.png, DIR/at.png, DIR/after.png,\n"
        "DIR/figure.png (the three side by side), DIR/worked-example.md, DIR/data.csv,\n"
        "DIR/data.json, DIR/events.csv, and DIR/animation.mp4 or .gif with --format; for a\n"
        "lesson also DIR/lesson.md, DIR/variants.png (its variants) and DIR/penalty.svg,\n"
        "DIR/penalty-overlap.svg, DIR/penalty.csv (its [penalty] contact).\n"
        "Every file is written under a temporary name and renamed when complete.\n"
        "Example: collide render lessons/scenes/billiards-2d.toml -o out/billiards\n"
        "See docs/commands/render.md.");

    bool lessons_json = false;
    CLI::App* lessons = app.add_subcommand("lessons", "List the bundled lessons: id, title, dimension, duration");
    lessons->add_flag("--json", lessons_json, "one JSON object per lesson, one per line");
    lessons->footer(
        "Render one: collide render ID -o DIR. Lessons live in lessons/*.toml (docs/formats/lesson-files.md).");

    collide::MaterialOptions material_options;
    CLI::App* material = app.add_subcommand("material", "Write a self-contained HTML site of lessons (works offline)");
    material->add_option("LESSON", material_options.lessons,
                         "lesson ids or lesson files (default: every bundled lesson)");
    material->add_option("-o,--output", material_options.out_dir, "output directory")->required();
    material->add_option("--size", material_options.size, "frame size: WxH, or 480p, 720p, 1080p, 1440p")
        ->capture_default_str();
    material->add_option("--fps", material_options.fps, "frames per simulated second")->capture_default_str();
    choice(material, "--quality", material_options.quality, "low, medium or high (as collide render)", choices.quality);
    material->add_flag("--quiet", material_options.quiet, "no progress and no summary");
    material->add_flag("--force", material_options.force, "replace a directory that is not empty");
    material->footer(
        "Writes DIR/index.html (every lesson with a thumbnail), DIR/ID/index.html per lesson\n"
        "(explanation, figure, animation, worked example, table, plots, questions with answers),\n"
        "DIR/style.css (with print rules) and, per lesson, what collide render writes. The site is\n"
        "built beside DIR and renamed into place when complete.\n"
        "Example: collide material -o out/site && chromium out/site/index.html\n"
        "See docs/commands/material.md.");
    collide::WorksheetOptions worksheet_options;
    CLI::App* worksheet =
        app.add_subcommand("worksheet", "Write printable worksheets: each student's own numbers, and an answer key");
    worksheet->add_option("LESSON", worksheet_options.lessons, "lesson ids or lesson files")->required();
    worksheet->add_option("-o,--output", worksheet_options.out_dir, "output directory")->required();
    worksheet->add_option("--students", worksheet_options.students, "how many sheets (1 to 1000)")
        ->capture_default_str();
    worksheet->add_option("--seed", worksheet_options.seed, "the draw: the same seed gives the same sheets")
        ->check([](const std::string& text) {  // not "-1" or 2^64 quietly made the largest seed
            errno = 0;
            char* end = nullptr;
            std::strtoull(text.c_str(), &end, 10);
            return !text.empty() && text.find_first_not_of("0123456789") == std::string::npos && errno != ERANGE
                       ? std::string()
                       : "expected a whole number from 0 to 18446744073709551615 (2^64 - 1), got '" + text + "'";
        })
        ->capture_default_str();
    worksheet->add_flag("--force", worksheet_options.force, "replace a directory that is not empty");
    worksheet
        ->add_option("--format", worksheet_options.format,
                     "what to write, comma-separated: html (sheets.html, key.html, PDFs), moodle (DIR/moodle.xml, "
                     "Moodle XML questions), qti (DIR/qti.zip, an IMS QTI 2.1 package); key.json always")
        ->capture_default_str();
    worksheet->footer(
        "Each student's values are drawn from the lesson's [[vary]] ranges and the engine answers\n"
        "each sheet. Writes, in DIR (for several lessons in DIR/ID/, with DIR/index.html):\n"
        "sheets.html (one page per student: givens, questions, blanks), key.html (every student's\n"
        "values, answers and worked example), key.json (for scripts) and, when weasyprint is\n"
        "installed, sheets.pdf and key.pdf; with --format moodle also DIR/moodle.xml (a question\n"
        "category per lesson question, a variant per student), with --format qti DIR/qti.zip (an\n"
        "IMS QTI 2.1 package: an item per question and student). Built beside DIR and renamed into\n"
        "place when complete. Mark the answers with collide grade DIR/key.json ANSWERS.csv.\n"
        "Example: collide worksheet catch-up -o out/ws --students 30 --seed 7\n"
        "See docs/commands/worksheet.md.");
    collide::GradeOptions grade_options;
    CLI::App* grade =
        app.add_subcommand("grade", "Mark a class's answers (CSV) against a worksheet's key.json; write a report");
    grade->add_option("KEY", grade_options.key, "the key.json collide worksheet wrote")->required();
    grade->add_option("ANSWERS", grade_options.answers, "CSV (RFC 4180) of student,question,answer")->required();
    grade->add_option("-o,--output", grade_options.out_dir, "also write REPORT/marks.csv and REPORT/report.html");
    grade->add_flag("--force", grade_options.force, "replace a REPORT directory that is not empty");
    grade->footer(
        "Each answer (a number or (x, y) vector, with or without its unit, a decimal point or a\n"
        "decimal comma in double quotes) is marked right when within the question's tolerance of\n"
        "the engine's answer, after its unit is converted (km/h, kJ, rpm, ...). Prints a table per\n"
        "student and per question; wrong answers are compared with likely slips (the sign\n"
        "flipped, the impulse without (1 + e), ...). A bad row: exit 2 naming file, line, field.\n"
        "Example: collide grade out/ws/key.json answers.csv -o out/marks\n"
        "See docs/commands/grade.md.");
    collide::GuiOptions gui_options;
    CLI::App* gui =
        app.add_subcommand("gui", "Open a window: the scene's frame with controls to change it, play it and step it");
    gui->add_option("SCENARIO", gui_options.scenario, "a lesson id, a lesson file or a scenario file")
        ->capture_default_str();
    gui->add_option("--size", gui_options.size, "the frame: WxH, or 480p, 720p, 1080p, 1440p")->capture_default_str();
    gui->add_option("--fps", gui_options.fps, "frames per simulated second (as collide render)")->capture_default_str();
    choice(gui, "--view", gui_options.view, "2d or 3d (default: 2d for 1D and 2D scenes, 3d for 3D)", choices.view,
           false);
    gui->add_option("--script", gui_options.script,
                    "run the actions of FILE, one a window frame (tests, demonstrations)");
    gui->add_option("-o,--output", gui_options.out_dir, "where Save frame and Save figure write")
        ->capture_default_str();
    gui->footer(
        "The frame is the one collide render draws at the playback time. Every change re-runs\n"
        "the scene from t = 0. Keys: Space play / pause, Right / Left one frame, N next collision,\n"
        "Home the start, S slower, R reset, F save the frame, G save the figure, H help, Q quit;\n"
        "in the 3D view drag over the frame to turn the camera and use the wheel to zoom.\n"
        "A script holds one action a line ('#' comments):\n"
        "  set e X | set mu X | set model NAME | set policy NAME | set BODY mass X | set BODY size K\n"
        "  set BODY v X [Y [Z]] | set BODY w W (2D) | set BODY w X Y Z (3D)\n"
        "  play | pause | step [N] | back [N] | next-collision | time T | slow SPEED | reset\n"
        "  toggle velocities|impacts|trails|labels|com|directions|header|table|plots|timeline\n"
        "  screenshot FILE.png | save-frame FILE.png | save-figure FILE.png | wait [N] | quit\n"
        "  orbit RIGHT UP (degrees) | zoom FACTOR (the 3D view's camera) | open LESSON|FILE\n"
        "Needs a display; without one: xvfb-run collide gui ... (Debian's xvfb).\n"
        "Example: collide gui rotation-directions --size 720p\n"
        "See docs/commands/gui.md.");
    collide::CompareOptions compare_options;
    CLI::App* compare =
        app.add_subcommand("compare",
                           "Run a 2D scenario through collide and through Box2D 2.4.1 and compare their "
                           "collisions");
    compare->add_option("FILE", compare_options.file, "a 2D scenario (TOML), lesson file or lesson id; - reads stdin")
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
    compare->add_option("--dt", compare_options.dt, "Box2D's time step (s), > 0")->capture_default_str();
    compare
        ->add_option("--velocity-iterations", compare_options.velocity_iterations,
                     "Box2D's velocity iterations per step, >= 1")
        ->capture_default_str();
    compare
        ->add_option("--position-iterations", compare_options.position_iterations,
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
        "See docs/commands/compare.md.");

    // Every command that runs a scene: the work a run may take before it is refused (exit 2).
    double max_work = collide::kDefaultWorkBudget;
    for (CLI::App* c : {step, render, gui, material, worksheet, compare})
        c->add_option("--max-work", max_work,
                      "the work a run may take before it is refused, in units of about a microsecond "
                      "(docs/stepping.md, \"Work budget\")")
            ->check([](const std::string& text) {
                char* end = nullptr;
                const double x = std::strtod(text.c_str(), &end);
                return *end == '\0' && x > 0.0 && std::isfinite(x) ? std::string()
                                                                   : "expected a number > 0, got '" + text + "'";
            })
            ->capture_default_str();

    if (argc == 1) {  // bare `collide`: show what it can do
        std::cout << app.help();
        return 0;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : kBadInput;
    }
    return collide::cli::run_command(std::cerr, [&] {
        collide::set_default_work_budget(max_work);
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
            const bool loop = interactive || (!no_interactive && !step_options.json && !step_options.events &&
                                              scene_file != "-" && isatty(0) && isatty(1));
            return run_step(scene_file, step_options, loop);
        }
        if (*render) return collide::run_render(render_options, std::cout, std::cerr);
        if (*gui) return collide::run_gui(gui_options, std::cout, std::cerr);
        if (*material) return collide::run_material(material_options, std::cout, std::cerr);
        if (*worksheet) return collide::run_worksheet(worksheet_options, std::cout, std::cerr);
        if (*grade) return collide::run_grade(grade_options, std::cout, std::cerr);
        if (*lessons) {
            std::ostringstream out;
            collide::write_lesson_list(collide::load_lessons(collide::lessons_dir()), lessons_json, out);
            std::cout << out.str() << std::flush;
            return 0;
        }
        return 0;
    });
}
