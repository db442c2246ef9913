// Scenario files: what a valid file yields (masses from density, a polygon's centre of mass,
// pair rules) and that every kind of mistake is refused with its file, line and key.
#include <cmath>
#include <sstream>
#include <streambuf>

#include <gtest/gtest.h>

#include "scenario/input_error.h"
#include "scenario/scene_file.h"
#include "scenario/toml_reader.h"

namespace collide {
namespace {

const char* kGood = R"(
[scene]
dimension = 2
gravity = [0.0, -9.81]
duration = 2.0
output_dt = 0.5
model = "coulomb"
policy = "simultaneous"
restitution = 0.8
friction = 0.4

[[body]]
name = "ground"
shape = "plane"
normal = [0.0, 2.0]
offset = 0.0
restitution = 0.5

[[body]]
name = "ball"
shape = "disc"
radius = 0.1
density = 100.0
position = [0.0, 1.0]
v = [1.0, 0.0]
w = 3.0

[[body]]
shape = "polygon"
vertices = [[0.0, 0.0], [3.0, 0.0], [0.0, 3.0]]
mass = 2.0
position = [5.0, 1.0]
friction = 0.0
)";

TEST(SceneFile, ValidSceneYieldsBodies) {
    const Scene s = parse_scene_text(kGood, "good.toml");
    EXPECT_EQ(s.dimension, 2);
    EXPECT_EQ(s.model, Model::coulomb);
    EXPECT_EQ(s.policy, Policy::simultaneous);
    EXPECT_DOUBLE_EQ(s.gravity.y(), -9.81);
    ASSERT_EQ(s.bodies.size(), 3u);
    // The plane: static, unit normal.
    EXPECT_TRUE(s.bodies[0].is_static());
    EXPECT_NEAR(s.bodies[0].shape2.normal.y(), 1.0, 1e-15);
    // Disc of density 100 kg/m^2 and radius 0.1: m = 100 pi 0.01, I = m r^2 / 2.
    const Body2& ball = s.bodies[1].body2;
    EXPECT_NEAR(ball.mass, kPi, 1e-12);
    EXPECT_NEAR(ball.inertia, 0.5 * kPi * 0.01, 1e-12);
    EXPECT_EQ(ball.w, 3.0);
    // Polygon: default name, centre of mass at the centroid (1, 1) from its position;
    // polar moment of the right triangle about it: m (a^2 + b^2) / 18.
    const SceneBody& tri = s.bodies[2];
    EXPECT_EQ(tri.name, "body3");
    EXPECT_LE((tri.body2.position - Vec2(6.0, 2.0)).norm(), 1e-12);
    EXPECT_NEAR(tri.body2.inertia, 2.0 * 18.0 / 18.0, 1e-12);
    // Pair rules: e = min, mu = sqrt of the product.
    EXPECT_DOUBLE_EQ(s.pair_restitution(0, 1), 0.5);
    EXPECT_DOUBLE_EQ(s.pair_restitution(1, 2), 0.8);
    EXPECT_DOUBLE_EQ(s.pair_friction(0, 1), 0.4);
    EXPECT_DOUBLE_EQ(s.pair_friction(1, 2), 0.0);
}

TEST(SceneFile, OneAndThreeDimensions) {
    const Scene s1 = parse_scene_text(R"(
[scene]
dimension = 1
duration = 1.0
[[body]]
name = "a"
shape = "block"
length = 0.2
mass = 1.0
v = 2.0
[[body]]
name = "wall"
shape = "block"
length = 0.2
static = true
position = 1.0
)",
                                      "one.toml");
    EXPECT_EQ(s1.bodies[0].body1.v, 2.0);
    EXPECT_TRUE(s1.bodies[1].body1.is_static);
    const Scene s3 = parse_scene_text(R"(
[scene]
dimension = 3
duration = 1.0
[[body]]
name = "box"
shape = "box"
size = [1.0, 2.0, 3.0]
density = 10.0
orientation = [2.0, 0.0, 0.0, 0.0]
)",
                                      "three.toml");
    EXPECT_NEAR(s3.bodies[0].body3.mass, 60.0, 1e-12);
    EXPECT_NEAR(s3.bodies[0].body3.inertia(0, 0), 60.0 * (4.0 + 9.0) / 12.0, 1e-12);
    EXPECT_NEAR(s3.bodies[0].body3.orientation.norm(), 1.0, 1e-15);
}

struct Bad {
    const char* what;
    const char* text;
    const char* key;
    int line;
    const char* fragment;
};

void PrintTo(const Bad& b, std::ostream* os) { *os << b.what; }

const char* kHead = "[scene]\ndimension = 2\nduration = 1.0\n";  // lines 1-3

