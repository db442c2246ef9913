// A lesson's [teacher] table (docs/formats/lesson-files.md, "The teacher's page"): level,
// prerequisites, time, the misconceptions the lesson targets, questions to ask in class and how
// to run it live. Read here; the teacher's page (present/site_pages.cpp) shows it.
#include <optional>
#include <string>
#include <vector>

#include "scenario/lesson.h"
#include "scenario/lesson_parse.h"
#include "scenario/toml_reader.h"

namespace collide::lesson_parse {

namespace {

std::string required_text(const TableReader& t, const std::string& key, const std::string& what) {
    const std::string s = t.string(key, what).value_or("");
    if (s.find_first_not_of(" \t\r\n") == std::string::npos) t.fail(key, "missing key '" + key + "' (" + what + ")");
    return s;
}

}  // namespace

std::optional<LessonTeacher> parse_teacher(const TableReader& root) {
    if (!root.has("teacher")) return std::nullopt;
    const auto t = root.table("teacher");
    if (!t) root.fail("teacher", "expected a table [teacher]");
    t->allow_only({"level", "prerequisites", "minutes", "live", "misconception", "ask"});
    LessonTeacher T;
    T.level = required_text(*t, "level", "who the lesson is for, e.g. \"first year of university\"");
    if (!t->has("prerequisites"))
        t->fail("prerequisites", "missing key 'prerequisites' (what the students should know first, a list)");
    T.prerequisites = strings(*t, "prerequisites", "a list of prerequisites (strings)");
    if (T.prerequisites.empty()) t->fail("prerequisites", "expected at least one prerequisite");
    for (const std::string& p : T.prerequisites)
        if (p.empty()) t->fail("prerequisites", "expected prerequisites (strings); one of them is empty");
    if (!t->has("minutes")) t->fail("minutes", "missing key 'minutes' (the time the lesson needs in class)");
    const long long m = *t->integer("minutes", "the time the lesson needs in class, in minutes");
    if (m < 1 || m > 600) t->fail("minutes", "expected minutes from 1 to 600, got " + std::to_string(m));
    T.minutes = static_cast<int>(m);
    T.live = required_text(*t, "live", "how to run it live: which input to change, what to look for");
    for (const TableReader& e : t->tables("misconception")) {
        e.allow_only({"belief", "evidence"});
        T.misconceptions.push_back({required_text(e, "belief", "what a student may think"),
                                    required_text(e, "evidence", "what the lesson shows against it")});
    }
    if (T.misconceptions.empty())
        t->fail("misconception", "missing [[teacher.misconception]] (at least one: belief and evidence)");
    for (const TableReader& e : t->tables("ask")) {
        e.allow_only({"question", "listen_for"});
        T.ask.push_back({required_text(e, "question", "a question to ask the class"),
                         e.string("listen_for", "what a good answer contains (text)").value_or("")});
    }
    if (T.ask.empty()) t->fail("ask", "missing [[teacher.ask]] (at least one question to ask in class)");
    return T;
}

}  // namespace collide::lesson_parse
