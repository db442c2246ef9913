// PNG files through libpng. Images are RGBA bytes, top row first.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace collide::render {

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4, top row first
    const std::uint8_t* pixel(int x, int y) const {
        return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4;
    }
};

struct PngOptions {
    // zlib level 0..9. Measured at 1280x720 (../shared/STACK.md): level 1 with no filter takes
    // 11 ms per frame, libpng's defaults (6, adaptive filters) 48 ms, level 9 over 100 ms, for
    // files of about the same size on flat diagram content.
    int level = 1;
    bool filter_none = true;  // else libpng's adaptive filter choice
    bool alpha = false;       // keep the alpha channel (frames are opaque: RGB files)
};

// Encodes to memory. Throws std::runtime_error.
std::vector<std::uint8_t> encode_png(int width, int height, const std::uint8_t* rgba, const PngOptions& options = {});

// Writes `path` atomically: the image goes to `path.tmp-<unique>` in the same directory, which
// is then renamed to `path`; readers see either the complete file or none (or the previous
// one). On failure the temporary file is removed and std::runtime_error names the path.
void write_png_atomic(const std::string& path, int width, int height, const std::uint8_t* rgba,
                      const PngOptions& options = {});

// Any file, with the same guarantee (data.csv, data.json).
void write_file_atomic(const std::string& path, const std::string& data);

// A box-filtered copy `width` pixels wide (never wider than the image), same aspect.
Image shrink(const Image& image, int width);

// The images one under another, left-aligned on the background colour of the widest's
// first pixel (figures of one size stack exactly).
Image stack_vertically(const std::vector<Image>& images);

// Any PNG, converted to 8-bit RGBA. Throws std::runtime_error naming the path.
Image read_png(const std::string& path);

}  // namespace collide::render
