// `collide worksheet` end to end: the command is run as a user runs it, and its key.json is
// checked against answers computed here (closed forms for the 1D catch-up; for the turning bar
// of rotation-directions, the engine's answer_questions on lesson_with_values of the values
// read back, and conservation of angular momentum about the origin in closed form), its HTML
// for what a student must not see, and its refusals for what must leave nothing behind.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
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
