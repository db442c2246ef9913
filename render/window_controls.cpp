#include "render/window_controls.h"

#ifdef COLLIDE_HAVE_GLFW

#define GLFW_INCLUDE_NONE  // GL types come from render/gl.h; functions from the context
#include <GLFW/glfw3.h>
#include <cstdint>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "render/gl.h"

namespace collide::render {

WindowControls::WindowControls(Window& window, float font_px, const ImWchar* glyphs) : window_(window) {
    context_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(context_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.Fonts->AddFontFromFileTTF("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", font_px, nullptr, glyphs);
    ImGui::StyleColorsLight();
    ImGui::GetStyle().WindowRounding = 0.0f;
    ImGui_ImplGlfw_InitForOpenGL(window.handle(), true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
}

WindowControls::~WindowControls() {
    ImGui::SetCurrentContext(context_);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext(context_);
}

void WindowControls::make_current() { ImGui::SetCurrentContext(context_); }

void WindowControls::poll_events(double wait) {
    if (wait > 0) glfwWaitEventsTimeout(wait);
    else glfwPollEvents();
}

void WindowControls::begin_frame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void WindowControls::end_frame(const float background[4]) {
    ImGui::Render();
    int fb_w = 0, fb_h = 0;
    window_.framebuffer_size(&fb_w, &fb_h);
    const Gl& gl = window_.gl();
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.Viewport(0, 0, fb_w, fb_h);
    gl.ClearColor(background[0], background[1], background[2], background[3]);
    gl.Clear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

// GLFW's letter keys are their upper-case ASCII codes (GLFW_KEY_A = 'A'), and ImGui 1.86's
// GLFW backend indexes KeysDown by GLFW's key codes.
bool WindowControls::letter_pressed(char upper) {
    static_assert(GLFW_KEY_A == 'A' && GLFW_KEY_Z == 'Z', "GLFW letter keys are ASCII");
    return ImGui::IsKeyPressed(static_cast<int>(upper));
}

WindowImage::~WindowImage() {
    if (texture_) window_.gl().DeleteTextures(1, &texture_);
}

void WindowImage::upload(int width, int height, const unsigned char* rgba) {
    const Gl& gl = window_.gl();
    if (!texture_) gl.GenTextures(1, &texture_);
    gl.BindTexture(GL_TEXTURE_2D, texture_);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // pixel for pixel
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
}

void WindowImage::draw_behind(int width, int height) const {
    ImGui::GetBackgroundDrawList()->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture_)),
                                             ImVec2(0, 0),
                                             ImVec2(static_cast<float>(width), static_cast<float>(height)));
}

}  // namespace collide::render

#endif
