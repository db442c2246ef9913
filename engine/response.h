// Collision response: one function per model, in 1D, 2D and 3D (docs/conventions.md).
//
//   n      unit contact normal, from A into B (1D: +1 or -1)
//   ra, rb contact point relative to each centre of mass, world frame
//   u      relative contact-point velocity (vb + wb x rb) - (va + wa x ra); un = u.n
//   P      impulse: +P on B, -P on A, applied at the contact point
//   e      Newton's coefficient of restitution, mu Coulomb's friction coefficient
//
// Approaching contacts have un < 0. Separating or resting contacts (un >= 0) get no impulse in
// every model (except the page's listing, which is transcribed as written).
//
// The 2D and 3D functions are kept parallel on purpose: the angular term is a scalar in 2D
// and a tensor product in 3D, and a reader should see each.
#pragma once

#include <string>

#include "engine/body.h"

namespace collide {

// routh: the impact integrated over the normal impulse with Coulomb friction (engine/routh.h),
// ended by a restitution law.
enum class Model { frictionless, coulomb, matrix, stick, page_listing, routh };

const char* model_name(Model m);
// "frictionless" | "coulomb" | "matrix" | "stick" | "page-listing" | "routh"; false if unknown.
bool parse_model(const std::string& name, Model* out);

struct Response1 {
    double P = 0.0;  // impulse on B along +x, N s (A receives -P)
    bool separating = false;
    double va = 0.0, vb = 0.0;  // after, m/s
};

struct Response2 {
    Vec2 P = Vec2::Zero();  // impulse on B, N s (A receives -P), at the contact point
    double couple = 0.0;    // angular impulse on B beyond rb x P (stick only), N m s
    bool separating = false;
    bool sliding = false;                       // coulomb: the sticking impulse left the friction cone
    bool painleve = false;                      // coulomb: no one-step answer with friction (see coulomb())
    bool approximate = false;                   // routh: see Response3
    Vec2 va = Vec2::Zero(), vb = Vec2::Zero();  // after, m/s
    double wa = 0.0, wb = 0.0;                  // after, rad/s
};

struct Response3 {
    Vec3 P = Vec3::Zero();       // impulse on B, N s (A receives -P), at the contact point
    Vec3 couple = Vec3::Zero();  // angular impulse on B beyond rb x P (stick only), N m s
    bool separating = false;
    bool sliding = false;
    bool painleve = false;
    // routh: the impact could not be integrated to its end as specified (RouthDetail::settled
    // false, or jammed): this answer is an approximation, and every output says so.
    bool approximate = false;
    Vec3 va = Vec3::Zero(), vb = Vec3::Zero();
    Vec3 wa = Vec3::Zero(), wb = Vec3::Zero();
};

// ---- Building blocks (each formula once; the worked examples print these same terms) ----

// u = (vb + wb x rb) - (va + wa x ra)
Vec3 relative_velocity(const ImpactBody3& a, const ImpactBody3& b);
Vec2 relative_velocity(const ImpactBody2& a, const ImpactBody2& b);

// Rotational term of the frictionless denominator for one body: (r x n) . I^-1 (r x n).
double rotational_term(const ImpactBody3& body, const Vec3& n);
// 2D: (r x n)^2 / I with the scalar cross product r x n = rx ny - ry nx.
double rotational_term(const ImpactBody2& body, const Vec2& n);

// Collision matrix K = (1/ma + 1/mb) E - [ra]x Ia^-1 [ra]x - [rb]x Ib^-1 [rb]x.
// An impulse P changes u by K P. K is symmetric positive definite whenever one body is dynamic.
Mat3 collision_matrix(const ImpactBody3& a, const ImpactBody3& b);
// 2D: K = (1/ma + 1/mb) E + perp(ra) perp(ra)^T / Ia + perp(rb) perp(rb)^T / Ib.
Mat2 collision_matrix(const ImpactBody2& a, const ImpactBody2& b);

// Velocities after the impulse P (+P on B, -P on A, at the contact point) and couple C
// (+C on B, -C on A):
//   va' = va - P/ma, wa' = wa - Ia^-1 (ra x P + C), vb' = vb + P/mb, wb' = wb + Ib^-1 (rb x P + C)
void apply_impulse(const ImpactBody3& a, const ImpactBody3& b, Response3* r);
void apply_impulse(const ImpactBody2& a, const ImpactBody2& b, Response2* r);

// The answer to a separating or resting contact (un >= 0): no impulse, every velocity as it
// was, `separating` set. Every model returns it there.
Response3 unchanged(const ImpactBody3& a, const ImpactBody3& b);
Response2 unchanged(const ImpactBody2& a, const ImpactBody2& b);

// ---- The models ----

// Frictionless, Newton restitution (the page's general case, with its sign errors corrected):
//   j = -(1 + e) un / (1/ma + 1/mb + (ra x n).Ia^-1(ra x n) + (rb x n).Ib^-1(rb x n)), P = j n.
Response3 frictionless(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e);
Response2 frictionless(const ImpactBody2& a, const ImpactBody2& b, const Vec2& n, double e);
// 1D: r = 0, j = -(1 + e) un / (1/ma + 1/mb), un = (vb - va) n.
Response1 frictionless(const ImpactBody1& a, const ImpactBody1& b, double n, double e);

// Coulomb friction mu, one step. First the sticking impulse P = K^-1 (-e un n - u) (tangential
// slip stopped, normal velocity reversed by e). If it lies in the cone |Pt| <= mu Pn it is the
// answer; otherwise the contact slides: P = j (n - mu t), t the unit direction of the initial
// tangential slip, j = -(1 + e) un / (n . K (n - mu t)). mu = 0 gives the frictionless impulse.
// Beyond the model: when n . K (n - mu t) <= 0 (large mu with a strongly coupled K, a
// Painleve-like configuration the one-step model cannot resolve), the sticking impulse is kept
// if it pushes (P.n >= 0), else the frictionless impulse is used and `painleve` is set; the
// impulse never pulls.
Response3 coulomb(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e, double mu);
Response2 coulomb(const ImpactBody2& a, const ImpactBody2& b, const Vec2& n, double e, double mu);

// Sticking impulse P = K^-1 (-e un n - u) (the first step of coulomb).
Vec3 sticking_impulse(const Mat3& K, const Vec3& u, const Vec3& n, double e);
Vec2 sticking_impulse(const Mat2& K, const Vec2& u, const Vec2& n, double e);
// Denominator of the sliding impulse, n . K (n - mu t) (see coulomb()).
double sliding_denominator(const Mat3& K, const Vec3& n, const Vec3& t, double mu);
double sliding_denominator(const Mat2& K, const Vec2& n, const Vec2& t, double mu);
// Direction of tangential slip t used by the sliding impulse (see coulomb()).
Vec3 slip_direction(const Mat3& K, const Vec3& u, const Vec3& n);
Vec2 slip_direction(const Mat2& K, const Vec2& u, const Vec2& n);

// The page's matrix method: (e + 1) times the whole relative velocity is reversed,
// K P = -(1 + e) u, so P = -(1 + e) K^-1 u. A "rough" (superball) collision, not the
// frictionless one. K is symmetric positive definite, so Cholesky inverts it. n only decides
// whether the bodies approach (un < 0).
Response3 matrix(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e);
Response2 matrix(const ImpactBody2& a, const ImpactBody2& b, const Vec2& n, double e);

// Perfectly inelastic: the bodies continue as one rigid body. Combined mass M, centre xc,
// inertia about xc by the parallel-axis theorem; v = total momentum / M, w = I^-1 L with L the
// total angular momentum about xc; each body then moves with that rigid motion. Needs only r
// (centres are at p - r). n only decides whether the bodies approach (un < 0).
Response3 stick(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n);
// The welded pair as one rigid body, positions relative to the contact point p (two dynamic
// bodies): M = ma + mb, xc = (ma xa + mb xb) / M, I = sum (Ii + mi (|di|^2 E - di di^T)) with
// di = xi - xc, v = (ma va + mb vb) / M, L = sum (Ii wi + mi di x vi), w = I^-1 L.
struct Combined3 {
    double M = 0.0;
    Vec3 xc = Vec3::Zero(), da = Vec3::Zero(), db = Vec3::Zero();
    Mat3 I = Mat3::Zero();
    Vec3 v = Vec3::Zero(), L = Vec3::Zero(), w = Vec3::Zero();
};
Combined3 combined_body(const ImpactBody3& a, const ImpactBody3& b);
struct Combined2 {
    double M = 0.0;
    Vec2 xc = Vec2::Zero(), da = Vec2::Zero(), db = Vec2::Zero();
    double I = 0.0;
    Vec2 v = Vec2::Zero();
    double L = 0.0, w = 0.0;
};
Combined2 combined_body(const ImpactBody2& a, const ImpactBody2& b);
Response2 stick(const ImpactBody2& a, const ImpactBody2& b, const Vec2& n);
Response1 stick(const ImpactBody1& a, const ImpactBody1& b, double n);

// The same as stick(), computed as on the page with 6x6 Newton-Euler (spatial inertia)
// matrices, all taken about the contact point p:
//   NEM = [ Ip  [h]x ; [h]x^T  m E ],  h = m (x - p),  Ip = I + m ([c]x [c]x^T), c = x - p,
// acting on the 6-vector (w, v_p) of the body's motion at p. Then
//   (NEMa + NEMb) V = NEMa Va + NEMb Vb.
Response3 stick_newton_euler(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n);
// Newton-Euler matrix of one body about the contact point.
Mat6 newton_euler_matrix(const ImpactBody3& body);

}  // namespace collide
