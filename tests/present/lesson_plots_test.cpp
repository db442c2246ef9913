// A lesson's [[plot]] entries (scenario/lesson_plot.cpp, present/lesson_plots.h): the reader
// (what it takes, what it refuses and where), and the plotted values against closed forms:
// the bouncing ball's free-fall parabolas and its bounce intervals shrinking by the factor e,
// the restitution bars' centre velocities after the hit, the dominoes' fitted wave speed.
#include "present/lesson_plots.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "present/frame_times.h"
#include "scenario/lesson.h"

namespace collide {
namespace {

const std::string kLessons = std::string(COLLIDE_SOURCE_DIR) + "/lessons/";

// A ball dropped on a floor: 2D, the ball's bottom 1 m up, e = 0.5.
const std::string kBall = R"([lesson]
id = "plot-test"
title = "Plots"

[scene]
dimension = 2
gravity = [0.0, -9.81]
duration = 2.0
output_dt = 0.01
restitution = 0.5

[[body]]
name = "floor"
shape = "plane"
normal = [0.0, 1.0]
offset = 0.0

[[body]]
name = "ball"
shape = "disc"
radius = 0.1
mass = 0.1
position = [0.0, 1.1]

[[mark]]
body = "ball"
at = [0.1, 0.0]
name = "rim"
)";

Lesson parse(const std::string& plots) { return parse_lesson_text(kBall + plots, "plots.toml", "plots.toml"); }

// The error a lesson with these [[plot]] lines is refused with.
std::string refusal(const std::string& plots) {
    try {
        parse(plots);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(LessonPlots, TheReaderTakesEachKind) {
    const Lesson L = parse(R"(
[[plot]]
title = "Height"
y = "ball.position.y"

[[plot]]
title = "Speeds"
x = "t"
y = ["ball.v.y", "ball.rim.v.x"]

[[plot]]
title = "Bounces"
per = "collision"
pair = ["ball", "floor"]
counting = "bounce"
y = "interval"
fit = "ratio"

[[plot]]
title = "Energy"
y = ["kinetic_energy", "potential_energy", "energy"]
)");
    ASSERT_EQ(L.plots.size(), 4u);
    EXPECT_EQ(L.plots[0].per, PlotPer::sample);
    EXPECT_EQ(L.plots[0].x.name, "t");
    EXPECT_EQ(L.plots[0].y.at(0).kind, PlotQuantity::Kind::position);
    EXPECT_EQ(L.plots[0].y.at(0).component, 1);
    EXPECT_EQ(L.plots[0].y.at(0).unit, "m");
    EXPECT_EQ(L.plots[1].y.at(1).mark, 0);
    EXPECT_EQ(L.plots[1].y.at(1).unit, "m/s");
    EXPECT_EQ(L.plots[2].per, PlotPer::collision);
    EXPECT_EQ(L.plots[2].x.name, "collision");
    EXPECT_EQ(L.plots[2].fit, PlotFit::ratio);
    EXPECT_EQ(L.plots[2].counting, "bounce");
    EXPECT_EQ(L.plots[2].pair_index, (std::vector<std::size_t>{1, 0}));
    EXPECT_EQ(L.plots[3].y.size(), 3u);
}

TEST(LessonPlots, TheReaderRefusesNamingLineAndKey) {
    // kBall's lines, then a blank one: [[plot]] on the next line, its keys below it.
    const int plot_line = static_cast<int>(std::count(kBall.begin(), kBall.end(), '\n')) + 2;
    const std::string at = "plots.toml:" + std::to_string(plot_line + 3);
    EXPECT_NE(refusal("\n[[plot]]\ntitle = \"H\"\ny = \"ball.position.y\"\ncolour = \"red\"\n")
                  .find(at + ":1: plot[1].colour: unknown key"),
              std::string::npos);
    EXPECT_NE(refusal("\n[[plot]]\ntitle = \"H\"\ny = \"bal.position.y\"\n")
                  .find("plots.toml:" + std::to_string(plot_line + 2) + ":5: plot[1].y: 'bal"),
              std::string::npos);
    EXPECT_NE(refusal("\n[[plot]]\ntitle = \"H\"\ny = \"bal.position.y\"\n").find("did you mean 'ball'"),
              std::string::npos);
    EXPECT_NE(refusal("\n[[plot]]\ntitle = \"H\"\ny = \"ball.height\"\n").find("plot[1].y: 'ball.height'"),
              std::string::npos);
    EXPECT_NE(refusal("\n[[plot]]\ntitle = \"H\"\ny = \"ball.position.z\"\n").find("x or y"), std::string::npos);
    EXPECT_NE(refusal("\n[[plot]]\ny = \"ball.position.y\"\n").find("plot[1].title: missing key"), std::string::npos);
    EXPECT_NE(refusal("\n[[plot]]\ntitle = \"H\"\ny = [\"ball.position.y\", \"ball.v.y\"]\n").find("one unit"),
              std::string::npos);
    EXPECT_NE(refusal("\n[[plot]]\ntitle = \"H\"\ny = \"ball.position.y\"\nfit = \"ratio\"\n").find("plot[1].fit"),
              std::string::npos);
    EXPECT_NE(refusal("\n[[plot]]\ntitle = \"H\"\nper = \"collision\"\ny = \"ball.v.y\"\n").find("plot[1].y"),
              std::string::npos);
    EXPECT_NE(refusal("\n[[plot]]\ntitle = \"H\"\nper = \"collision\"\npair = [\"ball\", \"table\"]\ny = \"t\"\n")
                  .find("plot[1].pair: no body named 'table'"),
              std::string::npos);
    EXPECT_NE(refusal("\n[[plot]]\ntitle = \"H\"\ny = \"ball.position.y\"\npair = [\"ball\", \"floor\"]\n")
                  .find("plot[1].pair"),
              std::string::npos);
    EXPECT_NE(refusal("\n[[plot]]\ntitle = \"H\"\ny = \"ball.rim.w\"\n").find("plot[1].y"), std::string::npos);
}

// The bundled bouncing ball, run as its page runs it: heights on the free-fall parabolas
// between the bounces, and the intervals between bounces shrinking by e.
TEST(LessonPlots, BouncingBallFollowsTheParabolasAndTheGeometricSeries) {
    const Lesson L = load_lesson(kLessons + "18-bouncing-ball.toml");
    const SceneRun run = run_scene(L.scene, frame_times(L.scene, 100));
    const std::vector<PlotData> plots = lesson_plots(L, L.scene, run);
    ASSERT_EQ(plots.size(), 2u);
    const double g = 9.81, H = 1.0, R = 0.1, e = 0.5;
    const double t0 = std::sqrt(2 * H / g), v0 = std::sqrt(2 * g * H);
    // Bounce k (from 0) at t_k = t0 + sum_{i<k} 2 e^(i+1) v0 / g, leaving at e^(k+1) v0.
    std::vector<double> bounce = {t0};
    for (int k = 1; k < 60; ++k) bounce.push_back(bounce.back() + 2 * std::pow(e, k) * v0 / g);
    const double rest = t0 * (1 + e) / (1 - e);
    // Height: y(t) = R + H - g t^2 / 2 before the first bounce; after bounce k,
    // R + e^(k+1) v0 s - g s^2 / 2 with s = t - t_k; R after the last.
    const PlotSeriesData& h = plots[0].series.at(0);
    // Every sample, and the first recorded bounces twice (just before and just after).
    ASSERT_GT(h.x.size(), run.frames.size());
    ASSERT_EQ(h.x.size(), plot_states(L.scene, run).size());
    EXPECT_EQ(plots[0].x_unit, "s");
    EXPECT_EQ(plots[0].y_unit, "m");
    int checked = 0;
    for (std::size_t i = 0; i < h.x.size(); ++i) {
        const double t = h.x[i];
        double y = R;
        if (t < t0) {
            y = R + H - 0.5 * g * t * t;
        } else if (t < rest) {
            std::size_t k = 0;
            while (k + 1 < bounce.size() && bounce[k + 1] <= t) ++k;
            const double s = t - bounce[k];
            y = R + std::pow(e, static_cast<double>(k + 1)) * v0 * s - 0.5 * g * s * s;
        }
        EXPECT_NEAR(h.y[i], y, 1e-9) << "t = " << t;
        ++checked;
    }
    EXPECT_GT(checked, 150);
    // The intervals: bounce k (from 1) comes 2 e^(k-1) v0 / g after bounce k - 1, each e times
    // the one before (while the intervals are longer than the engine's rest tolerance).
    const PlotData& iv = plots[1];
    ASSERT_TRUE(iv.per_collision);
    ASSERT_TRUE(iv.ratio);
    ASSERT_TRUE(iv.ratio->restitution);
    EXPECT_DOUBLE_EQ(*iv.ratio->restitution, e);
    const PlotSeriesData& s = iv.series.at(0);
    ASSERT_GE(s.y.size(), 20u);
    EXPECT_EQ(s.number.front(), 2);  // the first bounce has none before it
    EXPECT_NEAR(iv.row_times.front(), t0, 1e-9);
    for (std::size_t k = 0; k < 20; ++k) {
        EXPECT_NEAR(s.y[k], 2 * std::pow(e, static_cast<double>(s.number[k] - 1)) * v0 / g, 1e-9) << k;
        if (k > 0) {
            EXPECT_NEAR(iv.ratio->ratios[k - 1], e, 1e-6) << k;
        }
    }
    EXPECT_NEAR(iv.ratio->mean, e, 0.01);
    EXPECT_NE(iv.summary.find("e = 0.5"), std::string::npos) << iv.summary;
    EXPECT_NE(iv.summary.find("0.5 times the one before"), std::string::npos) << iv.summary;
    // In words, and the intervals on a log scale (40 of them would lie on 0 on a linear one).
    EXPECT_EQ(h.words, "ball: height of centre, y");
    EXPECT_EQ(plots[0].y_label, "ball: height of centre, y (m)");
    EXPECT_EQ(s.words, "time since the previous bounce");
    EXPECT_FALSE(plots[0].log_y);
    EXPECT_TRUE(iv.log_y);
    EXPECT_EQ(iv.y_label, "time since the previous bounce (s, log scale)");
}

// Restitution, bottom row (e = 1): after the hit the centres move as the impulse
// j = (1 + e) 2 / (1/m_a + 1/m_b + (r_b x n)^2 / I_b) leaves them; the touching point starts
// where the mark is.
TEST(LessonPlots, RestitutionCentresAfterTheHitAreTheClosedForm) {
    const Lesson L = load_lesson(kLessons + "05-restitution.toml");
    const SceneRun run = run_scene(L.scene, frame_times(L.scene, 100));
    const std::vector<PlotData> plots = lesson_plots(L, L.scene, run);
    ASSERT_EQ(plots.size(), 1u);
    const PlotData& p = plots[0];
    ASSERT_EQ(p.series.size(), 3u);
    const double Ib = 1.0 * (0.06 * 0.06 + 0.5 * 0.5) / 12, e = 1.0;
    const double j = (1 + e) * 2.0 / (1 / 0.5 + 1 / 1.0 + 0.15 * 0.15 / Ib);
    const PlotSeriesData &A = p.series[0], &B = p.series[1], &point = p.series[2];
    EXPECT_EQ(point.label, "B (e=1).touching point.v.x");
    EXPECT_EQ(A.words, "A (e=1): velocity of centre, x");
    EXPECT_EQ(point.words, "B (e=1): velocity of touching point, x");
    EXPECT_EQ(p.y_label, "velocity (m/s)");
    int after = 0;
    for (std::size_t i = 0; i < A.x.size(); ++i) {
        if (A.y[i] > 2.0 - 1e-12) {  // before the hit: A at 2 m/s, B and its point at rest
            EXPECT_NEAR(B.y[i], 0.0, 1e-12);
            EXPECT_NEAR(point.y[i], 0.0, 1e-12);
            continue;
        }
        ++after;
        EXPECT_NEAR(A.y[i], 2.0 - j / 0.5, 1e-9);
        EXPECT_NEAR(B.y[i], j / 1.0, 1e-9);
        // Just after the hit (the instant's second point: the bar still upright) the touching
        // points separate at e times the 2 m/s they met at: Newton's law on the points.
        if (after == 1) {
            EXPECT_EQ(A.x[i], A.x[i - 1]);
            EXPECT_NEAR(point.y[i] - A.y[i], e * 2.0, 1e-9);
            EXPECT_GT(point.y[i], B.y[i] + 0.5);  // the point leaves faster than the centre
        }
    }
    EXPECT_GT(after, 10);
}

// Tower: every contact solved at the ball's impact instant, each with its impulse; the ball's
// and the ground's among them.
TEST(LessonPlots, TowerImpulsePerContactIsOneInstant) {
    const Lesson L = load_lesson(kLessons + "21-tower.toml");
    const SceneRun run = run_scene(L.scene, frame_times(L.scene, 30));
    const std::vector<PlotData> plots = lesson_plots(L, L.scene, run);
    ASSERT_EQ(plots.size(), 1u);
    const PlotData& p = plots[0];
    ASSERT_GE(p.row_times.size(), 6u);  // ball-box 4, box 4-box 3, ..., box 1-ground, box 4-box 5, ...
    for (double t : p.row_times) EXPECT_EQ(t, p.row_times.front());
    // The ball reaches the tower's left faces at x = -0.18 m: t = (0.8 - 0.18) / 4 s.
    EXPECT_NEAR(p.row_times.front(), 0.62 / 4, 1e-9);
    const auto has = [&](const std::string& words) {
        return std::find(p.row_names.begin(), p.row_names.end(), words) != p.row_names.end();
    };
    EXPECT_TRUE(has("box 4 and ball") || has("ball and box 4"));
    EXPECT_TRUE(has("ground and box 1") || has("box 1 and ground"));
    for (double y : p.series.at(0).y) EXPECT_GT(y, 0.0);
}

// Dominoes: the strike times along the row, the line fitted from domino 9 on, and the wave
// speed d / slope with d = 0.03 m; the speed beats the lesson's bound (a struck domino alone
// would need 0.059 s: v >= 0.51 m/s) and stays below the speed a domino's top reaches.
TEST(LessonPlots, DominoesWaveSpeedIsTheSpacingOverTheFittedSlope) {
    const Lesson L = load_lesson(kLessons + "22-dominoes.toml");
    const SceneRun run = run_scene(L.scene, frame_times(L.scene, 100));
    const std::vector<PlotData> plots = lesson_plots(L, L.scene, run);
    ASSERT_GE(plots.size(), 1u);
    const PlotData& p = plots[0];
    EXPECT_TRUE(p.missing.empty());
    const PlotSeriesData& s = p.series.at(0);
    ASSERT_EQ(s.y.size(), 14u);  // domino k strikes domino k + 1, k = 1 .. 14
    for (std::size_t k = 1; k < s.y.size(); ++k) EXPECT_GT(s.y[k], s.y[k - 1]);
    ASSERT_TRUE(p.line);
    EXPECT_EQ(p.line->points, 6);
    EXPECT_EQ(p.line->slope_unit, "s per domino");
    // The least-squares slope over k = 9 .. 14, by hand.
    double mx = 0, my = 0;
    for (std::size_t k = 8; k < 14; ++k) {
        mx += s.x[k] / 6;
        my += s.y[k] / 6;
    }
    double sxy = 0, sxx = 0;
    for (std::size_t k = 8; k < 14; ++k) {
        sxy += (s.x[k] - mx) * (s.y[k] - my);
        sxx += (s.x[k] - mx) * (s.x[k] - mx);
    }
    EXPECT_NEAR(p.line->slope, sxy / sxx, 1e-12);
    EXPECT_NEAR(p.line->spacing, 0.03, 1e-12);
    ASSERT_TRUE(p.line->speed);
    EXPECT_NEAR(*p.line->speed, 0.03 / p.line->slope, 1e-12);
    EXPECT_GT(*p.line->speed, 0.51);
    EXPECT_NE(p.summary.find("s per domino"), std::string::npos) << p.summary;
    EXPECT_NE(p.summary.find("wave speed"), std::string::npos) << p.summary;
}

// The quantities the Try-it panel's plot offers (plot_quantities) are those the reader takes:
// each, written as a [[plot]]'s y in every bundled lesson, reads back as the same quantity.
TEST(LessonPlots, EveryQuantityOnOfferIsOneTheReaderTakes) {
    int lessons = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kLessons)) {
        if (entry.path().extension() != ".toml") continue;
        const Lesson L = load_lesson(entry.path().string());
        const std::vector<PlotQuantity> offered = plot_quantities(L);
        ASSERT_GT(offered.size(), 3u) << L.id;
        std::string plots;
        for (const PlotQuantity& q : offered) {
            std::string quoted;  // a TOML basic string: the names hold spaces, dots and "=" at most
            for (char c : q.name) quoted += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
            plots += "\n[[plot]]\ntitle = \"Q\"\ny = \"" + quoted + "\"\n";
        }
        const Lesson with = parse_lesson_text(L.source + "\n" + plots, L.source_name, L.file);
        ASSERT_EQ(with.plots.size(), L.plots.size() + offered.size()) << L.id;
        for (std::size_t k = 0; k < offered.size(); ++k) {
            const PlotQuantity& read = with.plots[L.plots.size() + k].y.at(0);
            EXPECT_EQ(read.name, offered[k].name) << L.id;
            EXPECT_EQ(read.kind, offered[k].kind) << L.id << " " << offered[k].name;
            EXPECT_EQ(read.body, offered[k].body) << L.id << " " << offered[k].name;
            EXPECT_EQ(read.mark, offered[k].mark) << L.id << " " << offered[k].name;
            EXPECT_EQ(read.component, offered[k].component) << L.id << " " << offered[k].name;
            EXPECT_EQ(read.unit, offered[k].unit) << L.id << " " << offered[k].name;
        }
        ++lessons;
    }
    EXPECT_EQ(lessons, 22);
}

// A disc gliding and spinning (no gravity, no collision): its kinetic energy, momentum and
// angular momentum about the origin are the closed forms 1/2 m v.v + 1/2 I w^2, m v and
// I w + m (x vy - y vx), and a body's share of each total is its own (the other at rest).
TEST(LessonPlots, ABodysEnergyMomentumAndAngularMomentumAreTheClosedForms) {
    const Lesson L = parse_lesson_text(R"([lesson]
id = "totals-test"
title = "Totals"

[scene]
dimension = 2
duration = 1.0
output_dt = 0.01

[[body]]
name = "disc"
shape = "disc"
radius = 0.2
mass = 3.0
position = [0.5, 0.4]
v = [1.5, -0.5]
w = 2.0

[[body]]
name = "block"
shape = "rectangle"
size = [0.2, 0.2]
mass = 1.0
position = [5.0, 5.0]

[[plot]]
title = "E"
y = ["disc.kinetic_energy", "kinetic_energy", "block.kinetic_energy"]

[[plot]]
title = "p"
y = ["disc.momentum.x", "momentum.y", "block.momentum.x"]

[[plot]]
title = "L"
y = ["disc.angular_momentum", "angular_momentum"]
)",
                                       "totals.toml", "totals.toml");
    const SceneRun run = run_scene(L.scene, frame_times(L.scene, 50));
    const std::vector<PlotData> plots = lesson_plots(L, L.scene, run);
    ASSERT_EQ(plots.size(), 3u);
    const double m = 3, r = 0.2, I = 0.5 * m * r * r, w = 2, vx = 1.5, vy = -0.5;
    const double E = 0.5 * m * (vx * vx + vy * vy) + 0.5 * I * w * w;
    ASSERT_GT(plots[0].series.at(0).x.size(), 40u);
    for (std::size_t i = 0; i < plots[0].series[0].x.size(); ++i) {
        const double t = plots[0].series[0].x[i], x = 0.5 + vx * t, y = 0.4 + vy * t;
        EXPECT_NEAR(plots[0].series[0].y[i], E, 1e-12);
        EXPECT_NEAR(plots[0].series[1].y[i], E, 1e-12);  // the block at rest adds nothing
        EXPECT_EQ(plots[0].series[2].y[i], 0.0);
        EXPECT_NEAR(plots[1].series[0].y[i], m * vx, 1e-12);
        EXPECT_NEAR(plots[1].series[1].y[i], m * vy, 1e-12);
        EXPECT_EQ(plots[1].series[2].y[i], 0.0);
        EXPECT_NEAR(plots[2].series[0].y[i], I * w + m * (x * vy - y * vx), 1e-9) << "t = " << t;
        EXPECT_NEAR(plots[2].series[1].y[i], plots[2].series[0].y[i], 1e-12);
    }
    EXPECT_EQ(plots[2].y_unit, "kg m^2/s");
    EXPECT_NE(plots[2].series[0].words.find("disc: angular momentum about the origin"), std::string::npos);
}

