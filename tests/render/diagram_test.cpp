// The renderer, headless: bodies drawn where the state says, arrows covering the pixels from
// their tail to their tip, the label glyphs, the figure layout, and a small golden image.
#include <cmath>
#include <cstdlib>
#include <memory>
#include <sstream>

#include <gtest/gtest.h>

#include "scenario/scene_file.h"
#include "render/context.h"
#include "render/convex_hull.h"
#include "render/draw2d.h"
#include "render/imgui_layer.h"
#include "render/overlay.h"
#include "render/renderer.h"
#include "render/target.h"
#include "test_util.h"

namespace collide::render {
namespace {

class RenderTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { context_ = create_gl_context(GlBackend::osmesa).release(); }
    static void TearDownTestSuite() {
        delete context_;
        context_ = nullptr;
    }
    static GlContext* context_;
};
GlContext* RenderTest::context_ = nullptr;

const char* kTwoDiscs = R"(
[scene]
dimension = 2
duration = 1.0
[[body]]
name = "left"
shape = "disc"
radius = 0.25
mass = 1.0
position = [-1.0, 0.0]
[[body]]
name = "right"
shape = "disc"
radius = 0.25
mass = 1.0
position = [1.0, 0.5]
v = [2.0, 0.0]
)";

RenderSettings small(int w, int h) {
    RenderSettings s;
    s.width = w;
    s.height = h;
    s.samples = 0;
    s.header = false;
    s.table = false;
    s.plots = false;
    s.timeline = false;
    return s;
}

Decor bare() {
    Decor d;
    d.velocities = false;
    d.labels = false;
    d.com = false;
    d.trails = false;
    d.impacts = false;
    return d;
}

TEST_F(RenderTest, ContextIsOffscreenOpenGL33OrLater) {
    EXPECT_STREQ(context_->backend_name(), "osmesa");
    EXPECT_NE(context_->description().find("Core Profile"), std::string::npos) << context_->description();
}

TEST_F(RenderTest, ADiscIsDrawnWhereTheStateSays) {
    const Scene scene = parse_scene_text(kTwoDiscs, "two-discs.toml");
    Renderer r(*context_, scene, small(320, 240));
    const FrameState f = frame_state(scene, 0.0, std::vector<Body2>{scene.bodies[0].body2, scene.bodies[1].body2});
    r.prepare({f}, {});
    const Image im = r.render(f, bare());
    const Palette palette;
    const Colour fill = palette.fills[1];  // the second moving body

    const ImVec2 c = r.to_screen(Vec3(1.0, 0.5, 0.0));
    const ImVec2 far = r.to_screen(Vec3(1.6, 0.5, 0.0));
    const ImVec2 other = r.to_screen(Vec3(-1.0, 0.0, 0.0));
    ASSERT_TRUE(c.x > 0 && c.x < 320 && c.y > 0 && c.y < 240);
    EXPECT_TRUE(test::near_colour(im.pixel(static_cast<int>(c.x), static_cast<int>(c.y)), fill, 4));
    EXPECT_TRUE(test::near_colour(im.pixel(static_cast<int>(far.x), static_cast<int>(far.y)), palette.background, 4));
    // x to the right, y up.
    EXPECT_GT(c.x, other.x);
    EXPECT_LT(c.y, other.y);

    // The filled pixels form a disc of the right radius around the right centre.
    // Counted: pixels near the centre that are not paper (fill, outline, radius line); the
    // outline is centred on the edge, so the count is the disc's area.
    const double ppm = r.diagram()->pixels_per_metre();
    const double r_px = 0.25 * ppm;
    double n = 0, sx = 0, sy = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const double dx = x + 0.5 - c.x, dy = y + 0.5 - c.y;
            if (dx * dx + dy * dy > 2.25 * r_px * r_px) continue;
            const std::uint8_t* p = im.pixel(x, y);
            double coverage = 0;  // how far from paper, 0..1, for anti-aliased edges
            for (int k = 0; k < 3; ++k) {
                const int paper = static_cast<int>((palette.background >> (8 * k)) & 0xFF);
                const int want = static_cast<int>((fill >> (8 * k)) & 0xFF);
                if (paper != want)
                    coverage =
                        std::max(coverage, std::min(1.0, std::abs(p[k] - paper) / std::abs(double(want - paper))));
            }
            n += coverage;
            sx += coverage * (x + 0.5);
            sy += coverage * (y + 0.5);
        }
    EXPECT_NEAR(n, kPi * r_px * r_px, 0.06 * kPi * r_px * r_px);
    EXPECT_NEAR(sx / n, c.x, 0.5);
    EXPECT_NEAR(sy / n, c.y, 0.5);
}

