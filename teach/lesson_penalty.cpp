#include "teach/lesson_penalty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "teach/html.h"
#include "scenario/input_error.h"
#include "teach/notation.h"

namespace collide {

namespace {

std::string n(double x) { return notation::num_text(std::abs(x) < 1e-15 ? 0.0 : x); }

PenaltyRun run(const PenaltyStudy& s, const Lesson& L, double inv_a, double inv_b, double damping, bool pull,
               double stiffness = 0.0) {
    PenaltySetup p;
    p.inv_mass_a = inv_a;
    p.inv_mass_b = inv_b;
    p.va = s.va;
    p.vb = s.vb;
    p.stiffness = stiffness > 0 ? stiffness : s.stiffness;
    p.damping = damping;
    p.pull = pull;
    p.time_step = L.penalty->time_step;
    try {
        return penalty_collision(p);
    } catch (const std::invalid_argument& e) {
        throw InputError(L.file, L.penalty->step_pos, L.penalty->step_key, e.what());
    }
}

// The lines shared by the Markdown and the HTML: the impulse, then the matched spring.
std::vector<std::string> summary(const PenaltyStudy& s) {
    const PenaltyRun& r = s.matched;
    const double tc = penalty_contact_time(s.mass, s.stiffness, s.zeta, false);
    return {
        "The first collision: " + s.a + " on " + s.b + " at t = " + n(s.time) + " s, with m = 1 / (1/m_A + 1/m_B) = " +
            n(s.mass) + " kg, approach speed v_0 = " + n(s.va - s.vb) + " m/s and e = " + n(s.restitution) + ".",
        "The impulse model: P = (1 + e) m v_0 = " + n(s.impulse) + " N s, all at one instant; " + s.a + " leaves at " +
            n(s.va_after) + " m/s, " + s.b + " at " + n(s.vb_after) + " m/s.",
        "The penalty contact: a spring k = " + n(s.stiffness) + " N/m and a damper. For e = " + n(s.restitution) +
            " without pull, ζ = " + n(s.zeta) +
            " (solving e = exp(−ζ (π − 2 asin ζ) / √(1 − ζ²))), so c = 2 ζ √(k m) = " + n(s.damping) + " N s/m.",
        "Integrated (Runge-Kutta, " + std::to_string(r.steps) + " steps): the contact lasts " +
            n(r.contact_time * 1e3) + " ms (the formula (π − 2 asin ζ) / ω_d: " + n(tc * 1e3) +
            " ms), pushes with at most " + n(r.peak_force) + " N and goes " + n(r.max_overlap * 1e3) +
            " mm deep. Its impulse ∫F dt = " + n(r.impulse) + " N s; " + s.a + " leaves at " + n(r.va_after) +
            " m/s, " + s.b + " at " + n(r.vb_after) + " m/s: e = " + n(r.restitution) + ".",
    };
}

std::string stiffness_intro(const PenaltyStudy& s) {
    return "The stiffness does not change e: the same ζ = " + n(s.zeta) +
           " at each k (so c = 2 ζ √(k m) grows with √k). A stiffer spring gives the same bounce in a shorter, "
           "harder and shallower contact: contact time and depth go as 1 / √k, the peak force as √k.";
}

const char* kColours[] = {"#1d4ed8", "#0f766e", "#b45309", "#7c3aed", "#4b5563", "#0891b2", "#65a30d"};

}  // namespace

PenaltyStudy penalty_study(const Lesson& L, const AnyRecording& record) {
    if (!L.penalty) throw InputError(L.file, {}, "penalty", "the lesson has no [penalty] table");
    const Scene& scene = L.scene;
    const Recording<1>* line = std::get_if<Recording<1>>(&record);
    if (!line) throw std::invalid_argument("penalty_study: the [penalty] contact is 1D, the recording is not");
    if (line->events.empty())
        throw InputError(L.file, L.penalty->pos, "penalty",
                         "the run has no collision for the penalty contact to replay");
    const Event1& e = line->events.front();
    PenaltyStudy s;
    s.a = scene.bodies[e.a].name;
    s.b = scene.bodies[e.b].name;
    s.time = e.t;
    const double inv_a = scene.bodies[e.a].body1.inv_mass(), inv_b = scene.bodies[e.b].body1.inv_mass();
    s.mass = penalty_effective_mass(inv_a, inv_b);
    s.va = e.va_before;
    s.vb = e.vb_before;
    s.restitution = scene.pair_restitution(e.a, e.b);
    if (scene.model == Model::stick) s.restitution = 0.0;
    s.impulse = e.impulse;
    s.va_after = e.va_after;
    s.vb_after = e.vb_after;
    s.stiffness = L.penalty->stiffness;
    if (!(s.restitution > std::exp(-2.0)))
        throw InputError(L.file, L.penalty->pos, "penalty",
                         "the first collision has e = " + n(s.restitution) +
                             "; a spring-damper that only pushes matches e > exp(-2) = 0.135 (under-damped)");
    s.zeta = penalty_damping_ratio_for(s.restitution, false);
    s.damping = penalty_damping(s.mass, s.stiffness, s.zeta);
    s.matched = run(s, L, inv_a, inv_b, s.damping, false);
    for (double z : L.penalty->damping_ratios) {
        PenaltyStudy::Row row;
        row.zeta = z;
        row.damping = penalty_damping(s.mass, s.stiffness, z);
        row.e_push = penalty_restitution(z, false);
        row.e_pull = penalty_restitution(z, true);
        row.push = run(s, L, inv_a, inv_b, row.damping, false);
        row.pull = run(s, L, inv_a, inv_b, row.damping, true);
        s.rows.push_back(std::move(row));
    }
    // The time step is the table's for every stiffness (when set): a stiffer spring with the
    // same step shows the step's error growing.
    for (double k : L.penalty->stiffnesses) {
        PenaltyStudy::Stiff st;
        st.stiffness = k;
        st.damping = penalty_damping(s.mass, k, s.zeta);
        st.run = run(s, L, inv_a, inv_b, st.damping, false, k);
        s.stiffer.push_back(std::move(st));
    }
    return s;
}

namespace {

// One plot of the runs without pull (the table's damping ratios, then the matched spring in
// red) against time in ms, every run on one grid. After the blocks let go the force is 0; the
// overlap (coast) shrinks on at the parting speed until the blocks are apart: a damped spring
// lets go while they still overlap (its damper would have to pull).
std::string plot_runs(const PenaltyStudy& s, const std::string& title, double PenaltySample::*field, double scale,
                      bool coast) {
    std::vector<const PenaltyRun*> runs;
    for (const PenaltyStudy::Row& r : s.rows) runs.push_back(&r.push);
    runs.push_back(&s.matched);
    double end = 0;
    for (const PenaltyRun* r : runs) end = std::max(end, r->contact_time);
    // The time axis ends on a round number of ms a little after the longest contact.
    const double step = std::pow(10.0, std::floor(std::log10(end * 1.05e3))) / 5;
    end = std::ceil(end * 1.05e3 / step) * step / 1e3;
    const int N = 600;
    std::vector<double> t(N + 1);
    for (int i = 0; i <= N; ++i) t[i] = end * i / N;
    const auto value_at = [&](const PenaltyRun& r, double time) {
        const auto& p = r.samples;
        if (p.empty()) return 0.0;
        if (time >= p.back().t)
            return coast ? std::max(0.0, p.back().*field + p.back().rate * (time - p.back().t)) * scale : 0.0;
        const auto it =
            std::upper_bound(p.begin(), p.end(), time, [](double x, const PenaltySample& q) { return x < q.t; });
        if (it == p.begin()) return p.front().*field * scale;
        const PenaltySample &hi = *it, &lo = *(it - 1);
        return (lo.*field + (hi.*field - lo.*field) * (time - lo.t) / (hi.t - lo.t)) * scale;
    };
    std::vector<html::Series> series;
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const bool matched = k + 1 == runs.size();
        html::Series ser{matched ? "e = " + n(s.restitution) : "ζ = " + n(s.rows[k].zeta),
                         matched ? "#ce2029" : kColours[k % (sizeof kColours / sizeof *kColours)],
                         {}};
        for (double x : t) ser.values.push_back(value_at(*runs[k], x));
        series.push_back(std::move(ser));
    }
    std::vector<double> t_ms;
    for (double x : t) t_ms.push_back(x * 1e3);
    return html::svg_plot(title, t_ms, series, {}, end * 1e3, "ms");
}

}  // namespace

