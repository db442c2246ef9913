// [[plot]] of a lesson file (docs/formats/lesson-files.md, "Plots"): what to plot against what,
// every name checked against the scene's bodies and the lesson's [[mark]] list.
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenario/lesson.h"
#include "scenario/lesson_parse.h"
#include "scenario/toml_reader.h"

namespace collide::lesson_parse {

namespace {

using Kind = PlotQuantity::Kind;

// "x", "y", "z" as 0, 1, 2 within the scene's dimension; -1 otherwise.
int axis(const std::string& s, int dim) {
    const int k = s == "x" ? 0 : s == "y" ? 1 : s == "z" ? 2 : -1;
    return k < dim ? k : -1;
}

std::string axes_of(int dim) { return dim == 1 ? "x" : dim == 2 ? "x or y" : "x, y or z"; }

// A per-sample quantity (PlotQuantity), or fails at `key` saying what it may be.
// The totals' names and one body's (after "BODY."): energies, momentum, angular momentum.
// Fills q's kind, unit and component; false when `field` is none of them.
bool totals_quantity(const std::string& field, const std::string& comp, int dim, PlotQuantity& q,
                     const std::function<void(const std::string&)>& fail) {
    if (field == "kinetic_energy" || field == "potential_energy" || field == "energy") {
        if (!comp.empty()) fail(field + " is one number");
        q.kind = field == "energy" ? Kind::energy : field == "kinetic_energy" ? Kind::kinetic : Kind::potential;
        q.unit = "J";
        return true;
    }
    if (field == "momentum") {
        q.kind = Kind::momentum;
        q.unit = "kg m/s";
        if (comp.empty() && dim == 1) return true;
        q.component = axis(comp, dim);
        if (q.component < 0) fail("momentum has the components " + axes_of(dim) + ": momentum.x");
        return true;
    }
    if (field == "angular_momentum") {
        q.kind = Kind::angular_momentum;
        q.unit = "kg m^2/s";
        if (dim == 1) fail("bodies on a line have no angular momentum");
        if (dim == 2 && comp.empty()) q.component = 2;
        else if (dim == 3 && axis(comp, 3) >= 0) q.component = axis(comp, 3);
        else
            fail(dim == 2 ? "in 2D the angular momentum is one number (about z): angular_momentum"
                          : "angular_momentum has the components x, y or z: angular_momentum.x");
        return true;
    }
    return false;
}

// A per-sample quantity (PlotQuantity), or calls `refuse` (which throws) saying why not.
PlotQuantity sample_quantity(const std::string& name, const Lesson& L,
                             const std::function<void(const std::string&)>& refuse) {
    const int dim = L.scene.dimension;
    PlotQuantity q;
    q.name = name;
    const auto fail = [&](const std::string& why) {
        refuse("'" + name + "': " + why +
               " (a per-sample quantity is t, kinetic_energy, potential_energy, energy, momentum.x, "
               "angular_momentum, or BODY.position.x, BODY.v.x, BODY.w, BODY.angle, BODY.kinetic_energy, "
               "BODY.momentum.x, BODY.angular_momentum, BODY.MARK.v.x with a body's name and one of its "
               "[[mark]] names)");
    };
    if (name == "t") {
        q.unit = "s";
        return q;
    }
    {
        const std::size_t dot = name.find('.');
        if (totals_quantity(name.substr(0, dot), dot == std::string::npos ? "" : name.substr(dot + 1), dim, q, fail))
            return q;
    }
    // BODY.rest: the longest body name followed by a dot (names may hold dots: "A (e=0.1)").
    int body = -1;
    std::size_t len = 0;
    for (std::size_t i = 0; i < L.scene.bodies.size(); ++i) {
        const std::string& b = L.scene.bodies[i].name;
        if (name.size() > b.size() + 1 && name.compare(0, b.size(), b) == 0 && name[b.size()] == '.' &&
            b.size() >= len) {
            body = static_cast<int>(i);
            len = b.size();
        }
    }
    if (body < 0) {
        std::vector<std::string> names;
        for (const SceneBody& b : L.scene.bodies) names.push_back(b.name);
        const std::string head = name.substr(0, name.find('.'));
        const std::string hint = closest_match(head, names);
        fail("no body of the scene begins it" + (hint.empty() ? std::string() : "; did you mean '" + hint + "'?"));
    }
    q.body = body;
    std::string rest = name.substr(len + 1);
    // A [[mark]] of that body: BODY.MARK.position.x, BODY.MARK.v.x.
    for (std::size_t m = 0; m < L.view.marks.size(); ++m) {
        const ViewMark& mk = L.view.marks[m];
        if (mk.body != static_cast<std::size_t>(body)) continue;
        if (rest.size() > mk.name.size() + 1 && rest.compare(0, mk.name.size(), mk.name) == 0 &&
            rest[mk.name.size()] == '.') {
            q.mark = static_cast<int>(m);
            rest = rest.substr(mk.name.size() + 1);
            break;
        }
    }
    const std::size_t dot = rest.find('.');
    const std::string field = rest.substr(0, dot);
    const std::string comp = dot == std::string::npos ? "" : rest.substr(dot + 1);
    if (field == "position" || field == "v") {
        q.kind = field == "v" ? Kind::velocity : Kind::position;
        q.unit = field == "v" ? "m/s" : "m";
        q.component = axis(comp, dim);
        if (q.component < 0) fail(field + " has the components " + axes_of(dim) + ": " + field + ".x");
        return q;
    }
    if (q.mark >= 0) fail("a [[mark]] has position and v");
    if (totals_quantity(field, comp, dim, q, fail)) return q;
    if (field == "w") {
        q.kind = Kind::spin;
        q.unit = "rad/s";
        if (dim == 1) fail("a body on a line does not turn");
        if (dim == 2 && comp.empty()) q.component = 2;
        else if (dim == 3 && !comp.empty() && axis(comp, 3) >= 0) q.component = axis(comp, 3);
        else fail(dim == 2 ? "in 2D the spin is one number: BODY.w" : "w has the components x, y or z: w.x");
        return q;
    }
    if (field == "angle" && comp.empty()) {
        if (dim != 2) fail("the angle is a 2D body's");
        q.kind = Kind::angle;
        q.unit = "rad";
        return q;
    }
    fail("no such quantity of body '" + L.scene.bodies[body].name + "'" +
         (L.view.marks.empty() ? "" : " or of its marks"));
    return q;  // not reached: fail throws
}

PlotQuantity sample_quantity(const std::string& name, const Lesson& L, const TableReader& t, const std::string& key) {
    return sample_quantity(name, L, [&](const std::string& why) { t.fail(key, why); });
}

PlotQuantity collision_quantity(const std::string& name, bool is_x, const TableReader& t, const std::string& key) {
    for (const PlotQuantity& q : plot_collision_quantities())
        if (q.name == name && (is_x ? q.name != "interval" && q.name != "impulse" : q.name != "collision")) return q;
    t.fail(key, "'" + name + "': per collision, " +
                    (is_x ? std::string("x is \"collision\" (its number) or \"t\"")
                          : std::string("y is \"t\", \"interval\" or \"impulse\"")));
    return {};  // not reached: fail throws
}

}  // namespace

void parse_plots(const TableReader& root, Lesson& L) {
    for (const TableReader& p : root.tables("plot")) {
        p.allow_only({"title", "per", "x", "y", "pair", "chain", "instant", "counting", "fit", "fit_from"});
        LessonPlot P;
        P.where = p.prefix();
        P.pos = p.table_pos();
        P.title = p.string("title", "the plot's title (text)").value_or("");
        if (P.title.empty()) p.fail("title", "missing key 'title' (the plot's heading and the start of its alt text)");
        P.per = read_choice(p, "per", {"sample", "collision"}, "per", "sample") == "sample" ? PlotPer::sample
                                                                                            : PlotPer::collision;
        const bool per_sample = P.per == PlotPer::sample;
        const std::string x = p.string("x", "the quantity along x").value_or(per_sample ? "t" : "collision");
        P.x = per_sample ? sample_quantity(x, L, p, "x") : collision_quantity(x, true, p, "x");
        std::vector<std::string> ys;
        if (const toml::node* n = p.node("y"); n && n->is_string()) ys.push_back(*n->value<std::string>());
        else ys = strings(p, "y", "a quantity or a list of quantities");
        if (ys.empty()) p.fail("y", "missing key 'y' (the quantity, or a list of quantities, to plot)");
        if (ys.size() > 6) p.fail("y", "at most 6 quantities on one plot");
        for (const std::string& y : ys)
            P.y.push_back(per_sample ? sample_quantity(y, L, p, "y") : collision_quantity(y, false, p, "y"));
        if (per_sample)
            for (const PlotQuantity& y : P.y)
                if (y.unit != P.y.front().unit)
                    p.fail("y", "'" + y.name + "' is in " + y.unit + ", '" + P.y.front().name + "' in " +
                                    P.y.front().unit + ": one plot has one unit along y");
        for (const char* k : {"pair", "chain", "instant", "counting", "fit_from"})
            if (per_sample && p.has(k)) p.fail(k, std::string("'") + k + "' is for per = \"collision\"");
        P.pair = strings(p, "pair", "two body names");
        P.chain = strings(p, "chain", "a list of body names");
        P.instant = strings(p, "instant", "two body names");
        if ((!P.pair.empty()) + (!P.chain.empty()) + (!P.instant.empty()) > 1)
            p.fail(P.instant.empty() ? "chain" : "instant", "give one of 'pair', 'chain' and 'instant'");
        if (p.has("pair") && P.pair.size() != 2) p.fail("pair", "expected two body names");
        if (p.has("instant") && P.instant.size() != 2) p.fail("instant", "expected two body names");
        for (const std::string& b : P.instant) P.instant_index.push_back(body_named(L.scene, b, p, "instant"));
        if (P.instant.size() == 2 && P.instant_index[0] == P.instant_index[1]) p.fail("instant", "the same body twice");
        if (p.has("chain") && P.chain.size() < 2) p.fail("chain", "expected at least two body names");
        for (const std::string& b : P.pair) P.pair_index.push_back(body_named(L.scene, b, p, "pair"));
        for (const std::string& b : P.chain) P.chain_index.push_back(body_named(L.scene, b, p, "chain"));
        if (P.pair.size() == 2 && P.pair_index[0] == P.pair_index[1]) p.fail("pair", "the same body twice");
        for (std::size_t k = 0; k + 1 < P.chain_index.size(); ++k)
            for (std::size_t j = k + 1; j < P.chain_index.size(); ++j)
                if (P.chain_index[k] == P.chain_index[j]) p.fail("chain", "'" + P.chain[k] + "' twice");
        P.counting = p.string("counting", "what one step of x counts (a word)").value_or("collision");
        if (p.has("counting") && (P.counting.empty() || P.x.name != "collision"))
            p.fail("counting", "names what x = \"collision\" counts (\"bounce\", \"domino\")");
        const std::string fit = read_choice(p, "fit", {"none", "line", "ratio"}, "fit", "none");
        P.fit = fit == "line" ? PlotFit::line : fit == "ratio" ? PlotFit::ratio : PlotFit::none;
        if (P.fit != PlotFit::none && P.y.size() != 1) p.fail("fit", "a fit is of one quantity: give one y");
        if (P.fit == PlotFit::ratio && (per_sample || P.x.name != "collision"))
            p.fail("fit", "\"ratio\" (of each value to the one before) is per collision with x = \"collision\"");
        const long long from = p.integer("fit_from", "the first collision number the line fits").value_or(1);
        if (p.has("fit_from") && P.fit != PlotFit::line) p.fail("fit_from", "applies to fit = \"line\"");
        if (from < 1 || from > 1000000)
            p.fail("fit_from", "expected a collision number from 1, got " + std::to_string(from));
        P.fit_from = static_cast<int>(from);
        L.plots.push_back(std::move(P));
    }
}

}  // namespace collide::lesson_parse

