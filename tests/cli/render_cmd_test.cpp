// `collide render` end to end on tiny scenes: the files it writes, and its refusals.
#include "cli/render_cmd.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "present/figures.h"
#include "render/png.h"
#include "render/video.h"
#include "tests/render/test_util.h"

namespace collide {
namespace {

namespace fs = std::filesystem;

const char* kCollision2d = R"([scene]
title = "Two discs"
dimension = 2
duration = 0.5
restitution = 1.0
[[body]]
name = "a"
shape = "disc"
radius = 0.1
mass = 1.0
position = [-0.3, 0.0]
v = [2.0, 0.0]
[[body]]
name = "b"
shape = "disc"
radius = 0.1
mass = 1.0
position = [0.3, 0.05]
)";

std::string write(const render::test::TempDir& dir, const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
}

RenderOptions tiny(const std::string& scenario, const std::string& out) {
    RenderOptions o;
    o.scenario = scenario;
    o.out_dir = out;
    o.size = "160x120";
    o.fps = 10;
    o.quiet = true;
    return o;
}

std::size_t lines(const std::string& path) {
    std::ifstream in(path);
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
}

TEST(RenderCommand, WritesFramesStillsFigureAndData) {
    render::test::TempDir dir;
    const std::string scenario = write(dir, "s.toml", kCollision2d);
    std::ostringstream out, err;
    ASSERT_EQ(run_render(tiny(scenario, dir / "out"), out, err), 0) << err.str();
    // 0.5 s at 10 frames/s: frames at 0, 0.1, ..., 0.5.
    for (int k = 0; k <= 5; ++k) {
        char name[40];
        std::snprintf(name, sizeof name, "out/frames/frame_%05d.png", k);
        const render::Image im = render::read_png(dir / name);
        EXPECT_EQ(im.width, 160);
        EXPECT_EQ(im.height, 120);
    }
    EXPECT_FALSE(fs::exists(dir / "out/frames/frame_00006.png"));
    for (const char* still : {"before.png", "at.png", "after.png"})
        EXPECT_EQ(render::read_png(dir / (std::string("out/") + still)).width, 160) << still;
    const render::Image figure = render::read_png(dir / "out/figure.png");
    // Laid out for the site's text column (present/figures.h), scaled to the 120-pixel size: the
    // wide strips of this scene (two discs on a line) stacked, three of them.
    EXPECT_NEAR(figure.width, kColumnWidth * 120.0 / 720.0, 2.0);
    EXPECT_GT(figure.height, figure.width);
    EXPECT_EQ(lines(dir / "out/data.csv"), 7u);    // header + 6 frames
    EXPECT_EQ(lines(dir / "out/events.csv"), 2u);  // header + the collision
    std::ifstream in(dir / "out/data.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["title"], "Two discs");
    EXPECT_EQ(j["frames"].size(), 6u);
    ASSERT_EQ(j["events"].size(), 1u);
    EXPECT_EQ(j["events"][0]["a"], "a");
    EXPECT_NEAR(j["frames"][5]["t"].get<double>(), 0.5, 1e-12);
    // The worked example of the collision: equal discs, e = 1, so j = -(1 + e) u_n / D with
    // D = 2/m is -u_n; the event's impulse along the normal is the same number.
    std::ifstream md_in(dir / "out/worked-example.md");
    const std::string md((std::istreambuf_iterator<char>(md_in)), std::istreambuf_iterator<char>());
    EXPECT_NE(md.find("# a and b at t = "), std::string::npos) << md;
    EXPECT_NE(md.find("model frictionless, e = 1"), std::string::npos) << md;
    const auto& ev = j["events"][0];
    const double jn = ev["impulse"][0].get<double>() * ev["normal"][0].get<double>() +
                      ev["impulse"][1].get<double>() * ev["normal"][1].get<double>();
    const double ua = ev["before"]["a"]["v"][0].get<double>() * ev["normal"][0].get<double>();
    EXPECT_NEAR(jn, ua, 1e-9);  // -u_n = the approach speed along n (b at rest, m = 1)
    // Nothing half-written is left behind.
    for (const auto& e : fs::recursive_directory_iterator(dir / "out"))
        EXPECT_EQ(e.path().string().find(".tmp-"), std::string::npos) << e.path();
}

TEST(RenderCommand, OneDimensionalAndThreeDimensionalScenesRender) {
    render::test::TempDir dir;
    const std::string one = write(dir, "1d.toml", R"([scene]
dimension = 1
duration = 0.4
[[body]]
name = "cart"
shape = "block"
length = 0.2
mass = 1.0
position = -0.3
v = 2.0
[[body]]
name = "wall"
shape = "block"
length = 0.2
static = true
position = 0.3
)");
    const std::string three = write(dir, "3d.toml", R"([scene]
dimension = 3
duration = 0.4
[[body]]
name = "ball"
shape = "sphere"
radius = 0.1
mass = 1.0
position = [-0.3, 0.0, 0.0]
v = [2.0, 0.0, 0.0]
[[body]]
name = "box"
shape = "box"
size = [0.2, 0.2, 0.2]
mass = 1.0
position = [0.3, 0.05, 0.0]
)");
    std::ostringstream out, err;
    EXPECT_EQ(run_render(tiny(one, dir / "one"), out, err), 0) << err.str();
    EXPECT_TRUE(fs::exists(dir / "one/figure.png"));
    EXPECT_EQ(run_render(tiny(three, dir / "three"), out, err), 0) << err.str();
    EXPECT_TRUE(fs::exists(dir / "three/at.png"));
    RenderOptions flat = tiny(three, dir / "front");  // a 3D scene seen from the front
    flat.view = "2d";
    EXPECT_EQ(run_render(flat, out, err), 0) << err.str();
    RenderOptions solid = tiny(one, dir / "solid");  // a 1D scene in 3D
    solid.view = "3d";
    EXPECT_EQ(run_render(solid, out, err), 0) << err.str();
}

TEST(RenderCommand, WithoutACollisionTheStillsAreSkippedWithANote) {
    render::test::TempDir dir;
    const std::string scenario = write(dir, "s.toml", R"([scene]
dimension = 2
duration = 0.2
[[body]]
name = "lonely"
shape = "disc"
radius = 0.1
mass = 1.0
v = [1.0, 0.0]
)");
    std::ostringstream out, err;
    ASSERT_EQ(run_render(tiny(scenario, dir / "out"), out, err), 0) << err.str();
    EXPECT_NE(err.str().find("no collision"), std::string::npos) << err.str();
    EXPECT_FALSE(fs::exists(dir / "out/before.png"));
    EXPECT_FALSE(fs::exists(dir / "out/figure.png"));
    EXPECT_TRUE(fs::exists(dir / "out/frames/frame_00002.png"));
}

// Splits one CSV line by RFC 4180 (quoted fields may hold commas and doubled quotes).
std::vector<std::string> csv_fields(const std::string& line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') out.back() += '"', ++i;
        else if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) out.emplace_back();
        else out.back() += c;
    }
    return out;
}

