// The worked example of `collide solve` (text and Markdown, from teach/worked_lines.h) and its
// JSON record.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/diagnostics.h"
#include "teach/notation.h"
#include "teach/solve.h"
#include "teach/worked_lines.h"

namespace collide {

using notation::num_text;

std::string energy_gain_note(Model model) {
    const std::string name = model_name(model);
    if (model == Model::page_listing)
        return "Energy gained: the page's listing, as written, leaves the pair with more kinetic energy than it "
               "had, which no real impact can do (its J acts with the wrong sign: see the errata list).";
    if (model == Model::routh)
        return "Energy gained: Newton's restitution law left the pair with more kinetic energy than it had, which "
               "no real impact can do. This is Kane's paradox, and integrating the impact does not cure it: "
               "Newton's law asks for a normal velocity after the impact that friction may have made costly. "
               "restitution_law = \"stronge\" (the default) never creates energy.";
    return "Energy gained: the " + name +
           " model left the pair with more kinetic energy than it had, which no "
           "real impact can do. This is Kane's paradox: a friction law applied in one step, with Newton's "
           "restitution, creates energy when the slip stops or reverses during the impact. model = \"routh\" "
           "(the impact integrated over the normal impulse) with Stronge's energetic restitution never does.";
}

std::string routh_approximation(const Solution& s) {
    if (s.painleve)
        return "Routh's integration could not end the compression (the approach kept speeding up, a Painleve-like "
               "jam): this is the frictionless impulse, not Routh's answer.";
    return "Routh's integration could not be finished: the slip's direction was still turning after 20000 steps, "
           "and the rest of the impact was taken along its last direction. This impulse is an approximation.";
}

namespace {

std::string headline(const SolveProblem& P) {
    std::string h = "Collision response: " + std::to_string(P.dimension) + "D, model " + model_name(P.model) +
                    ", e = " + num_text(P.restitution);
    if (P.model == Model::coulomb || P.model == Model::routh) h += ", μ = " + num_text(P.friction);
    if (P.model == Model::routh) h += std::string(", restitution law ") + restitution_law_name(P.restitution_law);
    return h;
}

const char* kConventions =
    "Conventions: n points from A into B; the impulse P acts as +P on B and -P on A at the "
    "contact point; u = v_pb - v_pa, u_n < 0 means approaching; SI units.";

}  // namespace

void write_text(const SolveProblem& P, const Solution& s, std::ostream& out) {
    if (!P.title.empty()) out << P.title << "\n";
    out << headline(P) << "\n" << kConventions << "\n";
    int i = 0;
    for (const WorkedStep& st : worked_steps(P, s)) {
        out << "\n" << ++i << ". " << st.title << "\n";
        for (const std::string& line : st.lines) out << "   " << line << "\n";
        for (const std::string& note : st.notes) out << "   " << note << "\n";
    }
}

void write_markdown(const SolveProblem& P, const Solution& s, std::ostream& out) {
    out << "# " << (P.title.empty() ? "Collision response" : P.title) << "\n\n";
    out << "*" << headline(P) << ".* " << kConventions << "\n";
    int i = 0;
    for (const WorkedLines& st : worked_lines(P, s)) {
        out << "\n## " << ++i << ". " << st.title() << "\n\n";
        for (const notation::F& line : st.lines) out << "$$" << line.tex << "$$\n\n";
        for (const std::string& note : st.notes) out << note << "\n\n";
    }
}

void write_json(const SolveProblem& P, const Solution& s, std::ostream& out) {
    using nlohmann::ordered_json;
    const int d = P.dimension;
    // Vectors have the problem's dimension; 1D values are numbers.
    auto V = [d](const Vec3& v) -> ordered_json {
        if (d == 1) return v.x();
        ordered_json a = ordered_json::array();
        for (int i = 0; i < d; ++i) a.push_back(v[i]);
        return a;
    };
    auto W = [d, &V](const Vec3& w) -> ordered_json { return d == 2 ? ordered_json(w.z()) : V(w); };
    auto body = [&](const Vec3& v, const Vec3& w) {
        ordered_json b;
        b["v"] = V(v);
        if (d >= 2) b["w"] = W(w);
        return b;
    };
    ordered_json j;
    j["dimension"] = d;
    j["model"] = model_name(P.model);
    j["restitution"] = P.restitution;
    j["friction"] = P.friction;
    j["normal"] = V(s.n);
    if (d >= 2) j["point"] = V(P.point);
    j["impulse"] = V(s.P);
    j["normal_impulse"] = s.P.dot(s.n);
    j["sliding"] = s.sliding;
    j["separating"] = s.separating;
    j["energy_gain"] = gains_energy(s.ke_before, s.ke_after);
    if (P.model == Model::routh) {
        j["restitution_law"] = restitution_law_name(P.restitution_law);
        ordered_json phases = ordered_json::array();
        for (const RouthPhase& ph : s.routh.phases)
            phases.push_back({{"kind", routh_phase_name(ph.kind)},
                              {"normal_impulse_from", ph.normal_impulse_from},
                              {"normal_impulse_to", ph.normal_impulse_to}});
        j["phases"] = phases;
        j["compression_impulse"] = s.routh.compression_impulse;
        j["work"] = {{"compression", s.routh.compression_work}, {"restitution", s.routh.restitution_work}};
        // Only when it happens (every other answer prints as before): what was not integrated.
        if (s.approximate) j["approximate"] = routh_approximation(s);
    }
    j["a"] = body(s.va, s.wa);
    j["b"] = body(s.vb, s.wb);
    j["relative_normal_velocity"] = {{"before", s.un}, {"after", s.un_after}};
    j["kinetic_energy"] = {{"before", s.ke_before}, {"after", s.ke_after}};
    j["momentum"] = {{"before", V(s.p_before)}, {"after", V(s.p_after)}};
    if (d >= 2) {
        j["angular_momentum"] = {{"before", W(s.L_before)}, {"after", W(s.L_after)}};
        j["about"] = V(P.about);
        if (P.model == Model::stick) j["couple"] = W(s.couple);
    }
    out << j.dump(2) << "\n";
}

}  // namespace collide
