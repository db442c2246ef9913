// The worked example of `collide solve` as steps: each shows the formula in the page's
// symbols, then the numbers substituted (teach/worked_lines.h).
#include "teach/worked_lines.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "engine/diagnostics.h"

namespace collide {

namespace {

using namespace notation;

// A step's title: its name, and its formula when it has one ("Impulse", "j = ...").
struct Title {
    std::string name, formula;
    Title(const char* name) : name(name) {}  // a title without a formula
    Title(std::string name) : name(std::move(name)) {}
    Title(std::string name, std::string formula) : name(std::move(name)), formula(std::move(formula)) {}
};

// Symbols with a body subscript: sym("v", 'a') = "v_a".
// A base that already has a subscript extends it: sym("v_p", 'a') = "v_pa".
std::string sym(const std::string& base, char body) {
    return base + (base.find('_') == std::string::npos ? "_" : "") + body;
}

class Builder {
public:
    Builder(const SolveProblem& P, const Solution& s) : P(P), s(s), d(P.dimension) {}

    std::vector<WorkedLines> build() {
        given();
        if (d == 1) {
            step("Relative velocity along the normal",
                 {f("u_n = (v_b − v_a) n"), f("u_n = (") + num(s.vpb.x()) + f(" − ") + paren(s.vpa.x()) + f(") × ") +
                                                paren(s.n.x()) + f(" = ") + num(s.un) + unit("m/s")});
        } else {
            kinematics();
        }
        if (s.separating) {
            step("No collision", {f("u_n = ") + num(s.un) + unit("m/s") + f(" ≥ 0")},
                 {"The contact points are separating (or resting): no impulse acts, every velocity "
                  "stays as it was."});
        } else {
            const std::size_t first_model_step = steps.size();
            switch (P.model) {
                case Model::frictionless: frictionless_steps(); break;
                case Model::coulomb: coulomb_steps(); break;
                case Model::matrix: matrix_steps(); break;
                case Model::stick: stick_steps(); break;
                case Model::page_listing: listing_steps(); break;
                case Model::routh: routh_steps(); break;
            }
            for (std::size_t k = first_model_step; k < steps.size(); ++k) steps[k].response = true;
            if (P.model != Model::page_listing && P.model != Model::stick) final_velocities();
            restitution_check();
        }
        checks();
        return steps;
    }

private:
    const SolveProblem& P;
    const Solution& s;
    const int d;
    std::vector<WorkedLines> steps;

    F V(const Vec3& v) const { return vec(v, d); }
    F W(const Vec3& w) const { return spin(w, d); }
    // After an operator: a negative 1D value in parentheses (vectors carry their own).
    F Vp(const Vec3& v) const { return d == 1 ? paren(v.x()) : vec(v, d); }
    // After an operator: a negative 2D spin in parentheses.
    F Wp(const Vec3& w) const { return d == 2 ? paren(w.z()) : spin(w, d); }
    // (On the printed number: a round-off -1e-20 prints as 0, without parentheses.)
    static F paren(double x) {
        const F n = num(x);
        return n.txt.rfind('-', 0) == 0 ? f("(") + n + f(")") : n;
    }
    const SolveBody& body(char c) const { return c == 'a' ? P.a : P.b; }
    bool is_static(char c) const { return body(c).b3.is_static; }

    void step(const Title& title, std::vector<F> lines, std::vector<std::string> notes = {}) {
        steps.push_back({title.name, title.formula, std::move(lines), std::move(notes)});
    }

