// The contact solver: impulses for many contact points at once, the simultaneous policy's
// impacts and the resting islands' forces (docs/stepping.md, "At an impact" and "Resting
// contact"). It knows contact points (rows) and bodies, not the world that found them.
//
// Each contact point k is a row: its normal n, lever arms ra, rb, and a goal (PointGoal): a
// normal velocity un+ to reach (exactly, or at least with P_k.n >= 0 where push_only), and
// a tangential one within the friction limit mu P_k.n. Projected Gauss-Seidel sweeps the rows,
// each time solving its own point with the others' impulses held (mn = 1 / n.K n, K the
// collision matrix, engine/response.h) and clamping to P.n >= 0 and the friction cone; for two
// points this is the LCP of Box2D's block solver. After a few sweeps the active-set polish
// solves the pushing and sticking points' equations exactly (conjugate gradients, see
// contact_solver.cpp), so a stack in balance gets forces that balance it to round-off.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "engine/space.h"

namespace collide {

// One touching pair at the current instant (a < b), with the impulses the solve gave it.
template <int D>
struct Contact {
    using Vec = typename Space<D>::Vec;
    std::size_t a = 0, b = 0;
    typename Space<D>::Manifold m;
    Vec impulse = Vec::Zero();  // summed over its points, on b
    double weight = 0.0;        // summed normal impulse
    Vec moment = Vec::Zero();   // summed normal impulse times point
    bool approximate = false;   // a point's answer was approximate (Response3::approximate)
};

// What the solve aims at for one contact point.
template <int D>
struct PointGoal {
    using Vec = typename Space<D>::Vec;
    double un = 0.0;  // normal velocity to reach (at least, if push_only)
    bool push_only = true;
    double mu = 0.0;       // 0: no friction; < 0: unlimited
    Vec ut = Vec::Zero();  // tangential velocity to reach
};

template <int D>
class ContactSolver {
public:
    using Vec = typename Space<D>::Vec;
    using Spin = typename Space<D>::Spin;
    using Body = typename Space<D>::Body;

    ContactSolver() = default;
    // round[i]: body i is a disc or sphere (its lever arms are taken along n exactly).
    explicit ContactSolver(const std::vector<bool>& round);

    // Impulses with P.n >= 0 such that each point leaves with un >= goal (equality where
    // P.n > 0), tangential impulses within mu P.n aiming at the tangential goal: goals[g] for
    // the g-th point of `contacts` (in order, manifold points in order; a goal un of -infinity
    // leaves its point out). The bodies of `state` (indexed like the contacts' a, b) get them;
    // each contact adds its points' impulses to its impulse, weight and moment.
    void solve(std::vector<Contact<D>>* contacts, const std::vector<PointGoal<D>>& goals,
               std::vector<Body>* state) const;

private:
    // The type of the inverse inertia in the world frame, as the dimension needs it.
    using InvInertia = std::conditional_t<D == 2, double, Mat3>;

    std::vector<bool> round_;
};

}  // namespace collide
