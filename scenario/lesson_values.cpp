// A lesson's values: the [[vary]] ranges a worksheet draws them from, and the lesson with some
// of them changed (lesson_with_values: what-if questions, worksheets, the Try-it panel).
#include "scenario/lesson.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
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

// A key as written, "mass" or "v.x": the table's key and the component (-1: none). Returns
// an explanation instead when the component is not x, y or z.
struct KeyParts {
    std::string field;
    int component = -1;
    std::string error;
};
KeyParts key_parts(const std::string& key) {
    KeyParts k;
    const std::size_t dot = key.find('.');
    k.field = key.substr(0, dot);
    if (dot == std::string::npos) return k;
    const std::string c = key.substr(dot + 1);
    if (c == "x" || c == "y" || c == "z") k.component = c[0] - 'x';
    else
        k.error = "'" + key + "': after the dot a component x, y or z of the vector '" + k.field + "' (e.g. \"" +
                  k.field + ".x\")";
    return k;
}

// The number `key` names in `owner` (a number, or a component of an array of numbers), or an
// explanation of why there is none (`table_name` in it, e.g. "body 'A'").
const toml::node* keyed_number(const toml::table& owner, const KeyParts& k, const std::string& key,
                               const std::string& table_name, std::string* why) {
    const toml::node* old = owner.get(k.field);
    if (!old) {
        *why = table_name + " has no key '" + k.field + "' (vary a number the table gives)";
        return nullptr;
    }
    if (k.component < 0) {
        if (old->is_number()) return old;
        *why = "'" + k.field + "' of " + table_name + " is not a number" +
               (old->is_array() ? " but a vector: name one component, e.g. \"" + k.field + ".x\"" : "");
        return nullptr;
    }
    if (k.field == "orientation") {
        *why = "'" + key + "': a quaternion's components are not independent (vary an angle in 2D, or a velocity)";
        return nullptr;
    }
    const toml::array* arr = old->as_array();
    if (!arr) {
        *why = "'" + k.field + "' of " + table_name + " is a number, not a vector: write \"" + k.field + "\"";
        return nullptr;
    }
    const toml::node* c = arr->get(static_cast<std::size_t>(k.component));
    if (!c) {
        *why = "'" + k.field + "' of " + table_name + " has " + std::to_string(arr->size()) + " components, no " +
               std::string(1, static_cast<char>('x' + k.component));
        return nullptr;
    }
    if (!c->is_number()) {
        *why = "'" + key + "' of " + table_name + " is not a number";
        return nullptr;
    }
    return c;
}

// The grid's number of steps from lo to hi, when the step divides the range to within a
// billionth of a step (0.1 divides [0, 1] though 1 / 0.1 is 10.000000000000002 in doubles);
// -1 when it does not.
long long grid_steps(double lo, double hi, double step) {
    const double q = (hi - lo) / step;
    const double n = std::round(q);
    if (std::abs(q - n) > 1e-9 * std::max(1.0, n)) return -1;
    return static_cast<long long>(n);
}

