// Routh's method: the impact integrated over the normal impulse, with Coulomb friction
// (Routh 1860; Mirtich's thesis 1996; Stronge, "Impact Mechanics"). Conventions: response.h.
//
// An impulse increment dP changes the relative contact velocity u by K dP (K = collision_matrix,
// symmetric positive definite). The impact is followed with the normal impulse P_n as the
// (monotonic) time-like variable, dP = dP_n (n + tangential part):
//   slip   (u_t != 0): tangential part -mu s, s the unit slip direction u_t/|u_t|;
//   stick  (u_t = 0, needing |lambda| <= mu): tangential part lambda, the rate that keeps u_t = 0;
//   reverse: slip stopped but sticking would need |lambda| > mu: slip restarts, in the
//            direction the dynamics chooses (2D: the opposite one).
// Compression ends where u_n = 0 (P_n = P_c); in 3D the turning slip can make the approach
// resume (u_n < 0 again), and restitution then waits for u_n = 0 again, P_c and W_c being those
// of the deepest compression (least W). Restitution ends by the restitution law:
//   newton:  u_n' = -e un0 (can create energy with friction: Kane's paradox);
//   poisson: P_n,final = (1 + e) P_c;
//   stronge: W_r = -e^2 W_c, the works of the normal impulse W = integral of u_n dP_n over
//            restitution and compression (never creates energy).
// 2D is exact and piecewise linear in P_n (u linear in each phase, closed-form phase ends).
// 3D slip turns (s follows u_t); that phase is integrated numerically (routh.cpp states the
// tolerance); once slip stops every later phase is linear again and exact.
#pragma once

#include <string>
#include <vector>

#include "engine/response.h"

namespace collide {

enum class RestitutionLaw { newton, poisson, stronge };

// "newton" | "poisson" | "stronge"
const char* restitution_law_name(RestitutionLaw law);
// false (and *out untouched) if the name is unknown.
bool parse_restitution_law(const std::string& name, RestitutionLaw* out);

// One stretch of the impact with one slip state, over the normal impulse P_n (N s).
struct RouthPhase {
    // slip: sliding against the friction mu; stick: u_t = 0 held inside the cone;
    // reverse: slip in the opposite direction (3D: the direction the dynamics chooses) after
    // slip stopped and sticking could not hold.
    enum class Kind { slip, stick, reverse } kind = Kind::slip;
    double normal_impulse_from = 0.0, normal_impulse_to = 0.0;
};

const char* routh_phase_name(RouthPhase::Kind kind);  // "slip" | "stick" | "reverse"

struct RouthDetail {
    std::vector<RouthPhase> phases;        // in order; a phase may span compression and restitution
    double compression_impulse = 0.0;      // P_c, N s: P_n where u_n = 0 (at the deepest compression)
    double final_normal_impulse = 0.0;     // P_n at the end, N s
    double compression_work = 0.0;         // J, W_c = integral_0^P_c u_n dP_n (<= 0)
    double restitution_work = 0.0;         // J, W_r = integral_P_c^P_f u_n dP_n (>= 0)
    double energy_change = 0.0;            // J, integral of u . dP = kinetic energy after - before
    bool jammed = false;                   // 3D only: integration gave up (see routh.cpp)
    int slip_steps = 0;                    // 3D only: Taylor steps taken on the turning slip
    bool slip_end_in_closed_form = false;  // 3D only: the slip's end taken from its series
    bool slip_end_on_ray = false;          // 3D only: the slip's end taken on its ray (near the stick threshold)
    // 3D only: false if the turning slip could not be followed to its end (20000 steps) and was
    // finished along the direction it had then: the answer is then approximate, and says so
    // (collide solve's JSON "settled": false and a line in the text; the world's event).
    bool settled = true;
};

// Impact with Coulomb friction mu and restitution e by the given law. Separating or resting
// contacts (un >= 0) get no impulse (`separating`). `sliding` is set when the contact still
// slides at the end. P is the total impulse on B (A receives -P).
Response2 routh(const ImpactBody2& a, const ImpactBody2& b, const Vec2& n, double e, double mu, RestitutionLaw law,
                RouthDetail* detail = nullptr);
Response3 routh(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e, double mu, RestitutionLaw law,
                RouthDetail* detail = nullptr);

// The 3D integration's settings, for tests that check it against itself: the tolerance of its
// steps (relative to the impact's scales, see routh.cpp) and whether the slip's end is taken in
// closed form. routh() above uses these defaults.
struct RouthIntegration {
    double tolerance = 1e-11;
    bool closed_form_end = true;
    // Taylor steps of the first pass, and of the second (near the stick threshold, see
    // routh_slip.cpp): beyond the second's, the slip is finished along its direction and the
    // answer flagged (RouthDetail::settled = false).
    int first_pass_steps = 500, last_step = 20000;
};
Response3 routh(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e, double mu, RestitutionLaw law,
                const RouthIntegration& how, RouthDetail* detail = nullptr);

}  // namespace collide
