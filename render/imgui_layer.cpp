#include "render/imgui_layer.h"

#include <imgui.h>
#include <imgui_freetype.h>
#include <imgui_internal.h>  // ImTextCharFromUtf8

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace collide::render {

namespace {

// The glyphs the labels use (pairs of inclusive ranges, zero-terminated). ImWchar is 16 bits
// in Debian's build, so everything here is in the Basic Multilingual Plane.
const ImWchar kGlyphRanges[] = {
    0x0020, 0x00FF,  // Basic Latin, Latin-1 (², ³, ¹, ·, ×, ½, °)
    0x0370, 0x03FF,  // Greek (ω, α, β, θ, μ, Δ, Σ)
    0x1D2C, 0x1D6A,  // modifier letters (ᵀ) and phonetic subscripts: ᵢ ᵣ ᵤ ᵥ ᵦ ᵧ ᵨ ᵩ ᵪ
    0x2010, 0x2027,  // dashes, quotes, bullet, ellipsis
    0x2030, 0x203A,  // per mille, primes (′ ″)
    0x2070, 0x209F,  // superscripts and subscripts (⁻¹, ⁰..⁹, ₀..₉, ₐ ₑ ₒ ₓ ...)
    0x2190, 0x21FF,  // arrows
    0x2200, 0x22FF,  // mathematical operators (−, √, ∑, ≤, ≈, ⋅)
    0x25A0, 0x25FF,  // geometric shapes (legend marks)
    0,
};

std::vector<char> read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": font not found (Debian: apt-get install fonts-dejavu-core)");
    return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

const char* kVertex = R"(#version 330 core
layout(location = 0) in vec2 position;
layout(location = 1) in vec2 uv;
layout(location = 2) in vec4 colour;
uniform mat4 projection;
out vec2 f_uv;
out vec4 f_colour;
void main() {
    f_uv = uv;
    f_colour = colour;
    gl_Position = projection * vec4(position, 0.0, 1.0);
})";

const char* kFragment = R"(#version 330 core
uniform sampler2D atlas;
in vec2 f_uv;
in vec4 f_colour;
out vec4 colour;
void main() { colour = f_colour * texture(atlas, f_uv); })";

}  // namespace

FontSizes FontSizes::for_height(int height) {
    const float s = static_cast<float>(height) / 720.0f;
    const auto px = [s](float at720, float least) { return std::max(least, std::round(at720 * s)); };
    return {px(19.0f, 9.0f), px(13.0f, 7.0f), px(22.0f, 10.0f), px(16.0f, 8.0f)};
}

namespace {

// Throws with GL's log when a shader did not compile or a program did not link (the object
// deleted first). The shader and program calls have the same signatures.
void check_built(const Gl& gl, GLuint object, bool shader) {
    GLint ok = 0;
    (shader ? gl.GetShaderiv : gl.GetProgramiv)(object, shader ? GL_COMPILE_STATUS : GL_LINK_STATUS, &ok);
    if (ok) return;
    char log[2048] = "";
    (shader ? gl.GetShaderInfoLog : gl.GetProgramInfoLog)(object, sizeof log, nullptr, log);
    (shader ? gl.DeleteShader : gl.DeleteProgram)(object);
    throw std::runtime_error(std::string(shader ? "shader compilation failed: " : "shader linking failed: ") + log);
}

}  // namespace

GLuint build_program(const Gl& gl, const char* vertex_source, const char* fragment_source,
                     const std::vector<std::pair<GLuint, const char*>>& attributes) {
    const auto compile = [&gl](GLenum type, const char* source) {
        const GLuint s = gl.CreateShader(type);
        gl.ShaderSource(s, 1, &source, nullptr);
        gl.CompileShader(s);
        check_built(gl, s, true);
        return s;
    };
    const GLuint vs = compile(GL_VERTEX_SHADER, vertex_source);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment_source);
    const GLuint p = gl.CreateProgram();
    gl.AttachShader(p, vs);
    gl.AttachShader(p, fs);
    for (const auto& [index, name] : attributes) gl.BindAttribLocation(p, index, name);
    gl.LinkProgram(p);
    gl.DeleteShader(vs);
    gl.DeleteShader(fs);
    check_built(gl, p, false);
    return p;
}

