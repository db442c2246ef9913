// What students see, read from annotations.json (render/annotation.h) for every bundled lesson
// and checked against the run's events.csv and against geometry: the collision panel draws
// +P on b and -P on a at the contact point, n from a into b, the lever arms from each centre
// to the contact point; every arrow points along the quantity it stands for; every spin arc
// turns in the sense of w; every label's number is its quantity at the precision shown; no
// two labels overlap.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "present/figures.h"
#include "cli/render_cmd.h"
#include "render/png.h"
#include "scenario/lesson.h"
#include "tests/render/test_util.h"

namespace collide {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// events.csv, by column name (the values as the file prints them: 10 significant digits).
struct EventRow {
    std::map<std::string, std::string> text;
    double num(const std::string& column) const { return std::stod(text.at(column)); }
};

std::vector<EventRow> read_events(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::vector<std::string> header;
    std::vector<EventRow> rows;
    const auto split = [](const std::string& s) {
        std::vector<std::string> cells;
        std::stringstream ss(s);
        for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
        return cells;
    };
    if (std::getline(in, line)) header = split(line);
    while (std::getline(in, line)) {
        const std::vector<std::string> cells = split(line);
        EventRow row;
        for (std::size_t k = 0; k < header.size() && k < cells.size(); ++k) row.text[header[k]] = cells[k];
        rows.push_back(row);
    }
    return rows;
}

// A point or vector of annotations.json (an array of D numbers; a number in 1D values).
std::vector<double> vec(const json& j) {
    if (j.is_number()) return {j.get<double>()};
    std::vector<double> v;
    for (const json& x : j) v.push_back(x.get<double>());
    return v;
}

// events.csv's vector `name` in `dimension` components ("point.x", ...; 1D: "point").
std::vector<double> event_vec(const EventRow& e, const std::string& name, int dimension) {
    if (dimension == 1) return {e.num(name)};
    const char* axes[3] = {".x", ".y", ".z"};
    std::vector<double> v;
    for (int k = 0; k < dimension; ++k) v.push_back(e.num(name + axes[k]));
    return v;
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
    double s = 0;
    for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) s += a[k] * b[k];
    return s;
}
double norm(const std::vector<double>& a) { return std::sqrt(dot(a, a)); }
std::vector<double> minus(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> d(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) d[k] = a[k] - b[k];
    return d;
}

// events.csv prints 10 significant digits: values agree to that, relative to their scale.
bool same(const std::vector<double>& a, const std::vector<double>& b, double scale) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (std::abs(a[k] - b[k]) > 1e-9 * std::max(scale, 1e-3)) return false;
    return true;
}

// Whether `d` points along `v` (same sense; parallel to 1e-6 of their lengths).
bool along(const std::vector<double>& d, const std::vector<double>& v) {
    const double nd = norm(d), nv = norm(v);
    if (nd == 0 || nv == 0) return false;
    return dot(d, v) / (nd * nv) > 1.0 - 1e-6;
}

