// Lessons (scenario/lesson.h, teach/answers.h): every bundled lesson loads, runs and answers its questions; the
// answers match closed forms; malformed lesson files are refused with their key.
#include "teach/answers.h"

#include "engine/world.h"
#include "engine/world1d.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

namespace collide {
namespace {

const std::string kDir = std::string(COLLIDE_SOURCE_DIR) + "/lessons";

const Lesson& find(const std::vector<Lesson>& all, const std::string& id) {
    for (const Lesson& L : all)
        if (L.id == id) return L;
    throw std::runtime_error("no lesson " + id);
}

TEST(Lessons, EveryBundledLessonLoadsRunsAndAnswersEveryQuestion) {
    const std::vector<Lesson> all = load_lessons(kDir);
    ASSERT_FALSE(all.empty());
    for (const Lesson& L : all) {
        SCOPED_TRACE(L.file);
        EXPECT_FALSE(L.title.empty());
        EXPECT_FALSE(L.explanation.empty());
        EXPECT_FALSE(L.goals.empty());
        // The student's page asks before it tells: the givens come first, on their own; the
        // teacher's page has its own content (scenario/lesson.h LessonTeacher).
        EXPECT_FALSE(L.setup.empty()) << "a bundled lesson needs its set-up (the givens)";
        ASSERT_TRUE(L.teacher.has_value()) << "a bundled lesson needs its [teacher] table";
        EXPECT_FALSE(L.teacher->level.empty());
        EXPECT_FALSE(L.teacher->prerequisites.empty());
        EXPECT_GT(L.teacher->minutes, 0);
        EXPECT_FALSE(L.teacher->misconceptions.empty());
        EXPECT_FALSE(L.teacher->ask.empty());
        EXPECT_FALSE(L.teacher->live.empty());
        const std::vector<LessonAnswer> answers = answer_questions(L);
        ASSERT_EQ(answers.size(), L.questions.size());
        for (const LessonAnswer& a : answers) EXPECT_TRUE(std::isfinite(a.value)) << a.text;
        std::ostringstream md;
        write_lesson_markdown(L, answers, md);
        EXPECT_NE(md.str().find("# " + L.title), std::string::npos);
    }
    // Ordered, ids unique (load_lessons refuses duplicates).
    for (std::size_t i = 1; i < all.size(); ++i) EXPECT_LE(all[i - 1].order, all[i].order);
}

// Every bundled lesson's run (and every bundled scene's) stays well within the WebAssembly
// module's work budget (engine/scene.h kWasmWorkBudget, 5e6; the command's is 1e8), so that no
// lesson page's Try-it panel is refused at its own values: within a fifth of it (the largest,
// bin-2d, takes about 4e5).
TEST(Lessons, EveryBundledRunIsWellWithinTheBrowsersWorkBudget) {
    std::vector<std::string> files;
    for (const Lesson& L : load_lessons(kDir)) files.push_back(L.file);
    for (const auto& e : std::filesystem::directory_iterator(kDir + "/scenes")) files.push_back(e.path().string());
    for (const std::string& f : files) {
        SCOPED_TRACE(f);
        const Scene s = load_scenario(f);
        EXPECT_EQ(s.work_budget, kDefaultWorkBudget);
        double work = 0.0;
        if (s.dimension == 1) {
            World1 w(s);
            std::vector<Event1> events;
            w.advance_to(s.duration, &events);
            work = static_cast<double>(w.work_done());
        } else if (s.dimension == 2) {
            World2 w(s);
            std::vector<Event2> events;
            w.advance_to(s.duration, &events);
            work = static_cast<double>(w.work_done());
        } else {
            World3 w(s);
            std::vector<Event3> events;
            w.advance_to(s.duration, &events);
            work = static_cast<double>(w.work_done());
        }
        EXPECT_LT(work, kWasmWorkBudget / 5);
    }
}

// The tumbling box's comment states the moments of inertia a teacher reads off the file; they
// once were not those of the box the file builds (issue 34: 0.02, 0.05, 0.065 for 0.0167,
// 0.0333, 0.0433). Each stated moment, to its last digit (1e-4 kg m^2), is the engine's.
TEST(Lessons, TheTumblingBoxStatesTheMomentsTheEngineUses) {
    const std::string file = kDir + "/scenes/tumbling-box-3d.toml";
    std::ifstream in(file);
    std::string comment;
    for (std::string line; std::getline(in, line) && line.rfind('#', 0) == 0;) comment += line.substr(1);
    std::string flat;  // the comment on one line, single spaces
    for (char c : comment)
        if (!(c == ' ' && !flat.empty() && flat.back() == ' ')) flat += c;
    const std::size_t at = flat.find("= ");
    ASSERT_NE(at, std::string::npos) << flat;
    double stated[3] = {0, 0, 0};
    ASSERT_EQ(std::sscanf(flat.c_str() + at, "= %lf, %lf and %lf kg m^2", &stated[0], &stated[1], &stated[2]), 3)
        << flat;
    const Scene s = load_scenario(file);
    ASSERT_EQ(s.bodies.size(), 1u);
    for (int k = 0; k < 3; ++k) {
        const double I = s.bodies[0].body3.inertia(k, k);
        EXPECT_NEAR(stated[k], I, 0.5e-4) << "axis " << k;  // half the last stated digit
    }
}

TEST(Lessons, CatchUpAnswersAreTheClosedForms) {
    const std::vector<Lesson> all = load_lessons(kDir);
    const Lesson& L = find(all, "catch-up");
    const double ma = L.scene.bodies[0].body1.mass, mb = L.scene.bodies[1].body1.mass;
    const double va = L.scene.bodies[0].body1.v, vb = L.scene.bodies[1].body1.v;
    const double e = L.scene.restitution;
    // J = (1 + e) ma mb (va - vb) / (ma + mb); va' = va - J/ma; vb' = vb + J/mb;
    // lost energy (1 - e^2) ma mb (va - vb)^2 / (2 (ma + mb)).
    const double J = (1 + e) * ma * mb * (va - vb) / (ma + mb);
    const double lost = (1 - e * e) * ma * mb * (va - vb) * (va - vb) / (2 * (ma + mb));
    const std::vector<LessonAnswer> a = answer_questions(L);
    ASSERT_EQ(a.size(), 7u);
    EXPECT_NEAR(a[0].value, J, 1e-12);
    EXPECT_NEAR(a[1].value, va - J / ma, 1e-12);
    EXPECT_NEAR(a[2].value, vb + J / mb, 1e-12);
    EXPECT_NEAR(a[3].value, lost, 1e-12);
    EXPECT_GT(J, 0.0);  // A catches B: J > 0
    // The prediction and the why question are answered by the lesson's own text.
    EXPECT_FALSE(a[4].computed);
    EXPECT_EQ(a[4].text, "option 1");
    EXPECT_FALSE(a[5].computed);
    EXPECT_EQ(a[5].text, L.questions[5].answer);
    // What if the masses were swapped: the run of the changed scene answers, J unchanged
    // (m_a m_b / (m_a + m_b) is symmetric) and A, now 1 kg, loses J / 1 of its speed.
    ASSERT_EQ(L.questions[6].what_if.size(), 2u);
    EXPECT_TRUE(a[6].computed);
    const double ma2 = L.questions[6].what_if.at("A.mass"), mb2 = L.questions[6].what_if.at("B.mass");
    const double J2 = (1 + e) * ma2 * mb2 * (va - vb) / (ma2 + mb2);
    EXPECT_NEAR(J2, J, 1e-12);
    EXPECT_NEAR(a[6].value, va - J2 / ma2, 1e-12);
    EXPECT_GT(std::abs(a[6].value - a[1].value), 0.1);  // not the lesson's own answer
}

// A what-if on the scene: the bouncing ball's bounces end at T = sqrt(2H/g) (1 + e) / (1 - e)
// for the question's e, not the lesson's.
TEST(Lessons, BouncingBallWhatIfIsAnsweredForItsOwnRestitution) {
    const std::vector<Lesson> all = load_lessons(kDir);
    const Lesson& L = find(all, "bouncing-ball");
    std::size_t k = L.questions.size();
    for (std::size_t i = 0; i < L.questions.size(); ++i)
        if (!L.questions[i].what_if.empty()) k = i;
    ASSERT_LT(k, L.questions.size());
    const double e = L.questions[k].what_if.at("scene.restitution");
    EXPECT_NE(e, L.scene.restitution);
    const double g = -L.scene.gravity.y();
    const double H =
        L.scene.bodies[1].body2.position.y() - L.scene.bodies[1].shape2.radius - L.scene.bodies[0].shape2.offset;
    const std::vector<LessonAnswer> a = answer_questions(L);
    EXPECT_NEAR(a[k].value, std::sqrt(2 * H / g) * (1 + e) / (1 - e), 1e-6);
}

// lesson.md asks the predictions before the figure and checks them after it; choices are
// numbered and every option's reason is given; numbers show their tolerance.
TEST(Lessons, MarkdownAsksPredictionsBeforeTheFigureAndChecksThemAfter) {
    const std::vector<Lesson> all = load_lessons(kDir);
    const Lesson& L = find(all, "catch-up");
    std::ostringstream md;
    write_lesson_markdown(L, answer_questions(L), md);
    const std::string s = md.str();
    const std::size_t before = s.find("## Before you watch"), figure = s.find("](figure.png)"),
                      check = s.find("## Check your predictions"), questions = s.find("## Questions");
    ASSERT_NE(before, std::string::npos);
    ASSERT_NE(check, std::string::npos);
    EXPECT_LT(before, figure);
    EXPECT_LT(figure, check);
    EXPECT_LT(check, questions);
    const std::string& predict = L.questions[4].text;
    EXPECT_LT(s.find(predict), figure);                                          // asked before
    EXPECT_NE(s.find(predict, figure), std::string::npos);                       // and checked after
    EXPECT_EQ(s.find("Option 1 is right"), s.find("Option 1 is right", check));  // only after
    EXPECT_NE(s.find("   - (4) " + L.questions[4].choices[3]), std::string::npos);
    for (std::size_t k = 0; k < L.questions[4].reasons.size(); ++k)
        EXPECT_NE(s.find(L.questions[4].reasons[k], check), std::string::npos) << k;
    EXPECT_NE(s.find("What impulse J does B receive? *(to within 2 %)*"), std::string::npos);
    EXPECT_NE(s.find(L.questions[5].answer), std::string::npos);
}

TEST(Lessons, CatchUpVariantsGiveTheClosedFormImpulseForTheirRestitution) {
    const std::vector<Lesson> all = load_lessons(kDir);
    const Lesson& L = find(all, "catch-up");
    ASSERT_EQ(L.variants.size(), 2u);
    for (const LessonVariant& v : L.variants) {
        SCOPED_TRACE(v.label);
        const Scene& s = v.scene;
        const double ma = s.bodies[0].body1.mass, mb = s.bodies[1].body1.mass;
        const double dv = s.bodies[0].body1.v - s.bodies[1].body1.v;
        const double e = s.pair_restitution(0, 1);
        EXPECT_NE(e, L.scene.pair_restitution(0, 1));  // the variant changed it
        World1 world(s);
        std::vector<Event1> events;
        world.advance_to(s.duration, &events);
        ASSERT_FALSE(events.empty());
        EXPECT_NEAR(events[0].impulse, (1 + e) * ma * mb * dv / (ma + mb), 1e-12);
    }
}

TEST(Lessons, AnIdResolvesToItsFileAndAnUnknownOneGetsAHint) {
    const std::vector<Lesson> all = load_lessons(kDir);
    EXPECT_EQ(resolve_lesson("catch-up", kDir), find(all, "catch-up").file);
    try {
        resolve_lesson("catchup", kDir);
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("did you mean 'catch-up'?"), std::string::npos) << e.what();
    }
}

// A lesson found by its file name (NN-id.toml) is read alone: another lesson's mistake in
// the same folder does not stop it; a lesson whose file is named otherwise is still found.
TEST(Lessons, AnIdIsFoundBesideABrokenLesson) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(::testing::TempDir()) / "lessons-beside-broken";
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy_file(find(load_lessons(kDir), "catch-up").file, dir / "01-catch-up.toml");
    fs::copy_file(find(load_lessons(kDir), "reversed").file, dir / "renamed.toml");
    std::ofstream(dir / "03-broken.toml") << "[lesson]\nid = \"broken\"\nthis is not toml\n";
    EXPECT_EQ(resolve_lesson("catch-up", dir.string()), (dir / "01-catch-up.toml").string());
    EXPECT_THROW(load_lessons(dir.string()), InputError);                // listing them all still fails
    EXPECT_THROW(resolve_lesson("reversed", dir.string()), InputError);  // found only by scanning all
    fs::remove(dir / "03-broken.toml");
    EXPECT_EQ(resolve_lesson("reversed", dir.string()), (dir / "renamed.toml").string());
    fs::remove_all(dir);
}

