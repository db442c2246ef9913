// A lesson's answers, from its run (engine/record.h): what each question asks, computed by the
// engine's functions from the recorded collision or final state; and the lesson as Markdown.
#include "teach/answers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>

#include "engine/diagnostics.h"
#include "teach/event_problem.h"
#include "teach/lesson_penalty.h"
#include "teach/notation.h"
#include "teach/solve.h"

namespace collide {

// ---- Answers ----

namespace {

// The two bodies' total linear momentum and angular momentum about `about` (a fixed point),
// with the velocities before or after the impulse; static bodies left out (diagnostics.h).
std::pair<Vec3, Vec3> pair_momenta(const Scene& scene, const CollisionInstant& c, bool after, const Vec3& about) {
    const SolveProblem p = collision_problem(scene, c);
    const Vec3 va = after ? c.va_after : c.before_a.v, wa = after ? c.wa_after : c.before_a.w;
    const Vec3 vb = after ? c.vb_after : c.before_b.v, wb = after ? c.wb_after : c.before_b.w;
    if (scene.dimension == 1) {
        Body1 a = p.a.b1, b = p.b.b1;
        a.v = va.x();
        b.v = vb.x();
        return {Vec3(totals(std::vector<Body1>{a, b}).momentum, 0, 0), Vec3::Zero()};
    }
    if (scene.dimension == 2) {
        Body2 a = p.a.b2, b = p.b.b2;
        a.v = va.head<2>();
        a.w = wa.z();
        b.v = vb.head<2>();
        b.w = wb.z();
        const Totals2 t = totals(std::vector<Body2>{a, b}, about.head<2>());
        return {Vec3(t.momentum.x(), t.momentum.y(), 0), Vec3(0, 0, t.angular_momentum)};
    }
    Body3 a = p.a.b3, b = p.b.b3;
    a.v = va;
    a.w = wa;
    b.v = vb;
    b.w = wb;
    const Totals3 t = totals(std::vector<Body3>{a, b}, about);
    return {t.momentum, t.angular_momentum};
}

using collide::lift;
Vec3 lift(double x) { return lift_line(x); }  // a 1D value along x
Vec3 spin_of(const Body1&) { return Vec3::Zero(); }
Vec3 spin_of(const Body2& b) { return Vec3(0, 0, b.w); }
Vec3 spin_of(const Body3& b) { return b.w; }

// A question without a quantity: its answer is the lesson's own text.
LessonAnswer written_answer(const LessonQuestion& q) {
    LessonAnswer a;
    a.computed = false;
    a.text = q.has_choices() ? "option " + option_number(static_cast<std::size_t>(q.correct - 1)) : q.answer;
    return a;
}

// A what-if question: the same question asked of the lesson run again with its values.
LessonAnswer what_if_answer(const Lesson& L, const LessonQuestion& q, std::size_t qi) {
    const std::string where = "question[" + std::to_string(qi + 1) + "].what_if";
    Lesson changed = lesson_with_values(L, q.what_if);
    LessonQuestion plain = q;
    plain.what_if.clear();
    changed.questions = {plain};
    try {
        return answer_questions(changed).front();
    } catch (const InputError& e) {
        std::string values;
        for (const auto& [key, value] : q.what_if)
            values += (values.empty() ? "" : ", ") + key + " = " + notation::num_text(value);
        throw InputError(L.file, {}, where, "with " + values + ": " + e.message());
    }
}

// The switch over quantities below has no default: a quantity without its case does not
// compile (the warning is made an error here, in builds without COLLIDE_WERROR too).
#pragma GCC diagnostic push
#pragma GCC diagnostic error "-Wswitch"
template <int D>
std::vector<LessonAnswer> answer(const Lesson& L, const Recording<D>& run, const AnyRecording& record,
                                 const PenaltyStudy* given) {
    const Scene& scene = L.scene;
    const auto& events = run.events;
    const auto& final_bodies = run.states.back();  // at the run's last sampled instant
    // Event k with the bodies where they touch (once per event however many questions ask).
    std::map<std::size_t, CollisionInstant> instants;
    const auto instant = [&](std::size_t k) -> const CollisionInstant& {
        if (auto it = instants.find(k); it != instants.end()) return it->second;
        // In the lesson's roles: a [[figure]] naming this pair says which body is a (a
        // question's `pair` gives the same roles: the lesson refuses others).
        CollisionInstant c = collision_instant(events[k]);
        for (const LessonFigure& f : L.figures) c = with_roles(c, f.ia, f.ib);
        return instants.emplace(k, c).first->second;
    };
    const auto body_index = [&](const std::string& name) {
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
            if (scene.bodies[i].name == name) return i;
        return scene.bodies.size();
    };

    // [penalty]: the study given, or made once when a question asks.
    std::optional<PenaltyStudy> made;
    const auto study = [&]() -> const PenaltyStudy& {
        if (given) return *given;
        if (!made) made = penalty_study(L, record);
        return *made;
    };
    std::vector<LessonAnswer> out;
    for (std::size_t qi = 0; qi < L.questions.size(); ++qi) {
        const LessonQuestion& q = L.questions[qi];
        if (!q.has_quantity()) {
            out.push_back(written_answer(q));
            continue;
        }
        if (!q.what_if.empty()) {
            out.push_back(what_if_answer(L, q, qi));
            continue;
        }
        const Quantity quantity = *q.quantity;
        const QuantityInfo info = quantity_info(quantity);
        const std::string where = "question[" + std::to_string(qi + 1) + "]";
        LessonAnswer a;
        a.unit = info.unit;
        const std::size_t body = info.needs_body ? body_index(q.body) : 0;
        // The collision an event quantity is of (k: its index in the run), with the body's side.
        std::size_t k = 0;
        CollisionInstant c;
        bool is_a = false;
        if (info.needs_event) {
            k = question_event(L, q, where, events);
            c = instant(k);
            if (q.has_pair()) c = with_roles(c, q.pair_a, q.pair_b);
            if (info.needs_body && body != c.a && body != c.b)
                throw InputError(L.file, {}, where + ".body",
                                 "'" + q.body + "' takes no part in collision " + std::to_string(k + 1) + " (" +
                                     scene.bodies[c.a].name + " and " + scene.bodies[c.b].name + ")");
            is_a = body == c.a;
        }
        // Before or after the impulse: the velocities of the body's side of the collision.
        const Vec3& v_before = is_a ? c.before_a.v : c.before_b.v;
        const Vec3& w_before = is_a ? c.before_a.w : c.before_b.w;
        const Vec3& v_after = is_a ? c.va_after : c.vb_after;
        const Vec3& w_after = is_a ? c.wa_after : c.wb_after;
        // Every quantity has its case (no default: the compiler names a new one left out). A
        // vector quantity's case gives `vec`, read out below as its catalogue entry says.
        Vec3 vec = Vec3::Zero();
        switch (quantity) {
            case Quantity::impulse: vec = c.impulse; break;
            case Quantity::impulse_normal: a.value = c.impulse.dot(c.normal); break;
            case Quantity::velocity_before: vec = v_before; break;
            case Quantity::velocity_after: vec = v_after; break;
            case Quantity::spin_before: vec = w_before; break;
            case Quantity::spin_after: vec = w_after; break;
            case Quantity::kinetic_energy_before: a.value = pair_kinetic_energy(scene, c, false); break;
            case Quantity::kinetic_energy_after: a.value = pair_kinetic_energy(scene, c, true); break;
            case Quantity::energy_lost:
                a.value = pair_kinetic_energy(scene, c, false) - pair_kinetic_energy(scene, c, true);
                break;
            case Quantity::time: a.value = c.t; break;
            case Quantity::slip_stop_impulse: {
                // The event's own problem solved again (the world applied this same impact):
                // the end of the first slip phase when another phase follows it.
                if (scene.model != Model::routh)
                    throw InputError(L.file, {}, where + ".quantity", "'slip_stop_impulse' needs model = \"routh\"");
                const Solution s = solve(collision_problem(scene, c));
                const std::vector<RouthPhase>& ph = s.routh.phases;
                if (ph.size() < 2 || ph[0].kind != RouthPhase::Kind::slip)
                    throw InputError(L.file, {}, where + ".quantity",
                                     "the slip does not stop during collision " + std::to_string(k + 1));
                a.value = ph[0].normal_impulse_to;
                break;
            }
            case Quantity::point_velocity_before:
            case Quantity::point_velocity_after: {
                const bool after = quantity == Quantity::point_velocity_after;
                const Vec3 v = after ? v_after : v_before;
                const Vec3 w = after ? w_after : w_before;
                const Vec3& x = is_a ? c.before_a.x : c.before_b.x;
                vec = v + w.cross(q.at.value_or(c.point) - x);
                break;
            }
            case Quantity::normal_velocity_before:
            case Quantity::normal_velocity_after: {
                const bool after = quantity == Quantity::normal_velocity_after;
                const Vec3 va = after ? c.va_after : c.before_a.v, wa = after ? c.wa_after : c.before_a.w;
                const Vec3 vb = after ? c.vb_after : c.before_b.v, wb = after ? c.wb_after : c.before_b.w;
                const Vec3 u = (vb + wb.cross(c.point - c.before_b.x)) - (va + wa.cross(c.point - c.before_a.x));
                a.value = u.dot(c.normal);
                break;
            }
            case Quantity::momentum_before:
            case Quantity::momentum_after:
                vec = pair_momenta(scene, c, quantity == Quantity::momentum_after, Vec3::Zero()).first;
                break;
            case Quantity::angular_momentum_before:
            case Quantity::angular_momentum_after:
                vec =
                    pair_momenta(scene, c, quantity == Quantity::angular_momentum_after, q.about.value_or(Vec3::Zero()))
                        .second;
                break;
            case Quantity::spin_angular_momentum_before:
            case Quantity::spin_angular_momentum_after: {
                const SolveProblem p = collision_problem(scene, c);
                const Vec3 w = quantity == Quantity::spin_angular_momentum_after ? w_after : w_before;
                const SolveBody& sb = is_a ? p.a : p.b;
                if (scene.bodies[body].is_static()) vec = Vec3::Zero();
                else if (D == 2) vec = Vec3(0, 0, sb.b2.inertia * w.z());
                else vec = sb.b3.inertia_world() * w;
                break;
            }
            case Quantity::collisions: a.value = static_cast<double>(events.size()); break;
            case Quantity::last_collision_time:
                if (events.empty()) throw InputError(L.file, {}, where + ".quantity", "the run has no collision");
                a.value = events.back().t;
                break;
            case Quantity::final_velocity: vec = lift(final_bodies[body].v); break;
            case Quantity::final_spin: vec = spin_of(final_bodies[body]); break;
            case Quantity::final_kinetic_energy: a.value = totals(final_bodies).kinetic_energy; break;
            case Quantity::penalty_damping_ratio: a.value = study().zeta; break;
            case Quantity::penalty_damping: a.value = study().damping; break;
            case Quantity::penalty_contact_time: a.value = study().matched.contact_time; break;
            case Quantity::penalty_peak_force: a.value = study().matched.peak_force; break;
            case Quantity::penalty_max_overlap: a.value = study().matched.max_overlap; break;
            case Quantity::penalty_impulse: a.value = study().matched.impulse; break;
            case Quantity::penalty_restitution: a.value = study().matched.restitution; break;
        }
        if (info.readout == Readout::vector) {
            if (D == 1) {
                a.value = vec.x();
            } else if (D == 2 && info.angular) {
                a.value = vec.z();
            } else {
                a.vector = vec;
                a.value = vec.norm();
                a.is_vector = true;
            }
        }
        // The text: the number (or vector) to 4 significant digits, then the unit. A vector's
        // components below 5e-5 of its largest print as 0: at the 4 digits of the largest they
        // round to 0 (as notation::vec writes vectors for students), and the world finds
        // contacts only to 1e-10 m (World::kTouch) anyway. The value keeps full precision.
        // Four significant digits, as students write them (issue: 3 or 4 in student text).
        const auto n = [](double x, double floor) { return notation::num_answer(std::abs(x) < floor ? 0.0 : x); };
        if (a.is_vector) {
            const double floor = std::max(1e-12, 5e-5 * a.vector.cwiseAbs().maxCoeff());
            a.text = "(" + n(a.vector.x(), floor) + ", " + n(a.vector.y(), floor) +
                     (D == 3 ? ", " + n(a.vector.z(), floor) : "") + ")";
        } else {
            a.text = n(a.value, 1e-12);
        }
        if (!a.unit.empty()) a.text += " " + a.unit;
        out.push_back(a);
    }
    return out;
}
#pragma GCC diagnostic pop

}  // namespace

std::string option_number(std::size_t index) { return std::to_string(index + 1); }

bool shows_tolerance(const LessonQuestion& q) {
    return q.has_quantity() && quantity_info(*q.quantity).readout != Readout::count;
}

double marking_allowance(double want_size, double tolerance) { return tolerance * std::abs(want_size) + 1e-9; }

std::string tolerance_text(double tolerance) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g %%", tolerance * 100);
    return buf;
}