TEST(RenderCommand, ABodyNamedWithACommaIsOneQuotedCsvColumn) {
    render::test::TempDir dir;
    std::string text = kCollision2d;
    text.replace(text.find("name = \"a\""), 10, "name = \"cart, \\\"left\\\"\"");
    const std::string scenario = write(dir, "s.toml", text);
    std::ostringstream out, err;
    ASSERT_EQ(run_render(tiny(scenario, dir / "out"), out, err), 0) << err.str();
    std::ifstream data(dir / "out/data.csv"), events(dir / "out/events.csv");
    std::string header, row;
    std::getline(data, header);
    std::getline(data, row);
    const std::vector<std::string> h = csv_fields(header);
    EXPECT_EQ(h.size(), csv_fields(row).size()) << header;
    EXPECT_EQ(h.at(1), "cart, \"left\".x.x");  // t, then the first body's x
    std::getline(events, header);
    std::getline(events, row);
    const std::vector<std::string> e = csv_fields(row);
    EXPECT_EQ(csv_fields(header).size(), e.size()) << row;
    EXPECT_EQ(e.at(1), "cart, \"left\"");
}

// One run, one record: a lesson is run once, and each of its variants once; the answers, the
// figure, the worked example, the data files and the frames all read those runs. A what-if
// question is the one exception: it asks about another scene, run once for it.
TEST(RenderCommand, ALessonRunsEachSceneOnce) {
    const render::test::TempDir dir;
    const std::string lesson = std::string(COLLIDE_SOURCE_DIR) + "/lessons/01-catch-up.toml";
    std::ostringstream err;
    const std::uint64_t before = RunCount::total();
    const RenderReport r = render_scenario(parse_render_request(tiny(lesson, dir / "out")), err);
    const std::uint64_t runs = RunCount::total() - before;
    ASSERT_TRUE(r.lesson);
    ASSERT_EQ(r.lesson->variants.size(), 2u);  // two other values of e beside the scene's
    EXPECT_FALSE(r.answers.empty());
    EXPECT_TRUE(r.problem);
    EXPECT_EQ(r.variants.size(), 3u);
    std::size_t what_if = 0;
    for (const LessonQuestion& q : r.lesson->questions) what_if += q.what_if.empty() ? 0 : 1;
    EXPECT_EQ(what_if, 1u);
    EXPECT_EQ(runs, 1u + r.lesson->variants.size() + what_if);
}

