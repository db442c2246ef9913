// The EGL backend: the surfaceless platform (no window system, no surface at all; the renderer
// draws into framebuffer objects). Mesa provides it with llvmpipe, and with a GPU's driver
// where one exists.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "render/context.h"

namespace collide::render {

namespace {

void* egl_proc(const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); }

std::string egl_error(const char* what) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", eglGetError());
    return std::string("EGL: ") + what + " failed (error " + code + ")";
}

class EglContext final : public GlContext {
public:
    EglContext() {
        const auto get_display =
            reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!get_display) throw std::runtime_error("EGL: no eglGetPlatformDisplayEXT");
        display_ = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display_ == EGL_NO_DISPLAY) throw std::runtime_error(egl_error("surfaceless display"));
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display_, &major, &minor)) throw std::runtime_error(egl_error("eglInitialize"));
        try {
            if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error(egl_error("eglBindAPI"));
            // No surface is ever made, so no config is needed where EGL_KHR_no_config_context
            // is offered (Mesa's surfaceless platform may list no configs at all).
            EGLConfig config = EGL_NO_CONFIG_KHR;
            const char* extensions = eglQueryString(display_, EGL_EXTENSIONS);
            if (!extensions || !std::strstr(extensions, "EGL_KHR_no_config_context")) {
                const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
                EGLint count = 0;
                if (!eglChooseConfig(display_, config_attribs, &config, 1, &count) || count < 1)
                    throw std::runtime_error(egl_error("eglChooseConfig"));
            }
            const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                              3,
                                              EGL_CONTEXT_MINOR_VERSION,
                                              3,
                                              EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                              EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                              EGL_NONE};
            context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attribs);
            if (context_ == EGL_NO_CONTEXT) throw std::runtime_error(egl_error("eglCreateContext"));
            make_current();
            gl_ = load_gl(&egl_proc);
        } catch (...) {
            if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
            eglTerminate(display_);
            throw;
        }
    }
    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }

    void make_current() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw std::runtime_error(egl_error("eglMakeCurrent"));
    }
    const char* backend_name() const override { return "egl"; }

private:
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> create_egl_context() { return std::make_unique<EglContext>(); }

}  // namespace collide::render