ImGuiLayer::ImGuiLayer(const Gl& gl, int width, int height, const FontSizes& sizes, const std::string& font_dir)
    : gl_(gl), width_(width), height_(height) {
    font_files_.push_back(read_file(font_dir + "/DejaVuSans.ttf"));
    font_files_.push_back(read_file(font_dir + "/DejaVuSans-Bold.ttf"));

    IMGUI_CHECKVERSION();
    ImGuiContext* previous = ImGui::GetCurrentContext();
    context_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(context_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini
    io.LogFilename = nullptr;
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.DeltaTime = 1.0f / 60.0f;
    io.BackendRendererName = "collide-gl33";
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
    ImGui::StyleColorsLight();
    ImGui::GetStyle().CircleTessellationMaxError = 0.2f;  // smooth circles at any size

    ImFontAtlas* atlas = io.Fonts;
    atlas->FontBuilderIO = ImGuiFreeType::GetBuilderForFreeType();
    atlas->FontBuilderFlags = ImGuiFreeTypeBuilderFlags_LightHinting;
    const auto add = [&](std::vector<char>& file, float px) {
        ImFontConfig config;
        config.FontDataOwnedByAtlas = false;
        config.OversampleH = 1;  // FreeType ignores oversampling; keep the atlas small
        config.PixelSnapH = true;
        ImFont* f = atlas->AddFontFromMemoryTTF(file.data(), static_cast<int>(file.size()), px, &config, kGlyphRanges);
        if (!f) throw std::runtime_error("Dear ImGui could not load a font");
        return f;
    };
    fonts_.text = add(font_files_[0], sizes.text);
    fonts_.small = add(font_files_[0], sizes.small);
    fonts_.bold = add(font_files_[1], sizes.bold);
    fonts_.table = add(font_files_[0], sizes.table);
    fonts_.text_px = sizes.text;
    fonts_.small_px = sizes.small;
    fonts_.bold_px = sizes.bold;
    fonts_.table_px = sizes.table;
    unsigned char* pixels = nullptr;
    int tw = 0, th = 0;
    atlas->GetTexDataAsRGBA32(&pixels, &tw, &th);
    if (!pixels) throw std::runtime_error("Dear ImGui could not build its font atlas");

    gl_.GenTextures(1, &font_texture_);
    gl_.BindTexture(GL_TEXTURE_2D, font_texture_);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);  // bilinear: AA lines
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, tw, th, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    atlas->SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(font_texture_)));
    atlas->ClearTexData();

    program_ = build_program(gl_, kVertex, kFragment, {});
    proj_location_ = gl_.GetUniformLocation(program_, "projection");
    tex_location_ = gl_.GetUniformLocation(program_, "atlas");
    gl_.GenVertexArrays(1, &vao_);
    gl_.GenBuffers(1, &vbo_);
    gl_.GenBuffers(1, &ibo_);
    gl_.BindVertexArray(vao_);
    gl_.BindBuffer(GL_ARRAY_BUFFER, vbo_);
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
    gl_.EnableVertexAttribArray(0);
    gl_.EnableVertexAttribArray(1);
    gl_.EnableVertexAttribArray(2);
    const auto offset = [](std::size_t o) { return reinterpret_cast<const void*>(o); };
    gl_.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(ImDrawVert), offset(offsetof(ImDrawVert, pos)));
    gl_.VertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, sizeof(ImDrawVert), offset(offsetof(ImDrawVert, uv)));
    gl_.VertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(ImDrawVert), offset(offsetof(ImDrawVert, col)));
    gl_.BindVertexArray(0);
    check_gl(gl_, "setting up Dear ImGui");
    if (previous) ImGui::SetCurrentContext(previous);
}

ImGuiLayer::~ImGuiLayer() {
    gl_.DeleteBuffers(1, &vbo_);
    gl_.DeleteBuffers(1, &ibo_);
    gl_.DeleteVertexArrays(1, &vao_);
    gl_.DeleteProgram(program_);
    gl_.DeleteTextures(1, &font_texture_);
    ImGui::DestroyContext(context_);
}