// The number a label prints after "= ": "1.50", "−1.20" (U+2212), "2.42×10⁻⁵"; NaN when
// there is none. Read here independently of the renderer's formatting.
double label_number(const std::string& text, int* significant) {
    std::size_t at = text.find("= ");
    if (at == std::string::npos) return std::nan("");
    at += 2;
    double sign = 1.0;
    const std::string minus_sign = "\u2212";
    if (text.compare(at, minus_sign.size(), minus_sign) == 0) {
        sign = -1.0;
        at += minus_sign.size();
    } else if (text[at] == '-') {
        return std::nan("");  // a hyphen is not the minus sign labels use
    }
    std::size_t end = at;
    int digits = 0;
    bool leading = true;
    while (end < text.size() && (std::isdigit(static_cast<unsigned char>(text[end])) || text[end] == '.')) {
        if (text[end] != '.') {
            if (text[end] != '0') leading = false;
            if (!leading) ++digits;
        }
        ++end;
    }
    if (end == at) return std::nan("");
    double x = std::stod(text.substr(at, end - at));
    const std::string times10 = "\u00D710";
    if (text.compare(end, times10.size(), times10) == 0) {
        std::size_t p = end + times10.size();
        static const std::vector<std::string> sup = {"\u2070", "\u00B9", "\u00B2", "\u00B3", "\u2074",
                                                     "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
        int e = 0, e_sign = 1;
        if (text.compare(p, 3, "\u207B") == 0) {
            e_sign = -1;
            p += 3;
        }
        for (bool more = true; more;) {
            more = false;
            for (int d = 0; d < 10; ++d)
                if (text.compare(p, sup[static_cast<std::size_t>(d)].size(), sup[static_cast<std::size_t>(d)]) == 0) {
                    e = 10 * e + d;
                    p += sup[static_cast<std::size_t>(d)].size();
                    more = true;
                    break;
                }
        }
        x *= std::pow(10.0, e_sign * e);
    }
    if (significant) *significant = digits;
    return sign * x;
}

// The number a label should print for the item it labels (render/annotation.h). The 2D
// diagram: in 1D the signed velocity or impulse along +x, else the magnitude of its front view
// (x, y); a spin's w about +z. The 3D view: magnitudes.
double labelled_quantity(const json& item, int dimension, bool three_d) {
    const std::vector<double> v = vec(item["value"]);
    const std::string kind = item["kind"];
    if (three_d) return norm(v);
    if (kind == "spin") return v.size() == 3 ? v[2] : v[0];
    if (dimension == 1) return v[0];
    return std::hypot(v[0], v[1]);
}

struct LessonFile {
    std::string id;
    std::string path;
};

std::vector<LessonFile> bundled_lessons() {
    std::vector<LessonFile> out;
    for (const auto& e : fs::directory_iterator(fs::path(COLLIDE_SOURCE_DIR) / "lessons"))
        if (e.path().extension() == ".toml") out.push_back({e.path().stem().string(), e.path().string()});
    std::sort(out.begin(), out.end(), [](const LessonFile& a, const LessonFile& b) { return a.id < b.id; });
    return out;
}

void PrintTo(const LessonFile& lesson, std::ostream* os) { *os << lesson.id; }

// Distance from c to a convex polygon (pixels), 0 inside it.
double outline_distance(const std::vector<std::array<double, 2>>& poly, const std::array<double, 2>& c) {
    double best = 1e300;
    int sign = 0;
    bool inside = poly.size() >= 3;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        const std::array<double, 2>& a = poly[k];
        const std::array<double, 2>& b = poly[(k + 1) % poly.size()];
        const double ex = b[0] - a[0], ey = b[1] - a[1], px = c[0] - a[0], py = c[1] - a[1];
        const double cr = ex * py - ey * px;
        if (cr != 0) {
            const int sg = cr > 0 ? 1 : -1;
            if (sign == 0) sign = sg;
            else if (sg != sign) inside = false;
        }
        const double len2 = ex * ex + ey * ey;
        const double t = len2 > 0 ? std::clamp((px * ex + py * ey) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(px - t * ex, py - t * ey));
    }
    return inside ? 0.0 : best;
}

class LessonFigure : public ::testing::TestWithParam<LessonFile> {};

void check_figure(const std::string& file, const ::collide::LessonFigure* pick, const std::vector<EventRow>& events,
                  const json& data);

TEST_P(LessonFigure, AnnotationsAgreeWithTheEventsAndTheGeometry) {
    render::test::TempDir dir;
    RenderOptions o;
    o.scenario = GetParam().path;
    o.out_dir = dir / "out";
    // The default size: the figure students see (smaller frames crowd the labels).
    o.fps = 2;  // few frames: the figure is what is checked
    o.quiet = true;
    std::ostringstream out, err;
    ASSERT_EQ(run_render(o, out, err), 0) << err.str();

    const std::vector<EventRow> events = read_events(dir / "out/events.csv");
    std::ifstream data_in(dir / "out/data.json");
    const json data = json::parse(data_in);
    ASSERT_FALSE(events.empty()) << "every bundled lesson has a collision";
    // Each figure: figure.png (annotations.json), then a lesson's next [[figure]] entries
    // (annotations-K.json), each about its pair's collision.
    const collide::Lesson lesson = load_lesson(GetParam().path);
    const std::size_t figures = std::max<std::size_t>(1, lesson.figures.size());
    for (std::size_t fig = 0; fig < figures; ++fig)
        check_figure(dir / (fig == 0 ? std::string("out/annotations.json")
                                     : "out/annotations-" + std::to_string(fig + 1) + ".json"),
                     lesson.figures.empty() ? nullptr : &lesson.figures[fig], events, data);
}

