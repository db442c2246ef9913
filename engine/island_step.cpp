// One step of the stepped islands (island_step.h): rows, warm start, velocity sweeps, split
// impulse.
#include "engine/island_step.h"

#include <algorithm>
#include <cmath>

namespace collide {

namespace {

// The body's inverse inertia in the world frame, as the dimension needs it.
double inv_inertia(const Body2& b) { return b.inv_inertia(); }
Mat3 inv_inertia(const Body3& b) { return b.is_static ? Mat3::Zero() : b.inv_inertia_world(); }

// (r x n) I^-1 (r x n): a lever arm's share of 1 / (effective mass) along n.
double turning_share(const Vec2& r, const Vec2& n, double inv_I) {
    const double c = cross(r, n);
    return c * c * inv_I;
}
double turning_share(const Vec3& r, const Vec3& n, const Mat3& inv_I) {
    const Vec3 c = r.cross(n);
    return c.dot(inv_I * c);
}


// A point in the body's own frame.
Vec2 to_local(const Body2& b, const Vec2& p) {
    const Vec2 d = p - b.position;
    const double c = std::cos(b.angle), s = std::sin(b.angle);
    return Vec2(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
}
Vec3 to_local(const Body3& b, const Vec3& p) { return b.orientation.conjugate() * (p - b.position); }

// The pseudo-velocities' correction of a pose over h (2D: angle; 3D: the small rotation w h).
void correct(Body2* b, const Vec2& dx, double dtheta) {
    b->position += dx;
    b->angle += dtheta;
}
void correct(Body3* b, const Vec3& dx, const Vec3& dtheta) {
    b->position += dx;
    const double angle = dtheta.norm();
    if (angle > 0.0) b->orientation = (Quat(Eigen::AngleAxisd(angle, dtheta / angle)) * b->orientation).normalized();
}

}  // namespace

template <int D>
void IslandStepper<D>::step(std::vector<StepContact<D>>* contacts, const std::vector<std::size_t>& members,
                            std::vector<Body>* bodies, const Vec& g, double h) {
    std::vector<Body>& B = *bodies;
    if (slot_.size() != B.size()) slot_.assign(B.size(), -1);
    if (last_.size() != B.size()) last_.assign(B.size(), 0);
    ++serial_;
    struct Slot {
        Vec v = Vec::Zero(), vp = Vec::Zero();  // velocity, pseudo-velocity (m/s)
        Spin w = zero<Spin>(), wp = zero<Spin>();  // spin, pseudo-spin (rad/s)
        double inv_m = 0.0;
        InvInertia inv_I{};
    };
    std::vector<Slot> s(members.size());
    for (std::size_t q = 0; q < members.size(); ++q) {
        const Body& b = B[members[q]];
        slot_[members[q]] = static_cast<int>(q);
        s[q].v = b.v;
        s[q].w = b.w;
        s[q].vp = zero<Vec>();
        s[q].wp = zero<Spin>();
        s[q].inv_m = b.inv_mass();
        s[q].inv_I = inv_inertia(b);
    }

    struct Row {
        std::size_t c = 0;
        int k = 0;
        int sa = -1, sb = -1;  // slots; -1: the body does not move in this step
        Vec ra = Vec::Zero(), rb = Vec::Zero(), n = Vec::Zero();
        std::array<Vec, 2> t = {Vec::Zero(), Vec::Zero()};
        int nt = 0;
        double mn = 0.0;
        std::array<double, 2> mt{};
        double target = 0.0;   // normal velocity goal
        double depth = 0.0;    // signed separation at the step's start
        double mu = 0.0;
        double lam = 0.0, lam_p = 0.0;
        std::array<double, 2> lam_t{};
    };
    std::vector<Row> rows;
    auto vel = [&](int slot, std::size_t body, const Vec& r) {
        if (slot < 0) return Vec(B[body].v + spin_cross(B[body].w, r));
        return Vec(s[slot].v + spin_cross(s[slot].w, r));
    };
    auto rel = [&](const Row& r) {
        const StepContact<D>& c = (*contacts)[r.c];
        return Vec(vel(r.sb, c.b, r.rb) - vel(r.sa, c.a, r.ra));
    };
    auto rel_pseudo = [&](const Row& r) {
        Vec u = zero<Vec>();
        if (r.sb >= 0) u += s[r.sb].vp + spin_cross(s[r.sb].wp, r.rb);
        if (r.sa >= 0) u -= s[r.sa].vp + spin_cross(s[r.sa].wp, r.ra);
        return u.dot(r.n);
    };
    auto apply = [&](const Row& r, const Vec& P) {
        if (r.sa >= 0) {
            s[r.sa].v -= P * s[r.sa].inv_m;
            s[r.sa].w -= s[r.sa].inv_I * lever(r.ra, P);
        }
        if (r.sb >= 0) {
            s[r.sb].v += P * s[r.sb].inv_m;
            s[r.sb].w += s[r.sb].inv_I * lever(r.rb, P);
        }
    };
    auto apply_pseudo = [&](const Row& r, double lam) {
        const Vec P = lam * r.n;
        if (r.sa >= 0) {
            s[r.sa].vp -= P * s[r.sa].inv_m;
            s[r.sa].wp -= s[r.sa].inv_I * lever(r.ra, P);
        }
        if (r.sb >= 0) {
            s[r.sb].vp += P * s[r.sb].inv_m;
            s[r.sb].wp += s[r.sb].inv_I * lever(r.rb, P);
        }
    };

    // Rows, their goals from the velocities before the step, and last step's impulses.
    for (std::size_t ci = 0; ci < contacts->size(); ++ci) {
        StepContact<D>& c = (*contacts)[ci];
        c.impulse = zero<Vec>();
        c.weight = 0.0;
        c.moment = zero<Vec>();
        c.approach = 0.0;
        const std::uint64_t key = static_cast<std::uint64_t>(c.a) << 32 | c.b;
        const auto found = cache_.find(key);
        const int sa = slot_[c.a], sb = slot_[c.b];
        const Cached* before = found == cache_.end() ? nullptr : &found->second;
        if (before && ((sa >= 0 && before->serial != last_[c.a]) || (sb >= 0 && before->serial != last_[c.b])))
            before = nullptr;  // not in contact at their last step
        c.fresh = true;
        if (before)
            for (int q = 0; q < before->count; ++q) c.fresh = c.fresh && !(before->lam[q] > 0.0);
        const double inv_ma = sa >= 0 ? s[sa].inv_m : 0.0, inv_mb = sb >= 0 ? s[sb].inv_m : 0.0;
        for (int k = 0; k < c.m.count; ++k) {
            Row r;
            r.c = ci;
            r.k = k;
            r.sa = sa;
            r.sb = sb;
            r.n = c.m.normal;
            r.ra = c.m.points[k] - B[c.a].position;
            r.rb = c.m.points[k] - B[c.b].position;
            r.depth = c.m.depths[k];
            r.mu = c.mu;
            double kn = inv_ma + inv_mb;
            if (sa >= 0) kn += turning_share(r.ra, r.n, s[sa].inv_I);
            if (sb >= 0) kn += turning_share(r.rb, r.n, s[sb].inv_I);
            r.mn = kn > 0.0 ? 1.0 / kn : 0.0;
            if (r.mu != 0.0) {
                r.nt = tangents(r.n, &r.t);
                for (int q = 0; q < r.nt; ++q) {
                    double kt = inv_ma + inv_mb;
                    if (sa >= 0) kt += turning_share(r.ra, r.t[q], s[sa].inv_I);
                    if (sb >= 0) kt += turning_share(r.rb, r.t[q], s[sb].inv_I);
                    r.mt[q] = kt > 0.0 ? 1.0 / kt : 0.0;
                }
            }
            const double un = rel(r).dot(r.n);
            c.approach = std::min(c.approach, un);
            const double gap = std::max(r.depth, 0.0);
            r.target = -gap / h;
            if (un < 0.0 && gap + h * un <= 0.0) r.target = std::max(r.target, -c.e * un);
            if (before) {  // the nearest of last step's points, if near enough
                const Vec here = to_local(B[c.a], c.m.points[k]);
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
                    for (int q = 0; q < r.nt; ++q) r.lam_t[q] = before->lam_t[best].dot(r.t[q]);
                }
            }
            rows.push_back(r);
        }
    }