TEST_F(RenderTest, AVelocityArrowCoversThePixelsFromTheCentreToItsTip) {
    const Scene scene = parse_scene_text(kTwoDiscs, "two-discs.toml");
    Renderer r(*context_, scene, small(320, 240));
    const FrameState f = frame_state(scene, 0.0, std::vector<Body2>{scene.bodies[0].body2, scene.bodies[1].body2});
    r.prepare({f}, {});
    Decor d = bare();
    d.velocities = true;
    const Image im = r.render(f, d);
    const Palette palette;
    const double k = r.diagram()->metres_per_speed();
    ASSERT_GT(k, 0.0);
    const Vec3 centre(1.0, 0.5, 0.0), tip = centre + k * Vec3(2.0, 0.0, 0.0);
    // Along the shaft, outside the disc (the disc's edge is at 0.25 m), and the head near the tip.
    for (double s : {0.4, 0.6, 0.8, 0.97}) {
        const Vec3 p = centre + s * (tip - centre);
        if ((p - centre).norm() < 0.3) continue;
        const ImVec2 q = r.to_screen(p);
        // The pixel the segment passes through (the line is 1.5 px wide here).
        EXPECT_TRUE(test::near_colour(im.pixel(static_cast<int>(q.x), static_cast<int>(q.y)), palette.velocity, 60))
            << "at " << s << " of the arrow";
    }
    // Beside the arrow and beyond its tip: background.
    const ImVec2 beside = r.to_screen(centre + 0.6 * (tip - centre) + Vec3(0, 0.2, 0));
    const ImVec2 beyond = r.to_screen(tip + Vec3(0.15, 0, 0));
    EXPECT_TRUE(
        test::near_colour(im.pixel(static_cast<int>(beside.x), static_cast<int>(beside.y)), palette.background, 4));
    EXPECT_TRUE(
        test::near_colour(im.pixel(static_cast<int>(beyond.x), static_cast<int>(beyond.y)), palette.background, 4));
}

TEST_F(RenderTest, DrawArrowCoversTheSegmentAndNothingBeside) {
    const Gl& gl = context_->gl();
    RenderTarget target(gl, 240, 160, 0);
    ImGuiLayer imgui(gl, 240, 160, FontSizes::for_height(160));
    target.bind();
    gl.ClearColor(1, 1, 1, 1);
    gl.Clear(GL_COLOR_BUFFER_BIT);
    imgui.begin();
    const Colour red = rgb(200, 0, 0);
    const ImVec2 p(30, 40), q(200, 120);
    draw_arrow(imgui.draw_list(), p, q, red, 4.0f, 16.0f, 12.0f);
    imgui.end();
    Image im;
    im.width = 240;
    im.height = 160;
    im.rgba.resize(240 * 160 * 4);
    target.read_rgba(im.rgba.data());
    for (float s : {0.05f, 0.25f, 0.5f, 0.75f, 0.95f}) {
        const int x = static_cast<int>(p.x + s * (q.x - p.x)), y = static_cast<int>(p.y + s * (q.y - p.y));
        EXPECT_TRUE(test::near_colour(im.pixel(x, y), red, 30)) << "at " << s;
    }
    // 10 pixels off the line on either side, and beyond the tip.
    const float len = std::hypot(q.x - p.x, q.y - p.y);
    const float nx = -(q.y - p.y) / len, ny = (q.x - p.x) / len;
    for (float side : {-10.0f, 10.0f}) {
        const int x = static_cast<int>(0.5f * (p.x + q.x) + side * nx),
                  y = static_cast<int>(0.5f * (p.y + q.y) + side * ny);
        EXPECT_TRUE(test::near_colour(im.pixel(x, y), rgb(255, 255, 255), 2));
    }
    EXPECT_TRUE(test::near_colour(im.pixel(215, 127), rgb(255, 255, 255), 2));
}

TEST_F(RenderTest, EglGivesTheSameFrameWhereItIsAvailable) {
    if (!gl_backend_available(GlBackend::egl)) GTEST_SKIP() << "built without EGL";
#ifdef COLLIDE_SANITIZED  // COLLIDE_SANITIZE (clang has no __SANITIZE_ADDRESS__)
    // glvnd unloads Mesa's EGL driver at exit, and LeakSanitizer then reports the driver's
    // own allocations from an unnamed module, which no suppression can match.
    GTEST_SKIP() << "not under AddressSanitizer";
#endif
    std::unique_ptr<GlContext> egl;
    try {
        egl = create_gl_context(GlBackend::egl);
    } catch (const std::runtime_error& e) {
        GTEST_SKIP() << "no EGL display here: " << e.what();
    }
    EXPECT_STREQ(egl->backend_name(), "egl");
    const Scene scene = parse_scene_text(kTwoDiscs, "two-discs.toml");
    const FrameState f = frame_state(scene, 0.0, std::vector<Body2>{scene.bodies[0].body2, scene.bodies[1].body2});
    Image a, b;
    {
        Renderer r(*egl, scene, small(200, 150));
        r.prepare({f}, {});
        a = r.render(f, bare());
    }
    context_->make_current();
    Renderer r(*context_, scene, small(200, 150));
    r.prepare({f}, {});
    b = r.render(f, bare());
    int off = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) off += std::abs(a.rgba[i] - b.rgba[i]) > 8;
    EXPECT_LE(off, 50);
}

TEST_F(RenderTest, TheLabelFontHasGreekSubscriptsAndSuperscripts) {
    const Scene scene = parse_scene_text(kTwoDiscs, "two-discs.toml");
    Renderer r(*context_, scene, small(160, 120));
    EXPECT_TRUE(r.has_glyphs(
        "\u03C9 \u2090 \u1D66 \u207B\u00B9 \u00BD \u2264 \u221A \u2211 \u2212 \u00D7"));  // ω ₐ ᵦ ⁻¹ ½ ≤ √ ∑ − ×
    EXPECT_FALSE(r.has_glyphs("\u4E2D"));                                                 // not every glyph exists
}