// The plots step at a collision: two points at its instant, the totals just before and just
// after, exact. Catch-up: A 2 kg at 1.5 m/s, B 1 kg at 0.3 m/s, e = 0.5: E_k before
// = 2 x 1.5^2 / 2 + 1 x 0.3^2 / 2 = 2.295 J; lost (1 - e^2) m_a m_b (v_a - v_b)^2 / (2 (m_a + m_b))
// = 0.36 J; momentum 3.3 kg m/s on both sides.
TEST(RenderCommand, ThePlotsStepExactlyAtEachCollision) {
    const render::test::TempDir dir;
    const std::string lesson = std::string(COLLIDE_SOURCE_DIR) + "/lessons/01-catch-up.toml";
    std::ostringstream err;
    const RenderReport r = render_scenario(parse_render_request(tiny(lesson, dir / "out")), err);
    ASSERT_EQ(r.collision_times.size(), 1u);
    const double te = r.collision_times[0];
    std::vector<std::size_t> at;
    for (std::size_t k = 0; k < r.plot_t.size(); ++k)
        if (r.plot_t[k] == te) at.push_back(k);
    ASSERT_EQ(at.size(), 2u);
    EXPECT_EQ(at[1], at[0] + 1);
    EXPECT_NEAR(r.plot_totals[at[0]].kinetic, 2.295, 1e-12);
    EXPECT_NEAR(r.plot_totals[at[1]].kinetic, 2.295 - 0.36, 1e-12);
    EXPECT_NEAR(r.plot_totals[at[0]].momentum.x(), 3.3, 1e-12);
    EXPECT_NEAR(r.plot_totals[at[1]].momentum.x(), 3.3, 1e-12);
    EXPECT_TRUE(std::is_sorted(r.plot_t.begin(), r.plot_t.end()));
    EXPECT_EQ(r.plot_t.size(), r.plot_totals.size());
}

// Lesson 2 names A (right, 2 kg, 0.3 m/s) as a and B (left, 1 kg, 1.5 m/s) as b, as the page
// does: n = -x from A into B, and B receives the page's J = (1 + e) m_a m_b (v_a - v_b) / (m_a + m_b)
// = 1.5 x 2 x 1 x (0.3 - 1.5) / 3 = -1.2 N s, negative; the figure draws it on B.
TEST(RenderCommand, AReversedLessonWorksOutTheNegativeJInItsOwnRoles) {
    const render::test::TempDir dir;
    const std::string lesson = std::string(COLLIDE_SOURCE_DIR) + "/lessons/02-reversed.toml";
    std::ostringstream err;
    const RenderReport r = render_scenario(parse_render_request(tiny(lesson, dir / "out")), err);
    ASSERT_TRUE(r.problem && r.solution);
    EXPECT_EQ(r.problem->a.name, "A");
    EXPECT_EQ(r.problem->b.name, "B");
    EXPECT_EQ(r.problem->normal.x(), -1.0);
    EXPECT_NEAR(r.solution->P.x(), 1.5 * 2 * 1 * (0.3 - 1.5) / 3, 1e-12);
    EXPECT_NEAR(r.solution->va.x(), 0.3 - (-1.2) / 2, 1e-12);
    EXPECT_NEAR(r.solution->vb.x(), 1.5 + (-1.2) / 1, 1e-12);
    std::ifstream in(dir / "out/annotations.json");
    const nlohmann::json doc = nlohmann::json::parse(in);
    int on_b = 0;
    for (const nlohmann::json& it : doc["panels"]["at"]) {
        if (it["kind"] != "impulse") continue;
        const double P = it["value"].is_array() ? it["value"][0].get<double>() : it["value"].get<double>();
        if (it["body"] == "B") {
            EXPECT_NEAR(P, -1.2, 1e-9);
            ++on_b;
        } else {
            EXPECT_EQ(it["body"], "A");
            EXPECT_NEAR(P, 1.2, 1e-9);
        }
    }
    EXPECT_EQ(on_b, 1);
    std::ifstream md(dir / "out/worked-example.md");
    const std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("P = j n = -1.2"), std::string::npos) << text;
}

