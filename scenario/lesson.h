// Lessons (docs/formats/lesson-files.md): a scenario (the [scene], [[body]] and [view] tables of a
// scenario file) with its teaching text in a [lesson] table and [[question]] tables of four
// kinds (QuestionKind below): numeric ones, whose answers the engine computes from the run,
// predictions asked before the animation, multiple choice with a reason for each option, and
// why / what-if questions with a model answer. Lesson files live in lessons/*.toml.
#pragma once

#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "scenario/input_error.h"
#include "scenario/lesson_quantity.h"
#include "scenario/scene_file.h"

namespace collide {

// What a [[question]] asks of the student (docs/formats/lesson-files.md, "Questions"):
//   numeric  (the default) a quantity the engine computes from the run (`quantity`, with
//            `event` or `pair` and `collision`, `body`, `at`, `about` as it needs), marked right within `tolerance`
//            (relative, 0 < tolerance < 1, default 0.02); `what_if` asks it of the scene
//            run again with other values ({"A.mass" = 4.0, "scene.restitution" = 1.0}).
//   predict  asked before the animation, checked after it: either `choices` + `correct` +
//            `reasons` or a `quantity` the engine answers; `explain` (required) says why.
//   choice   `choices` (2 to 6), `correct` (1-based) and one `reason` per choice (why that
//            option is right or wrong).
//   explain  a why or what-if question with a model `answer` (required).
enum class QuestionKind { numeric, predict, choice, explain };

struct LessonQuestion {
    QuestionKind kind = QuestionKind::numeric;
    std::string text;                  // the question, as asked
    std::optional<Quantity> quantity;  // what answers it (scenario/lesson_quantity.h); none when
                                       // the question has none (choice, explain, predict with choices)
    int event = 1;                     // event quantities: which collision of the run, from 1
    // Or, instead of `event`, the collision named by its bodies: the `collision`-th (from 1)
    // of pair[0] and pair[1], with pair[0] as the page's a and pair[1] as its b (the impulse is
    // the one on pair[1]). A run of many bodies numbers its collisions in an order that any
    // change of the engine can shift; a pair and its count name the same one whatever else
    // collides around it (a row of dominoes: "domino 5 hits domino 6").
    std::vector<std::string> pair;       // empty, or two body names
    std::size_t pair_a = 0, pair_b = 0;  // their scene indices
    int collision = 1;
    std::string body;                  // body quantities: the body's name
    std::string explain;               // optional (required for predict): why, shown with the answer
    std::optional<Vec3> at;            // point_velocity_*: a point of the body (world frame at the
                                       // collision instant, m); unset: the contact point
    std::optional<Vec3> about;         // angular_momentum_*: the fixed point (m); unset: the origin
    double tolerance = 0.02;           // with a quantity: relative tolerance for marking an answer
    std::vector<std::string> choices;  // choice, predict with choices: the options, in order
    int correct = 0;                   // with choices: the right option, from 1
    std::vector<std::string> reasons;  // with choices: why each option is right or wrong
    std::string answer;                // explain: the model answer
    // numeric: the scene's values changed for this question ("A.mass", "scene.restitution");
    // empty: the lesson's own run answers it.
    std::map<std::string, double> what_if;