TEST_F(RenderTest, FigurePlacesPanelsSideBySide) {
    std::vector<Image> panels(3);
    const std::uint8_t colours[3][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
    for (int k = 0; k < 3; ++k) {
        panels[k].width = 100;
        panels[k].height = 80;
        panels[k].rgba.resize(100 * 80 * 4);
        for (std::size_t i = 0; i < panels[k].rgba.size(); i += 4) {
            std::copy(colours[k], colours[k] + 3, panels[k].rgba.begin() + static_cast<std::ptrdiff_t>(i));
            panels[k].rgba[i + 3] = 255;
        }
    }
    const Image fig =
        compose_figure(*context_, panels, {"before", "at collision", "after"}, {"t = 1 s", "t = 2 s", "t = 3 s"}, 360);
    EXPECT_GT(fig.width, 300);
    EXPECT_GT(fig.height, 80);
    // Each panel's centre, left to right.
    const int y = 10 + 40;
    int found = 0;
    int last_x = -1;
    for (int k = 0; k < 3; ++k)
        for (int x = last_x + 1; x < fig.width; ++x)
            if (test::near_colour(fig.pixel(x, y), rgb(colours[k][0], colours[k][1], colours[k][2]), 2)) {
                ++found;
                last_x = x + 90;
                break;
            }
    EXPECT_EQ(found, 3);
}

// A small golden image: two bodies on the ground with velocity and spin arrows and a collision
// (impulse, normal, r vectors). Regenerate with COLLIDE_UPDATE_GOLDEN=1 after a deliberate
// change of the look, and look at the new file before committing it.
// A second line behind the semantic tests: the whole picture, labels on, against a golden
// image. The tolerance lets edge anti-aliasing round differently (every channel within 24, at
// most 0.2% of the pixels beyond), and the test shows that a reversed impulse breaks it.
TEST_F(RenderTest, GoldenDiagramMatchesWithinTolerance) {
    const char* text = R"(
[scene]
dimension = 2
duration = 1.0
gravity = [0.0, -9.81]
[[body]]
name = "ground"
shape = "plane"
normal = [0.0, 1.0]
offset = 0.0
[[body]]
name = "ball"
shape = "disc"
radius = 0.3
mass = 1.0
position = [-0.6, 0.8]
v = [1.0, -1.0]
w = 3.0
[[body]]
name = "box"
shape = "rectangle"
size = [0.6, 0.4]
mass = 2.0
position = [0.6, 0.2]
angle = 0.0
)";
    const Scene scene = parse_scene_text(text, "golden.toml");
    const auto draw = [&](double sign) {
        Renderer r(*context_, scene, small(320, 240));
        std::vector<Body2> bodies;
        for (const SceneBody& b : scene.bodies) bodies.push_back(b.body2);
        FrameState f = frame_state(scene, 0.0, bodies);
        ImpactMark im;
        im.a = 1;
        im.b = 2;
        im.point = Vec3(0.3, 0.3, 0.0);
        im.normal = Vec3(1.0, 0.0, 0.0);
        im.impulse = sign * Vec3(1.0, 0.2, 0.0);
        f.impacts.push_back(im);
        r.prepare({f}, {im});
        Decor d;  // labels, velocities, spin, impulse, normal, lever arms
        d.trails = false;
        return r.render(f, d);
    };
    const Image got = draw(1.0);
    const std::string golden = std::string(COLLIDE_RENDER_GOLDEN_DIR) + "/diagram-320x240.png";
    if (std::getenv("COLLIDE_UPDATE_GOLDEN")) {
        write_png_atomic(golden, got.width, got.height, got.rgba.data());
        GTEST_SKIP() << "golden image rewritten: " << golden;
    }
    const Image want = read_png(golden);
    ASSERT_EQ(want.width, got.width);
    ASSERT_EQ(want.height, got.height);
    const auto differing = [](const Image& a, const Image& b) {
        int off = 0;
        for (int y = 0; y < a.height; ++y)
            for (int x = 0; x < a.width; ++x)
                for (int c = 0; c < 3; ++c)
                    if (std::abs(a.pixel(x, y)[c] - b.pixel(x, y)[c]) > 24) {
                        ++off;
                        break;
                    }
        return off;
    };
    const int tolerance = got.width * got.height / 500;
    EXPECT_LE(differing(got, want), tolerance) << "see " << golden;
    EXPECT_GT(differing(draw(-1.0), want), 2 * tolerance);  // a reversed impulse is seen
}

// How wide (pixels) the stroke of `colour` is across the point `back` pixels behind `tip`,
// measured along the normal to `dir` (screen, unit) in half-pixel steps.
float width_behind(const Image& im, ImVec2 tip, ImVec2 dir, Colour colour, float back) {
    const ImVec2 n(-dir.y, dir.x);
    const ImVec2 c(tip.x - dir.x * back, tip.y - dir.y * back);
    float width = 0;
    for (const float sign : {1.0f, -1.0f})
        for (float s = 0.25f; s < 20.0f; s += 0.5f) {
            const int x = static_cast<int>(std::floor(c.x + n.x * s * sign));
            const int y = static_cast<int>(std::floor(c.y + n.y * s * sign));
            if (x < 0 || y < 0 || x >= im.width || y >= im.height || !test::near_colour(im.pixel(x, y), colour, 60))
                break;
            width += 0.5f;
        }
    return width;
}

