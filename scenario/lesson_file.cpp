// The lesson file (docs/formats/lesson-files.md): the [lesson] table, [[variant]], [[figure]] and
// [penalty] read here; [[question]] in lesson_question.cpp, [[vary]] in lesson_values.cpp.
#include "scenario/lesson.h"

#include <cctype>
#include <string>
#include <utility>
#include <vector>

#include "scenario/lesson_parse.h"
#include "scenario/toml_reader.h"

namespace collide {

namespace lesson_parse {

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

}  // namespace lesson_parse

using lesson_parse::parse_question;
using lesson_parse::parse_vary;
using lesson_parse::strings;

const std::vector<std::string>& lesson_tables() {
    static const std::vector<std::string> tables = {"lesson", "question", "variant", "penalty",
                                                    "figure", "vary",     "teacher", "plot"};
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
    const toml::table table = parse_toml_text(text, name);  // read once: the scene and the lesson's tables
    L.scene = parse_scene_table(table, name, &L.view, lesson_tables());
    const TableReader root(table, name, "");
    const auto lt = root.table("lesson");
    if (!lt)
        root.fail("",
                  "missing table [lesson] (a scenario file without one is run with "
                  "'collide step' or 'collide render FILE')");
    lt->allow_only({"id", "order", "title", "section", "goals", "setup", "explanation", "teacher_notes", "label"});
    L.id = lt->string("id", "a lesson id (letters, digits and -)").value_or("");
    if (L.id.empty()) lt->fail("id", "missing key 'id' (used as `collide render ID`)");
    for (char ch : L.id)
        if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '-'))
            lt->fail("id", "a lesson id has letters, digits and - only, got '" + L.id + "'");
    L.order = static_cast<int>(lt->integer("order", "the lesson's position in the list").value_or(0));
    L.title = lt->line("title", "the lesson's title").value_or("");
    if (L.title.empty()) lt->fail("title", "missing key 'title'");
    L.section = lt->line("section", "the page's section it teaches").value_or("");
    L.goals = strings(*lt, "goals", "a list of learning goals (strings)");
    L.setup = lt->string("setup", "the set-up: the givens (text)").value_or("");
    L.explanation = lt->string("explanation", "the explanation (text)").value_or("");
    L.teacher_notes = lt->string("teacher_notes", "notes for the teacher (text)").value_or("");
    if (L.scene.title.empty()) L.scene.title = L.title;
    L.label = lt->string("label", "the scene's label beside its variants").value_or("");
    L.teacher = lesson_parse::parse_teacher(root);

    // [[variant]]: the scene again with other scene-wide settings.
    for (const TableReader& v : root.tables("variant")) {
        v.allow_only({"label", "restitution", "friction", "model", "restitution_law", "policy"});
        LessonVariant V{v.string("label", "the variant's label").value_or(""), L.scene};
        if (V.label.empty()) v.fail("label", "missing key 'label' (shown under its panels)");
        if (v.has("restitution")) {
            const double e = *v.number("restitution", "a coefficient of restitution");
            if (e < 0 || e > 1)
                v.fail("restitution", "expected a coefficient of restitution in [0, 1], got " + show(e));
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
        if (V.scene.model == Model::page_listing && (V.scene.dimension != 3 || V.scene.policy != Policy::sequential))
            v.fail(v.has("model") ? "model" : "policy",
                   "\"page-listing\" (the page's listing, 3D code answering one point at a time) runs only "
                   "in 3D scenes with policy = \"sequential\"");
        L.variants.push_back(std::move(V));
    }

    // [[figure]]: the collisions the lesson is about, with the roles a and b it gives them.
    for (const TableReader& f : root.tables("figure")) {
        f.allow_only({"a", "b", "collision", "caption", "touching"});
        LessonFigure F;
        F.key = f.prefix();
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

    // [penalty]: the first collision again with a spring-damper contact (1D).
    if (root.has("penalty")) {
        const auto pt = root.table("penalty");
        if (!pt) root.fail("penalty", "expected a table [penalty]");
        if (L.scene.dimension != 1) pt->fail("", "the penalty contact is on a line: [penalty] needs dimension = 1");
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
    lesson_parse::parse_plots(root, L);

    constexpr int kMaxWhatIfs = 20;
    int what_ifs = 0;
    for (const TableReader& q : root.tables("question")) {
        // Each what-if reads the whole file again (and its answer runs the scene again):
        // a bound keeps a lesson's cost linear in its size.
        if (q.has("what_if") && ++what_ifs > kMaxWhatIfs)
            q.fail("what_if", "a lesson may have at most " + std::to_string(kMaxWhatIfs) + " what-if questions");
        L.questions.push_back(parse_question(q, L));
    }
    return L;
}

}  // namespace collide
