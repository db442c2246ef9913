#include "render/context.h"

#include <stdexcept>

namespace collide::render {

std::unique_ptr<GlContext> create_osmesa_context(int width, int height);  // context_osmesa.cpp
#ifdef COLLIDE_HAVE_EGL
std::unique_ptr<GlContext> create_egl_context();  // context_egl.cpp
#endif

std::string GlContext::description() const {
    const auto str = [this](GLenum name) {
        const GLubyte* s = gl_.GetString(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return str(GL_RENDERER) + ", " + str(GL_VERSION);
}

std::unique_ptr<GlContext> create_gl_context(GlBackend backend, int width, int height) {
    switch (backend) {
        case GlBackend::osmesa: return create_osmesa_context(width, height);
        case GlBackend::egl:
#ifdef COLLIDE_HAVE_EGL
            return create_egl_context();
#else
            throw std::runtime_error("this build has no EGL backend (install libegl-dev and rebuild)");
#endif
    }
    throw std::logic_error("unknown GL backend");
}

bool gl_backend_available(GlBackend backend) {
#ifdef COLLIDE_HAVE_EGL
    return backend == GlBackend::osmesa || backend == GlBackend::egl;
#else
    return backend == GlBackend::osmesa;
#endif
}

bool parse_gl_backend(const std::string& name, GlBackend* out) {
    GlBackend b;
    if (name == "osmesa") b = GlBackend::osmesa;
    else if (name == "egl") b = GlBackend::egl;
    else return false;
    if (!gl_backend_available(b)) return false;
    *out = b;
    return true;
}

}  // namespace collide::render
