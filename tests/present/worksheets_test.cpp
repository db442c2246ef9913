// `collide worksheet` end to end: the command is run as a user runs it, and its key.json is
// checked against answers computed here (closed forms for the 1D catch-up; for the turning bar
// of rotation-directions, the engine's answer_questions on lesson_with_values of the values
// read back, and conservation of angular momentum about the origin in closed form), its HTML
// for what a student must not see, and its refusals for what must leave nothing behind.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "teach/answers.h"
#include "teach/worksheet.h"

namespace collide {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

const std::string kLessons = std::string(COLLIDE_SOURCE_DIR) + "/lessons/";

fs::path scratch(const std::string& name) {
    const fs::path p =
        fs::temp_directory_path() / ("collide-worksheet-test-" + std::to_string(::getpid()) + "-" + name);
    fs::remove_all(p);
    return p;
}

std::string slurp(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

// Runs `collide worksheet ARGS`; returns its exit code, stderr in *err. Without `pdf` the
// command finds no weasyprint (an empty PATH): the PDFs take most of the time, and only one
// test is about them.
int worksheet(const std::string& args, std::string* err = nullptr, bool pdf = false) {
    const fs::path e = scratch("stderr");
    const std::string cmd = std::string(pdf ? "" : "PATH=/nonexistent ") + COLLIDE_BIN + " worksheet " + args +
                            " >/dev/null 2>" + e.string();
    const int status = std::system(cmd.c_str());
    if (err) *err = slurp(e);
    fs::remove(e);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The sheets of one lesson, written once for the tests that read them (30 students, seed 1).
const fs::path& written(const std::string& id) {
    static std::map<std::string, fs::path> dirs;
    if (auto it = dirs.find(id); it != dirs.end()) return it->second;
    const fs::path dir = scratch(id);
    std::string err;
    EXPECT_EQ(worksheet(id + " -o " + dir.string() + " --students 30 --seed 1", &err), 0) << err;
    return dirs.emplace(id, dir).first->second;
}

json key(const std::string& id) { return json::parse(slurp(written(id) / "key.json")); }

Lesson lesson_file(const std::string& file) { return load_lesson(kLessons + file); }

// Every student has a value for each [[vary]] entry, on its grid; not all students alike.
void expect_on_grids(const Lesson& L, const json& k) {
    ASSERT_EQ(k["students"].size(), 30u);
    std::set<std::string> distinct;
    for (const json& s : k["students"]) {
        ASSERT_EQ(s["values"].size(), L.vary.size());
        for (const LessonVary& v : L.vary) {
            ASSERT_TRUE(s["values"].contains(v.name())) << v.name();
            const double x = s["values"][v.name()].get<double>();
            const double steps = (x - v.lo) / v.step;
            EXPECT_GE(x, v.lo - 1e-12) << v.name();
            EXPECT_LE(x, v.hi + 1e-12) << v.name();
            EXPECT_NEAR(steps, std::round(steps), 1e-9) << v.name() << " = " << x << " is off the grid";
        }
        distinct.insert(s["values"].dump());
    }
    // 30 draws from grids of thousands of points: nearly all differ.
    EXPECT_GE(distinct.size(), 25u);
}

double rel(double x) { return 1e-9 * std::max(1.0, std::abs(x)); }

TEST(Worksheet, CatchUpAnswersAreTheClosedForms) {
    const Lesson L = lesson_file("01-catch-up.toml");
    const json k = key("catch-up");
    EXPECT_EQ(k["lesson"], "catch-up");
    EXPECT_EQ(k["seed"], 1);
    expect_on_grids(L, k);
    for (const json& s : k["students"]) {
        const json& v = s["values"];
        const double ma = v["A.mass"], va = v["A.v"], mb = v["B.mass"], vb = v["B.v"], e = v["scene.restitution"];
        const double j = (1 + e) * ma * mb * (va - vb) / (ma + mb);
        const double vaf = va - j / ma, vbf = vb + j / mb;
        const double lost = 0.5 * ma * va * va + 0.5 * mb * vb * vb - 0.5 * ma * vaf * vaf - 0.5 * mb * vbf * vbf;
        // Questions 1 to 4 of the lesson page: J, v_af, v_bf, the energy lost.
        const std::vector<std::pair<std::string, double>> expected = {
            {"impulse", j}, {"velocity_after", vaf}, {"velocity_after", vbf}, {"energy_lost", lost}};
        ASSERT_EQ(s["answers"].size(), expected.size()) << s.dump();
        for (std::size_t i = 0; i < expected.size(); ++i) {
            const json& a = s["answers"][i];
            EXPECT_EQ(a["question"], static_cast<int>(i) + 1);
            EXPECT_EQ(a["quantity"], expected[i].first);
            EXPECT_NEAR(a["value"].get<double>(), expected[i].second, rel(expected[i].second))
                << "student " << s["student"] << ", question " << i + 1;
        }
        EXPECT_EQ(s["answers"][0]["unit"], "N s");
        EXPECT_EQ(s["answers"][0]["text"], "What impulse J does B receive?");  // the lesson's words
        EXPECT_EQ(s["answers"][1]["unit"], "m/s");
        EXPECT_EQ(s["answers"][3]["unit"], "J");
    }
}

TEST(Worksheet, RotationAnswersAreTheEnginesAndKeepAngularMomentum) {
    const Lesson L = lesson_file("03-rotation-directions.toml");
    const json k = key("rotation-directions");
    expect_on_grids(L, k);
    Lesson asked = L;
    asked.questions.clear();
    for (std::size_t i : worksheet_questions(L))
        if (L.questions[i].has_quantity()) asked.questions.push_back(L.questions[i]);
    ASSERT_EQ(asked.questions.size(), 5u);
    for (const json& s : k["students"]) {
        const std::map<std::string, double> values = s["values"].get<std::map<std::string, double>>();
        Lesson changed = lesson_with_values(L, values);
        changed.questions = asked.questions;
        const std::vector<LessonAnswer> answers = answer_questions(changed);
        ASSERT_EQ(s["answers"].size(), answers.size());
        for (std::size_t i = 0; i < answers.size(); ++i)
            EXPECT_NEAR(s["answers"][i]["value"].get<double>(), answers[i].value, rel(answers[i].value))
                << "student " << s["student"] << ", question " << i + 1;
        // Question 5: the total about the origin after the hit. Before it only A turns, about
        // its centre at the origin, and B is at rest: L = I_a w_ai with I_a = m (L^2 + h^2) / 12.
        const double Ia = 1.0 * (1.0 * 1.0 + 0.06 * 0.06) / 12.0;
        const json& total = s["answers"][4];
        EXPECT_EQ(total["quantity"], "angular_momentum_after");
        EXPECT_NEAR(total["value"].get<double>(), Ia * values.at("A.w"), 1e-9) << "student " << s["student"];
    }
}

// A 2D sheet gives each body's angle in degrees (the lesson file's radians beside it): A's
// angle of rotation-directions, whatever a student's value in radians, as 180 a / pi.
TEST(Worksheet, TwoDimensionalAnglesAreInDegrees) {
    const std::string sheets = slurp(written("rotation-directions") / "sheets.html");
    const json k = key("rotation-directions");
    EXPECT_EQ(sheets.find("angle (rad)"), std::string::npos);
    for (const json& s : k["students"]) {
        const auto values = s["values"].get<std::map<std::string, double>>();
        const double a = values.count("A.angle") ? values.at("A.angle") : 0.6;
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.4g\u00b0 (%g rad)", a * 180.0 / 3.14159265358979323846, a);
        EXPECT_NE(sheets.find(buf), std::string::npos) << buf;
    }
}

// The tags of `html` that carry `marker` (an attribute and its value), each as its text
// between '<' and '>'.
std::vector<std::string> tags_with(const std::string& html, const std::string& marker) {
    std::vector<std::string> out;
    for (std::size_t at = html.find(marker); at != std::string::npos; at = html.find(marker, at + 1)) {
        const std::size_t open = html.rfind('<', at), close = html.find('>', at);
        out.push_back(html.substr(open, close - open + 1));
    }
    return out;
}

// An attribute's value in a tag; NaN when it has none.
double attr(const std::string& tag, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const std::size_t at = tag.find(key);
    if (at == std::string::npos) return std::nan("");
    return std::stod(tag.substr(at + key.size()));
}

// The one tag of `html` with `marker`; fails the test unless there is exactly one.
std::string one_tag(const std::string& html, const std::string& marker) {
    const std::vector<std::string> tags = tags_with(html, marker);
    EXPECT_EQ(tags.size(), 1u) << marker;
    return tags.empty() ? std::string() : tags.front();
}

// Each student's sheet of a 2D lesson draws their own set-up (issue 33, item 7): the contact
// point p, the normal n and r_a, r_b of the SVG are those of the student's collision as the
// key works it out (draw_student, 1e-9), and those are the closed forms of general-2d's
// geometry: A (0.4 x 0.2, turned 45 degrees) meets B's left face (x = 0.2) with its right-most
// corner, (0.3, 0.1) / sqrt 2 from its centre, whatever the student's values; n = (1, 0).
// The bodies at the start and the velocities drawn are the student's values; no two labels
// overlap; students with other values get other figures.
TEST(Worksheet, TwoDimensionalSheetsDrawEachStudentsSetUp) {
    const Lesson L = lesson_file("06-general-2d.toml");
    const fs::path out = scratch("figure");
    std::string err;
    ASSERT_EQ(worksheet("general-2d -o " + out.string() + " --students 5 --seed 3", &err), 0) << err;
    const std::string sheets = slurp(out / "sheets.html");
    std::vector<std::string> sections;
    for (std::size_t at = sheets.find("<section class=\"sheet\">"); at != std::string::npos;) {
        const std::size_t next = sheets.find("<section class=\"sheet\">", at + 1);
        sections.push_back(sheets.substr(at, next == std::string::npos ? std::string::npos : next - at));
        at = next;
    }
    ASSERT_EQ(sections.size(), 5u);
    const double c = std::sqrt(0.5);
    std::vector<std::string> svgs;
    for (int k = 1; k <= 5; ++k) {
        const std::string& sec = sections[static_cast<std::size_t>(k - 1)];
        SCOPED_TRACE("student " + std::to_string(k));
        ASSERT_EQ(tags_with(sec, "<svg").size(), 1u);
        const std::size_t s0 = sec.find("<svg"), s1 = sec.find("</svg>");
        const std::string svg = sec.substr(s0, s1 - s0);
        svgs.push_back(svg);
        const StudentSheet s = draw_student(L, 3, k);
        ASSERT_EQ(s.worked.size(), 1u);
        const SolveProblem& pr = s.worked[0].problem;
        // p and n: the problem's, and the closed form.
        const std::string p = one_tag(svg, "data-point=\"p\"");
        EXPECT_NEAR(attr(p, "data-x"), pr.point.x(), 1e-9);
        EXPECT_NEAR(attr(p, "data-y"), pr.point.y(), 1e-9);
        EXPECT_NEAR(attr(p, "data-x"), 0.2, 1e-6);
        EXPECT_NEAR(attr(p, "data-y"), 0.1 * c, 1e-6);
        const std::string nv = one_tag(svg, "data-vector=\"n\"");
        EXPECT_NEAR(attr(nv, "data-x"), pr.point.x(), 1e-9);
        EXPECT_NEAR(attr(nv, "data-y"), pr.point.y(), 1e-9);
        EXPECT_NEAR(attr(nv, "data-dx"), pr.normal.x(), 1e-9);
        EXPECT_NEAR(attr(nv, "data-dy"), pr.normal.y(), 1e-9);
        EXPECT_NEAR(attr(nv, "data-dx"), 1.0, 1e-9);
        EXPECT_NEAR(attr(nv, "data-dy"), 0.0, 1e-9);
        // r_a, r_b: from each centre where the bodies touch to p.
        const std::string ra = one_tag(svg, "data-vector=\"r_a\""), rb = one_tag(svg, "data-vector=\"r_b\"");
        EXPECT_NEAR(attr(ra, "data-x"), pr.a.b2.position.x(), 1e-9);
        EXPECT_NEAR(attr(ra, "data-dx"), pr.point.x() - pr.a.b2.position.x(), 1e-9);
        EXPECT_NEAR(attr(ra, "data-dy"), pr.point.y() - pr.a.b2.position.y(), 1e-9);
        EXPECT_NEAR(attr(ra, "data-dx"), 0.3 * c, 1e-6);
        EXPECT_NEAR(attr(ra, "data-dy"), 0.1 * c, 1e-6);
        const double yb = s.values.at("B.position.y");
        EXPECT_NEAR(attr(rb, "data-x"), 0.3, 1e-9);  // B does not move before the hit
        EXPECT_NEAR(attr(rb, "data-y"), yb, 1e-9);
        EXPECT_NEAR(attr(rb, "data-dx"), -0.1, 1e-6);
        EXPECT_NEAR(attr(rb, "data-dy"), 0.1 * c - yb, 1e-6);
        // A drawn where it touches: moved along +x only, by the distance its corner had to go.
        const std::string a_hit = one_tag(svg, "data-body-at-hit=\"A\"");
        EXPECT_NEAR(attr(a_hit, "data-x"), 0.2 - 0.3 * c, 1e-6);
        EXPECT_NEAR(attr(a_hit, "data-y"), 0.0, 1e-9);
        EXPECT_TRUE(tags_with(svg, "data-body-at-hit=\"B\"").empty());  // B waits at its start
        // The start: the student's values, as the givens' table has them.
        const std::string b = one_tag(svg, "data-body=\"B\" data-x");
        EXPECT_EQ(attr(b, "data-y"), yb);
        const std::string a = one_tag(svg, "data-body=\"A\" data-x");
        EXPECT_EQ(attr(a, "data-x"), -0.6);
        EXPECT_NEAR(attr(a, "data-angle"), 0.25 * 3.14159265358979323846, 1e-15);
        const std::string va = one_tag(svg, "data-vector=\"v\"");
        EXPECT_NE(va.find("data-body=\"A\""), std::string::npos);
        EXPECT_EQ(attr(va, "data-dx"), s.values.at("A.v.x"));
        EXPECT_EQ(attr(va, "data-dy"), 0.0);
        // No answer: no impulse, nothing after.
        EXPECT_EQ(svg.find("impulse"), std::string::npos);
        // The labels: each of p, n, r_a, r_b, v_A, A, B once, placed where no other is.
        std::vector<std::array<double, 4>> boxes;
        for (const std::string& t : tags_with(svg, "data-box=")) {
            EXPECT_EQ(t.find("data-crowded"), std::string::npos) << t;
            std::istringstream in(t.substr(t.find("data-box=\"") + 10));
            std::array<double, 4> box{};
            in >> box[0] >> box[1] >> box[2] >> box[3];
            for (const auto& o : boxes)
                EXPECT_FALSE(box[0] < o[2] && o[0] < box[2] && box[1] < o[3] && o[1] < box[3]) << t;
            boxes.push_back(box);
        }
        for (const char* label : {"p", "n", "r_a", "r_b", "v_A", "A", "B", "x", "y"})
            EXPECT_EQ(tags_with(svg, std::string("data-label=\"") + label + "\"").size(), 1u) << label;
    }
    // Other values, another figure.
    for (std::size_t i = 0; i < svgs.size(); ++i)
        for (std::size_t j = i + 1; j < svgs.size(); ++j)
            if (draw_student(L, 3, static_cast<int>(i) + 1).values !=
                draw_student(L, 3, static_cast<int>(j) + 1).values) {
                EXPECT_NE(svgs[i], svgs[j]) << "students " << i + 1 << " and " << j + 1;
            }
    // A 1D sheet has no figure.
    EXPECT_EQ(slurp(written("catch-up") / "sheets.html").find("<svg"), std::string::npos);
    fs::remove_all(out);
}

TEST(Worksheet, SheetsShowNoAnswerAndNoWorkedExample) {
    for (const std::string id : {"catch-up", "rotation-directions"}) {
        const std::string sheets = slurp(written(id) / "sheets.html");
        const json k = key(id);
        EXPECT_EQ(std::count(sheets.begin(), sheets.end(), '\n') > 0, true);
        EXPECT_NE(sheets.find("Student 30"), std::string::npos);
        EXPECT_NE(sheets.find("break-after: page"), std::string::npos);
        EXPECT_EQ(sheets.find("worked out"), std::string::npos) << id;
        EXPECT_EQ(sheets.find("class=\"math"), std::string::npos) << id;
        EXPECT_EQ(sheets.find("Explanation"), std::string::npos) << id;
        // Each answer as the key prints it (4 significant figures) or to 6, followed by its
        // unit: never on a sheet.
        for (const json& s : k["students"])
            for (const json& a : s["answers"]) {
                const double x = std::abs(a["value"].get<double>());
                for (const char* format : {"%.4g", "%.6g"}) {
                    char buf[40];
                    std::snprintf(buf, sizeof buf, format, x);
                    const std::string shown = std::string(buf) + " " + a["unit"].get<std::string>();
                    EXPECT_EQ(sheets.find(shown), std::string::npos) << id << ": " << shown;
                }
            }
        // The key has them all, and the worked example.
        const std::string key_html = slurp(written(id) / "key.html");
        EXPECT_NE(key_html.find("worked out"), std::string::npos);
        EXPECT_NE(key_html.find("Student 30"), std::string::npos);
    }
}

// A seed outside 0 .. 2^64 - 1 ("-1", 2^64) quietly became the largest seed (issue 34): now
// refused (exit 2) naming the range, before anything is written; the largest seed itself is
// taken as written.
TEST(Worksheet, ASeedOutsideItsRangeIsRefusedNotMadeTheLargest) {
    const fs::path out = scratch("seed-range");
    for (const char* seed : {"-1", "18446744073709551616", "1e3", "7x", "''"}) {
        std::string err;
        EXPECT_EQ(worksheet("catch-up -o " + out.string() + " --students 2 --seed " + seed, &err), 2) << seed;
        EXPECT_NE(err.find("expected a whole number from 0 to 18446744073709551615"), std::string::npos) << err;
        EXPECT_FALSE(fs::exists(out)) << seed;
    }
    ASSERT_EQ(worksheet("catch-up -o " + out.string() + " --students 2 --seed 18446744073709551615"), 0);
    EXPECT_EQ(json::parse(slurp(out / "key.json"))["seed"].get<std::uint64_t>(), 18446744073709551615ULL);
    fs::remove_all(out);
}

TEST(Worksheet, TheSameSeedGivesTheSameFilesAnotherSeedOtherValues) {
    const fs::path a = scratch("seed-a"), b = scratch("seed-b"), c = scratch("seed-c");
    ASSERT_EQ(worksheet("catch-up rotation-directions -o " + a.string() + " --students 4 --seed 7"), 0);
    ASSERT_EQ(worksheet("catch-up rotation-directions -o " + b.string() + " --students 4 --seed 7"), 0);
    ASSERT_EQ(worksheet("catch-up rotation-directions -o " + c.string() + " --students 4 --seed 8"), 0);
    EXPECT_TRUE(fs::exists(a / "index.html"));
    for (const std::string id : {"catch-up", "rotation-directions"}) {
        for (const char* f : {"sheets.html", "key.html", "key.json"})
            EXPECT_EQ(slurp(a / id / f), slurp(b / id / f)) << id << "/" << f;
        const json ka = json::parse(slurp(a / id / "key.json")), kc = json::parse(slurp(c / id / "key.json"));
        EXPECT_EQ(ka["seed"], 7);
        EXPECT_EQ(kc["seed"], 8);
        int same = 0;
        for (std::size_t s = 0; s < 4; ++s) same += ka["students"][s]["values"] == kc["students"][s]["values"];
        EXPECT_LT(same, 4) << id;
    }
    fs::remove_all(a);
    fs::remove_all(b);
    fs::remove_all(c);
}

TEST(Worksheet, ARangeThatCannotCollideIsRefusedAndNothingIsWritten) {
    // catch-up with B up to 100 km/s: only B slower than about 1.08 m/s is caught within the
    // run (the lesson's own 0.3 m/s is on the grid, but 1 value in 100 000 of it).
    std::string text = slurp(kLessons + "01-catch-up.toml");
    const std::string from = "key = \"v\"\nrange = [0.1, 0.6]";
    ASSERT_NE(text.find(from), std::string::npos);
    text.replace(text.find(from), from.size(), "key = \"v\"\nrange = [0.3, 99999.9]");
    const fs::path file = scratch("slow.toml"), out = scratch("slow-out");
    std::ofstream(file) << text;
    std::string err;
    EXPECT_EQ(worksheet(file.string() + " -o " + out.string() + " --students 3", &err), 2);
    EXPECT_NE(err.find("collide: error: " + file.string()), std::string::npos) << err;
    EXPECT_NE(err.find("vary: no draw of A.mass, A.v, B.mass, B.v, scene.restitution in 50 tries"), std::string::npos)
        << err;
    EXPECT_NE(err.find("B.v = "), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_FALSE(fs::exists(out));
    for (const fs::directory_entry& e : fs::directory_iterator(out.parent_path()))
        EXPECT_EQ(e.path().filename().string().rfind(out.filename().string() + ".tmp", 0), std::string::npos);
    fs::remove(file);
}

// Runs `collide worksheet ARGS`; returns its exit code, stdout in *out.
int worksheet_stdout(const std::string& args, std::string* out) {
    const fs::path o = scratch("stdout");
    const std::string cmd =
        std::string("PATH=/nonexistent ") + COLLIDE_BIN + " worksheet " + args + " >" + o.string() + " 2>/dev/null";
    const int status = std::system(cmd.c_str());
    *out = slurp(o);
    fs::remove(o);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A user's lesson without [[vary]]: a sheet of the lesson's own numbers, said in the summary
// on stdout (not only on stderr) and in the key.
TEST(Worksheet, ALessonWithoutInputsSaysSoInItsSummary) {
    std::string text = slurp(kLessons + "01-catch-up.toml");
    text = text.substr(0, text.find("[[vary]]")) + text.substr(text.find("[[variant]]"));
    ASSERT_EQ(text.find("[[vary]]"), std::string::npos);
    const fs::path file = scratch("same.toml"), out = scratch("same-out");
    std::ofstream(file) << text;
    std::string stdout_text;
    ASSERT_EQ(worksheet_stdout(file.string() + " -o " + out.string() + " --students 2", &stdout_text), 0);
    EXPECT_NE(stdout_text.find("\nnote: catch-up has no [[vary]] ranges: every student's sheet has the lesson's own "
                               "numbers\n"),
              std::string::npos)
        << stdout_text;
    EXPECT_NE(slurp(out / "key.html").find("This lesson declares no [[vary]] ranges"), std::string::npos);
    // A lesson with inputs has no such line.
    const fs::path out2 = scratch("inputs-out");
    ASSERT_EQ(worksheet_stdout("catch-up -o " + out2.string() + " --students 2", &stdout_text), 0);
    EXPECT_EQ(stdout_text.find("note:"), std::string::npos) << stdout_text;
    fs::remove(file);
    fs::remove_all(out);
    fs::remove_all(out2);
}

TEST(Worksheet, ANonEmptyDirectoryNeedsForce) {
    const fs::path out = scratch("full");
    fs::create_directories(out);
    std::ofstream(out / "keep.txt") << "mine";
    std::string err;
    EXPECT_EQ(worksheet("catch-up -o " + out.string() + " --students 2", &err), 2);
    EXPECT_NE(err.find("not empty"), std::string::npos) << err;
    EXPECT_TRUE(fs::exists(out / "keep.txt"));
    EXPECT_EQ(worksheet("catch-up -o " + out.string() + " --students 2 --force", &err), 0) << err;
    EXPECT_FALSE(fs::exists(out / "keep.txt"));
    EXPECT_TRUE(fs::exists(out / "key.json"));
    EXPECT_FALSE(fs::exists(out / "sheets.pdf"));
    EXPECT_NE(err.find("PDFs skipped: weasyprint is not installed"), std::string::npos) << err;
    fs::remove_all(out);
}

// Output paths (issue 34): "-o DIR/" is DIR (it used to stage inside DIR and fail after all
// the work with "cannot rename: Invalid argument", leaving an empty DIR); "-o ." and a
// symbolic link that loops are refused at once, before any sheet is drawn, and leave nothing.
// A symbolic link to a directory is written through.
TEST(Worksheet, OutputPathsAreCheckedBeforeAnyWork) {
    const fs::path out = scratch("slash");
    std::string err;
    EXPECT_EQ(worksheet("catch-up -o " + out.string() + "/ --students 2", &err), 0) << err;
    EXPECT_TRUE(fs::exists(out / "key.json"));
    for (const fs::directory_entry& e : fs::directory_iterator(out))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos);
    fs::remove_all(out);

    const fs::path here = scratch("here");
    fs::create_directories(here);
    const std::string in_here = "cd " + here.string() + " && ";
    const fs::path e = scratch("here-err");
    const auto in = [&](const std::string& args) {
        const int status = std::system(
            (in_here + "PATH=/nonexistent " + COLLIDE_BIN + " worksheet " + args + " >/dev/null 2>" + e.string())
                .c_str());
        err = slurp(e);
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    };
    EXPECT_EQ(in("catch-up -o . --students 2 --force"), 2);
    EXPECT_NE(err.find("holds the current directory"), std::string::npos) << err;
    EXPECT_EQ(in("catch-up -o .. --students 2 --force"), 2);
    EXPECT_TRUE(fs::is_empty(here));
    fs::create_symlink("loop", here / "loop");
    EXPECT_EQ(in("catch-up -o loop --students 2"), 2);
    EXPECT_NE(err.find("loop: is a symbolic link that leads nowhere"), std::string::npos) << err;
    EXPECT_EQ(in("catch-up -o loop/inner --students 2"), 2);
    EXPECT_NE(err.find("loop/inner: cannot be"), std::string::npos) << err;
    fs::create_directories(here / "real");
    fs::create_directory_symlink("real", here / "link");
    EXPECT_EQ(in("catch-up -o link --students 2"), 0) << err;
    EXPECT_TRUE(fs::exists(here / "real/key.json"));
    EXPECT_TRUE(fs::is_symlink(here / "link"));
    fs::remove(e);
    fs::remove_all(here);
}

TEST(Worksheet, PdfsWhenWeasyprintIsInstalled) {
    if (std::system("command -v weasyprint >/dev/null 2>&1") != 0) GTEST_SKIP() << "weasyprint is not installed";
    const fs::path out = scratch("pdf");
    std::string err;
    ASSERT_EQ(worksheet("catch-up rotation-directions -o " + out.string() + " --students 3", &err, true), 0) << err;
    EXPECT_EQ(err.find("PDFs skipped"), std::string::npos) << err;
    const bool pdfinfo = std::system("command -v pdfinfo >/dev/null 2>&1") == 0;
    for (const std::string id : {"catch-up", "rotation-directions"})
        for (const char* f : {"sheets.pdf", "key.pdf"}) {
            const fs::path pdf = out / id / f;
            EXPECT_EQ(slurp(pdf).rfind("%PDF-", 0), 0u) << pdf;
            if (!pdfinfo || std::string(f) != "sheets.pdf") continue;
            // One page a student: a sheet that runs onto a second page is not a worksheet.
            const fs::path info = scratch("pdfinfo");
            ASSERT_EQ(std::system(("pdfinfo " + pdf.string() + " >" + info.string()).c_str()), 0);
            EXPECT_NE(slurp(info).find("Pages:           3\n"), std::string::npos) << pdf << "\n" << slurp(info);
            fs::remove(info);
        }
    fs::remove_all(out);
}

TEST(Worksheet, TheGeneratorIsSplitmix64) {
    // The published first outputs of splitmix64 from state 0: the draw is the same everywhere.
    std::uint64_t state = 0;
    EXPECT_EQ(splitmix64(state), 0xe220a8397b1dcdafULL);
    EXPECT_EQ(splitmix64(state), 0x6e789e6aa1b965f4ULL);
}

}  // namespace
}  // namespace collide