    // Gravity over the step, then last step's impulses (warm start).
    for (Slot& b : s)
        if (b.inv_m > 0.0) b.v += h * g;
    for (const Row& r : rows) {
        Vec P = r.lam * r.n;
        for (int q = 0; q < r.nt; ++q) P += r.lam_t[q] * r.t[q];
        apply(r, P);
    }

    // Velocity sweeps: friction (within the cone of the present normal impulse), then normal.
    for (int sweep = 0; sweep < kVelocitySweeps; ++sweep)
        for (Row& r : rows) {
            if (r.nt > 0) {
                const Vec u = rel(r);
                std::array<double, 2> want{};
                for (int q = 0; q < r.nt; ++q) want[q] = r.lam_t[q] - r.mt[q] * u.dot(r.t[q]);
                if (r.mu >= 0.0) {
                    const double limit = r.mu * r.lam;
                    const double size = std::sqrt(want[0] * want[0] + want[1] * want[1]);
                    if (size > limit) {
                        const double scale = size > 0.0 ? limit / size : 0.0;
                        want[0] *= scale;
                        want[1] *= scale;
                    }
                }
                Vec P = zero<Vec>();
                for (int q = 0; q < r.nt; ++q) {
                    P += (want[q] - r.lam_t[q]) * r.t[q];
                    r.lam_t[q] = want[q];
                }
                apply(r, P);
            }
            const double un = rel(r).dot(r.n);
            const double lam = std::max(0.0, r.lam + r.mn * (r.target - un));
            apply(r, (lam - r.lam) * r.n);
            r.lam = lam;
        }

