#include "cli/step.h"

#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "cli/notation.h"
#include "engine/diagnostics.h"
#include "engine/world1d.h"

namespace collide {

namespace {

using nlohmann::ordered_json;

// The output instants t = k output_dt, k = 0 .. K, with the last one at the duration exactly
// (K = the duration / output_dt rounded, when that is within 1e-9 of an integer, else rounded up).
std::vector<double> output_times(const Scene& s) {
    const double steps = s.duration / s.output_dt;
    const auto K = static_cast<long>(std::abs(steps - std::round(steps)) < 1e-9 ? std::round(steps)
                                                                               : std::ceil(steps));
    std::vector<double> t;
    for (long k = 0; k <= K; ++k) t.push_back(std::min(s.duration, k * s.output_dt));
    return t;
}

std::string fixed(double x, int width) {
    std::ostringstream o;
    o << std::setw(width) << notation::num_text(x);
    return o.str();
}

void table_header(const Scene& s, std::ostream& out) {
    out << std::setw(10) << "t (s)";
    for (const SceneBody& b : s.bodies) {
        out << "  " << std::setw(12) << (b.name + ".x") << std::setw(12) << (b.name + ".v");
    }
    out << std::setw(14) << "kinetic (J)" << std::setw(14) << "total (J)" << std::setw(16)
        << "momentum (N s)" << "\n";
}

}  // namespace

void write_steps(const Scene& s, const StepOptions& options, std::ostream& out) {
    if (s.dimension != 1)
        throw std::runtime_error("stepping " + std::to_string(s.dimension) +
                                 "D scenes is not available yet (1D scenes step today)");
    World1 world(s);
    std::vector<Event1> events;
    if (!options.events && !options.json) table_header(s, out);
    for (double t : output_times(s)) {
        const std::size_t first = events.size();
        world.advance_to(t, &events);
        if (options.events) {
            for (std::size_t k = first; k < events.size(); ++k) {
                const Event1& e = events[k];
                const std::string& a = s.bodies[e.a].name;
                const std::string& b = s.bodies[e.b].name;
                if (options.json) {
                    ordered_json j;
                    j["t"] = e.t;
                    j["a"] = a;
                    j["b"] = b;
                    j["point"] = e.point;
                    j["normal"] = 1.0;
                    j["impulse"] = e.impulse;
                    j["before"] = {{a, {{"v", e.va_before}}}, {b, {{"v", e.vb_before}}}};
                    j["after"] = {{a, {{"v", e.va_after}}}, {b, {{"v", e.vb_after}}}};
                    out << j.dump() << "\n";
                } else {
                    out << "t = " << notation::num_text(e.t) << " s: " << a << " hits " << b
                        << " at x = " << notation::num_text(e.point) << " m, impulse on " << b
                        << " " << notation::num_text(e.impulse) << " N s; " << a << " v "
                        << notation::num_text(e.va_before) << " -> " << notation::num_text(e.va_after)
                        << " m/s, " << b << " v " << notation::num_text(e.vb_before) << " -> "
                        << notation::num_text(e.vb_after) << " m/s\n";
                }
            }
            continue;
        }
        const Totals1 totals_now = totals(world.bodies());
        // Potential energy in uniform gravity, zero at x = 0: -m g . x (dynamic bodies).
        double potential = 0.0;
        for (const Body1& b : world.bodies())
            if (!b.is_static) potential -= b.mass * s.gravity.x() * b.position;
        if (options.json) {
            ordered_json j;
            j["t"] = t;
            ordered_json bodies = ordered_json::object();
            for (std::size_t i = 0; i < s.bodies.size(); ++i)
                bodies[s.bodies[i].name] = {{"x", world.bodies()[i].position}, {"v", world.bodies()[i].v}};
            j["bodies"] = bodies;
            j["kinetic_energy"] = totals_now.kinetic_energy;
            j["potential_energy"] = potential;
            j["momentum"] = totals_now.momentum;
            out << j.dump() << "\n";
        } else {
            out << fixed(t, 10);
            for (const Body1& b : world.bodies()) out << "  " << fixed(b.position, 12) << fixed(b.v, 12);
            out << fixed(totals_now.kinetic_energy, 14)
                << fixed(totals_now.kinetic_energy + potential, 14)
                << fixed(totals_now.momentum, 16) << "\n";
        }
    }
}

}  // namespace collide
