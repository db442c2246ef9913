// Stepped islands ("Stepped islands" in docs/stepping.md): one time step of length h of the bodies
// whose contacts persist, at the impulse level (Moreau-Jean's time-stepping, as in Siconos; the
// sweeps are those of Box2D and Bullet).
//
// The bodies' velocities at the step's start, v-, become v+ = v- + h g + M^-1 J^T lambda, and
// the step then moves them at v+ (x+ = x- + h v+: positions follow the new velocities, which
// keeps a body resting on another exactly at rest). The impulses lambda are found per contact
// point (normal n from A into B, +lambda on B, -lambda on A, docs/conventions.md) by projected
// Gauss-Seidel with a fixed number of sweeps, warm-started from the impulses the same points
// carried at the previous step (points matched by where they sit on body A), so that a stack's
// load is carried over from step to step instead of being found again.
//
// The goal of each point, with d its signed separation at the step's start (> 0 apart) and
// un- its normal relative velocity before the step (before gravity):
//   un+ >= -max(d, 0) / h           a gap may close within the step, no further (speculative
//                                    contact: nothing passes through, no penetration is added);
//   un+ >= -e un-   where un- < 0 and the gap closes within the step (max(d, 0) + h un- <= 0):
//                                    Newton's law on the approach before the step, at every
//                                    step, with no threshold. A body that rested at the step's
//                                    start has un- = 0: gravity's h g is stopped, not bounced;
//   tangential: Coulomb, |lambda_t| <= mu lambda_n (mu < 0: unlimited, mu = 0: none), aiming at
//   ut+ = 0.
// Penetration (d < -slop) is removed by pseudo-velocities that move the bodies and are then
// forgotten (split impulse: no energy is added): each step removes kBeta of it beyond kSlop.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "engine/space.h"

namespace collide {

// One pair of bodies within the speculative margin at the step's start.
template <int D>
struct StepContact {
    using Vec = typename Space<D>::Vec;
    std::size_t a = 0, b = 0;       // body indices; the manifold's normal points from a into b
    typename Space<D>::Manifold m;  // its points (separations up to the margin)
    double e = 0.0;                 // restitution of the pair
    double mu = 0.0;                // friction limit (PointGoal::mu: < 0 unlimited, 0 none)
    // Filled by the step:
    Vec impulse = Vec::Zero();  // summed over its points, on b (N s)
    double weight = 0.0;        // summed normal impulse
    Vec moment = Vec::Zero();   // summed normal impulse times point
    double approach = 0.0;      // the most negative un- over its points (m/s)
    bool fresh = true;          // carried no normal impulse at the previous step
};

template <int D>
class IslandStepper {
public:
    using Vec = typename Space<D>::Vec;
    using Spin = typename Space<D>::Spin;
    using Body = typename Space<D>::Body;

    static constexpr int kVelocitySweeps = 8;
    static constexpr int kImpactSweeps = 8;  // more, on the rows of a pair's first impact
    static constexpr int kPositionSweeps = 3;
    static constexpr double kSlop = 5e-5;   // m of penetration left alone (contacts persist)
    static constexpr double kBeta = 0.8;    // fraction of the rest removed per step
    static constexpr double kMatch = 5e-3;  // m: a point within this of last step's is the same

    IslandStepper() = default;

    // One step of length h from the bodies' present state (indexed like the contacts' a, b;
    // `members`: the dynamic bodies stepped, every other body of a contact counts as static):
    // velocities become v+ (gravity g included), positions are corrected for penetration (the
    // step's motion itself is left to the caller: x+ = x- + h v+).
    void step(std::vector<StepContact<D>>* contacts, const std::vector<std::size_t>& members, std::vector<Body>* bodies,
              const Vec& g, double h);

private:
    using InvInertia = std::conditional_t<D == 2, double, Mat3>;
    using Frame = std::conditional_t<D == 2, Vec2, Quat>;  // 2D: (cos, sin) of the angle; 3D: q^-1
    struct Slot {  // a body of the step's contacts (members first; the others keep their motion)
        Vec v = Vec::Zero(), vp = Vec::Zero();     // velocity, pseudo-velocity (m/s)
        Spin w = zero<Spin>(), wp = zero<Spin>();  // spin, pseudo-spin (rad/s)
        double inv_m = 0.0;                        // 0 for a body that is not a member
        InvInertia inv_I{};
        Vec x = Vec::Zero();  // position at the step's start
        Frame frame{};        // where a world point sits on the body
    };
    // One direction of a point's impulse (its normal or a tangent), worked out once per step so
    // that a sweep costs a few dot products: d; the moments r x d of the lever arms; what a unit
    // impulse along d does to each body's spin, I^-1 (r x d) (0 for a body that does not move);
    // and the effective mass along d, 1 / (1/ma + 1/mb + (ra x d).Ia^-1(ra x d) + the same of b).
    // Then the relative velocity along d is (vb - va).d + wb.(rb x d) - wa.(ra x d), and an
    // impulse p d on b (-p d on a) adds p/mb d to vb and p Ib^-1(rb x d) to wb.
    struct Axis {
        Vec d = Vec::Zero();
        Spin ra_d = zero<Spin>(), rb_d = zero<Spin>();      // ra x d, rb x d
        Spin turn_a = zero<Spin>(), turn_b = zero<Spin>();  // Ia^-1 (ra x d), Ib^-1 (rb x d)
        double mass = 0.0;
    };
    struct Row {  // one contact point
        std::size_t c = 0;
        int k = 0;
        int sa = 0, sb = 0;  // slots
        Axis n;
        std::array<Axis, 2> t;
        int nt = 0;
        double target = 0.0;  // normal velocity goal
        double depth = 0.0;   // signed separation at the step's start
        double mu = 0.0;
        double lam = 0.0, lam_p = 0.0;
        std::array<double, 2> lam_t{};
    };
    struct Cached {                // one pair's points at its last step
        std::uint64_t serial = 0;  // the step() that wrote it
        int count = 0;
        std::array<Vec, Space<D>::kMaxPoints> anchor;  // on body a, in its own frame
        std::array<double, Space<D>::kMaxPoints> lam{};
        std::array<Vec, Space<D>::kMaxPoints> lam_t;  // tangential impulse, world
    };
    // A pair's points are last step's only if it was written at each of its moving bodies'
    // last step (islands may step apart: a step taken again after an impact is one island's).
    std::unordered_map<std::uint64_t, Cached> cache_;
    std::uint64_t serial_ = 0;         // step() calls
    std::vector<std::uint64_t> last_;  // per body: the serial of its last step
    std::vector<int> slot_;            // body index -> slot in the step's arrays (-1: not in the step)
    std::vector<Slot> slots_;          // (kept between steps: no allocation per step)
    std::vector<Row> rows_;
    std::vector<std::size_t> impacts_;  // rows of pairs approaching that carried no impulse
};

}  // namespace collide