// The list is what is drawn: for every velocity and impulse arrow of the 2D diagram's list,
// its head is where the list puts the tip, not at the tail; each spin arc's head is at the
// end its sweep gives. (annotation_test.cpp checks the list against the physics.)
TEST_F(RenderTest, EveryArrowOfTheListIsDrawnWithItsHeadAtItsTip) {
    const char* text = R"(
[scene]
dimension = 2
duration = 1.0
[[body]]
name = "a"
shape = "disc"
radius = 0.3
mass = 1.0
position = [-0.8, 0.0]
v = [2.0, 0.5]
w = 3.0
[[body]]
name = "b"
shape = "rectangle"
size = [0.6, 0.6]
mass = 1.0
position = [0.8, 0.2]
v = [-1.0, 0.0]
w = -2.0
)";
    const Scene scene = parse_scene_text(text, "arrows.toml");
    RenderSettings settings = small(1280, 720);
    Renderer r(*context_, scene, settings);
    std::vector<Body2> bodies;
    for (const SceneBody& b : scene.bodies) bodies.push_back(b.body2);
    FrameState f = frame_state(scene, 0.0, bodies);
    ImpactMark im;
    im.a = 0;
    im.b = 1;
    im.point = Vec3(0.0, 0.1, 0.0);
    im.normal = Vec3(1.0, 0.0, 0.0);
    im.impulse = Vec3(1.5, 0.3, 0.0);
    f.impacts.push_back(im);
    r.prepare({f}, {im});
    Decor d;
    d.labels = false;
    d.trails = false;
    d.com = false;
    const Image image = r.render(f, d);
    const Palette c;
    const Style style = Style::for_height(settings.height);
    // 0.6 of a head back from the tip an arrow's head is 0.6 head widths wide (7 px here; the
    // spin arcs' heads, 0.85 as large, 0.7 of theirs), the shaft 3 px: wider than 5 px is a head.
    const float back = style.lw(style.head_length) * 0.6f, head = 5.0f;
    int arrows = 0, spins = 0;
    for (const Annotation& a : r.annotations()) {
        if (a.kind == Mark::velocity || (a.kind == Mark::impulse && !a.faint)) {
            const ImVec2 p = r.to_screen(a.from), q = r.to_screen(a.to);
            const float len = std::hypot(q.x - p.x, q.y - p.y);
            ASSERT_GT(len, 3.0f * style.lw(style.head_length)) << mark_name(a.kind) << ": too short to tell";
            const ImVec2 u((q.x - p.x) / len, (q.y - p.y) / len);
            const Colour colour = a.kind == Mark::velocity ? c.velocity : c.impulse;
            EXPECT_GT(width_behind(image, q, u, colour, back), head) << mark_name(a.kind) << " of body " << a.body;
            EXPECT_LT(width_behind(image, p, ImVec2(-u.x, -u.y), colour, back), head)
                << mark_name(a.kind) << " of body " << a.body << " has a head at its tail";
            ++arrows;
        } else if (a.kind == Mark::spin) {
            // The arc is centred above the body: its ends at pi/2 -+ sweep/2 (world angles, y up).
            const ImVec2 centre = r.to_screen(a.from);
            const auto at = [&](double angle) {
                return ImVec2(centre.x + a.radius * static_cast<float>(std::cos(angle)),
                              centre.y - a.radius * static_cast<float>(std::sin(angle)));
            };
            const double end = 0.5 * kPi + 0.5 * a.sweep, start = 0.5 * kPi - 0.5 * a.sweep;
            const double sense = a.sweep > 0 ? 1.0 : -1.0;
            // The tangent along the sweep, on screen (y down).
            const auto tangent = [&](double angle, double s) {
                return ImVec2(static_cast<float>(-std::sin(angle) * s), static_cast<float>(-std::cos(angle) * s));
            };
            EXPECT_GT(width_behind(image, at(end), tangent(end, sense), c.spin, back), head)
                << "spin of body " << a.body;
            EXPECT_LT(width_behind(image, at(start), tangent(start, -sense), c.spin, back), head)
                << "spin of body " << a.body << " has its head at the start of the arc";
            ++spins;
        }
    }
    EXPECT_EQ(arrows, 3);  // two velocities, +P on b
    EXPECT_EQ(spins, 2);
}

// The numbers of a table cell ("1.50", "(3.00, −1.00)", U+2212 minus), read independently.
std::vector<double> cell_numbers(const std::string& cell) {
    std::string s;
    for (std::size_t i = 0; i < cell.size(); ++i) {
        if (cell.compare(i, 3, "\u2212") == 0) {
            s += '-';
            i += 2;
        } else {
            s += (cell[i] == '(' || cell[i] == ')' || cell[i] == ',') ? ' ' : cell[i];
        }
    }
    std::istringstream in(s);
    std::vector<double> out;
    for (double x; in >> x;) out.push_back(x);
    return out;
}

// A disc and a box, both moving and spinning: the table's and the overlays' tests.
const char* kDiscAndBox = R"(
[scene]
dimension = 2
duration = 1.0
[[body]]
name = "disc"
shape = "disc"
radius = 0.5
mass = 2.0
position = [-1.0, 0.0]
v = [1.5, -0.5]
w = 2.0
[[body]]
name = "box"
shape = "rectangle"
size = [0.6, 0.4]
mass = 3.0
position = [1.0, 0.0]
v = [-1.0, 0.25]
w = -1.0
)";

