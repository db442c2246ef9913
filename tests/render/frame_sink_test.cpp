// Frame sequences: names, completeness, bounded memory, errors.
#include "render/frame_sink.h"

#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "test_util.h"

namespace collide::render {
namespace {

namespace fs = std::filesystem;

TEST(FrameSink, WritesNumberedCompleteFrames) {
    test::TempDir dir;
    FrameSinkOptions o;
    o.dir = dir.str();
    o.threads = 2;
    o.buffers = 3;
    const int w = 24, h = 16, n = 40;
    {
        FrameSink sink(w, h, o);
        EXPECT_EQ(sink.buffer_count(), 3u);  // memory: three frames, however many are written
        for (int k = 0; k < n; ++k) {
            FrameSink::Buffer* b = sink.acquire();
            for (std::size_t i = 0; i < b->size(); ++i)
                (*b)[i] = i % 4 == 3 ? 255 : static_cast<std::uint8_t>(k * 5 + i % 4);
            sink.submit(k, b);
        }
        sink.finish();
        EXPECT_EQ(sink.written(), n);
        EXPECT_EQ(sink.path_of(7), dir / "frame_00007.png");
    }
    int count = 0;
    for (const auto& e : fs::directory_iterator(dir.str())) {
        EXPECT_EQ(e.path().extension(), ".png") << e.path();
        ++count;
    }
    EXPECT_EQ(count, n);
    for (int k : {0, 17, n - 1}) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05d.png", k);
        const Image im = read_png(dir / name);
        ASSERT_EQ(im.width, w);
        EXPECT_EQ(im.pixel(3, 5)[1], static_cast<std::uint8_t>(k * 5 + 1));
    }
}

TEST(FrameSink, AWriteErrorStopsTheSinkAndNamesThePath) {
    test::TempDir dir;
    FrameSinkOptions o;
    o.dir = dir / "no-such-dir";
    FrameSink sink(8, 8, o);
    bool thrown = false;
    try {
        for (int k = 0; k < 20; ++k) sink.submit(k, sink.acquire());
        sink.finish();
    } catch (const std::runtime_error& e) {
        thrown = true;
        EXPECT_NE(std::string(e.what()).find("no-such-dir/frame_0000"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(thrown);
}

TEST(ProgressBar, SilentWhenDisabledAndEndsWithANewline) {
    std::ostringstream quiet, shown;
    ProgressBar off(quiet, 10, false);
    off.update(5);
    off.finish();
    EXPECT_EQ(quiet.str(), "");
    ProgressBar on(shown, 10, true, "rendering");
    on.update(5);
    on.finish();
    EXPECT_NE(shown.str().find("rendering ["), std::string::npos);
    EXPECT_NE(shown.str().find("10/10"), std::string::npos);
    EXPECT_EQ(shown.str().back(), '\n');
}

}  // namespace
}  // namespace collide::render