namespace {

// A question's options as a numbered list (indented under its number).
void write_choices(const LessonQuestion& q, std::ostream& out) {
    for (std::size_t k = 0; k < q.choices.size(); ++k)
        out << "   - (" << option_number(k) << ") " << q.choices[k] << "\n";
    out << "\n";
}

// What opens under a question: the answer, then why (each option's reason for choices).
void write_answer(const LessonQuestion& q, const LessonAnswer* a, const char* summary, std::ostream& out) {
    out << "   <details><summary>" << summary << "</summary>\n\n   ";
    if (q.has_choices()) {
        out << "Option " << option_number(static_cast<std::size_t>(q.correct - 1)) << ".\n\n";
        for (std::size_t k = 0; k < q.choices.size(); ++k)
            out << "   - Option " << option_number(k)
                << (static_cast<int>(k) + 1 == q.correct ? " is right: " : " is wrong: ") << q.reasons[k] << "\n";
        if (!q.explain.empty()) out << "\n   " << q.explain << "\n";
    } else {
        out << (a ? a->text : std::string("?"));
        if (!q.explain.empty()) out << ". " << q.explain;
        out << "\n";
    }
    out << "\n   </details>\n\n";
}

// The question's own line: its text, and for a number the tolerance it is marked to.
std::string question_line(const LessonQuestion& q) {
    std::string s = q.text;
    if (shows_tolerance(q)) s += " *(to within " + tolerance_text(q.tolerance) + ")*";
    return s;
}

}  // namespace