void ImGuiLayer::begin(bool anti_aliased) {
    ImGui::SetCurrentContext(context_);
    ImGuiStyle& style = ImGui::GetStyle();
    style.AntiAliasedLines = anti_aliased;
    style.AntiAliasedLinesUseTex = anti_aliased;
    style.AntiAliasedFill = anti_aliased;
    ImGui::NewFrame();
}

ImDrawList* ImGuiLayer::draw_list() { return ImGui::GetBackgroundDrawList(); }

void ImGuiLayer::end() {
    ImGui::SetCurrentContext(context_);
    ImGui::Render();
    render_draw_data();
}

bool ImGuiLayer::has_glyphs(const std::string& utf8) const {
    const char* p = utf8.data();
    const char* end = p + utf8.size();
    while (p < end) {
        unsigned cp = 0;
        p += ImTextCharFromUtf8(&cp, p, end);
        if (cp > 0xFFFF || !fonts_.text->FindGlyphNoFallback(static_cast<ImWchar>(cp))) return false;
    }
    return true;
}

void ImGuiLayer::render_draw_data() {
    const ImDrawData* data = ImGui::GetDrawData();
    if (!data || data->CmdListsCount == 0) return;
    gl_.Enable(GL_BLEND);
    gl_.BlendEquation(GL_FUNC_ADD);
    // Colour blends over; alpha accumulates so that an opaque background stays opaque.
    gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    gl_.Disable(GL_CULL_FACE);
    gl_.Disable(GL_DEPTH_TEST);
    gl_.Enable(GL_SCISSOR_TEST);
    gl_.UseProgram(program_);
    // Pixels (origin top left, y down) to clip space.
    const float L = data->DisplayPos.x, R = L + data->DisplaySize.x;
    const float T = data->DisplayPos.y, B = T + data->DisplaySize.y;
    const float projection[16] = {2.0f / (R - L),    0, 0, 0, 0, 2.0f / (T - B), 0, 0, 0, 0, -1, 0, (R + L) / (L - R),
                                  (T + B) / (B - T), 0, 1};
    gl_.UniformMatrix4fv(proj_location_, 1, GL_FALSE, projection);
    gl_.Uniform1i(tex_location_, 0);
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindVertexArray(vao_);
    gl_.BindBuffer(GL_ARRAY_BUFFER, vbo_);
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
    for (int n = 0; n < data->CmdListsCount; ++n) {
        const ImDrawList* list = data->CmdLists[n];
        gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(list->VtxBuffer.Size) * sizeof(ImDrawVert),
                       list->VtxBuffer.Data, GL_STREAM_DRAW);
        gl_.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(list->IdxBuffer.Size) * sizeof(ImDrawIdx),
                       list->IdxBuffer.Data, GL_STREAM_DRAW);
        for (const ImDrawCmd& cmd : list->CmdBuffer) {
            if (cmd.UserCallback) {
                cmd.UserCallback(list, &cmd);
                continue;
            }
            const ImVec4 clip(cmd.ClipRect.x - L, cmd.ClipRect.y - T, cmd.ClipRect.z - L, cmd.ClipRect.w - T);
            if (clip.z <= clip.x || clip.w <= clip.y) continue;
            gl_.Scissor(static_cast<GLint>(clip.x), static_cast<GLint>(static_cast<float>(height_) - clip.w),
                        static_cast<GLsizei>(clip.z - clip.x), static_cast<GLsizei>(clip.w - clip.y));
            gl_.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(reinterpret_cast<std::uintptr_t>(cmd.GetTexID())));
            gl_.DrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(cmd.ElemCount),
                                       sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT,
                                       reinterpret_cast<const void*>(cmd.IdxOffset * sizeof(ImDrawIdx)),
                                       static_cast<GLint>(cmd.VtxOffset));
        }
    }
    gl_.Disable(GL_SCISSOR_TEST);
    gl_.BindVertexArray(0);
    check_gl(gl_, "drawing Dear ImGui's draw lists");
}

}  // namespace collide::render
