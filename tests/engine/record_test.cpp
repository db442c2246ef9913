// One run, one record (engine/record.h): the recording holds the run's samples, its events with
// the poses where the bodies touch, and every body at the first collision instants. Checked
// against closed forms (free flight to a head-on impact, a ball falling onto the ground), and
// against the same world sampled directly: recording must not change the run.
// Tolerances: 1e-12 relative for positions a few operations deep; kTouch (1e-10 m) where the
// world stops at contact (the gap it calls touching).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/record.h"
#include "tests/scenes/world_scenes.h"

namespace collide {
namespace {

using namespace scenes;

std::vector<double> every(double dt, double end) {
    std::vector<double> t;
    for (int k = 0; k * dt <= end + 1e-12; ++k) t.push_back(k * dt);
    return t;
}

// Two discs head-on: a at -1 moving +2 m/s, b at rest at +1; radii 0.1 and 0.2 touch when the
// centres are 0.3 apart: te = (2 - 0.3) / 2 = 0.85 s, xa = -1 + 2 te = 0.7, xb = 1.
TEST(Record, EventPosesAreWhereTheDiscsTouch) {
    Scene s = empty_scene(2, Policy::sequential, 1.0);
    s.duration = 2.0;
    s.bodies.push_back(disc("a", 0.1, 1.0, Vec2(-1.0, 0.0), Vec2(2.0, 0.0)));
    s.bodies.push_back(disc("b", 0.2, 1.0, Vec2(1.0, 0.0)));
    const Recording<2> r = record<2>(s, every(0.1, 2.0));
    ASSERT_EQ(r.events.size(), 1u);
    const Event2& e = r.events[0];
    const double te = 0.85;
    EXPECT_NEAR(e.t, te, 1e-10);
    EXPECT_NEAR(e.pose_a.x.x(), -1.0 + 2.0 * e.t, 1e-12);
    EXPECT_NEAR(e.pose_b.x.x(), 1.0, 1e-12);
    EXPECT_NEAR((e.pose_b.x - e.pose_a.x).norm(), 0.3, World2::kTouch);
    // The instant: every body there, after the impulse (equal masses, e = 1: they swap).
    ASSERT_EQ(r.instants.size(), 1u);
    const auto& in = r.instants[0];
    EXPECT_EQ(in.t, e.t);
    EXPECT_EQ(in.first, 0u);
    EXPECT_EQ(in.end, 1u);
    EXPECT_EQ(r.instant_of(0), &in);
    EXPECT_NEAR(in.bodies[0].position.x(), e.pose_a.x.x(), 1e-15);
    EXPECT_NEAR(in.bodies[0].v.x(), 0.0, 1e-12);
    EXPECT_NEAR(in.bodies[1].v.x(), 2.0, 1e-12);
    // Samples: before te, a flies freely; after it, b does.
    ASSERT_EQ(r.times.size(), 21u);
    for (std::size_t k = 0; k < r.times.size(); ++k) {
        const double t = r.times[k];
        const double xa = t < te ? -1.0 + 2.0 * t : 0.7, xb = t < te ? 1.0 : 1.0 + 2.0 * (t - te);
        EXPECT_NEAR(r.states[k][0].position.x(), xa, 1e-9) << "t = " << t;
        EXPECT_NEAR(r.states[k][1].position.x(), xb, 1e-9) << "t = " << t;
        EXPECT_EQ(r.events_upto[k], t < te ? 0u : 1u) << "t = " << t;
    }
}

// A ball dropped from rest onto the ground (e = 1): it lands when it has fallen h - r,
// te = sqrt(2 (h - r) / g), every 2 te after that again; each event's pose is on the ground.
TEST(Record, ABouncingBallsEventsAreOnTheGroundAndOnlyTheFirstInstantsAreKept) {
    const double g = 9.81, r0 = 0.1, h = 1.0;
    Scene s = empty_scene(3, Policy::sequential, 1.0, Vec3(0, -g, 0));
    s.duration = 3.0;
    s.bodies.push_back(half_space("ground", Vec3::UnitY(), 0.0));
    s.bodies.push_back(sphere("ball", r0, 1.0, Vec3(0, h, 0)));
    RecordOptions options;
    options.instants = 2;
    const Recording<3> r = record<3>(s, every(0.05, 3.0), options);
    const double te = std::sqrt(2.0 * (h - r0) / g);
    ASSERT_EQ(r.events.size(), 4u);  // at te, 3 te, 5 te, 7 te (7 te = 3.0 s: 2.999 s)
    for (std::size_t k = 0; k < r.events.size(); ++k) {
        EXPECT_NEAR(r.events[k].t, (2.0 * k + 1.0) * te, 1e-9) << k;
        EXPECT_NEAR(r.events[k].pose_b.x.y(), r0, 1e-9) << k;
    }
    ASSERT_EQ(r.instants.size(), 2u);
    EXPECT_EQ(r.instant_of(2), nullptr);
    EXPECT_NEAR(r.instants[1].bodies[1].v.y(), std::sqrt(2.0 * g * (h - r0)), 1e-9);
}

// Two balls bounce on the ground (e = 1), the second dropped from higher; only one instant is
// kept besides those asked for by pair: the second ball's second and third landings (at
// 3 te2 and 5 te2) are kept for a figure of "the 3rd collision of ground and high", its 4th is not.
TEST(Record, TheInstantsOfAKeptPairsCollisionsAreKeptWhereverTheyFall) {
    const double g = 9.81, r0 = 0.1, h1 = 0.5, h2 = 1.0;
    Scene s = empty_scene(3, Policy::sequential, 1.0, Vec3(0, -g, 0));
    s.duration = 3.0;
    s.bodies.push_back(half_space("ground", Vec3::UnitY(), 0.0));
    s.bodies.push_back(sphere("low", r0, 1.0, Vec3(0, h1, 0)));
    s.bodies.push_back(sphere("high", r0, 1.0, Vec3(1, h2, 0)));
    RecordOptions options;
    options.instants = 1;
    options.keep = {{0, 2, 3}};
    const Recording<3> r = record<3>(s, every(0.05, 3.0), options);
    const double te1 = std::sqrt(2.0 * (h1 - r0) / g), te2 = std::sqrt(2.0 * (h2 - r0) / g);
    ASSERT_EQ(r.instants.size(), 4u);  // low's first landing; high's first three
    EXPECT_NEAR(r.instants[0].t, te1, 1e-9);
    for (int k = 1; k <= 3; ++k) {
        const auto& in = r.instants[static_cast<std::size_t>(k)];
        EXPECT_NEAR(in.t, (2.0 * k - 1.0) * te2, 1e-9) << k;
        ASSERT_EQ(in.end - in.first, 1u);
        EXPECT_EQ(r.events[in.first].b, 2u);
        EXPECT_NEAR(in.bodies[2].v.y(), std::sqrt(2.0 * g * (h2 - r0)), 1e-8) << k;  // just after
    }
}

// Recording a run changes nothing in it: the same world advanced to the same instants gives
// the same states and events, bit for bit (a pile of boxes: resting contact, sleeping).
TEST(Record, RecordingDoesNotChangeTheRun) {
    PileSpec p;
    p.n = 6;
    p.per_column = 3;
    const Scene s = pile(2, p);
    const std::vector<double> times = every(0.05, 1.0);
    const Recording<2> r = record<2>(s, times);
    World2 w(s);
    std::vector<Event2> events;
    for (std::size_t k = 0; k < times.size(); ++k) {
        w.advance_to(times[k], &events);
        ASSERT_EQ(events.size(), r.events_upto[k]);
        for (std::size_t i = 0; i < s.bodies.size(); ++i) {
            EXPECT_EQ(w.bodies()[i].position, r.states[k][i].position);
            EXPECT_EQ(w.bodies()[i].v, r.states[k][i].v);
        }
    }
    EXPECT_GT(events.size(), 0u);
    for (std::size_t k = 0; k < events.size(); ++k) EXPECT_EQ(events[k].t, r.events[k].t);
}

// The sample hook (how collide gui shows progress and cancels a run): called once per sample,
// in order, after the world reached it; the run is the same with it; what it throws stops the
// run and comes out of record.
TEST(Record, TheSampleHookSeesEverySampleAndCanStopTheRun) {
    PileSpec p;
    p.n = 6;
    p.per_column = 3;
    const Scene s = pile(2, p);
    const std::vector<double> times = every(0.05, 1.0);
    std::vector<double> seen;
    RecordOptions o;
    o.on_sample = [&](double t) { seen.push_back(t); };
    const Recording<2> hooked = record<2>(s, times, o);
    EXPECT_EQ(seen, times);
    const Recording<2> plain = record<2>(s, times);
    ASSERT_EQ(hooked.events.size(), plain.events.size());
    for (std::size_t k = 0; k < plain.events.size(); ++k) EXPECT_EQ(hooked.events[k].t, plain.events[k].t);
    for (std::size_t i = 0; i < s.bodies.size(); ++i)
        EXPECT_EQ(hooked.states.back()[i].position, plain.states.back()[i].position);

    struct Stop {};
    seen.clear();
    o.on_sample = [&](double t) {
        seen.push_back(t);
        if (seen.size() == 3) throw Stop{};
    };
    EXPECT_THROW(record<2>(s, times, o), Stop);
    EXPECT_EQ(seen.size(), 3u);  // nothing run after the throw
}

// 1D: the event carries the blocks' centres; 1 m/s onto a block at rest 0.5 m away (faces
// 0.1 m from the centres): they touch after 0.3 s.
TEST(Record, OneDimensionalEventsCarryTheCentres) {
    Scene s = empty_scene(1, Policy::sequential, 1.0);
    s.duration = 1.0;
    for (double x : {0.0, 0.5}) {
        SceneBody b;
        b.name = x == 0.0 ? "a" : "b";
        b.shape = "block";
        b.length = 0.2;
        b.body1 = Body1{1.0, false, x, x == 0.0 ? 1.0 : 0.0};
        s.bodies.push_back(b);
    }
    const Recording<1> r = record<1>(s, every(0.1, 1.0));
    ASSERT_EQ(r.events.size(), 1u);
    EXPECT_NEAR(r.events[0].t, 0.3, 1e-12);
    EXPECT_NEAR(r.events[0].xa, 0.3, 1e-12);
    EXPECT_NEAR(r.events[0].xb, 0.5, 1e-12);
    ASSERT_EQ(r.instants.size(), 1u);
    EXPECT_NEAR(r.instants[0].bodies[1].v, 1.0, 1e-12);
}

}  // namespace
}  // namespace collide