// The data table against the physics of the frame: v, then p = m v, E_k = m v.v / 2 + I w^2 / 2
// (a disc: I = m r^2 / 2; a rectangle: m (w^2 + h^2) / 12), and the totals, to the decimals
// shown.
TEST_F(RenderTest, TheTablesNumbersAreTheFramesMomentumAndEnergy) {
    const Scene scene = parse_scene_text(kDiscAndBox, "table.toml");
    ImGuiLayer imgui(context_->gl(), 640, 480, FontSizes::for_height(480));
    DataTable table(scene, Style::for_height(480));
    std::vector<Body2> bodies;
    for (const SceneBody& b : scene.bodies) bodies.push_back(b.body2);
    const FrameState f = frame_state(scene, 0.0, bodies);
    table.prepare(imgui.fonts(), {f});
    const auto rows = table.text(f);
    ASSERT_EQ(rows.size(), 4u);  // header, disc, box, totals
    EXPECT_EQ(rows[0].back().substr(0, 2), "E_");
    const double m[2] = {2.0, 3.0};
    const Vec2 v[2] = {Vec2(1.5, -0.5), Vec2(-1.0, 0.25)};
    const double w[2] = {2.0, -1.0};
    const double I[2] = {0.5 * 2.0 * 0.25, 3.0 * (0.36 + 0.16) / 12.0};
    Vec2 p_total = Vec2::Zero();
    double e_total = 0;
    for (int i = 0; i < 2; ++i) {
        SCOPED_TRACE(scene.bodies[static_cast<std::size_t>(i)].name);
        const auto& row = rows[static_cast<std::size_t>(i) + 1];
        ASSERT_EQ(row.size(), 6u);  // name, m, v, w, p, E_k
        const std::vector<double> mv = cell_numbers(row[1]), vv = cell_numbers(row[2]), wv = cell_numbers(row[3]),
                                  pv = cell_numbers(row[4]), ev = cell_numbers(row[5]);
        ASSERT_EQ(vv.size(), 2u);
        ASSERT_EQ(pv.size(), 2u);
        const Vec2 p = m[i] * v[i];
        const double e = 0.5 * m[i] * v[i].squaredNorm() + 0.5 * I[i] * w[i] * w[i];
        p_total += p;
        e_total += e;
        // Two decimals at least: half a unit of the last one.
        EXPECT_NEAR(mv[0], m[i], 0.005);
        EXPECT_NEAR(vv[0], v[i].x(), 0.005);
        EXPECT_NEAR(vv[1], v[i].y(), 0.005);
        EXPECT_NEAR(wv[0], w[i], 0.005);
        EXPECT_NEAR(pv[0], p.x(), 0.005);
        EXPECT_NEAR(pv[1], p.y(), 0.005);
        EXPECT_NEAR(ev[0], e, 0.005);
    }
    // The totals: name, mass, (no v, no w), p, E_k.
    const auto& total = rows[3];
    ASSERT_EQ(total.size(), 6u);
    const std::vector<double> mt = cell_numbers(total[1]), pt = cell_numbers(total[4]), et = cell_numbers(total[5]);
    ASSERT_EQ(pt.size(), 2u);
    EXPECT_NEAR(mt[0], 5.0, 0.005);
    EXPECT_NEAR(pt[0], p_total.x(), 0.005);
    EXPECT_NEAR(pt[1], p_total.y(), 0.005);
    EXPECT_NEAR(et[0], e_total, 0.005);
}

