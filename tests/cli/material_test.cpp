// `collide material`: every bundled lesson renders (a low-resolution smoke run), the site it
// writes is complete and self-contained (every internal link and image resolves, nothing is
// fetched from the network), the answers are on the pages, and bad input writes nothing.
#include "cli/material_cmd.h"
#include "teach/answers.h"
#include "teach/html.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
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

TEST(Material, EveryLessonRendersAndEveryLinkAndImageResolvesOffline) {
    // The smoke render of every bundled lesson (160x120, 10 frames/s: about 6 s), as the site.
    render::test::TempDir dir;
    std::ostringstream out, err;
    MaterialOptions o = tiny(dir / "site");
    o.lessons.clear();  // all of them
    ASSERT_EQ(run_material(o, out, err), 0) << err.str();
    const std::vector<Lesson> all = load_lessons(std::string(COLLIDE_SOURCE_DIR) + "/lessons");
    const std::regex attr(R"re((?:href|src|poster)="([^"]*)")re");
    int pages = 0, links = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir / "site")) {
        if (e.path().extension() != ".html") continue;
        ++pages;
        const std::string html = read(e.path());
        EXPECT_EQ(html.find("http://"), std::string::npos) << e.path();
        EXPECT_EQ(html.find("https://"), std::string::npos) << e.path();
        for (std::sregex_iterator m(html.begin(), html.end(), attr), end; m != end; ++m) {
            const std::string target = (*m)[1];
            ++links;
            EXPECT_TRUE(fs::exists(e.path().parent_path() / target)) << e.path() << " -> " << target;
        }
    }
    EXPECT_EQ(pages, static_cast<int>(all.size()) + 1);  // the index and one page a lesson
    for (const Lesson& L : all) {
        SCOPED_TRACE(L.id);
        const fs::path d = fs::path(dir / "site") / L.id;
        for (const char* name : {"index.html", "lesson.md", "data.csv", "energy.svg", "momentum.svg"})
            EXPECT_TRUE(fs::exists(d / name)) << name;
        EXPECT_TRUE(fs::exists(d / "frames/frame_00000.png"));
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
    const std::string lesson = read(fs::path(dir / "site") / "catch-up/index.html");
    EXPECT_NE(lesson.find("What impulse J does B receive?"), std::string::npos);
    EXPECT_NE(lesson.find("<details><summary>Answer</summary>"), std::string::npos);
    EXPECT_NE(lesson.find("1.2 N s"), std::string::npos);  // J = (1 + 0.5) 2 1 (1.5 - 0.3) / 3
    EXPECT_NE(read(fs::path(dir / "site") / "index.html").find("catch-up/index.html"), std::string::npos);
    EXPECT_NE(read(fs::path(dir / "site") / "style.css").find("@media print"), std::string::npos);
    // Print: math wraps (no nowrap anywhere in the stylesheet); the animation section, screen
    // only, leaves no empty heading; each question has a space to write in and, for the
    // teacher's copy, its answer.
    const std::string css = read(fs::path(dir / "site") / "style.css");
    EXPECT_EQ(css.find("nowrap"), std::string::npos);
    EXPECT_NE(lesson.find("<section class=\"animation noprint\">\n<h2>Animation</h2>"), std::string::npos);
    // Per lesson: each question once, folded on screen, with a space to write in (a choice
    // question: a number to circle instead) and its answer for the teacher's copy.
    const auto count = [](const std::string& text, const std::string& what) {
        std::size_t k = 0;
        for (std::size_t at = 0; (at = text.find(what, at)) != std::string::npos; at += what.size()) ++k;
        return k;
    };
    for (const Lesson& L : all) {
        SCOPED_TRACE(L.id);
        const std::string page = read(fs::path(dir / "site") / L.id / "index.html");
        std::size_t predict = 0, asked = 0, spaces = 0, numbers = 0;
        for (const LessonQuestion& q : L.questions) {
            (q.kind == QuestionKind::predict ? predict : asked) += 1;
            spaces += q.has_choices() ? 0 : 1;
            numbers += q.choices.size();
        }
        EXPECT_EQ(count(page, "<details><summary>Answer</summary>"), asked);
        EXPECT_EQ(count(page, "<details><summary>Check your prediction</summary>"), predict);
        EXPECT_EQ(count(page, "<div class=\"write-here"), spaces);
        EXPECT_EQ(count(page, "class=\"printed-answer\""), L.questions.size());
        // Every option numbered where it is asked, and again with its reason in the answer
        // (on screen and printed).
        EXPECT_EQ(count(page, "<span class=\"letter\">"), 3 * numbers);
        EXPECT_EQ(count(page, "id=\"print-answers\""), 1u);
    }
    // The predictions come before the figure and the animation, which show what happens, and
    // are not screen-only; their answers come after the animation.
    for (const Lesson& L : all) {
        SCOPED_TRACE(L.id);
        const std::string page = read(fs::path(dir / "site") / L.id / "index.html");
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
    // Print: predictions print (they are not screen-only) with a space to write in; their
    // answers and every other answer only in the teacher's copy; explanations get more room.
    const std::string print = css.substr(css.find("@media print"));
    for (const char* rule : {".write-here { display: block;", "body.with-answers .printed-answer { display: block; }",
                             "section.check { display: none; }", "body.with-answers section.check { display: block; }",
                             ".write-here.tall {", "details { display: none; }", "ol.predictions > li"})
        EXPECT_NE(print.find(rule), std::string::npos) << rule;
    for (const char* hidden :
         {"section.predict { display: none", ".choices { display: none", ".letter { display: none"})
        EXPECT_EQ(print.find(hidden), std::string::npos) << hidden;
    // Student pages name no commands and no files of the repository: those go in the
    // teacher's section.
    for (const Lesson& L : all) {
        std::string page = read(fs::path(dir / "site") / L.id / "index.html");
        const std::size_t teacher = page.find("<section class=\"teacher\">");
        if (teacher != std::string::npos) page.erase(teacher, page.find("</section>", teacher) - teacher);
        for (const char* word : {"collide solve", "collide compare", "collide render", "docs/"})
            EXPECT_EQ(page.find(word), std::string::npos) << L.id << " tells students \"" << word << "\"";
    }
    // Every collision the figures do not show is worked out too (at most 8), folded.
    for (const Lesson& L : all) {
        const std::string page = read(fs::path(dir / "site") / L.id / "index.html");
        std::size_t events = 0, later = 0;
        std::ifstream csv(fs::path(dir / "site") / L.id / "events.csv");
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
        const std::string page = read(fs::path(dir / "site") / L.id / "index.html");
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
        const std::string page = read(fs::path(dir / "site") / L.id / "index.html");
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
    EXPECT_NE(before.find("<input type=\"text\" class=\"prediction\""), std::string::npos);
    EXPECT_NE(before.find("<div class=\"write-here\" aria-hidden=\"true\"></div>"), std::string::npos);
    EXPECT_EQ(before.find("1.5 m/s"), std::string::npos);  // not answered where it is asked
    // v_bf = v_bi + J / m_b = 0.3 + 1.2 / 1 (the lesson's worked numbers)
    EXPECT_NE(page.find("<span class=\"answer\">1.5 m/s</span><br>B receives +J.", check), std::string::npos);
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
