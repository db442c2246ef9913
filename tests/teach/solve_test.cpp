// `collide solve` end to end through the library: the bundled examples against closed forms,
// the geometry rules of the file format, the JSON schema and the Markdown math.
#include <cmath>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scenario/input_error.h"
#include "teach/solve.h"

namespace collide {
namespace {

std::string example(const std::string& name) { return std::string(COLLIDE_SOURCE_DIR) + "/lessons/solve/" + name; }

constexpr double kTol = 1e-12;

// A uniform rod (m, L) falls at v0 with its lower end on frictionless static ground, at angle
// theta to the ground. With r = (-L/2 cos th, -L/2 sin th), n = +y and I = m L^2 / 12:
//   D = 1/m + (r x n)^2 / I = (1 + 3 cos^2 th) / m,  j = (1 + e) v0 / D,
//   w' = (r x P) / I = -(L/2) cos th j / I.
TEST(SolveExamples, RodOnGroundMatchesClosedForm) {
    const SolveProblem P = parse_solve_file(example("rod-on-ground.toml"));
    const Solution s = solve(P);
    const double m = 1, L = 1, e = 0.5, v0 = 2, th = kPi / 6, I = m * L * L / 12;
    const double j = (1 + e) * m * v0 / (1 + 3 * std::cos(th) * std::cos(th));
    EXPECT_NEAR(s.P.y(), j, kTol);
    EXPECT_NEAR(s.P.x(), 0.0, kTol);
    EXPECT_NEAR(s.vb.y(), -v0 + j / m, kTol);
    EXPECT_NEAR(s.wb.z(), -(L / 2) * std::cos(th) * j / I, 1e-9);
    EXPECT_NEAR(s.un_after, -e * s.un, kTol);
    // The ground is static: angular momentum about the contact point is conserved.
    EXPECT_NEAR(s.Lp_after.z(), s.Lp_before.z(), kTol);
}

// 1D: va' = (ma va + mb vb + mb e (vb - va)) / (ma + mb), vb' = (... + ma e (va - vb)) / (...).
TEST(SolveExamples, CartsMatchTextbook) {
    const Solution s = solve(parse_solve_file(example("carts-1d.toml")));
    const double ma = 2, mb = 1, va = 3, vb = 0, e = 0.5;
    EXPECT_NEAR(s.va.x(), (ma * va + mb * vb + mb * e * (vb - va)) / (ma + mb), kTol);
    EXPECT_NEAR(s.vb.x(), (ma * va + mb * vb + ma * e * (va - vb)) / (ma + mb), kTol);
    EXPECT_NEAR(s.p_after.x(), s.p_before.x(), kTol);
    // Energy lost in 1D: (1 - e^2) ma mb (va - vb)^2 / (2 (ma + mb)).
    EXPECT_NEAR(s.ke_before - s.ke_after, (1 - e * e) * ma * mb * 9 / (2 * (ma + mb)), kTol);
}

// with_outcome: another solver's outcome for the same two bodies, with the checks recomputed.
// Carts (2 kg at 3 m/s, 1 kg at rest) given the perfectly plastic outcome (both at
// p / (ma + mb) = 2 m/s, impulse mb * 2 = 2 N s) instead of e = 0.5's: momentum 6 kg m/s
// before and after, kinetic energy 9 J before and (ma + mb) 2^2 / 2 = 6 J after, u' = 0.
TEST(SolveExamples, AnotherOutcomeGetsItsOwnChecks) {
    const SolveProblem P = parse_solve_file(example("carts-1d.toml"));
    const Solution alone = solve(P);
    const Solution plastic =
        with_outcome(P, alone, Vec3(2, 0, 0), Vec3(2, 0, 0), Vec3::Zero(), Vec3(2, 0, 0), Vec3::Zero());
    EXPECT_NEAR(plastic.p_before.x(), 6.0, kTol);
    EXPECT_NEAR(plastic.p_after.x(), 6.0, kTol);
    EXPECT_NEAR(plastic.ke_before, 9.0, kTol);
    EXPECT_NEAR(plastic.ke_after, 6.0, kTol);
    EXPECT_NEAR(plastic.un_after, 0.0, kTol);
    EXPECT_NEAR(plastic.P.x(), 2.0, kTol);
    // The problem's own outcome changes nothing.
    const Solution same = with_outcome(P, alone, alone.P, alone.va, alone.wa, alone.vb, alone.wb);
    EXPECT_EQ(same.ke_after, alone.ke_after);
    EXPECT_EQ(same.p_after, alone.p_after);
    EXPECT_EQ(same.un_after, alone.un_after);
}

// The matrix method with e = 1 reverses the whole contact velocity and keeps the energy.
TEST(SolveExamples, SuperballReversesWholeContactVelocity) {
    const Solution s = solve(parse_solve_file(example("superball-2d.toml")));
    EXPECT_LE((s.u_after + s.u).norm(), kTol);
    EXPECT_NEAR(s.ke_after, s.ke_before, 1e-12 * s.ke_before);
}

TEST(SolveExamples, BoxesSlideOnTheConeEdge) {
    const Solution s = solve(parse_solve_file(example("boxes-3d.toml")));
    ASSERT_TRUE(s.sliding);
    const double Pn = s.P.dot(s.n);
    EXPECT_NEAR((s.P - Pn * s.n).norm(), 0.3 * Pn, kTol);  // |P_t| = mu P_n when sliding
    EXPECT_LE((s.p_after - s.p_before).norm(), kTol);
    EXPECT_LE((s.L_after - s.L_before).norm(), kTol);
    EXPECT_NEAR(s.un_after, -0.5 * s.un, kTol);
}

// The ball (0.5 kg, r = 0.1 m, at (0.5, 0, -0.1), v = (0, 0, 4)) sticks to the end of the rod
// (2 kg, L = 1 m, R = 0.02 m, along x at the origin, at rest). Afterwards they are one rigid
// body: its centre x_c = sum m x / M moves at p / M, and it turns at w = I_c^-1 L_c, with L_c
// and I_c about x_c (parallel axes: I + m (|d|^2 E - d d^T)). Each body's centre then moves
// at v_c + w x (x - x_c). Written out here, not taken from the engine's combined_body.
TEST(SolveExamples, StickIsOneRigidBodyAfterwards) {
    const Solution s = solve(parse_solve_file(example("stick-3d.toml")));
    const double ma = 0.5, mb = 2.0, M = ma + mb, r = 0.1, L = 1.0, R = 0.02;
    const Vec3 xa(0.5, 0, -0.1), xb(0, 0, 0), va(0, 0, 4), vb(0, 0, 0);
    const Vec3 xc = (ma * xa + mb * xb) / M, vc = (ma * va + mb * vb) / M;
    const Mat3 Ia = Mat3::Identity() * (0.4 * ma * r * r);
    const Mat3 Ib = Vec3(mb * R * R / 2, mb * (3 * R * R + L * L) / 12, mb * (3 * R * R + L * L) / 12).asDiagonal();
    const auto shifted = [](const Mat3& I, double m, const Vec3& d) {
        return Mat3(I + m * (d.squaredNorm() * Mat3::Identity() - d * d.transpose()));
    };
    const Mat3 Ic = shifted(Ia, ma, xa - xc) + shifted(Ib, mb, xb - xc);
    const Vec3 Lc = (xa - xc).cross(ma * va) + (xb - xc).cross(mb * vb);  // neither spins before
    const Vec3 w = Ic.inverse() * Lc;
    // The sizes involved are of order 1: 1e-12 is rounding.
    EXPECT_LE((s.wa - w).norm(), 1e-12);
    EXPECT_LE((s.wb - w).norm(), 1e-12);
    EXPECT_LE((s.va - (vc + w.cross(xa - xc))).norm(), 1e-12);
    EXPECT_LE((s.vb - (vc + w.cross(xb - xc))).norm(), 1e-12);
    EXPECT_LT(s.newton_euler_difference, 1e-12);
    EXPECT_LE((s.wa - s.wb).norm(), kTol);
    EXPECT_LE((s.p_after - s.p_before).norm(), kTol);
    EXPECT_LE((s.L_after - s.L_before).norm(), kTol);
    EXPECT_LT(s.ke_after, s.ke_before);
}

const char* kTwoSpheres = R"(
dimension = 3
restitution = 1.0
normal = [1.0, 0.0, 0.0]
[a]
mass = 1.0
shape = "sphere"
radius = 0.5
position = [-0.5, 0.0, 0.0]
v = [1.0, 0.0, 0.0]
[b]
mass = 1.0
shape = "sphere"
radius = 0.5
position = [0.5, 0.0, 0.0]
r = [-0.5, 0.0, 0.0]
)";

// Without 'point', the body that gives position and r fixes the contact point; the other
// body's r follows from its position.
TEST(SolveFormat, ContactPointFromPositionAndR) {
    const SolveProblem P = parse_solve_text(kTwoSpheres, "spheres.toml");
    EXPECT_LE((P.point - Vec3::Zero()).norm(), kTol);
    const Solution s = solve(P);
    EXPECT_LE((s.ra - Vec3(0.5, 0, 0)).norm(), kTol);
    // Equal spheres, head on, e = 1: velocities exchange.
    EXPECT_LE((s.va - Vec3::Zero()).norm(), kTol);
    EXPECT_LE((s.vb - Vec3(1, 0, 0)).norm(), kTol);
}

TEST(SolveFormat, NormalIsNormalisedAndQuaternionToo) {
    std::string text = kTwoSpheres;
    text.replace(text.find("normal = [1.0, 0.0, 0.0]"), 24, "normal = [4.0, 0.0, 0.0]");
    const SolveProblem P = parse_solve_text(text, "x.toml");
    EXPECT_NEAR(P.normal.norm(), 1.0, kTol);
    EXPECT_NEAR(P.normal.x(), 1.0, kTol);
    // A quaternion given at twice its length is the same rotation: boxes-3d's A is turned
    // 30 degrees about z, so its x axis is (cos 30, sin 30, 0) whatever the length given.
    std::ifstream in(example("boxes-3d.toml"));
    std::stringstream file;
    file << in.rdbuf();
    std::string boxes = file.str();
    const std::string given = "orientation = [0.9659258, 0.0, 0.0, 0.2588190]";
    ASSERT_NE(boxes.find(given), std::string::npos);
    boxes.replace(boxes.find(given), given.size(), "orientation = [1.9318516, 0.0, 0.0, 0.5176380]");
    const SolveProblem Q = parse_solve_text(boxes, "boxes.toml");
    const Quat q = Q.a.b3.orientation;
    EXPECT_NEAR(q.norm(), 1.0, 1e-12);
    const Vec3 x_axis = q * Vec3::UnitX();
    const double c30 = std::sqrt(3.0) / 2.0;
    EXPECT_NEAR(x_axis.x(), c30, 1e-6);  // the file's digits: 7 decimals
    EXPECT_NEAR(x_axis.y(), 0.5, 1e-6);
    EXPECT_NEAR(x_axis.z(), 0.0, 1e-12);
}

TEST(SolveFormat, ErrorsNameFileLineAndKey) {
    std::string text = kTwoSpheres;
    text.replace(text.find("mass = 1.0"), 10, "mass = -1.0");
    try {
        parse_solve_text(text, "bad.toml");
        FAIL() << "negative mass accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "bad.toml");
        EXPECT_EQ(e.key(), "a.mass");
        EXPECT_EQ(e.pos().line, 6);
        EXPECT_EQ(e.pos().column, 8);
    }
}

// The JSON record: the documented keys in order, vectors of the file's dimension.
TEST(SolveJson, SchemaFor3D) {
    const SolveProblem P = parse_solve_file(example("boxes-3d.toml"));
    std::ostringstream out;
    write_json(P, solve(P), out);
    const auto j = nlohmann::ordered_json::parse(out.str());
    const std::vector<std::string> keys = {
        "dimension",      "model",    "restitution",     "friction",    "normal", "point", "impulse",
        "normal_impulse", "sliding",  "separating",      "energy_gain", "a",      "b",     "relative_normal_velocity",
        "kinetic_energy", "momentum", "angular_momentum"};
    std::size_t i = 0;
    for (auto it = j.begin(); it != j.end() && i < keys.size(); ++it)
        if (it.key() == keys[i]) ++i;
    EXPECT_EQ(i, keys.size()) << "missing or out of order: " << (i < keys.size() ? keys[i] : "");
    EXPECT_EQ(j["dimension"], 3);
    EXPECT_EQ(j["model"], "coulomb");
    EXPECT_EQ(j["impulse"].size(), 3u);
    EXPECT_EQ(j["a"]["w"].size(), 3u);
    EXPECT_EQ(j["angular_momentum"]["before"].size(), 3u);
    EXPECT_TRUE(j["sliding"].get<bool>());
}

// Kane's paradox, said every time: the rough rod of issue 19 (1 kg, 1 m, 50 degrees, lower end
// on the ground, v = (-0.2, -1) m/s, w = 6 rad/s, mu = 0.5, e = 0.9) under the one-step Coulomb
// model ends with more kinetic energy than the 0.52 + 1.5 = 2.02 J it had (computed here from
// the velocities after). JSON says "energy_gain": true and the worked example names the paradox;
// without friction the rod loses energy and neither appears.
TEST(SolveJson, AGainOfEnergyIsNeverSilent) {
    for (const char* model : {"coulomb", "frictionless"}) {
        SCOPED_TRACE(model);
        const SolveProblem P = parse_solve_text(std::string("dimension = 2\nmodel = \"") + model + R"("
restitution = 0.9
friction = 0.5
normal = [0.0, -1.0]
point = [0.0, 0.0]
[a]
name = "rod"
mass = 1.0
shape = "rod"
length = 1.0
angle = 0.8726646259971648
r = [-0.3213938048432697, -0.3830222215594891]
v = [-0.2, -1.0]
w = 6.0
[b]
name = "ground"
static = true
)",
                                                "rod.toml");
        const Solution s = solve(P);
        const double after = 0.5 * s.va.head<2>().squaredNorm() + 0.5 * (1.0 / 12.0) * s.wa.z() * s.wa.z();
        const bool gains = std::string(model) == "coulomb";
        EXPECT_EQ(after > 2.02 + 1e-6, gains) << after;
        std::ostringstream json, text, markdown;
        write_json(P, s, json);
        write_text(P, s, text);
        write_markdown(P, s, markdown);
        EXPECT_EQ(nlohmann::json::parse(json.str())["energy_gain"].get<bool>(), gains);
        EXPECT_EQ(text.str().find("Kane's paradox") != std::string::npos, gains);
        EXPECT_EQ(markdown.str().find("Kane's paradox") != std::string::npos, gains);
    }
}

