#include "teach/step_output.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include <nlohmann/json.hpp>

#include "teach/event_problem.h"
#include "teach/notation.h"
#include "engine/diagnostics.h"

namespace collide {

namespace {

// What an event flagged `approximate` (engine/world.h Event) says, in its JSON and its text.
const char* const kApproximate =
    "Routh's integration of this impact could not be finished as specified; this impulse is an approximation";

// The end of an event's text line when its instant gained energy (energy_gains).
std::string gain_warning(bool energy_gain) {
    return energy_gain ? "  [kinetic energy gained, which no real impact can do: Kane's paradox of a one-step "
                         "friction model with Newton's restitution]"
                       : "";
}

// energy_gains: the events grouped by instant (equal times, consecutive).
template <class Event>
std::vector<bool> gains_of(const Scene& s, const std::vector<Event>& events) {
    std::vector<bool> out(events.size(), false);
    for (std::size_t first = 0; first < events.size();) {
        std::size_t end = first;
        std::vector<CollisionInstant> instant;
        while (end < events.size() && events[end].t == events[first].t)
            instant.push_back(collision_instant(events[end++]));
        const InstantEnergy e = instant_kinetic_energy(s, instant);
        if (gains_energy(e.before, e.after))
            std::fill(out.begin() + static_cast<long>(first), out.begin() + static_cast<long>(end), true);
        first = end;
    }
    return out;
}

using nlohmann::ordered_json;

// ---- Numbers and vectors ----

ordered_json arr(double x) { return x; }
ordered_json arr(const Vec2& v) { return ordered_json::array({v.x(), v.y()}); }
ordered_json arr(const Vec3& v) { return ordered_json::array({v.x(), v.y(), v.z()}); }
ordered_json arr(const Quat& q) { return ordered_json::array({q.w(), q.x(), q.y(), q.z()}); }

std::string txt(double x) { return notation::num_text(x); }
std::string txt(const Vec2& v) { return "(" + txt(v.x()) + ", " + txt(v.y()) + ")"; }
std::string txt(const Vec3& v) { return "(" + txt(v.x()) + ", " + txt(v.y()) + ", " + txt(v.z()) + ")"; }
std::string txt(const Quat& q) {
    return "(" + txt(q.w()) + ", " + txt(q.x()) + ", " + txt(q.y()) + ", " + txt(q.z()) + ")";
}

// ---- One body ----

ordered_json body_json(const Body1& b) { return {{"x", b.position}, {"v", b.v}}; }
ordered_json body_json(const Body2& b) {
    return {{"x", arr(b.position)}, {"v", arr(b.v)}, {"w", b.w}, {"angle", b.angle}};
}
ordered_json body_json(const Body3& b) {
    return {{"x", arr(b.position)}, {"v", arr(b.v)}, {"w", arr(b.w)}, {"orientation", arr(b.orientation)}};
}

std::string body_text(const Body1& b) { return "x " + txt(b.position) + " m   v " + txt(b.v) + " m/s"; }
std::string body_text(const Body2& b) {
    return "x " + txt(b.position) + " m   v " + txt(b.v) + " m/s   angle " + txt(b.angle) + " rad   w " + txt(b.w) +
           " rad/s";
}
std::string body_text(const Body3& b) {
    return "x " + txt(b.position) + " m   v " + txt(b.v) + " m/s   orientation " + txt(b.orientation) + "   w " +
           txt(b.w) + " rad/s";
}

template <class Body>
double potential_energy(const Scene& s, const std::vector<Body>& bodies) {
    double potential = 0.0;
    for (const Body& b : bodies) potential += potential_energy(b, s.gravity);
    return potential;
}

// ---- One state, one event ----

template <class Body>
std::string state_json_of(const Scene& s, double t, const std::vector<Body>& bodies, std::size_t only) {
    ordered_json j;
    j["t"] = t;
    ordered_json named = ordered_json::object();
    for (std::size_t i = 0; i < bodies.size(); ++i)
        if (only == kAllBodies || only == i) named[s.bodies[i].name] = body_json(bodies[i]);
    j["bodies"] = named;
    const auto sums = totals(bodies);
    j["kinetic_energy"] = sums.kinetic_energy;
    j["potential_energy"] = potential_energy(s, bodies);
    j["momentum"] = arr(sums.momentum);
    if constexpr (!std::is_same_v<Body, Body1>) j["angular_momentum"] = arr(sums.angular_momentum);
    return j.dump();
}

template <class Body>
std::string state_text_of(const Scene& s, double t, const std::vector<Body>& bodies, std::size_t only) {
    std::size_t width = 0;
    for (const SceneBody& b : s.bodies) width = std::max(width, b.name.size());
    std::ostringstream out;
    out << "t = " << txt(t) << " s\n";
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (only != kAllBodies && only != i) continue;
        out << "  " << std::left << std::setw(static_cast<int>(width)) << s.bodies[i].name << std::right << "  "
            << (bodies[i].is_static ? "static" : body_text(bodies[i])) << "\n";
    }
    if (only == kAllBodies) {
        const auto sums = totals(bodies);
        out << "  kinetic " << txt(sums.kinetic_energy) << " J   total "
            << txt(sums.kinetic_energy + potential_energy(s, bodies)) << " J   momentum " << txt(sums.momentum)
            << " N s";
        if constexpr (!std::is_same_v<Body, Body1>)
            out << "   angular momentum " << txt(sums.angular_momentum) << " kg m^2/s";
        out << "\n";
    }
    return out.str();
}

template <int D>
ordered_json velocity_json(const typename Event<D>::Velocity& u) {
    return {{"v", arr(u.v)}, {"w", arr(u.w)}};
}

// One collision as JSON, in the order every dimension writes it (point, normal and impulse:
// numbers in 1D, arrays in 2D and 3D; each body's velocities before and after).
std::string event_json_with(double t, const std::string& a, const std::string& b, ordered_json point,
                            ordered_json normal, ordered_json impulse, ordered_json before_a, ordered_json before_b,
                            ordered_json after_a, ordered_json after_b, bool energy_gain, bool approximate = false) {
    ordered_json j;
    j["t"] = t;
    j["a"] = a;
    j["b"] = b;
    j["point"] = std::move(point);
    j["normal"] = std::move(normal);
    j["impulse"] = std::move(impulse);
    j["before"] = {{a, std::move(before_a)}, {b, std::move(before_b)}};
    j["after"] = {{a, std::move(after_a)}, {b, std::move(after_b)}};
    j["energy_gain"] = energy_gain;
    if (approximate) j["approximate"] = kApproximate;  // only then: other runs print as before
    return j.dump();
}

template <int D>
std::string event_json_of(const Scene& s, const Event<D>& e, bool energy_gain) {
    return event_json_with(e.t, s.bodies[e.a].name, s.bodies[e.b].name, arr(e.point), arr(e.normal), arr(e.impulse),
                           velocity_json<D>(e.before_a), velocity_json<D>(e.before_b), velocity_json<D>(e.after_a),
                           velocity_json<D>(e.after_b), energy_gain, e.approximate);
}

template <int D>
std::string event_text_of(const Scene& s, const Event<D>& e, bool energy_gain) {
    const std::string& a = s.bodies[e.a].name;
    const std::string& b = s.bodies[e.b].name;
    const auto change = [](const std::string& name, const typename Event<D>::Velocity& before,
                           const typename Event<D>::Velocity& after) {
        return name + " v " + txt(before.v) + " -> " + txt(after.v) + " m/s, w " + txt(before.w) + " -> " +
               txt(after.w) + " rad/s";
    };
    return "t = " + txt(e.t) + " s: " + a + " hits " + b + " at " + txt(e.point) + " m, normal " + txt(e.normal) +
           ", impulse on " + b + " " + txt(e.impulse) + " N s; " + change(a, e.before_a, e.after_a) + "; " +
           change(b, e.before_b, e.after_b) + gain_warning(energy_gain) +
           (e.approximate ? std::string("  [approximate: ") + kApproximate + "]" : "");
}

// ---- The table ----

std::string fixed(double x, int width) {
    std::ostringstream o;
    o << std::setw(width) << notation::num_text(x);
    return o.str();
}

void table_header_1d(const Scene& s, std::ostream& out) {
    out << std::setw(10) << "t (s)";
    for (const SceneBody& b : s.bodies) {
        out << "  " << std::setw(12) << (b.name + ".x") << std::setw(12) << (b.name + ".v");
    }
    out << std::setw(14) << "kinetic (J)" << std::setw(14) << "total (J)" << std::setw(16) << "momentum (N s)"
        << "\n";
}

void table_row_1d(const Scene& s, double t, const std::vector<Body1>& bodies, std::ostream& out) {
    const Totals1 sums = totals(bodies);
    out << fixed(t, 10);
    for (const Body1& b : bodies) out << "  " << fixed(b.position, 12) << fixed(b.v, 12);
    out << fixed(sums.kinetic_energy, 14) << fixed(sums.kinetic_energy + potential_energy(s, bodies), 14)
        << fixed(sums.momentum, 16) << "\n";
}

// A table whose columns fit their widest entry, the components of vectors aligned too; a wider
// gap opens each body's group of columns. 2D and 3D rows are too varied for fixed widths.
class Table {
public:
    using Cell = std::vector<std::string>;  // one number, or a vector's components

