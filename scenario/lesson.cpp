#include "scenario/lesson.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <type_traits>
#include <variant>
#include <utility>
#include <ostream>

#include <nlohmann/json.hpp>

#include "scenario/toml_reader.h"

#ifndef COLLIDE_LESSONS_DIR
#define COLLIDE_LESSONS_DIR "lessons"
#endif

namespace collide {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> strings(const TableReader& t, const std::string& key, const std::string& what) {
    std::vector<std::string> out;
    const toml::node* n = t.node(key);
    if (!n) return out;
    const toml::array* arr = n->as_array();
    if (!arr) t.fail(key, "expected " + what);
    for (const toml::node& el : *arr) {
        if (!el.is_string()) t.fail(key, "expected " + what);
        out.push_back(*el.value<std::string>());
    }
    return out;
}

}  // namespace

const std::map<std::string, QuantityInfo>& quantity_table() {
    static const std::map<std::string, QuantityInfo> table = {
        {"impulse", {"N s", true, false}},
        {"impulse_normal", {"N s", true, false}},
        {"velocity_before", {"m/s", true, true}},
        {"velocity_after", {"m/s", true, true}},
        {"spin_before", {"rad/s", true, true, true}},
        {"spin_after", {"rad/s", true, true, true}},
        {"point_velocity_before", {"m/s", true, true}},
        {"point_velocity_after", {"m/s", true, true}},
        {"normal_velocity_before", {"m/s", true, false}},
        {"normal_velocity_after", {"m/s", true, false}},
        {"momentum_before", {"kg m/s", true, false}},
        {"momentum_after", {"kg m/s", true, false}},
        {"angular_momentum_before", {"kg m^2/s", true, false, true}},
        {"angular_momentum_after", {"kg m^2/s", true, false, true}},
        {"spin_angular_momentum_before", {"kg m^2/s", true, true, true}},
        {"spin_angular_momentum_after", {"kg m^2/s", true, true, true}},
        {"kinetic_energy_before", {"J", true, false}},
        {"kinetic_energy_after", {"J", true, false}},
        {"energy_lost", {"J", true, false}},
        {"time", {"s", true, false}},
        {"collisions", {"", false, false}},
        {"last_collision_time", {"s", false, false}},
        {"final_velocity", {"m/s", false, true}},
        {"final_spin", {"rad/s", false, true, true}},
        {"final_kinetic_energy", {"J", false, false}},
        {"penalty_damping_ratio", {"", false, false, false, true}},
        {"penalty_damping", {"N s/m", false, false, false, true}},
        {"penalty_contact_time", {"s", false, false, false, true}},
        {"penalty_peak_force", {"N", false, false, false, true}},
        {"penalty_max_overlap", {"m", false, false, false, true}},
        {"penalty_impulse", {"N s", false, false, false, true}},
        {"penalty_restitution", {"", false, false, false, true}},
    };
    return table;
}
const std::vector<std::string>& lesson_tables() {

    static const std::vector<std::string> tables = {"lesson", "question", "variant", "penalty", "figure"};
    return tables;
}

const std::vector<std::string>& lesson_quantities() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        for (const auto& [name, info] : quantity_table()) v.push_back(name);
        return v;
    }();
    return names;
}

Lesson load_lesson(const std::string& path) {
    std::string name;
    const std::string text = read_input_file(path, &name);
    return parse_lesson_text(text, name, path);
}

