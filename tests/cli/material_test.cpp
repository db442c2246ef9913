// `collide material`: every bundled lesson renders (a low-resolution smoke run), the site it
// writes is complete and self-contained (every internal link and image resolves, nothing is
// fetched from the network), the answers are on the pages, and bad input writes nothing.
#include "cli/material_cmd.h"
#include "teach/answers.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

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
    std::size_t questions = 0, spaces = 0, printed = 0;
    for (std::size_t at = 0; (at = lesson.find("<details><summary>Answer</summary>", at)) != std::string::npos; ++at)
        ++questions;
    for (std::size_t at = 0; (at = lesson.find("class=\"write-here\"", at)) != std::string::npos; ++at) ++spaces;
    for (std::size_t at = 0; (at = lesson.find("class=\"printed-answer\"", at)) != std::string::npos; ++at) ++printed;
    EXPECT_GT(questions, 0u);
    EXPECT_EQ(spaces, questions);
    EXPECT_EQ(printed, questions);
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