// One [[vary]] table: body (or "scene"), key (a number that table has, or a vector's
// component), range, step, in_proportion.
LessonVary parse_vary_entry(const TableReader& v, const toml::table& file, const Lesson& L) {
    v.allow_only({"body", "key", "range", "step", "in_proportion"});
    LessonVary V;
    V.pos = v.table_pos();
    V.body = v.string("body", "a body's name, or \"scene\"").value_or("");
    if (V.body.empty()) v.fail("body", "missing key 'body' (a [[body]] name, or \"scene\" for [scene])");
    std::vector<std::string> names = {"scene"};
    for (const SceneBody& b : L.scene.bodies) names.push_back(b.name);
    const toml::table* owner = vary_owner(file, V.body);
    if (!owner) {
        const std::string hint = closest_match(V.body, names);
        v.fail("body", "no body named '" + V.body + "' (write a [[body]] name, or \"scene\")" +
                           (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
    }
    V.key =
        v.string("key", "a numeric key of that table (e.g. \"mass\"), or a vector's component (\"v.x\")").value_or("");
    if (V.key.empty()) v.fail("key", "missing key 'key' (the number to vary, e.g. \"mass\" or \"v.x\")");
    const KeyParts parts = key_parts(V.key);
    if (!parts.error.empty()) v.fail("key", parts.error);
    V.field = parts.field;
    V.component = parts.component;
    const std::string table_name = V.body == "scene" ? "[scene]" : "body '" + V.body + "'";
    std::string why;
    const toml::node* old = keyed_number(*owner, parts, V.key, table_name, &why);
    if (!old) v.fail("key", why);
    V.lesson_value = old->value<double>().value_or(0.0);

    if (!v.has("range")) v.fail("range", "missing key 'range' ([lo, hi], the values drawn from)");
    const std::vector<double> r = *v.numbers("range", 2, "a range [lo, hi] of two numbers");
    V.lo = r[0];
    V.hi = r[1];
    if (V.lo > V.hi) v.fail("range", "expected lo <= hi, got [" + show(V.lo) + ", " + show(V.hi) + "]");
    if (!v.has("step")) v.fail("step", "missing key 'step' (> 0: values are lo, lo + step, ... up to hi)");
    V.step = *v.number("step", "a step (> 0)");
    if (!(V.step > 0)) v.fail("step", "expected a step > 0, got " + show(V.step));
    const long long steps = grid_steps(V.lo, V.hi, V.step);
    if (steps < 0) {
        const double below = V.lo + std::floor((V.hi - V.lo) / V.step) * V.step;
        v.fail("step", "the step " + show(V.step) + " does not divide the range [" + show(V.lo) + ", " + show(V.hi) +
                           "]: the values lo + k step would miss hi (the last would be " + show(below) +
                           "); choose a step that divides hi − lo, or hi = " + show(below) + " or " +
                           show(below + V.step));
    }
    // A bound on the grid keeps the count an ordinary integer (and catches a step in the wrong
    // unit).
    if (static_cast<double>(steps) + 1 > static_cast<double>(kMaxVaryValues))
        v.fail("step", "the grid from lo to hi has " + std::to_string(steps + 1) + " values, more than " +
                           std::to_string(kMaxVaryValues) + ": a larger step");
    if (V.lesson_value < V.lo || V.lesson_value > V.hi || grid_steps(V.lo, V.lesson_value, V.step) < 0)
        v.fail("range", "the lesson's own " + V.name() + " = " + show(V.lesson_value) +
                            " is not one of the values lo, lo + step, " + "..., hi of [" + show(V.lo) + ", " +
                            show(V.hi) + "] in steps of " + show(V.step) +
                            " (the slider starts at the lesson's value): choose a range and step through it");

    if (v.has("in_proportion")) {
        const toml::array* list = v.node("in_proportion")->as_array();
        if (!list || list->empty())
            v.fail("in_proportion", "expected a list of body names, e.g. in_proportion = [\"domino 3\", \"domino 4\"]");
        if (V.body == "scene") v.fail("in_proportion", "only a body's key can change other bodies' in proportion");
        if (V.lesson_value == 0)
            v.fail("in_proportion", "the lesson's own " + V.name() +
                                        " is 0: the others cannot change in proportion to it (vary a key that is "
                                        "not 0 in the lesson)");
        for (const toml::node& n : *list) {
            const std::optional<std::string> name = n.value<std::string>();
            if (!name) v.fail("in_proportion", "expected a list of body names (strings)");
            const toml::table* other = *name == "scene" ? nullptr : vary_owner(file, *name);
            if (!other) {
                const std::string hint = closest_match(*name, names);
                v.fail("in_proportion",
                       "no body named '" + *name + "'" + (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
            }
            if (*name == V.body ||
                std::find(V.in_proportion.begin(), V.in_proportion.end(), *name) != V.in_proportion.end())
                v.fail("in_proportion", "'" + *name + "' is named twice (the body itself or an earlier entry)");
            if (!keyed_number(*other, parts, V.key, "body '" + *name + "'", &why)) v.fail("in_proportion", why);
            V.in_proportion.push_back(*name);
        }
    }
    // Every number this entry changes, against those of the entries before it.
    std::vector<std::string> changes = {V.name()};
    for (const std::string& b : V.in_proportion) changes.push_back(b + "." + V.key);
    for (const LessonVary& W : L.vary) {
        std::vector<std::string> theirs = {W.name()};
        for (const std::string& b : W.in_proportion) theirs.push_back(b + "." + W.key);
        for (const std::string& c : changes)
            if (std::find(theirs.begin(), theirs.end(), c) != theirs.end())
                v.fail(c == V.name() ? "key" : "in_proportion", "'" + c + "' is already varied by " + W.where);
    }
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
    const long long n = grid_steps(lo, hi, step);
    return static_cast<std::size_t>(std::max(0LL, n)) + 1;
}

double LessonVary::value(std::size_t k) const {
    if (k + 1 >= count()) return hi;
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

// A value's name split: the table it goes into ("scene" or a body's name: the longest one
// the name starts with, followed by a dot, since a body's name may hold dots) and the key.
std::pair<std::string, std::string> split_name(const std::string& name, const Lesson& L) {
    std::string owner;
    for (const SceneBody& b : L.scene.bodies)
        if (b.name.size() > owner.size() && name.size() > b.name.size() + 1 &&
            name.compare(0, b.name.size(), b.name) == 0 && name[b.name.size()] == '.')
            owner = b.name;
    if (owner.empty() && name.rfind("scene.", 0) == 0) owner = "scene";
    if (owner.empty()) {
        const std::size_t dot = name.find('.');
        if (dot == std::string::npos || dot == 0 || dot + 1 == name.size())
            throw InputError(L.source_name, {}, name,
                             "expected BODY.KEY or scene.KEY (e.g. A.mass, scene.restitution, ball.v.x)");
        owner = name.substr(0, dot);
    }
    return {owner, name.substr(owner.size() + 1)};
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

// A number as the file would hold it: an integer stays an integer when the file wrote one (a
// key may require it).
template <class Insert>
void put_number(const toml::node* old, double value, Insert insert) {
    if (old && old->is_integer() && value == std::floor(value) && std::abs(value) < 1e15)
        insert(toml::value<int64_t>(static_cast<int64_t>(value)));
    else insert(toml::value<double>(value));
}

// The number a key names in `owner` (for in_proportion), or NaN.
double number_in(const toml::table& owner, const KeyParts& k) {
    const toml::node* n = owner.get(k.field);
    if (n && k.component >= 0) n = n->is_array() ? n->as_array()->get(static_cast<std::size_t>(k.component)) : nullptr;
    return n && n->is_number() ? n->value<double>().value_or(NAN) : NAN;
}

// Sets `name`'s number (BODY.KEY, BODY.KEY.C, scene.KEY) in `file` to `value`.
void set_value(toml::table& file, const std::string& name, double value, const Lesson& L) {
    const auto [owner_name, key] = split_name(name, L);
    toml::table& owner = value_owner(file, owner_name, L, name);
    const KeyParts k = key_parts(key);
    if (!k.error.empty()) throw InputError(L.source_name, {}, name, k.error);
    if (k.component < 0) {
        put_number(owner.get(k.field), value, [&](auto&& v) { owner.insert_or_assign(k.field, std::move(v)); });
        return;
    }
    std::string why;
    const std::string table_name = owner_name == "scene" ? "[scene]" : "body '" + owner_name + "'";
    const toml::node* old = keyed_number(owner, k, key, table_name, &why);
    if (!old) throw InputError(L.source_name, {}, name, why);
    toml::array& arr = *owner.get(k.field)->as_array();
    const auto at = arr.cbegin() + k.component;
    put_number(old, value, [&](auto&& v) { arr.replace(at, std::move(v)); });
}

// lesson_with_values on the lesson's file already read (`file`, a copy edited here).
Lesson with_values(const Lesson& L, const std::map<std::string, double>& values, toml::table file) {
    file.erase("question");  // only the scene is wanted, and questions may hold what_if themselves
    file.erase("vary");      // the ranges are the caller's business (a worksheet draws from them)
    for (const auto& [name, value] : values) set_value(file, name, value, L);
    std::ostringstream text;
    text << file;
    Lesson out = parse_lesson_text(text.str(), L.source_name + " (with " + describe_values(values) + ")", L.file);
    return out;
}

// input_values on the lesson's file already read.
std::map<std::string, double> values_of_inputs(const Lesson& L, const std::map<std::string, double>& inputs,
                                               const toml::table& file) {
    std::map<std::string, double> out = inputs;
    for (const LessonVary& v : L.vary) {
        const auto given = inputs.find(v.name());
        if (given == inputs.end()) continue;
        const KeyParts k = key_parts(v.key);
        for (const std::string& body : v.in_proportion) {
            const std::string other = body + "." + v.key;
            if (inputs.count(other))
                throw InputError(L.source_name, {}, other,
                                 "is given a value, but it changes in proportion with " + v.name() + " (" + v.where +
                                     "): give only " + v.name());
            const toml::table* t = vary_owner(file, body);
            out[other] = (t ? number_in(*t, k) : NAN) * (given->second / v.lesson_value);
        }
    }
    return out;
}

}  // namespace

Lesson lesson_with_values(const Lesson& L, const std::map<std::string, double>& values) {
    return with_values(L, values, parse_toml_text(L.source, L.source_name));
}

std::map<std::string, double> input_values(const Lesson& L, const std::map<std::string, double>& inputs) {
    return values_of_inputs(L, inputs, parse_toml_text(L.source, L.source_name));
}

// The file read once for both (the Try-it panel's every move).
Lesson lesson_with_inputs(const Lesson& L, const std::map<std::string, double>& inputs) {
    toml::table file = parse_toml_text(L.source, L.source_name);
    const std::map<std::string, double> values = values_of_inputs(L, inputs, file);
    return with_values(L, values, std::move(file));
}

}  // namespace collide
