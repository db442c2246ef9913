// `collide material`: every bundled lesson renders (a low-resolution smoke run), the site it
// writes is complete and self-contained (every internal link and image resolves, nothing is
// fetched from the network), the answers are on the pages, and bad input writes nothing.
#include "cli/material_cmd.h"
#include "teach/answers.h"
#include "teach/html.h"
#include "present/render_job.h"
#include "present/scene_run.h"
#include "teach/event_problem.h"
#include "teach/notation.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <tuple>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "tests/render/test_util.h"

namespace collide {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

MaterialOptions tiny(const std::string& out) {
    MaterialOptions o;
    o.out_dir = out;
    o.lessons = {"catch-up"};
    o.size = "160x120";
    o.fps = 10;
    o.quiet = true;
    return o;
}

// The site of every bundled lesson as tiny() renders it (a low-resolution smoke run, about 30 s):
// under ctest the fixture material.tiny_site (tests/cli/CMakeLists.txt) renders it once for the
// tests that read it and COLLIDE_TINY_SITE names its directory; run alone, each renders its own
// into `dir`.
fs::path every_lesson_site(const render::test::TempDir& dir) {
    if (const char* shared = std::getenv("COLLIDE_TINY_SITE")) {
        EXPECT_TRUE(fs::exists(fs::path(shared) / "index.html")) << "the fixture's site is missing: " << shared;
        return shared;
    }
    std::ostringstream out, err;
    MaterialOptions o = tiny(dir / "site");
    o.lessons.clear();  // all of them
    EXPECT_EQ(run_material(o, out, err), 0) << err.str();
    return dir / "site";
}

TEST(Material, EveryLessonRendersAndEveryLinkAndImageResolvesOffline) {
    render::test::TempDir dir;
    const fs::path site = every_lesson_site(dir);
    const std::vector<Lesson> all = load_lessons(std::string(COLLIDE_SOURCE_DIR) + "/lessons");
    const std::regex attr(R"re((?:href|src|poster)="([^"]*)")re");
    int pages = 0, links = 0;
    for (const auto& e : fs::recursive_directory_iterator(site)) {
        if (e.path().extension() != ".html") continue;
        ++pages;
        const std::string html = read(e.path());
        EXPECT_EQ(html.find("http://"), std::string::npos) << e.path();
        EXPECT_EQ(html.find("https://"), std::string::npos) << e.path();
        for (std::sregex_iterator m(html.begin(), html.end(), attr), end; m != end; ++m) {
            std::string target = (*m)[1];
            target = target.substr(0, target.find('#'));  // a place in a page: the page
            target = target.substr(0, target.find('?'));  // the page with its inputs set: the page
            EXPECT_EQ(target.find(' '), std::string::npos) << e.path() << " -> " << target;
            ++links;
            EXPECT_TRUE(fs::exists(e.path().parent_path() / target)) << e.path() << " -> " << target;
        }
    }
    EXPECT_EQ(pages, 2 * static_cast<int>(all.size()) + 1);  // the index, a student's and a teacher's page a lesson
    for (const Lesson& L : all) {
        SCOPED_TRACE(L.id);
        const fs::path d = site / L.id;
        for (const char* name : {"index.html", "teacher.html", "lesson.md", "data.csv", "energy.svg", "momentum.svg"})
            EXPECT_TRUE(fs::exists(d / name)) << name;
        EXPECT_TRUE(fs::exists(d / "frames/frame_00000.png"));
        // The plots' legends are SVG (an HTML <sub> inside <text> is not drawn: "p p"), and
        // each picture's alt text says what it shows (not one text shared by every lesson).
        for (const char* svg : {"energy.svg", "momentum.svg"})
            EXPECT_EQ(read(d / svg).find("<sub>"), std::string::npos);
        const std::string student = read(d / "index.html");
        for (const char* generic : {"alt=\"Energy against time\"", "alt=\"Momentum against time\"",
                                    "alt=\"The scene and its variants, before, at and after the collision\""})
            EXPECT_EQ(student.find(generic), std::string::npos) << generic;
        EXPECT_NE(student.find("alt=\"Energy against time, from 0 to "), std::string::npos);
        // lesson.md shows each of the lesson's figures (figure.png, figure-2.png, ...), and
        // the page each of them: every [[figure]] has its picture.
        const std::string md = read(d / "lesson.md"), page = read(d / "index.html");
        const std::size_t figures = std::max<std::size_t>(1, L.figures.size());
        for (std::size_t k = 1; k <= figures; ++k) {
            const std::string file = k == 1 ? "figure.png" : "figure-" + std::to_string(k) + ".png";
            EXPECT_TRUE(fs::exists(d / file)) << file;
            EXPECT_NE(md.find("](" + file + ")"), std::string::npos) << "lesson.md lacks " << file;
            EXPECT_NE(page.find("<img src=\"" + file + "\""), std::string::npos) << "the page lacks " << file;
        }
        EXPECT_FALSE(fs::exists(d / ("figure-" + std::to_string(figures + 1) + ".png")));
        if (!L.variants.empty()) {
            EXPECT_TRUE(fs::exists(d / "variants.png"));
        }
        if (L.penalty) {
            for (const char* name : {"penalty.svg", "penalty-overlap.svg", "penalty.csv"})
                EXPECT_TRUE(fs::exists(d / name)) << name;
        }
    }
    EXPECT_GT(links, 10);
    // The lesson page holds its questions and the computed answers; the index links to it.
    const std::string lesson = read(site / "catch-up/index.html");
    EXPECT_NE(lesson.find("What impulse J does B receive?"), std::string::npos);
    EXPECT_NE(lesson.find("<details class=\"answer\"><summary>Answer</summary>"), std::string::npos);
    EXPECT_NE(lesson.find("1.2 N s"), std::string::npos);  // J = (1 + 0.5) 2 1 (1.5 - 0.3) / 3
    EXPECT_NE(read(site / "index.html").find("catch-up/index.html"), std::string::npos);
    EXPECT_NE(read(site / "index.html").find("catch-up/teacher.html"), std::string::npos);
    EXPECT_NE(read(site / "style.css").find("@media print"), std::string::npos);
    // Print: math wraps (no nowrap anywhere in the stylesheet); the animation section, screen
    // only, leaves no empty heading; each question has a space to write in.
    const std::string css = read(site / "style.css");
    EXPECT_EQ(css.find("nowrap"), std::string::npos);
    EXPECT_NE(lesson.find("<section class=\"animation noprint\">\n<h3>Animation</h3>"), std::string::npos);
    // Per lesson: each question once, folded on screen, with a space to write in (a choice
    // question: a number to circle instead); the teacher's page is linked.
    const auto count = [](const std::string& text, const std::string& what) {
        std::size_t k = 0;
        for (std::size_t at = 0; (at = text.find(what, at)) != std::string::npos; at += what.size()) ++k;
        return k;
    };
    for (const Lesson& L : all) {
        SCOPED_TRACE(L.id);
        const std::string page = read(site / L.id / "index.html");
        std::size_t predict = 0, asked = 0, spaces = 0, numbers = 0;
        for (const LessonQuestion& q : L.questions) {
            (q.kind == QuestionKind::predict ? predict : asked) += 1;
            spaces += q.has_choices() ? 0 : 1;
            numbers += q.choices.size();
        }
        EXPECT_EQ(count(page, "<details class=\"answer\"><summary>Answer</summary>"), asked);
        EXPECT_EQ(count(page, "<summary>Check your prediction</summary>"), predict);
        EXPECT_EQ(count(page, "<div class=\"write-here"), spaces);
        // Every option numbered where it is asked, and again with its reason in the answer
        // (folded on screen, never printed).
        EXPECT_EQ(count(page, "<span class=\"letter\">"), 2 * numbers);
        EXPECT_EQ(count(page, "<a href=\"teacher.html\">"), 1u);
    }
    // The predictions come before the figure and the animation, which show what happens, and
    // are not screen-only; their answers come after the animation.
    for (const Lesson& L : all) {
        SCOPED_TRACE(L.id);
        const std::string page = read(site / L.id / "index.html");
        const std::size_t predict = page.find("<section class=\"predict\""),
                          figure = page.find("<img src=\"figure.png\""),
                          animation = page.find("<section class=\"animation noprint\">"),
                          check = page.find("<section class=\"check\">");
        ASSERT_NE(predict, std::string::npos);
        ASSERT_NE(check, std::string::npos);
        EXPECT_LT(predict, figure);
        EXPECT_LT(predict, animation);
        EXPECT_GT(check, animation);
        const std::string before = page.substr(0, animation);
        EXPECT_EQ(before.find("<details"), std::string::npos) << "an answer before the animation";
        EXPECT_EQ(before.find("class=\"reasons\""), std::string::npos) << "a reason before the animation";
        for (const LessonQuestion& q : L.questions) {
            if (q.kind != QuestionKind::predict) continue;
            const std::string asked = html::math(q.text);
            EXPECT_LT(page.find(asked), animation) << q.text;
            EXPECT_NE(page.find(asked, check), std::string::npos) << q.text;
        }
    }
    // catch-up: the prediction's options numbered, its answer the right number with every
    // option's reason; a number's tolerance shown; the why question's model answer.
    {
        const Lesson& L = all.front();
        ASSERT_EQ(L.id, "catch-up");
        const std::size_t check = lesson.find("<section class=\"check\">");
        EXPECT_NE(lesson.find("<span class=\"letter\">(2)</span> It stops</label>"), std::string::npos);
        EXPECT_NE(lesson.find("<span class=\"answer\">Option 1.</span>", check), std::string::npos);
        EXPECT_NE(lesson.find("<li class=\"wrong\"><span class=\"letter\">(3)</span> <em>Wrong:</em>", check),
                  std::string::npos);
        EXPECT_NE(lesson.find("What impulse J does B receive? <span class=\"tolerance\">(to within 2 %)</span>"),
                  std::string::npos);
        EXPECT_NE(lesson.find(html::math(L.questions[5].answer)), std::string::npos);
        EXPECT_NE(lesson.find("<span class=\"answer\">0.3 m/s</span>"), std::string::npos);  // the what-if's run
    }
    // Print: predictions print (they are not screen-only) with a space to write in; no answer
    // prints on the student's page (they are on the teacher's page): no folded answer, no
    // predictions checked, no worked example, nor the figures and plots, which show the run's
    // numbers; explanations get more room; a heading stays with what follows it and a figure
    // or a question is not split.
    const std::string print = css.substr(css.find("@media print"));
    for (const char* rule :
         {".write-here { display: block;",
          "body.student details, body.student section.check, "
          "body.student section.worked",
          ".write-here.tall {", "ol.predictions > li", "h1, h2, h3 { break-after: avoid;",
          "figure, table, .plots, ol.questions > li", "figure img { width: auto; max-width: 100%; max-height:"})
        EXPECT_NE(print.find(rule), std::string::npos) << rule;
    for (const Lesson& L : all) {
        const std::string page = read(site / L.id / "index.html");
        // The figures, the animation and the plots are screen-only on the student's page.
        const std::size_t watch = page.find("<section class=\"watch\">\n<h2>Watch</h2>\n<div class=\"noprint\">");
        EXPECT_NE(watch, std::string::npos) << L.id;
        EXPECT_LT(watch, page.find("<img src=\"figure.png\"")) << L.id;
        EXPECT_NE(page.find("<body class=\"student\">"), std::string::npos) << L.id;
    }
    for (const char* hidden :
         {"section.predict { display: none", ".choices { display: none", ".letter { display: none"})
        EXPECT_EQ(print.find(hidden), std::string::npos) << hidden;
    // Student pages name no commands and no files of the repository: those go on the
    // teacher's page.
    for (const Lesson& L : all) {
        const std::string page = read(site / L.id / "index.html");
        for (const char* word : {"collide solve", "collide compare", "collide render", "docs/"})
            EXPECT_EQ(page.find(word), std::string::npos) << L.id << " tells students \"" << word << "\"";
    }
    // Every collision the figures do not show is worked out too (at most 8), folded.
    for (const Lesson& L : all) {
        const std::string page = read(site / L.id / "index.html");
        std::size_t events = 0, later = 0;
        std::ifstream csv(site / L.id / "events.csv");
        for (std::string line; std::getline(csv, line);) ++events;
        events -= 1;  // the header
        for (std::size_t at = 0; (at = page.find("<details class=\"later\">", at)) != std::string::npos; ++at) ++later;
        const std::size_t shown = std::max<std::size_t>(1, L.figures.size());
        EXPECT_EQ(later, std::min<std::size_t>(events > shown ? events - shown : 0, 8)) << L.id;
    }
    // Worked examples in numbers a student reads: at most 4 significant figures, and no
    // floating-point noise of the exact event (a contact point at (0, -5.55e-17) m is (0, 0)):
    // none below 1e-10 unless the line shows it beside a number at most 10^6 times larger (a
    // tiny collision's own numbers are no noise: a domino's corner rattling on the table loses
    // 2.8e-10 J of its 9.6e-5 J).
    const std::regex math_line(R"re(<div class="math[^"]*">(.*?)</div>)re");
    const std::regex number(R"re((\d+(?:\.\d+)?)(e[-+]?\d+)?)re");
    std::size_t math_lines = 0;
    for (const Lesson& L : all) {
        const std::string page = read(site / L.id / "index.html");
        for (std::sregex_iterator m(page.begin(), page.end(), math_line), end; m != end; ++m) {
            ++math_lines;
            const std::string text = (*m)[1];
            std::vector<double> values;
            for (std::sregex_iterator k(text.begin(), text.end(), number); k != end; ++k)
                values.push_back(std::stod((*k)[0].str()));
            for (std::sregex_iterator k(text.begin(), text.end(), number); k != end; ++k) {
                std::string digits;
                for (char ch : (*k)[1].str())
                    if (ch != '.' && !(digits.empty() && ch == '0')) digits += ch;
                EXPECT_LE(digits.size(), 4u) << L.id << ": " << (*k)[0] << " in " << text;
                if ((*k)[2].matched && std::stoi((*k)[2].str().substr(1)) <= -10) {
                    const double x = std::stod((*k)[0].str());
                    const bool beside =
                        std::any_of(values.begin(), values.end(), [x](double y) { return y > x && y <= 1e6 * x; });
                    EXPECT_TRUE(beside) << L.id << ": " << text;
                }
            }
        }
    }
    EXPECT_GT(math_lines, 19u * 10);
    // Each figure's alternative text tells its own collision: no two lessons share one.
    std::set<std::string> alts;
    const std::regex figure_alt(R"re(<img src="figure.png" alt="([^"]*)")re");
    for (const Lesson& L : all) {
        const std::string page = read(site / L.id / "index.html");
        std::smatch m;
        ASSERT_TRUE(std::regex_search(page, m, figure_alt)) << L.id;
        EXPECT_NE(m[1].str().find("the impulse on"), std::string::npos) << L.id << ": " << m[1];
        EXPECT_TRUE(alts.insert(m[1]).second) << L.id << " shares its alt text: " << m[1];
    }
    EXPECT_NE(lesson.find("Before: A (2 kg) moves at 1.5 m/s along +x; B (1 kg) moves at 0.3 m/s along +x. "
                          "At the collision the impulse on B is 1.2 N s along +x"),
              std::string::npos);
    // Built beside the directory and renamed: no temporary left.
    for (const auto& e : fs::directory_iterator(dir.str()))
        EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

// What a student sees of a piece of a page before opening anything: its text without tags,
// scripts and folded <details> (answers, the worked example), entities decoded, spaces joined.
std::string visible_text(const std::string& html) {
    std::string s = html, out;
    for (const char* tag : {"script", "details"}) {
        // Remove each outermost <tag ...>...</tag> (nested ones go with it).
        const std::string open = std::string("<") + tag, close = std::string("</") + tag + ">";
        std::string kept;
        int depth = 0;
        for (std::size_t i = 0; i < s.size();) {
            if (s.compare(i, open.size(), open) == 0 && (s[i + open.size()] == '>' || s[i + open.size()] == ' ')) {
                ++depth;
                i += open.size();
            } else if (depth > 0 && s.compare(i, close.size(), close) == 0) {
                --depth;
                i += close.size();
            } else {
                if (depth == 0) kept += s[i];
                ++i;
            }
        }
        s = kept;
    }
    bool in_tag = false;
    for (char c : s) {
        if (c == '<') in_tag = true;
        else if (c == '>') in_tag = false;
        else if (!in_tag) out += c;
    }
    for (const auto& [entity, text] : std::vector<std::pair<std::string, std::string>>{
             {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&amp;", "&"}})
        for (std::size_t at; (at = out.find(entity)) != std::string::npos;) out.replace(at, entity.size(), text);
    std::string joined;
    for (char c : out) {
        const bool space = c == ' ' || c == '\n' || c == '\t' || c == '\r';
        if (space && (joined.empty() || joined.back() == ' ')) continue;
        joined += space ? ' ' : c;
    }
    return joined;
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// Everything a student can read in a piece of a page without committing an answer: its text
// with every fold opened (the worked example, the plots' tables, the predictions' checks) and
// the images' alternative texts, but not the answers of questions (each opens once its
// question is answered) or scripts.
std::string readable_text(const std::string& html) {
    static const std::regex answers(R"re(<details class="answer">[\s\S]*?</details>)re");
    static const std::regex alt(R"re(<img [^>]*alt="([^"]*)")re");
    std::string s = std::regex_replace(html, answers, " ");
    s = std::regex_replace(s, alt, " $1 <img ");
    for (const std::string tag : {"<details", "</details>"})
        for (std::size_t at; (at = s.find(tag)) != std::string::npos;)
            s.replace(at, tag.size(), tag[1] == '/' ? "</div>" : "<div");
    return visible_text(s);
}

// A number of a text written with at least 3 significant digits ("0.501", "4.077",
// "1.234e-3"), with how many it has (a number written to that precision names a value; "1.5"
// or "2" may be any given) and the unit written right after it ("J" in "1.69 J"; "" if none).
struct Printed {
    double value = 0;
    int digits = 0;
    std::string unit;
};
std::vector<Printed> precise_numbers(const std::string& text) {
    static const std::regex number(
        R"re((\d+\.\d+|\d+)(e[-+]?\d+)?( (kg m²/s|kg m/s|N s|rad/s|m/s²|m/s|J|kg|s|m)(?![A-Za-z/²]))?)re");
    std::vector<Printed> out;
    for (std::sregex_iterator k(text.begin(), text.end(), number), end; k != end; ++k) {
        std::string digits;
        for (char ch : (*k)[1].str())
            if (ch != '.' && !(digits.empty() && ch == '0')) digits += ch;
        while (!digits.empty() && digits.back() == '0' && (*k)[1].str().find('.') == std::string::npos)
            digits.pop_back();
        if (digits.size() >= 3)
            out.push_back({std::stod((*k)[1].str() + (*k)[2].str()), static_cast<int>(digits.size()), (*k)[4].str()});
    }
    return out;
}

// Whether `x`, written with `digits` significant digits, is `a` as written to that precision
// (the same number a student would copy).
bool same_as_written(double a, double x, int digits) {
    if (a == 0) return x == 0;
    const double scale = std::pow(10.0, digits - 1 - static_cast<int>(std::floor(std::log10(std::abs(a)))));
    return std::abs(std::round(std::abs(a) * scale) - std::abs(x) * scale) < 1e-6;
}

// Issue 33, "Ask before telling": on every lesson's student page, nothing a student can read
// above a prediction or a numeric question gives its answer, as the page writes it (the right
// option's text, or the answer's text; and no number to 3 or more digits within 0.5 % of one of
// the answer's): not the text, not a fold opened by hand (the worked example, a plot's table),
// not an image's alternative text. "Check yourself" asks its numbers with other values than
// the run the figures show (teach/check_variant.h), so the figures do not answer them. Two
// kinds of answer may appear above, each listed and checked to still be one: a given of the
// set-up (A's speed before is B's after), only there; and an answer that the other values do
// not change (the first block of a cradle stops whatever its mass), where the page's answer
// equals the lesson's own run's (computed here). A number with another unit next to it is
// another quantity; one that has the answer's digits but no unit beside it is listed.
TEST(Material, NothingAboveAQuestionGivesItsAnswer) {
    render::test::TempDir dir;
    const fs::path site = every_lesson_site(dir);
    const std::vector<Lesson> all = load_lessons(std::string(COLLIDE_SOURCE_DIR) + "/lessons");
    // {lesson, question number from 1}: answers equal to a given of the set-up.
    std::set<std::pair<std::string, int>> givens = {
        {"catch-up", 7},     // with the masses swapped A leaves at 0.3 m/s, B's speed before
        {"restitution", 4},  // e = 1: the points part at the 2 m/s they met at
    };
    // {lesson, question number from 1}: answers that "Check yourself"'s other values leave as
    // in the lesson's own run, which the figures show.
    std::set<std::pair<std::string, int>> unchanged = {
        {"restitution", 1},
        {"restitution", 2},
        {"restitution", 3},  // -e u_n: the masses do not enter
        {"superball", 5},    // e = 1, rough: no energy lost
        {"box2d", 4},        // e = 1: no energy lost
        {"newtons-cradle", 2},
        {"newtons-cradle", 3},
        {"newtons-cradle", 4},        // 2 collisions; the first two stop
        {"bouncing-ball", 4},         // at rest on the floor at the end
        {"centre-of-percussion", 2},  // hit at the sweet spot, the handle end stays still
    };
    // {lesson, question number from 1}: the same digits as another quantity of the watched run
    // that the page does not write with a unit next to it.
    std::set<std::pair<std::string, int>> coincidences = {
        {"penalty", 6},  // A at 1.688 m/s with the other numbers; the run's kinetic energy after, 1.688 J
    };
    std::set<std::pair<std::string, int>> used, used_unchanged, used_coincidences;
    int checked = 0;
    for (const Lesson& L : all) {
        SCOPED_TRACE(L.id);
        const std::string page = read(site / L.id / "index.html");
        const std::vector<LessonAnswer> own = answer_questions(L);
        const std::size_t setup_at = page.find("<section class=\"setup\">"),
                          setup_end = page.find("</section>", setup_at);
        ASSERT_NE(setup_at, std::string::npos);
        int predict_k = 0;
        for (std::size_t i = 0; i < L.questions.size(); ++i) {
            const LessonQuestion& q = L.questions[i];
            if (q.kind == QuestionKind::predict) ++predict_k;
            if (!(q.kind == QuestionKind::predict || q.has_quantity())) continue;
            const int number = static_cast<int>(i) + 1;
            SCOPED_TRACE("question " + std::to_string(number) + ": " + q.text);
            const std::size_t asked = page.find(" data-q=\"" + std::to_string(number) + "\"");
            ASSERT_NE(asked, std::string::npos);
            // The answer as the page writes it (in the fold below the question, or for a
            // prediction in "Check your predictions").
            const std::size_t fold = q.kind == QuestionKind::predict
                                         ? page.find("<details id=\"check-" + std::to_string(predict_k) + "\"")
                                         : page.find("<details class=\"answer\">", asked);
            ASSERT_NE(fold, std::string::npos);
            const std::size_t a0 = page.find("<span class=\"answer\">", fold);
            ASSERT_NE(a0, std::string::npos);
            const std::size_t a1 = page.find("</span>", a0);
            std::string answer = visible_text(page.substr(a0, a1 - a0));
            if (q.has_choices()) {
                EXPECT_EQ(answer, "Option " + std::to_string(q.correct) + ".");
                answer = visible_text(html::math(q.choices[static_cast<std::size_t>(q.correct - 1)]));
            }
            ASSERT_FALSE(answer.empty());
            // A count ("6") is found as a count of something ("6 collisions"), not inside "16".
            const bool count = answer.find_first_not_of("0123456789") == std::string::npos;
            const std::regex counted(count ? "(^|[^0-9.])" + answer + " (collision|landing|bounce|contact|time)" : "x");
            const auto spoils = [&](const std::string& html) {
                const std::string seen = readable_text(html);
                if (count) return std::regex_search(seen, counted) ? "\"" + answer + " ...\"" : std::string();
                if (lower(seen).find(lower(answer)) != std::string::npos) return "\"" + answer + "\"";
                if (q.has_choices()) return std::string();
                // A number with another unit is another quantity ("1.69 J" for "1.688 m/s").
                const std::string unit = answer.substr(answer.find_last_of("0123456789)") + 1);
                for (const Printed& a : precise_numbers(answer))
                    for (const Printed& x : precise_numbers(seen)) {
                        if (!x.unit.empty() && " " + x.unit != unit) continue;
                        if (x.digits <= a.digits ? same_as_written(a.value, x.value, x.digits)
                                                 : same_as_written(x.value, a.value, a.digits))
                            return std::to_string(x.value) + " (the answer: " + answer + ")";
                    }
                return std::string();
            };
            const std::string above = page.substr(0, asked);
            const std::string found = spoils(above);
            if (givens.count({L.id, number})) {
                used.insert({L.id, number});
                EXPECT_FALSE(found.empty()) << "listed as a given but not found above: remove it from the list";
                // The set-up has it (the figures' "before" and the worked example's givens repeat it).
                EXPECT_NE(spoils(page.substr(setup_at, setup_end - setup_at)), "");
            } else if (coincidences.count({L.id, number})) {
                used_coincidences.insert({L.id, number});
                EXPECT_FALSE(found.empty()) << "listed as a coincidence but not found above: remove it from the list";
            } else if (unchanged.count({L.id, number})) {
                used_unchanged.insert({L.id, number});
                EXPECT_FALSE(found.empty()) << "listed as unchanged but not found above: remove it from the list";
                // The page's answer (what it marks) is the lesson's own run's.
                const std::size_t tag_end = page.find('>', asked);
                const std::string tag = page.substr(asked, tag_end - asked);
                std::smatch m;
                ASSERT_TRUE(std::regex_search(tag, m, std::regex(R"re(data-value="\[([^\]]*)\]")re"))) << tag;
                std::vector<double> marked;
                std::istringstream values(m[1].str());
                for (std::string x; std::getline(values, x, ',');) marked.push_back(std::stod(x));
                const LessonAnswer& a = own[i];
                const std::vector<double> want =
                    a.is_vector ? std::vector<double>(a.vector.data(), a.vector.data() + marked.size())
                                : std::vector<double>{a.value};
                ASSERT_EQ(marked.size(), want.size());
                double d2 = 0, n2 = 0;
                for (std::size_t k = 0; k < want.size(); ++k) {
                    d2 += (marked[k] - want[k]) * (marked[k] - want[k]);
                    n2 += want[k] * want[k];
                }
                EXPECT_LE(std::sqrt(d2), q.tolerance * std::sqrt(n2) + 1e-9) << "listed as unchanged but it changed";
            } else {
                EXPECT_EQ(found, "") << "the page shows the answer above the question";
            }
            ++checked;
        }
    }
    EXPECT_EQ(used_unchanged, unchanged);
    EXPECT_EQ(used_coincidences, coincidences);
    EXPECT_EQ(used, givens);
    EXPECT_GT(checked, 22 * 4);
}

// Issue 33, "Two audiences": every lesson has a teacher's page, linked from the index and from
// the lesson's page, that holds the lesson's [teacher] content, its [[vary]] inputs, every
// answer of the student's page and every worked example, unfolded.
TEST(Material, EveryLessonHasATeachersPageWithEveryAnswer) {
    render::test::TempDir dir;
    const fs::path site = every_lesson_site(dir);
    const std::vector<Lesson> all = load_lessons(std::string(COLLIDE_SOURCE_DIR) + "/lessons");
    const std::string index = read(site / "index.html");
    const std::regex answer(R"re(<span class="answer">(.*?)</span>)re");
    const std::regex math_line(R"re(<div class="math[^"]*">(.*?)</div>)re");
    for (const Lesson& L : all) {
        SCOPED_TRACE(L.id);
        ASSERT_TRUE(L.teacher.has_value());
        const std::string student = read(site / L.id / "index.html");
        const std::string teacher = read(site / L.id / "teacher.html");
        EXPECT_NE(index.find("href=\"" + L.id + "/teacher.html\""), std::string::npos);
        EXPECT_NE(student.find("<a href=\"teacher.html\">"), std::string::npos);
        EXPECT_NE(teacher.find("<a href=\"index.html\">"), std::string::npos);
        EXPECT_NE(teacher.find(html::math(L.teacher->level)), std::string::npos);
        EXPECT_NE(teacher.find("about " + std::to_string(L.teacher->minutes) + " minutes"), std::string::npos);
        for (const std::string& p : L.teacher->prerequisites) EXPECT_NE(teacher.find(html::math(p)), std::string::npos);
        for (const LessonMisconception& m : L.teacher->misconceptions) {
            EXPECT_NE(teacher.find(html::math(m.belief)), std::string::npos);
            EXPECT_NE(teacher.find(html::math(m.evidence)), std::string::npos);
        }
        for (const LessonClassQuestion& q : L.teacher->ask)
            EXPECT_NE(teacher.find(html::math(q.question)), std::string::npos);
        // How to run it live: the lesson's inputs from its [[vary]] tables, or a plain note
        // that it has none.
        if (L.vary.empty()) {
            EXPECT_NE(teacher.find("declares no <code>[[vary]]</code> inputs"), std::string::npos);
        } else {
            for (const LessonVary& v : L.vary)
                EXPECT_NE(teacher.find("<code>" + html::escape(v.name()) + "</code>"), std::string::npos) << v.name();
        }
        // Every answer of the student's page, and each model answer.
        std::size_t answers = 0;
        for (std::sregex_iterator m(student.begin(), student.end(), answer), end; m != end; ++m, ++answers)
            EXPECT_NE(teacher.find((*m)[0].str()), std::string::npos) << (*m)[0];
        EXPECT_GE(answers, L.questions.size() -
                               std::count_if(L.questions.begin(), L.questions.end(),
                                             [](const LessonQuestion& q) { return q.kind == QuestionKind::explain; }));
        for (const LessonQuestion& q : L.questions) {
            EXPECT_NE(teacher.find(html::math(q.text)), std::string::npos) << q.text;
            if (q.kind == QuestionKind::explain) {
                EXPECT_NE(teacher.find(html::paragraphs(q.answer)), std::string::npos);
            }
            for (const std::string& r : q.reasons) EXPECT_NE(teacher.find(html::math(r)), std::string::npos);
        }
        // Every worked line of the student's folded worked example, unfolded: no <details>
        // but the run's later collisions (one line each when printed) and the numbers behind a
        // plot (its table, folded under it as on the student's page).
        std::size_t lines = 0;
        for (std::sregex_iterator m(student.begin(), student.end(), math_line), end; m != end; ++m, ++lines)
            EXPECT_NE(teacher.find((*m)[0].str()), std::string::npos) << (*m)[0];
        EXPECT_GT(lines, 5u);
        EXPECT_EQ(teacher.find("<details class=\"worked\""), std::string::npos);
        for (std::size_t at = 0; (at = teacher.find("<details", at)) != std::string::npos; ++at)
            EXPECT_TRUE(teacher.compare(at, 23, "<details class=\"later\">") == 0 ||
                        teacher.compare(at, 27, "<details class=\"plot-data\">") == 0)
                << teacher.substr(at, 40);
        // The teacher's notes (commands, files) are on the teacher's page, not the student's.
        if (!L.teacher_notes.empty()) {
            EXPECT_NE(teacher.find(html::paragraphs(L.teacher_notes)), std::string::npos);
        }
    }
}

// A prediction of a number: on screen a field to type it in, printed a space to write it in;
// after the animation the engine's answer with its tolerance and why. A what-if's answer is
// its own scene's.
TEST(Material, APredictedNumberIsTypedOrWrittenAndCheckedAgainstTheEngine) {
    render::test::TempDir dir;
    const std::string file = dir / "predict-number.toml";
    std::string text = read(fs::path(COLLIDE_SOURCE_DIR) / "lessons/01-catch-up.toml");
    const std::string id = "id = \"catch-up\"";
    text.replace(text.find(id), id.size(), "id = \"predict-number\"");
    text +=
        "\n[[question]]\nkind = \"predict\"\ntext = \"How fast will B move after the collision?\"\n"
        "quantity = \"velocity_after\"\nbody = \"B\"\ntolerance = 0.05\nexplain = \"B receives +J.\"\n";
    std::ofstream(file) << text;
    std::ostringstream out, err;
    MaterialOptions o = tiny(dir / "site");
    o.lessons = {file};
    ASSERT_EQ(run_material(o, out, err), 0) << err.str();
    const std::string page = read(fs::path(dir / "site") / "predict-number/index.html");
    const std::size_t asked = page.find(
                          "How fast will B move after the collision? <span class=\"tolerance\">(to within 5 %)</span>"),
                      animation = page.find("<section class=\"animation noprint\">"),
                      check = page.find("<section class=\"check\">");
    ASSERT_NE(asked, std::string::npos);
    EXPECT_LT(asked, animation);
    const std::string before = page.substr(asked, page.find("</section>", asked) - asked);  // the box
    EXPECT_NE(before.find("<input type=\"text\" class=\"answer-in prediction\""), std::string::npos);
    EXPECT_NE(before.find("<div class=\"write-here\" aria-hidden=\"true\"></div>"), std::string::npos);
    EXPECT_EQ(before.find("1.5 m/s"), std::string::npos);  // not answered where it is asked
    // v_bf = v_bi + J / m_b = 0.3 + 1.2 / 1 (the lesson's worked numbers)
    EXPECT_NE(page.find("<span class=\"answer\">1.5 m/s</span><br>B receives +J.", check), std::string::npos);
}

// One truth per page (issue 33): in a many-body lesson the world resolves the shown collision
// with the other contacts of its instant (box 4 rests on box 3 and under box 5; domino 2 stands
// on the floor). The page's table, the figure's alt text and the answers give the run's numbers;
// the two-body calculation is labelled a simplified one, with the run's results beside it.
TEST(Material, AManyBodyPageGivesTheRunsNumbersAndLabelsTheTwoBodyCalculation) {
    render::test::TempDir dir;
    const fs::path site = every_lesson_site(dir);
    const notation::StudentNumbers student;  // the page's numbers: 4 figures, no noise
    for (const auto& [id, a_name, b_name] :
         {std::tuple<std::string, std::string, std::string>{"tower", "ball", "box 4"},
          {"dominoes", "domino 1", "domino 2"}}) {
        SCOPED_TRACE(id);
        // The shown collision, from the engine's own run of the lesson's scene.
        const RenderSource src = load_render_source(id);
        const Scene& scene = src.scene;
        const int d = scene.dimension;
        std::size_t ia = 0, ib = 0;
        for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
            if (scene.bodies[k].name == a_name) ia = k;
            if (scene.bodies[k].name == b_name) ib = k;
        }
        const SceneRun run = run_scene(scene, {0.0, scene.duration}, nullptr, {RecordOptions::Keep{ia, ib, 1}});
        std::optional<CollisionInstant> c;
        std::visit(
            [&](const auto& rec) {
                if (const auto pc = find_pair_collision(rec, ia, ib, 1))
                    c = with_roles(collision_instant(rec.events[pc->first]), ia, ib);
            },
            run.record);
        ASSERT_TRUE(c.has_value());
        const SolveProblem problem = collision_problem(scene, *c);
        const double mb = problem.b.b3.mass;
        // The two bodies alone (solve()) turn b otherwise than the run does: the case this is about.
        const Solution alone = solve(problem);
        EXPECT_GT((alone.wb - c->wb_after).norm(), 1.0);

        const std::string page = read(site / id / "index.html");
        // The table: b's row with the run's velocity and spin after.
        const auto spin = [d](const Vec3& w) { return d == 2 ? notation::num_text(w.z()) : notation::vec(w, 3).txt; };
        const std::size_t tb = page.find("<h3>Before and after</h3>");
        ASSERT_NE(tb, std::string::npos);
        const std::string table = page.substr(tb, page.find("</table>", tb) - tb);  // the bodies' table
        const std::string row = "<tr><td>" + b_name + "</td><td>" + notation::num_text(mb) + "</td><td>" +
                                notation::vec(c->before_b.v, d).txt + "</td><td>" + notation::vec(c->vb_after, d).txt +
                                "</td><td>" + spin(c->before_b.w) + "</td><td>" + spin(c->wb_after) + "</td></tr>";
        EXPECT_NE(table.find(row), std::string::npos) << row;
        EXPECT_EQ(table.find(html::escape(spin(alone.wb))), std::string::npos) << "the two-body spin in the table";
        // The calculation is labelled, and the run's results follow it.
        const std::size_t label = page.find("A simplified calculation: " + a_name + " and " + b_name + " alone.");
        ASSERT_NE(label, std::string::npos);
        EXPECT_LT(label, page.find(html::escape(spin(alone.wb)), label));
        const std::size_t beside = page.find("<table class=\"beside\">", label);
        ASSERT_NE(beside, std::string::npos);
        EXPECT_NE(
            page.find("<td>" + html::escape(spin(alone.wb)) + "</td><td>" + html::escape(spin(c->wb_after)) + "</td>",
                      beside),
            std::string::npos);
        // The figure's alt text: b spins as the run has it.
        const std::size_t alt = page.find("<img src=\"figure.png\" alt=\"");
        ASSERT_NE(alt, std::string::npos);
        const std::string alt_text = page.substr(alt, page.find('>', alt) - alt);
        EXPECT_NE(alt_text.find("spins at " +
                                html::escape(notation::sig_text(d == 2 ? c->wb_after.z() : c->wb_after.norm(), 3))),
                  std::string::npos)
            << alt_text;
    }
}

// Issue 33, "The lesson's point as a plot": each [[plot]] of the four lessons that declare one is
// on its page under "Watch" (plot-K.svg, drawn with its units), with an alt text that says what
// the run shows and the numbers behind it in a folded table.
TEST(Material, EachDeclaredPlotIsOnItsPageWithAltTextAndTable) {
    render::test::TempDir dir;
    const fs::path site = every_lesson_site(dir);
    // {lesson, plot number, words its alt text must hold}
    const std::vector<std::tuple<std::string, int, std::string>> expected = {
        {"bouncing-ball", 1, "Height of the ball's centre against time: "},
        {"bouncing-ball", 2, "times the one before"},
        {"bouncing-ball", 2, "and e = 0.5"},
        {"dominoes", 1, "Strike time against domino number: a straight line"},
        {"dominoes", 1, " s per domino"},
        {"dominoes", 1, "a wave speed of "},
        {"dominoes", 2, "Time between strikes"},
        {"tower", 1, "Impulse at each contact of the tower when the ball strikes: "},
        {"restitution", 1, "B (e=1): velocity of touching point, x from "},
    };
    for (const auto& [id, k, words] : expected) {
        SCOPED_TRACE(id + " plot " + std::to_string(k));
        const fs::path d = site / id;
        const std::string page = read(d / "index.html");
        const std::string file = "plot-" + std::to_string(k) + ".svg";
        ASSERT_TRUE(fs::exists(d / file));
        const std::string svg = read(d / file);
        EXPECT_NE(svg.find("<svg"), std::string::npos);
        const std::size_t img = page.find("<img src=\"" + file + "\" alt=\"");
        ASSERT_NE(img, std::string::npos);
        // The teacher's page has it too.
        EXPECT_NE(read(d / "teacher.html").find("<img src=\"" + file + "\" alt=\""), std::string::npos);
        // Under "Watch", before the explanation.
        EXPECT_GT(img, page.find("<h2>Watch</h2>"));
        EXPECT_LT(img, page.find("<section class=\"explain\">"));
        const std::size_t a0 = img + file.size() + 17, a1 = page.find('"', a0);
        const std::string alt = page.substr(a0, a1 - a0);
        EXPECT_NE(alt.find(html::escape(words)), std::string::npos) << alt;
        // The table behind it, folded.
        const std::size_t table = page.find("<details class=\"plot-data\">", img);
        ASSERT_NE(table, std::string::npos);
        EXPECT_LT(table, page.find("<img src=\"plot-" + std::to_string(k + 1) + ".svg\"", img));
        EXPECT_NE(page.find("<table>", table), std::string::npos);
        // The title once: the page's heading, and in the SVG only its <title> (not drawn again).
        EXPECT_NE(svg.find("<title>"), std::string::npos);
        EXPECT_EQ(svg.find("font-weight=\"bold\""), std::string::npos);
        // The axes carry units, and the quantities in words.
        if (id == "bouncing-ball" && k == 1) {
            EXPECT_NE(svg.find(">t (s)<"), std::string::npos);
            EXPECT_NE(svg.find(">ball: height of centre, y (m)<"), std::string::npos);
        }
        if (id == "bouncing-ball" && k == 2) {
            EXPECT_NE(svg.find("log scale)<"), std::string::npos);
        }
        if (id == "restitution") {
            EXPECT_NE(svg.find(">velocity (m/s)<"), std::string::npos);
            EXPECT_NE(svg.find(">B (e=1): velocity of touching point, x<"), std::string::npos);
            EXPECT_EQ(svg.find("B (e=1).touching point.v.x"), std::string::npos);
        }
        if (id == "dominoes" && k == 1) {
            EXPECT_NE(svg.find(">time t (s)<"), std::string::npos);
            EXPECT_NE(svg.find("s per domino"), std::string::npos);
        }
    }
}

TEST(Material, BadInputWritesNothing) {
    render::test::TempDir dir;
    std::ostringstream out, err;
    MaterialOptions o = tiny(dir / "site");
    o.lessons = {"no-such-lesson"};
    EXPECT_EQ(run_material(o, out, err), 2);
    EXPECT_NE(err.str().find("no-such-lesson"), std::string::npos) << err.str();
    EXPECT_FALSE(fs::exists(dir / "site"));
    // A directory that is not empty is kept unless --force.
    fs::create_directories(dir / "busy");
    std::ofstream(dir / "busy/keep.txt") << "mine";
    err.str("");
    EXPECT_EQ(run_material(tiny(dir / "busy"), out, err), 2);
    EXPECT_NE(err.str().find("--force"), std::string::npos) << err.str();
    EXPECT_TRUE(fs::exists(dir / "busy/keep.txt"));
    MaterialOptions forced = tiny(dir / "busy");
    forced.force = true;
    EXPECT_EQ(run_material(forced, out, err), 0) << err.str();
    EXPECT_TRUE(fs::exists(dir / "busy/index.html"));
    EXPECT_FALSE(fs::exists(dir / "busy/keep.txt"));
}

}  // namespace
}  // namespace collide