    void column(const std::string& header, bool group) { columns_.push_back({header, group}); }
    void row(std::vector<Cell> cells) { rows_.push_back(std::move(cells)); }

    void write(std::ostream& out) const {
        std::vector<std::vector<std::size_t>> part(columns_.size());  // component widths
        std::vector<std::size_t> width(columns_.size());
        for (std::size_t c = 0; c < columns_.size(); ++c) {
            for (const auto& r : rows_) {
                part[c].resize(r[c].size());
                for (std::size_t k = 0; k < r[c].size(); ++k) part[c][k] = std::max(part[c][k], r[c][k].size());
            }
            width[c] = std::max(content_width(part[c]), columns_[c].header.size());
        }
        for (std::size_t c = 0; c < columns_.size(); ++c)
            out << gap(c) << std::setw(static_cast<int>(width[c])) << columns_[c].header;
        out << "\n";
        for (const auto& r : rows_) {
            for (std::size_t c = 0; c < columns_.size(); ++c) {
                out << gap(c) << std::string(width[c] - content_width(part[c]), ' ');
                if (r[c].size() == 1) {
                    out << std::setw(static_cast<int>(part[c][0])) << r[c][0];
                    continue;
                }
                for (std::size_t k = 0; k < r[c].size(); ++k)
                    out << (k ? ", " : "(") << std::setw(static_cast<int>(part[c][k])) << r[c][k];
                out << ")";
            }
            out << "\n";
        }
    }

private:
    struct Column {
        std::string header;
        bool group;
    };
    static std::size_t content_width(const std::vector<std::size_t>& parts) {
        std::size_t w = 0;
        for (std::size_t p : parts) w += p;
        return parts.size() == 1 ? w : w + 2 * parts.size();  // "(", ", " between, ")"
    }
    std::string gap(std::size_t c) const { return c == 0 ? "" : columns_[c].group ? "    " : "  "; }

