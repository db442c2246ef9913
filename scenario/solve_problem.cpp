#include "scenario/solve_problem.h"

#include <cmath>

#include "scenario/toml_reader.h"
#include "engine/mass.h"

namespace collide {

namespace {

struct Shape {
    std::string name;
    Mat3 inertia3 = Mat3::Identity();
    double inertia2 = 1.0;
    bool thin_rod = false;  // 3D rod of radius 0: no moment about its own axis
};

Shape read_shape(const TableReader& t, int dim, double mass, bool is_static) {
    Shape s;
    const std::vector<std::string> shapes2 = {"disc", "rectangle", "rod"};
    const std::vector<std::string> shapes3 = {"sphere", "box", "rod", "disc", "rectangle"};
    s.name = read_choice(t, "shape", dim == 2 ? shapes2 : shapes3, "shape", "");
    // Which size keys each shape takes.
    const bool round = s.name == "sphere" || s.name == "disc";
    const bool sized = s.name == "box" || s.name == "rectangle";
    const bool rod = s.name == "rod";
    if (!round && !(rod && dim == 3)) t.forbid("radius", "a " + s.name + " has no radius here");
    if (!sized) t.forbid("size", "a " + s.name + " has no size (it takes " + (round ? "radius" : "length") + ")");
    if (!rod) t.forbid("length", "a " + s.name + " has no length");
    const double m = is_static ? 1.0 : mass;  // a static body's shape is geometry only
    if (round) {
        const double R = read_positive(t, "radius", "the radius in m");
        s.inertia2 = disc_inertia_2d(m, R);
        s.inertia3 = s.name == "sphere" ? sphere_inertia(m, R) : disc_inertia(m, R);
    } else if (sized) {
        const std::size_t n = s.name == "box" ? 3 : 2;
        const std::string what = n == 3 ? "[x, y, z] full edge lengths in m" : "[width, height] full edge lengths in m";
        auto size = t.numbers("size", n, what);
        if (!size) t.fail("", "missing key 'size' (" + what + ") for the " + s.name);
        for (double x : *size)
            if (!(x >= kMinSize)) t.fail("size", "edge lengths must be positive (at least 1e-12 m)");
        if (n == 3) {
            s.inertia3 = box_inertia(m, Vec3((*size)[0], (*size)[1], (*size)[2]));
        } else {
            s.inertia3 = rectangle_inertia(m, (*size)[0], (*size)[1]);
            s.inertia2 = rectangle_inertia_2d(m, (*size)[0], (*size)[1]);
        }
    } else {
        const double L = read_positive(t, "length", "the length in m");
        double R = 0.0;
        if (t.has("radius")) {
            R = *t.number("radius", "the rod's radius in m");
            if (R < 0) t.fail("radius", "the radius must be >= 0 (0: a thin rod)");
        }
        s.inertia2 = rod_inertia_2d(m, L);
        s.inertia3 = rod_inertia(m, L, R);
        s.thin_rod = R == 0.0;
    }
    return s;
}

SolveBody read_body(const TableReader& root, const std::string& key, int dim, bool* thin_rod) {
    auto tr = root.table(key);
    if (!tr) root.fail("", "missing table [" + key + "] (body " + (key == "a" ? "A" : "B") + ")");
    const TableReader& t = *tr;
    forbid_other_dimension_keys(t, dim);
    if (dim == 1)
        for (const char* k : {"w", "r", "inertia", "shape", "radius", "size", "length"})
            t.forbid(k, std::string("'") + k + "' has no meaning in 1D (bodies are points on a line)");
    std::vector<std::string> allowed = {"name", "mass", "static", "position", "v"};
    if (dim >= 2) {
        for (const char* k : {"inertia", "shape", "radius", "size", "length", "w", "r"}) allowed.push_back(k);
        allowed.push_back(dim == 2 ? "angle" : "orientation");
    }
    t.allow_only(allowed);

    SolveBody body;
    body.name = t.string("name", "a name").value_or(key == "a" ? "A" : "B");
    const bool is_static = t.boolean("static").value_or(false);
    double mass = 1.0;
    if (is_static) {
        t.forbid("mass", "a static body is immovable (infinite mass); remove 'mass' or set static = false");
        t.forbid("inertia", "a static body is immovable; remove 'inertia'");
    } else {
        if (!t.has("mass")) t.fail("", "missing key 'mass' (kg); or set static = true for an immovable body");
        mass = read_positive(t, "mass", "a mass in kg");
    }
    const Vec3 x = read_vec(t, "position", dim, "m").value_or(Vec3::Zero());
    const Vec3 v = read_vec(t, "v", dim, "m/s").value_or(Vec3::Zero());
    const Vec3 w = read_spin(t, dim);
    const double angle = t.number("angle", "an angle in rad").value_or(0.0);
    const Quat q = dim == 3 ? read_orientation(t) : lift_angle(angle);

    Mat3 I3 = Mat3::Identity();
    double I2 = 1.0;
    if (dim >= 2) {
        if (t.has("shape") && t.has("inertia"))
            t.fail("inertia", "give either 'inertia' or 'shape' (with its size), not both");
        if (t.has("shape")) {
            const Shape s = read_shape(t, dim, mass, is_static);
            body.shape = s.name;
            I3 = s.inertia3;
            I2 = s.inertia2;
            *thin_rod = dim == 3 && s.thin_rod && !is_static;
        } else {
            for (const char* k : {"radius", "size", "length"})
                t.forbid(k, std::string("'") + k + "' needs a shape (shape = \"...\")");
            if (!is_static && !t.has("inertia"))
                t.fail("", "missing key 'inertia' (" +
                               std::string(dim == 2 ? "a number in kg m^2"
                                                    : "[[..],[..],[..]] or [Ixx, Iyy, Izz] in kg m^2") +
                               ") or 'shape'");
            if (dim == 2 && t.has("inertia")) {
                I2 = read_positive(t, "inertia", "a moment of inertia in kg m^2");
            } else if (dim == 3 && t.has("inertia")) {
                const toml::node* n = t.node("inertia");
                const toml::array* arr = n->as_array();
                if (arr && arr->size() > 0 && arr->get(0)->is_array()) {
                    I3 = *t.matrix3("inertia", "a 3x3 inertia tensor [[..],[..],[..]] in kg m^2");
                } else {
                    auto d = t.numbers("inertia", 3, "[Ixx, Iyy, Izz] in kg m^2 or a 3x3 tensor");
                    I3 = Vec3((*d)[0], (*d)[1], (*d)[2]).asDiagonal();
                }
                check_inertia(t, "inertia", I3);
            }
        }
    }

    body.b1 = Body1{mass, is_static, x.x(), v.x()};
    body.b2 = Body2{mass, is_static, I2, angle, x.head<2>(), v.head<2>(), w.z()};
    body.b3 = Body3{mass, is_static, I3, q, x, v, w};
    return body;
}

// Resolves the contact point p and each body's centre x and lever r = p - x from what the file
// gives: p (optional), and per body position (optional) and r (optional).
void resolve_geometry(const TableReader& root, SolveProblem* P) {
    const int dim = P->dimension;
    auto ta = root.table("a"), tb = root.table("b");
    struct Side {
        const TableReader* t;
        SolveBody* body;
        std::optional<Vec3> r;
        bool has_x;
    };
    Side sides[2] = {{&*ta, &P->a, read_vec(*ta, "r", dim, "m"), ta->has("position")},
                     {&*tb, &P->b, read_vec(*tb, "r", dim, "m"), tb->has("position")}};
    std::optional<Vec3> p = read_vec(root, "point", dim, "m");
    // Without 'point', a body that gives both position and r fixes it; otherwise the origin.
    if (!p) {
        for (const Side& s : sides)
            if (s.r && s.has_x) {
                p = s.body->b3.position + *s.r;
                break;
            }
    }
    if (!p) p = Vec3::Zero();
    P->point = *p;
    for (Side& s : sides) {
        Vec3& x = s.body->b3.position;
        if (s.r && s.has_x) {
            const Vec3 miss = x + *s.r - *p;
            const double scale = std::max({1.0, x.norm(), s.r->norm(), p->norm()});
            if (miss.norm() > 1e-9 * scale)
                s.t->fail("r", "position + r must be the contact point " +
                                   std::string(root.has("point") ? "'point'" : "(fixed by the other body)") +
                                   "; they differ by " + show(miss.norm()) +
                                   " m (give only two of point, position, r)");
        } else if (s.r) {
            x = *p - *s.r;
        }
        s.body->b2.position = x.head<2>();
    }
}

}  // namespace

SolveProblem parse_solve_text(const std::string& text, const std::string& name) {
    return parse_solve_table(parse_toml_text(text, name), name);
}

SolveProblem parse_solve_table(const toml::table& table, const std::string& name) {
    const TableReader root(table, name, "");
    if (root.has("scene") || root.has("body"))
        root.fail("",
                  "this is a scenario file ([scene], [[body]]): run it with 'collide step'; "
                  "collision files give dimension, normal, [a] and [b] at the top");
    root.allow_only({"title", "dimension", "model", "restitution_law", "restitution", "friction", "normal", "point",
                     "about", "a", "b"});
    SolveProblem P;
    P.file = name;
    P.title = root.line("title", "a title").value_or("");
    P.dimension = read_dimension(root);
    const int d = P.dimension;

    const std::string model =
        read_choice(root, "model", {"frictionless", "coulomb", "matrix", "stick", "page-listing", "routh"}, "model",
                    "frictionless");
    parse_model(model, &P.model);
    if (root.has("restitution_law")) {
        if (P.model != Model::routh)
            root.fail("restitution_law", "applies to model = \"routh\" only (the other models use Newton's law)");
        parse_restitution_law(
            read_choice(root, "restitution_law", {"newton", "poisson", "stronge"}, "restitution_law", "stronge"),
            &P.restitution_law);
    }
    P.restitution = root.required_number("restitution", "the coefficient of restitution e in [0, 1]");
    if (P.restitution < 0 || P.restitution > 1)
        root.fail("restitution", "e must lie in [0, 1] (0: perfectly inelastic, 1: elastic)");
    P.friction = root.number("friction", "the friction coefficient mu >= 0").value_or(0.0);
    if (P.friction < 0) root.fail("friction", "mu must be >= 0");

    if (d == 1) {
        root.forbid("point", "'point' is not used in 1D (bodies are points on a line)");
        root.forbid("about", "'about' is not used in 1D (there is no angular momentum on a line)");
    }
    auto n = read_vec(root, "normal", d, "(a direction, from A into B)");
    if (!n)
        root.fail("", std::string("missing key 'normal' (from A into B; ") + (d == 1   ? "1 or -1)"
                                                                              : d == 2 ? "[x, y])"
                                                                                       : "[x, y, z])"));
    if (!(n->norm() > 0)) root.fail("normal", "a zero normal has no direction");
    P.normal = n->normalized();
    P.about = read_vec(root, "about", d, "m").value_or(Vec3::Zero());

    bool thin_a = false, thin_b = false;
    P.a = read_body(root, "a", d, &thin_a);
    P.b = read_body(root, "b", d, &thin_b);
    if (P.a.b3.is_static && P.b.b3.is_static)
        root.fail("b", "both bodies are static: nothing can move (make at least one dynamic)");
    if (d >= 2) resolve_geometry(root, &P);

    // A thin rod has no moment about its axis: it can only be struck on that axis.
    for (auto [thin, body, key] : {std::tuple{thin_a, &P.a, "a"}, std::tuple{thin_b, &P.b, "b"}}) {
        if (!thin) continue;
        const Vec3 axis = body->b3.orientation * Vec3::UnitX();
        const Vec3 r = P.point - body->b3.position;
        if (r.cross(axis).norm() > 1e-9 * std::max(1.0, r.norm()))
            root.table(key)->fail("radius",
                                  "a thin rod (radius 0) can only be struck on its axis; "
                                  "give the rod a radius or move the contact point onto the rod");
    }
    return P;
}

SolveProblem parse_solve_file(const std::string& path) {
    std::string name;
    const std::string text = read_input_file(path, &name);
    return parse_solve_text(text, name);
}

}  // namespace collide