class SceneFileBad : public ::testing::TestWithParam<Bad> {};

TEST_P(SceneFileBad, IsRefusedWithItsKeyAndLine) {
    const Bad& b = GetParam();
    try {
        parse_scene_text(std::string(kHead) + b.text, "bad.toml");
        FAIL() << b.what << ": accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "bad.toml") << b.what;
        EXPECT_EQ(e.key(), b.key) << b.what << ": " << e.what();
        EXPECT_EQ(e.pos().line, b.line) << b.what << ": " << e.what();
        EXPECT_NE(std::string(e.what()).find(b.fragment), std::string::npos) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(
    Catalogue, SceneFileBad,
    ::testing::Values(
        Bad{"duplicate names",
            "[[body]]\nname = \"b\"\nshape = \"disc\"\nradius = 0.1\nmass = 1.0\n"
            "[[body]]\nname = \"b\"\nshape = \"disc\"\nradius = 0.1\nmass = 1.0\nposition = [1.0, 0.0]\n",
            "body[2].name", 10, "already used by body[1]"},
        Bad{"name with a line break", "[[body]]\nname = \"heavy\\ncart\"\nshape = \"disc\"\nradius = 0.1\nmass = 1.0\n",
            "body[1].name", 5, "must be one line, without line breaks or tabs, got 'heavy\\ncart'"},
        Bad{"overlap at the start",
            "[[body]]\nname = \"a\"\nshape = \"disc\"\nradius = 0.5\nmass = 1.0\n"
            "[[body]]\nname = \"b\"\nshape = \"rectangle\"\nsize = [1.0, 1.0]\nmass = 1.0\n"
            "position = [0.9, 0.0]\n",
            "body[2].position", 14, "'b' overlaps 'a' by 0.1 m"},
        Bad{"inside the ground",
            "[[body]]\nname = \"ground\"\nshape = \"plane\"\nnormal = [0.0, 1.0]\n"
            "[[body]]\nname = \"ball\"\nshape = \"disc\"\nradius = 0.5\nmass = 1.0\n"
            "position = [0.0, 0.25]\n",
            "body[2].position", 13, "overlaps 'ground' by 0.25 m"},
        Bad{"static body with velocity",
            "[[body]]\nname = \"w\"\nshape = \"rectangle\"\nsize = [1.0, 1.0]\nstatic = true\n"
            "v = [1.0, 0.0]\n",
            "body[1].v", 9, "a static body stays where it is"},
        Bad{"mass and density", "[[body]]\nshape = \"disc\"\nradius = 0.1\nmass = 1.0\ndensity = 2.0\n", "body[1].mass",
            7, "exactly one of mass, density"},
        Bad{"clockwise polygon",
            "[[body]]\nshape = \"polygon\"\nvertices = [[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]]\nmass = 1.0\n",
            "body[1].vertices", 6, "counter-clockwise"},
        Bad{"radius on a rectangle", "[[body]]\nshape = \"rectangle\"\nsize = [1.0, 1.0]\nradius = 0.5\nmass = 1.0\n",
            "body[1].radius", 7, "a rectangle has no 'radius'"},
        Bad{"3D shape in 2D", "[[body]]\nshape = \"sphere\"\nradius = 0.5\nmass = 1.0\n", "body[1].shape", 5,
            "unknown 2D shape 'sphere'; expected disc, rectangle, polygon or plane"},
        Bad{"unknown key with a hint", "[[body]]\nshape = \"disc\"\nradius = 0.5\nmass = 1.0\nvelocity = [1.0, 0.0]\n",
            "body[1].velocity", 8, "did you mean 'v'?"},
        Bad{"plane that moves", "[[body]]\nshape = \"plane\"\nnormal = [0.0, 1.0]\nv = [1.0, 0.0]\n", "body[1].v", 7,
            "a plane is placed by normal and offset"},
        Bad{"no bodies", "", "", 0, "expected one or more [[body]] tables"},
        Bad{"camera looking straight down",
            "[view]\ncamera_elevation = 95.0\n[[body]]\nshape = \"disc\"\nradius = 0.5\nmass = 1.0\n",
            "view.camera_elevation", 5, "between -89 and 89"},
        Bad{"unknown view key with a hint",
            "[view]\ndirection = true\n[[body]]\nshape = \"disc\"\nradius = 0.5\nmass = 1.0\n", "view.direction", 5,
            "did you mean 'directions'?"},
        Bad{"camera target of another dimension",
            "[view]\ncamera_target = [0.0, 0.0, 1.0]\n[[body]]\nshape = \"disc\"\nradius = 0.5\nmass = 1.0\n",
            "view.camera_target", 5, "2"},
        Bad{"unknown policy", "policy = \"together\"\n[[body]]\nshape = \"disc\"\nradius = 0.5\nmass = 1.0\n",
            "scene.policy", 4, "expected sequential or simultaneous"}));

TEST(SceneFile, ViewTableIsReadAndOptional) {
    SceneView view;
    parse_scene_text(std::string(kHead) +
                         "[view]\ncamera_azimuth = -40.0\ncamera_elevation = 10\n"
                         "camera_target = [0.5, 0.25]\ncamera_distance = 3.0\ndirections = true\n"
                         "[[body]]\nshape = \"disc\"\nradius = 0.5\nmass = 1.0\n",
                     "view.toml", &view);
    EXPECT_EQ(view.camera_azimuth, -40.0);
    EXPECT_EQ(view.camera_elevation, 10.0);
    ASSERT_TRUE(view.camera_target.has_value());
    EXPECT_EQ(*view.camera_target, Vec3(0.5, 0.25, 0.0));
    EXPECT_EQ(view.camera_distance, 3.0);
    EXPECT_TRUE(view.directions);
    SceneView none;
    parse_scene_text(std::string(kHead) + "[[body]]\nshape = \"disc\"\nradius = 0.5\nmass = 1.0\n", "plain.toml",
                     &none);
    EXPECT_FALSE(none.camera_azimuth || none.camera_elevation || none.camera_target || none.camera_distance);
    EXPECT_FALSE(none.directions);
}

TEST(SceneFile, CollisionFileIsPointedToSolve) {
    try {
        parse_scene_text("dimension = 1\nrestitution = 1.0\n[a]\nmass = 1.0\n", "c.toml");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("run it with 'collide solve'"), std::string::npos);
    }
}

TEST(SceneFile, MessagesQuotingALineBreakStayOnOneLine) {
    // The user's text comes back escaped, as they would write it in a TOML string.
    for (const char* text : {"[[body]]\nshape = \"\"\"\ndisc\n\"\"\"\nradius = 0.1\nmass = 1.0\n",
                             "[[body]]\nshape = \"disc\"\nradius = 0.1\nmass = 1.0\n\"v\\tx\" = 1.0\n",
                             "[[body]]\nshape = \"disc\\r\"\nradius = 0.1\nmass = 1.0\n",
                             "[[body]]\nshape = \"disc\\u0007\"\nradius = 0.1\nmass = 1.0\n"}) {
        try {
            parse_scene_text(std::string(kHead) + text, "bad.toml");
            FAIL() << text << ": accepted";
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.find_first_of("\n\r\t\a"), std::string::npos) << what;
            EXPECT_EQ(what.find("bad.toml:"), 0u) << what;
        }
    }
    EXPECT_EQ(one_line("'disc\n' \t\r\x7f\x01 ok"), "'disc\\n' \\t\\r\\u007F\\u0001 ok");
}