TEST(RenderCommand, RefusesANonEmptyDirectoryUnlessForced) {
    render::test::TempDir dir;
    const std::string scenario = write(dir, "s.toml", kCollision2d);
    fs::create_directories(dir / "out/frames");
    std::ofstream(dir / "out/notes.txt") << "keep me";
    std::ofstream(dir / "out/frames/frame_00099.png") << "stale";
    std::ostringstream out, err;
    EXPECT_EQ(run_render(tiny(scenario, dir / "out"), out, err), 2);
    EXPECT_NE(err.str().find("not empty"), std::string::npos) << err.str();
    EXPECT_FALSE(fs::exists(dir / "out/frames/frame_00000.png"));
    RenderOptions forced = tiny(scenario, dir / "out");
    forced.force = true;
    EXPECT_EQ(run_render(forced, out, err), 0) << err.str();
    EXPECT_TRUE(fs::exists(dir / "out/notes.txt"));                // not ours: kept
    EXPECT_FALSE(fs::exists(dir / "out/frames/frame_00099.png"));  // an old frame: removed
    EXPECT_TRUE(fs::exists(dir / "out/frames/frame_00005.png"));
}

TEST(RenderCommand, BadInputIsRefusedWithExitCode2) {
    render::test::TempDir dir;
    const std::string scenario = write(dir, "s.toml", kCollision2d);
    const std::string broken = write(dir, "broken.toml", "[scene]\ndimension = 7\n");
    const auto refuse = [&](RenderOptions o, const std::string& expect) {
        std::ostringstream out, err;
        EXPECT_EQ(run_render(o, out, err), 2) << expect;
        EXPECT_NE(err.str().find(expect), std::string::npos) << err.str();
        EXPECT_EQ(err.str().rfind("collide: error: ", 0), 0u) << err.str();
    };
    RenderOptions o = tiny(scenario, dir / "out");
    o.size = "12x12";
    refuse(o, "--size");
    o = tiny(scenario, dir / "out");
    o.size = "wide";
    refuse(o, "--size");
    o = tiny(scenario, dir / "out");
    o.fps = 0;
    refuse(o, "--fps");
    o = tiny(scenario, dir / "out");
    o.quality = "ultra";
    refuse(o, "--quality");
    o = tiny(scenario, dir / "out");
    o.view = "4d";
    refuse(o, "--view");
    o = tiny(scenario, dir / "out");
    o.format = "avi";
    refuse(o, "--format");
    {
        // Without ffmpeg on the PATH, mp4 is refused before anything is written.
        const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
        setenv("PATH", (dir / "empty").c_str(), 1);
        o = tiny(scenario, dir / "out");
        o.format = "mp4";
        refuse(o, "ffmpeg, which is not installed");
        setenv("PATH", path.c_str(), 1);
    }
    refuse(tiny(broken, dir / "out"), "broken.toml");
    refuse(tiny(dir / "absent.toml", dir / "out"), "absent.toml");
    EXPECT_FALSE(fs::exists(dir / "out"));  // nothing written on bad input
}

