// One step of the stepped islands (island_step.h): rows, warm start, velocity sweeps, split
// impulse.
#include "engine/island_step.h"

#include <algorithm>
#include <cmath>

#include "engine/rotation.h"

namespace collide {

namespace {

// The body's inverse inertia in the world frame, as the dimension needs it.
double inv_inertia(const Body2& b) { return b.inv_inertia(); }
Mat3 inv_inertia(const Body3& b) { return b.is_static ? Mat3::Zero() : b.inv_inertia_world(); }

// The product of two spins (2D: numbers; 3D: vectors).
double spin_dot(double a, double b) { return a * b; }
double spin_dot(const Vec3& a, const Vec3& b) { return a.dot(b); }

// A point in the body's own frame, from the frame kept in its slot (2D: the angle's cosine and
// sine, found once per body and step; 3D: the inverse orientation).
Vec2 to_local(const Vec2& x, const Vec2& cs, const Vec2& p) {
    const Vec2 d = p - x;
    return Vec2(cs.x() * d.x() + cs.y() * d.y(), -cs.y() * d.x() + cs.x() * d.y());
}
Vec3 to_local(const Vec3& x, const Quat& q_inv, const Vec3& p) { return q_inv * (p - x); }
Vec2 frame_of(const Body2& b) {
    const SinCos sc = sin_cos(b.angle);
    return Vec2(sc.cos, sc.sin);
}
Quat frame_of(const Body3& b) { return b.orientation.conjugate(); }

// The pseudo-velocities' correction of a pose over h (2D: angle; 3D: the small rotation w h).
void correct(Body2* b, const Vec2& dx, double dtheta) {
    b->position += dx;
    b->angle += dtheta;
}
void correct(Body3* b, const Vec3& dx, const Vec3& dtheta) {
    b->position += dx;
    if (dtheta.squaredNorm() > 0.0) b->orientation = (exp_map(dtheta) * b->orientation).normalized();
}

}  // namespace

template <int D>
void IslandStepper<D>::step(std::vector<StepContact<D>>* contacts, const std::vector<std::size_t>& members,
                            std::vector<Body>* bodies, const Vec& g, double h) {
    std::vector<Body>& B = *bodies;
    if (slot_.size() != B.size()) slot_.assign(B.size(), -1);
    if (last_.size() != B.size()) last_.assign(B.size(), 0);
    ++serial_;
    // Slots: the members first, then every other body of a contact, which keeps its velocity
    // (zero inverse mass and inertia: the impulses leave it as it is).
    std::vector<Slot>& s = slots_;
    s.clear();
    auto add_slot = [&](std::size_t i, bool moves) {
        const Body& b = B[i];
        slot_[i] = static_cast<int>(s.size());
        Slot q;
        q.v = b.v;
        q.w = b.w;
        q.x = b.position;
        q.frame = frame_of(b);
        q.inv_m = moves ? b.inv_mass() : 0.0;
        if constexpr (D == 2) q.inv_I = moves ? inv_inertia(b) : 0.0;
        else q.inv_I = moves ? inv_inertia(b) : Mat3::Zero();
        s.push_back(q);
    };
    for (std::size_t i : members) add_slot(i, true);
    for (const StepContact<D>& c : *contacts)
        for (std::size_t i : {c.a, c.b})
            if (slot_[i] < 0) add_slot(i, false);
    const std::size_t moving = members.size();

    // The relative velocity of a row's bodies along one of its axes (pseudo: of their
    // pseudo-velocities), and an impulse p along it: +p on b, -p on a.
    auto speed = [&](const Row& r, const Axis& x, bool pseudo) {
        const Slot& A = s[r.sa];
        const Slot& Bs = s[r.sb];
        return pseudo ? (Bs.vp - A.vp).dot(x.d) + spin_dot(Bs.wp, x.rb_d) - spin_dot(A.wp, x.ra_d)
                      : (Bs.v - A.v).dot(x.d) + spin_dot(Bs.w, x.rb_d) - spin_dot(A.w, x.ra_d);
    };
    auto push = [&](const Row& r, const Axis& x, double p, bool pseudo) {
        Slot& A = s[r.sa];
        Slot& Bs = s[r.sb];
        (pseudo ? A.vp : A.v) -= (p * A.inv_m) * x.d;
        (pseudo ? A.wp : A.w) -= p * x.turn_a;
        (pseudo ? Bs.vp : Bs.v) += (p * Bs.inv_m) * x.d;
        (pseudo ? Bs.wp : Bs.w) += p * x.turn_b;
    };
    auto axis = [&](const Row& r, const Vec& d, const Vec& ra, const Vec& rb) {
        const Slot& A = s[r.sa];
        const Slot& Bs = s[r.sb];
        Axis x;
        x.d = d;
        x.ra_d = lever(ra, d);
        x.rb_d = lever(rb, d);
        x.turn_a = A.inv_I * x.ra_d;  // (inv_I is 0 for a body that does not move)
        x.turn_b = Bs.inv_I * x.rb_d;
        const double k = A.inv_m + Bs.inv_m + spin_dot(x.ra_d, x.turn_a) + spin_dot(x.rb_d, x.turn_b);
        x.mass = k > 0.0 ? 1.0 / k : 0.0;
        return x;
    };

    // Rows, their goals from the velocities before the step, and last step's impulses.
    std::vector<Row>& rows = rows_;
    rows.clear();
    impacts_.clear();
    // An approach faster than two steps of gravity add: an impact, not a contact closing again
    // in a heap (those converge from their neighbours' warm start).
    const double impact_speed = 2.0 * g.norm() * h;
    for (std::size_t ci = 0; ci < contacts->size(); ++ci) {
        StepContact<D>& c = (*contacts)[ci];
        c.impulse = zero<Vec>();
        c.weight = 0.0;
        c.moment = zero<Vec>();
        c.approach = 0.0;
        const std::uint64_t key = static_cast<std::uint64_t>(c.a) << 32 | c.b;
        const auto found = cache_.find(key);
        const int sa = slot_[c.a], sb = slot_[c.b];
        const bool a_moves = static_cast<std::size_t>(sa) < moving, b_moves = static_cast<std::size_t>(sb) < moving;
        const Cached* before = found == cache_.end() ? nullptr : &found->second;
        if (before && ((a_moves && before->serial != last_[c.a]) || (b_moves && before->serial != last_[c.b])))
            before = nullptr;  // not in contact at their last step
        c.fresh = true;
        if (before)
            for (int q = 0; q < before->count; ++q) c.fresh = c.fresh && !(before->lam[q] > 0.0);
        const Slot& A = s[sa];
        const Slot& Bs = s[sb];
        for (int k = 0; k < c.m.count; ++k) {
            Row r;
            r.c = ci;
            r.k = k;
            r.sa = sa;
            r.sb = sb;
            const Vec ra = c.m.points[k] - A.x, rb = c.m.points[k] - Bs.x;
            r.n = axis(r, c.m.normal, ra, rb);
            r.depth = c.m.depths[k];
            r.mu = c.mu;
            if (r.mu != 0.0) {
                std::array<Vec, 2> t;
                r.nt = tangents(c.m.normal, &t);
                for (int q = 0; q < r.nt; ++q) r.t[q] = axis(r, t[q], ra, rb);
            }
            const double un = speed(r, r.n, false);
            c.approach = std::min(c.approach, un);
            const double gap = std::max(r.depth, 0.0);
            r.target = -gap / h;
            if (un < 0.0 && gap + h * un <= 0.0) {
                r.target = std::max(r.target, -c.e * un);
                if (c.fresh && -un > impact_speed) impacts_.push_back(rows.size());
            }
            if (before) {  // the nearest of last step's points, if near enough
                const Vec here = to_local(A.x, A.frame, c.m.points[k]);
                int best = -1;
                double best_d = kMatch;
                for (int q = 0; q < before->count; ++q) {
                    const double d = (before->anchor[q] - here).norm();
                    if (d < best_d) {
                        best_d = d;
                        best = q;
                    }
                }
                if (best >= 0) {
                    r.lam = before->lam[best];
                    for (int q = 0; q < r.nt; ++q) r.lam_t[q] = before->lam_t[best].dot(r.t[q].d);
                }
            }
            rows.push_back(r);
        }
    }

    // Gravity over the step, then last step's impulses (warm start).
    for (std::size_t q = 0; q < moving; ++q)
        if (s[q].inv_m > 0.0) s[q].v += h * g;
    for (const Row& r : rows) {
        push(r, r.n, r.lam, false);
        for (int q = 0; q < r.nt; ++q) push(r, r.t[q], r.lam_t[q], false);
    }

    // Velocity sweeps: friction (within the cone of the present normal impulse), then normal.
    auto solve = [&](Row& r) {
        if (r.nt > 0) {
            std::array<double, 2> want{};
            for (int q = 0; q < r.nt; ++q) want[q] = r.lam_t[q] - r.t[q].mass * speed(r, r.t[q], false);
            if (r.mu >= 0.0) {
                const double limit = r.mu * r.lam;
                const double size = std::sqrt(want[0] * want[0] + want[1] * want[1]);
                if (size > limit) {
                    const double scale = size > 0.0 ? limit / size : 0.0;
                    want[0] *= scale;
                    want[1] *= scale;
                }
            }
            for (int q = 0; q < r.nt; ++q) {
                push(r, r.t[q], want[q] - r.lam_t[q], false);
                r.lam_t[q] = want[q];
            }
        }
        const double un = speed(r, r.n, false);
        const double lam = std::max(0.0, r.lam + r.n.mass * (r.target - un));
        push(r, r.n, lam - r.lam, false);
        r.lam = lam;
    };
    for (int sweep = 0; sweep < kVelocitySweeps; ++sweep)
        for (Row& r : rows) solve(r);
    // A pair's first impact starts from no impulse (nothing to warm start from) and its points
    // share the blow: its rows get more sweeps, so that Newton's law holds between them.
    for (int sweep = 0; sweep < kImpactSweeps && !impacts_.empty(); ++sweep)
        for (std::size_t k : impacts_) solve(rows[k]);

    // Split impulse: pseudo-velocities that take kBeta of the penetration beyond kSlop away in
    // this step, applied to the poses and forgotten.
    for (int sweep = 0; sweep < kPositionSweeps; ++sweep)
        for (Row& r : rows) {
            const double goal = kBeta * std::max(0.0, -(r.depth + kSlop)) / h;
            const double lam = std::max(0.0, r.lam_p + r.n.mass * (goal - speed(r, r.n, true)));
            push(r, r.n, lam - r.lam_p, true);
            r.lam_p = lam;
        }

    // Results: contacts' impulses, last step's points for the next, the bodies.
    for (const StepContact<D>& c : *contacts) {
        Cached& saved = cache_[static_cast<std::uint64_t>(c.a) << 32 | c.b];
        saved.serial = serial_;
        saved.count = 0;
    }
    for (const Row& r : rows) {
        StepContact<D>& c = (*contacts)[r.c];
        Vec P = r.lam * r.n.d;
        for (int q = 0; q < r.nt; ++q) P += r.lam_t[q] * r.t[q].d;
        c.impulse += P;
        c.weight += r.lam;
        c.moment += r.lam * c.m.points[r.k];
        Cached& saved = cache_[static_cast<std::uint64_t>(c.a) << 32 | c.b];
        if (saved.count == Space<D>::kMaxPoints) continue;  // (a pair is listed once)
        saved.anchor[saved.count] = to_local(s[r.sa].x, s[r.sa].frame, c.m.points[r.k]);
        saved.lam[saved.count] = r.lam;
        saved.lam_t[saved.count] = P - r.lam * r.n.d;
        ++saved.count;
    }
    for (std::size_t q = 0; q < moving; ++q) {
        last_[members[q]] = serial_;
        Body& b = B[members[q]];
        b.v = s[q].v;
        b.w = s[q].w;
        correct(&b, Vec(h * s[q].vp), Spin(h * s[q].wp));
    }
    for (std::size_t i : members) slot_[i] = -1;
    for (const StepContact<D>& c : *contacts) slot_[c.a] = slot_[c.b] = -1;
}

template class IslandStepper<2>;
template class IslandStepper<3>;

}  // namespace collide