    void given() {
        std::vector<F> lines;
        std::vector<std::string> notes;
        for (char c : {'a', 'b'}) {
            const SolveBody& B = body(c);
            const bool show_shape = !B.shape.empty() && B.shape != B.name;
            const std::string who = B.name + (show_shape ? " (" + B.shape + ")" : "");
            // The parser fills b3 in every dimension (1D: along x), so it serves all three.
            const Vec3& x = B.b3.position;
            const Vec3& vi = B.b3.v;
            F line = words(who + ": ");
            if (B.b3.is_static) line = line + words("static (immovable), ") + f("1/" + sym("m", c) + " = 0");
            else line = line + f(sym("m", c) + " = ") + num(B.b3.mass) + unit("kg");
            if (d >= 2 || B.b1.position != 0.0) line = line + f(",  " + sym("x", c) + " = ") + V(x) + unit("m");
            line = line + f(",  " + sym("v", c) + " = ") + V(vi) + unit("m/s");
            if (d >= 2) line = line + f(",  " + sym("ω", c) + " = ") + W(B.b3.w) + unit("rad/s");
            lines.push_back(line);
            if (d >= 2 && !B.b3.is_static) {
                const Mat3& I = c == 'a' ? s.Ia : s.Ib;
                if (d == 2) lines.push_back(f(sym("I", c) + " = ") + num(I(2, 2)) + unit("kg·m²"));
                else lines.push_back(f(sym("I", c) + " = R I_body Rᵀ = ") + mat(I, 3) + unit("kg·m²"));
            }
        }
        if (d >= 2) lines.push_back(f("p = ") + V(P.point) + unit("m") + f(",  n = ") + V(s.n));
        else lines.push_back(f("n = ") + num(s.n.x()));
        F coeffs = f("e = ") + num(P.restitution);
        if (P.model == Model::coulomb || P.model == Model::routh) coeffs = coeffs + f(",  μ = ") + num(P.friction);
        lines.push_back(coeffs);
        if (d == 3) notes.push_back("Inertia tensors are in world axes, about each centre of mass.");
        if (d >= 2) notes.push_back("p is the contact point; n the unit normal from A into B.");
        else notes.push_back("n = +1 when B lies in the +x direction from A, -1 otherwise.");
        step("Given", lines, notes);
    }

    void kinematics() {
        std::vector<F> lever, vel;
        for (char c : {'a', 'b'}) {
            const SolveBody& B = body(c);
            const Vec3& r = c == 'a' ? s.ra : s.rb;
            const Vec3& vp = c == 'a' ? s.vpa : s.vpb;
            lever.push_back(f(sym("r", c) + " = p − " + sym("x", c) + " = ") + V(P.point) + f(" − ") +
                            V(B.b3.position) + f(" = ") + V(r) + unit("m"));
            vel.push_back(f(sym("v_p", c) + " = " + sym("v", c) + " + " + sym("ω", c) + " × " + sym("r", c) + " = ") +
                          V(B.b3.v) + f(" + ") + W(B.b3.w) + f(" × ") + V(r) + f(" = ") + V(vp) +
                          unit("m/s"));  // vectors carry parentheses
        }
        step({"Lever arms", "r = p − x"}, lever);
        step({"Contact-point velocities", "v_p = v + ω × r"}, vel,
             d == 2 ? std::vector<std::string>{"In 2D, ω × r = ω (−r_y, r_x)."} : std::vector<std::string>{});
        step({"Relative velocity at the contact", "u = v_pb − v_pa,  u_n = u · n"},
             {f("u = ") + V(s.vpb) + f(" − ") + V(s.vpa) + f(" = ") + V(s.u) + unit("m/s"),
              f("u_n = ") + V(s.u) + f(" · ") + V(s.n) + f(" = ") + num(s.un) + unit("m/s") +
                  words(s.un < 0 ? "  (approaching)" : "")});
    }

    // The frictionless denominator D and its terms.
    F denominator_formula() const {
        if (d == 1) return f("D = 1/m_a + 1/m_b");
        if (d == 2) return f("D = 1/m_a + 1/m_b + (r_a × n)²/I_a + (r_b × n)²/I_b");
        return f("D = 1/m_a + 1/m_b + (r_a × n)·I_a⁻¹(r_a × n) + (r_b × n)·I_b⁻¹(r_b × n)");
    }
    double denominator() const { return s.inv_ma + s.inv_mb + s.rot_a + s.rot_b; }
    F denominator_numbers() const {
        F line = f("D = ") + num(s.inv_ma) + f(" + ") + num(s.inv_mb);
        // A rotational term below 1e-12 of D is round-off of a lever arm along n (a disc or a
        // sphere): it changes no printed digit of D, and is printed as the 0 it stands for.
        const auto term = [&](double x) { return std::abs(x) < 1e-12 * denominator() ? 0.0 : x; };
        if (d >= 2) line = line + f(" + ") + num(term(s.rot_a)) + f(" + ") + num(term(s.rot_b));
        return line + f(" = ") + num(denominator()) + unit("1/kg");
    }

