// Computes a collision with the engine's functions and records each intermediate quantity of
// the worked example. No formula is written here: every number comes from engine/.
#include "teach/solve.h"

#include <type_traits>

#include "engine/diagnostics.h"
#include "engine/respond.h"

namespace collide {

namespace {

// engine/math.h's lift under one name for the templates below, whose doubles are 2D spins.
Vec3 embed(const Vec2& v) { return lift(v); }
Vec3 embed(double w) { return lift_spin(w); }
Vec3 embed(const Vec3& v) { return v; }
Mat3 embed(const Mat2& m) {
    Mat3 out = Mat3::Zero();
    out.topLeftCorner<2, 2>() = m;
    return out;
}
Mat3 embed(const Mat3& m) { return m; }
Mat3 embed_inertia(double I) { return Vec3(0.0, 0.0, I).asDiagonal(); }
Mat3 embed_inertia(const Mat3& I) { return I; }
Combined3 embed(const Combined2& c) {
    return {c.M, embed(c.xc), embed(c.da), embed(c.db), embed_inertia(c.I), embed(c.v), embed(c.L), embed(c.w)};
}
const Combined3& embed(const Combined3& c) { return c; }

// A 2D body as a 3D one moving in the xy plane (for the page's 3D listing): every torque is
// along z, so an isotropic inertia equal to the 2D moment acts exactly like it.
ImpactBody3 as_3d(const ImpactBody2& b) {
    ImpactBody3 o;
    o.inv_m = b.inv_m;
    o.inv_I = Mat3::Identity() * b.inv_I;
    o.I = Mat3::Identity() * b.I;
    o.r = embed(b.r);
    o.v = embed(b.v);
    o.w = embed(b.w);
    return o;
}
const ImpactBody3& as_3d(const ImpactBody3& b) { return b; }

// The 2D and 3D computations are the same sequence of (overloaded) engine calls.
template <class IB, class V>
void compute(const IB& a, const IB& b, const V& n, const SolveProblem& P, Solution* s) {
    const double e = P.restitution, mu = P.friction;
    s->ra = embed(a.r);
    s->rb = embed(b.r);
    s->vpa = embed(point_velocity(a));
    s->vpb = embed(point_velocity(b));
    s->u = embed(relative_velocity(a, b));
    s->un = s->u.dot(s->n);
    s->inv_ma = a.inv_m;
    s->inv_mb = b.inv_m;
    s->rot_a = rotational_term(a, n);
    s->rot_b = rotational_term(b, n);
    s->inv_Ia = embed_inertia(a.inv_I);
    s->inv_Ib = embed_inertia(b.inv_I);
    s->Ia = embed_inertia(a.I);
    s->Ib = embed_inertia(b.I);
    const auto K = collision_matrix(a, b);
    s->K = embed(K);
    const auto u = relative_velocity(a, b);
    s->P_stick = embed(sticking_impulse(K, u, n, e));
    const auto t = slip_direction(K, u, n);
    s->slip = embed(t);
    s->slide_denominator = sliding_denominator(K, n, t, mu);
    if (!a.is_static() && !b.is_static()) s->combined = embed(combined_body(a, b));
    s->listing = page::listing(as_3d(a), as_3d(b), embed(n), e);

    // The page's listing is filled from s->listing by solve(): its P is the page's J.
    if (P.model != Model::page_listing) {
        const auto r = respond(P.model, a, b, n, e, mu, P.restitution_law, &s->routh);
        s->separating = r.separating;
        s->sliding = r.sliding;
        if constexpr (!std::is_same_v<decltype(r), Response1>) {
            s->painleve = r.painleve;
            s->approximate = r.approximate;
        }
        s->P = embed(r.P);
        s->couple = embed(r.couple);
        s->va = embed(r.va);
        s->wa = embed(r.wa);
        s->vb = embed(r.vb);
        s->wb = embed(r.wb);
    }
}

template <class Body>
void set_velocity(Body* body, const Vec3& v, const Vec3& w);
template <>
void set_velocity(Body1* body, const Vec3& v, const Vec3&) {
    body->v = v.x();
}
template <>
void set_velocity(Body2* body, const Vec3& v, const Vec3& w) {
    body->v = v.head<2>();
    body->w = w.z();
}
template <>
void set_velocity(Body3* body, const Vec3& v, const Vec3& w) {
    body->v = v;
    body->w = w;
}

// The relative contact velocity after the impulse, and the checks with the engine's
// diagnostics on copies of the bodies, before and after.
void after_impulse(const SolveProblem& P, Solution* out) {
    Solution& s = *out;
    s.u_after = (s.vb + s.wb.cross(s.rb)) - (s.va + s.wa.cross(s.ra));
    s.un_after = s.u_after.dot(s.n);
    SolveBody a = P.a, b = P.b;
    auto check = [&](Vec3* p, Vec3* L, Vec3* Lp, double* ke) {
        if (P.dimension == 3) {
            const std::vector<Body3> bodies = {a.b3, b.b3};
            const Totals3 t = totals(bodies, P.about), tp = totals(bodies, P.point);
            *p = t.momentum;
            *L = t.angular_momentum;
            *Lp = tp.angular_momentum;
            *ke = t.kinetic_energy;
        } else if (P.dimension == 2) {
            const std::vector<Body2> bodies = {a.b2, b.b2};
            const Totals2 t = totals(bodies, P.about.head<2>()), tp = totals(bodies, P.point.head<2>());
            *p = embed(t.momentum);
            *L = embed(t.angular_momentum);
            *Lp = embed(tp.angular_momentum);
            *ke = t.kinetic_energy;
        } else {
            const Totals1 t = totals(std::vector<Body1>{a.b1, b.b1});
            *p = Vec3(t.momentum, 0, 0);
            *ke = t.kinetic_energy;
        }
    };
    check(&s.p_before, &s.L_before, &s.Lp_before, &s.ke_before);
    set_velocity(&a.b1, s.va, s.wa);
    set_velocity(&b.b1, s.vb, s.wb);
    set_velocity(&a.b2, s.va, s.wa);
    set_velocity(&b.b2, s.vb, s.wb);
    set_velocity(&a.b3, s.va, s.wa);
    set_velocity(&b.b3, s.vb, s.wb);
    check(&s.p_after, &s.L_after, &s.Lp_after, &s.ke_after);
}

}  // namespace

Solution solve(const SolveProblem& P) {
    Solution s;
    s.dim = P.dimension;
    s.n = P.normal;
    const double e = P.restitution;
    if (P.dimension == 3) {
        const ImpactBody3 a = at_contact(P.a.b3, P.point), b = at_contact(P.b.b3, P.point);
        compute(a, b, P.normal, P, &s);
        if (P.model == Model::stick && !a.is_static() && !b.is_static()) {
            const Response3 direct = stick(a, b, P.normal), ne = stick_newton_euler(a, b, P.normal);
            s.newton_euler_difference = std::max({(direct.va - ne.va).norm(), (direct.vb - ne.vb).norm(),
                                                  (direct.wa - ne.wa).norm(), (direct.wb - ne.wb).norm()});
        }
    } else if (P.dimension == 2) {
        const ImpactBody2 a = at_contact(P.a.b2, P.point.head<2>()), b = at_contact(P.b.b2, P.point.head<2>());
        compute(a, b, Vec2(P.normal.head<2>()), P, &s);
    } else {
        const ImpactBody1 a = at_contact(P.a.b1), b = at_contact(P.b.b1);
        const double n = P.normal.x();
        s.inv_ma = a.inv_m;
        s.inv_mb = b.inv_m;
        s.vpa = Vec3(a.v, 0, 0);
        s.vpb = Vec3(b.v, 0, 0);
        s.u = s.vpb - s.vpa;
        s.un = s.u.x() * n;
        s.K = Mat3::Identity() * (a.inv_m + b.inv_m);
        double& M = s.combined.M;
        M = (a.is_static() || b.is_static()) ? 0.0 : 1.0 / a.inv_m + 1.0 / b.inv_m;
        if (M > 0) s.combined.v = Vec3((a.v / a.inv_m + b.v / b.inv_m) / M, 0, 0);
        const page::Listing1 L = page::listing(a, b, n, e);
        s.listing.scalar = L.scalar;
        s.listing.Jmod = L.Jmod;
        s.listing.J = Vec3(L.J, 0, 0);
        s.listing.vaf = Vec3(L.vaf, 0, 0);
        s.listing.vbf = Vec3(L.vbf, 0, 0);
        // coulomb, matrix and routh have no tangent on a line: they are the frictionless formula.
        const Response1 r = P.model == Model::stick ? stick(a, b, n) : frictionless(a, b, n, e);
        if (P.model != Model::page_listing) {
            s.separating = r.separating;
            s.P = Vec3(r.P, 0, 0);
            s.va = Vec3(r.va, 0, 0);
            s.vb = Vec3(r.vb, 0, 0);
        }
    }
    if (P.model == Model::page_listing) {
        s.P = s.listing.J;  // the page's J; the listing applies -J/ma to A and -J/mb to B
        s.va = s.listing.vaf;
        s.vb = s.listing.vbf;
        s.wa = P.dimension == 1 ? Vec3::Zero() : s.listing.waf;
        s.wb = P.dimension == 1 ? Vec3::Zero() : s.listing.wbf;
        if (P.dimension == 2) {  // the 2D motion keeps only the z spin
            s.wa = Vec3(0, 0, s.wa.z());
            s.wb = Vec3(0, 0, s.wb.z());
        }
    }
    after_impulse(P, &s);
    return s;
}

Solution with_outcome(const SolveProblem& P, Solution s, const Vec3& impulse, const Vec3& va, const Vec3& wa,
                      const Vec3& vb, const Vec3& wb) {
    s.P = impulse;
    s.va = va;
    s.wa = wa;
    s.vb = vb;
    s.wb = wb;
    after_impulse(P, &s);
    return s;
}

}  // namespace collide
