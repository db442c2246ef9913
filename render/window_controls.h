// The controls drawn over a window (`collide gui`): a Dear ImGui context of their own with
// Debian's prebuilt GLFW and OpenGL 3 backends (the frames' ImGui context lives in the
// renderer), and the window's events. Everything that speaks to GLFW or to ImGui's backends
// is here, so the command draws its panels with ImGui's widgets alone. Only with GLFW
// (COLLIDE_HAVE_GLFW).
#pragma once

#ifdef COLLIDE_HAVE_GLFW

#include <imgui.h>

#include "render/window.h"

namespace collide::render {

class WindowControls {
public:
    // A context with the label font (DejaVu Sans) at `font_px` pixels with `glyphs` (ImGui's
    // ranges, 0-terminated), the light style, square windows, no .ini file.
    WindowControls(Window& window, float font_px, const ImWchar* glyphs);
    ~WindowControls();
    WindowControls(const WindowControls&) = delete;
    WindowControls& operator=(const WindowControls&) = delete;

    void make_current();
    // Handles the window's events: at once (`wait` 0), or waiting for one at most `wait` s.
    void poll_events(double wait);
    // Starts the controls' ImGui frame (make_current first).
    void begin_frame();
    // Renders the frame's controls into the window's back buffer over `background` (RGBA 0..1).
    void end_frame(const float background[4]);
    // A letter key ('A' to 'Z') pressed in this frame.
    static bool letter_pressed(char upper);

private:
    Window& window_;
    ImGuiContext* context_ = nullptr;
};

// An RGBA image shown pixel for pixel behind the controls (the frame the renderer drew), as
// a texture of the window's context.
class WindowImage {
public:
    explicit WindowImage(Window& window) : window_(window) {}
    ~WindowImage();
    WindowImage(const WindowImage&) = delete;
    WindowImage& operator=(const WindowImage&) = delete;

    // The image's pixels (top row first), width x height.
    void upload(int width, int height, const unsigned char* rgba);
    // Behind the current controls' windows, its top left corner at the window's.
    void draw_behind(int width, int height) const;

private:
    Window& window_;
    unsigned texture_ = 0;
};

}  // namespace collide::render

#endif