    void frictionless_steps() {
        std::vector<std::string> notes;
        if (d == 2) notes.push_back("2D cross products are scalars: r × n = r_x n_y − r_y n_x.");
        if (d == 1 && P.model != Model::frictionless)
            notes.push_back(std::string("On a line there is no tangential direction: the ") + model_name(P.model) +
                            " model is the frictionless formula.");
        step("Denominator (effective inverse mass along n)", {denominator_formula(), denominator_numbers()}, notes);
        impulse_along_n(denominator());
    }

    void impulse_along_n(double D) {
        const double j = s.P.dot(s.n);
        step({"Impulse", "j = −(1 + e) u_n / D,  P = j n"},
             {f("j = −(1 + ") + num(P.restitution) + f(") × ") + paren(s.un) + f(" / ") + num(D) + f(" = ") + num(j) +
                  unit("N·s"),
              f("P = j n = ") + V(s.P) + unit("N·s")},
             {"P acts on B at the contact point; A receives −P."});
    }

    void collision_matrix_step() {
        const std::string formula = d == 2
                                        ? "K = (1/m_a + 1/m_b) E + perp(r_a) perp(r_a)ᵀ/I_a + perp(r_b) perp(r_b)ᵀ/I_b"
                                        : "K = (1/m_a + 1/m_b) E − [r_a]× I_a⁻¹ [r_a]× − [r_b]× I_b⁻¹ [r_b]×";
        std::vector<std::string> notes = {
            "An impulse P changes the relative contact velocity by K P. K is symmetric positive "
            "definite, so it can always be inverted (Cholesky: K = L Lᵀ)."};
        if (d == 2) notes.push_back("perp(r) = (−r_y, r_x).");
        step("Collision matrix", {f(formula), f("K = ") + mat(s.K, d) + unit("1/kg")}, notes);
    }

    void coulomb_steps() {
        collision_matrix_step();
        const double Pn = s.P_stick.dot(s.n);
        const double Pt = (s.P_stick - Pn * s.n).norm();
        step({"Sticking impulse", "P_s = K⁻¹(−e u_n n − u)"},
             {f("P_s = ") + V(s.P_stick) + unit("N·s"),
              f("P_n = P_s · n = ") + num(Pn) + unit("N·s") + f(",  |P_t| = |P_s − P_n n| = ") + num(Pt) + unit("N·s")},
             {"The impulse that stops the tangential slip and reverses the normal approach by e."});
        const bool inside = Pn >= 0 && Pt <= P.friction * Pn;  // the engine's test
        step({"Friction cone", "|P_t| ≤ μ P_n"},
             {num(Pt) + f(inside ? " ≤ " : " > ") + num(P.friction) + f(" × ") + paren(Pn) + f(" = ") +
              num(P.friction * Pn)},
             {inside ? "Inside the cone: the contact sticks, P = P_s."
                     : "Outside the cone: sticking would need more friction than μ allows."});
        if (inside) {
            step("Impulse", {f("P = P_s = ") + V(s.P) + unit("N·s")});
            return;
        }
        if (!s.sliding) {
            const std::string why = "n · K(n − μ t) = " + num_text(s.slide_denominator) +
                                    " ≤ 0: no sliding impulse can reverse the approach (a Painlevé-like case, beyond "
                                    "what a one-step friction model can resolve). ";
            step("No sliding solution", {f("P = ") + V(s.P) + unit("N·s")},
                 {why + (s.painleve ? "The sticking impulse would pull, so Collide uses the "
                                      "frictionless impulse."
                                    : "Collide keeps the sticking impulse (it pushes): friction "
                                      "as large as needed.")});
            return;
        }
        const double j = s.P.dot(s.n);
        step({"Sliding impulse", "P = j (n − μ t),  j = −(1 + e) u_n / (n · K(n − μ t))"},
             {f("t = ") + V(s.slip) + words("  (the direction of the initial tangential slip)"),
              f("n · K(n − μ t) = ") + num(s.slide_denominator) + unit("1/kg"),
              f("j = −(1 + ") + num(P.restitution) + f(") × ") + paren(s.un) + f(" / ") + num(s.slide_denominator) +
                  f(" = ") + num(j) + unit("N·s"),
              f("P = ") + V(s.P) + unit("N·s")},
             {"Friction μ j opposes the initial slip; μ = 0 gives the frictionless impulse."});
    }

