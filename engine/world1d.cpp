#include "engine/world1d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "engine/run_error.h"

namespace collide {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
constexpr std::size_t kMaxEventsPerAdvance = 1000000;

}  // namespace

World1::World1(const Scene& scene) : scene_(scene) {
    if (scene.dimension != 1) throw std::invalid_argument("World1 needs a 1D scene");
    for (const SceneBody& b : scene.bodies) bodies_.push_back(b.body1);
    supported_.assign(bodies_.size(), false);
}

double World1::acceleration(std::size_t i) const {
    return bodies_[i].is_static || supported_[i] ? 0.0 : scene_.gravity.x();
}

void World1::update_support() {
    const double g = scene_.gravity.x();
    supported_.assign(bodies_.size(), false);
    if (g == 0.0) return;
    // Walk from the end gravity pulls towards: each block rests on the one below it.
    std::vector<std::size_t> order = left_to_right();
    if (g > 0.0) std::reverse(order.begin(), order.end());
    const double up = g < 0.0 ? 1.0 : -1.0;
    for (std::size_t k = 1; k < order.size(); ++k) {
        const std::size_t i = order[k], below = order[k - 1];
        Body1& b = bodies_[i];
        const Body1& support = bodies_[below];
        if (b.is_static || !(support.is_static || supported_[below])) continue;
        if ((g < 0.0 ? gap(below, i) : gap(i, below)) > kTouch) continue;
        const double rise = up * (b.v - support.v);  // speed away from the support
        if (rise < 0.0) continue;                    // approaching: an impact, not rest
        const double e = scene_.pair_restitution(below, i);
        const double series = e < 1.0 ? 2.0 * rise / (std::abs(g) * (1.0 - e)) : kNever;
        if (rise == 0.0 || series < kZenoTime) {
            b.v = support.v;
            supported_[i] = true;
        }
    }
}

double World1::right_face(std::size_t i) const { return bodies_[i].position + 0.5 * scene_.bodies[i].length; }

double World1::gap(std::size_t i, std::size_t j) const {
    return (bodies_[j].position - 0.5 * scene_.bodies[j].length) - right_face(i);
}

double World1::first_contact(std::size_t i, std::size_t j, double horizon) const {
    // Order the pair left (L) to right (R); the gap closes at dv = vR - vL, accelerates at dg.
    const bool i_left = bodies_[i].position <= bodies_[j].position;
    const std::size_t L = i_left ? i : j, R = i_left ? j : i;
    const double dv = bodies_[R].v - bodies_[L].v;
    const double dg = acceleration(R) - acceleration(L);
    const double g0 = gap(L, R);
    double t;
    if (g0 <= kTouch) {
        // Touching and not approaching (resolve_contacts saw to that): resting (dv = 0, held by
        // update_support) or parting; gravity may bring a parting pair back.
        t = dg < 0.0 && dv > 0.0 ? -2.0 * dv / dg : kNever;
    } else {
        t = first_root(0.5 * dg, dv, g0);
    }
    return t <= horizon ? t : kNever;
}

void World1::drift(double dt) {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        Body1& b = bodies_[i];
        if (b.is_static || supported_[i]) continue;
        const double a = acceleration(i);
        b.position += b.v * dt + 0.5 * a * dt * dt;
        b.v += a * dt;
    }
}

std::vector<Body1> World1::bodies_at(double) const { return bodies_; }

void World1::set_body(std::size_t i, const Body1& body) {
    bodies_.at(i) = body;
    supported_.assign(bodies_.size(), false);
}

void World1::advance_to(double target, std::vector<Event1>* events, const ImpactHook& on_impact) {
    const std::size_t start = events->size();
    const std::size_t n = bodies_.size();
    while (true) {
        const std::size_t recorded = events->size();
        resolve_contacts(events);
        if (on_impact && events->size() > recorded) on_impact(time_);
        update_support();
        if (events->size() - start > kMaxEventsPerAdvance)
            throw std::runtime_error("more than 10^6 impacts in one output step at t = " + std::to_string(time_) +
                                     " s");
        work_ += 1 + (events->size() - recorded);
        if (static_cast<double>(work_) > scene_.work_budget) refuse_work();
        const double horizon = target - time_;
        if (horizon <= 0.0) return check_finite();
        double earliest = kNever;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                if (!(bodies_[i].is_static && bodies_[j].is_static))
                    earliest = std::min(earliest, first_contact(i, j, horizon));
        if (earliest == kNever) {
            drift(horizon);
            time_ = target;
            return check_finite();
        }
        drift(earliest);
        time_ += earliest;
    }
}

// As the 2D and 3D worlds (World<D>::refuse_work).
void World1::refuse_work() const {
    const double done = static_cast<double>(work_);
    const double all = time_ > 0.0 ? done * scene_.duration / time_ : done;
    throw RunError(run_source(scene_.file) + "the scene has taken " + run_number(done) + " units of work by t = " +
                   run_number(time_) + " s of its " + run_number(scene_.duration) + " s (at this rate about " +
                   run_number(all) + " in all, " + run_duration(all) + "), more than its budget of " +
                   run_number(scene_.work_budget) + " (--max-work raises it; see docs/stepping.md, \"Work budget\")");
}

// As the 2D and 3D worlds (World<D>::check_finite): no state that is not finite leaves.
void World1::check_finite() const {
    for (std::size_t i = 0; i < bodies_.size(); ++i)
        if (!bodies_[i].state_finite())
            throw RunError(run_source(scene_.file) + "the state of '" + scene_.bodies[i].name +
                           "' is no longer finite by t = " + run_number(time_) + " s (a number overflowed)");
}

