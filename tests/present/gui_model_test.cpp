// What `collide gui` shows and changes, without a window (present/gui_model.h): the run sampled as
// `collide render` samples it, playback, edits that re-run the scene (checked against the
// closed form of the 1D collision), and the script's grammar and its located errors.
#include "present/gui_model.h"

#include <cmath>

#include <gtest/gtest.h>

#include "scenario/input_error.h"
#include "scenario/lesson.h"

namespace collide {
namespace {

Scene catch_up() { return load_scenario("catch-up"); }

// The first collision's velocities after it, for e: v_a' = v_a - J / m_a, v_b' = v_b + J / m_b,
// J = (1 + e) m_a m_b (v_a - v_b) / (m_a + m_b).
void expect_closed_form(const GuiModel& m, double e) {
    const Scene& s = m.scene();
    const double ma = s.bodies[0].body1.mass, mb = s.bodies[1].body1.mass;
    const double va = s.bodies[0].body1.v, vb = s.bodies[1].body1.v;
    const double J = (1 + e) * ma * mb * (va - vb) / (ma + mb);
    const render::FrameState& last = m.frames().back();
    EXPECT_NEAR(last.bodies[0].v.x(), va - J / ma, 1e-12);
    EXPECT_NEAR(last.bodies[1].v.x(), vb + J / mb, 1e-12);
}

TEST(GuiModel, FramesAreTheRendersSamplingAndEditsRerunTheScene) {
    GuiModel m(catch_up(), 30.0);
    const double duration = m.scene().duration;
    ASSERT_EQ(m.frames().size(), static_cast<std::size_t>(std::lround(duration * 30)) + 1);
    EXPECT_DOUBLE_EQ(m.frames()[3].t, 0.1);
    ASSERT_EQ(m.impacts().size(), 1u);
    expect_closed_form(m, m.scene().restitution);
    m.set_restitution(1.0);
    expect_closed_form(m, 1.0);
    m.set_restitution(0.0);
    expect_closed_form(m, 0.0);
    // The mass of A doubled: its inertia follows (1D: none), the closed form with the new mass.
    m.set_mass(0, 4.0);
    EXPECT_EQ(m.scene().bodies[0].body1.mass, 4.0);
    expect_closed_form(m, 0.0);
    m.reset();
    EXPECT_EQ(m.scene().restitution, m.original().restitution);
    expect_closed_form(m, m.scene().restitution);
}

// Twice as long, A (a block of length L centred at x_a) meets B (left face at x_b - L_b / 2)
// L_a / 2 sooner: at t = (x_b - L_b/2 - x_a - L_a) / (v_a - v_b) instead of ... - L_a / 2.
// Grown until it would overlap B, the edit is refused and nothing changes.
TEST(GuiModel, SizeScalesTheShapeAndAnOverlapIsRefused) {
    GuiModel m(catch_up(), 30.0);
    const SceneBody a = m.scene().bodies[0], b = m.scene().bodies[1];
    m.scale_size(0, 2.0);
    EXPECT_TRUE(m.error().empty()) << m.error();
    const double t = (b.body1.position - b.length / 2 - a.body1.position - a.length) / (a.body1.v - b.body1.v);
    ASSERT_EQ(m.impacts().size(), 1u);
    EXPECT_NEAR(m.impacts()[0].t, t, 1e-12);
    expect_closed_form(m, m.scene().restitution);  // mass kept: the same velocities after
    m.scale_size(0, 10.0);
    EXPECT_NE(m.error().find("would overlap 'B'"), std::string::npos) << m.error();
    EXPECT_EQ(m.scene().bodies[0].length, 2 * a.length);
}

// As the window edits: the re-run goes to the worker and the edit returns at once; the frames
// stay the last complete run's (with its scene) until poll() or finish() takes the new one, and
// of two quick edits only the newer's run ever shows.
TEST(GuiModel, InTheBackgroundTheFramesWaitForTheNewestRun) {
    GuiModel m(catch_up(), 30.0, Rerun::background);
    const double e0 = m.scene().restitution;
    ASSERT_NE(e0, 0.0);
    m.seek_time(0.5);
    m.set_restitution(1.0);
    m.set_restitution(0.0);
    EXPECT_EQ(m.scene().restitution, 0.0);       // the controls show the edit
    EXPECT_EQ(m.shown_scene().restitution, e0);  // the frames, the run before it
    expect_closed_form(m, e0);
    m.finish();
    EXPECT_FALSE(m.running());
    EXPECT_EQ(m.run_progress(), 1.0);
    EXPECT_EQ(m.shown_scene().restitution, 0.0);
    expect_closed_form(m, 0.0);
    EXPECT_DOUBLE_EQ(m.time(), 0.5);  // the playback time kept
    EXPECT_FALSE(m.poll());           // taken once
    // A script waits for its edits' runs whatever the mode.
    GuiToggles t;
    for (const GuiAction& a : parse_gui_script_text("set e 1\ntime 0\nnext-collision\n", "s.txt"))
        EXPECT_TRUE(run_script_action(a, "s.txt", &m, &t)) << a.verb;
    EXPECT_EQ(m.shown_scene().restitution, 1.0);
    expect_closed_form(m, 1.0);
}

// A run the world refuses, in the background: its error is reported (the window shows it in
// red), the frames stay the previous run's, and the next good edit clears it. (The page's
// listing is 3D code: a 2D world refuses it.)
TEST(GuiModel, InTheBackgroundARefusedRunReportsItsErrorAndKeepsTheFrames) {
    GuiModel m(load_scenario(std::string(COLLIDE_SOURCE_DIR) + "/lessons/scenes/billiards-2d.toml"), 30.0,
               Rerun::background);
    const Model before = m.scene().model;
    const std::size_t impacts = m.impacts().size();
    m.set_model(Model::page_listing);
    m.finish();
    EXPECT_NE(m.error().find("3D"), std::string::npos) << m.error();
    EXPECT_EQ(m.shown_scene().model, before);
    EXPECT_EQ(m.impacts().size(), impacts);
    m.set_model(before);
    m.finish();
    EXPECT_TRUE(m.error().empty()) << m.error();
}

TEST(GuiModel, PlaybackStepsSeeksAndFindsTheCollision) {
    GuiModel m(catch_up(), 30.0);
    EXPECT_EQ(m.index(), 0u);
    m.step(5);
    EXPECT_EQ(m.index(), 5u);
    m.step(-10);
    EXPECT_EQ(m.index(), 0u);  // stops at the start
    ASSERT_TRUE(m.next_collision());
    const double tc = m.impacts()[0].t;
    EXPECT_GE(m.time(), tc);
    EXPECT_LT(m.time() - tc, 1.0 / 30 + 1e-12);  // the first frame at or after it
    // That frame shows the impact (as the offscreen render does); the next one does not.
    EXPECT_EQ(m.display_frame().impacts.size(), 1u);
    m.step(1);
    EXPECT_TRUE(m.display_frame().impacts.empty());
    EXPECT_FALSE(m.next_collision());  // there is no second one
    m.seek_time(0.5);
    EXPECT_DOUBLE_EQ(m.time(), 0.5);
    m.seek_time(1e9);
    EXPECT_EQ(m.index(), m.frames().size() - 1);
    // Playing at a quarter speed: 0.4 s of wall time is 0.1 s of the run.
    m.seek_index(0);
    m.speed = 0.25;
    m.playing = true;
    m.advance(0.4);
    EXPECT_NEAR(m.time(), 0.1, 1e-12);
    m.advance(100.0);
    EXPECT_EQ(m.index(), m.frames().size() - 1);
    EXPECT_FALSE(m.playing);  // stops at the end
}

TEST(GuiModel, ScriptActionsChangeTheModelAndTheToggles) {
    GuiModel m(catch_up(), 30.0);
    GuiToggles t;
    const auto actions = parse_gui_script_text(
        "# a comment\nset e 1   # elastic\nset A v 2.5\nset A mass 3\ntoggle trails\nnext-collision\nback 2\n"
        "slow 0.25\nscreenshot shot.png\n",
        "s.txt");
    ASSERT_EQ(actions.size(), 8u);
    EXPECT_EQ(actions[0].line, 2);
    for (const GuiAction& a : actions) {
        if (a.verb == "screenshot") continue;
        EXPECT_TRUE(run_script_action(a, "s.txt", &m, &t)) << a.verb;
    }
    EXPECT_FALSE(run_script_action(actions.back(), "s.txt", &m, &t));  // the window's
    EXPECT_EQ(m.scene().restitution, 1.0);
    EXPECT_EQ(m.scene().bodies[0].body1.v, 2.5);
    EXPECT_EQ(m.scene().bodies[0].body1.mass, 3.0);
    expect_closed_form(m, 1.0);
    EXPECT_FALSE(t.decor.trails);
    EXPECT_EQ(m.speed, 0.25);
}

TEST(GuiModel, ScriptMistakesNameTheLineAndTheWord) {
    const auto refused = [](const std::string& text, const std::string& fragment, int line = 1) {
        try {
            parse_gui_script_text(text, "s.txt");
            ADD_FAILURE() << "accepted: " << text;
        } catch (const InputError& e) {
            EXPECT_EQ(e.pos().line, line) << e.what();
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
        }
    };
    refused("jump\n", "unknown action");
    refused("\nset e\n", "expected: set e", 2);
    refused("set e high\n", "expected a finite number, got 'high'");
    refused("set e nan\n", "expected a finite number");
    refused("step 1.5\n", "whole number");
    refused("slow 0\n", "(0, 10]");
    refused("toggle arrows\n", "got 'arrows'");
    refused("set model elastic\n", "frictionless, coulomb");
    refused("set A colour 2\n", "mass, size, v or w");
    refused("set A size\n", "expected: set A size FACTOR");
    refused("screenshot\n", "screenshot FILE.png");
    // Found when run: a body that does not exist, e out of range, a spin in 1D.
    GuiModel m(catch_up(), 30.0);
    GuiToggles t;
    const auto fails = [&](const std::string& text, const std::string& fragment) {
        const auto a = parse_gui_script_text(text, "s.txt");
        try {
            run_script_action(a.at(0), "s.txt", &m, &t);
            ADD_FAILURE() << "accepted: " << text;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
        }
    };
    fails("set C mass 1\n", "no body named 'C'");
    fails("set e 1.5\n", "e in [0, 1]");
    fails("set A w 1\n", "do not spin");
    fails("set A v 1 2\n", "expected one number in 1D");
}

}  // namespace
}  // namespace collide