    // Routh's method (engine/routh.h): the impact followed over the normal impulse P_n, phase by
    // phase, then ended by the restitution law; the energy balance splits into the works of the
    // normal impulse in compression and restitution and the work of friction.
    void routh_steps() {
        collision_matrix_step();
        const RouthDetail& r = s.routh;
        std::vector<F> lines = {f("du/dP_n = K (n − μ s)") + words("  while slipping (s: the unit slip direction)"),
                                f("du/dP_n = K (n + λ)") + words("  while sticking (λ keeps u_t = 0, |λ| ≤ μ)")};
        int k = 0;
        for (const RouthPhase& ph : r.phases)
            lines.push_back(words("phase " + std::to_string(++k) + ": " + routh_phase_name(ph.kind) + ", P_n from ") +
                            num(ph.normal_impulse_from) + words(" to ") + num(ph.normal_impulse_to) + unit("N·s"));
        step("Impact integrated over the normal impulse (Routh's method)", lines,
             {"Between changes of slip, u changes linearly with P_n" +
                  std::string(d == 3 ? " (in 3D the slip direction turns while slipping: integrated to 1e-9)" : "") +
                  ". Slip stops where u_t = 0; then the contact sticks if friction can hold it, otherwise it "
                  "slips again (reverse).",
              "Compression ends where u_n = 0; the law below ends restitution."});
        const double e = P.restitution, Pc = r.compression_impulse, Pf = r.final_normal_impulse;
        std::vector<F> law = {f("P_c = ") + num(Pc) + unit("N·s") + f(",  W_c = ") + num(r.compression_work) +
                              unit("J")};
        std::string note;
        switch (P.restitution_law) {
            case RestitutionLaw::newton:
                law.push_back(f("u_n′ = −e u_n = −") + num(e) + f(" × ") + paren(s.un) + f(" = ") + num(-e * s.un) +
                              unit("m/s"));
                note =
                    "Newton's law ends the impact when the normal velocity has been reversed and scaled by e. "
                    "With friction it can create energy (Kane's paradox).";
                break;
            case RestitutionLaw::poisson:
                law.push_back(f("P_n = (1 + e) P_c = (1 + ") + num(e) + f(") × ") + num(Pc) + f(" = ") + num(Pf) +
                              unit("N·s"));
                note = "Poisson's law: the normal impulse of restitution is e times that of compression.";
                break;
            case RestitutionLaw::stronge:
                law.push_back(f("W_r = −e e W_c = −") + num(e) + f(" × ") + num(e) + f(" × ") +
                              paren(r.compression_work) + f(" = ") + num(r.restitution_work) + unit("J"));
                note =
                    "Stronge's energetic law: the normal impulse gives back e² of the work it absorbed in "
                    "compression. It never creates energy.";
                break;
        }
        law.push_back(f("P_n = ") + num(Pf) + unit("N·s") + f(",  P = ") + V(s.P) + unit("N·s"));
        step(std::string("Restitution law: ") + restitution_law_name(P.restitution_law), law, {note});
        const double Wt = r.energy_change - r.compression_work - r.restitution_work;
        step({"Energy balance", "ΔE = W_c + W_r + W_t"},
             {f("ΔE = W_c + W_r + W_t = ") + num(r.compression_work) + f(" + ") + num(r.restitution_work) + f(" + ") +
              paren(Wt) + f(" = ") + num(r.energy_change) + unit("J")},
             {"W_t is the work of friction (never positive). ΔE is the change of kinetic energy."});
    }