    std::vector<Column> columns_;
    std::vector<std::vector<Cell>> rows_;
};

Table::Cell cell(double x) { return {txt(x)}; }
template <class V>
Table::Cell cell(const V& v) {
    Table::Cell c;
    for (int k = 0; k < v.size(); ++k) c.push_back(txt(v[k]));
    return c;
}

// Per moving body: x, v, (2D) angle, w; static bodies never move and are left out.
std::vector<Table::Cell> body_cells(const Body2& b) { return {cell(b.position), cell(b.v), cell(b.angle), cell(b.w)}; }
std::vector<Table::Cell> body_cells(const Body3& b) { return {cell(b.position), cell(b.v), cell(b.w)}; }

template <int D>
Table table_columns(const Scene& s) {
    Table table;
    table.column("t (s)", false);
    for (const SceneBody& b : s.bodies) {
        if (b.is_static()) continue;
        table.column(b.name + ".x", true);
        table.column(b.name + ".v", false);
        if (D == 2) table.column(b.name + ".angle", false);
        table.column(b.name + ".w", false);
    }
    table.column("kinetic (J)", true);
    table.column("total (J)", false);
    table.column("momentum (N s)", false);
    return table;
}

template <class Body>
std::vector<Table::Cell> table_row(const Scene& s, double t, const std::vector<Body>& bodies) {
    std::vector<Table::Cell> row{cell(t)};
    for (const Body& b : bodies) {
        if (b.is_static) continue;
        for (Table::Cell& c : body_cells(b)) row.push_back(std::move(c));
    }
    const auto sums = totals(bodies);
    row.push_back(cell(sums.kinetic_energy));
    row.push_back(cell(sums.kinetic_energy + potential_energy(s, bodies)));
    row.push_back(cell(sums.momentum));
    return row;
}

// ---- The run ----

// Runs the scene once, calling visit(t, bodies, events) at every output instant with the
// bodies there and the collisions since the previous instant.
template <int D, class Visit>
void run_steps(const Scene& s, Visit visit) {
    typename Stepping<D>::World world(s);
    std::vector<typename Stepping<D>::Event> events;
    for (double t : output_times(s)) {
        events.clear();
        world.advance_to(t, &events);
        visit(t, world.bodies(), events);
    }
}

template <int D>
void write_run(const Scene& s, const StepOptions& options, std::ostream& out) {
    const bool table = !options.events && !options.json;
    Table rows;  // 2D and 3D: written at the end, when the column widths are known
    if (table && D == 1) table_header_1d(s, out);
    if (table && D > 1) rows = table_columns<D>(s);
    run_steps<D>(s, [&](double t, const auto& bodies, const auto& events) {
        if (options.events) {
            const std::vector<bool> gains = energy_gains(s, events);
            for (std::size_t k = 0; k < events.size(); ++k)
                out << (options.json ? event_json(s, events[k], gains[k]) : event_text(s, events[k], gains[k])) << "\n";
        } else if (options.json) {
            out << state_json(s, t, bodies) << "\n";
        } else if constexpr (D == 1) {
            table_row_1d(s, t, bodies, out);
        } else {
            rows.row(table_row(s, t, bodies));
        }
    });
    if (table && D > 1) rows.write(out);
}

template <int D>
StepJson json_run(const Scene& s) {
    StepJson out;
    run_steps<D>(s, [&](double t, const auto& bodies, const auto& events) {
        const std::vector<bool> gains = energy_gains(s, events);
        for (std::size_t k = 0; k < events.size(); ++k) out.events.push_back(event_json(s, events[k], gains[k]));
        out.states.push_back(state_json(s, t, bodies));
    });
    return out;
}

}  // namespace