struct BadLesson {
    const char* what;
    const char* tail;  // appended to a valid 1D scene
    const char* key;
    const char* fragment;
};

void PrintTo(const BadLesson& b, std::ostream* os) { *os << b.what; }

class LessonBad : public ::testing::TestWithParam<BadLesson> {};

const char* kScene = R"([scene]
dimension = 1
duration = 1.0
[[body]]
name = "A"
shape = "block"
length = 0.2
mass = 1.0
position = -0.5
v = 1.0
[[body]]
name = "B"
shape = "block"
length = 0.2
mass = 1.0
position = 0.5
)";

TEST_P(LessonBad, IsRefusedWithItsKey) {
    const BadLesson& b = GetParam();
    // One file per case: ctest runs the cases in parallel processes.
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '-';
    const std::string path = ::testing::TempDir() + "/lesson-" + name + ".toml";
    {
        std::ofstream out(path);
        out << kScene << b.tail;
    }
    try {
        const Lesson L = load_lesson(path);
        answer_questions(L);
        FAIL() << b.what << ": accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.key(), b.key) << b.what << ": " << e.what();
        EXPECT_NE(std::string(e.what()).find(b.fragment), std::string::npos) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(
    Catalogue, LessonBad,
    ::testing::Values(
        BadLesson{"no [lesson] table", "", "", "missing table [lesson]"},
        BadLesson{"unknown key in [teacher]",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[teacher]\nlevel = \"l\"\nprerequisites = [\"p\"]\n"
                  "minute = 20\n",
                  "teacher.minute", "did you mean 'minutes'?"},
        BadLesson{"[teacher] without a level",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[teacher]\nprerequisites = [\"p\"]\nminutes = 20\n",
                  "teacher.level", "missing key 'level'"},
        BadLesson{"[teacher] without a misconception",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[teacher]\nlevel = \"l\"\nprerequisites = [\"p\"]\n"
                  "minutes = 20\nlive = \"move e\"\n",
                  "teacher.misconception", "at least one"},
        BadLesson{"unknown key in a misconception",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[teacher]\nlevel = \"l\"\nprerequisites = [\"p\"]\n"
                  "minutes = 20\nlive = \"move e\"\n[[teacher.misconception]]\nbelief = \"b\"\nevidenc = \"e\"\n",
                  "teacher.misconception[1].evidenc", "did you mean 'evidence'?"},
        BadLesson{"[teacher] minutes out of range",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[teacher]\nlevel = \"l\"\nprerequisites = [\"p\"]\n"
                  "minutes = 0\n",
                  "teacher.minutes", "from 1 to 600"},
        BadLesson{"setup not text", "[lesson]\nid = \"x\"\ntitle = \"t\"\nsetup = 3\n", "lesson.setup", "the set-up"},

        BadLesson{"no id", "[lesson]\ntitle = \"t\"\n", "lesson.id", "missing key 'id'"},
        BadLesson{"bad id", "[lesson]\nid = \"a b\"\ntitle = \"t\"\n", "lesson.id", "letters, digits and -"},
        BadLesson{"unknown quantity",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\ntext = \"?\"\nquantity = \"impuls\"\n",
                  "question[1].quantity", "did you mean 'impulse'?"},
        BadLesson{"unknown body",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\ntext = \"?\"\n"
                  "quantity = \"velocity_after\"\nbody = \"C\"\n",
                  "question[1].body", "no body named 'C'"},
        BadLesson{"spin on a line",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\ntext = \"?\"\n"
                  "quantity = \"spin_after\"\nbody = \"A\"\n",
                  "question[1].quantity", "do not spin"},
        BadLesson{"a collision the run does not have",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\ntext = \"?\"\n"
                  "quantity = \"impulse\"\nevent = 3\n",
                  "question[1].event", "the run has 1"},
        BadLesson{"variant with e > 1",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[variant]]\nlabel = \"e = 2\"\nrestitution = 2.0\n",
                  "variant[1].restitution", "in [0, 1]"},
        BadLesson{"variant without a label", "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[variant]]\nrestitution = 0.5\n",
                  "variant[1].label", "missing key 'label'"},
        BadLesson{"penalty stiffness not positive",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[penalty]\nstiffness = -2.0e4\n", "penalty.stiffness",
                  "expected a stiffness > 0 N/m"},
        BadLesson{"penalty damping ratio over-damped",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[penalty]\nstiffness = 2.0e4\ndamping_ratios = [0.2, 1.5]\n",
                  "penalty.damping_ratios", "in [0, 1)"},
        BadLesson{"penalty stiffnesses with a zero",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[penalty]\nstiffness = 2.0e4\nstiffnesses = [1.0e4, 0.0]\n",
                  "penalty.stiffnesses", "expected stiffnesses > 0 N/m"},
        BadLesson{"penalty key misspelt", "[lesson]\nid = \"x\"\ntitle = \"t\"\n[penalty]\nstifness = 2.0e4\n",
                  "penalty.stifness", "did you mean 'stiffness'?"},
        BadLesson{"penalty time step of a nanosecond",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[penalty]\nstiffness = 2.0e4\ntime_step = 1e-9\n"
                  "[[question]]\ntext = \"?\"\nquantity = \"penalty_contact_time\"\n",
                  "penalty.time_step", "at least pi sqrt(m/k) / 100000"},
        BadLesson{"penalty quantity without [penalty]",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\ntext = \"?\"\nquantity = \"penalty_impulse\"\n",
                  "question[1].quantity", "add a [penalty] table"},
        BadLesson{"unknown question kind",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\nkind = \"chioce\"\ntext = \"?\"\n",
                  "question[1].kind", "did you mean 'choice'?"},
        BadLesson{"choice: right option out of range",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\nkind = \"choice\"\ntext = \"?\"\n"
                  "choices = [\"a\", \"b\"]\ncorrect = 0\nreasons = [\"r\", \"s\"]\n",
                  "question[1].correct", "from 1 to 2, got 0"},
        BadLesson{"choice: fewer reasons than choices",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\nkind = \"choice\"\ntext = \"?\"\n"
                  "choices = [\"a\", \"b\", \"c\"]\ncorrect = 1\nreasons = [\"r\", \"s\"]\n",
                  "question[1].reasons", "one reason for each of the 3 choices, got 2"},
        BadLesson{"choice: seven options",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\nkind = \"choice\"\ntext = \"?\"\n"
                  "choices = [\"a\", \"b\", \"c\", \"d\", \"e\", \"f\", \"g\"]\ncorrect = 1\n"
                  "reasons = [\"1\", \"2\", \"3\", \"4\", \"5\", \"6\", \"7\"]\n",
                  "question[1].choices", "expected 2 to 6 options, got 7"},
        BadLesson{"choice: an empty reason",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\nkind = \"choice\"\ntext = \"?\"\n"
                  "choices = [\"a\", \"b\"]\ncorrect = 1\nreasons = [\"r\", \"\"]\n",
                  "question[1].reasons", "one of them is empty"},
        BadLesson{"choice with a quantity",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\nkind = \"choice\"\ntext = \"?\"\n"
                  "quantity = \"impulse\"\nchoices = [\"a\", \"b\"]\ncorrect = 1\nreasons = [\"r\", \"s\"]\n",
                  "question[1].quantity", "this one is a choice question"},
        BadLesson{"explain without an answer",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\nkind = \"explain\"\ntext = \"Why?\"\n",
                  "question[1].answer", "missing key 'answer'"},
        BadLesson{"explain with explain",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\nkind = \"explain\"\ntext = \"Why?\"\n"
                  "answer = \"a\"\nexplain = \"b\"\n",
                  "question[1].explain", "model answer is its 'answer'"},
        BadLesson{"numeric tolerance of 0",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\ntext = \"?\"\nquantity = \"impulse\"\n"
                  "tolerance = 0.0\n",
                  "question[1].tolerance", "> 0 and < 1"},
        BadLesson{"numeric with choices",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\ntext = \"?\"\nquantity = \"impulse\"\n"
                  "choices = [\"a\", \"b\"]\n",
                  "question[1].choices", "this one is a numeric question"},
        BadLesson{"predict with neither choices nor a quantity",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\nkind = \"predict\"\ntext = \"?\"\n"
                  "explain = \"e\"\n",
                  "question[1].quantity", "either 'choices'"},
        BadLesson{"predict with choices and a body",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\nkind = \"predict\"\ntext = \"?\"\n"
                  "choices = [\"a\", \"b\"]\ncorrect = 1\nreasons = [\"r\", \"s\"]\nbody = \"A\"\nexplain = \"e\"\n",
                  "question[1].body", "goes with 'quantity'"},
        BadLesson{"predict without why",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\nkind = \"predict\"\ntext = \"?\"\n"
                  "quantity = \"impulse\"\n",
                  "question[1].explain", "missing key 'explain'"},
        BadLesson{"what-if on a body that does not exist",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\ntext = \"?\"\nquantity = \"impulse\"\n"
                  "what_if = { \"C.mass\" = 2.0 }\n",
                  "question[1].what_if", "no body named 'C'"},
        BadLesson{"what-if that is not a number",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\ntext = \"?\"\nquantity = \"impulse\"\n"
                  "what_if = { \"A.mass\" = \"heavy\" }\n",
                  "question[1].what_if.A.mass", "expected a number"},
        BadLesson{"what-if after which the bodies never meet",
                  "[lesson]\nid = \"x\"\ntitle = \"t\"\n[[question]]\ntext = \"?\"\nquantity = \"impulse\"\n"
                  "what_if = { \"A.v\" = -1.0 }\n",
                  "question[1].what_if", "with A.v = -1: asks for collision 1 but the run has 0"},
        BadLesson{"unknown lesson key", "[lesson]\nid = \"x\"\ntitle = \"t\"\ngoal = [\"g\"]\n", "lesson.goal",
                  "did you mean 'goals'?"}));

}  // namespace
}  // namespace collide