// The overlays are in the frame's list too, and the list is what they drew: every table cell
// carries its quantity (m, v, ω, p = m v, E_k = ½ m v² + ½ I ω², the totals) and prints it to
// the decimals shown, in a box holding ink; the formula's lines are the text asked for, the
// last in the impulse's red; each plot's dot is in its series' colour where the list puts it.
TEST_F(RenderTest, TheOverlaysListWhatTheyDraw) {
    const Scene scene = parse_scene_text(kDiscAndBox, "overlays.toml");
    RenderSettings s = small(960, 540);
    s.table = true;
    s.plots = true;
    s.formula.heading = "Collision of disc and box";
    s.formula.lines = {"j = 1 + 2 = 3 N s", "P = j n = (3, 0) N s"};
    Renderer r(*context_, scene, s);
    std::vector<Body2> bodies;
    for (const SceneBody& b : scene.bodies) bodies.push_back(b.body2);
    const FrameState f0 = frame_state(scene, 0.0, bodies);
    for (Body2& b : bodies) b.position += 0.5 * b.v;
    const FrameState f1 = frame_state(scene, 0.5, bodies);
    r.prepare({f0, f1}, {});
    const Image im = r.render(f1, Decor{});
    const Palette palette;
    const auto ink_in = [&](const ImVec4& box, Colour colour) {
        int n = 0;
        for (int y = static_cast<int>(box.y); y < static_cast<int>(std::ceil(box.w)); ++y)
            for (int x = static_cast<int>(box.x); x < static_cast<int>(std::ceil(box.z)); ++x)
                n += x >= 0 && y >= 0 && x < im.width && y < im.height && test::near_colour(im.pixel(x, y), colour, 60);
        return n;
    };
    const double m[2] = {2.0, 3.0}, w[2] = {2.0, -1.0};
    const Vec2 v[2] = {Vec2(1.5, -0.5), Vec2(-1.0, 0.25)};
    const double I[2] = {0.5 * 2.0 * 0.25, 3.0 * (0.36 + 0.16) / 12.0};
    const double E[2] = {0.5 * m[0] * v[0].squaredNorm() + 0.5 * I[0] * w[0] * w[0],
                         0.5 * m[1] * v[1].squaredNorm() + 0.5 * I[1] * w[1] * w[1]};
    const Vec2 p_total = m[0] * v[0] + m[1] * v[1];
    int cells = 0, lines = 0, dots = 0;
    for (const Annotation& a : r.annotations()) {
        if (a.kind == Mark::table_cell) {
            ++cells;
            EXPECT_GT(ink_in(a.box, a.body >= 0       ? palette.ink
                                    : a.value.empty() ? palette.muted
                                                      : palette.ink),
                      5)
                << a.text;
            if (a.value.empty()) continue;
            // What the cell stands for, by row and column: name, m, v, ω, p, E_k.
            std::vector<double> want;
            const int i = a.body;
            switch (a.of) {
                case 1: want = {i >= 0 ? m[i] : m[0] + m[1]}; break;
                case 2: want = {v[i].x(), v[i].y()}; break;
                case 3: want = {w[i]}; break;
                case 4:
                    want = i >= 0 ? std::vector<double>{m[i] * v[i].x(), m[i] * v[i].y()}
                                  : std::vector<double>{p_total.x(), p_total.y()};
                    break;
                case 5: want = {i >= 0 ? E[i] : E[0] + E[1]}; break;
                default: ADD_FAILURE() << "column " << a.of;
            }
            ASSERT_EQ(a.value.size(), want.size()) << a.text;
            const std::vector<double> shown = cell_numbers(a.text);
            ASSERT_EQ(shown.size(), want.size()) << a.text;
            for (std::size_t k = 0; k < want.size(); ++k) {
                EXPECT_NEAR(a.value[k], want[k], 1e-12) << a.text;
                EXPECT_NEAR(shown[k], want[k], 0.005) << a.text;  // two decimals at least
            }
        } else if (a.kind == Mark::formula_line) {
            const std::vector<std::string> want{s.formula.heading, s.formula.lines[0], s.formula.lines[1]};
            ASSERT_LT(lines, 3);
            EXPECT_EQ(a.text, want[static_cast<std::size_t>(lines)]);
            EXPECT_GT(ink_in(a.box, lines == 2 ? palette.impulse : palette.ink), 5) << a.text;
            ++lines;
        } else if (a.kind == Mark::plot_value) {
            ++dots;
            const int x = static_cast<int>(std::lround(a.anchor.x)), y = static_cast<int>(std::lround(a.anchor.y));
            EXPECT_TRUE(test::near_colour(im.pixel(x, y), a.colour, 40)) << a.text;
            if (a.text.find("kinetic") != std::string::npos) {
                EXPECT_NEAR(a.value[0], E[0] + E[1], 1e-9);
            }
        }
    }
    EXPECT_EQ(cells, 6 + 2 * 6 + 4);  // the header, two bodies, the totals (no v, no ω)
    EXPECT_EQ(lines, 3);
    EXPECT_GE(dots, 3);  // kinetic energy, p_x, p_y
}

// Given the totals just before and just after a collision, the plots step at its instant:
// a frame a little before it shows the value before, not one interpolated toward the after.
TEST_F(RenderTest, PlotsStepAtTheCollisionInstant) {
    const Scene scene = parse_scene_text(kTwoDiscs, "two-discs.toml");
    RenderSettings s = small(960, 540);
    s.plots = true;
    Renderer r(*context_, scene, s);
    const auto totals = [](double kinetic) {
        FrameTotals t;
        t.kinetic = kinetic;
        return t;
    };
    r.set_plot_totals({0.0, 0.5, 0.5, 1.0}, {totals(2.0), totals(2.0), totals(1.0), totals(1.0)});
    std::vector<Body2> bodies{scene.bodies[0].body2, scene.bodies[1].body2};
    const FrameState f0 = frame_state(scene, 0.0, bodies), f1 = frame_state(scene, 1.0, bodies);
    r.prepare({f0, f1}, {});
    const auto kinetic_at = [&](double t) {
        r.render(frame_state(scene, t, bodies), bare());
        for (const Annotation& a : r.annotations())
            if (a.kind == Mark::plot_value && a.text == "E_{k}") return a.value.at(0);
        ADD_FAILURE() << "no kinetic energy dot";
        return 0.0;
    };
    EXPECT_DOUBLE_EQ(kinetic_at(0.45), 2.0);
    EXPECT_DOUBLE_EQ(kinetic_at(0.55), 1.0);
}

// The time line's marker: solid velocity-blue pixels in the bottom strip; their centre.
double time_marker_x(const Image& im) {
    const Palette palette;
    double n = 0, sx = 0;
    for (int y = im.height - 60; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x)
            if (test::near_colour(im.pixel(x, y), palette.velocity, 12)) n += 1, sx += x + 0.5;
    return n > 0 ? sx / n : -1;
}