    void matrix_steps() {
        collision_matrix_step();
        const Mat3 Kinv = d == 2 ? embed2_inverse() : Mat3(s.K.inverse());
        std::vector<std::string> notes = {
            "Restitution acts on the whole relative velocity, tangential part too: a rough "
            "(\"superball\") collision, not the frictionless one. Afterwards u′ = −e u."};
        if (s.P.dot(s.n) < 0)
            notes.push_back("Here P · n = " + num_text(s.P.dot(s.n)) +
                            " N·s < 0: the impulse pulls the bodies together at the contact. "
                            "Reversing the whole relative velocity is not always possible with a "
                            "push; this is where the method stops being a model of a real contact.");
        step({"The page's matrix method", "(e + 1) u = −K P  →  P = −(1 + e) K⁻¹ u"},
             {f("K⁻¹ = ") + mat(Kinv, d) + unit("kg"),
              f("P = −(1 + ") + num(P.restitution) + f(") K⁻¹ ") + V(s.u) + f(" = ") + V(s.P) + unit("N·s")},
             notes);
    }
    Mat3 embed2_inverse() const {
        Mat3 out = Mat3::Zero();
        out.topLeftCorner<2, 2>() = s.K.topLeftCorner<2, 2>().inverse();
        return out;
    }

    void stick_steps() {
        if (is_static(a_or_b_static())) {
            const char st = a_or_b_static();
            const std::string k(1, st);
            step("Stick to a static body",
                 {d == 1 ? f("v′ = v_" + k) : f("v′ = v_" + k + " + ω_" + k + " × (x − x_" + k + "),  ω′ = ω_" + k)},
                 {"The moving body welds to the immovable one and takes its motion."});
            final_values();
            return;
        }
        const Combined3& c = s.combined;
        if (d == 1) {
            step({"Combined body", "M = m_a + m_b,  v = (m_a v_a + m_b v_b)/M"},
                 {f("M = ") + num(c.M) + unit("kg") + f(",  v = ") + num(c.v.x()) + unit("m/s")},
                 {"Perfectly inelastic on a line: both move on with the centre-of-mass velocity."});
            final_values();
            impulse_from_change();
            return;
        }
        const Vec3 xc = P.point + c.xc;
        step({"Combined body", "M = m_a + m_b,  x_c = (m_a x_a + m_b x_b)/M"},
             {f("M = ") + num(c.M) + unit("kg") + f(",  x_c = ") + V(xc) + unit("m"),
              f("d_a = x_a − x_c = ") + V(c.da) + unit("m") + f(",  d_b = x_b − x_c = ") + V(c.db) + unit("m")});
        step({"Inertia about x_c (parallel axis)",
              d == 2 ? "I = I_a + m_a |d_a|² + I_b + m_b |d_b|²" : "I = Σ (I_i + m_i (|d_i|² E − d_i d_iᵀ))"},
             {f("I = ") + (d == 2 ? num(c.I(2, 2)) : mat(c.I, 3)) + unit("kg·m²")});
        step("Momentum and angular momentum about x_c",
             {f("v = (m_a v_a + m_b v_b)/M = ") + V(c.v) + unit("m/s"),
              f("L = I_a ω_a + m_a d_a × v_a + I_b ω_b + m_b d_b × v_b = ") + W(c.L) + unit("kg·m²/s"),
              f("ω = I⁻¹ L = ") + W(c.w) + unit("rad/s")});
        final_values();
        impulse_from_change();
        if (d == 3)
            step("The page's 6×6 Newton-Euler form gives the same motion",
                 {f("(NEM_a + NEM_b) V = NEM_a V_a + NEM_b V_b,  NEM = [[I_p, [h]×], [[h]×ᵀ, m E]]"),
                  f("max difference from the direct result = ") + num(s.newton_euler_difference)},
                 {"Every matrix is taken about the same point (the contact point), as the page says "
                  "rotations must be; h = m (x − p), I_p = I + m [c]× [c]×ᵀ with c = x − p."});
    }
    char a_or_b_static() const { return is_static('a') ? 'a' : 'b'; }

