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
#include <sstream>

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

// The keys a question of each kind may have (anything else is refused by name).
const std::vector<std::string>& question_keys() {
    static const std::vector<std::string> keys = {"kind", "text", "quantity", "event", "pair", "collision", "body",
                                                  "explain", "at", "about", "tolerance", "choices", "correct",
                                                  "reasons", "answer", "what_if"};
    return keys;
}

// Keys that mean nothing on this question: "'reasons' is for choice and predict questions;
// this one is a numeric question".
void forbid_on(const TableReader& q, const std::string& kind, const std::vector<std::string>& keys,
               const std::string& for_what) {
    const std::string article = kind == "explain" ? "an " : "a ";
    for (const std::string& k : keys)
        q.forbid(k, "'" + k + "' is " + for_what + "; this one is " + article + kind + " question");
}

// The engine quantity of a question and what it needs (event, body, at, about), checked
// against the lesson's scene.
void parse_quantity(const TableReader& q, const Lesson& L, LessonQuestion& Q) {
    const std::string name = read_choice(q, "quantity", lesson_quantities(), "quantity", "");
    Q.quantity = quantity_named(name);
    const QuantityInfo info = quantity_info(*Q.quantity);
    if (info.needs_event && q.has("pair")) {
        // The collision by its bodies: `pair` (a, then b) and `collision` (which of theirs).
        q.forbid("event", "'event' (a collision of the run) and 'pair' (a collision of two bodies) name it twice");
        Q.pair = strings(q, "pair", "two body names, a then b");
        if (Q.pair.size() != 2)
            q.fail("pair", "expected two body names, a then b, got " + std::to_string(Q.pair.size()));
        Q.pair_a = body_named(L.scene, Q.pair[0], q, "pair");
        Q.pair_b = body_named(L.scene, Q.pair[1], q, "pair");
        if (Q.pair_a == Q.pair_b) q.fail("pair", "a and b are the same body '" + Q.pair[0] + "'");
        for (const LessonFigure& f : L.figures)
            if (f.ia == Q.pair_b && f.ib == Q.pair_a)
                q.fail("pair", f.key + " calls '" + f.a + "' a and '" + f.b +
                                   "' b: one lesson gives a pair of bodies one pair of roles");
        const long long k = q.integer("collision", "which collision of the pair, from 1").value_or(1);
        if (k < 1 || k > 1000000) q.fail("collision", "expected a collision number from 1, got " + std::to_string(k));
        Q.collision = static_cast<int>(k);
    } else if (info.needs_event) {
        const long long e = q.integer("event", "a collision number, from 1").value_or(1);
        if (e < 1 || e > 1000000) q.fail("event", "expected a collision number from 1");
        Q.event = static_cast<int>(e);
        q.forbid("collision", "'collision' counts the collisions of a 'pair'; give the pair, or 'event' alone");
    } else {
        q.forbid("event", "'" + name + "' is about the whole run, not one collision");
        q.forbid("pair", "'" + name + "' is about the whole run, not one collision");
        q.forbid("collision", "'" + name + "' is about the whole run, not one collision");
    }
    if (info.needs_body) {
        Q.body = q.string("body", "a body's name").value_or("");
        if (Q.body.empty()) q.fail("body", "missing key 'body' ('" + name + "' is a body's)");
        body_named(L.scene, Q.body, q, "body");
    } else {
        q.forbid("body", "'" + name + "' is not about one body");
    }
    if (info.needs_penalty && !L.penalty)
        q.fail("quantity", "'" + name + "' is answered by the penalty contact: add a [penalty] table");
    if (info.angular && L.scene.dimension == 1)
        q.fail("quantity", "bodies on a line do not spin (no angular quantities in 1D)");
    if (info.point == QuantityPoint::at) Q.at = read_vec(q, "at", L.scene.dimension, "m");
    else q.forbid("at", "'at' (a point of the body) is for point_velocity_before and _after");
    if (info.point == QuantityPoint::about) Q.about = read_vec(q, "about", L.scene.dimension, "m");
    else q.forbid("about", "'about' (a fixed point) is for angular_momentum_before and _after");
    if (q.has("tolerance")) {
        Q.tolerance = *q.number("tolerance", "a relative tolerance (0.02 for 2 %)");
        if (!(Q.tolerance > 0 && Q.tolerance < 1))
            q.fail("tolerance", "expected a relative tolerance > 0 and < 1 (0.02 for 2 %), got " + show(Q.tolerance));
    }
}

// A list of 1 to `most` non-empty strings.
std::vector<std::string> text_list(const TableReader& q, const std::string& key, const std::string& what) {
    std::vector<std::string> out = strings(q, key, what);
    for (const std::string& s : out)
        if (s.empty()) q.fail(key, "expected " + what + "; one of them is empty");
    return out;
}

