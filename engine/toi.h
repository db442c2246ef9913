// Time of impact: the first instant two bodies on known motions touch, to a tolerance (the
// worlds use kTouch, 1e-10 m). Three ways, from the cheapest:
//
// Closed forms. A round body (disc, sphere) against a plane, or against another round body
// with the same acceleration: the gap is a quadratic in time (the surface of a round body does
// not move when it turns), and the time is its smallest root.
//
// Conservative advancement, 2D (time_of_impact). Each body follows a known free motion over
// the interval: x(t) = x + v t + g t^2/2 (g: the body's own acceleration, gravity for dynamic
// bodies, 0 for static ones) and angle(t) = angle + w t (a torque-free body in the plane keeps
// w). At time t the shapes are d apart along the unit normal n between their nearest points.
// Before they can touch, some point of B must gain d on A along n; it gains at most
//     rate = max(0, -n.(vb - va)) + max(0, -n.(gb - ga)) (t_end - t) + |wa| Ra + |wb| Rb
// per second (R: each shape's bounding radius), so the next time to look is t + d / rate. The
// iteration stops when d <= tolerance: the first contact, never a pose that already overlaps
// by more than round-off.
//
// Conservative advancement, the worlds' (advance_to_contact, 2D and 3D): the same bound with
// the bodies' own motions (3D turning with the gyroscopic term, welded bodies circling their
// compound's centre), which also tries longer steps from the gap's observed closing rate and
// keeps one only when the gap at its end is still open (a corner turning slowly near the
// ground would crawl), and watches pairs already touching (resting on a corner, or parting).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/body.h"
#include "engine/space.h"

