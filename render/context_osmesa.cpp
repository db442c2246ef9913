// The OSMesa backend: a core-profile context rendering into a small client-memory buffer
// (the renderer itself draws into framebuffer objects).
#include "render/context.h"  // first: <GL/glcorearb.h> gives the GL types osmesa.h needs

// <GL/osmesa.h> includes the legacy <GL/gl.h>, which would clash with <GL/glcorearb.h>.
#define __gl_h_
#ifndef GLAPIENTRY
#define GLAPIENTRY
#endif
#include <GL/osmesa.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace collide::render {

namespace {

void* osmesa_proc(const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }

class OsmesaContext final : public GlContext {
public:
    OsmesaContext(int width, int height)
        : width_(width),
          height_(height),
          buffer_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
        // OpenGL 3.3 core (Mesa gives 4.5); no depth or stencil in the default buffer.
        const int attribs[] = {OSMESA_FORMAT,
                               OSMESA_RGBA,
                               OSMESA_DEPTH_BITS,
                               0,
                               OSMESA_STENCIL_BITS,
                               0,
                               OSMESA_ACCUM_BITS,
                               0,
                               OSMESA_PROFILE,
                               OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION,
                               3,
                               OSMESA_CONTEXT_MINOR_VERSION,
                               3,
                               0};
        ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
        if (!ctx_) throw std::runtime_error("OSMesa could not create an OpenGL 3.3 core context (Debian: libosmesa6)");
        make_current();
        gl_ = load_gl(&osmesa_proc);
    }
    ~OsmesaContext() override { OSMesaDestroyContext(ctx_); }

    void make_current() override {
        if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
            throw std::runtime_error("OSMesaMakeCurrent failed");
    }
    const char* backend_name() const override { return "osmesa"; }

private:
    OSMesaContext ctx_ = nullptr;
    int width_, height_;
    std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlContext> create_osmesa_context(int width, int height) {
    if (width < 1 || height < 1) throw std::invalid_argument("OSMesa buffer size must be positive");
    return std::make_unique<OsmesaContext>(width, height);
}

}  // namespace collide::render
