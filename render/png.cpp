#include "render/png.h"

#include <fcntl.h>
#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace collide::render {

namespace {

// Where encoded bytes go: a file descriptor or a vector (`out`).
struct Sink {
    int fd = -1;
    std::vector<std::uint8_t>* out = nullptr;
    int error = 0;  // errno of a failed write
};

void sink_write(png_structp png, png_bytep data, png_size_t size) {
    auto* sink = static_cast<Sink*>(png_get_io_ptr(png));
    if (sink->out) {
        sink->out->insert(sink->out->end(), data, data + size);
        return;
    }
    while (size > 0) {
        const ssize_t n = ::write(sink->fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            sink->error = n < 0 ? errno : EIO;
            png_error(png, "write failed");
        }
        data += n;
        size -= static_cast<std::size_t>(n);
    }
}

void sink_flush(png_structp) {}

// libpng reports errors by longjmp; `message` keeps the text.
struct ErrorState {
    char message[256] = "";
};

void on_error(png_structp png, png_const_charp text) {
    auto* state = static_cast<ErrorState*>(png_get_error_ptr(png));
    std::snprintf(state->message, sizeof state->message, "%s", text);
    png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

// The libpng calls, between setjmp and any longjmp: only plain data lives in this frame (no
// destructors are skipped). rows: height pointers prepared by the caller. Returns false with
// state->message set on failure.
bool encode_rows(Sink* sink, ErrorState* state, int width, int height, png_bytepp rows, const PngOptions& options) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, state, on_error, on_warning);
    if (!png) {
        std::snprintf(state->message, sizeof state->message, "out of memory");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        if (!state->message[0]) std::snprintf(state->message, sizeof state->message, "libpng failed");
        return false;
    }
    png_set_write_fn(png, sink, sink_write, sink_flush);
    png_set_compression_level(png, options.level);
    if (options.filter_none) png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
                 options.alpha ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    if (!options.alpha) png_set_filler(png, 0, PNG_FILLER_AFTER);  // drop the 4th byte
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

void check_args(int width, int height, const std::uint8_t* rgba, const PngOptions& options) {
    if (width < 1 || height < 1 || !rgba) throw std::invalid_argument("PNG: empty image");
    if (options.level < 0 || options.level > 9) throw std::invalid_argument("PNG: zlib level must be 0..9");
}

std::vector<png_bytep> row_pointers(int width, int height, const std::uint8_t* rgba) {
    std::vector<png_bytep> rows(static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y)
        rows[static_cast<std::size_t>(y)] = const_cast<png_bytep>(rgba + static_cast<std::size_t>(y) * width * 4);
    return rows;
}

std::string errno_text(int e) { return std::strerror(e); }

}  // namespace

std::vector<std::uint8_t> encode_png(int width, int height, const std::uint8_t* rgba, const PngOptions& options) {
    check_args(width, height, rgba, options);
    std::vector<png_bytep> rows = row_pointers(width, height, rgba);
    std::vector<std::uint8_t> out;
    out.reserve(static_cast<std::size_t>(width) * height / 2);
    Sink sink;
    sink.out = &out;
    ErrorState state;
    if (!encode_rows(&sink, &state, width, height, rows.data(), options))
        throw std::runtime_error(std::string("PNG encoding failed: ") + state.message);
    return out;
}

namespace {

// Creates `path.tmp-<pid>-<n>` exclusively; returns its descriptor and name.
int create_temporary(const std::string& path, std::string* tmp) {
    static std::atomic<unsigned> counter{0};
    for (int attempt = 0; attempt < 100; ++attempt) {
        *tmp = path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
        const int fd = ::open(tmp->c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST) return fd;
    }
    return -1;
}

}  // namespace

void write_file_atomic(const std::string& path, const std::string& data) {
    std::string tmp;
    const int fd = create_temporary(path, &tmp);
    if (fd < 0) throw std::runtime_error(path + ": cannot create: " + errno_text(errno));
    const char* p = data.data();
    std::size_t left = data.size();
    int error = 0;
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            error = n < 0 ? errno : EIO;
            break;
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    if (::close(fd) != 0 && !error) error = errno;
    if (!error && ::rename(tmp.c_str(), path.c_str()) != 0) error = errno;
    if (error) {
        ::unlink(tmp.c_str());
        throw std::runtime_error(path + ": cannot write: " + errno_text(error));
    }
}