void write_lesson_markdown(const Lesson& L, const std::vector<LessonAnswer>& answers, std::ostream& out) {
    out << "# " << L.title << "\n\n";
    if (!L.section.empty()) out << "*The page's section: " << L.section << ".*\n\n";
    if (!L.goals.empty()) {
        out << "## Learning goals\n\n";
        for (const std::string& g : L.goals) out << "- " << g << "\n";
        out << "\n";
    }
    if (!L.setup.empty()) out << "## The set-up\n\n" << L.setup << "\n\n";
    std::vector<std::size_t> predict, others;
    for (std::size_t i = 0; i < L.questions.size(); ++i)
        (L.questions[i].kind == QuestionKind::predict ? predict : others).push_back(i);
    // The questions `which` (indices into L.questions), numbered from 1 under `heading`, each
    // item written by write(question, its answer); nothing when there are none.
    const auto numbered = [&](const std::vector<std::size_t>& which, const char* heading, const auto& write) {
        if (which.empty()) return;
        out << heading;
        for (std::size_t k = 0; k < which.size(); ++k) {
            out << k + 1 << ". ";
            write(L.questions[which[k]], which[k] < answers.size() ? &answers[which[k]] : nullptr);
        }
    };
    // A question as asked: its line, and its choices when it has them.
    const auto ask = [&](const LessonQuestion& q) {
        out << question_line(q) << "\n\n";
        if (q.has_choices()) write_choices(q, out);
    };
    // Predictions before the figure: it shows what happens.
    numbered(predict,
             "## Before you watch\n\nWrite down what you expect before you look at the figure and the animation.\n\n",
             [&](const LessonQuestion& q, const LessonAnswer*) { ask(q); });
    // The figures: the lesson's [[figure]] entries (figure.png, figure-2.png, ...), each with
    // its caption, or the run's first collision.
    if (L.figures.empty()) out << "![before, at and after the first collision](figure.png)\n\n";
    for (std::size_t k = 0; k < L.figures.size(); ++k) {
        const LessonFigure& f = L.figures[k];
        const std::string what =
            f.caption.empty() ? "before, at and after the collision of " + f.a + " and " + f.b : f.caption;
        out << "![" << what << "](figure" << (k == 0 ? std::string() : "-" + std::to_string(k + 1)) << ".png)\n\n";
        if (!f.caption.empty()) out << "*" << f.caption << "*\n\n";
    }
    numbered(predict, "## Check your predictions\n\n", [&](const LessonQuestion& q, const LessonAnswer* a) {
        out << q.text << "\n\n";
        write_answer(q, a, "Check your prediction", out);
    });
    // The explanation after the figures and the predictions checked, as the lesson page has it.
    if (!L.explanation.empty()) out << "## Explanation\n\n" << L.explanation << "\n\n";
    numbered(others, "## Questions\n\n", [&](const LessonQuestion& q, const LessonAnswer* a) {
        ask(q);
        write_answer(q, a, "Answer", out);
    });
    out << "The first collision worked out step by step: [worked-example.md](worked-example.md).\n";
    if (!L.teacher_notes.empty()) out << "\n## For the teacher\n\n" << L.teacher_notes << "\n";
}

std::vector<LessonAnswer> answer_questions(const Lesson& lesson, const AnyRecording& run, const PenaltyStudy* penalty) {
    if (lesson.scene.dimension != static_cast<int>(run.index()) + 1)
        throw std::invalid_argument("answer_questions: the recording is of another dimension");
    return std::visit(
        [&](const auto& r) { return answer<std::decay_t<decltype(r)>::dimension>(lesson, r, run, penalty); }, run);
}

std::vector<LessonAnswer> answer_questions(const Lesson& lesson) {
    return answer_questions(lesson, record_any(lesson.scene, {lesson.scene.duration}));
}

}  // namespace collide