// model = "routh": the JSON keeps its schema and adds the law and the phases, which tile the
// normal impulse from 0 to the normal impulse applied; Kane's rod slips, then slips back once
// its slip has stopped during compression (engine/routh tests check the phases' closed forms).
TEST(SolveJson, RouthAddsItsLawAndPhases) {
    const SolveProblem P = parse_solve_file(example("kane-rod.toml"));
    std::ostringstream out;
    write_json(P, solve(P), out);
    const auto j = nlohmann::json::parse(out.str());
    EXPECT_EQ(j["model"], "routh");
    EXPECT_EQ(j["restitution_law"], "stronge");
    ASSERT_EQ(j["phases"].size(), 2u);
    EXPECT_EQ(j["phases"][0]["kind"], "slip");
    EXPECT_EQ(j["phases"][1]["kind"], "reverse");
    double at = 0.0;
    for (const auto& ph : j["phases"]) {
        EXPECT_DOUBLE_EQ(ph["normal_impulse_from"].get<double>(), at);
        at = ph["normal_impulse_to"].get<double>();
        EXPECT_GT(at, ph["normal_impulse_from"].get<double>());
    }
    EXPECT_NEAR(at, j["normal_impulse"].get<double>(), 1e-12);
    // The slip stopped during compression: before P_c.
    EXPECT_LT(j["phases"][0]["normal_impulse_to"].get<double>(), j["compression_impulse"].get<double>());
    // Stronge: the restitution work is e^2 times minus the compression work, and no energy gain.
    EXPECT_NEAR(j["work"]["restitution"].get<double>(), -0.81 * j["work"]["compression"].get<double>(), 1e-12);
    EXPECT_FALSE(j["energy_gain"].get<bool>());
    // The impulse stays in the friction cone: |P_t| <= mu P_n (here the ground's normal is -y).
    const double Pn = j["normal_impulse"].get<double>(), Pt = std::abs(j["impulse"][0].get<double>());
    EXPECT_LE(Pt, 0.5 * Pn + 1e-12);
}

