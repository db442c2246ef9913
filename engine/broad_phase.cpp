// The broad phase (broad_phase.h): swept boxes and the grid's cells.
#include "engine/broad_phase.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

}  // namespace

template <int D>
BroadPhase<D>::BroadPhase(const std::vector<bool>& plane) : plane_(plane) {
    for (std::size_t i = 0; i < plane.size(); ++i)
        if (plane[i]) planes_.push_back(i);
    seen_.assign(plane.size(), 0);
}

template <int D>
void BroadPhase<D>::swept_box(const Vec& x, const Vec& v, const Vec& acc, double s0, double s1, double margin, Vec* lo,
                              Vec* hi) {
    // The centre follows x + v s + a s^2 / 2: the box of both ends and of the turning point.
    Vec a0 = x + v * s0 + 0.5 * s0 * s0 * acc;
    Vec a1 = x + v * s1 + 0.5 * s1 * s1 * acc;
    *lo = a0.cwiseMin(a1);
    *hi = a0.cwiseMax(a1);
    for (int d = 0; d < D; ++d) {
        if (acc[d] == 0.0) continue;
        const double s = -v[d] / acc[d];
        if (s > s0 && s < s1) {
            const double xd = x[d] + v[d] * s + 0.5 * s * s * acc[d];
            (*lo)[d] = std::min((*lo)[d], xd);
            (*hi)[d] = std::max((*hi)[d], xd);
        }
    }
    for (int d = 0; d < D; ++d) {
        (*lo)[d] -= margin;
        (*hi)[d] += margin;
    }
}

template <int D>
typename BroadPhase<D>::CellBox BroadPhase<D>::cell_box(const Vec& lo, const Vec& hi) const {
    CellBox box;
    box.hi = {0, 0, 0};  // the unused axes of 2D: one layer
    for (int d = 0; d < D; ++d) {
        box.lo[d] = std::clamp(static_cast<int>(std::floor((lo[d] - grid_lo_[d]) / cell_)), 0, dims_[d] - 1);
        box.hi[d] = std::clamp(static_cast<int>(std::floor((hi[d] - grid_lo_[d]) / cell_)), 0, dims_[d] - 1);
    }
    return box;
}

// A body re-inserted after an event (new velocity, new swept box) is added only to the cells
// it was not in yet this substep, so cell lists do not grow with the number of events.
template <int D>
void BroadPhase<D>::insert(std::size_t i, const Vec& lo, const Vec& hi) {
    CellBox box = cell_box(lo, hi);
    CellBox& had = placed_[i];
    const CellBox skip = had;
    if (!had.empty())
        for (int d = 0; d < 3; ++d) {
            box.lo[d] = std::min(box.lo[d], had.lo[d]);
            box.hi[d] = std::max(box.hi[d], had.hi[d]);
        }
    had = box;
    std::array<Vec, 2>& b = boxes_[i];
    if (skip.empty()) {
        b = {lo, hi};
    } else {
        b[0] = b[0].cwiseMin(lo);
        b[1] = b[1].cwiseMax(hi);
    }
    for_each_cell(box, skip, [&](std::size_t c) {
        if (cells_[c].empty()) used_cells_.push_back(c);
        cells_[c].push_back(static_cast<std::uint32_t>(i));
    });
}

template <int D>
void BroadPhase<D>::build(const std::vector<std::array<Vec, 2>>& moving) {
    for (std::size_t c : used_cells_) cells_[c].clear();
    used_cells_.clear();
    // Cell size: the median swept box of the moving bodies, so a typical body meets few cells.
    Vec lo = Vec::Constant(kNever), hi = Vec::Constant(-kNever);
    std::vector<double> extents;
    for (const std::array<Vec, 2>& box : moving) {
        const Vec& a = box[0];
        const Vec& b = box[1];
        lo = lo.cwiseMin(a);
        hi = hi.cwiseMax(b);
        extents.push_back((b - a).maxCoeff());
    }
    if (moving.empty()) {
        lo = Vec::Zero();
        hi = Vec::Ones();
        extents.push_back(1.0);
    }
    std::nth_element(extents.begin(), extents.begin() + extents.size() / 2, extents.end());
    cell_ = std::max(extents[extents.size() / 2], 1e-9);
    const double budget = 4.0 * static_cast<double>(moving.size()) + 64.0;
    for (;;) {
        double count = 1.0;
        for (int d = 0; d < D; ++d) count *= std::floor((hi[d] - lo[d]) / cell_) + 1.0;
        if (count <= budget) break;
        cell_ *= 1.5;
    }
    grid_lo_ = lo;
    std::size_t total = 1;
    dims_ = {1, 1, 1};
    for (int d = 0; d < D; ++d) {
        dims_[d] = static_cast<int>(std::floor((hi[d] - lo[d]) / cell_)) + 1;
        total *= static_cast<std::size_t>(dims_[d]);
    }
    if (cells_.size() < total) cells_.resize(total);
    placed_.assign(plane_.size(), CellBox{});
    boxes_.resize(plane_.size());
}

template class BroadPhase<2>;
template class BroadPhase<3>;

}  // namespace collide