void write_png_atomic(const std::string& path, int width, int height, const std::uint8_t* rgba,
                      const PngOptions& options) {
    check_args(width, height, rgba, options);
    std::vector<png_bytep> rows = row_pointers(width, height, rgba);

    // A unique temporary name beside the target (rename is atomic within one file system).
    std::string tmp;
    const int fd = create_temporary(path, &tmp);
    if (fd < 0) throw std::runtime_error(path + ": cannot create: " + errno_text(errno));

    Sink sink;
    sink.fd = fd;
    ErrorState state;
    const bool ok = encode_rows(&sink, &state, width, height, rows.data(), options);
    const int close_result = ::close(fd);
    const int close_errno = errno;
    std::string failure;
    if (!ok) failure = sink.error ? errno_text(sink.error) : std::string("PNG encoding failed: ") + state.message;
    else if (close_result != 0) failure = errno_text(close_errno);
    else if (::rename(tmp.c_str(), path.c_str()) != 0) failure = errno_text(errno);
    if (!failure.empty()) {
        ::unlink(tmp.c_str());
        throw std::runtime_error(path + ": cannot write: " + failure);
    }
}

Image read_png(const std::string& path) {
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path.c_str()))
        throw std::runtime_error(path + ": cannot read PNG: " + image.message);
    image.format = PNG_FORMAT_RGBA;
    Image out;
    out.width = static_cast<int>(image.width);
    out.height = static_cast<int>(image.height);
    out.rgba.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, out.rgba.data(), 0, nullptr)) {
        const std::string message = image.message;
        png_image_free(&image);
        throw std::runtime_error(path + ": cannot read PNG: " + message);
    }
    return out;
}

Image shrink(const Image& im, int width) {
    Image out;
    out.width = std::max(1, std::min(width, im.width));
    out.height = std::max(1, static_cast<int>(std::lround(static_cast<double>(im.height) * out.width / im.width)));
    out.rgba.assign(static_cast<std::size_t>(out.width) * out.height * 4, 0);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            // The source pixels this one covers (at least one).
            const int x0 = x * im.width / out.width, x1 = std::max(x0 + 1, (x + 1) * im.width / out.width);
            const int y0 = y * im.height / out.height, y1 = std::max(y0 + 1, (y + 1) * im.height / out.height);
            unsigned sum[4] = {0, 0, 0, 0};
            for (int yy = y0; yy < y1; ++yy)
                for (int xx = x0; xx < x1; ++xx)
                    for (int c = 0; c < 4; ++c) sum[c] += im.pixel(xx, yy)[c];
            const unsigned count = static_cast<unsigned>((x1 - x0) * (y1 - y0));
            for (int c = 0; c < 4; ++c)
                out.rgba[(static_cast<std::size_t>(y) * out.width + x) * 4 + c] =
                    static_cast<std::uint8_t>(sum[c] / count);
        }
    return out;
}

Image stack_vertically(const std::vector<Image>& images) {
    Image out;
    for (const Image& im : images) {
        out.width = std::max(out.width, im.width);
        out.height += im.height;
    }
    out.rgba.assign(static_cast<std::size_t>(out.width) * out.height * 4, 255);
    if (!images.empty() && !images[0].rgba.empty())  // the paper colour around narrower rows
        for (std::size_t p = 0; p < out.rgba.size(); p += 4)
            std::copy(images[0].rgba.begin(), images[0].rgba.begin() + 4, out.rgba.begin() + static_cast<long>(p));
    int y0 = 0;
    for (const Image& im : images) {
        for (int y = 0; y < im.height; ++y)
            std::copy(im.rgba.begin() + static_cast<long>(y) * im.width * 4,
                      im.rgba.begin() + static_cast<long>(y + 1) * im.width * 4,
                      out.rgba.begin() + (static_cast<long>(y0 + y) * out.width) * 4);
        y0 += im.height;
    }
    return out;
}

}  // namespace collide::render
