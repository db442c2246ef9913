// Which bodies get a row of the data table (render::table_rows) and which get their velocity
// and spin labelled (render::motion_label_floor): the rules docs/commands/render.md states,
// on hand-made frames whose answer is written out.
#include <gtest/gtest.h>

#include "render/frame_state.h"

namespace collide::render {
namespace {

// A frame of n bodies; body k moves at speed[k] along x and turns at spin[k] about z.
FrameState frame_of(const std::vector<double>& speed, const std::vector<double>& spin = {}) {
    FrameState f;
    for (std::size_t k = 0; k < speed.size(); ++k) {
        BodyState s;
        s.v = Vec3(speed[k], 0, 0);
        s.w = Vec3(0, 0, k < spin.size() ? spin[k] : 0.0);
        f.bodies.push_back(s);
    }
    return f;
}

ImpactMark impact(std::size_t a, std::size_t b, double impulse) {
    ImpactMark m;
    m.a = a;
    m.b = b;
    m.impulse = Vec3(0, impulse, 0);
    return m;
}

std::vector<std::size_t> range(std::size_t from, std::size_t to) {
    std::vector<std::size_t> out;
    for (std::size_t i = from; i < to; ++i) out.push_back(i);
    return out;
}

TEST(TableRows, AFewBodiesAllGetARow) {
    const FrameState f = frame_of({0, 1, 2, 3});
    const TableRows r = table_rows({1, 2, 3}, {0, 0.5, 2, 4.5}, f);  // body 0 static
    EXPECT_EQ(r.shown, (std::vector<std::size_t>{1, 2, 3}));
    EXPECT_EQ(r.others, 0u);
}

TEST(TableRows, EightBodiesStillAllGetARow) {
    std::vector<double> speed(8, 1.0);
    const TableRows r = table_rows(range(0, 8), std::vector<double>(8, 0.5), frame_of(speed));
    EXPECT_EQ(r.shown, range(0, 8));
    EXPECT_EQ(r.others, 0u);
}

TEST(TableRows, BeyondEightTheMostEnergeticSevenAndALineForTheOthers) {
    // Twelve moving bodies (0 is static): energies rise with the index except body 3, the
    // most energetic; the rows go to 3 and 6 ... 11, listed in scene order.
    std::vector<double> speed(13), spin(13), kinetic(13);
    for (std::size_t i = 1; i < 13; ++i) speed[i] = 0.1 * i, spin[i] = 0.01 * i, kinetic[i] = 0.5 * speed[i] * speed[i];
    kinetic[3] = 100.0;
    const TableRows r = table_rows(range(1, 13), kinetic, frame_of(speed, spin));
    EXPECT_EQ(r.shown, (std::vector<std::size_t>{3, 7, 8, 9, 10, 11, 12}));
    ASSERT_EQ(r.others, 5u);                // bodies 1, 2, 4, 5, 6
    EXPECT_DOUBLE_EQ(r.others_speed, 0.6);  // body 6, the fastest without a row
    EXPECT_DOUBLE_EQ(r.others_spin, 0.06);
}

TEST(TableRows, TheBodiesOfTheLargestCollisionComeFirstThenTheMostEnergy) {
    // Ten bodies at rest but for 8 and 9; collisions of 1 with 2 (small) and of 4 with 5
    // (large); four rows: 4 and 5 (the largest collision), then 9 and 8 by energy, not 1 and 2;
    // the others' line.
    std::vector<double> speed(10, 0.0), kinetic(10, 0.0);
    speed[8] = 2.0, speed[9] = 3.0, kinetic[8] = 2.0, kinetic[9] = 4.5;
    FrameState f = frame_of(speed);
    f.impacts = {impact(1, 2, 0.1), impact(4, 5, 1.0)};
    const TableRows r = table_rows(range(0, 10), kinetic, f, 5);
    EXPECT_EQ(r.shown, (std::vector<std::size_t>{4, 5, 8, 9}));
    EXPECT_EQ(r.others, 6u);
    EXPECT_DOUBLE_EQ(r.others_speed, 0.0);
    // With three rows: the collision's two, then the most energetic.
    EXPECT_EQ(table_rows(range(0, 10), kinetic, f, 4).shown, (std::vector<std::size_t>{4, 5, 9}));
    // With two: the larger collision only; the line's bound is true of the fast ones left out.
    const TableRows two = table_rows(range(0, 10), kinetic, f, 3);
    EXPECT_EQ(two.shown, (std::vector<std::size_t>{4, 5}));
    EXPECT_DOUBLE_EQ(two.others_speed, 3.0);
}

TEST(TableRows, AStaticPartnerOfACollisionGetsNoRow) {
    // The ground (0) strikes body 1; nine moving bodies, five rows: 1, then by energy.
    std::vector<double> speed(10, 0.0), kinetic(10, 0.0);
    for (std::size_t i = 1; i < 10; ++i) kinetic[i] = static_cast<double>(i);
    FrameState f = frame_of(speed);
    f.impacts = {impact(0, 1, 5.0)};
    const TableRows r = table_rows(range(1, 10), kinetic, f, 5);
    EXPECT_EQ(r.shown, (std::vector<std::size_t>{1, 7, 8, 9}));
    EXPECT_EQ(r.others, 5u);
}

TEST(TableRows, OthersAtRestSaySo) {
    std::vector<double> speed(10, 0.0), kinetic(10, 0.0);
    speed[0] = 1.0, kinetic[0] = 0.5;
    const TableRows r = table_rows(range(0, 10), kinetic, frame_of(speed), 3);
    EXPECT_EQ(r.shown, (std::vector<std::size_t>{0, 1}));  // then scene order among equals
    EXPECT_EQ(r.others, 8u);
    EXPECT_EQ(r.others_speed, 0.0);
    EXPECT_EQ(r.others_spin, 0.0);
}

// Velocity and spin labels (render::motion_label_floor): all of up to four bodies; of up to
// eight, those at least a tenth of the largest; beyond, also only the six largest.
TEST(MotionLabels, FourBodiesAreAllLabelledMoreOnlyTheLargest) {
    EXPECT_EQ(motion_label_floor({0.0, 0.001, 5.0, 1.0}), 0.0);
    // The tower at 0.7 s: the spins of its seven moving bodies (rad/s).
    EXPECT_DOUBLE_EQ(motion_label_floor({10.0, 9.03e-4, 3.64, 7.35, 0.0037, 2.52, 0.0693}), 1.0);
    EXPECT_EQ(motion_label_floor({0.0, 0.001, 5.0, 1.0, 0, 0, 0, 0}), 0.5);
    std::vector<double> speeds = {9, 8, 7, 6, 5, 4, 3, 2, 1, 0.5};
    EXPECT_EQ(motion_label_floor(speeds), 4.0);  // the sixth largest
    speeds = {10, 9, 0.5, 0.4, 0.3, 0.2, 0.1, 0.05, 0.01};
    EXPECT_EQ(motion_label_floor(speeds), 1.0);  // a tenth of the largest
    EXPECT_TRUE(motion_labelled(4.0, 4.0));
    EXPECT_FALSE(motion_labelled(3.9, 4.0));
}

// Beyond eight moving bodies at most six labels of a kind, also when many share a value (a
// bin's boxes falling together all equal the sixth largest): a collision's bodies first, then
// the largest, in scene order among equals.
TEST(MotionLabels, ACollisionsBodiesFirstThenTheLargestAtMostSix) {
    EXPECT_EQ(motion_label_budget(3), 3u);
    EXPECT_EQ(motion_label_budget(kQuietBodies), kQuietBodies);
    EXPECT_EQ(motion_label_budget(kQuietBodies + 1), kMaxMotionLabels);
    const auto chosen = [](const std::vector<bool>& labels) {
        std::vector<std::size_t> out;
        for (std::size_t k = 0; k < labels.size(); ++k)
            if (labels[k]) out.push_back(k);
        return out;
    };
    const std::vector<double> falling(100, 2.94);
    std::vector<bool> first(100, false);
    EXPECT_EQ(chosen(motion_labels(falling, first)), (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
    first[57] = first[93] = true;  // the pair of the frame's collision
    EXPECT_EQ(chosen(motion_labels(falling, first)), (std::vector<std::size_t>{0, 1, 2, 3, 57, 93}));
    // Distinct values: the largest six; a collision's body below the floor stays unlabelled.
    std::vector<double> speeds = {0.5, 9, 1, 8, 2, 7, 3, 6, 4, 5, 0.01};
    std::vector<bool> in(11, false);
    in[10] = true;
    EXPECT_EQ(chosen(motion_labels(speeds, in)), (std::vector<std::size_t>{1, 3, 5, 7, 8, 9}));
    // Up to four bodies every one, at rest too.
    EXPECT_EQ(chosen(motion_labels({0.0, 1.0, 0.001}, {})), (std::vector<std::size_t>{0, 1, 2}));
}

}  // namespace
}  // namespace collide::render
