// PNG files: round trips, the atomic write (complete or absent), errors that name the path.
#include "render/png.h"

#include <filesystem>
#include <fstream>
#include <random>

#include <gtest/gtest.h>

#include "test_util.h"

namespace collide::render {
namespace {

namespace fs = std::filesystem;

Image noise(int w, int h, bool opaque, unsigned seed) {
    std::mt19937 rng(seed);
    Image im;
    im.width = w;
    im.height = h;
    im.rgba.resize(static_cast<std::size_t>(w) * h * 4);
    for (std::size_t i = 0; i < im.rgba.size(); ++i)
        im.rgba[i] = (opaque && i % 4 == 3) ? 255 : static_cast<std::uint8_t>(rng() & 0xFF);
    return im;
}

std::vector<std::string> leftovers(const std::string& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().find(".tmp-") != std::string::npos) out.push_back(e.path().string());
    return out;
}

TEST(Png, RoundTripKeepsEveryByteWithAlpha) {
    test::TempDir dir;
    const Image im = noise(37, 23, false, 1);  // odd sizes: no row padding assumptions
    PngOptions options;
    options.alpha = true;
    write_png_atomic(dir / "a.png", im.width, im.height, im.rgba.data(), options);
    const Image back = read_png(dir / "a.png");
    EXPECT_EQ(back.width, 37);
    EXPECT_EQ(back.height, 23);
    EXPECT_EQ(back.rgba, im.rgba);
}

TEST(Png, OpaqueFramesAreWrittenAsRgb) {
    test::TempDir dir;
    const Image im = noise(64, 48, true, 2);
    write_png_atomic(dir / "rgb.png", im.width, im.height, im.rgba.data());  // defaults: RGB
    EXPECT_EQ(read_png(dir / "rgb.png").rgba, im.rgba);
    // RGB data is three quarters of RGBA; stored noise does not compress.
    PngOptions rgba;
    rgba.alpha = true;
    write_png_atomic(dir / "rgba.png", im.width, im.height, im.rgba.data(), rgba);
    EXPECT_LT(fs::file_size(dir / "rgb.png"), fs::file_size(dir / "rgba.png"));
}

TEST(Png, EveryLevelAndFilterRoundTrips) {
    test::TempDir dir;
    const Image im = noise(20, 10, true, 3);
    for (int level : {0, 1, 6, 9})
        for (bool none : {true, false}) {
            PngOptions o;
            o.level = level;
            o.filter_none = none;
            const std::vector<std::uint8_t> bytes = encode_png(im.width, im.height, im.rgba.data(), o);
            std::ofstream(dir / "m.png", std::ios::binary)
                .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
            EXPECT_EQ(read_png(dir / "m.png").rgba, im.rgba) << "level " << level;
        }
}

TEST(Png, AtomicWriteLeavesNoTemporaryAndReplacesTheOldFile) {
    test::TempDir dir;
    const Image first = noise(16, 16, true, 4), second = noise(16, 16, true, 5);
    write_png_atomic(dir / "f.png", 16, 16, first.rgba.data());
    write_png_atomic(dir / "f.png", 16, 16, second.rgba.data());
    EXPECT_EQ(read_png(dir / "f.png").rgba, second.rgba);
    EXPECT_TRUE(leftovers(dir.str()).empty());
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir.str())) names.push_back(e.path().filename().string());
    EXPECT_EQ(names, std::vector<std::string>{"f.png"});
}

TEST(Png, FailedWriteNamesThePathAndLeavesNothing) {
    test::TempDir dir;
    const Image im = noise(8, 8, true, 6);
    const std::string path = dir / "missing-dir/frame.png";
    try {
        write_png_atomic(path, 8, 8, im.rgba.data());
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    // A directory in the way of the target: the encoded temporary file is removed.
    fs::create_directories(dir / "taken.png");
    EXPECT_THROW(write_png_atomic(dir / "taken.png", 8, 8, im.rgba.data()), std::runtime_error);
    EXPECT_TRUE(leftovers(dir.str()).empty());
}

TEST(Png, ReadErrorsNameThePath) {
    test::TempDir dir;
    std::ofstream(dir / "bad.png") << "not a png";
    for (const std::string& p : {dir / "bad.png", dir / "absent.png"}) {
        try {
            read_png(p);
            FAIL() << "expected an error for " << p;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
        }
    }
}

TEST(Png, TextFilesAreWrittenAtomicallyToo) {
    test::TempDir dir;
    write_file_atomic(dir / "data.csv", "t,x\n0,1\n");
    std::ifstream in(dir / "data.csv");
    std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(all, "t,x\n0,1\n");
    EXPECT_TRUE(leftovers(dir.str()).empty());
}

}  // namespace
}  // namespace collide::render