TEST_F(RenderTest, TheTimeLineMarksTheTimeInProportionAndTheFormulaEndsInTheImpulseColour) {
    const Scene scene = parse_scene_text(kTwoDiscs, "two-discs.toml");  // duration 1 s
    RenderSettings s = small(640, 360);
    s.timeline = true;
    s.formula = {"Collision", {"j = \u2212(1 + e) u_{n} / D", "P = 1 N s"}, ""};
    Renderer r(*context_, scene, s);
    const std::vector<Body2> bodies{scene.bodies[0].body2, scene.bodies[1].body2};
    std::vector<FrameState> frames;
    for (double t : {0.25, 0.5, 0.75}) frames.push_back(frame_state(scene, t, bodies));
    r.prepare(frames, {});
    std::vector<double> x;
    for (const FrameState& f : frames) x.push_back(time_marker_x(r.render(f, bare())));
    // Linear in time: equal steps, about half the frame's width from t = 0.25 to 0.75.
    ASSERT_GT(x[0], 0);
    EXPECT_NEAR(x[1] - x[0], x[2] - x[1], 1.5);
    EXPECT_GT(x[2] - x[0], 0.4 * 640);
    EXPECT_LT(x[2] - x[0], 0.5 * 640);
    // The formula's last line (the result) is drawn in the impulse's colour, at the bottom right.
    const Image im = r.render(frames[0], bare());
    int red = 0;  // reddish pixels: the impulse colour, anti-aliased on paper
    for (int y = im.height / 2; y < im.height; ++y)
        for (int x2 = im.width / 2; x2 < im.width; ++x2) {
            const std::uint8_t* p = im.pixel(x2, y);
            red += p[0] > p[1] + 60 && p[0] > p[2] + 60;
        }
    EXPECT_GT(red, 15);
    if (const char* dump = std::getenv("COLLIDE_TEST_DUMP"))
        write_png_atomic(dump, im.width, im.height, im.rgba.data());
}

TEST_F(RenderTest, TheScenariosCameraIsHonoured) {
    // From the front (azimuth 0, elevation 0) at a set target and distance: the target is at
    // the view's centre, +x goes right along the same row, +y straight up.
    const Scene scene = parse_scene_text(kTwoDiscs, "two-discs.toml");
    RenderSettings s = small(320, 240);
    s.view = ViewKind::perspective;
    s.camera = {0.0, 0.0, Vec3(0.2, 0.1, 0.0), 5.0};
    Renderer r(*context_, scene, s);
    const std::vector<Body2> bodies{scene.bodies[0].body2, scene.bodies[1].body2};
    r.prepare({frame_state(scene, 0.0, bodies)}, {});
    const ImVec2 c = r.to_screen(Vec3(0.2, 0.1, 0.0));
    EXPECT_NEAR(c.x, 160.0f, 0.5f);
    EXPECT_NEAR(c.y, 120.0f, 0.5f);
    const ImVec2 right = r.to_screen(Vec3(1.2, 0.1, 0.0)), up = r.to_screen(Vec3(0.2, 1.1, 0.0));
    EXPECT_GT(right.x, c.x + 10.0f);
    EXPECT_NEAR(right.y, c.y, 0.5f);
    EXPECT_NEAR(up.x, c.x, 0.5f);
    EXPECT_LT(up.y, c.y - 10.0f);
    // 1 m at 5 m with a 30 degree vertical field of view: 240 / (2 * 5 tan 15 deg) pixels.
    EXPECT_NEAR(c.y - up.y, 240.0 / (2.0 * 5.0 * std::tan(15.0 * kPi / 180.0)), 1.0);
}

// A 3D box is drawn at its pose: its corners, turned by the test's own rotation matrix and
// projected by a pinhole camera written here (from the front, at the scenario's distance, the
// 30 degree field of view), fall on the box's pixels just inside the silhouette and on the
// background just outside it (above its centre: below it lies its shadow). The box's pixels are those that change when the box is moved
// away. Drawn with the inverse rotation, the corners miss (checked here too).
TEST_F(RenderTest, ABoxIsDrawnAtItsOrientationIn3D) {
    const Scene scene = parse_scene_text(R"([scene]
dimension = 3
duration = 1.0
[[body]]
name = "box"
shape = "box"
size = [1.2, 0.5, 0.3]
mass = 1.0
position = [0.0, 1.0, 0.0]
)",
                                         "box.toml");
    const double D = 6.0, W = 320, H = 240;
    const Vec3 target(0.0, 1.0, 0.0);
    RenderSettings s = small(static_cast<int>(W), static_cast<int>(H));
    s.view = ViewKind::perspective;
    s.camera = {0.0, 0.0, target, D};
    const Eigen::AngleAxisd turn(0.7, Vec3(0.3, 0.5, 0.8).normalized());
    // The pinhole: the eye at target + D z, looking along -z, y up; f in pixels.
    const double f = H / (2.0 * std::tan(15.0 * kPi / 180.0));
    const auto project = [&](const Vec3& p) {
        const double k = f / (D - (p.z() - target.z()));
        return Vec2(0.5 * W + k * (p.x() - target.x()), 0.5 * H - k * (p.y() - target.y()));
    };
    const auto draw = [&](const Quat& q, const Vec3& at) {
        Body3 b = scene.bodies[0].body3;
        b.orientation = q;
        b.position = at;
        Renderer r(*context_, scene, s);
        const FrameState fs = frame_state(scene, 0.0, std::vector<Body3>{b});
        r.prepare({fs}, {});
        return r.render(fs, bare());
    };
    const Image away = draw(Quat::Identity(), Vec3(40.0, 40.0, -40.0));
    // How many of the checks a picture of the box fails.
    const auto misses = [&](const Image& im) {
        const auto is_box = [&](const Vec2& p) {
            const int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
            const auto* a = im.pixel(x, y);
            const auto* b = away.pixel(x, y);
            return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) > 30;
        };
        const Mat3 R = turn.toRotationMatrix();
        const Vec3 half(0.6, 0.25, 0.15);
        std::vector<Vec2> corners;
        const Vec2 centre = project(target);
        int missed = 0;
        for (int k = 0; k < 8; ++k) {
            const Vec3 c((k & 1) ? half.x() : -half.x(), (k & 2) ? half.y() : -half.y(),
                         (k & 4) ? half.z() : -half.z());
            corners.push_back(project(target + R * c));
            missed += !is_box(project(target + R * (0.85 * c)));  // inside the box: on it
        }
        for (const Vec2& v : convex_hull(corners)) {
            if (v.y() > centre.y()) continue;  // below the box: its shadow on the ground
            const Vec2 out = centre + (v - centre) * (1.0 + 8.0 / (v - centre).norm());  // 8 px outside
            missed += is_box(out);
        }
        return missed;
    };
    EXPECT_EQ(misses(draw(Quat(turn), target)), 0);
    EXPECT_GE(misses(draw(Quat(turn).conjugate(), target)), 4);  // the check sees the inverse
}