    bool has_quantity() const { return quantity.has_value(); }
    bool has_pair() const { return !pair.empty(); }
    bool has_choices() const { return !choices.empty(); }
};

// The name of a kind as written in a lesson file ("numeric", "predict", ...).
const char* question_kind_name(QuestionKind kind);

// The same scene with other settings, shown side by side with it ("e = 1, 0.5, 0").
struct LessonVariant {
    std::string label;  // e.g. "e = 0"
    Scene scene;        // the lesson's scene with the variant's settings
};

// [[figure]]: a collision the lesson is about, shown as its own before / at / after figure and
// worked out on its own: the `collision`-th time (from 1) that bodies a and b collide, drawn
// and worked out with a as the page's body a and b as its body b (the normal n points from a
// into b, b receives +P) whatever order the engine found them in. The first entry is
// figure.png (and the worked example, stills and annotations.json); each next one is
// figure-K.png. The roles hold for every collision of that pair: answers, later collisions.
struct LessonFigure {
    std::string a, b;            // the bodies' names
    std::size_t ia = 0, ib = 0;  // their scene indices
    int collision = 1;           // which collision of the pair, in time order, from 1
    std::string caption;         // optional: what the figure shows, in the lesson's words
    bool touching = false;       // before and after drawn where the bodies touch (default: a
                                 // moment apart), so that points of the bodies (a [[mark]]) keep
                                 // the instant's positions and velocities
    SourcePos pos;               // of the entry (for errors found when the scene is run)
    std::string key;             // "figure[K]"
};

// [teacher] (docs/formats/lesson-files.md, "The teacher's page"): what the teacher's page of a
// lesson says beyond the lesson's own text and answers. Bundled lessons must have it (the tests
// refuse one without); a user's lesson may leave it out, and its teacher's page says so.
struct LessonMisconception {
    std::string belief;    // what a student may think, in the student's words
    std::string evidence;  // what the lesson shows against it (a figure, a number, a panel)
};
struct LessonClassQuestion {
    std::string question;    // to ask the class
    std::string listen_for;  // what a good answer contains (optional)
};
struct LessonTeacher {
    std::string level;                       // e.g. "Final year of school or first year of university"
    std::vector<std::string> prerequisites;  // what the students should know before it
    int minutes = 0;                         // the time it needs in class
    std::vector<LessonMisconception> misconceptions;
    std::vector<LessonClassQuestion> ask;  // questions to ask in class
    std::string live;                      // how to run it live: what to move, what to look for
};

// [penalty] (1D lessons, docs/formats/lesson-files.md): the first collision again with a penalty
// (spring-damper) contact instead of the impulse (engine/penalty.h, teach/lesson_penalty.h).
struct LessonPenalty {
    double stiffness = 0.0;              // k, N/m
    std::vector<double> damping_ratios;  // zeta in [0, 1): the table and the force plot
    std::vector<double> stiffnesses;     // N/m, > 0: the matched spring at each (default k/4, k, 4k)
    double time_step = 0.0;              // s; 0: the engine's default (2000 steps a contact)
    SourcePos pos, step_pos;             // of the table and of its time_step (for errors found
    std::string step_key = "penalty";    // when the contact is run)
};

// [[vary]] (docs/formats/lesson-files.md, "The lesson's inputs"): one input of the lesson, a
// range its value is drawn from (worksheets) or set in (the Try-it panel's slider): `key` of the
// [[body]] named `body` (or of [scene] when body is "scene") takes one of lo, lo + step, ...,
// hi. The key is a number the table already has (its lesson value), or one component of a
// vector it has ("v.x": field "v", component 0). Bodies listed in `in_proportion` have the
// same key changed with it, each in proportion to its own value (a row's spacing).
struct LessonVary {
    std::string body;                        // a body's name, or "scene"
    std::string key;                         // as written: "mass", "v.x"
    std::string field;                       // the table's key: "mass", "v"
    int component = -1;                      // -1: the number itself; 0, 1, 2: x, y, z of a vector
    std::vector<std::string> in_proportion;  // other bodies whose `key` scales with this one
    double lo = 0.0, hi = 0.0, step = 1.0;
    double lesson_value = 0.0;  // the lesson's own value: what the table gives the key
    SourcePos pos;              // of the entry (for errors found when a draw is run)
    std::string where;          // "vary[K]"

