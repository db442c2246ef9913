#include "teach/worksheet.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "engine/record.h"
#include "teach/event_problem.h"
#include "teach/notation.h"

namespace collide {

namespace {

// FNV-1a of the lesson id: two lessons drawn with one seed get different numbers.
std::uint64_t fnv1a(const std::string& s) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const char c : s) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001b3ULL;
    }
    return h;
}

bool has_digit(const std::string& s) {
    return std::any_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
}

// "A.mass = 2, B.v = 0.5": values in a message.
std::string describe(const std::map<std::string, double>& values) {
    std::string s;
    for (const auto& [key, value] : values) s += (s.empty() ? "" : ", ") + key + " = " + notation::num_text(value);
    return s;
}

// The collisions the asked questions name, as numbers of the run's collisions from 1 (each
// once, in order; the first when none does). Throws InputError when the run lacks one.
template <class Event>
std::vector<int> asked_events(const Lesson& L, const std::vector<std::size_t>& asked, const std::vector<Event>& run) {
    std::vector<int> events;
    for (std::size_t i : asked) {
        const LessonQuestion& q = L.questions[i];
        if (!q.has_quantity() || !quantity_info(*q.quantity).needs_event) continue;
        const int k = static_cast<int>(question_event(L, q, "question[" + std::to_string(i + 1) + "]", run)) + 1;
        if (std::find(events.begin(), events.end(), k) == events.end()) events.push_back(k);
    }
    if (events.empty()) events.push_back(1);
    std::sort(events.begin(), events.end());
    return events;
}

// The student's lesson run once: the answers and the collisions worked out. Throws
// InputError when the run cannot answer (no collision, too few).
void answer_sheet(const Lesson& original, StudentSheet& s) {
    const AnyRecording run = record_any(s.lesson.scene, {s.lesson.scene.duration});
    s.answers = answer_questions(s.lesson, run);
    s.worked.clear();
    std::visit(
        [&](const auto& r) {
            for (int k : asked_events(original, s.asked, r.events)) {
                if (static_cast<std::size_t>(k) > r.events.size())
                    throw InputError(original.file, {}, "vary",
                                     r.events.empty()
                                         ? "the run has no collision"
                                         : "the run has " + std::to_string(r.events.size()) +
                                               " collisions, a question asks for collision " + std::to_string(k));
                CollisionInstant c = collision_instant(r.events[static_cast<std::size_t>(k - 1)]);
                for (const LessonFigure& f : s.lesson.figures) c = with_roles(c, f.ia, f.ib);
                for (std::size_t i : s.asked) {  // a question's pair gives the same roles
                    const LessonQuestion& q = original.questions[i];
                    if (q.has_pair()) c = with_roles(c, q.pair_a, q.pair_b);
                }
                WorkedCollision w;
                w.event = k;
                w.a = c.a;
                w.b = c.b;
                w.t = c.t;
                w.problem = collision_problem(s.lesson.scene, c);
                w.solution = solve(w.problem);
                s.worked.push_back(std::move(w));
            }
        },
        run);
}

}  // namespace

std::uint64_t splitmix64(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

std::vector<std::size_t> worksheet_questions(const Lesson& L) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < L.questions.size(); ++i) {
        const LessonQuestion& q = L.questions[i];
        const bool numeric = q.kind == QuestionKind::numeric && q.what_if.empty();
        const bool words = (q.kind == QuestionKind::choice || q.kind == QuestionKind::explain) && !has_digit(q.text);
        if (numeric || words) out.push_back(i);
    }
    return out;
}

int question_number(const Lesson& L, std::size_t index) {
    const bool predict = L.questions[index].kind == QuestionKind::predict;
    int k = 0;
    for (std::size_t i = 0; i <= index; ++i)
        if ((L.questions[i].kind == QuestionKind::predict) == predict) ++k;
    return k;
}

StudentSheet draw_student(const Lesson& L, std::uint64_t seed, int student) {
    // One stream per (seed, lesson, student): a student's numbers do not depend on how many
    // students the class has or on how many draws another student needed.
    std::uint64_t mix = seed;
    std::uint64_t state = splitmix64(mix) ^ fnv1a(L.id);
    state += static_cast<std::uint64_t>(student) * 0xd1b54a32d192ed03ULL;
    splitmix64(state);
    StudentSheet s;
    s.student = student;
    s.asked = worksheet_questions(L);
    std::string last_error;
    for (int attempt = 1; attempt <= kWorksheetTries; ++attempt) {
        s.tries = attempt;
        s.values.clear();
        for (const LessonVary& v : L.vary) s.values[v.name()] = v.value(splitmix64(state) % v.count());
        try {
            s.lesson = lesson_with_inputs(L, s.values);
            s.lesson.questions.clear();
            for (std::size_t i : s.asked) s.lesson.questions.push_back(L.questions[i]);
            answer_sheet(L, s);
            return s;
        } catch (const InputError& e) {
            last_error = e.message();
        } catch (const std::invalid_argument& e) {  // a world refusing the scene
            last_error = e.what();
        }
        if (L.vary.empty()) break;  // the same values every time: no point in drawing again
    }
    std::string keys;
    for (const LessonVary& v : L.vary) keys += (keys.empty() ? "" : ", ") + v.name();
    throw InputError(L.file, L.vary.empty() ? SourcePos{} : L.vary.front().pos, "vary",
                     "no draw of " + (keys.empty() ? std::string("the lesson's values") : keys) + " in " +
                         std::to_string(s.tries) + " tries gives a run that answers the questions (student " +
                         std::to_string(student) + "; the last: " + describe(s.values) + ": " + last_error +
                         "); narrow the ranges");
}

}  // namespace collide
