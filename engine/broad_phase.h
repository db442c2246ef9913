// The broad phase: which bodies may meet within a substep. A uniform grid over the bodies'
// swept bounding boxes (the box a body's centre covers during the substep, widened by its
// reach), rebuilt each substep: a body's neighbours are the bodies in the cells its own box
// covers whose boxes overlap it, about N log N per second simulated instead of N^2 pairs.
// Planes are unbounded: they are in no cell and every body's neighbours.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "engine/space.h"

namespace collide {

template <int D>
class BroadPhase {
public:
    using Vec = typename Space<D>::Vec;

    BroadPhase() = default;
    // plane[i]: body i is a plane (in no cell, everyone's neighbour).
    explicit BroadPhase(const std::vector<bool>& plane);

    // The box a centre at x with velocity v and constant acceleration acc covers from s0 to s1
    // seconds on (x + v s + acc s^2 / 2), widened by margin (m) on every side.
    static void swept_box(const Vec& x, const Vec& v, const Vec& acc, double s0, double s1, double margin, Vec* lo,
                          Vec* hi);

    // A new, empty grid for a substep, its cells sized by the swept boxes (lo, hi) of the
    // moving bodies; then every body but the planes comes in by insert().
    void build(const std::vector<std::array<Vec, 2>>& moving);
    // Body i with its swept box (lo, hi); again after an event (new velocity, new box).
    void insert(std::size_t i, const Vec& lo, const Vec& hi);
    // Calls f(j) once for every body j that may meet body i (not i itself): those in the cells
    // of i's swept box, box(&lo, &hi) (not asked for a plane), then the planes.
    template <class Box, class F>
    void for_each_neighbour(std::size_t i, const Box& box, F&& f);

private:
    struct CellBox {  // grid index ranges, inclusive; empty when lo > hi
        std::array<int, 3> lo{0, 0, 0}, hi{-1, -1, -1};
        bool empty() const { return hi[0] < lo[0]; }
    };
    CellBox cell_box(const Vec& lo, const Vec& hi) const;
    template <class F>
    void for_each_cell(const CellBox& box, const CellBox& skip, F&& f) const;

    std::vector<bool> plane_;
    std::vector<std::size_t> planes_;  // indices of the plane bodies
    Vec grid_lo_;
    double cell_ = 1.0;
    std::array<int, 3> dims_{1, 1, 1};
    std::vector<std::vector<std::uint32_t>> cells_;
    std::vector<std::size_t> used_cells_;
    std::vector<CellBox> placed_;  // per body: the cells it is in this substep
    // Per body: the union of its swept boxes this substep (as its cells are a union): a body in
    // a shared cell whose box does not overlap the query's is not a neighbour.
    std::vector<std::array<Vec, 2>> boxes_;
    std::vector<std::uint32_t> seen_;
    std::vector<std::uint32_t> scratch_;
    std::uint32_t query_ = 0;
};

// Calls f for every cell of `box` outside `skip` (an empty skip: every cell).
template <int D>
template <class F>
void BroadPhase<D>::for_each_cell(const CellBox& box, const CellBox& skip, F&& f) const {
    for (int z = box.lo[2]; z <= box.hi[2]; ++z)
        for (int y = box.lo[1]; y <= box.hi[1]; ++y)
            for (int x = box.lo[0]; x <= box.hi[0]; ++x) {
                if (x >= skip.lo[0] && x <= skip.hi[0] && y >= skip.lo[1] && y <= skip.hi[1] && z >= skip.lo[2] &&
                    z <= skip.hi[2])
                    continue;
                f((static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0] + x);
            }
}

template <int D>
template <class Box, class F>
void BroadPhase<D>::for_each_neighbour(std::size_t i, const Box& box, F&& f) {
    if (++query_ == 0) {
        std::fill(seen_.begin(), seen_.end(), 0);
        query_ = 1;
    }
    seen_[i] = query_;
    if (!plane_[i]) {
        Vec lo, hi;
        box(&lo, &hi);
        std::vector<std::uint32_t>& found = scratch_;  // f never asks for neighbours itself
        found.clear();
        for_each_cell(cell_box(lo, hi), CellBox{}, [&](std::size_t c) {
            for (std::uint32_t j : cells_[c])
                if (seen_[j] != query_) {
                    seen_[j] = query_;
                    const std::array<Vec, 2>& b = boxes_[j];
                    if ((b[0].array() <= hi.array()).all() && (lo.array() <= b[1].array()).all()) found.push_back(j);
                }
        });
        for (std::uint32_t j : found) f(static_cast<std::size_t>(j));
    }
    for (std::size_t p : planes_)
        if (p != i) f(p);
}

}  // namespace collide