std::vector<double> output_times(const Scene& s) {
    // K = the duration / output_dt rounded, when that is within 1e-9 of an integer, else rounded up.
    const double steps = s.duration / s.output_dt;
    const auto K = static_cast<long>(std::abs(steps - std::round(steps)) < 1e-9 ? std::round(steps) : std::ceil(steps));
    std::vector<double> t;
    for (long k = 0; k <= K; ++k) t.push_back(std::min(s.duration, k * s.output_dt));
    return t;
}

template <class Body>
std::string state_json(const Scene& s, double t, const std::vector<Body>& b, std::size_t only) {
    return state_json_of(s, t, b, only);
}
template <class Body>
std::string state_text(const Scene& s, double t, const std::vector<Body>& b, std::size_t only) {
    return state_text_of(s, t, b, only);
}
// The bodies of the three dimensions.
template std::string state_json(const Scene&, double, const std::vector<Body1>&, std::size_t);
template std::string state_json(const Scene&, double, const std::vector<Body2>&, std::size_t);
template std::string state_json(const Scene&, double, const std::vector<Body3>&, std::size_t);
template std::string state_text(const Scene&, double, const std::vector<Body1>&, std::size_t);
template std::string state_text(const Scene&, double, const std::vector<Body2>&, std::size_t);
template std::string state_text(const Scene&, double, const std::vector<Body3>&, std::size_t);

std::string event_json(const Scene& s, const Event1& e, bool energy_gain) {
    return event_json_with(e.t, s.bodies[e.a].name, s.bodies[e.b].name, e.point, 1.0, e.impulse, {{"v", e.va_before}},
                           {{"v", e.vb_before}}, {{"v", e.va_after}}, {{"v", e.vb_after}}, energy_gain);
}
std::string event_json(const Scene& s, const Event2& e, bool gain) { return event_json_of<2>(s, e, gain); }
std::string event_json(const Scene& s, const Event3& e, bool gain) { return event_json_of<3>(s, e, gain); }

std::string event_text(const Scene& s, const Event1& e, bool energy_gain) {
    const std::string& a = s.bodies[e.a].name;
    const std::string& b = s.bodies[e.b].name;
    return "t = " + txt(e.t) + " s: " + a + " hits " + b + " at x = " + txt(e.point) + " m, impulse on " + b + " " +
           txt(e.impulse) + " N s; " + a + " v " + txt(e.va_before) + " -> " + txt(e.va_after) + " m/s, " + b + " v " +
           txt(e.vb_before) + " -> " + txt(e.vb_after) + " m/s" + gain_warning(energy_gain);
}
std::string event_text(const Scene& s, const Event2& e, bool gain) { return event_text_of<2>(s, e, gain); }
std::string event_text(const Scene& s, const Event3& e, bool gain) { return event_text_of<3>(s, e, gain); }

std::vector<bool> energy_gains(const Scene& s, const std::vector<Event1>& events) { return gains_of(s, events); }
std::vector<bool> energy_gains(const Scene& s, const std::vector<Event2>& events) { return gains_of(s, events); }
std::vector<bool> energy_gains(const Scene& s, const std::vector<Event3>& events) { return gains_of(s, events); }

void write_steps(const Scene& s, const StepOptions& options, std::ostream& out) {
    if (s.dimension == 1) write_run<1>(s, options, out);
    else if (s.dimension == 2) write_run<2>(s, options, out);
    else write_run<3>(s, options, out);
}

StepJson step_json(const Scene& s) {
    if (s.dimension == 1) return json_run<1>(s);
    if (s.dimension == 2) return json_run<2>(s);
    return json_run<3>(s);
}

}  // namespace collide
