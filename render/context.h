// An offscreen OpenGL context: the one place that knows which library provides OpenGL.
//
// Backends (each gives an OpenGL 3.3+ core context; on a machine without a GPU both run Mesa's
// llvmpipe on the CPU):
//   osmesa: Mesa's off-screen library (the default: in Debian 12 everywhere). Upstream Mesa
//           removed it in 25.1;
//   egl:    EGL with the surfaceless platform (EGL_MESA_platform_surfaceless): no window system,
//           and a GPU where there is one. Built when CMake finds pkg-config `egl`.
// The renderer draws into its own framebuffer objects (render/target.h), never into a window
// or the context's default buffer, so a backend only has to create a context and make it current.
// A new backend is one more subclass and one more case in create_gl_context.
#pragma once

#include <memory>
#include <string>

#include "render/gl.h"

namespace collide::render {

enum class GlBackend { osmesa, egl };

class GlContext {
public:
    virtual ~GlContext() = default;
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    // Makes this context current on the calling thread (create_gl_context already did).
    virtual void make_current() = 0;
    virtual const char* backend_name() const = 0;  // "osmesa" or "egl"

    // The GL functions, loaded through this context.
    const Gl& gl() const { return gl_; }
    // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
    std::string description() const;

protected:
    GlContext() = default;
    Gl gl_;
};

// A context of the given backend, current on the calling thread. width and height (pixels) size
// the backend's own buffer where it needs one; frames of any size are drawn into render targets.
// Throws std::runtime_error saying what failed (and which Debian package provides the backend).
std::unique_ptr<GlContext> create_gl_context(GlBackend backend = GlBackend::osmesa, int width = 16, int height = 16);

// "osmesa" or "egl"; false for anything else (or for egl when it was not built).
bool parse_gl_backend(const std::string& name, GlBackend* out);
bool gl_backend_available(GlBackend backend);

}  // namespace collide::render
