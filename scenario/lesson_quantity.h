// The quantities a lesson's question can ask for (docs/formats/lesson-files.md), and what each one is:
// its name in lesson files, its unit, what the question must name (a collision, a body, a
// point), and how its answer reads out. Adding one means adding its enumerator below, its entry
// in quantity_info() and its case in the answer (teach/answers.cpp): both are switches without
// a default, so the compiler (-Wswitch, an error under COLLIDE_WERROR) names any that is missing.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace collide {

// Static bodies count in none of the totals. "Event" quantities are of one collision, named by
// the question's `event` (or `pair` and `collision`); "body" ones of the body it names.
enum class Quantity {
    impulse,                 // event: P, the impulse on b
    impulse_normal,          // event: j = P . n
    slip_stop_impulse,       // event, model routh: the normal impulse P_n at which the contact
                             // point's slip stops (engine/routh.h); an error when it never stops
    velocity_before,         // event, body
    velocity_after,          // event, body
    spin_before,             // event, body
    spin_after,              // event, body
    point_velocity_before,   // event, body: vp = v + w x (p - x) of the body's point p, the
    point_velocity_after,    // contact point unless the question gives `at` (a world point at
                             // the collision instant)
    normal_velocity_before,  // event: the relative normal velocity of the contact points,
    normal_velocity_after,   // u_n = ((vb + wb x rb) - (va + wa x ra)) . n, negative while approaching
    momentum_before,         // event: the two bodies' total linear momentum
    momentum_after,
    angular_momentum_before,       // event: the two bodies' total angular momentum about a fixed point,
    angular_momentum_after,        // the origin unless the question gives `about`: sum of I w + (x - o) x m v
    spin_angular_momentum_before,  // event, body: I w, the body's angular momentum about its own
    spin_angular_momentum_after,   // centre of mass
    kinetic_energy_before,         // event: the two bodies'
    kinetic_energy_after,
    energy_lost,  // event: kinetic_energy_before - kinetic_energy_after
    time,         // event: when it happens
    collisions,   // the count over the run
    last_collision_time,
    final_velocity,        // body, at the end of the run
    final_spin,            // body, at the end of the run
    final_kinetic_energy,  // every body's, at the end of the run
    // With a [penalty] table: the first collision with the penalty contact matched to its e (no
    // pull; teach/lesson_penalty.h).
    penalty_damping_ratio,
    penalty_damping,
    penalty_contact_time,
    penalty_peak_force,
    penalty_max_overlap,
    penalty_impulse,
    penalty_restitution,
};

// How an answer reads out (lesson.md, worksheets and their key.json).
enum class Readout {
    number,  // one number: "0.6 J"
    vector,  // a vector in 2D and 3D ("(0.9, 0.1) m/s"), its x component in 1D; an angular one
             // is a number in 2D (its z component, counter-clockwise +)
    count,   // a whole number, marked exactly: no tolerance is shown for it
};

// The point a question may give for its quantity (none: the key is refused).
enum class QuantityPoint {
    none,
    at,     // `at`: a point of the body (default: the contact point)
    about,  // `about`: the fixed point the angular momentum is taken about (default: the origin)
};

// One quantity's entry, written by name in quantity_info():
//   QuantityInfo("spin_after", "rad/s").of_collision().of_body().angular().reads(Readout::vector)
struct QuantityInfo {
    const char* name = nullptr;  // as lesson files write it; null: not a quantity
    const char* unit = "";       // "" for a pure number
    bool needs_event = false;    // of one collision (`event`, or `pair` and `collision`; the
                                 // worksheet works that collision out); else of the whole run
    bool needs_body = false;     // of the body the question names (`body`)
    bool angular = false;        // about turning: none in 1D, a number (z) in 2D
    bool needs_penalty = false;  // answered by the [penalty] contact: the lesson needs that table
    QuantityPoint point = QuantityPoint::none;
    Readout readout = Readout::number;

    constexpr QuantityInfo() = default;
    constexpr QuantityInfo(const char* file_name, const char* unit_text) : name(file_name), unit(unit_text) {}
    constexpr QuantityInfo of_collision() const { return with(&QuantityInfo::needs_event); }
    constexpr QuantityInfo of_body() const { return with(&QuantityInfo::needs_body); }
    constexpr QuantityInfo turning() const { return with(&QuantityInfo::angular); }
    constexpr QuantityInfo of_penalty() const { return with(&QuantityInfo::needs_penalty); }
    constexpr QuantityInfo takes(QuantityPoint p) const {
        QuantityInfo q = *this;
        q.point = p;
        return q;
    }
    constexpr QuantityInfo reads(Readout r) const {
        QuantityInfo q = *this;
        q.readout = r;
        return q;
    }

private:
    constexpr QuantityInfo with(bool QuantityInfo::*flag) const {
        QuantityInfo q = *this;
        q.*flag = true;
        return q;
    }
};