std::string penalty_svg(const PenaltyStudy& s) {
    return plot_runs(s, "Contact force (N)", &PenaltySample::force, 1.0, false);
}

std::string penalty_overlap_svg(const PenaltyStudy& s) {
    return plot_runs(s, "Overlap (mm)", &PenaltySample::overlap, 1e3, true);
}

std::string penalty_csv(const PenaltyStudy& s) {
    std::ostringstream o;
    o.precision(17);
    o << "run,k_N_per_m,zeta,pull,t_s,overlap_m,rate_m_per_s,force_N,impulse_N_s\n";
    const auto rows = [&](const char* name, double k, double zeta, bool pull, const PenaltyRun& r) {
        for (const PenaltySample& p : r.samples)
            o << name << ',' << k << ',' << zeta << ',' << (pull ? 1 : 0) << ',' << p.t << ',' << p.overlap << ','
              << p.rate << ',' << p.force << ',' << p.impulse << '\n';
    };
    rows("matched", s.stiffness, s.zeta, false, s.matched);
    for (const PenaltyStudy::Row& r : s.rows) {
        rows("damping", s.stiffness, r.zeta, false, r.push);
        rows("damping", s.stiffness, r.zeta, true, r.pull);
    }
    for (const PenaltyStudy::Stiff& r : s.stiffer) rows("stiffness", r.stiffness, s.zeta, false, r.run);
    return o.str();
}