    // stick: each body moves with the combined rigid motion.
    void final_values() {
        std::vector<F> lines;
        for (char c : {'a', 'b'}) {
            const Vec3& v = c == 'a' ? s.va : s.vb;
            const Vec3& w = c == 'a' ? s.wa : s.wb;
            const bool welded = d >= 2 && !is_static('a') && !is_static('b');
            F line = f(sym("v", c) + (welded ? "′ = v + ω × " + sym("d", c) + " = " : "′ = "));
            line = line + V(v) + unit("m/s");
            if (d >= 2) line = line + f(",  " + sym("ω", c) + "′ = ") + W(w) + unit("rad/s");
            lines.push_back(line);
        }
        step("Final velocities", lines);
    }

    void impulse_from_change() {
        std::vector<F> lines = {f("P = m_b (v_b′ − v_b) = ") + V(s.P) + unit("N·s")};
        std::vector<std::string> notes;
        if (d >= 2) {
            lines.push_back(f("C = I_b (ω_b′ − ω_b) − r_b × P = ") + W(s.couple) + unit("N·m·s"));
            notes.push_back(
                "The page asks whether a rotational impulse can pass between colliding bodies. "
                "For bodies that stick, yes: the weld transmits the couple C besides the impulse P.");
        }
        step("Impulse that did this", lines, notes);
    }

    void listing_steps() {
        const page::Listing3& L = s.listing;
        std::vector<F> lines;
        if (d >= 2) {
            lines.push_back(f("angularVelChangea = I_a⁻¹(n × r_a) = ") + W(L.angularVelChangea));
            lines.push_back(f("angularVelChangeb = I_b⁻¹(n × r_b) = ") + W(L.angularVelChangeb));
            lines.push_back(f("scalar = 1/m_a + ((I_a⁻¹(n × r_a)) × r_a)·n + 1/m_b + ((I_b⁻¹(n × r_b)) × r_b)·n = ") +
                            num(L.scalar) + unit("1/kg"));
        } else {
            lines.push_back(f("scalar = 1/m_a + 1/m_b = ") + num(L.scalar) + unit("1/kg"));
        }
        lines.push_back(f("Jmod = (e + 1)|v_ai − v_bi| / scalar = ") + num(L.Jmod) + unit("N·s"));
        lines.push_back(f("J = n Jmod = ") + V(L.J) + unit("N·s"));
        lines.push_back(f("v_af = v_ai − J/m_a = ") + V(L.vaf) + unit("m/s"));
        lines.push_back(f("v_bf = v_bi − J/m_b = ") + V(L.vbf) + unit("m/s"));
        if (d >= 2) {
            lines.push_back(f("ω_af = ω_ai − angularVelChangea = ") + W(s.wa) + unit("rad/s"));
            lines.push_back(f("ω_bf = ω_bi − angularVelChangeb = ") + W(s.wb) + unit("rad/s"));
        }
        std::vector<std::string> notes = {
            std::string("This is the page's code listing run as written: the errata lesson's "
                        "example, not physics. It uses the speed of the centres |v_ai − v_bi| "
                        "instead of the normal contact-point velocity (") +
            (d >= 2 ? "it ignores spin and direction, and " : "it ignores direction and ") +
            "acts on separating bodies); v_bf subtracts J, so momentum is not conserved" +
            (d >= 2 ? "; the angular changes are per unit impulse (not times Jmod)." : ".")};
        if (d >= 2) {
            const double correct = denominator();
            notes.push_back(
                "Its rotational terms are subtracted (n × r, then × r again): scalar = " + num_text(L.scalar) +
                " 1/kg where the correct denominator is " + num_text(correct) + " 1/kg.");
        }
        notes.push_back("For the correct answer, solve the same collision with the frictionless model.");
        step("The page's listing, as written", lines, notes);
    }

