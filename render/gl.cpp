#include "render/gl.h"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace collide::render {

Gl load_gl(GlProcLoader loader) {
    Gl gl;
#define COLLIDE_GL_LOAD(type, name)                                                                                    \
    gl.name = reinterpret_cast<type>(loader("gl" #name));                                                              \
    if (!gl.name) throw std::runtime_error("OpenGL function gl" #name " is not available");
    COLLIDE_GL_FUNCTIONS(COLLIDE_GL_LOAD)
#undef COLLIDE_GL_LOAD
    return gl;
}

void check_gl(const Gl& gl, const char* what) {
    const GLenum e = gl.GetError();
    if (e == GL_NO_ERROR) return;
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", e);
    throw std::runtime_error(std::string(what) + ": OpenGL error " + code);
}

}  // namespace collide::render
