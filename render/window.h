// A window on the screen with an OpenGL 3.3 core context (GLFW), for `collide gui`: the same
// renderer draws into it as into the offscreen contexts. Built when CMake finds GLFW
// (Debian's libglfw3-dev); window_support() says whether it was and, if not, how to get it.
#pragma once

#include <memory>
#include <string>

#include "render/context.h"

struct GLFWwindow;

namespace collide::render {

class Window : public GlContext {
public:
    // Opens a window of width x height pixels and makes its context current. Throws
    // std::runtime_error saying why when there is no display (DISPLAY unset) or no GLFW.
    static std::unique_ptr<Window> open(int width, int height, const std::string& title);
    ~Window() override;

    GLFWwindow* handle() const { return window_; }
    void make_current() override;
    const char* backend_name() const override { return "glfw"; }
    bool should_close() const;
    void close();
    // The default framebuffer's size in pixels (may differ from the window's on HiDPI screens).
    void framebuffer_size(int* width, int* height) const;
    void swap();
    // Draws into the window again (after an offscreen target of the same context was bound).
    void use_default_framebuffer();
    // Reads the default framebuffer's back buffer (what the next swap shows) as RGBA, top row first.
    void read_back_buffer(int width, int height, unsigned char* rgba);

private:
    Window() = default;
    GLFWwindow* window_ = nullptr;
};

// Empty when windows are supported; otherwise what to install and rebuild.
std::string window_support();

}  // namespace collide::render