TEST_F(RenderTest, MultisamplingOnlyWhereTheBodiesAreGivesTheWholeFramesMultisampledPicture) {
    // The 3D view multisamples only the rectangle the bodies and arrows cover (msaa_region):
    // the frame must be the one multisampling everywhere gives, and differ from no MSAA.
    const Scene scene = parse_scene_text(kTwoDiscs, "two-discs.toml");
    const FrameState f = frame_state(scene, 0.0, std::vector<Body2>{scene.bodies[0].body2, scene.bodies[1].body2});
    Decor arrows = bare();
    arrows.velocities = true;
    const auto render = [&](int samples, bool region) {
        RenderSettings s = small(320, 240);
        s.view = ViewKind::perspective;
        s.samples = samples;
        s.msaa_region = region;
        Renderer r(*context_, scene, s);
        r.prepare({f}, {});
        return r.render(f, arrows);
    };
    const Image region = render(4, true), whole = render(4, false), none = render(0, false);
    const auto differing = [](const Image& a, const Image& b, int tolerance) {
        int n = 0;
        for (std::size_t i = 0; i < a.rgba.size(); i += 4)
            for (int c = 0; c < 3; ++c)
                if (std::abs(a.rgba[i + c] - b.rgba[i + c]) > tolerance) {
                    ++n;
                    break;
                }
        return n;
    };
    EXPECT_LE(differing(region, whole, 2), 320 * 240 / 1000);  // at most 0.1% of the pixels
    EXPECT_GE(differing(whole, none, 8), 200);                 // the edges MSAA smooths
    EXPECT_GE(differing(region, none, 8), 200);
}

TEST_F(RenderTest, PositiveDirectionArrowsPointAlongPlusX) {
    const Palette palette;
    // Muted grey pixels in a box (pixels), and their mean x.
    const auto grey = [&](const Image& im, int x0, int y0, int x1, int y1, double* mean_x) {
        int n = 0;
        double sx = 0;
        for (int y = std::max(0, y0); y < std::min(im.height, y1); ++y)
            for (int x = std::max(0, x0); x < std::min(im.width, x1); ++x)
                if (test::near_colour(im.pixel(x, y), palette.muted, 25)) ++n, sx += x;
        if (mean_x) *mean_x = n ? sx / n : 0;
        return n;
    };
    // 1D: an arrow over the block, centred on it, its head (more grey pixels) on the +x side.
    const Scene line = parse_scene_text(R"([scene]
dimension = 1
duration = 1.0
[[body]]
name = "cart"
shape = "block"
length = 0.5
mass = 1.0
position = 0.0
)",
                                        "line.toml");
    const FrameState f1 = frame_state(line, 0.0, std::vector<Body1>{line.bodies[0].body1});
    for (bool on : {false, true}) {
        RenderSettings s = small(400, 300);
        s.directions = on;
        Renderer r(*context_, line, s);
        r.prepare({f1}, {});
        const Image im = r.render(f1, bare());
        const ImVec2 top = r.to_screen(Vec3(0.0, 2.0 * block_height(line, 0) / 2.0, 0.0));
        double mean = 0;
        const int n = grey(im, static_cast<int>(top.x) - 60, static_cast<int>(top.y) - 50, static_cast<int>(top.x) + 60,
                           static_cast<int>(top.y) - 2, &mean);
        if (!on) {
            EXPECT_EQ(n, 0);
        } else {
            EXPECT_GT(n, 20);
            EXPECT_GT(mean, top.x);
            EXPECT_LT(mean, top.x + 10.0);
        }
    }
    // 2D: the +x, +y, +ω glyph in the lower left corner of the view.
    const Scene scene = parse_scene_text(kTwoDiscs, "two-discs.toml");
    const FrameState f2 = frame_state(scene, 0.0, std::vector<Body2>{scene.bodies[0].body2, scene.bodies[1].body2});
    std::vector<int> counts;
    for (bool on : {false, true}) {
        RenderSettings s = small(400, 300);
        s.directions = on;
        Renderer r(*context_, scene, s);
        r.prepare({f2}, {});
        const Image im = r.render(f2, bare());
        counts.push_back(grey(im, 0, 300 - 90, 90, 300, nullptr));
    }
    // (Anti-aliased outlines leave a few grey pixels without the glyph.)
    EXPECT_GT(counts[1], counts[0] + 40);
}

}  // namespace
}  // namespace collide::render
