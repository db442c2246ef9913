// The OSMesa backend: a core-profile context rendering into a small client-memory buffer
// (the renderer itself draws into framebuffer objects).
//
// libOSMesa is opened here, at the first context, not linked: it pulls in Mesa's llvmpipe and
// libLLVM, whose loading and relocation took about 0.1 s at every start of `collide`, also for
// the commands that never draw (solve, step, a refused file). Four entry points are taken from
// it; every GL function comes through OSMesaGetProcAddress as before.
#include "render/context.h"  // first: <GL/glcorearb.h> gives the GL types osmesa.h needs

// <GL/osmesa.h> includes the legacy <GL/gl.h>, which would clash with <GL/glcorearb.h>.
#define __gl_h_
#ifndef GLAPIENTRY
#define GLAPIENTRY
#endif
#include <GL/osmesa.h>

#include <dlfcn.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace collide::render {

namespace {

// The library's soname (Debian 12: libosmesa6) and the four functions used.
constexpr const char* kOsmesaLibrary = "libOSMesa.so.8";

struct OsmesaApi {
    decltype(&::OSMesaCreateContextAttribs) create_context_attribs = nullptr;
    decltype(&::OSMesaDestroyContext) destroy_context = nullptr;
    decltype(&::OSMesaMakeCurrent) make_current = nullptr;
    decltype(&::OSMesaGetProcAddress) get_proc_address = nullptr;
};

template <class F>
void take(void* library, const char* name, F& to) {
    to = reinterpret_cast<F>(dlsym(library, name));
    if (!to) throw std::runtime_error(std::string("OSMesa: ") + kOsmesaLibrary + " has no " + name);
}

// Opened once, kept open for the process (a context may be made again; closing LLVM at exit
// is left to the system).
const OsmesaApi& osmesa() {
    static const OsmesaApi api = [] {
        void* library = dlopen(kOsmesaLibrary, RTLD_NOW | RTLD_LOCAL);
        if (!library) {
            const char* why = dlerror();
            throw std::runtime_error(std::string("OSMesa could not be loaded (") + (why ? why : kOsmesaLibrary) +
                                     "; Debian: apt-get install libosmesa6)");
        }
        OsmesaApi a;
        take(library, "OSMesaCreateContextAttribs", a.create_context_attribs);
        take(library, "OSMesaDestroyContext", a.destroy_context);
        take(library, "OSMesaMakeCurrent", a.make_current);
        take(library, "OSMesaGetProcAddress", a.get_proc_address);
        return a;
    }();
    return api;
}

void* osmesa_proc(const char* name) { return reinterpret_cast<void*>(osmesa().get_proc_address(name)); }

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
        ctx_ = osmesa().create_context_attribs(attribs, nullptr);
        if (!ctx_) throw std::runtime_error("OSMesa could not create an OpenGL 3.3 core context (Debian: libosmesa6)");
        make_current();
        gl_ = load_gl(&osmesa_proc);
    }
    ~OsmesaContext() override { osmesa().destroy_context(ctx_); }

    void make_current() override {
        if (!osmesa().make_current(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
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