// `choices`, `correct` and `reasons`: 2 to 6 options, the right one among them, and a reason
// for each (why it is right or wrong: what a student who picks it needs to read).
void parse_choices(const TableReader& q, LessonQuestion& Q) {
    if (!q.has("choices")) q.fail("choices", "missing key 'choices' (2 to 6 options, as a list of strings)");
    Q.choices = text_list(q, "choices", "a list of 2 to 6 options (strings)");
    if (Q.choices.size() < 2 || Q.choices.size() > 6)
        q.fail("choices", "expected 2 to 6 options, got " + std::to_string(Q.choices.size()));
    if (!q.has("correct")) q.fail("correct", "missing key 'correct' (the right option's number, from 1)");
    const long long k = *q.integer("correct", "the right option's number, from 1");
    if (k < 1 || k > static_cast<long long>(Q.choices.size()))
        q.fail("correct", "expected an option's number from 1 to " + std::to_string(Q.choices.size()) + ", got " +
                              std::to_string(k));
    Q.correct = static_cast<int>(k);
    if (!q.has("reasons"))
        q.fail("reasons", "missing key 'reasons' (one for each choice: why it is right or wrong)");
    Q.reasons = text_list(q, "reasons", "a list of reasons (strings), one for each choice");
    if (Q.reasons.size() != Q.choices.size())
        q.fail("reasons", "expected one reason for each of the " + std::to_string(Q.choices.size()) +
                              " choices, got " + std::to_string(Q.reasons.size()));
}

// `what_if = { "A.mass" = 4.0 }`: each value a number; the lesson with them must load (its
// errors are given at the what_if key, since the changed file has no lines of its own).
void parse_what_if(const TableReader& q, const Lesson& L, LessonQuestion& Q) {
    const toml::table* t = q.node("what_if")->as_table();
    if (!t || t->empty())
        q.fail("what_if", "expected a table of values, e.g. what_if = { \"A.mass\" = 4.0, \"scene.restitution\" = 1.0 }");
    const TableReader w(*t, q.file(), q.full_key("what_if"));
    for (auto&& [k, v] : *t) {
        const std::string key(k.str());
        Q.what_if[key] = *w.number(key, "a number (the value " + key + " takes in this question)");
    }
    try {
        lesson_with_values(L, Q.what_if);
    } catch (const InputError& e) {
        q.fail("what_if", "the lesson with these values is refused: " + e.key() + ": " + e.message());
    }
}

// One [[question]] table, by its kind (README.md, "Lessons").
LessonQuestion parse_question(const TableReader& q, const Lesson& L) {
    q.allow_only(question_keys());
    LessonQuestion Q;
    const std::string kind = read_choice(q, "kind", {"numeric", "predict", "choice", "explain"}, "kind", "numeric");
    Q.kind = kind == "predict" ? QuestionKind::predict
             : kind == "choice" ? QuestionKind::choice
             : kind == "explain" ? QuestionKind::explain
                                 : QuestionKind::numeric;
    Q.text = q.string("text", "the question (text)").value_or("");
    if (Q.text.empty()) q.fail("text", "missing key 'text'");
    Q.explain = q.string("explain", "why (text)").value_or("");
    const std::vector<std::string> choice_keys = {"choices", "correct", "reasons"};
    const std::vector<std::string> quantity_keys = {"quantity", "event", "pair", "collision", "body", "at", "about", "tolerance"};
    if (Q.kind != QuestionKind::explain) forbid_on(q, kind, {"answer"}, "the model answer of an explain question");
    if (Q.kind != QuestionKind::numeric) forbid_on(q, kind, {"what_if"}, "for numeric questions");
    switch (Q.kind) {
    case QuestionKind::numeric:
        forbid_on(q, kind, choice_keys, "for choice and predict questions");
        parse_quantity(q, L, Q);
        if (q.has("what_if")) parse_what_if(q, L, Q);
        break;
    case QuestionKind::predict:
        if (q.has("quantity") == q.has("choices"))
            q.fail(q.has("quantity") ? "choices" : "quantity",
                   "a predict question has either 'choices' (with 'correct' and 'reasons') or a 'quantity' the "
                   "engine answers, not both and not neither");
        if (q.has("quantity")) {
            for (const std::string& k : choice_keys)
                q.forbid(k, "'" + k + "' goes with 'choices'; this predict question has a 'quantity' instead");
            parse_quantity(q, L, Q);
        } else {
            for (const std::string& k : quantity_keys)
                q.forbid(k, "'" + k + "' goes with 'quantity'; this predict question has 'choices' instead");
            parse_choices(q, Q);
        }
        if (Q.explain.empty()) q.fail("explain", "missing key 'explain' (why it happens: shown when the student checks the prediction)");
        break;
    case QuestionKind::choice:
        forbid_on(q, kind, quantity_keys, "for numeric and predict questions");
        parse_choices(q, Q);
        break;
    case QuestionKind::explain:
        forbid_on(q, kind, quantity_keys, "for numeric and predict questions");
        forbid_on(q, kind, choice_keys, "for choice and predict questions");
        q.forbid("explain", "an explain question's model answer is its 'answer' (write it there)");
        Q.answer = q.string("answer", "the model answer (text)").value_or("");
        if (Q.answer.empty()) q.fail("answer", "missing key 'answer' (the model answer an explain question shows)");
        break;
    }
    return Q;
}

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

