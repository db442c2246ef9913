// A lesson's values: the [[vary]] ranges a worksheet draws them from, and the lesson with some
// of them changed (lesson_with_values: what-if questions, worksheets, the Try-it panel).
#include "scenario/lesson.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "scenario/lesson_parse.h"
#include "scenario/toml_reader.h"

namespace collide {

namespace {

// The table a [[vary]] entry changes: [scene], or the [[body]] named `owner` (null: none).
const toml::table* vary_owner(const toml::table& root, const std::string& owner) {
    if (owner == "scene") return root["scene"].as_table();
    if (const toml::array* bodies = root["body"].as_array())
        for (const toml::node& b : *bodies)
            if (const toml::table* t = b.as_table(); t && (*t)["name"].value<std::string>() == owner) return t;
    return nullptr;
}

// One [[vary]] table: body (or "scene"), key (a number that table has), range, step.
LessonVary parse_vary_entry(const TableReader& v, const toml::table& file, const Lesson& L) {
    v.allow_only({"body", "key", "range", "step"});
    LessonVary V;
    V.pos = v.table_pos();
    V.body = v.string("body", "a body's name, or \"scene\"").value_or("");
    if (V.body.empty()) v.fail("body", "missing key 'body' (a [[body]] name, or \"scene\" for [scene])");
    const toml::table* owner = vary_owner(file, V.body);
    if (!owner) {
        std::vector<std::string> names = {"scene"};
        for (const SceneBody& b : L.scene.bodies) names.push_back(b.name);
        const std::string hint = closest_match(V.body, names);
        v.fail("body", "no body named '" + V.body + "' (write a [[body]] name, or \"scene\")" +
                           (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
    }
    V.key = v.string("key", "a numeric key of that table (e.g. \"mass\")").value_or("");
    if (V.key.empty()) v.fail("key", "missing key 'key' (the number to vary, e.g. \"mass\")");
    const toml::node* old = owner->get(V.key);
    const std::string table_name = V.body == "scene" ? "[scene]" : "body '" + V.body + "'";
    if (!old) v.fail("key", table_name + " has no key '" + V.key + "' (vary a number the table gives)");
    if (!old->is_number()) v.fail("key", "'" + V.key + "' of " + table_name + " is not a number");
    V.lesson_value = old->value<double>().value_or(0.0);
    if (!v.has("range")) v.fail("range", "missing key 'range' ([lo, hi], the values drawn from)");
    const std::vector<double> r = *v.numbers("range", 2, "a range [lo, hi] of two numbers");
    V.lo = r[0];
    V.hi = r[1];
    if (V.lo > V.hi) v.fail("range", "expected lo <= hi, got [" + show(V.lo) + ", " + show(V.hi) + "]");
    if (!v.has("step")) v.fail("step", "missing key 'step' (> 0: values are lo, lo + step, ... up to hi)");
    V.step = *v.number("step", "a step (> 0)");
    if (!(V.step > 0)) v.fail("step", "expected a step > 0, got " + show(V.step));
    // A bound on the grid keeps the count an ordinary integer (and catches a step in the
    // wrong unit).
    if ((V.hi - V.lo) / V.step > 1e6) v.fail("step", "more than a million values from lo to hi: a larger step");
    for (const LessonVary& W : L.vary)
        if (W.name() == V.name()) v.fail("key", "'" + V.name() + "' is already varied by " + W.where);
    return V;
}

}  // namespace

namespace lesson_parse {

// [[vary]]: the ranges a worksheet draws each student's values from.
void parse_vary(const TableReader& root, const toml::table& file, Lesson& L) {
    for (const TableReader& entry : root.tables("vary")) {
        LessonVary V = parse_vary_entry(entry, file, L);
        V.where = entry.prefix();
        L.vary.push_back(std::move(V));
    }
}

}  // namespace lesson_parse

std::size_t LessonVary::count() const {
    // A hair of slack: 0.1 steps from 1.0 to 4.0 are 30, though 3.0 / 0.1 is 29.999...
    return static_cast<std::size_t>(std::floor((hi - lo) / step + 1e-9)) + 1;
}

double LessonVary::value(std::size_t k) const {
    const double x = lo + static_cast<double>(k) * step;
    return std::round(x * 1e9) / 1e9;
}

namespace {

// "A.mass = 4, scene.restitution = 1": the changed values, for messages.
std::string describe_values(const std::map<std::string, double>& values) {
    std::string s;
    for (const auto& [key, value] : values) s += (s.empty() ? "" : ", ") + key + " = " + show(value);
    return s;
}

// The table a "BODY.KEY" or "scene.KEY" value goes into: [scene], or the [[body]] named BODY.
toml::table& value_owner(toml::table& file, const std::string& owner, const Lesson& L, const std::string& key) {
    if (owner == "scene") {
        if (toml::table* scene = file["scene"].as_table()) return *scene;
    } else if (toml::array* bodies = file["body"].as_array()) {
        for (toml::node& b : *bodies)
            if (toml::table* t = b.as_table(); t && (*t)["name"].value<std::string>() == owner) return *t;
    }
    std::vector<std::string> names = {"scene"};
    for (const SceneBody& b : L.scene.bodies) names.push_back(b.name);
    const std::string hint = closest_match(owner, names);
    throw InputError(L.source_name, {}, key,
                     "no body named '" + owner + "' (write BODY.KEY for a [[body]] or scene.KEY)" +
                         (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
}

}  // namespace

Lesson lesson_with_values(const Lesson& L, const std::map<std::string, double>& values) {
    toml::table file = parse_toml_text(L.source, L.source_name);
    file.erase("question");  // only the scene is wanted, and questions may hold what_if themselves
    file.erase("vary");      // the ranges are the caller's business (a worksheet draws from them)
    for (const auto& [key, value] : values) {
        const std::size_t dot = key.find('.');
        if (dot == std::string::npos || dot == 0 || dot + 1 == key.size())
            throw InputError(L.source_name, {}, key, "expected BODY.KEY or scene.KEY (e.g. A.mass, scene.restitution)");
        toml::table& owner = value_owner(file, key.substr(0, dot), L, key);
        const std::string name = key.substr(dot + 1);
        // An integer stays an integer when the file wrote one (a key may require it).
        const toml::node* old = owner.get(name);
        if (old && old->is_integer() && value == std::floor(value) && std::abs(value) < 1e15)
            owner.insert_or_assign(name, static_cast<int64_t>(value));
        else owner.insert_or_assign(name, value);
    }
    std::ostringstream text;
    text << file;
    Lesson out = parse_lesson_text(text.str(), L.source_name + " (with " + describe_values(values) + ")", L.file);
    return out;
}

}  // namespace collide
