// render/convex_hull.h: the corners of the hull, counter-clockwise, and nothing outside it.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "engine/math.h"
#include "render/convex_hull.h"

namespace collide::render {
namespace {

TEST(ConvexHullTest, KeepsTheCornersCounterClockwiseAndDropsTheRest) {
    // A square's corners, its centre, a point inside and the middle of its bottom edge.
    const std::vector<Vec2> points = {{1, 1}, {0, 0}, {0.5, 0.5}, {1, 0}, {0.2, 0.7}, {0, 1}, {0.5, 0}};
    const std::vector<Vec2> h = convex_hull(points);
    const std::vector<Vec2> expected = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    EXPECT_EQ(h, expected);
}

TEST(ConvexHullTest, EveryPointIsInsideOrOnTheHull) {
    std::mt19937 rng(7);
    std::normal_distribution<double> g(0.0, 1.0);
    std::vector<Vec2> points;
    for (int k = 0; k < 200; ++k) points.emplace_back(g(rng), 0.3 * g(rng));
    const std::vector<Vec2> h = convex_hull(points);
    ASSERT_GE(h.size(), 3u);
    for (std::size_t i = 0; i < h.size(); ++i) {
        const Vec2& a = h[i];
        const Vec2& b = h[(i + 1) % h.size()];
        // Each edge turns left (strictly: no point on an edge is a corner) ...
        EXPECT_GT(cross(b - a, h[(i + 2) % h.size()] - b), 0.0);
        // ... and has every point on its left or on it.
        for (const Vec2& p : points) EXPECT_GE(cross(b - a, p - a), -1e-12);
    }
}

TEST(ConvexHullTest, FewerThanThreePointsComeBackSorted) {
    EXPECT_TRUE(convex_hull({}).empty());
    const std::vector<Vec2> two = convex_hull({{1, 0}, {0, 2}});
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(two[0], Vec2(0, 2));
}

}  // namespace
}  // namespace collide::render
