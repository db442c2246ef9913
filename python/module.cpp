// collide._collide: the Python module's C++ half (pybind11). Each function calls what the
// command calls and returns what it prints, so Python and `collide` cannot disagree:
//   solve_json      collide solve --format json          (teach/solve.h write_json)
//   run_json        collide step --json, --events --json (teach/step_output.h step_json: one run)
//   figure_png      collide render's figure.png          (present/render_job.h figure_png)
// python/collide/__init__.py turns the JSON into dicts and NumPy arrays. A scene or a
// collision comes as a file name (or a lesson id) or as a dict with the file's tables, read
// here into a TOML table. Bad input raises ValueError with the command's message (file, line,
// key; a dict is named "<dict>" and its values have no line).
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <toml++/toml.h>

#include "engine/run_error.h"
#include "present/frame_spec.h"
#include "present/render_job.h"
#include "teach/step_output.h"
#include "scenario/input_error.h"
#include "scenario/lesson.h"
#include "scenario/scene_file.h"
#include "scenario/solve_problem.h"
#include "teach/solve.h"

namespace py = pybind11;

namespace collide {
namespace {

const char* const kDictName = "<dict>";  // a dict in messages, as "<stdin>" is standard input

// ---- A dict as a TOML table ----

// How deep a dict may nest (the formats need 4: [[body]] vertices = [[x, y], ...]) and how many
// values it may hold in all (as a file's 1 MiB): beyond either, and for a dict or list that
// contains itself, ValueError naming where, never a crash or a RecursionError.
constexpr int kMaxDepth = 64;
constexpr std::size_t kMaxValues = 1 << 20;

struct Conversion {
    std::vector<const PyObject*> open;  // the dicts and lists being converted, outermost first
    std::size_t values = 0;
};

toml::table to_table(const py::dict& dict, const std::string& where, Conversion* c);
toml::array to_array(py::handle sequence, const std::string& where, Conversion* c);

// A dict or list entered: refused if it is one of its own ancestors (a cycle) or nested too
// deep; left by the destructor.
class Entered {
public:
    Entered(py::handle container, const std::string& where, Conversion* c) : c_(c) {
        for (const PyObject* o : c->open)
            if (o == container.ptr())
                throw InputError(kDictName, {}, where, "contains itself (a dict or list inside its own value)");
        if (c->open.size() >= static_cast<std::size_t>(kMaxDepth))
            throw InputError(kDictName, {}, where,
                             "nested more than " + std::to_string(kMaxDepth) + " deep (the formats need 4)");
        c->open.push_back(container.ptr());
    }
    ~Entered() { c_->open.pop_back(); }
    Entered(const Entered&) = delete;
    Entered& operator=(const Entered&) = delete;

private:
    Conversion* c_;
};

// Hands `insert` the TOML value of a Python value: bool, int, float, str, dict, list or tuple
// (python/collide/__init__.py has already turned NumPy arrays and scalars into these).
template <class Insert>
void convert(py::handle value, const std::string& where, Conversion* c, Insert insert) {
    if (++c->values > kMaxValues)
        throw InputError(kDictName, {}, where, "more than 2^20 values in all (input files are limited to 1 MiB)");
    if (py::isinstance<py::bool_>(value)) {
        insert(value.cast<bool>());
    } else if (py::isinstance<py::int_>(value)) {
        try {
            insert(value.cast<std::int64_t>());
        } catch (const py::cast_error&) {
            throw InputError(kDictName, {}, where, "integer out of range");
        }
    } else if (py::isinstance<py::float_>(value)) {
        insert(value.cast<double>());
    } else if (py::isinstance<py::str>(value)) {
        insert(value.cast<std::string>());
    } else if (py::isinstance<py::dict>(value)) {
        insert(to_table(value.cast<py::dict>(), where, c));
    } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
        insert(to_array(value, where, c));
    } else {
        const std::string type = py::str(py::type::of(value).attr("__name__"));
        throw InputError(kDictName, {}, where,
                         "expected a number, a string, a boolean, a list or a dict, got a " + type);
    }
}

// (convert is instantiated for the two inserters below only: lists and dicts recurse through
// these functions, not through new lambdas.)
toml::array to_array(py::handle sequence, const std::string& where, Conversion* c) {
    const Entered entered(sequence, where, c);
    toml::array array;
    std::size_t k = 0;
    for (py::handle item : sequence)
        convert(item, where + "[" + std::to_string(k++) + "]", c,
                [&array](auto&& v) { array.push_back(std::move(v)); });
    return array;
}

toml::table to_table(const py::dict& dict, const std::string& where, Conversion* c) {
    const Entered entered(dict, where, c);
    toml::table table;
    for (auto [key, value] : dict) {
        if (!py::isinstance<py::str>(key))
            throw InputError(kDictName, {}, where, "keys must be strings, got " + std::string(py::repr(key)));
        const std::string name = key.cast<std::string>();
        const std::string full = where.empty() ? name : where + "." + name;
        convert(value, full, c, [&](auto&& v) { table.insert_or_assign(name, std::move(v)); });
    }
    return table;
}

// A whole dict (a file's root table).
toml::table to_table(const py::dict& dict) {
    Conversion c;
    return to_table(dict, "", &c);
}

// ---- Errors ----

// Runs f, turning bad input into ValueError with the command's message. A render option's
// message names it as Python does (size, not --size).
template <class F>
auto translating(F f) {
    try {
        return f();
    } catch (const InputError& e) {
        if (e.file().empty() && e.key().rfind("--", 0) == 0)
            throw py::value_error(InputError::format("", {}, e.key().substr(2), e.message()));
        throw py::value_error(e.what());
    } catch (const RunError& e) {  // a scene the engine cannot run as asked (exit 2 for the command)
        throw py::value_error(e.what());
    }
}

// ---- The three functions ----

std::string solve_json(const py::object& source, const std::string& model) {
    SolveProblem problem = translating([&] {
        SolveProblem p = py::isinstance<py::dict>(source)
                             ? parse_solve_table(to_table(source.cast<py::dict>()), kDictName)
                             : parse_solve_file(source.cast<std::string>());
        if (!model.empty() && !parse_model(model, &p.model))
            throw InputError(
                "", {}, "model",
                "expected frictionless, coulomb, matrix, stick, page-listing or routh, got '" + model + "'");
        return p;
    });
    std::ostringstream out;
    {
        py::gil_scoped_release unlocked;
        write_json(problem, solve(problem), out);
    }
    return out.str();
}

// A scene to run or draw: a dict (a scenario's tables), or a scenario file, a lesson file or a
// lesson id (looked up in lessons_dir(installed)).
RenderSource render_source(const py::object& source, const std::string& installed) {
    return translating([&] {
        if (py::isinstance<py::dict>(source)) {
            RenderSource s;
            s.scene = parse_scene_table(to_table(source.cast<py::dict>()), kDictName, &s.view);
            return s;
        }
        return load_render_source(resolve_lesson(source.cast<std::string>(), lessons_dir(installed)));
    });
}

// max_work: the run's work budget (engine/scene.h); None keeps the default.
void set_budget(Scene* scene, std::optional<double> max_work) {
    if (!max_work) return;
    if (!(*max_work > 0.0) || !std::isfinite(*max_work))
        throw py::value_error("max_work: expected a number > 0 (units of work, about a microsecond each), got " +
                              std::string(py::repr(py::float_(*max_work))));
    scene->work_budget = *max_work;
}

std::pair<std::vector<std::string>, std::vector<std::string>> run_json(const py::object& source,
                                                                       const std::string& installed,
                                                                       std::optional<double> max_work) {
    Scene scene = render_source(source, installed).scene;
    set_budget(&scene, max_work);
    py::gil_scoped_release unlocked;
    StepJson run = translating([&] { return step_json(scene); });
    return {std::move(run.states), std::move(run.events)};
}

std::optional<py::bytes> figure_png_bytes(const py::object& source, const std::string& installed,
                                          const std::string& size, const std::string& view, const std::string& quality,
                                          const std::string& backend, double fps, std::optional<double> max_work) {
    RenderSource scene = render_source(source, installed);
    set_budget(&scene.scene, max_work);
    // Read in the order the command reads them (cli/render_options.cpp): the first wrong one is named.
    FrameSpec frame;
    render::GlBackend gl = render::GlBackend::osmesa;
    translating([&] {
        frame = read_frame_spec(size, fps, quality, view);
        gl = read_backend(backend);
        return 0;
    });
    std::optional<std::vector<std::uint8_t>> png;
    {
        py::gil_scoped_release unlocked;
        png = translating([&] { return figure_png(frame, gl, std::move(scene)); });
    }
    if (!png) return std::nullopt;
    return py::bytes(reinterpret_cast<const char*>(png->data()), png->size());
}

}  // namespace
}  // namespace collide

PYBIND11_MODULE(_collide, m) {
    m.doc() = "Collide's C++ half: the command's own functions (use the collide package).";
    m.def("solve_json", &collide::solve_json, py::arg("source"), py::arg("model") = "",
          "`collide solve --format json` of a collision file or dict: the JSON text.");
    m.def("run_json", &collide::run_json, py::arg("source"), py::arg("installed_lessons") = "",
          py::arg("max_work") = py::none(),
          "One run of a scene: the lines of `collide step --json` and of `--events --json`.");
    m.def("figure_png", &collide::figure_png_bytes, py::arg("source"), py::arg("installed_lessons") = "",
          py::arg("size") = "720p", py::arg("view") = "", py::arg("quality") = "medium", py::arg("backend") = "osmesa",
          py::arg("fps") = 30.0, py::arg("max_work") = py::none(),
          "collide render's figure.png of a scene: PNG bytes, or None when nothing collides.");
}