namespace collide {

struct Motion2 {
    Vec2 x = Vec2::Zero();  // centre of mass at t = 0, m
    Vec2 v = Vec2::Zero();  // m/s
    Vec2 g = Vec2::Zero();  // m/s^2
    double angle = 0.0;     // rad
    double w = 0.0;         // rad/s
    Pose2 at(double t) const { return Pose2{x + v * t + 0.5 * t * t * g, angle + w * t}; }
    Vec2 velocity(double t) const { return v + g * t; }
};

struct TimeOfImpact {
    bool hit = false;    // contact within [0, t_end]
    double t = 0.0;      // s, the first time the separation is <= tolerance
    Manifold2 manifold;  // at t (points reported within the tolerance)
    int iterations = 0;
    bool converged = true;  // false: max_iterations ran out first (hit is then false)
};

struct ToiSettings {
    double tolerance = 1e-10;  // m: contact when the separation is at most this
    int max_iterations = 10000;
};

TimeOfImpact time_of_impact(const Shape2& a, const Motion2& ma, const Shape2& b, const Motion2& mb, double t_end,
                            const ToiSettings& settings = {});

// ---- Closed forms (the time from now, s; +infinity if never) ----

// A round body of radius r against the plane n.x = offset: gap(s) = n.x(s) - offset - r with
// x(s) = x + v s + a s^2/2, a quadratic in s. `gap`: the gap now; `touching`: in contact now.
double plane_contact_time(const Vec2& n, const Vec2& v, const Vec2& a, double gap, bool touching);
double plane_contact_time(const Vec3& n, const Vec3& v, const Vec3& a, double gap, bool touching);
// Two round bodies with the same acceleration, their radii summing to R: |d + u s| = R with d, u
// the relative position and velocity. `touching`: in contact now (then no time: they part).
double round_contact_time(const Vec2& d, const Vec2& u, double R, bool touching);
double round_contact_time(const Vec3& d, const Vec3& u, double R, bool touching);

// ---- The bound on turning ----

// Largest spin the body can reach while free (rad/s): 2D w is constant; in 3D the rotational
// energy E = w.I w/2 is, so |w| <= sqrt(2 E / I_min).
double spin_bound(const Body2& b, double inv_min_moment);
double spin_bound(const Body3& b, double inv_min_moment);
// 1 / the smallest principal moment (0 for a static body): the spin bound's I_min.
double inverse_smallest_moment(const Body2& b);
double inverse_smallest_moment(const Body3& b);

// ---- The worlds' conservative advancement ----

// What advance_to_contact needs to know of a pair besides its shapes and motions.
template <class Vec>
struct Approach {
    double t = 0.0;                         // s: now
    double horizon = 0.0;                   // s: how far ahead to look
    double touch = 0.0;                     // m: a gap this small is contact
    double v_rest = 0.0;                    // m/s: a normal speed this small is resting
    double turn_rate = 0.0;                 // m/s: how fast the bodies' surfaces can turn towards each other
    double radius_a = 0.0, radius_b = 0.0;  // m: bounding radii
    bool touching = false;                  // in contact now (resting on a corner, or parting)
    Vec acc_a, acc_b;                       // m/s^2: each body's constant acceleration
};

// The first instant (from c.t, at most c.horizon later) the shapes sa and sb, carried by the
// motions ma and mb, touch: a body that lands on the other, or a touching point that
// approaches; +infinity if nothing happens in the horizon. A motion M holds `body`, a copy of
// its body, and advance(&m, dt) moves it dt seconds along its motion.
template <class Shape, class Vec, class M, class Advance>
double advance_to_contact(const Shape& sa, const Shape& sb, M ma, M mb, const Advance& advance,
                          const Approach<Vec>& c) {
    using Body = decltype(M::body);
    constexpr double kNever = std::numeric_limits<double>::infinity();
    const double kTouch = c.touch;  // the world's contact tolerance
    const double t = c.t, horizon = c.horizon, v_rest = c.v_rest;
    const bool touching = c.touching;
    const Body& ca = ma.body;
    const Body& cb = mb.body;
    // Touching already (resting on a corner, or parting): watch every point of the pair, not
    // only the nearest, so that a box rocking onto its other corner is caught when it lands.
    const double wide = 2.0 * std::max(c.radius_a, c.radius_b) + kTouch;
    const double margin = touching ? wide : kTouch;
    double s = 0.0;
    // The gap that matters: the nearest point not already resting in contact; `lands` and
    // `leave` report touching points that approach or lift off.
    struct Look {
        double gap = kNever, leave = kNever, separation = 0.0;
        bool lands = false;
        Vec normal;
    };
    auto look = [&](const Body& pa, const Body& pb, bool start) {
        auto mm = collide(sa, pose_of(pa), sb, pose_of(pb), margin);
        // Box against box, the separating-axis test prefers a face to an edge pair that is
        // better by less than its tolerance (1e-6 of the size, far above kTouch): then the
        // separation can be within kTouch while every clipped point of the face is farther.
        // The points decide, as they do for the contact manifold of World::resolve(): their depths
        // (from the wide manifold: same points, a larger margin) are the gap.
        if (!touching && mm.count == 0 && mm.separation <= kTouch) mm = collide(sa, pose_of(pa), sb, pose_of(pb), wide);
        Look l;
        l.normal = mm.normal;
        l.separation = mm.separation;
        if (mm.count == 0) l.gap = mm.separation;
        bool near = false;  // a point within kTouch
        for (int k = 0; k < mm.count; ++k) {
            const double depth = mm.depths[k];
            if (depth > kTouch) {
                l.gap = std::min(l.gap, depth);
                continue;
            }
            near = true;
            const Vec& p = mm.points[k];
            const double un = ((pb.v + spin_cross(pb.w, p - pb.position)) - (pa.v + spin_cross(pa.w, p - pa.position)))
                                  .dot(mm.normal);
            // (At s = 0 the contact manifold of World::predict_pair decided already; this wider one
            // may pick other points of a face and must not disagree with it.)
            if (un < -v_rest && !start) l.lands = true;
            if (un > v_rest) {
                // Lifts off: look again when it has left the contact band, or, pulled back,
                // when it is back where it started (a ballistic arc, 2 un / |an| later).
                const double an = mm.normal.dot(c.acc_b - c.acc_a);
                l.leave = std::min(l.leave, (2.0 * kTouch - depth) / un);
                if (an < 0.0) l.leave = std::min(l.leave, 2.0 * un / -an);
            }
        }
        if (!touching && (mm.count == 0 ? mm.separation <= kTouch : near)) l.lands = true;
        return l;
    };
    double previous_gap = kNever, previous_s = 0.0;
    for (int it = 0; it < 20000; ++it) {
        const Look l = look(ca, cb, s == 0.0);
        if (l.lands) return t + s;
        if (!std::isfinite(l.gap) && !std::isfinite(l.leave)) return kNever;  // resting, nothing to come
        const double rate = std::max(0.0, -l.normal.dot(cb.v - ca.v)) +
                            std::max(0.0, -l.normal.dot(c.acc_b - c.acc_a)) * (horizon - s) + c.turn_rate;
        double step = l.leave;
        if (std::isfinite(l.gap)) {
            if (!(rate > 0.0) && !std::isfinite(l.leave)) return kNever;
            if (rate > 0.0) step = std::min(step, l.gap / rate);
            // The bound on the closing speed can be far above the real one (a slowly turning
            // corner near the ground, or one hovering just outside the contact band): then try
            // half the time the gap takes to close at its observed rate (twice the last step if
            // it does not close), and keep the jump if the gap there is still open.
            if (s > previous_s) {
                const double last = s - previous_s;
                const double closing = l.gap < previous_gap ? l.gap * last / (previous_gap - l.gap) : kNever;
                const double jump = std::min({0.5 * closing, 2.0 * last, horizon - s});
                if (jump > step) {
                    M ja = ma, jb = mb;
                    advance(&ja, jump);
                    advance(&jb, jump);
                    const Look lj = look(ja.body, jb.body, false);
                    if (!lj.lands && lj.gap > kTouch) step = jump;
                }
            }
        }
        if (s + step > horizon) return kNever;
        previous_gap = l.gap;
        previous_s = s;
        advance(&ma, step);
        advance(&mb, step);
        s += step;
    }
    return t + s;  // not converged: look again from there (never a silent miss)
}

}  // namespace collide
