// The GLFW window (render/window.h).
#include "render/window.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <utility>
#include <vector>

#ifdef COLLIDE_HAVE_GLFW
#define GLFW_INCLUDE_NONE  // GL types come from render/gl.h; functions from the context
#include <GLFW/glfw3.h>
#endif

namespace collide::render {

#ifdef COLLIDE_HAVE_GLFW

namespace {

std::string glfw_error() {
    const char* text = nullptr;
    glfwGetError(&text);
    return text ? text : "unknown error";
}

void* glfw_proc(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

}  // namespace

std::unique_ptr<Window> Window::open(int width, int height, const std::string& title) {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland))
        throw std::runtime_error(
            "no display (DISPLAY is not set): collide gui needs a screen; on a machine without one, "
            "run it under xvfb-run, or use collide render for frames");
    if (!glfwInit()) throw std::runtime_error("GLFW could not start: " + glfw_error());
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);  // the frame has the render's size
    std::unique_ptr<Window> w(new Window());
    w->window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!w->window_) {
        const std::string why = glfw_error();
        glfwTerminate();
        throw std::runtime_error("GLFW could not open an OpenGL 3.3 window: " + why);
    }
    glfwMakeContextCurrent(w->window_);
    glfwSwapInterval(1);
    w->gl_ = load_gl(glfw_proc);
    return w;
}

Window::~Window() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

void Window::make_current() { glfwMakeContextCurrent(window_); }
bool Window::should_close() const { return glfwWindowShouldClose(window_) != 0; }
void Window::close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void Window::framebuffer_size(int* width, int* height) const { glfwGetFramebufferSize(window_, width, height); }
void Window::swap() { glfwSwapBuffers(window_); }
void Window::use_default_framebuffer() { gl_.BindFramebuffer(GL_FRAMEBUFFER, 0); }

void Window::read_back_buffer(int width, int height, unsigned char* rgba) {
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    gl_.ReadBuffer(GL_BACK);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    std::vector<unsigned char> rows(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    gl_.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    const std::size_t stride = static_cast<std::size_t>(width) * 4;
    for (int y = 0; y < height; ++y)  // OpenGL's rows run bottom-up
        std::copy_n(rows.data() + static_cast<std::size_t>(height - 1 - y) * stride, stride, rgba + y * stride);
}

std::string window_support() { return {}; }

#else

std::unique_ptr<Window> Window::open(int, int, const std::string&) { throw std::runtime_error(window_support()); }
Window::~Window() = default;
void Window::make_current() {}
bool Window::should_close() const { return true; }
void Window::close() {}
void Window::framebuffer_size(int* width, int* height) const { *width = *height = 0; }
void Window::swap() {}
void Window::use_default_framebuffer() {}
void Window::read_back_buffer(int, int, unsigned char*) {}

std::string window_support() {
    return "this collide was built without GLFW, so it has no window: install it (Debian: apt-get install "
           "libglfw3-dev) and rebuild (scripts/build.sh; the CMake option COLLIDE_GUI must be ON, its default); "
           "collide render makes the same frames without a display";
}

#endif

}  // namespace collide::render
