#include "engine/penalty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/math.h"

namespace collide {

namespace {

void require(bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("penalty contact: " + what);
}

void require_ratio(double zeta) {
    require(std::isfinite(zeta) && zeta >= 0.0 && zeta < 1.0,
            "the closed forms need a damping ratio in [0, 1), got " + std::to_string(zeta));
}

}  // namespace

double penalty_effective_mass(double inv_mass_a, double inv_mass_b) {
    require(std::isfinite(inv_mass_a) && std::isfinite(inv_mass_b) && inv_mass_a >= 0 && inv_mass_b >= 0,
            "inverse masses must be finite and >= 0");
    require(inv_mass_a + inv_mass_b > 0, "both blocks are static");
    return 1.0 / (inv_mass_a + inv_mass_b);
}

double penalty_damping_ratio(double m, double k, double c) { return c / (2.0 * std::sqrt(k * m)); }

double penalty_damping(double m, double k, double zeta) { return 2.0 * zeta * std::sqrt(k * m); }

double penalty_restitution(double zeta, bool pull) {
    require_ratio(zeta);
    // Pull: the oscillation's half period, pi in wd t; no pull: it ends early, at pi - 2 asin zeta.
    const double phase = pull ? kPi : kPi - 2.0 * std::asin(zeta);
    return std::exp(-zeta * phase / std::sqrt(1.0 - zeta * zeta));
}

double penalty_contact_time(double m, double k, double zeta, bool pull) {
    require_ratio(zeta);
    const double wd = std::sqrt(k / m) * std::sqrt(1.0 - zeta * zeta);
    return (pull ? kPi : kPi - 2.0 * std::asin(zeta)) / wd;
}

double penalty_damping_ratio_for(double e, bool pull) {
    require(std::isfinite(e) && e > 0.0 && e <= 1.0, "restitution must be in (0, 1], got " + std::to_string(e));
    if (pull) {
        // e = exp(-zeta pi / sqrt(1 - zeta^2))  =>  ln e^2 (1 - zeta^2) = pi^2 zeta^2.
        const double l = std::log(e);
        return -l / std::sqrt(kPi * kPi + l * l);
    }
    require(e > std::exp(-2.0), "without pull an under-damped contact bounces with e > exp(-2) = 0.135; e = " +
                                    std::to_string(e) + " needs a damping ratio >= 1");
    // e(zeta) falls from 1 at zeta = 0 to exp(-2) as zeta -> 1: bisection.
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (penalty_restitution(mid, false) > e) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

PenaltyRun penalty_collision(const PenaltySetup& s) {
    const double m = penalty_effective_mass(s.inv_mass_a, s.inv_mass_b);
    const double k = s.stiffness, c = s.damping;
    require(std::isfinite(k) && k > 0, "the stiffness k must be > 0");
    require(std::isfinite(c) && c >= 0, "the damping c must be >= 0");
    require(std::isfinite(s.va) && std::isfinite(s.vb) && s.va > s.vb, "the blocks must approach (v_A > v_B)");
    const double t_ref = kPi * std::sqrt(m / k);  // the undamped contact time
    const double h = s.time_step > 0 ? s.time_step : t_ref / 2000.0;
    require(std::isfinite(h) && h <= t_ref, "the time step must be at most pi sqrt(m/k)");
    // A floor on the step keeps the run (and its samples) to at most 100 000 steps a contact.
    require(h >= t_ref * 1e-5, "the time step must be at least pi sqrt(m/k) / 100000");

    // State y = (delta, delta', J): delta'' = -F/m, J' = F, F = k delta + c delta'.
    using State = std::array<double, 3>;
    const auto force = [&](const State& y) { return k * y[0] + c * y[1]; };
    const auto rk4 = [&](const State& y, double dt) {
        const auto f = [&](const State& z) { return State{z[1], -force(z) / m, force(z)}; };
        const auto add = [](const State& a, const State& b, double w) {
            return State{a[0] + w * b[0], a[1] + w * b[1], a[2] + w * b[2]};
        };
        const State k1 = f(y), k2 = f(add(y, k1, dt / 2)), k3 = f(add(y, k2, dt / 2)), k4 = f(add(y, k3, dt));
        State out;
        for (int i = 0; i < 3; ++i) out[i] = y[i] + dt / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
        return out;
    };
    // The contact holds while this is > 0: the overlap (pull) or the pushing force (no pull).
    const auto holds = [&](const State& y) { return s.pull ? y[0] : force(y); };

    PenaltyRun run;
    State y{0.0, s.va - s.vb, 0.0};
    double t = 0.0;
    const auto sample = [&](const State& z) {
        run.samples.push_back({t, z[0], z[1], s.pull ? force(z) : std::max(0.0, force(z)), z[2]});
        run.peak_force = std::max(run.peak_force, force(z));
        run.max_overlap = std::max(run.max_overlap, z[0]);
    };
    sample(y);
    const int max_steps = static_cast<int>(std::ceil(100.0 * t_ref / h));
    for (int i = 0; i < max_steps; ++i) {
        const State next = rk4(y, h);
        ++run.steps;
        if (holds(next) > 0.0) {
            y = next;
            t += h;
            sample(y);
            continue;
        }
        // It lets go inside this step: bisect the step length for the instant.
        double lo = 0.0, hi = h;
        for (int j = 0; j < 80 && hi - lo > 1e-15 * h; ++j) {
            const double mid = 0.5 * (lo + hi);
            if (holds(rk4(y, mid)) > 0.0) lo = mid;
            else hi = mid;
        }
        y = rk4(y, hi);
        t += hi;
        run.separated = true;
        sample(y);
        break;
    }
    run.contact_time = t;
    run.impulse = y[2];
    run.va_after = s.va - run.impulse * s.inv_mass_a;
    run.vb_after = s.vb + run.impulse * s.inv_mass_b;
    run.restitution = (run.vb_after - run.va_after) / (s.va - s.vb);
    return run;
}

}  // namespace collide