// [[vary]]: the ranges a worksheet draws each student's values from.
void parse_vary(const TableReader& root, const toml::table& file, Lesson& L) {
    const toml::node* list = root.node("vary");
    if (!list) return;
    const toml::array* vs = list->as_array();
    if (!vs) root.fail("vary", "expected [[vary]] tables");
    for (std::size_t i = 0; i < vs->size(); ++i) {
        const toml::table* t = vs->get(i)->as_table();
        const std::string key = "vary[" + std::to_string(i + 1) + "]";
        if (!t) root.fail("vary", key + " is not a table; write [[vary]]");
        LessonVary V = parse_vary_entry(TableReader(*t, root.file(), key), file, L);
        V.where = key;
        L.vary.push_back(std::move(V));
    }
}

}  // namespace

std::size_t LessonVary::count() const {
    // A hair of slack: 0.1 steps from 1.0 to 4.0 are 30, though 3.0 / 0.1 is 29.999...
    return static_cast<std::size_t>(std::floor((hi - lo) / step + 1e-9)) + 1;
}

double LessonVary::value(std::size_t k) const {
    const double x = lo + static_cast<double>(k) * step;
    return std::round(x * 1e9) / 1e9;
}

const char* question_kind_name(QuestionKind kind) {
    switch (kind) {
    case QuestionKind::numeric: return "numeric";
    case QuestionKind::predict: return "predict";
    case QuestionKind::choice: return "choice";
    case QuestionKind::explain: return "explain";
    }
    return "numeric";
}

const std::vector<std::string>& lesson_tables() {
    static const std::vector<std::string> tables = {"lesson", "question", "variant", "penalty", "figure", "vary"};
    return tables;
}

Lesson load_lesson(const std::string& path) {
    std::string name;
    const std::string text = read_input_file(path, &name);
    return parse_lesson_text(text, name, path);
}

Lesson parse_lesson_text(const std::string& text, const std::string& name, const std::string& path) {
    Lesson L;
    L.file = path;
    L.source = text;
    L.source_name = name;
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
            v.allow_only({"label", "restitution", "friction", "model", "restitution_law", "policy"});
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
                parse_model(read_choice(v, "model", {"frictionless", "coulomb", "matrix", "stick", "page-listing", "routh"},
                                        "model", ""),
                            &V.scene.model);
            if (v.has("restitution_law")) {
                if (V.scene.model != Model::routh)
                    v.fail("restitution_law", "applies to model = \"routh\" only (the other models use Newton's law)");
                parse_restitution_law(
                    read_choice(v, "restitution_law", {"newton", "poisson", "stronge"}, "restitution_law", ""),
                    &V.scene.restitution_law);
            }
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
        for (std::size_t i = 0; i < fs->size(); ++i) {
            const toml::table* t = fs->get(i)->as_table();
            const std::string key = "figure[" + std::to_string(i + 1) + "]";
            if (!t) root.fail("figure", key + " is not a table; write [[figure]]");
            const TableReader f(*t, name, key);
            f.allow_only({"a", "b", "collision", "caption", "touching"});
            LessonFigure F;
            F.key = key;
            F.pos = f.table_pos();
            const auto body = [&](const char* role, std::size_t* index) {
                const std::string who = f.string(role, "a body's name").value_or("");
                if (who.empty())
                    f.fail(role, std::string("missing key '") + role + "' (the body the figure calls " + role + ")");
                *index = body_named(L.scene, who, f, role);
                return who;
            };
            F.a = body("a", &F.ia);
            F.b = body("b", &F.ib);
            if (F.ia == F.ib) f.fail("b", "a and b are the same body '" + F.a + "'");
            const long long k = f.integer("collision", "which collision of a and b, from 1").value_or(1);
            if (k < 1 || k > 1000000) f.fail("collision", "expected a collision number from 1, got " + std::to_string(k));
            F.collision = static_cast<int>(k);
            F.caption = f.string("caption", "the figure's caption (text)").value_or("");
            F.touching = f.boolean("touching").value_or(false);
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

    parse_vary(root, table, L);

    if (const toml::node* list = root.node("question")) {
        const toml::array* qs = list->as_array();
        if (!qs) root.fail("question", "expected [[question]] tables");
        constexpr int kMaxWhatIfs = 20;
        int what_ifs = 0;
        for (std::size_t i = 0; i < qs->size(); ++i) {
            const toml::table* t = qs->get(i)->as_table();
            const std::string key = "question[" + std::to_string(i + 1) + "]";
            if (!t) root.fail("question", key + " is not a table; write [[question]]");
            const TableReader q(*t, name, key);
            // Each what-if reads the whole file again (and its answer runs the scene again):
            // a bound keeps a lesson's cost linear in its size.
            if (q.has("what_if") && ++what_ifs > kMaxWhatIfs)
                q.fail("what_if", "a lesson may have at most " + std::to_string(kMaxWhatIfs) + " what-if questions");
            L.questions.push_back(parse_question(q, L));
        }
    }
    return L;
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
        else
            owner.insert_or_assign(name, value);
    }
    std::ostringstream text;
    text << file;
    Lesson out = parse_lesson_text(text.str(), L.source_name + " (with " + describe_values(values) + ")", L.file);
    return out;
}

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
