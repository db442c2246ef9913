// A lesson's [[question]] tables (docs/formats/lesson-files.md, "Questions"): each by its kind, and a
// numeric one's quantity checked against the catalogue (scenario/lesson_quantity.h) and the
// lesson's scene.
#include "scenario/lesson.h"

#include <string>
#include <vector>

#include "scenario/lesson_parse.h"
#include "scenario/toml_reader.h"

namespace collide {

using lesson_parse::strings;

namespace {

// The keys a question of each kind may have (anything else is refused by name).
const std::vector<std::string>& question_keys() {
    static const std::vector<std::string> keys = {"kind",    "text",    "quantity", "event",  "pair",      "collision",
                                                  "body",    "explain", "at",       "about",  "tolerance", "choices",
                                                  "correct", "reasons", "answer",   "what_if"};
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
    if (!q.has("reasons")) q.fail("reasons", "missing key 'reasons' (one for each choice: why it is right or wrong)");
    Q.reasons = text_list(q, "reasons", "a list of reasons (strings), one for each choice");
    if (Q.reasons.size() != Q.choices.size())
        q.fail("reasons", "expected one reason for each of the " + std::to_string(Q.choices.size()) + " choices, got " +
                              std::to_string(Q.reasons.size()));
}

// `what_if = { "A.mass" = 4.0 }`: each value a number; the lesson with them must load (its
// errors are given at the what_if key, since the changed file has no lines of its own).
void parse_what_if(const TableReader& q, const Lesson& L, LessonQuestion& Q) {
    const toml::table* t = q.node("what_if")->as_table();
    if (!t || t->empty())
        q.fail("what_if",
               "expected a table of values, e.g. what_if = { \"A.mass\" = 4.0, \"scene.restitution\" = 1.0 }");
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

}  // namespace

namespace lesson_parse {

// One [[question]] table, by its kind (docs/formats/lesson-files.md, "Questions").
LessonQuestion parse_question(const TableReader& q, const Lesson& L) {
    q.allow_only(question_keys());
    LessonQuestion Q;
    const std::string kind = read_choice(q, "kind", {"numeric", "predict", "choice", "explain"}, "kind", "numeric");
    Q.kind = kind == "predict"   ? QuestionKind::predict
             : kind == "choice"  ? QuestionKind::choice
             : kind == "explain" ? QuestionKind::explain
                                 : QuestionKind::numeric;
    Q.text = q.string("text", "the question (text)").value_or("");
    if (Q.text.empty()) q.fail("text", "missing key 'text'");
    Q.explain = q.string("explain", "why (text)").value_or("");
    const std::vector<std::string> choice_keys = {"choices", "correct", "reasons"};
    const std::vector<std::string> quantity_keys = {"quantity", "event", "pair",  "collision",
                                                    "body",     "at",    "about", "tolerance"};
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
            if (Q.explain.empty())
                q.fail("explain",
                       "missing key 'explain' (why it happens: shown when the student checks the prediction)");
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

}  // namespace lesson_parse

const char* question_kind_name(QuestionKind kind) {
    switch (kind) {
        case QuestionKind::numeric: return "numeric";
        case QuestionKind::predict: return "predict";
        case QuestionKind::choice: return "choice";
        case QuestionKind::explain: return "explain";
    }
    return "numeric";
}

}  // namespace collide