namespace collide {

std::vector<PlotQuantity> plot_collision_quantities() {
    std::vector<PlotQuantity> out;
    for (const auto& [name, unit] :
         {std::pair<const char*, const char*>{"collision", ""}, {"t", "s"}, {"interval", "s"}, {"impulse", "N s"}}) {
        PlotQuantity q;
        q.name = name;
        q.unit = unit;
        out.push_back(q);
    }
    return out;
}

std::vector<PlotQuantity> plot_quantities(const Lesson& L) {
    const int dim = L.scene.dimension;
    const std::vector<std::string> axes = dim == 1   ? std::vector<std::string>{"x"}
                                          : dim == 2 ? std::vector<std::string>{"x", "y"}
                                                     : std::vector<std::string>{"x", "y", "z"};
    const auto totals = [&](const std::string& head, std::vector<std::string>& out) {
        for (const char* e : {"kinetic_energy", "potential_energy", "energy"}) out.push_back(head + e);
        if (dim == 1) out.push_back(head + "momentum");
        else
            for (const std::string& a : axes) out.push_back(head + "momentum." + a);
        if (dim == 2) out.push_back(head + "angular_momentum");
        if (dim == 3)
            for (const std::string& a : axes) out.push_back(head + "angular_momentum." + a);
    };
    std::vector<std::string> out{"t"};
    totals("", out);
    for (std::size_t i = 0; i < L.scene.bodies.size(); ++i) {
        const SceneBody& b = L.scene.bodies[i];
        if (b.is_static()) continue;
        for (const char* f : {"position", "v"})
            for (const std::string& a : axes) out.push_back(b.name + "." + f + "." + a);
        if (dim == 2) out.insert(out.end(), {b.name + ".w", b.name + ".angle"});
        if (dim == 3)
            for (const std::string& a : axes) out.push_back(b.name + ".w." + a);
        totals(b.name + ".", out);
        for (const ViewMark& mk : L.view.marks)
            if (mk.body == i)
                for (const char* f : {"position", "v"})
                    for (const std::string& a : axes) out.push_back(b.name + "." + mk.name + "." + f + "." + a);
    }
    std::vector<PlotQuantity> quantities;
    for (const std::string& name : out)
        quantities.push_back(lesson_parse::sample_quantity(
            name, L, [&](const std::string& why) { throw std::logic_error("plot_quantities: " + why); }));
    return quantities;
}

}  // namespace collide