void write_penalty_markdown(const PenaltyStudy& s, std::ostream& out) {
    out << "## The penalty contact beside the impulse\n\n";
    for (const std::string& line : summary(s)) out << line << "\n\n";
    out << "![contact force against time](penalty.svg) ![overlap against time](penalty-overlap.svg)\n\n"
        << "| ζ | c (N s/m) | e, no pull: formula | integrated | e, may pull: formula | integrated | contact (ms) | "
           "peak force (N) |\n|---|---|---|---|---|---|---|---|\n";
    for (const PenaltyStudy::Row& r : s.rows)
        out << "| " << n(r.zeta) << " | " << n(r.damping) << " | " << n(r.e_push) << " | " << n(r.push.restitution)
            << " | " << n(r.e_pull) << " | " << n(r.pull.restitution) << " | " << n(r.push.contact_time * 1e3) << " | "
            << n(r.push.peak_force) << " |\n";
    out << "\nContact time and peak force: without pull. The samples: [penalty.csv](penalty.csv).\n\n"
        << stiffness_intro(s)
        << "\n\n| k (N/m) | c (N s/m) | contact (ms) | peak force (N) | deepest (mm) | "
           "e, integrated |\n|---|---|---|---|---|---|\n";
    for (const PenaltyStudy::Stiff& r : s.stiffer)
        out << "| " << n(r.stiffness) << " | " << n(r.damping) << " | " << n(r.run.contact_time * 1e3) << " | "
            << n(r.run.peak_force) << " | " << n(r.run.max_overlap * 1e3) << " | " << n(r.run.restitution) << " |\n";
    out << "\n";
}

std::string penalty_html(const PenaltyStudy& s) {
    std::ostringstream o;
    o << "<h2>The penalty contact beside the impulse</h2>\n";
    for (const std::string& line : summary(s)) o << "<p>" << html::math(line) << "</p>\n";
    o << "<figure><div class=\"plots\"><img src=\"penalty.svg\" alt=\"The contact force against time for each damping "
         "ratio\"><img src=\"penalty-overlap.svg\" alt=\"The overlap against time for each damping ratio\"></div>"
         "<figcaption>The contact force and the overlap against time, without pull: one curve per damping ratio ζ, "
         "and in red the spring matched to the lesson's e. When the force reaches 0 the blocks part while they still "
         "overlap (holding on, the damper would pull), and the overlap shrinks at the parting speed. Data: "
         "<a href=\"penalty.csv\">penalty.csv</a>.</figcaption></figure>\n";
    o << "<table>\n<tr><th>ζ</th><th>c (N s/m)</th><th>e, no pull: formula</th><th>integrated</th>"
         "<th>e, may pull: formula</th><th>integrated</th><th>contact (ms)</th><th>peak force (N)</th></tr>\n";
    for (const PenaltyStudy::Row& r : s.rows)
        o << "<tr><td>" << n(r.zeta) << "</td><td>" << n(r.damping) << "</td><td>" << n(r.e_push) << "</td><td>"
          << n(r.push.restitution) << "</td><td>" << n(r.e_pull) << "</td><td>" << n(r.pull.restitution) << "</td><td>"
          << n(r.push.contact_time * 1e3) << "</td><td>" << n(r.push.peak_force) << "</td></tr>\n";
    o << "</table>\n<p class=\"note\">Contact time and peak force: without pull.</p>\n";
    o << "<p>" << html::math(stiffness_intro(s))
      << "</p>\n<table>\n<tr><th>k (N/m)</th><th>c (N s/m)</th>"
         "<th>contact (ms)</th><th>peak force (N)</th><th>deepest (mm)</th><th>e, integrated</th></tr>\n";
    for (const PenaltyStudy::Stiff& r : s.stiffer)
        o << "<tr><td>" << n(r.stiffness) << "</td><td>" << n(r.damping) << "</td><td>" << n(r.run.contact_time * 1e3)
          << "</td><td>" << n(r.run.peak_force) << "</td><td>" << n(r.run.max_overlap * 1e3) << "</td><td>"
          << n(r.run.restitution) << "</td></tr>\n";
    o << "</table>\n";
    return o.str();
}

}  // namespace collide