// MP4 and GIF go through ffmpeg (installed by scripts/install-deps.sh). The files must be
// what they say they are: an MP4 has an 'ftyp' box at offset 4, a GIF starts with GIF89a.
TEST(RenderCommand, Mp4AndGifAreEncodedByFfmpeg) {
    if (render::find_program("ffmpeg").empty()) GTEST_SKIP() << "ffmpeg is not installed";
    render::test::TempDir dir;
    const std::string scenario = write(dir, "s.toml", kCollision2d);
    for (const std::string format : {"mp4", "gif"}) {
        RenderOptions o = tiny(scenario, dir / format);
        o.size = "161x121";  // odd: MP4 needs even sizes, rounded down by the encoder
        o.format = format;
        std::ostringstream out, err;
        ASSERT_EQ(run_render(o, out, err), 0) << err.str();
        std::ifstream in(dir / (format + "/animation." + format), std::ios::binary);
        std::string head(12, '\0');
        in.read(head.data(), 12);
        ASSERT_TRUE(in) << format;
        if (format == "mp4") EXPECT_EQ(head.substr(4, 4), "ftyp");
        else EXPECT_EQ(head.substr(0, 6), "GIF89a");
        for (const auto& e : fs::recursive_directory_iterator(dir / format))
            EXPECT_EQ(e.path().string().find(".tmp-"), std::string::npos) << e.path();
    }
}

// The options are read once, into a typed request: nothing after it reads their text.
TEST(RenderCommand, OptionsBecomeATypedRequest) {
    RenderOptions o = tiny("s.toml", "out");
    RenderRequest r = parse_render_request(o);
    EXPECT_EQ(r.scenario, "s.toml");
    EXPECT_EQ(r.out_dir, "out");
    EXPECT_EQ(r.frame.width, 160);
    EXPECT_EQ(r.frame.height, 120);
    EXPECT_EQ(r.frame.fps, 10);
    EXPECT_EQ(r.frame.quality.samples_3d, 4);  // medium
    EXPECT_EQ(r.frame.quality.png.level, 1);
    EXPECT_FALSE(r.frame.view);  // by the scene's dimension
    EXPECT_FALSE(r.video);       // png: the frames alone
    EXPECT_EQ(r.backend, render::GlBackend::osmesa);
    EXPECT_TRUE(r.quiet);
    EXPECT_FALSE(r.force);
    o.quality = "high";
    o.view = "3d";
    o.size = "1080p";
    r = parse_render_request(o);
    EXPECT_EQ(r.frame.quality.encoders, 2);
    EXPECT_EQ(r.frame.quality.png.level, 6);
    EXPECT_EQ(r.frame.view, render::ViewKind::perspective);
    EXPECT_EQ(r.frame.width, 1920);
    o.quality = "low";
    o.view = "2d";
    r = parse_render_request(o);
    EXPECT_EQ(r.frame.quality.samples_3d, 0);
    EXPECT_FALSE(r.frame.quality.smooth);
    EXPECT_EQ(r.frame.view, render::ViewKind::diagram);
    if (!render::find_program("ffmpeg").empty()) {
        o.format = "gif";
        r = parse_render_request(o);
        ASSERT_TRUE(r.video);
        EXPECT_EQ(r.video->format, render::VideoFormat::gif);
        EXPECT_EQ(r.video->file_name(), "animation.gif");
        EXPECT_FALSE(r.video->ffmpeg.empty());
    }
    // Every value --help lists is one the parse takes.
    for (const std::string& q : render_choices().quality) {
        o.quality = q;
        EXPECT_NO_THROW(parse_render_request(o)) << q;
    }
    o.quality = "medium";
    for (const std::string& v : render_choices().view) {
        o.view = v;
        EXPECT_NO_THROW(parse_render_request(o)) << v;
    }
}

TEST(RenderCommand, SizePresetsAndWxH) {
    int w = 0, h = 0;
    EXPECT_TRUE(parse_render_size("720p", &w, &h));
    EXPECT_EQ(w, 1280);
    EXPECT_EQ(h, 720);
    EXPECT_TRUE(parse_render_size("480p", &w, &h));
    EXPECT_EQ(w, 854);
    EXPECT_TRUE(parse_render_size("1440p", &w, &h));
    EXPECT_EQ(h, 1440);
    EXPECT_TRUE(parse_render_size("640x360", &w, &h));
    EXPECT_EQ(w, 640);
    EXPECT_FALSE(parse_render_size("640x", &w, &h));
    EXPECT_FALSE(parse_render_size("640x360x2", &w, &h));
    EXPECT_FALSE(parse_render_size("9000x100", &w, &h));
}

}  // namespace
}  // namespace collide