TEST(SceneFile, MissingSceneTable) {
    EXPECT_THROW(parse_scene_text("[[body]]\nshape = \"disc\"\n", "x.toml"), InputError);
}

// ---- Input without end ---------------------------------------------------------------------

// A stream that never ends ('#', a comment, for ever), counting what is read of it.
class Endless : public std::streambuf {
public:
    std::size_t served = 0;

protected:
    int_type underflow() override {
        buffer_.assign(4096, '#');
        setg(buffer_.data(), buffer_.data(), buffer_.data() + buffer_.size());
        served += buffer_.size();
        return traits_type::to_int_type('#');
    }

private:
    std::string buffer_;
};

// The 1 MiB limit is checked while reading: an endless stream is refused having been read no
// further than the limit and one 64 KiB chunk (it used to be read whole: 3 GB in 30 s of
// /dev/zero). A file of exactly 1 MiB is read; one byte more is refused.
TEST(InputFiles, AStreamWithoutEndIsRefusedAtTheLimitWhileReading) {
    Endless endless;
    std::istream in(&endless);
    try {
        read_bounded(in, "<stdin>");
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "<stdin>");
        EXPECT_NE(e.message().find("1 MiB"), std::string::npos) << e.what();
    }
    EXPECT_LE(endless.served, kMaxInputBytes + (1u << 16) + 4096);
    std::istringstream exact(std::string(kMaxInputBytes, '#'));
    EXPECT_EQ(read_bounded(exact, "f").size(), kMaxInputBytes);
    std::istringstream over(std::string(kMaxInputBytes + 1, '#'));
    EXPECT_THROW(read_bounded(over, "f"), InputError);
    std::istringstream binary(std::string("a = 1\n\0", 7));
    EXPECT_THROW(read_bounded(binary, "f"), InputError);
}

}  // namespace
}  // namespace collide