Lesson parse_lesson_text(const std::string& text, const std::string& name, const std::string& path) {
    Lesson L;
    L.file = path;
    L.scene = parse_scene_text(text, name, &L.view, lesson_tables());
    const toml::table table = parse_toml_text(text, name);
    const TableReader root(table, name, "");
    const auto lt = root.table("lesson");
    if (!lt) root.fail("", "missing table [lesson] (a scenario file without one is run with "
                           "'collide step' or 'collide render FILE')");
    lt->allow_only({"id", "order", "title", "section", "goals", "explanation", "teacher_notes", "label"});
    L.id = lt->string("id", "a lesson id (letters, digits and -)").value_or("");
    if (L.id.empty()) lt->fail("id", "missing key 'id' (used as `collide render ID`)");
    for (char ch : L.id)
        if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '-'))
            lt->fail("id", "a lesson id has letters, digits and - only, got '" + L.id + "'");
    L.order = static_cast<int>(lt->integer("order", "the lesson's position in the list").value_or(0));
    L.title = lt->string("title", "the lesson's title").value_or("");
    if (L.title.empty()) lt->fail("title", "missing key 'title'");
    L.section = lt->string("section", "the page's section it teaches").value_or("");
    L.goals = strings(*lt, "goals", "a list of learning goals (strings)");
    L.explanation = lt->string("explanation", "the explanation (text)").value_or("");
    L.teacher_notes = lt->string("teacher_notes", "notes for the teacher (text)").value_or("");
    if (L.scene.title.empty()) L.scene.title = L.title;
    L.label = lt->string("label", "the scene's label beside its variants").value_or("");

    // [[variant]]: the scene again with other scene-wide settings.
    if (const toml::node* list = root.node("variant")) {
        const toml::array* vs = list->as_array();
        if (!vs) root.fail("variant", "expected [[variant]] tables");
        for (std::size_t i = 0; i < vs->size(); ++i) {
            const toml::table* t = vs->get(i)->as_table();
            const std::string key = "variant[" + std::to_string(i + 1) + "]";
            if (!t) root.fail("variant", key + " is not a table; write [[variant]]");
            const TableReader v(*t, name, key);
            v.allow_only({"label", "restitution", "friction", "model", "policy"});
            LessonVariant V{v.string("label", "the variant's label").value_or(""), L.scene};
            if (V.label.empty()) v.fail("label", "missing key 'label' (shown under its panels)");
            if (v.has("restitution")) {
                const double e = *v.number("restitution", "a coefficient of restitution");
                if (e < 0 || e > 1) v.fail("restitution", "expected a coefficient of restitution in [0, 1], got " + show(e));
                V.scene.restitution = e;
                for (SceneBody& b : V.scene.bodies) b.restitution.reset();  // the variant's e for every pair
            }
            if (v.has("friction")) {
                const double mu = *v.number("friction", "a friction coefficient");
                if (mu < 0) v.fail("friction", "expected a friction coefficient >= 0, got " + show(mu));
                V.scene.friction = mu;
                for (SceneBody& b : V.scene.bodies) b.friction.reset();
            }
            if (v.has("model"))
                parse_model(read_choice(v, "model", {"frictionless", "coulomb", "matrix", "stick", "page-listing"}, "model", ""),
                            &V.scene.model);
            if (v.has("policy"))
                V.scene.policy = read_choice(v, "policy", {"sequential", "simultaneous"}, "policy", "") == "sequential"
                                     ? Policy::sequential
                                     : Policy::simultaneous;
            if (V.scene.model == Model::page_listing &&
                (V.scene.dimension != 3 || V.scene.policy != Policy::sequential))
                v.fail(v.has("model") ? "model" : "policy",
                       "\"page-listing\" (the page's listing, 3D code answering one point at a time) runs only "
                       "in 3D scenes with policy = \"sequential\"");
            L.variants.push_back(std::move(V));
        }
    }

    // [[figure]]: the collisions the lesson is about, with the roles a and b it gives them.
    if (const toml::node* list = root.node("figure")) {
        const toml::array* fs = list->as_array();
        if (!fs) root.fail("figure", "expected [[figure]] tables");
        std::vector<std::string> names;
        for (const SceneBody& b : L.scene.bodies) names.push_back(b.name);
        for (std::size_t i = 0; i < fs->size(); ++i) {
            const toml::table* t = fs->get(i)->as_table();
            const std::string key = "figure[" + std::to_string(i + 1) + "]";
            if (!t) root.fail("figure", key + " is not a table; write [[figure]]");
            const TableReader f(*t, name, key);
            f.allow_only({"a", "b", "collision", "caption"});
            LessonFigure F;
            F.key = key;
            F.pos = f.table_pos();
            const auto body = [&](const char* role, std::size_t* index) {
                const std::string who = f.string(role, "a body's name").value_or("");
                if (who.empty())
                    f.fail(role, std::string("missing key '") + role + "' (the body the figure calls " + role + ")");
                const auto it = std::find(names.begin(), names.end(), who);
                if (it == names.end()) {
                    const std::string hint = closest_match(who, names);
                    f.fail(role, "no body named '" + who + "'" + (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
                }
                *index = static_cast<std::size_t>(it - names.begin());
                return who;
            };
            F.a = body("a", &F.ia);
            F.b = body("b", &F.ib);
            if (F.ia == F.ib) f.fail("b", "a and b are the same body '" + F.a + "'");
            const long long k = f.integer("collision", "which collision of a and b, from 1").value_or(1);
            if (k < 1 || k > 1000000) f.fail("collision", "expected a collision number from 1, got " + std::to_string(k));
            F.collision = static_cast<int>(k);
            F.caption = f.string("caption", "the figure's caption (text)").value_or("");
            for (const LessonFigure& G : L.figures) {
                if ((G.ia == F.ib && G.ib == F.ia))
                    f.fail("a", G.key + " calls '" + G.a + "' a and '" + G.b +
                                    "' b: one lesson gives a pair of bodies one pair of roles");
                if (G.ia == F.ia && G.ib == F.ib && G.collision == F.collision)
                    f.fail("collision", "the same collision as " + G.key);
            }
            L.figures.push_back(std::move(F));
        }
    }

    // [penalty]: the first collision again with a spring-damper contact (1D).
    if (root.has("penalty")) {
        const auto pt = root.table("penalty");
        if (!pt) root.fail("penalty", "expected a table [penalty]");
        if (L.scene.dimension != 1)
            pt->fail("", "the penalty contact is on a line: [penalty] needs dimension = 1");
        pt->allow_only({"stiffness", "damping_ratios", "stiffnesses", "time_step"});
        LessonPenalty P;
        if (!pt->has("stiffness")) pt->fail("stiffness", "missing key 'stiffness' (the spring's k, N/m)");
        P.stiffness = *pt->number("stiffness", "a stiffness (N/m)");
        if (!(P.stiffness > 0)) pt->fail("stiffness", "expected a stiffness > 0 N/m, got " + show(P.stiffness));
        P.damping_ratios = pt->numbers("damping_ratios", 0, "a list of damping ratios")
                               .value_or(std::vector<double>{0.0, 0.1, 0.2, 0.4, 0.7});
        for (double z : P.damping_ratios)
            if (z < 0 || z >= 1)
                pt->fail("damping_ratios", "expected damping ratios in [0, 1) (under-damped), got " + show(z));
        P.stiffnesses = pt->numbers("stiffnesses", 0, "a list of stiffnesses (N/m)")
                            .value_or(std::vector<double>{P.stiffness / 4, P.stiffness, 4 * P.stiffness});
        for (double k : P.stiffnesses)
            if (!(k > 0)) pt->fail("stiffnesses", "expected stiffnesses > 0 N/m, got " + show(k));
        P.time_step = pt->number("time_step", "a time step (s)").value_or(0.0);
        if (pt->has("time_step") && !(P.time_step > 0))
            pt->fail("time_step", "expected a time step > 0 s, got " + show(P.time_step));
        P.pos = P.step_pos = pt->table_pos();
        if (pt->has("time_step")) {
            P.step_pos = pt->pos("time_step");
            P.step_key = "penalty.time_step";
        }
        L.penalty = P;
    }

    if (const toml::node* list = root.node("question")) {
        const toml::array* qs = list->as_array();
        if (!qs) root.fail("question", "expected [[question]] tables");
        for (std::size_t i = 0; i < qs->size(); ++i) {
            const toml::table* t = qs->get(i)->as_table();
            const std::string key = "question[" + std::to_string(i + 1) + "]";
            if (!t) root.fail("question", key + " is not a table; write [[question]]");
            const TableReader q(*t, name, key);
            q.allow_only({"text", "quantity", "event", "body", "explain", "at", "about"});
            LessonQuestion Q;
            Q.text = q.string("text", "the question (text)").value_or("");
            if (Q.text.empty()) q.fail("text", "missing key 'text'");
            Q.quantity = read_choice(q, "quantity", lesson_quantities(), "quantity", "");
            const QuantityInfo& info = quantity_table().at(Q.quantity);
            if (info.needs_event) {
                const long long e = q.integer("event", "a collision number, from 1").value_or(1);
                if (e < 1 || e > 1000000) q.fail("event", "expected a collision number from 1");
                Q.event = static_cast<int>(e);
            } else {
                q.forbid("event", "'" + Q.quantity + "' is about the whole run, not one collision");
            }
            if (info.needs_body) {
                Q.body = q.string("body", "a body's name").value_or("");
                if (Q.body.empty()) q.fail("body", "missing key 'body' ('" + Q.quantity + "' is a body's)");
                bool found = false;
                std::vector<std::string> names;
                for (const SceneBody& b : L.scene.bodies) {
                    names.push_back(b.name);
                    found = found || b.name == Q.body;
                }
                if (!found) {
                    const std::string hint = closest_match(Q.body, names);
                    q.fail("body", "no body named '" + Q.body + "'" +
                                       (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
                }
            } else {
                q.forbid("body", "'" + Q.quantity + "' is not about one body");
            }
            if (info.penalty && !L.penalty)
                q.fail("quantity", "'" + Q.quantity + "' is answered by the penalty contact: add a [penalty] table");
            if (info.angular && L.scene.dimension == 1)
                q.fail("quantity", "bodies on a line do not spin (no angular quantities in 1D)");
            const bool point_velocity = Q.quantity.rfind("point_velocity_", 0) == 0;
            const bool about_point = Q.quantity.rfind("angular_momentum_", 0) == 0;
            if (point_velocity) Q.at = read_vec(q, "at", L.scene.dimension, "m");
            else q.forbid("at", "'at' (a point of the body) is for point_velocity_before and _after");
            if (about_point) Q.about = read_vec(q, "about", L.scene.dimension, "m");
            else q.forbid("about", "'about' (a fixed point) is for angular_momentum_before and _after");
            Q.explain = q.string("explain", "how to get there (text)").value_or("");
            L.questions.push_back(std::move(Q));
        }
    }
    return L;
}

std::string lessons_dir() {
    if (const char* env = std::getenv("COLLIDE_LESSONS")) return env;
    return COLLIDE_LESSONS_DIR;
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
    if (fs::is_regular_file(id_or_file, ec) || id_or_file == "-") return id_or_file;
    // The file named after the id (NN-id.toml) when it holds that lesson: then one file is
    // read, and a mistake in another lesson does not stop this one.
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
        const std::string stem = e.path().stem().string();
        const bool named = stem == id_or_file ||
                           (stem.size() > id_or_file.size() &&
                            stem.compare(stem.size() - id_or_file.size() - 1, std::string::npos, "-" + id_or_file) == 0);
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
    throw InputError(id_or_file, {}, "",
                     "no such file, and no lesson with this id" +
                         (hint.empty() ? std::string(" (collide lessons lists them)")
                                       : "; did you mean '" + hint + "'?"));
}

Scene load_scenario(const std::string& arg, SceneView* view, std::optional<Lesson>* lesson) {
    const std::string file = resolve_lesson(arg, lessons_dir());
    std::string name;
    const std::string text = read_input_file(file, &name);
    if (parse_toml_text(text, name).contains("lesson")) {
        Lesson L = load_lesson(file);
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
            out << nlohmann::ordered_json{{"id", L.id}, {"order", L.order}, {"title", L.title},
                                          {"section", L.section}, {"dimension", L.scene.dimension},
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