void World1::resolve_contacts(std::vector<Event1>* events) {
    // One at a time, impulses can pass back and forth for ever (a block pressed between the
    // floor and a falling block: each pass halves the approach). After 64 passes per block the
    // sequence has converged to round-off, and what little approach is left is solved in one
    // simultaneous step, the limit the sequence tends to.
    const std::size_t sequential_passes = scene_.policy == Policy::sequential ? 64 * bodies_.size() : 0;
    std::size_t pass = 0;
    for (; pass < sequential_passes; ++pass)
        if (!resolve_sequential(events)) return;
    for (; pass < sequential_passes + 100 * bodies_.size() + 100; ++pass)
        if (!resolve_simultaneous(events)) return;
    throw std::runtime_error("contacts did not settle at t = " + std::to_string(time_) + " s");
}

std::vector<std::size_t> World1::left_to_right() const {
    std::vector<std::size_t> order(bodies_.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return bodies_[a].position < bodies_[b].position; });
    return order;
}

bool World1::resolve_sequential(std::vector<Event1>* events) {
    const std::vector<std::size_t> order = left_to_right();
    // The leftmost touching pair that approaches, one impulse, then look again.
    for (std::size_t k = 0; k + 1 < order.size(); ++k) {
        const std::size_t L = order[k], R = order[k + 1];
        if (gap(L, R) > kTouch || bodies_[R].v - bodies_[L].v >= 0.0) continue;
        if (bodies_[L].is_static && bodies_[R].is_static) continue;
        const Response1 r =
            frictionless(at_contact(bodies_[L]), at_contact(bodies_[R]), 1.0, scene_.pair_restitution(L, R));
        Event1 e{time_,
                 L,
                 R,
                 right_face(L),
                 r.P,
                 bodies_[L].v,
                 bodies_[R].v,
                 r.va,
                 r.vb,
                 bodies_[L].position,
                 bodies_[R].position};
        bodies_[L].v = r.va;
        bodies_[R].v = r.vb;
        events->push_back(e);
        return true;
    }
    return false;
}

bool World1::resolve_simultaneous(std::vector<Event1>* events) {
    const std::vector<std::size_t> order = left_to_right();
    // Touching neighbours (left, right); the instant has an impact if one of them approaches.
    std::vector<std::pair<std::size_t, std::size_t>> contacts;
    bool approaching = false;
    for (std::size_t k = 0; k + 1 < order.size(); ++k) {
        const std::size_t L = order[k], R = order[k + 1];
        if (gap(L, R) > kTouch || (bodies_[L].is_static && bodies_[R].is_static)) continue;
        const double u = bodies_[R].v - bodies_[L].v;
        if (u > 0.0) continue;  // parting: no impulse
        contacts.emplace_back(L, R);
        approaching = approaching || u < 0.0;
    }
    if (!approaching) return false;
    // Contact k pushes R_k by +P_k and L_k by -P_k: u = J v with J_k = +1 at R_k, -1 at L_k,
    // and K = J M^-1 J^T. Wanted: u' = -e u, i.e. K P = -(1 + e) u, with every P_k >= 0.
    const std::size_t m = contacts.size();
    std::vector<bool> active(m, true);
    Eigen::VectorXd P = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m));
    for (std::size_t pass = 0; pass <= m; ++pass) {
        std::vector<std::size_t> idx;
        for (std::size_t k = 0; k < m; ++k)
            if (active[k]) idx.push_back(k);
        const auto na = static_cast<Eigen::Index>(idx.size());
        Eigen::MatrixXd K = Eigen::MatrixXd::Zero(na, na);
        Eigen::VectorXd rhs(na);
        for (Eigen::Index a = 0; a < na; ++a) {
            const auto [La, Ra] = contacts[idx[a]];
            rhs[a] = -(1.0 + scene_.pair_restitution(La, Ra)) * (bodies_[Ra].v - bodies_[La].v);
            for (Eigen::Index b = 0; b < na; ++b) {
                const auto [Lb, Rb] = contacts[idx[b]];
                auto J = [](std::size_t body, std::size_t L, std::size_t R) {
                    return body == R ? 1.0 : body == L ? -1.0 : 0.0;
                };
                for (std::size_t body : {La, Ra})
                    K(a, b) += J(body, La, Ra) * J(body, Lb, Rb) * bodies_[body].inv_mass();
            }
        }
        const Eigen::VectorXd Pa = K.ldlt().solve(rhs);
        // Drop the most negative impulse (that contact parts) and solve again.
        Eigen::Index worst = -1;
        for (Eigen::Index a = 0; a < na; ++a)
            if (Pa[a] < 0.0 && (worst < 0 || Pa[a] < Pa[worst])) worst = a;
        if (worst < 0) {
            P.setZero();
            for (Eigen::Index a = 0; a < na; ++a) P[static_cast<Eigen::Index>(idx[a])] = Pa[a];
            break;
        }
        active[idx[worst]] = false;
    }
    std::vector<double> v0(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) v0[i] = bodies_[i].v;
    for (std::size_t k = 0; k < m; ++k) {
        const auto [L, R] = contacts[k];
        const double p = P[static_cast<Eigen::Index>(k)];
        bodies_[L].v -= p * bodies_[L].inv_mass();
        bodies_[R].v += p * bodies_[R].inv_mass();
    }
    bool any = false;
    for (std::size_t k = 0; k < m; ++k) {
        const auto [L, R] = contacts[k];
        const double p = P[static_cast<Eigen::Index>(k)];
        if (p <= 0.0) continue;
        events->push_back(Event1{time_, L, R, right_face(L), p, v0[L], v0[R], bodies_[L].v, bodies_[R].v,
                                 bodies_[L].position, bodies_[R].position});
        any = true;
    }
    return any;
}

}  // namespace collide
