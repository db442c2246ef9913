// The lesson library on disk: where the bundled lessons are, every lesson of a folder, the
// file a command-line argument names, and `collide lessons`' list.
#include "scenario/lesson.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scenario/toml_reader.h"

// The source tree's lessons/ and the install's path from bin/ to share/collide/lessons
// (scenario/CMakeLists.txt).
#ifndef COLLIDE_LESSONS_DIR
#define COLLIDE_LESSONS_DIR "lessons"
#endif
#ifndef COLLIDE_LESSONS_FROM_BINDIR
#define COLLIDE_LESSONS_FROM_BINDIR "../share/collide/lessons"
#endif

namespace collide {

namespace fs = std::filesystem;

std::string lessons_dir(const std::string& installed) {
    if (const char* env = std::getenv("COLLIDE_LESSONS")) return env;
    std::error_code ec;
    if (!installed.empty() && fs::is_directory(installed, ec)) return installed;
    return COLLIDE_LESSONS_DIR;
}

std::string lessons_dir() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);  // Linux: the running program
    return lessons_dir(ec ? std::string() : installed_lessons_dir(exe.string()));
}

std::string installed_lessons_dir(const std::string& exe) {
    return (fs::path(exe).parent_path() / COLLIDE_LESSONS_FROM_BINDIR).lexically_normal().string();
}

std::vector<Lesson> load_lessons(const std::string& dir) {
    std::vector<Lesson> out;
    std::error_code ec;
    std::vector<std::string> files;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec))
        if (e.is_regular_file() && e.path().extension() == ".toml") files.push_back(e.path().string());
    if (ec) throw InputError(dir, {}, "", "cannot read the lessons directory: " + ec.message());
    std::sort(files.begin(), files.end());
    for (const std::string& f : files) out.push_back(load_lesson(f));
    std::stable_sort(out.begin(), out.end(), [](const Lesson& a, const Lesson& b) { return a.order < b.order; });
    for (std::size_t j = 0; j < out.size(); ++j)
        for (std::size_t i = 0; i < j; ++i)
            if (out[i].id == out[j].id)
                throw InputError(out[j].file, {}, "lesson.id",
                                 "the id '" + out[j].id + "' is already used by " + out[i].file);
    return out;
}

std::string resolve_lesson(const std::string& id_or_file, const std::string& dir) {
    std::error_code ec;
    // Any file that exists is read as one (a device, a FIFO: the reader says what is wrong with
    // it); so is a directory named as a path (with a '/'), which the reader refuses as such.
    if (id_or_file == "-" || (fs::exists(id_or_file, ec) && !fs::is_directory(id_or_file, ec)) ||
        (id_or_file.find('/') != std::string::npos && fs::is_directory(id_or_file, ec)))
        return id_or_file;
    // The file named after the id (NN-id.toml) when it holds that lesson: then one file is
    // read, and a mistake in another lesson does not stop this one.
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
        const std::string stem = e.path().stem().string();
        const bool named = stem == id_or_file ||
                           (stem.size() > id_or_file.size() && stem.compare(stem.size() - id_or_file.size() - 1,
                                                                            std::string::npos, "-" + id_or_file) == 0);
        if (!named || e.path().extension() != ".toml") continue;
        try {
            if (load_lesson(e.path().string()).id == id_or_file) return e.path().string();
        } catch (const InputError&) {
            return e.path().string();  // its own error will name it
        }
    }
    std::vector<std::string> ids;
    for (const Lesson& L : load_lessons(dir)) {
        if (L.id == id_or_file) return L.file;
        ids.push_back(L.id);
    }
    const std::string hint = closest_match(id_or_file, ids);
    throw InputError(
        id_or_file, {}, "",
        "no such file, and no lesson with this id" +
            (hint.empty() ? std::string(" (collide lessons lists them)") : "; did you mean '" + hint + "'?"));
}

Scene load_scenario(const std::string& arg, SceneView* view, std::optional<Lesson>* lesson) {
    const std::string file = resolve_lesson(arg, lessons_dir());
    std::string name;
    const std::string text = read_input_file(file, &name);
    return parse_scenario_text(text, name, file, view, lesson);
}

Scene parse_scenario_text(const std::string& text, const std::string& name, const std::string& path, SceneView* view,
                          std::optional<Lesson>* lesson) {
    if (parse_toml_text(text, name).contains("lesson")) {
        Lesson L = parse_lesson_text(text, name, path);
        if (view) *view = L.view;
        Scene scene = L.scene;
        if (lesson) *lesson = std::move(L);
        return scene;
    }
    return parse_scene_text(text, name, view);
}

void write_lesson_list(const std::vector<Lesson>& lessons, bool json, std::ostream& out) {
    if (json) {
        for (const Lesson& L : lessons)
            out << nlohmann::ordered_json{{"id", L.id},
                                          {"order", L.order},
                                          {"title", L.title},
                                          {"section", L.section},
                                          {"dimension", L.scene.dimension},
                                          {"duration", L.scene.duration}}
                       .dump()
                << "\n";
        return;
    }
    std::size_t w = 2;
    for (const Lesson& L : lessons) w = std::max(w, L.id.size());
    out << "  # " << std::string("id") + std::string(w - 2, ' ') << "  dim  duration  title\n";
    for (const Lesson& L : lessons) {
        char line[64];
        std::snprintf(line, sizeof line, "%3d ", L.order);
        out << line << L.id << std::string(w - L.id.size(), ' ');
        std::snprintf(line, sizeof line, "  %2dD  %6.3g s  ", L.scene.dimension, L.scene.duration);
        out << line << L.title << "\n";
    }
}

}  // namespace collide
