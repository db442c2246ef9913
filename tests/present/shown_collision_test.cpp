// The frame rate's instants and the collision a page shows (present/frame_times.h,
// present/shown_collision.h): the rules `collide render`, the site and the WebAssembly
// module's Try-it panel share, checked against a cradle whose collisions follow in closed form.
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "present/frame_times.h"
#include "present/shown_collision.h"
#include "scenario/lesson.h"

namespace collide {
namespace {

Scene cradle() {
    // first (1 kg, 2 m/s) reaches second after closing the gap 0.5 - 0.2 = 0.3 m: t = 0.15 s.
    // second and third touch: resolved one contact after the other in the same instant.
    std::ifstream in(std::string(COLLIDE_SOURCE_DIR) + "/lessons/scenes/cradle-1d.toml");
    std::stringstream text;
    text << in.rdbuf();
    return parse_scenario_text(text.str(), "cradle-1d.toml", "");
}

TEST(FrameTimes, EveryFrameOneOverFpsApartEndingAtTheDuration) {
    const Scene scene = cradle();  // duration 0.5 s
    const std::vector<double> t = frame_times(scene, 20.0);
    ASSERT_EQ(t.size(), 11u);  // 0, 0.05, ..., 0.5
    for (std::size_t k = 0; k < t.size(); ++k) EXPECT_NEAR(t[k], 0.05 * static_cast<double>(k), 1e-12);
    EXPECT_DOUBLE_EQ(t.back(), scene.duration);
}

TEST(ShownCollision, WithoutFiguresThePageShowsTheRunsFirstCollision) {
    const Scene scene = cradle();
    const AnyRecording any = record_any(scene, frame_times(scene, 30.0), {});
    const auto& rec = std::get<Recording<1>>(any);
    const std::optional<CollisionInstant> c = page_collision({}, rec);
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->t, 0.15, 1e-9);  // 0.3 m closed at 2 m/s
    EXPECT_EQ(c->a, 0u);
    EXPECT_EQ(c->b, 1u);
    // Equal masses, e = 1: the velocities swap, the impulse on b is m v = 2 N s.
    EXPECT_NEAR(c->va_after.x(), 0.0, 1e-9);
    EXPECT_NEAR(c->vb_after.x(), 2.0, 1e-9);
    EXPECT_NEAR(c->impulse.x(), 2.0, 1e-9);
}

TEST(ShownCollision, AFigurePicksItsPairInItsRoles) {
    const Scene scene = cradle();
    const AnyRecording any = record_any(scene, frame_times(scene, 30.0), {});
    const auto& rec = std::get<Recording<1>>(any);
    // third as a, second as b: the pair's contact in the same instant, seen from the other side.
    const std::optional<CollisionInstant> c = page_collision({CollisionPick{2, 1, 1}}, rec);
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->t, 0.15, 1e-9);
    EXPECT_EQ(c->a, 2u);
    EXPECT_EQ(c->b, 1u);
    EXPECT_NEAR(c->normal.x(), -1.0, 1e-12);  // from third (right) into second (left)
    EXPECT_NEAR(c->impulse.x(), -2.0, 1e-9);  // on second: it stops
    EXPECT_NEAR(c->va_after.x(), 2.0, 1e-9);  // third leaves at 2 m/s
    EXPECT_NEAR(c->vb_after.x(), 0.0, 1e-9);
    // A collision the run does not have: none shown (render refuses such a figure by name).
    EXPECT_FALSE(page_collision({CollisionPick{0, 1, 5}}, rec));
}

TEST(ShownCollision, PicksAndKeepsFollowTheLessonsFigures) {
    EXPECT_TRUE(figure_picks(nullptr).empty());
    EXPECT_TRUE(figure_keeps(nullptr).empty());
    std::optional<Lesson> lesson;
    load_scenario("newtons-cradle", nullptr, &lesson);
    ASSERT_TRUE(lesson);
    const std::vector<CollisionPick> picks = figure_picks(&*lesson);
    const std::vector<RecordOptions::Keep> keeps = figure_keeps(&*lesson);
    ASSERT_EQ(picks.size(), lesson->figures.size());
    ASSERT_EQ(keeps.size(), lesson->figures.size());
    for (std::size_t k = 0; k < picks.size(); ++k) {
        EXPECT_EQ(picks[k].a, lesson->figures[k].ia);
        EXPECT_EQ(picks[k].b, lesson->figures[k].ib);
        EXPECT_EQ(picks[k].order, lesson->figures[k].collision);
        EXPECT_FALSE(picks[k].whole_instant);
    }
}

}  // namespace
}  // namespace collide
