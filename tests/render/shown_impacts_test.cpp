// Which collisions a frame draws (render::shown_impacts): the rule docs/commands/render.md states, on
// hand-made lists whose answer is written out.
#include <gtest/gtest.h>

#include "render/frame_state.h"

namespace collide::render {
namespace {

ImpactMark mark(double t, std::size_t a, std::size_t b, double impulse, double x = 0.0) {
    ImpactMark m;
    m.t = t;
    m.a = a;
    m.b = b;
    m.point = Vec3(x, 0, 0);
    m.impulse = Vec3(0, impulse, 0);
    return m;
}

TEST(ShownImpacts, AFewOfSimilarSizeAreAllDetailedInTimeOrder) {
    const std::vector<ImpactMark> in = {mark(0.1, 0, 1, 1.0, 0.0), mark(0.2, 1, 2, 0.5, 1.0),
                                        mark(0.3, 2, 3, 2.0, 2.0)};
    const std::vector<ImpactMark> out = shown_impacts(in);
    ASSERT_EQ(out.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(out[k].t, in[k].t);
        EXPECT_TRUE(out[k].detailed);
    }
}

TEST(ShownImpacts, SmallOnesAreLeftOutAndAtMostSixAreDrawn) {
    std::vector<ImpactMark> in;
    // Ten collisions of 1 to 10 N s at different points, then a micro-collision of 0.05 N s.
    for (int k = 1; k <= 10; ++k) in.push_back(mark(0.01 * k, 0, static_cast<std::size_t>(k), k, k));
    in.push_back(mark(0.2, 0, 11, 0.05, 11));
    const std::vector<ImpactMark> out = shown_impacts(in);
    ASSERT_EQ(out.size(), kMaxShownImpacts);  // 10, 9, ..., 5 N s (all >= 10% of 10)
    // The three largest detailed, first, in time order (8, 9, 10 N s); then 5, 6, 7 N s.
    const double expected[6] = {8, 9, 10, 5, 6, 7};
    for (std::size_t k = 0; k < out.size(); ++k) {
        EXPECT_DOUBLE_EQ(out[k].impulse.y(), expected[k]) << k;
        EXPECT_EQ(out[k].detailed, k < kDetailedImpacts) << k;
    }
}

TEST(ShownImpacts, BelowATenthOfTheLargestIsNotDrawn) {
    const std::vector<ImpactMark> out =
        shown_impacts({mark(0.1, 0, 1, 1.0), mark(0.2, 0, 2, 0.099, 1.0), mark(0.3, 0, 3, 0.1, 2.0)});
    ASSERT_EQ(out.size(), 2u);
    EXPECT_DOUBLE_EQ(out[0].impulse.y(), 1.0);
    EXPECT_DOUBLE_EQ(out[1].impulse.y(), 0.1);
}

TEST(ShownImpacts, OnePairAtOnePointIsDetailedOnce) {
    // A ball's last bounces: the same pair, the same point, halving impulses.
    const std::vector<ImpactMark> out =
        shown_impacts({mark(0.1, 0, 1, 1.0), mark(0.2, 0, 1, 0.5), mark(0.3, 0, 1, 0.25)});
    ASSERT_EQ(out.size(), 3u);
    EXPECT_TRUE(out[0].detailed);
    EXPECT_DOUBLE_EQ(out[0].impulse.y(), 1.0);
    EXPECT_FALSE(out[1].detailed);
    EXPECT_FALSE(out[2].detailed);
}

}  // namespace
}  // namespace collide::render
