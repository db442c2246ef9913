// The contact solver (contact_solver.h): rows, projected Gauss-Seidel sweeps and the
// active-set polish.
#include "engine/contact_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

#include "engine/response.h"

namespace collide {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
// Projected Gauss-Seidel sweeps at most; a solve stops earlier when no impulse changes by more
// than 1e-13 of the largest (redundant points, e.g. a box's four corners, converge slowest).
constexpr int kMaxSweeps = 500;
// The active-set polish of solve(): tried after kPolishAfter sweeps and every
// 4 kPolishAfter after, accepted when every goal is met to kPolishTolerance of the largest
// initial miss (and impulses, friction cone, to that fraction of the largest impulse).
constexpr int kPolishAfter = 8;
constexpr double kPolishTolerance = 1e-12;
constexpr int kPolishRounds = 8;
constexpr double kPolishGrowth = 1e3;  // largest correction, in units of the problem's impulses

}  // namespace

template <int D>
ContactSolver<D>::ContactSolver(const std::vector<bool>& round) : round_(round) {}

// Projected Gauss-Seidel over the contact points of `contacts` (see engine/world.h): impulses with
// P.n >= 0 such that each point leaves with un >= target (equality where P.n > 0), tangential
// impulses held within mu P.n (mu < 0: no limit) aiming at the tangential target velocity.
template <int D>
void ContactSolver<D>::solve(std::vector<Contact<D>>* contacts, const std::vector<PointGoal<D>>& goals,
                             std::vector<Body>* state) const {
    struct Row {
        std::size_t c;
        int k;
        Vec ra = Vec::Zero(), rb = Vec::Zero(), n = Vec::Zero();
        InvInertia inv_Ia{}, inv_Ib{};  // world, at the solve
        std::array<Vec, 2> t = {Vec::Zero(), Vec::Zero()};
        int nt = 0;
        double mn = 0.0;
        std::array<double, 2> mt{};
        double lam = 0.0;
        std::array<double, 2> lam_t{};
        PointGoal<D> goal;
    };
    auto body_ref = [&](std::size_t i) -> Body& { return (*state)[i]; };
    std::vector<Row> rows;
    std::size_t g = 0;
    for (std::size_t ci = 0; ci < contacts->size(); ++ci) {
        Contact<D>& c = (*contacts)[ci];
        for (int k = 0; k < c.m.count; ++k, ++g) {
            Row r;
            r.c = ci;
            r.k = k;
            r.goal = goals[g];
            r.n = c.m.normal;
            auto ia = at_contact(body_ref(c.a), c.m.points[k]);
            auto ib = at_contact(body_ref(c.b), c.m.points[k]);
            if (round_[c.a]) ia.r = ia.r.dot(r.n) * r.n;  // as in World::resolve_point
            if (round_[c.b]) ib.r = ib.r.dot(r.n) * r.n;
            r.ra = ia.r;
            r.rb = ib.r;
            r.inv_Ia = ia.inv_I;
            r.inv_Ib = ib.inv_I;
            const auto K = collision_matrix(ia, ib);
            const double kn = r.n.dot(K * r.n);
            r.mn = kn > 0.0 ? 1.0 / kn : 0.0;
            if (r.goal.mu != 0.0) {
                r.nt = tangents(r.n, &r.t);
                for (int q = 0; q < r.nt; ++q) {
                    const double kt = r.t[q].dot(K * r.t[q]);
                    r.mt[q] = kt > 0.0 ? 1.0 / kt : 0.0;
                }
            }
            rows.push_back(r);
        }
    }
    auto apply = [&](const Row& r, const Vec& P) {
        const Contact<D>& c = (*contacts)[r.c];
        Body& A = body_ref(c.a);
        Body& B = body_ref(c.b);
        if (!A.is_static) {
            A.v -= P * A.inv_mass();
            A.w -= r.inv_Ia * lever(r.ra, P);
        }
        if (!B.is_static) {
            B.v += P * B.inv_mass();
            B.w += r.inv_Ib * lever(r.rb, P);
        }
    };
    auto rel = [&](const Row& r) {
        const Contact<D>& c = (*contacts)[r.c];
        const Body& A = body_ref(c.a);
        const Body& B = body_ref(c.b);
        return Vec((B.v + spin_cross(B.w, r.rb)) - (A.v + spin_cross(A.w, r.ra)));
    };
    // The size of the problem: the largest initial miss of a goal (m/s), the yardstick of the
    // polish's tolerances.
    double miss = 0.0;
    for (const Row& r : rows) {
        if (!std::isfinite(r.goal.un)) continue;
        const Vec u = rel(r);
        const double un = u.dot(r.n) - r.goal.un;
        miss = std::max(miss, r.goal.push_only ? -un : std::abs(un));
        for (int q = 0; q < r.nt; ++q) miss = std::max(miss, std::abs((u - r.goal.ut).dot(r.t[q])));
    }

    // Active-set polish. Projected Gauss-Seidel finds which points push and which stick after
    // a few sweeps but then converges slowly on stacks (the error of a tall pile decays like
    // that of a long chain). With the active set fixed, the impulses are the solution of a
    // linear system: every pushing point (impulse > 0 now) reaches its normal goal, every
    // sticking point its tangential goal. W x = b (b: the goals' present misses; W = J M^-1 J^T
    // over those rows: symmetric, positive semi-definite; singular for redundant points, e.g.
    // a box's corners, but consistent) is solved for the correction x by conjugate gradients
    // (Jacobi-preconditioned: diag W = 1/mn, 1/mt), matrix-free through the bodies. A point
    // the correction would make pull (impulse < 0) is released and the rest solved again (at
    // most kPolishRounds times): redundant points can share a load in many ways. Two variants:
    // `frictionless` first drops every Coulomb tangential impulse and asks only the normal
    // goals (a stack held by normal forces alone, e.g. a pyramid of aligned boxes: the friction
    // the sweeps spread over it is one of many equally valid choices), else the sticking
    // points' tangential impulses are unknowns too. The result is kept only if it solves the
    // whole problem to kPolishTolerance of `miss` (impulses to that fraction of the largest):
    // pushing points at their goals with impulses >= 0, tangential goals met inside the
    // friction cone, idle points not approaching; otherwise everything is undone and the sweeps
    // go on. Goals that no motion meets (W x = b inconsistent: the residual stalls while x
    // grows) abandon the polish.
    auto polish = [&](bool frictionless) -> bool {
        struct Unknown {
            std::size_t row;
            int q;  // -1: normal, else the tangent
            Vec d;  // the impulse direction
            double target, precond;
            int sa, sb;  // body slots, -1 for a static body
        };
        std::vector<std::size_t> slot_body;
        std::unordered_map<std::size_t, int> slot;
        auto slot_of = [&](std::size_t i) {
            if (body_ref(i).is_static) return -1;
            auto [it, fresh] = slot.emplace(i, static_cast<int>(slot_body.size()));
            if (fresh) slot_body.push_back(i);
            return it->second;
        };
        double lam_scale = 0.0;
        for (const Row& r : rows) {
            lam_scale = std::max(lam_scale, std::abs(r.lam));
            if (!std::isfinite(r.goal.un)) continue;
            const Contact<D>& c = (*contacts)[r.c];
            slot_of(c.a);
            slot_of(c.b);
        }
        const double lam_tol = kPolishTolerance * std::max(lam_scale, 1e-300);
        // What is undone if the polish fails.
        std::vector<Row> saved_rows = rows;
        std::vector<std::pair<Vec, Spin>> saved_bodies;
        for (std::size_t i : slot_body) saved_bodies.emplace_back(body_ref(i).v, body_ref(i).w);
        auto release = [&](Row& r, bool normal_too) {  // a row's impulses back to zero
            Vec P = zero<Vec>();
            for (int q = 0; q < r.nt; ++q) P -= r.lam_t[q] * r.t[q];
            r.lam_t = {0.0, 0.0};
            if (normal_too) {
                P -= r.lam * r.n;
                r.lam = 0.0;
            }
            apply(r, P);
        };
        if (frictionless)
            for (Row& r : rows)
                if (r.goal.mu > 0.0) release(r, false);
        const std::size_t nb = slot_body.size();
        std::vector<Vec> dv(nb);
        std::vector<Spin> dw(nb);
        const double tol = kPolishTolerance * miss;
        double worst = kNever;
        bool failed = false;
        // The impulses the problem can ask for: those held, or those that cancel the largest
        // miss at the stiffest point.
        double impulse_scale = lam_scale;
        for (const Row& r : rows) impulse_scale = std::max(impulse_scale, miss * std::max({r.mn, r.mt[0], r.mt[1]}));
        std::vector<Unknown> act;
        // Rounds: a pushing point the solve would have pull (impulse < 0) is released and the
        // rest solved again (redundant points share a load in many ways).
        for (int round = 0; round < kPolishRounds; ++round) {
            act.clear();
            for (std::size_t k = 0; k < rows.size(); ++k) {
                const Row& r = rows[k];
                if (!std::isfinite(r.goal.un) || (r.goal.push_only && !(r.lam > 0.0))) continue;
                const Contact<D>& c = (*contacts)[r.c];
                const int sa = slot_of(c.a), sb = slot_of(c.b);
                act.push_back(Unknown{k, -1, r.n, r.goal.un, r.mn, sa, sb});
                if (frictionless && r.goal.mu > 0.0) continue;
                for (int q = 0; q < r.nt; ++q)
                    act.push_back(Unknown{k, q, r.t[q], r.goal.ut.dot(r.t[q]), r.mt[q], sa, sb});
            }
            if (act.empty()) break;
            const std::size_t n = act.size();
            // y = W x: the velocity change along each direction from the impulses x.
            auto product = [&](const std::vector<double>& x, std::vector<double>* y) {
                std::fill(dv.begin(), dv.end(), zero<Vec>());
                std::fill(dw.begin(), dw.end(), zero<Spin>());
                for (std::size_t k = 0; k < n; ++k) {
                    const Unknown& u = act[k];
                    const Row& r = rows[u.row];
                    const Vec P = x[k] * u.d;
                    if (u.sa >= 0) {
                        dv[u.sa] -= P * body_ref(slot_body[u.sa]).inv_mass();
                        dw[u.sa] -= r.inv_Ia * lever(r.ra, P);
                    }
                    if (u.sb >= 0) {
                        dv[u.sb] += P * body_ref(slot_body[u.sb]).inv_mass();
                        dw[u.sb] += r.inv_Ib * lever(r.rb, P);
                    }
                }
                for (std::size_t k = 0; k < n; ++k) {
                    const Unknown& u = act[k];
                    const Row& r = rows[u.row];
                    Vec rel_v = zero<Vec>();
                    if (u.sb >= 0) rel_v += dv[u.sb] + spin_cross(dw[u.sb], r.rb);
                    if (u.sa >= 0) rel_v -= dv[u.sa] + spin_cross(dw[u.sa], r.ra);
                    (*y)[k] = rel_v.dot(u.d);
                }
            };
            // Conjugate gradients, restarted from the true residual every kRestart iterations
            // (a singular W lets round-off grow in its null space otherwise).
            std::vector<double> x(n, 0.0), b(n), res(n), z(n), p(n), q(n);
            for (std::size_t k = 0; k < n; ++k) b[k] = act[k].target - rel(rows[act[k].row]).dot(act[k].d);
            constexpr int kRestart = 64;
            const int max_iterations = static_cast<int>(std::min<std::size_t>(8 * n + 64, 20000));
            double rz = 0.0, restarted = kNever;
            for (int it = 0; it < max_iterations; ++it) {
                if (it % kRestart == 0) {
                    product(x, &q);
                    worst = 0.0;
                    rz = 0.0;
                    for (std::size_t k = 0; k < n; ++k) {
                        res[k] = b[k] - q[k];
                        worst = std::max(worst, std::abs(res[k]));
                        p[k] = act[k].precond * res[k];
                        rz += res[k] * p[k];
                    }
                    if (worst <= 0.5 * tol) break;
                    // Goals no motion of the bodies meets (e.g. a sliding face's corners asked
                    // to stop in a twist): the residual stalls while x grows without bound.
                    if (!(worst < 0.5 * restarted)) {
                        failed = true;
                        break;
                    }
                    restarted = worst;
                }
                product(p, &q);
                double pq = 0.0;
                for (std::size_t k = 0; k < n; ++k) pq += p[k] * q[k];
                if (!(pq > 0.0)) {
                    it += kRestart - 1 - it % kRestart;  // restart
                    continue;
                }
                const double alpha = rz / pq;
                double rz_new = 0.0;
                worst = 0.0;
                for (std::size_t k = 0; k < n; ++k) {
                    x[k] += alpha * p[k];
                    res[k] -= alpha * q[k];
                    worst = std::max(worst, std::abs(res[k]));
                    z[k] = act[k].precond * res[k];
                    rz_new += res[k] * z[k];
                }
                if (worst <= 0.1 * tol) it += kRestart - 1 - it % kRestart;  // confirm by a restart
                const double beta = rz_new / rz;
                rz = rz_new;
                for (std::size_t k = 0; k < n; ++k) p[k] = z[k] + beta * p[k];
            }
            double largest = 0.0;
            for (std::size_t k = 0; k < n; ++k) largest = std::max(largest, std::abs(x[k]));
            if (failed || !(largest <= kPolishGrowth * impulse_scale)) {
                failed = true;
                break;
            }
            for (std::size_t k = 0; k < n; ++k) {
                Row& r = rows[act[k].row];
                apply(r, x[k] * act[k].d);
                (act[k].q < 0 ? r.lam : r.lam_t[act[k].q]) += x[k];
            }
            bool pulled = false;
            for (Row& r : rows)
                if (std::isfinite(r.goal.un) && r.goal.push_only && r.lam < -lam_tol) {
                    release(r, true);
                    pulled = true;
                }
            if (!pulled) break;
        }
        // The whole problem, checked afresh on the bodies' velocities.
        bool ok = !failed;
        for (std::size_t k = 0; k < rows.size() && ok; ++k) {
            const Row& r = rows[k];
            if (!std::isfinite(r.goal.un)) continue;
            const Vec u = rel(r);
            const double un = u.dot(r.n) - r.goal.un;
            const bool pushing = !r.goal.push_only || r.lam != 0.0;
            ok = pushing ? std::abs(un) <= tol && (!r.goal.push_only || r.lam >= -lam_tol) : un >= -tol;
            if (!ok || r.nt == 0 || !pushing) continue;
            double norm = 0.0;
            for (int q2 = 0; q2 < r.nt; ++q2) {
                norm += r.lam_t[q2] * r.lam_t[q2];
                ok = ok && std::abs((u - r.goal.ut).dot(r.t[q2])) <= tol;
            }
            if (r.goal.mu > 0.0) ok = ok && std::sqrt(norm) <= r.goal.mu * std::max(0.0, r.lam) + lam_tol;
        }
        if (!ok) {
            rows = std::move(saved_rows);
            for (std::size_t s = 0; s < slot_body.size(); ++s) {
                body_ref(slot_body[s]).v = saved_bodies[s].first;
                body_ref(slot_body[s]).w = saved_bodies[s].second;
            }
        }
        return ok;
    };
    bool coulomb_rows = false;
    for (const Row& r : rows) coulomb_rows = coulomb_rows || (r.nt > 0 && r.goal.mu > 0.0);
    for (int it = 0; it < kMaxSweeps; ++it) {
        if (miss > 0.0 && (it == kPolishAfter || (it > kPolishAfter && it % (4 * kPolishAfter) == 0)) &&
            ((coulomb_rows && polish(true)) || polish(false)))
            break;
        double change = 0.0, scale = 1e-300;
        for (Row& r : rows) {
            if (!std::isfinite(r.goal.un)) continue;  // a point left out of this solve
            Vec u = rel(r);
            double lam = r.lam - r.mn * (u.dot(r.n) - r.goal.un);
            if (r.goal.push_only) lam = std::max(0.0, lam);
            change = std::max(change, std::abs(lam - r.lam));
            apply(r, (lam - r.lam) * r.n);
            r.lam = lam;
            scale = std::max(scale, std::abs(lam));
            if (r.nt == 0) continue;
            u = rel(r);
            std::array<double, 2> lt = r.lam_t;
            for (int q = 0; q < r.nt; ++q) lt[q] -= r.mt[q] * (u.dot(r.t[q]) - r.goal.ut.dot(r.t[q]));
            if (r.goal.mu > 0.0) {
                double norm = 0.0;
                for (int q = 0; q < r.nt; ++q) norm += lt[q] * lt[q];
                norm = std::sqrt(norm);
                const double limit = r.goal.mu * std::max(0.0, r.lam);
                if (norm > limit)
                    for (int q = 0; q < r.nt; ++q) lt[q] *= limit / norm;
            }
            Vec P = zero<Vec>();
            for (int q = 0; q < r.nt; ++q) {
                change = std::max(change, std::abs(lt[q] - r.lam_t[q]));
                P += (lt[q] - r.lam_t[q]) * r.t[q];
            }
            apply(r, P);
            r.lam_t = lt;
        }
        if (change <= 1e-13 * scale) break;
    }
    for (const Row& r : rows) {
        Contact<D>& c = (*contacts)[r.c];
        Vec P = r.lam * r.n;
        for (int q = 0; q < r.nt; ++q) P += r.lam_t[q] * r.t[q];
        c.impulse += P;
        c.weight += std::max(0.0, r.lam);
        c.moment += std::max(0.0, r.lam) * c.m.points[r.k];
    }
}

template class ContactSolver<2>;
template class ContactSolver<3>;

}  // namespace collide