    void final_velocities() {
        std::vector<F> lines;
        for (char c : {'a', 'b'}) {
            const char* sign = c == 'a' ? " − " : " + ";
            const Vec3& v0 = body(c).b3.v;
            const Vec3& v = c == 'a' ? s.va : s.vb;
            const Vec3& w = c == 'a' ? s.wa : s.wb;
            if (is_static(c)) {
                lines.push_back(f(sym("v", c) + "′ = " + sym("v", c) + " = ") + V(v) + unit("m/s") +
                                words("  (static)"));
                continue;
            }
            lines.push_back(f(sym("v", c) + "′ = " + sym("v", c) + sign + "P/" + sym("m", c) + " = ") + V(v0) +
                            f(sign) + Vp(s.P) + f(" / ") + num(body(c).b3.mass) + f(" = ") + V(v) + unit("m/s"));
            if (d >= 2) {
                const std::string torque =
                    d == 2 ? "(" + sym("r", c) + " × P)/" + sym("I", c) : sym("I", c) + "⁻¹(" + sym("r", c) + " × P)";
                // The torque term is what the engine's update changed: |w' - w|, signed as shown.
                const Vec3& w0 = body(c).b3.w;
                const Vec3 term = c == 'a' ? Vec3(w0 - w) : Vec3(w - w0);
                lines.push_back(f(sym("ω", c) + "′ = " + sym("ω", c) + sign + torque + " = ") + W(w0) + f(sign) +
                                Wp(term) + f(" = ") + W(w) + unit("rad/s"));
            }
        }
        step("Final velocities", lines, {"The impulse −P acts on A and +P on B, at the contact point."});
    }

    void restitution_check() {
        std::vector<F> lines = {f("u_n′ = ") + num(s.un_after) + unit("m/s")};
        std::vector<std::string> notes;
        switch (P.model) {
            case Model::frictionless:
                lines.push_back(f("−e u_n = ") + num(-P.restitution * s.un) + unit("m/s"));
                notes.push_back("Newton's restitution: the normal approach speed is reversed and scaled by e.");
                break;
            case Model::coulomb:
                lines.push_back(f("−e u_n = ") + num(-P.restitution * s.un) + unit("m/s"));
                if (d >= 2) lines.push_back(f("u_t′ = u′ − u_n′ n = ") + V(s.u_after - s.un_after * s.n) + unit("m/s"));
                if (!s.sliding) {
                    notes.push_back("Sticking: the tangential slip is stopped.");
                } else {
                    const double before = (s.u - s.un * s.n).norm();
                    const double after = (s.u_after - s.un_after * s.n).norm();
                    if (after <= before)
                        notes.push_back("Sliding: the slip speed fell from " + num_text(before) + " to " +
                                        num_text(after) + " m/s.");
                    else
                        notes.push_back("Sliding: the slip speed rose from " + num_text(before) + " to " +
                                        num_text(after) +
                                        " m/s. In this one-step model friction keeps the direction of the "
                                        "initial slip t for the whole impact, while the normal impulse itself "
                                        "drives tangential motion through the off-diagonal terms of K. Impact "
                                        "integration (Routh's method) lets the slip direction change during "
                                        "the impact.");
                }
                break;
            case Model::matrix:
                lines.push_back(f("u′ = ") + V(s.u_after) + f(",  −e u = ") + V(-P.restitution * s.u) + unit("m/s"));
                notes.push_back("The matrix method reverses the whole relative velocity, scaled by e.");
                break;
            case Model::stick:
                notes.push_back(
                    "The bodies move on as one: the contact points share one velocity "
                    "(u_n′ = 0).");
                break;
            case Model::page_listing:
                lines.push_back(f("−e u_n = ") + num(-P.restitution * s.un) + unit("m/s") +
                                words("  (what a correct answer gives)"));
                break;
            case Model::routh:
                if (d >= 2) lines.push_back(f("u_t′ = u′ − u_n′ n = ") + V(s.u_after - s.un_after * s.n) + unit("m/s"));
                notes.push_back(std::string(s.sliding ? "Still slipping at the end." : "The slip has stopped.") +
                                " The normal velocity after follows from the law, not from −e u_n (except "
                                "with Newton's).");
                break;
        }
        step("Restitution check", lines, notes);
    }

