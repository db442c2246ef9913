// The broad phase (engine/broad_phase.h) on its own: the pairs it reports against a brute-force
// check of every pair of boxes (none missed, none twice, never a body with itself), planes as
// everyone's neighbours, and the swept box of a body moving under constant acceleration
// against its trajectory sampled densely.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/broad_phase.h"
#include "tests/engine/random_bodies.h"

namespace collide {
namespace {

template <int D>
struct Boxes {
    using Vec = typename Space<D>::Vec;
    std::vector<std::array<Vec, 2>> box;  // lo, hi
    std::vector<bool> plane;
};

// n random boxes in a cube of side `span`, edges from `small` to `large` (a few much larger).
template <int D>
Boxes<D> random_boxes(collide_test::Random& rng, std::size_t n, double span, double small, double large) {
    using Vec = typename Space<D>::Vec;
    Boxes<D> out;
    for (std::size_t i = 0; i < n; ++i) {
        Vec lo, size;
        for (int d = 0; d < D; ++d) {
            lo[d] = rng.uniform(-0.5 * span, 0.5 * span);
            size[d] = rng.uniform(small, i % 17 == 0 ? 8.0 * large : large);
        }
        out.box.push_back({lo, Vec(lo + size)});
        out.plane.push_back(false);
    }
    return out;
}

template <int D>
bool overlap(const std::array<typename Space<D>::Vec, 2>& a, const std::array<typename Space<D>::Vec, 2>& b) {
    for (int d = 0; d < D; ++d)
        if (a[1][d] < b[0][d] || b[1][d] < a[0][d]) return false;
    return true;
}

// Every body's reported neighbours, checked as they come: never itself, never twice.
template <int D>
std::vector<std::set<std::size_t>> neighbours(BroadPhase<D>* grid, const Boxes<D>& boxes) {
    std::vector<std::set<std::size_t>> out(boxes.box.size());
    for (std::size_t i = 0; i < boxes.box.size(); ++i) {
        grid->for_each_neighbour(
            i,
            [&](auto* lo, auto* hi) {
                *lo = boxes.box[i][0];
                *hi = boxes.box[i][1];
            },
            [&](std::size_t j) {
                EXPECT_NE(j, i) << "a body is not its own neighbour";
                EXPECT_TRUE(out[i].insert(j).second) << "body " << j << " reported twice for body " << i;
            });
    }
    return out;
}

template <int D>
BroadPhase<D> built(const Boxes<D>& boxes) {
    BroadPhase<D> grid(boxes.plane);
    std::vector<std::array<typename Space<D>::Vec, 2>> moving;
    for (std::size_t i = 0; i < boxes.box.size(); ++i)
        if (!boxes.plane[i]) moving.push_back(boxes.box[i]);
    grid.build(moving);
    for (std::size_t i = 0; i < boxes.box.size(); ++i)
        if (!boxes.plane[i]) grid.insert(i, boxes.box[i][0], boxes.box[i][1]);
    return grid;
}

// Every overlapping pair is reported from both of its bodies.
template <int D>
void expect_no_pair_missed(const Boxes<D>& boxes, const std::vector<std::set<std::size_t>>& found) {
    std::size_t pairs = 0;
    for (std::size_t i = 0; i < boxes.box.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.box.size(); ++j) {
            if (boxes.plane[i] || boxes.plane[j] || !overlap<D>(boxes.box[i], boxes.box[j])) continue;
            ++pairs;
            EXPECT_TRUE(found[i].count(j)) << "missed " << i << "-" << j;
            EXPECT_TRUE(found[j].count(i)) << "missed " << j << "-" << i;
        }
    EXPECT_GT(pairs, 0u) << "the scene should have overlapping boxes to check";
}

template <class T>
class BroadPhaseTest : public ::testing::Test {};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
// Named 2d and 3d (an explicit name generator: clang -Wpedantic refuses the macro's empty
// variadic argument).
struct DimensionName {
    template <class T>
    static std::string GetName(int) {
        return std::to_string(T::value) + "d";
    }
};
TYPED_TEST_SUITE(BroadPhaseTest, Dimensions, DimensionName);

TYPED_TEST(BroadPhaseTest, FindsEveryOverlappingPairOfRandomBoxes) {
    constexpr int D = TypeParam::value;
    collide_test::Random rng(20240611 + D);
    for (int trial = 0; trial < 5; ++trial) {
        const Boxes<D> boxes = random_boxes<D>(rng, 300, 40.0, 0.05, 2.0 + trial);
        BroadPhase<D> grid = built(boxes);
        expect_no_pair_missed(boxes, neighbours(&grid, boxes));
    }
}

// Boxes far apart are not all reported: the grid is a broad phase, not every pair.
TYPED_TEST(BroadPhaseTest, ReportsFewerPairsThanAllPairsForSparseBoxes) {
    constexpr int D = TypeParam::value;
    collide_test::Random rng(7);
    const Boxes<D> boxes = random_boxes<D>(rng, 400, 200.0, 0.1, 1.0);
    BroadPhase<D> grid = built(boxes);
    std::size_t reported = 0;
    for (const auto& s : neighbours(&grid, boxes)) reported += s.size();
    EXPECT_LT(reported, boxes.box.size() * (boxes.box.size() - 1) / 10);
}

// A body inserted again after an event (a new box, elsewhere) meets what its new box overlaps,
// also outside the region the grid was built for (its cells clamp to the grid's edge).
TYPED_TEST(BroadPhaseTest, ReinsertedBodyMeetsWhatItsNewBoxOverlaps) {
    constexpr int D = TypeParam::value;
    using Vec = typename Space<D>::Vec;
    collide_test::Random rng(99);
    Boxes<D> boxes = random_boxes<D>(rng, 120, 20.0, 0.1, 1.5);
    BroadPhase<D> grid = built(boxes);
    for (std::size_t i = 0; i < boxes.box.size(); i += 3) {
        Vec shift;
        for (int d = 0; d < D; ++d) shift[d] = rng.uniform(-30.0, 30.0);
        boxes.box[i][0] += shift;
        boxes.box[i][1] += shift;
        grid.insert(i, boxes.box[i][0], boxes.box[i][1]);
    }
    expect_no_pair_missed(boxes, neighbours(&grid, boxes));
}

// Planes are in no cell: every body's neighbours, and a plane's neighbours are the other planes.
TYPED_TEST(BroadPhaseTest, PlanesAreEveryBodysNeighbours) {
    constexpr int D = TypeParam::value;
    collide_test::Random rng(3);
    Boxes<D> boxes = random_boxes<D>(rng, 50, 30.0, 0.1, 1.0);
    const std::vector<std::size_t> planes = {0, 17, 49};
    for (std::size_t p : planes) boxes.plane[p] = true;
    BroadPhase<D> grid = built(boxes);
    const auto found = neighbours(&grid, boxes);
    for (std::size_t i = 0; i < boxes.box.size(); ++i)
        for (std::size_t p : planes)
            if (p != i) {
                EXPECT_TRUE(found[i].count(p)) << "plane " << p << " missing for body " << i;
            }
    for (std::size_t p : planes)
        for (std::size_t j : found[p]) EXPECT_TRUE(boxes.plane[j]) << "plane " << p << " reported body " << j;
}

// x(s) = x + v s + acc s^2 / 2 for s in [s0, s1], widened by the margin: every sampled position
// lies inside, and the box is tight (each face is reached by the ends or the turning point).
TYPED_TEST(BroadPhaseTest, SweptBoxHoldsTheTrajectoryTightly) {
    constexpr int D = TypeParam::value;
    using Vec = typename Space<D>::Vec;
    collide_test::Random rng(11);
    for (int trial = 0; trial < 200; ++trial) {
        Vec x, v, acc;
        for (int d = 0; d < D; ++d) {
            x[d] = rng.uniform(-5.0, 5.0);
            v[d] = rng.uniform(-3.0, 3.0);
            acc[d] = trial % 4 == 0 ? 0.0 : rng.uniform(-10.0, 10.0);
        }
        const double s0 = rng.uniform(0.0, 0.5), s1 = s0 + rng.uniform(0.01, 1.0);
        const double margin = rng.uniform(0.0, 0.3);
        Vec lo, hi;
        BroadPhase<D>::swept_box(x, v, acc, s0, s1, margin, &lo, &hi);
        Vec seen_lo = Vec::Constant(1e300), seen_hi = Vec::Constant(-1e300);
        constexpr int kSamples = 20000;
        for (int k = 0; k <= kSamples; ++k) {
            const double s = s0 + (s1 - s0) * k / kSamples;
            const Vec p = x + v * s + 0.5 * s * s * acc;
            seen_lo = seen_lo.cwiseMin(p);
            seen_hi = seen_hi.cwiseMax(p);
        }
        for (int d = 0; d < D; ++d) {
            EXPECT_LE(lo[d] + margin, seen_lo[d] + 1e-12);
            EXPECT_GE(hi[d] - margin, seen_hi[d] - 1e-12);
            // Tight: the samples come within the spacing's reach of the exact extremes.
            const double reach = (std::abs(v[d]) + std::abs(acc[d]) * s1) * (s1 - s0) / kSamples;
            EXPECT_NEAR(lo[d] + margin, seen_lo[d], reach + 1e-12);
            EXPECT_NEAR(hi[d] - margin, seen_hi[d], reach + 1e-12);
        }
    }
}

}  // namespace
}  // namespace collide