    // Split impulse: pseudo-velocities that take kBeta of the penetration beyond kSlop away in
    // this step, applied to the poses and forgotten.
    for (int sweep = 0; sweep < kPositionSweeps; ++sweep)
        for (Row& r : rows) {
            const double goal = kBeta * std::max(0.0, -(r.depth + kSlop)) / h;
            const double lam = std::max(0.0, r.lam_p + r.mn * (goal - rel_pseudo(r)));
            apply_pseudo(r, lam - r.lam_p);
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
        Vec P = r.lam * r.n;
        for (int q = 0; q < r.nt; ++q) P += r.lam_t[q] * r.t[q];
        c.impulse += P;
        c.weight += r.lam;
        c.moment += r.lam * c.m.points[r.k];
        Cached& saved = cache_[static_cast<std::uint64_t>(c.a) << 32 | c.b];
        if (saved.count == Space<D>::kMaxPoints) continue;  // (a pair is listed once)
        saved.anchor[saved.count] = to_local(B[c.a], c.m.points[r.k]);
        saved.lam[saved.count] = r.lam;
        saved.lam_t[saved.count] = P - r.lam * r.n;
        ++saved.count;
    }
    for (std::size_t q = 0; q < members.size(); ++q) {
        last_[members[q]] = serial_;
        Body& b = B[members[q]];
        b.v = s[q].v;
        b.w = s[q].w;
        correct(&b, Vec(h * s[q].vp), Spin(h * s[q].wp));
        slot_[members[q]] = -1;
    }
}

template class IslandStepper<2>;
template class IslandStepper<3>;

}  // namespace collide