    // "A.mass", "ball.v.x" or "scene.restitution": the name lesson_with_values takes (the
    // Try-it panel's query string, key.json).
    std::string name() const { return body + "." + key; }
    // How many values the grid has: (hi - lo) / step + 1 (the step divides the range; the
    // reader refuses one that does not).
    std::size_t count() const;
    // The k-th value of the grid, lo + k step, rounded to 1e-9 so that it prints as written
    // (0.1 + 2 * 0.1 gives 0.3, not 0.30000000000000004); the last is hi exactly.
    double value(std::size_t k) const;
};

// [[plot]] (docs/formats/lesson-files.md, "Plots"): a recorded quantity of the lesson's run
// against another, drawn on its page with a table of the numbers. Per sample: every sampled
// instant, x and each y a sample quantity (PlotQuantity). Per collision: the collisions
// `pair` has (every one of those two bodies), or `chain` has (the first of each neighbouring
// pair, chain[k] striking chain[k+1]), or `instant` has (every collision of the instant its two
// bodies first collide), or every collision of the run; x is "collision" (its
// number among them, from 1) or "t", each y "t", "interval" (from the one before) or "impulse".
struct PlotQuantity {
    std::string name;  // as written: "ball.position.y", "energy", "t", "B.touching point.v.x"
    // Per sample: what it reads. kinetic ... angular_momentum: the moving bodies' total (body -1)
    // or one body's (BODY.kinetic_energy, BODY.momentum.x); angular momentum about the origin.
    enum class Kind { time, position, velocity, spin, angle, kinetic, potential, energy, momentum, angular_momentum };
    Kind kind = Kind::time;
    int body = -1;      // a body's scene index, or -1 (time and the totals)
    int mark = -1;      // an index into the lesson's [[mark]] list (view.marks), or -1
    int component = 0;  // 0, 1, 2: x, y, z (a number without component: 0)
    std::string unit;   // "m", "m/s", "rad/s", "rad", "J", "kg m/s", "s"
};
enum class PlotPer { sample, collision };
enum class PlotFit { none, line, ratio };

struct LessonPlot {
    std::string title;
    PlotPer per = PlotPer::sample;
    // Per sample: x and the y series. Per collision: x is "collision" or "t"; each y is a
    // PlotQuantity with name "t", "interval" or "impulse" (kind time; unit "s" or "N s").
    PlotQuantity x;
    std::vector<PlotQuantity> y;
    std::vector<std::string> pair, chain;  // per collision: which collisions (body names)
    // Or every collision of one instant: the first at which instant[0] and instant[1] collide
    // (a resting stack struck: each contact's impulse, solved together).
    std::vector<std::string> instant;
    std::vector<std::size_t> pair_index, chain_index, instant_index;
    std::string counting = "collision";  // per collision with x = "collision": what one step of x is
    PlotFit fit = PlotFit::none;
    int fit_from = 1;  // fit = "line" per collision: only the collisions numbered from here
    SourcePos pos;
    std::string where;  // "plot[K]"
};

// The most values a [[vary]] grid may have.
constexpr std::size_t kMaxVaryValues = 1000000;

struct Lesson {
    std::string file;         // as given or found
    std::string source;       // the file's text (lesson_with_values edits and re-reads it)
    std::string source_name;  // the file's name in messages
    std::string id;           // e.g. "catch-up": `collide render catch-up`
    int order = 0;            // position in `collide lessons`
    std::string title;
    std::string section;  // the page's section it teaches
    std::vector<std::string> goals;
    // The givens, shown before the predictions ("The set-up"): what is there and how it moves,
    // nothing the questions ask. Markdown paragraphs; may be empty (a user's lesson).
    std::string setup;
    std::string explanation;  // plain language, Markdown paragraphs; shown after the figures
    // For the teacher, not the students (commands to run, files to read): the site shows it
    // in its own section, left out of the student's print.
    std::string teacher_notes;
    std::optional<LessonTeacher> teacher;  // [teacher]: the teacher's page (may be absent)
    std::vector<LessonQuestion> questions;
    Scene scene;
    std::string label;  // the scene's own label beside its variants (e.g. "e = 0.5")
    std::vector<LessonVariant> variants;
    std::optional<LessonPenalty> penalty;
    std::vector<LessonFigure> figures;  // [[figure]] entries, in order (may be empty)
    std::vector<LessonVary> vary;       // [[vary]] entries, in order (may be empty)
    std::vector<LessonPlot> plots;      // [[plot]] entries, in order (may be empty)
    SceneView view;
};

// Every per-sample quantity a [[plot]] of `L` may name, read as a [[plot]]'s are (the Try-it
// panel's plot offers them): t, the totals, and each moving body's (and each [[mark]]'s).
std::vector<PlotQuantity> plot_quantities(const Lesson& L);
// Per collision: "collision" (its number; x only), "t", "interval" (from the one before; y only)
// and "impulse" (y only), with their units.
std::vector<PlotQuantity> plot_collision_quantities();

// ---- The file format (scenario/lesson_file.cpp, lesson_question.cpp) ----

// The top-level tables a lesson file adds to a scenario's.
const std::vector<std::string>& lesson_tables();

// Parses and validates a lesson file (the scenario part as parse_scene_text does). Throws
// InputError naming file, line and key.
Lesson load_lesson(const std::string& path);
// The same from the file's text (`name` in messages, `path` kept as Lesson::file).
Lesson parse_lesson_text(const std::string& text, const std::string& name, const std::string& path);

// ---- The values and their substitution (scenario/lesson_values.cpp) ----

// The lesson with some of its scene's values changed and everything validated again, as if
// the file had been written so: `values` maps "BODY.KEY" (a [[body]] named BODY) or
// "scene.KEY" ([scene]) to a number (e.g. {"A.mass": 4.0, "scene.restitution": 1.0}); KEY may
// name one component of a vector the table gives ("ball.v.x", "A.position.y"). Each changes
// the number it names and nothing else (a question's what_if). The result has no questions
// and no [[vary]] (only its scene, view, variants, figures and [penalty]). Throws InputError
// naming the changed key when there is no such body or key or the changed lesson is refused.
Lesson lesson_with_values(const Lesson& lesson, const std::map<std::string, double>& values);

// The numbers a set of the lesson's [[vary]] inputs changes: `inputs` itself, and for an input
// with in_proportion each of those bodies' key, times value / the input's lesson value. Throws
// InputError naming a body's key that is given beside the input that moves it.
std::map<std::string, double> input_values(const Lesson& lesson, const std::map<std::string, double>& inputs);

// lesson_with_values(lesson, input_values(lesson, inputs)): the lesson as the Try-it panel and a
// worksheet run it with these inputs.
Lesson lesson_with_inputs(const Lesson& lesson, const std::map<std::string, double>& inputs);

// ---- The lesson library on disk (scenario/lesson_library.cpp) ----

// The directory of the bundled lessons, the first of: $COLLIDE_LESSONS when set; `installed`
// when it is a directory (an installed program's share/collide/lessons); the source tree's
// lessons/ (the programs and tests of a build tree).
std::string lessons_dir(const std::string& installed);
// The same for the running program: lessons_dir(installed_lessons_dir(its executable)), so that
// an installed `collide` finds its own lessons from any directory.
std::string lessons_dir();
// Where a program installed at `exe` (e.g. /usr/bin/collide) finds the lessons installed with
// it: its directory, then the install's path from bin/ to share/collide/lessons
// (/usr/bin/../share/collide/lessons).
std::string installed_lessons_dir(const std::string& exe);
// Every lesson in `dir` (its *.toml files), in their order. Throws InputError on a bad file.
std::vector<Lesson> load_lessons(const std::string& dir);
// A lesson file for a command-line argument: an existing file, or a lesson id in dir.
// Throws InputError ("no lesson or file 'x'", with the closest id as a hint).
std::string resolve_lesson(const std::string& id_or_file, const std::string& dir);

// The scenario for a command-line argument: a scenario file, a lesson file or a lesson id (in
// lessons_dir()). `lesson` receives the lesson when it is one. Throws InputError.
Scene load_scenario(const std::string& arg, SceneView* view = nullptr, std::optional<Lesson>* lesson = nullptr);
// The same from a file's text (`name` in messages, `path` kept as Lesson::file): a lesson when
// it has a [lesson] table, else a scenario (the WebAssembly module's run(), wasm/).
Scene parse_scenario_text(const std::string& text, const std::string& name, const std::string& path,
                          SceneView* view = nullptr, std::optional<Lesson>* lesson = nullptr);

// `collide lessons`: a table (order, id, dimension, duration, title), or with json one object
// per line: {"id": .., "order": .., "title": .., "section": .., "dimension": .., "duration": ..}.
void write_lesson_list(const std::vector<Lesson>& lessons, bool json, std::ostream& out);

}  // namespace collide