// One figure's annotations against the run: `pick` the [[figure]] it shows (nullptr: the
// run's first collision); only that pair's events are drawn at its collision.
void check_figure(const std::string& file, const ::collide::LessonFigure* pick, const std::vector<EventRow>& events,
                  const json& data) {
    SCOPED_TRACE(file);
    std::ifstream in(file);
    ASSERT_TRUE(in) << "no " << file;
    const json doc = json::parse(in);
    const int dim = doc["dimension"];
    const bool three_d = doc["view"] == "3d";

    // Readable at the size the site shows it: a figure wider than the text column is shown in
    // the wide box, the others in the column (style.css; width: 100%, so each is scaled to
    // exactly that width), and every label's text is then at least 12 px tall.
    std::string png = file;
    png.replace(png.rfind("annotations"), std::string("annotations").size(), "figure");
    png.replace(png.rfind(".json"), 5, ".png");
    const int width = render::read_png(png).width;
    const double shown = width > kColumnWidth ? kWideFigureWidth : kColumnWidth;
    EXPECT_LE(width, kWideFigureWidth) << png << " is wider than the site shows it";
    for (const char* panel : {"before", "at", "after"})
        for (const json& it : doc["panels"][panel])
            if (it["kind"] == "label") {
                EXPECT_GE(it["font_px"].get<double>() * shown / width, 12.0)
                    << "the label \"" << it["text"] << "\" of " << png << " shows "
                    << it["font_px"].get<double>() * shown / width << " px tall";
                EXPECT_LE(it["font_px"].get<double>(), it["box"][3].get<double>() - it["box"][1].get<double>() + 1e-3)
                    << "a label's text is taller than its box";
            }

    const auto in_pick = [&](const std::string& a, const std::string& b) {
        return !pick || (a == pick->a && b == pick->b) || (a == pick->b && b == pick->a);
    };
    ASSERT_TRUE(doc["panels"].contains("at"));

    // The collision panel is the instant of the figure's collision: the run's first, or the
    // pick's (its pair's `collision`-th instant).
    const double t_at = doc["times"]["at"];
    std::vector<double> pair_times;
    for (const EventRow& e : events)
        if (in_pick(e.text.at("a"), e.text.at("b")) &&
            (pair_times.empty() || e.num("t") > pair_times.back() + 1e-9 * std::max(1.0, e.num("t"))))
            pair_times.push_back(e.num("t"));
    const std::size_t order = pick ? static_cast<std::size_t>(pick->collision) : 1;
    ASSERT_GE(pair_times.size(), order);
    EXPECT_NEAR(t_at, pair_times[order - 1], 1e-9 * std::max(1.0, t_at));
    std::vector<const EventRow*> now;  // the events of that instant (of that pair)
    for (const EventRow& e : events)
        if (std::abs(e.num("t") - t_at) <= 1e-9 * std::max(1.0, t_at) && in_pick(e.text.at("a"), e.text.at("b")))
            now.push_back(&e);

    int impulses_on_b = 0;
    for (const char* panel : {"before", "at", "after"}) {
        SCOPED_TRACE(panel);
        const json& items = doc["panels"][panel];
        std::map<std::string, std::vector<double>> centre;  // body name -> drawn centre
        for (const json& it : items)
            if (it["kind"] == "body") centre[it["body"]] = vec(it["from"]);
        std::vector<std::vector<double>> contacts;
        for (const json& it : items)
            if (it["kind"] == "contact") contacts.push_back(vec(it["from"]));

        for (const json& it : items) {
            const std::string kind = it["kind"];
            SCOPED_TRACE(it.dump());
            const std::vector<double> from = vec(it["from"]), to = vec(it["to"]);
            if (kind == "impulse") {
                ASSERT_EQ(std::string(panel), "at") << "impulses are drawn at the collision only";
                // +P on b, -P on a, from the contact point, each matching an event of the instant.
                const std::string body = it["body"];
                const std::vector<double> P = vec(it["value"]);
                bool found = false;
                for (const EventRow* e : now) {
                    const std::vector<double> Pe = event_vec(*e, "impulse", dim);
                    const std::vector<double> p = event_vec(*e, "point", dim);
                    std::vector<double> minusPe = Pe;
                    for (double& x : minusPe) x = -x;
                    const double scale = norm(Pe);
                    if (!same(from, p, std::max(1.0, norm(p)))) continue;
                    if (body == e->text.at("b") && same(P, Pe, scale)) {
                        found = true;
                        ++impulses_on_b;
                    }
                    if (body == e->text.at("a") && same(P, minusPe, scale)) found = true;
                }
                EXPECT_TRUE(found) << "an impulse arrow that is no event's +P on b or -P on a";
                EXPECT_TRUE(along(minus(to, from), P)) << "the impulse arrow points against its value";
            } else if (kind == "normal") {
                const std::vector<double> n = vec(it["value"]);
                EXPECT_NEAR(norm(n), 1.0, 1e-12);
                bool found = false;
                for (const EventRow* e : now) {
                    // In the figure's roles: a [[figure]] may call the engine's b its a, and
                    // then draws the normal the other way (still from its a into its b).
                    const bool swapped = pick && e->text.at("a") == pick->b;
                    const std::string a = e->text.at(swapped ? "b" : "a"), b = e->text.at(swapped ? "a" : "b");
                    std::vector<double> en = event_vec(*e, "normal", dim);
                    if (swapped)
                        for (double& x : en) x = -x;
                    if (!same(n, en, 1.0)) continue;
                    found = true;
                    // From a into b: b's centre lies on the +n side of the contact point, a's on
                    // the -n side (convex bodies; ground and walls have no centre drawn).
                    const std::vector<double> p = event_vec(*e, "point", dim);
                    if (centre.count(b)) {
                        EXPECT_GT(dot(minus(centre[b], p), n), 0.0) << "n does not point into b";
                    }
                    if (centre.count(a)) {
                        EXPECT_LT(dot(minus(centre[a], p), n), 0.0) << "n does not point out of a";
                    }
                }
                EXPECT_TRUE(found) << "a normal that is no event's";
                EXPECT_TRUE(along(minus(to, from), n));
            } else if (kind == "lever_arm") {
                // From the body's centre to a contact point.
                ASSERT_TRUE(centre.count(it["body"]));
                EXPECT_TRUE(same(from, centre[it["body"]], 1.0));
                bool at_contact = false;
                for (const auto& c : contacts) at_contact = at_contact || same(to, c, 1.0);
                EXPECT_TRUE(at_contact) << "a lever arm that does not end at the contact point";
                EXPECT_TRUE(same(vec(it["value"]), minus(to, from), 1.0));
            } else if (kind == "velocity") {
                ASSERT_TRUE(centre.count(it["body"]));
                // From the centre (the 3D view: from where the ray along v leaves the surface).
                const std::vector<double> out_of = minus(from, centre[it["body"]]);
                EXPECT_TRUE(same(from, centre[it["body"]], 1.0) || (three_d && along(out_of, vec(it["value"]))))
                    << "a velocity not drawn from the centre";
                EXPECT_TRUE(along(minus(to, from), vec(it["value"]))) << "a velocity arrow against v";
            } else if (kind == "point_velocity") {
                // A marked point's velocity, from the point: v + ω × (p − x) of its body as
                // the panel draws the body (a velocity or spin not drawn is zero).
                ASSERT_TRUE(centre.count(it["body"]));
                std::vector<double> v(static_cast<std::size_t>(dim), 0.0), w;
                for (const json& o : items) {
                    if (o["body"] != it["body"]) continue;
                    if (o["kind"] == "velocity") v = vec(o["value"]);
                    if (o["kind"] == "spin") w = vec(o["value"]);
                }
                const std::vector<double> r = minus(from, centre[it["body"]]);
                std::vector<double> expected = v;
                if (dim == 2 && !w.empty()) {
                    expected[0] -= w[0] * r[1];
                    expected[1] += w[0] * r[0];
                }
                EXPECT_TRUE(same(vec(it["value"]), expected, std::max(1.0, norm(expected))))
                    << "a point's velocity that is not v + w x r of its body";
                EXPECT_TRUE(along(minus(to, from), vec(it["value"]))) << "a point's velocity arrow against it";
            } else if (kind == "spin") {
                const double sweep = it["sweep"];
                if (three_d) {
                    // An arrow along w, its curl counter-clockwise seen from the tip.
                    EXPECT_TRUE(along(minus(to, from), vec(it["value"]))) << "a spin arrow against w";
                    EXPECT_GT(sweep, 0.0) << "the curl turns against the right-hand rule";
                } else {
                    EXPECT_GT(labelled_quantity(it, dim, false) * sweep, 0.0) << "the spin arc turns against w";
                }
            } else if (kind == "label" && !it["value"].is_null()) {
                // The number printed is the value at the precision shown (3 significant
                // figures), and the value is the labelled item's.
                int digits = 0;
                const double shown = label_number(it["text"], &digits);
                const double value = it["value"];
                ASSERT_FALSE(std::isnan(shown)) << "a label with a value but no number";
                EXPECT_EQ(digits, 3);
                const double ulp = std::pow(10.0, std::floor(std::log10(std::abs(value))) - 2);
                EXPECT_LE(std::abs(shown - value), 0.5 * ulp * (1 + 1e-9)) << "the label misprints its value";
                const int of = it["of"];
                ASSERT_GE(of, 0);
                ASSERT_LT(of, static_cast<int>(items.size()));
                EXPECT_NEAR(labelled_quantity(items[static_cast<std::size_t>(of)], dim, three_d), value,
                            1e-12 * std::max(1.0, std::abs(value)));
            }
        }
        if (std::string(panel) == "at") {
            // One contact point and (2D, 3D: in 1D n is the axis) one normal per event.
            std::size_t normals = 0;
            for (const json& it : items) normals += it["kind"] == "normal" ? 1 : 0;
            EXPECT_EQ(contacts.size(), now.size()) << "contact points";
            if (dim > 1 || three_d) {
                EXPECT_EQ(normals, now.size()) << "normals";
            }
        }
        // Before and after carry the numbers of the instant: each velocity and spin of a body
        // in one of its events is the event's just before (just after), as data.json gives
        // them at full precision.
        if (std::string(panel) != "at") {
            const char* when = std::string(panel) == "before" ? "before" : "after";
            for (const json& it : items) {
                const std::string kind = it["kind"];
                if (kind != "velocity" && kind != "spin") continue;
                const std::string body = it["body"];
                for (const json& e : data["events"]) {
                    if (std::abs(e["t"].get<double>() - t_at) > 1e-9 * std::max(1.0, t_at)) continue;
                    if (!in_pick(e["a"], e["b"])) continue;
                    if (!e[when].contains(body)) continue;
                    const std::vector<double> expected = vec(e[when][body][kind == "velocity" ? "v" : "w"]);
                    const std::vector<double> drawn = vec(it["value"]);
                    EXPECT_TRUE(same(drawn, expected, std::max(1.0, norm(expected))))
                        << body << "'s " << kind << " " << when << " is not the instant's";
                    break;  // the first event the body is in
                }
            }
        }
        // Before and after are recorded frames: every body is drawn at that frame's pose
        // (data.json, full precision; a quaternion and its negative are one orientation).
        // (With no frame between this collision and the next, "after" is the instant itself.)
        if (std::string(panel) != "at" && doc["times"][panel] != doc["times"]["at"]) {
            const double t = doc["times"][panel];
            const json* frame = nullptr;
            for (const json& fr : data["frames"])
                if (std::abs(fr["t"].get<double>() - t) <= 1e-9 * std::max(1.0, t)) frame = &fr;
            if (frame) {
                for (const json& it : items) {
                    if (it["kind"] != "body") continue;
                    const std::string body = it["body"];
                    const json& b = (*frame)["bodies"][body];
                    const std::vector<double> pose = vec(it["value"]), x = vec(b["x"]);
                    ASSERT_GE(pose.size(), x.size());
                    EXPECT_TRUE(same(std::vector<double>(pose.begin(), pose.begin() + static_cast<long>(x.size())), x,
                                     std::max(1.0, norm(x))))
                        << body << " is not drawn where the frame has it";
                    if (b.contains("angle")) {
                        EXPECT_NEAR(pose.at(2), b["angle"].get<double>(), 1e-9) << body << "'s angle";
                    }
                    if (b.contains("orientation")) {
                        const std::vector<double> q(pose.begin() + 3, pose.end()), qf = vec(b["orientation"]);
                        EXPECT_NEAR(std::abs(dot(q, qf)), 1.0, 1e-9) << body << "'s orientation";
                    }
                }
            } else {
                ADD_FAILURE() << "no frame of data.json at the " << panel << " panel's time";
            }
        }
        // Labels carry their units, as the page and the text write them: velocities m/s, spins
        // rad/s, impulses N s.
        for (const json& it : items) {
            if (it["kind"] != "label" || it["value"].is_null()) continue;
            const std::string labelled = items[it["of"].get<std::size_t>()]["kind"];
            const std::string text = it["text"];
            const std::string unit = labelled == "velocity" || labelled == "point_velocity" ? " m/s"
                                     : labelled == "spin"                                   ? " rad/s"
                                                                                            : " N s";
            EXPECT_TRUE(text.size() > unit.size() && text.compare(text.size() - unit.size(), unit.size(), unit) == 0)
                << "\"" << text << "\" does not end in \"" << unit << "\"";
        }
        // 3D: every label of a body sits nearer that body's projected outline than any other
        // body's (its box's centre; distance 0 inside an outline): a velocity or spin label
        // never stands beside another body.
        if (three_d) {
            std::map<std::string, std::vector<std::array<double, 2>>> outlines;
            for (const json& it : items)
                if (it["kind"] == "body" && it.contains("outline"))
                    for (const json& q : it["outline"]) outlines[it["body"]].push_back({q[0], q[1]});
            for (const json& it : items) {
                if (it["kind"] != "label" || it["body"].is_null() || !outlines.count(it["body"])) continue;
                const std::array<double, 2> c = {0.5 * (it["box"][0].get<double>() + it["box"][2].get<double>()),
                                                 0.5 * (it["box"][1].get<double>() + it["box"][3].get<double>())};
                const std::string own = it["body"];
                const double mine = outline_distance(outlines[own], c);
                for (const auto& [other, poly] : outlines)
                    if (other != own) {
                        EXPECT_LT(mine, outline_distance(poly, c))
                            << "the label \"" << it["text"] << "\" of " << own << " stands nearer " << other;
                    }
            }
        }
        // No arrow shaft (velocity, impulse, a point's velocity) runs through a body's name
        // (the 2D diagram: an arrow's box is its extent, and its screen direction is the
        // world's with y flipped, so the shaft is the box's diagonal along it).
        if (!three_d) {
            for (const json& name : items) {
                if (name["kind"] != "label" || name["of"].get<int>() < 0) continue;
                if (items[name["of"].get<std::size_t>()]["kind"] != "body") continue;
                const std::vector<double> nb = name["box"].get<std::vector<double>>();
                for (const json& arrow : items) {
                    const std::string k = arrow["kind"];
                    if (k != "velocity" && k != "impulse" && k != "point_velocity") continue;
                    const std::vector<double> b = arrow["box"].get<std::vector<double>>();
                    const std::vector<double> d = minus(vec(arrow["to"]), vec(arrow["from"]));
                    const double dx = d[0], dy = d.size() > 1 ? d[1] : 0.0;
                    const double px = dx >= 0 ? b[0] : b[2], py = dy >= 0 ? b[3] : b[1];
                    const double qx = dx >= 0 ? b[2] : b[0], qy = dy >= 0 ? b[1] : b[3];
                    // Liang-Barsky: does p-q pass through the name's box (shrunk by a pixel)?
                    double t0 = 0, t1 = 1;
                    const double e[4][2] = {{-(qx - px), px - (nb[0] + 1)},
                                            {qx - px, (nb[2] - 1) - px},
                                            {-(qy - py), py - (nb[1] + 1)},
                                            {qy - py, (nb[3] - 1) - py}};
                    bool outside = false;
                    for (const auto& c : e) {
                        if (c[0] == 0) {
                            outside = outside || c[1] < 0;
                        } else if (c[0] < 0) {
                            t0 = std::max(t0, c[1] / c[0]);
                        } else {
                            t1 = std::min(t1, c[1] / c[0]);
                        }
                    }
                    EXPECT_FALSE(!outside && t0 < t1)
                        << "the " << k << " arrow of " << arrow["body"] << " runs through the name " << name["text"];
                }
            }
        }
        // No two labels overlap (their boxes, padding included, may touch).
        std::vector<std::vector<double>> boxes;
        for (const json& it : items)
            if (it["kind"] == "label") boxes.push_back(it["box"].get<std::vector<double>>());
        for (std::size_t i = 0; i < boxes.size(); ++i)
            for (std::size_t j = i + 1; j < boxes.size(); ++j) {
                const double w = std::min(boxes[i][2], boxes[j][2]) - std::max(boxes[i][0], boxes[j][0]);
                const double h = std::min(boxes[i][3], boxes[j][3]) - std::max(boxes[i][1], boxes[j][1]);
                EXPECT_FALSE(w > 0.5 && h > 0.5) << "labels " << i << " and " << j << " overlap";
            }
    }
    EXPECT_GT(impulses_on_b, 0) << "the collision panel draws no impulse on b";
}

INSTANTIATE_TEST_SUITE_P(Bundled, LessonFigure, ::testing::ValuesIn(bundled_lessons()),
                         [](const ::testing::TestParamInfo<LessonFile>& info) {
                             std::string name;
                             for (char c : info.param.id) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                             return name;
                         });

}  // namespace
}  // namespace collide