// An approximate routh answer (engine Response3::approximate: the integration could not be
// finished, routh_test.cpp forces one) is said in the JSON ("approximate", only then) and in a
// line of the text; a finished one prints as before, without the key.
TEST(SolveJson, AnApproximateRouthAnswerSaysSo) {
    const SolveProblem P = parse_solve_file(example("kane-rod.toml"));
    Solution s = solve(P);
    std::ostringstream exact;
    write_json(P, s, exact);
    EXPECT_FALSE(nlohmann::json::parse(exact.str()).contains("approximate"));
    s.approximate = true;
    std::ostringstream json, text;
    write_json(P, s, json);
    write_text(P, s, text);
    const auto j = nlohmann::json::parse(json.str());
    ASSERT_TRUE(j.contains("approximate"));
    EXPECT_NE(j["approximate"].get<std::string>().find("could not be finished"), std::string::npos);
    EXPECT_NE(text.str().find("Routh's integration could not be finished"), std::string::npos) << text.str();
}

TEST(SolveJson, OneDimensionalValuesAreNumbers) {
    const SolveProblem P = parse_solve_file(example("carts-1d.toml"));
    std::ostringstream out;
    write_json(P, solve(P), out);
    const auto j = nlohmann::json::parse(out.str());
    EXPECT_TRUE(j["impulse"].is_number());
    EXPECT_TRUE(j["normal"].is_number());
    EXPECT_TRUE(j["a"]["v"].is_number());
    EXPECT_FALSE(j["a"].contains("w"));
    EXPECT_TRUE(j["momentum"]["after"].is_number());
    EXPECT_DOUBLE_EQ(j["impulse"].get<double>(), 3.0);  // (1 + e)(va - vb)/(1/ma + 1/mb)
}

// Markdown: every formula line is display math, with no Unicode left for LaTeX to choke on.
TEST(SolveMarkdown, FormulasAreLatex) {
    const SolveProblem P = parse_solve_file(example("boxes-3d.toml"));
    std::ostringstream out;
    write_markdown(P, solve(P), out);
    std::istringstream lines(out.str());
    int math = 0;
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("$$", 0) != 0) continue;
        ++math;
        for (const char* bad : {"ω", "×", "·", "⁻¹", "′", "−", "μ"})
            EXPECT_EQ(line.find(bad), std::string::npos) << line;
    }
    EXPECT_GT(math, 10);
}

TEST(SolveRun, SeparatingBodiesGetNoImpulse) {
    std::string text = kTwoSpheres;
    text.replace(text.find("v = [1.0, 0.0, 0.0]"), 19, "v = [-1.0, 0.0, 0.0]");
    const Solution s = solve(parse_solve_text(text, "x.toml"));
    EXPECT_TRUE(s.separating);
    EXPECT_EQ(s.P.norm(), 0.0);
    EXPECT_EQ(s.va, Vec3(-1, 0, 0));
}

}  // namespace
}  // namespace collide
