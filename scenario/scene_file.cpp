#include "scenario/scene_file.h"

#include <algorithm>
#include <cmath>

#include "scenario/toml_reader.h"
#include "engine/mass.h"

namespace collide {

namespace {

constexpr double kMaxOutputSteps = 1e6;
// The 2D and 3D worlds find a contact to an absolute 1e-10 m: on a body smaller than 1 um that
// would be more than 1e-4 of its size (tests/engine/numerical_edges_test.cpp), so it is refused.
constexpr double kMinBodySize = 1e-6;
const char* const kTooSmall = " is below 1e-6 m (1 um): contacts are found to 1e-10 m, too coarse for so small a body";

const std::vector<std::string>& shapes_of(int dim) {
    static const std::vector<std::string> s1 = {"block"};
    static const std::vector<std::string> s2 = {"disc", "rectangle", "polygon", "plane"};
    static const std::vector<std::string> s3 = {"sphere", "box", "plane"};
    return dim == 1 ? s1 : dim == 2 ? s2 : s3;
}

// Size keys: which shape takes which.
const char* size_key_owner(const std::string& key) {
    if (key == "radius") return "disc and sphere";
    if (key == "size") return "rectangle and box";
    if (key == "vertices") return "polygon";
    if (key == "length") return "block";
    return "plane";  // normal, offset
}
bool shape_takes(const std::string& shape, const std::string& key) {
    if (key == "radius") return shape == "disc" || shape == "sphere";
    if (key == "size") return shape == "rectangle" || shape == "box";
    if (key == "vertices") return shape == "polygon";
    if (key == "length") return shape == "block";
    return shape == "plane";
}

void read_material(const TableReader& t, std::optional<double>* e, std::optional<double>* mu) {
    *e = t.number("restitution", "the coefficient of restitution e in [0, 1]");
    if (*e && (**e < 0 || **e > 1))
        t.fail("restitution", "e must lie in [0, 1], got " + show(**e) +
                                  "; e = 1: they separate as fast as they approached, "
                                  "e = 0: not at all");
    *mu = t.number("friction", "the friction coefficient mu >= 0");
    if (*mu && **mu < 0) t.fail("friction", "mu must be >= 0, got " + show(**mu));
}

SceneBody read_body(const TableReader& t, int dim, std::size_t index) {
    std::vector<std::string> allowed = {"name",        "shape",    "mass",     "density", "static",
                                        "restitution", "friction", "position", "v"};
    if (dim == 1) allowed.push_back("length");
    if (dim >= 2)
        for (const char* k : {"radius", "size", "normal", "offset", "w"}) allowed.push_back(k);
    if (dim == 2) allowed.insert(allowed.end(), {"angle", "vertices"});
    if (dim == 3) allowed.push_back("orientation");
    forbid_other_dimension_keys(t, dim);
    t.allow_only(allowed);

    SceneBody b;
    b.name = t.string("name", "a name").value_or("body" + std::to_string(index + 1));
    if (b.name.empty()) t.fail("name", "a body's name must not be empty");
    // A line break (often from a """ string) would split the heading of the step table and of
    // data.csv, and a question's body = "cart" would not find it.
    if (std::any_of(b.name.begin(), b.name.end(),
                    [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }))
        t.fail("name", "a body's name must be one line, without line breaks or tabs, got '" + b.name + "'");
    b.shape = read_choice(t, "shape", shapes_of(dim), std::to_string(dim) + "D shape", "");
    for (const char* k : {"radius", "size", "vertices", "length", "normal", "offset"})
        if (!shape_takes(b.shape, k))
            t.forbid(k,
                     std::string("a ") + b.shape + " has no '" + k + "' (that is for the " + size_key_owner(k) + ")");
    read_material(t, &b.restitution, &b.friction);

    // Geometry, and the area (2D), volume (3D) or length (1D) that a density multiplies.
    const bool plane = b.shape == "plane";
    double extent = 0.0;
    Vec2 centroid = Vec2::Zero();  // polygon: centre of mass relative to the given position
    if (b.shape == "block") {
        b.length = read_positive(t, "length", "the block's length in m");
        extent = b.length;
    } else if (b.shape == "disc" || b.shape == "sphere") {
        const double r = read_positive(t, "radius", "the radius in m");
        if (r < kMinBodySize) t.fail("radius", "the radius " + show(r) + kTooSmall);
        b.shape2.kind = Shape2::Kind::disc;
        b.shape2.radius = r;
        b.shape3.kind = Shape3::Kind::sphere;
        b.shape3.radius = r;
        extent = dim == 2 ? kPi * r * r : 4.0 / 3.0 * kPi * r * r * r;
    } else if (b.shape == "rectangle" || b.shape == "box") {
        const std::string what =
            dim == 2 ? "[width, height], full edge lengths in m" : "[x, y, z] full edge lengths in m";
        auto size = t.numbers("size", static_cast<std::size_t>(dim), what);
        if (!size) t.fail("", "missing key 'size' (" + what + ")");
        for (double s : *size)
            if (!(s >= kMinSize)) t.fail("size", "edge lengths must be positive (at least 1e-12 m)");
        for (double s : *size)
            if (s < kMinBodySize) t.fail("size", "the edge " + show(s) + kTooSmall);
        if (dim == 2) {
            const auto [lo, hi] = std::minmax((*size)[0], (*size)[1]);
            if (hi > kMaxRectangleAspect * lo)
                t.fail("size", "the edges " + show(lo) + " and " + show(hi) +
                                   " m differ by more than a factor 1e9; the contact geometry "
                                   "cannot resolve so thin a rectangle");
            b.shape2.kind = Shape2::Kind::polygon;
            b.shape2.polygon = make_rectangle((*size)[0], (*size)[1]);
            extent = (*size)[0] * (*size)[1];
        } else {
            b.shape3.kind = Shape3::Kind::box;
            b.shape3.half = 0.5 * Vec3((*size)[0], (*size)[1], (*size)[2]);
            extent = (*size)[0] * (*size)[1] * (*size)[2];
        }
    } else if (b.shape == "polygon") {
        const toml::node* n = t.node("vertices");
        const toml::array* arr = n ? n->as_array() : nullptr;
        if (!arr) t.fail(n ? "vertices" : "", "expected vertices = [[x, y], ...] (counter-clockwise, m)");
        std::vector<Vec2> vertices;
        for (std::size_t i = 0; i < arr->size(); ++i) {
            const toml::array* xy = arr->get(i)->as_array();
            if (!xy || xy->size() != 2 || !xy->get(0)->is_number() || !xy->get(1)->is_number())
                t.fail("vertices", "vertex " + std::to_string(i + 1) + " is not [x, y]");
            const double x = xy->get(0)->value<double>().value_or(NAN);
            const double y = xy->get(1)->value<double>().value_or(NAN);
            if (!std::isfinite(x) || !std::isfinite(y) || std::abs(x) > 1e12 || std::abs(y) > 1e12)
                t.fail("vertices", "vertex " + std::to_string(i + 1) + " must be finite");
            vertices.emplace_back(x, y);
        }
        std::string error;
        b.shape2.kind = Shape2::Kind::polygon;
        if (!make_polygon(vertices, &b.shape2.polygon, &error, &centroid)) t.fail("vertices", error);
        Vec2 lo = vertices.front(), hi = vertices.front();
        for (const Vec2& v : vertices) {
            lo = lo.cwiseMin(v);
            hi = hi.cwiseMax(v);
        }
        if ((hi - lo).minCoeff() < kMinBodySize)
            t.fail("vertices", "the polygon's width " + show((hi - lo).minCoeff()) + kTooSmall);
        extent = polygon_area(b.shape2.polygon);
    } else {  // plane: the solid side is normal . p <= offset
        auto n = read_vec(t, "normal", dim, "(the outward unit normal)");
        if (!n) t.fail("", "missing key 'normal' (the plane's outward normal)");
        if (!(n->norm() > 0)) t.fail("normal", "a zero normal has no direction");
        const double offset = t.number("offset", "the plane's offset along its normal, m").value_or(0.0);
        b.shape2.kind = Shape2::Kind::half_plane;
        b.shape2.normal = n->head<2>().normalized();
        b.shape2.offset = offset;
        b.shape3.kind = Shape3::Kind::half_space;
        b.shape3.normal = n->normalized();
        b.shape3.offset = offset;
        for (const char* k : {"position", "angle", "orientation", "v", "w"})
            t.forbid(k, std::string("a plane is placed by normal and offset; '") + k + "' does not apply");
    }

    // Mass: exactly one of mass, density, static = true (a plane is always static).
    const bool is_static = t.boolean("static").value_or(plane);
    if (plane && !is_static) t.fail("static", "a plane is always static");
    const int given = t.has("mass") + t.has("density") + (is_static ? 1 : 0);
    if (given == 0) t.fail("", "missing key 'mass' (kg), 'density' or static = true");
    if (given > 1) t.fail(t.has("mass") ? "mass" : "density", "give exactly one of mass, density and static = true");
    double mass = 1.0;
    if (t.has("mass")) mass = read_positive(t, "mass", "a mass in kg");
    if (t.has("density")) {
        const char* unit = dim == 1 ? "kg/m" : dim == 2 ? "kg/m^2" : "kg/m^3";
        mass = read_positive(t, "density", std::string("a density in ") + unit) * extent;
    }

    const Vec3 x = read_vec(t, "position", dim, "m").value_or(Vec3::Zero());
    const Vec3 v = read_vec(t, "v", dim, "m/s").value_or(Vec3::Zero());
    const Vec3 w = read_spin(t, dim);
    if (is_static && (v.norm() > 0 || w.norm() > 0))
        t.fail(v.norm() > 0 ? "v" : "w",
               "a static body stays where it is; remove its velocity "
               "or give it a mass");

    if (dim == 1) {
        b.body1 = Body1{mass, is_static, x.x(), v.x()};
    } else if (dim == 2) {
        const double angle = t.number("angle", "an angle in rad").value_or(0.0);
        b.body2.mass = mass;
        b.body2.is_static = is_static;
        b.body2.angle = angle;
        b.body2.position = x.head<2>() + Pose2{Vec2::Zero(), angle}.rotate(centroid);
        b.body2.v = v.head<2>();
        b.body2.w = w.z();
        if (b.shape == "disc") b.body2.inertia = disc_inertia_2d(mass, b.shape2.radius);
        if (b.shape2.kind == Shape2::Kind::polygon) b.body2.inertia = mass * polygon_inertia_per_mass(b.shape2.polygon);
    } else {
        const Quat q = read_orientation(t);
        b.body3.mass = mass;
        b.body3.is_static = is_static;
        b.body3.orientation = q;
        b.body3.position = x;
        b.body3.v = v;
        b.body3.w = w;
        if (b.shape == "sphere") b.body3.inertia = sphere_inertia(mass, b.shape3.radius);
        if (b.shape == "box") b.body3.inertia = box_inertia(mass, 2.0 * b.shape3.half);
    }
    return b;
}

}  // namespace

double start_overlap(const Scene& s, const SceneBody& a, const SceneBody& b) {
    if (s.dimension == 1) return 0.5 * (a.length + b.length) - std::abs(a.body1.position - b.body1.position);
    if (s.dimension == 2)
        return -collide(a.shape2, Pose2{a.body2.position, a.body2.angle}, b.shape2,
                        Pose2{b.body2.position, b.body2.angle})
                    .separation;
    return -collide(a.shape3, Pose3{a.body3.position, a.body3.orientation}, b.shape3,
                    Pose3{b.body3.position, b.body3.orientation})
                .separation;
}

SceneView read_view(const TableReader& root, int dim) {
    SceneView v;
    const auto t = root.table("view");
    if (!t) return v;
    t->allow_only({"camera_azimuth", "camera_elevation", "camera_target", "camera_distance", "directions"});
    const auto bounded = [&](const char* key, double lo, double hi, const std::string& what) {
        const std::optional<double> x = t->number(key, what);
        if (x && (*x < lo || *x > hi))
            t->fail(key, "expected " + what + " between " + show(lo) + " and " + show(hi) + ", got " + show(*x));
        return x;
    };
    v.camera_azimuth = bounded("camera_azimuth", -360.0, 360.0, "an angle in degrees");
    v.camera_elevation = bounded("camera_elevation", -89.0, 89.0, "an angle in degrees");
    v.camera_target = read_vec(*t, "camera_target", dim, "m");
    if (t->has("camera_distance")) v.camera_distance = read_positive(*t, "camera_distance", "a distance in m");
    v.directions = t->boolean("directions").value_or(false);
    return v;
}

Scene parse_scene_text(const std::string& text, const std::string& name, SceneView* view,
                       const std::vector<std::string>& also_allowed) {
    return parse_scene_table(parse_toml_text(text, name), name, view, also_allowed);
}

Scene parse_scene_table(const toml::table& table, const std::string& name, SceneView* view,
                        const std::vector<std::string>& also_allowed) {
    const TableReader root(table, name, "");
    if (!root.has("scene") && (root.has("a") || root.has("dimension")))
        root.fail("",
                  "this is a collision file (dimension, [a], [b] at the top): run it with "
                  "'collide solve'; scenario files have a [scene] table and [[body]] tables");
    std::vector<std::string> top = {"scene", "body", "view", "mark"};
    top.insert(top.end(), also_allowed.begin(), also_allowed.end());
    root.allow_only(top);
    auto sc = root.table("scene");
    if (!sc) root.fail("", "missing table [scene]");
    sc->allow_only({"title", "dimension", "gravity", "duration", "output_dt", "model", "restitution_law", "policy",
                    "stepping", "restitution", "friction"});
    Scene s;
    s.file = name;
    s.title = sc->line("title", "a title").value_or("");
    s.dimension = read_dimension(*sc);
    s.gravity = read_vec(*sc, "gravity", s.dimension, "m/s^2").value_or(Vec3::Zero());
    s.duration = read_positive(*sc, "duration", "the simulated time in s");
    if (sc->has("output_dt")) s.output_dt = read_positive(*sc, "output_dt", "the output interval in s");
    if (s.duration / s.output_dt > kMaxOutputSteps)
        sc->fail("output_dt", "duration / output_dt gives more than 10^6 output steps");
    parse_model(read_choice(*sc, "model", {"frictionless", "coulomb", "matrix", "stick", "page-listing", "routh"},
                            "model", "frictionless"),
                &s.model);
    if (sc->has("restitution_law")) {
        if (s.model != Model::routh)
            sc->fail("restitution_law", "applies to model = \"routh\" only (the other models use Newton's law)");
        parse_restitution_law(
            read_choice(*sc, "restitution_law", {"newton", "poisson", "stronge"}, "restitution_law", "stronge"),
            &s.restitution_law);
    }
    s.policy = read_choice(*sc, "policy", {"sequential", "simultaneous"}, "policy", "sequential") == "sequential"
                   ? Policy::sequential
                   : Policy::simultaneous;
    if (sc->has("stepping")) {
        if (s.dimension == 1) sc->fail("stepping", "applies to 2D and 3D scenes (a 1D world is exact event by event)");
        const std::string st = read_choice(*sc, "stepping", {"auto", "always", "never"}, "stepping", "auto");
        s.stepping = st == "auto" ? StepMode::automatic : st == "always" ? StepMode::always : StepMode::never;
    }
    if (s.model == Model::page_listing && (s.dimension != 3 || s.policy != Policy::sequential))
        sc->fail("model",
                 "\"page-listing\" (the page's listing, 3D code answering one point at a time) runs "
                 "only in 3D scenes with policy = \"sequential\"");
    std::optional<double> e, mu;
    read_material(*sc, &e, &mu);
    s.restitution = e.value_or(1.0);
    s.friction = mu.value_or(0.0);
    const SceneView shown = read_view(root, s.dimension);
    if (view) *view = shown;

    const toml::node* list = root.node("body");
    const toml::array* bodies = list ? list->as_array() : nullptr;
    if (!bodies || bodies->empty()) root.fail(list ? "body" : "", "expected one or more [[body]] tables");
    const std::vector<TableReader> readers = root.tables("body");
    for (std::size_t i = 0; i < readers.size(); ++i) s.bodies.push_back(read_body(readers[i], s.dimension, i));
    for (std::size_t j = 0; j < s.bodies.size(); ++j) {
        for (std::size_t i = 0; i < j; ++i) {
            const SceneBody &a = s.bodies[i], &b = s.bodies[j];
            if (a.name == b.name)
                readers[j].fail("name",
                                "the name '" + b.name + "' is already used by body[" + std::to_string(i + 1) + "]");
            if (a.is_static() && b.is_static()) continue;
            const double depth = start_overlap(s, a, b);
            if (depth > kOverlapTolerance)
                readers[j].fail(readers[j].has("position") ? "position" : "",
                                "'" + b.name + "' overlaps '" + a.name + "' by " + show(depth) +
                                    " m at the start; bodies may touch but not overlap");
        }
    }
    // [[mark]]: points of bodies to draw (after the bodies: they name one).
    for (const TableReader& m : root.tables("mark")) {
        m.allow_only({"body", "at", "name", "velocity"});
        if (s.dimension == 3) m.fail("", "marked points are drawn in 1D and 2D diagrams only");
        ViewMark v;
        const std::string who = m.string("body", "a body's name").value_or("");
        if (who.empty()) m.fail("body", "missing key 'body' (the body the point belongs to)");
        v.body = body_named(s, who, m, "body");
        if (!m.has("at")) m.fail("at", "missing key 'at' (the point in the body's frame, m)");
        v.at = *read_vec(m, "at", s.dimension, "m");
        v.name = m.string("name", "the point's name").value_or("");
        if (v.name.empty()) m.fail("name", "missing key 'name' (drawn beside the point)");
        v.velocity = m.boolean("velocity").value_or(false);
        if (view) view->marks.push_back(std::move(v));
    }
    return s;
}

std::size_t body_named(const Scene& scene, const std::string& name, const TableReader& table, const std::string& key) {
    std::vector<std::string> names;
    for (const SceneBody& b : scene.bodies) names.push_back(b.name);
    const auto it = std::find(names.begin(), names.end(), name);
    if (it != names.end()) return static_cast<std::size_t>(it - names.begin());
    const std::string hint = closest_match(name, names);
    table.fail(key, "no body named '" + name + "'" + (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
}

Scene parse_scene_file(const std::string& path, SceneView* view) {
    std::string name;
    const std::string text = read_input_file(path, &name);
    return parse_scene_text(text, name, view);
}

}  // namespace collide