// Over general-2d's collision every body's share adds up to the totals, and the totals of
// momentum and angular momentum about the origin are the same before and after (no outside
// impulse: conservation, to round-off).
TEST(LessonPlots, GeneralTwoDimensionalSharesAddUpAndAreConserved) {
    Lesson L = load_lesson(kLessons + "06-general-2d.toml");
    L = parse_lesson_text(L.source + R"(

[[plot]]
title = "L"
y = ["A.angular_momentum", "B.angular_momentum", "angular_momentum"]

[[plot]]
title = "p"
y = ["A.momentum.x", "B.momentum.x", "momentum.x"]
)",
                          L.source_name, L.file);
    ASSERT_EQ(L.scene.gravity.norm(), 0.0);
    const SceneRun run = run_scene(L.scene, frame_times(L.scene, 100));
    const std::vector<PlotData> plots = lesson_plots(L, L.scene, run);
    const PlotData& Lp = plots.at(plots.size() - 2);
    const PlotData& pp = plots.back();
    const double L0 = Lp.series[2].y.front(), p0 = pp.series[2].y.front();
    for (std::size_t i = 0; i < Lp.series[2].y.size(); ++i) {
        EXPECT_NEAR(Lp.series[0].y[i] + Lp.series[1].y[i], Lp.series[2].y[i], 1e-12);
        EXPECT_NEAR(pp.series[0].y[i] + pp.series[1].y[i], pp.series[2].y[i], 1e-12);
        EXPECT_NEAR(Lp.series[2].y[i], L0, 1e-9 * std::max(1.0, std::abs(L0)));
        EXPECT_NEAR(pp.series[2].y[i], p0, 1e-9 * std::max(1.0, std::abs(p0)));
    }
    // The collision moved angular momentum from one body to the other (A's about the origin is 0
    // before: it slides along the x axis).
    EXPECT_GT(std::abs(Lp.series[0].y.back() - Lp.series[0].y.front()), 1e-2);
    EXPECT_NEAR(Lp.series[0].y.back() + Lp.series[1].y.back(), L0, 1e-9);
}

TEST(LessonPlots, TheReaderRefusesAngularMomentumOnALine) {
    const Lesson cu = load_lesson(kLessons + "01-catch-up.toml");
    try {
        parse_lesson_text(cu.source + "\n\n[[plot]]\ntitle = \"L\"\ny = \"A.angular_momentum\"\n", "c.toml", "c.toml");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("bodies on a line have no angular momentum"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace collide