    void checks() {
        std::vector<F> lines;
        auto row = [&](const std::string& name, F before, F after, F change, const std::string& u) {
            lines.push_back(words(name + ": ") + words("before ") + before + f(",  ") + words("after ") + after +
                            f(",  ") + words("change ") + change + unit(u));
        };
        // A change within round-off of the totals (1e-9 of them) is the 0 it stands for, not
        // "-5.55112e-17 J".
        const auto change = [](const Vec3& before, const Vec3& after) {
            const Vec3 c = after - before;
            return c.norm() <= 1e-9 * std::max(before.norm(), after.norm()) ? Vec3(Vec3::Zero()) : c;
        };
        // And a total kept to round-off prints its after-value as its before-value: 0.37635 J
        // kept is not "before 0.3764, after 0.3763, change 0".
        const auto after = [&](const Vec3& before, const Vec3& after) {
            return change(before, after).isZero(0.0) ? before : after;
        };
        row("momentum", V(s.p_before), V(after(s.p_before, s.p_after)), V(change(s.p_before, s.p_after)), "kg·m/s");
        if (d >= 2)
            row("angular momentum about o = " + vec(P.about, d).txt, W(s.L_before), W(after(s.L_before, s.L_after)),
                W(change(s.L_before, s.L_after)), "kg·m²/s");
        const double dke = change(Vec3(s.ke_before, 0, 0), Vec3(s.ke_after, 0, 0)).x();
        row("kinetic energy", num(s.ke_before), num(dke == 0.0 ? s.ke_before : s.ke_after), num(dke), "J");
        std::vector<std::string> notes;
        if (s.ke_before > 0) {
            char percent[32];  // three significant figures: a reader's number
            std::snprintf(percent, sizeof percent, "%.3g", 100.0 * dke / s.ke_before);
            notes.push_back("Kinetic energy changed by " + std::string(dke == 0.0 ? "0" : percent) + " %.");
        }
        if (gains_energy(s.ke_before, s.ke_after)) notes.push_back(energy_gain_note(P.model));
        if (s.approximate) notes.push_back(routh_approximation(s));
        notes.push_back(d >= 2 ? "Kinetic energy counts 1/2 m v·v + 1/2 ω·I ω (the full inertia tensor); "
                                 "angular momentum is Σ (I ω + m (x − o) × v), all about one fixed point."
                               : "Kinetic energy is Σ 1/2 m v².");
        if (is_static('a') || is_static('b')) {
            notes.push_back(
                "One body is static (immovable, infinite mass): it is left out of the "
                "totals, and the pair's momentum is not conserved (the static body "
                "absorbs it).");
            if (d >= 2)
                lines.push_back(words("angular momentum about the contact point: ") + words("before ") +
                                W(s.Lp_before) + f(",  ") + words("after ") + W(s.Lp_after) + unit("kg·m²/s"));
            if (d >= 2)
                notes.push_back(
                    "About the contact point the impulse has no lever arm, so that "
                    "angular momentum is conserved.");
        }
        step("Checks", lines, notes);
    }
};

}  // namespace

std::string WorkedLines::title() const { return formula.empty() ? name : name + "  " + formula; }

std::vector<WorkedLines> worked_lines(const SolveProblem& problem, const Solution& s) {
    return Builder(problem, s).build();
}

std::vector<WorkedStep> worked_steps(const SolveProblem& P, const Solution& s) {
    std::vector<WorkedStep> out;
    for (const WorkedLines& st : worked_lines(P, s)) {
        WorkedStep w{st.title(), st.formula, {}, st.notes, st.response};
        for (const F& line : st.lines) w.lines.push_back(line.txt);
        out.push_back(std::move(w));
    }
    return out;
}

}  // namespace collide