// The catalogue. No default: a new enumerator without its entry does not compile (the
// warning is made an error here, in builds without COLLIDE_WERROR too). A value that is no
// enumerator gives the empty entry (name null), which ends all_quantities().
#pragma GCC diagnostic push
#pragma GCC diagnostic error "-Wswitch"
constexpr QuantityInfo quantity_info(Quantity quantity) {
    using Q = Quantity;
    using I = QuantityInfo;
    constexpr Readout vector = Readout::vector;
    constexpr QuantityPoint at = QuantityPoint::at, about = QuantityPoint::about;
    switch (quantity) {
        case Q::impulse: return I("impulse", "N s").of_collision().reads(vector);
        case Q::impulse_normal: return I("impulse_normal", "N s").of_collision();
        case Q::slip_stop_impulse: return I("slip_stop_impulse", "N s").of_collision();
        case Q::velocity_before: return I("velocity_before", "m/s").of_collision().of_body().reads(vector);
        case Q::velocity_after: return I("velocity_after", "m/s").of_collision().of_body().reads(vector);
        case Q::spin_before: return I("spin_before", "rad/s").of_collision().of_body().turning().reads(vector);
        case Q::spin_after: return I("spin_after", "rad/s").of_collision().of_body().turning().reads(vector);
        case Q::point_velocity_before:
            return I("point_velocity_before", "m/s").of_collision().of_body().takes(at).reads(vector);
        case Q::point_velocity_after:
            return I("point_velocity_after", "m/s").of_collision().of_body().takes(at).reads(vector);
        case Q::normal_velocity_before: return I("normal_velocity_before", "m/s").of_collision();
        case Q::normal_velocity_after: return I("normal_velocity_after", "m/s").of_collision();
        case Q::momentum_before: return I("momentum_before", "kg m/s").of_collision().reads(vector);
        case Q::momentum_after: return I("momentum_after", "kg m/s").of_collision().reads(vector);
        case Q::angular_momentum_before:
            return I("angular_momentum_before", "kg m^2/s").of_collision().turning().takes(about).reads(vector);
        case Q::angular_momentum_after:
            return I("angular_momentum_after", "kg m^2/s").of_collision().turning().takes(about).reads(vector);
        case Q::spin_angular_momentum_before:
            return I("spin_angular_momentum_before", "kg m^2/s").of_collision().of_body().turning().reads(vector);
        case Q::spin_angular_momentum_after:
            return I("spin_angular_momentum_after", "kg m^2/s").of_collision().of_body().turning().reads(vector);
        case Q::kinetic_energy_before: return I("kinetic_energy_before", "J").of_collision();
        case Q::kinetic_energy_after: return I("kinetic_energy_after", "J").of_collision();
        case Q::energy_lost: return I("energy_lost", "J").of_collision();
        case Q::time: return I("time", "s").of_collision();
        case Q::collisions: return I("collisions", "").reads(Readout::count);
        case Q::last_collision_time: return I("last_collision_time", "s");
        case Q::final_velocity: return I("final_velocity", "m/s").of_body().reads(vector);
        case Q::final_spin: return I("final_spin", "rad/s").of_body().turning().reads(vector);
        case Q::final_kinetic_energy: return I("final_kinetic_energy", "J");
        case Q::penalty_damping_ratio: return I("penalty_damping_ratio", "").of_penalty();
        case Q::penalty_damping: return I("penalty_damping", "N s/m").of_penalty();
        case Q::penalty_contact_time: return I("penalty_contact_time", "s").of_penalty();
        case Q::penalty_peak_force: return I("penalty_peak_force", "N").of_penalty();
        case Q::penalty_max_overlap: return I("penalty_max_overlap", "m").of_penalty();
        case Q::penalty_impulse: return I("penalty_impulse", "N s").of_penalty();
        case Q::penalty_restitution: return I("penalty_restitution", "").of_penalty();
    }
    return I();
}
#pragma GCC diagnostic pop

// How many quantities there are: the enumerators run from 0 up, each with its entry.
constexpr std::size_t quantity_count() {
    std::size_t n = 0;
    while (quantity_info(static_cast<Quantity>(n)).name) ++n;
    return n;
}

// Every quantity, in the enumeration's order.
const std::vector<Quantity>& all_quantities();
// Its name in lesson files ("spin_after").
constexpr const char* quantity_name(Quantity quantity) { return quantity_info(quantity).name; }
// The quantity a lesson file names; none for a name that is no quantity's.
std::optional<Quantity> quantity_named(const std::string& name);
// Every quantity's name, sorted (as the reader lists them in its messages).
const std::vector<std::string>& lesson_quantities();

}  // namespace collide
