#include "render/batch3d.h"

#include <algorithm>
#include <cstddef>

#include "assets/shaders.h"      // generated from assets/shaders/ (cmake/embed.cmake)
#include "render/imgui_layer.h"  // build_program

namespace collide::render {

namespace {

// A corner of a line's quad (line.vert): the segment a-b, which end, which side, its look.
struct LineVertex {
    float a[3], b[3], corner[2], colour[4], width;
};

Vec3f colour3(Colour c) {
    return Vec3f(static_cast<float>(c & 0xFF), static_cast<float>((c >> 8) & 0xFF),
                 static_cast<float>((c >> 16) & 0xFF)) /
           255.0f;
}

}  // namespace

Batch3d::Batch3d(const Gl& gl) : gl_(gl) {
    // The embedded texts end in '\0': data() is a C string.
    mesh_program_ = build_program(gl_, shaders::mesh_vert.data(), shaders::mesh_frag.data(), {});
    line_program_ = build_program(gl_, shaders::line_vert.data(), shaders::line_frag.data(), {});
    ground_program_ = build_program(gl_, shaders::ground_vert.data(), shaders::ground_frag.data(), {});
    shadow_program_ = build_program(gl_, shaders::ground_vert.data(), shaders::shadow_frag.data(), {});

    gl_.GenVertexArrays(1, &line_vao_);
    gl_.GenBuffers(1, &line_vbo_);
    gl_.BindVertexArray(line_vao_);
    gl_.BindBuffer(GL_ARRAY_BUFFER, line_vbo_);
    const auto attr = [&](GLuint index, int n, std::size_t offset) {
        gl_.EnableVertexAttribArray(index);
        gl_.VertexAttribPointer(index, n, GL_FLOAT, GL_FALSE, sizeof(LineVertex),
                                reinterpret_cast<const void*>(offset));
    };
    attr(0, 3, offsetof(LineVertex, a));
    attr(1, 3, offsetof(LineVertex, b));
    attr(2, 2, offsetof(LineVertex, corner));
    attr(3, 4, offsetof(LineVertex, colour));
    attr(4, 1, offsetof(LineVertex, width));
    gl_.GenVertexArrays(1, &ground_vao_);
    gl_.GenBuffers(1, &ground_vbo_);
    gl_.BindVertexArray(ground_vao_);
    gl_.BindBuffer(GL_ARRAY_BUFFER, ground_vbo_);
    gl_.EnableVertexAttribArray(0);
    gl_.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    gl_.BindVertexArray(0);
    check_gl(gl_, "building the 3D view");
}

Batch3d::~Batch3d() {
    for (GpuMesh& m : meshes_) {
        if (!m.count) continue;
        gl_.DeleteBuffers(1, &m.vbo);
        gl_.DeleteVertexArrays(1, &m.vao);
    }
    gl_.DeleteBuffers(1, &line_vbo_);
    gl_.DeleteVertexArrays(1, &line_vao_);
    gl_.DeleteBuffers(1, &ground_vbo_);
    gl_.DeleteVertexArrays(1, &ground_vao_);
    gl_.DeleteProgram(mesh_program_);
    gl_.DeleteProgram(line_program_);
    gl_.DeleteProgram(ground_program_);
    gl_.DeleteProgram(shadow_program_);
}

int Batch3d::add(const Mesh& mesh) {
    GpuMesh m;
    m.count = static_cast<GLsizei>(mesh.size());
    if (m.count) {
        gl_.GenVertexArrays(1, &m.vao);
        gl_.GenBuffers(1, &m.vbo);
        gl_.BindVertexArray(m.vao);
        gl_.BindBuffer(GL_ARRAY_BUFFER, m.vbo);
        gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.size() * sizeof(Vertex)), mesh.data(),
                       GL_STATIC_DRAW);
        // Attributes 0, 1, 2: position, normal, local point (mesh.vert).
        for (GLuint a = 0; a < 3; ++a) {
            gl_.EnableVertexAttribArray(a);
            gl_.VertexAttribPointer(a, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                                    reinterpret_cast<const void*>(static_cast<std::size_t>(a) * 3 * sizeof(float)));
        }
        gl_.BindVertexArray(0);
    }
    meshes_.push_back(m);
    return static_cast<int>(meshes_.size()) - 1;
}

void Batch3d::set_camera(const Camera& camera) {
    frame_projection_ = camera.frame_projection();
    eye_ = camera.eye();
    frame_w_ = camera.frame_width();
    frame_h_ = camera.frame_height();
    const Vec3f fwd = camera.forward(), right = camera.right(), up = camera.up();
    key_light_ = (-0.45f * right + 0.75f * up - 0.5f * fwd).normalized();
    fill_light_ = (0.8f * right + 0.1f * up - 0.4f * fwd).normalized();
}

void Batch3d::begin() {
    gl_.Viewport(0, 0, frame_w_, frame_h_);
    gl_.Enable(GL_DEPTH_TEST);
    gl_.DepthFunc(GL_LEQUAL);
    gl_.DepthMask(GL_TRUE);
    gl_.Disable(GL_BLEND);
    gl_.Disable(GL_CULL_FACE);
}

void Batch3d::end(const char* what) {
    gl_.Disable(GL_DEPTH_TEST);
    gl_.BindVertexArray(0);
    check_gl(gl_, what);
}

void Batch3d::clear_depth() {
    gl_.DepthMask(GL_TRUE);
    gl_.Clear(GL_DEPTH_BUFFER_BIT);
}

void Batch3d::ground(const GroundDraw& g, const std::vector<Shadow>& shadows) {
    // The ground: one quad of plane coordinates (m), pushed back in depth.
    const float e = g.extent;
    const float quad[12] = {-e, -e, e, -e, e, e, -e, -e, e, e, -e, e};
    gl_.UseProgram(ground_program_);
    const auto u3 = [&](const char* name, const Vec3f& v) {
        gl_.Uniform3f(gl_.GetUniformLocation(ground_program_, name), v.x(), v.y(), v.z());
    };
    u3("origin", g.origin.cast<float>());
    u3("axis_u", g.u.cast<float>());
    u3("axis_v", g.v.cast<float>());
    u3("paper", colour3(g.paper));
    u3("ground", colour3(g.ground));
    u3("line_colour", colour3(g.grid));
    gl_.UniformMatrix4fv(gl_.GetUniformLocation(ground_program_, "view_projection"), 1, GL_FALSE,
                         frame_projection_.data());
    gl_.Uniform1f(gl_.GetUniformLocation(ground_program_, "spacing"), g.spacing);
    gl_.Uniform1f(gl_.GetUniformLocation(ground_program_, "fade"), e);
    gl_.BindVertexArray(ground_vao_);
    gl_.BindBuffer(GL_ARRAY_BUFFER, ground_vbo_);
    gl_.BufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STREAM_DRAW);
    gl_.Enable(GL_POLYGON_OFFSET_FILL);
    gl_.PolygonOffset(2.0f, 2.0f);
    gl_.DrawArrays(GL_TRIANGLES, 0, 6);

    // The shadows: a quad each on the same plane, blended as dst *= 1 - alpha.
    gl_.UseProgram(shadow_program_);
    gl_.UniformMatrix4fv(gl_.GetUniformLocation(shadow_program_, "view_projection"), 1, GL_FALSE,
                         frame_projection_.data());
    gl_.Uniform3f(gl_.GetUniformLocation(shadow_program_, "axis_u"), static_cast<float>(g.u.x()),
                  static_cast<float>(g.u.y()), static_cast<float>(g.u.z()));
    gl_.Uniform3f(gl_.GetUniformLocation(shadow_program_, "axis_v"), static_cast<float>(g.v.x()),
                  static_cast<float>(g.v.y()), static_cast<float>(g.v.z()));
    gl_.Enable(GL_BLEND);
    gl_.BlendFuncSeparate(GL_ZERO, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    gl_.DepthMask(GL_FALSE);
    gl_.PolygonOffset(1.0f, 1.0f);
    for (const Shadow& s : shadows) {
        const float q = s.radius;
        const float sq[12] = {-q, -q, q, -q, q, q, -q, -q, q, q, -q, q};
        gl_.Uniform3f(gl_.GetUniformLocation(shadow_program_, "origin"), static_cast<float>(s.foot.x()),
                      static_cast<float>(s.foot.y()), static_cast<float>(s.foot.z()));
        gl_.Uniform1f(gl_.GetUniformLocation(shadow_program_, "radius"), q);
        gl_.Uniform1f(gl_.GetUniformLocation(shadow_program_, "strength"), s.strength);
        gl_.BufferData(GL_ARRAY_BUFFER, sizeof sq, sq, GL_STREAM_DRAW);
        gl_.DrawArrays(GL_TRIANGLES, 0, 6);
    }
    gl_.DepthMask(GL_TRUE);
    gl_.Disable(GL_BLEND);
    gl_.Disable(GL_POLYGON_OFFSET_FILL);
}

void Batch3d::use_mesh_program() {
    gl_.UseProgram(mesh_program_);
    gl_.UniformMatrix4fv(gl_.GetUniformLocation(mesh_program_, "view_projection"), 1, GL_FALSE,
                         frame_projection_.data());
    gl_.Uniform3f(gl_.GetUniformLocation(mesh_program_, "eye"), eye_.x(), eye_.y(), eye_.z());
    gl_.Uniform3f(gl_.GetUniformLocation(mesh_program_, "key_light"), key_light_.x(), key_light_.y(), key_light_.z());
    gl_.Uniform3f(gl_.GetUniformLocation(mesh_program_, "fill_light"), fill_light_.x(), fill_light_.y(),
                  fill_light_.z());
}

void Batch3d::meshes(const std::vector<MeshDraw>& draws, MeshDepth depth) {
    if (depth == MeshDepth::over) gl_.Disable(GL_DEPTH_TEST);
    else gl_.Enable(GL_DEPTH_TEST);
    if (depth == MeshDepth::behind_lines) {
        gl_.Enable(GL_POLYGON_OFFSET_FILL);
        gl_.PolygonOffset(1.0f, 1.0f);
    }
    use_mesh_program();
    for (const MeshDraw& d : draws) {
        gl_.UniformMatrix4fv(gl_.GetUniformLocation(mesh_program_, "model"), 1, GL_FALSE, d.model.data());
        gl_.UniformMatrix3fv(gl_.GetUniformLocation(mesh_program_, "normal_matrix"), 1, GL_FALSE,
                             d.normal_matrix.data());
        const Vec3f c = colour3(d.colour);
        gl_.Uniform3f(gl_.GetUniformLocation(mesh_program_, "base"), c.x(), c.y(), c.z());
        gl_.Uniform1i(gl_.GetUniformLocation(mesh_program_, "pattern"), d.pattern);
        const GpuMesh& m = meshes_[static_cast<std::size_t>(d.mesh)];
        gl_.BindVertexArray(m.vao);
        gl_.DrawArrays(GL_TRIANGLES, 0, m.count);
    }
    if (depth == MeshDepth::behind_lines) gl_.Disable(GL_POLYGON_OFFSET_FILL);
}

void Batch3d::lines(const std::vector<Segment>& segments, bool depth_test, float depth_bias) {
    if (segments.empty()) return;
    // Six vertices a segment (two triangles), expanded to its width in line.vert.
    std::vector<LineVertex> vertices;
    vertices.reserve(6 * segments.size());
    const float corners[6][2] = {{0, -1}, {1, -1}, {1, 1}, {0, -1}, {1, 1}, {0, 1}};
    for (const Segment& s : segments) {
        const float col[4] = {
            static_cast<float>(s.colour & 0xFF) / 255.0f, static_cast<float>((s.colour >> 8) & 0xFF) / 255.0f,
            static_cast<float>((s.colour >> 16) & 0xFF) / 255.0f, static_cast<float>((s.colour >> 24) & 0xFF) / 255.0f};
        for (const auto& c : corners) {
            LineVertex v;
            for (int k = 0; k < 3; ++k) {
                v.a[k] = static_cast<float>(s.a[k]);
                v.b[k] = static_cast<float>(s.b[k]);
            }
            v.corner[0] = c[0];
            v.corner[1] = c[1];
            std::copy(col, col + 4, v.colour);
            v.width = s.width;
            vertices.push_back(v);
        }
    }
    gl_.UseProgram(line_program_);
    gl_.UniformMatrix4fv(gl_.GetUniformLocation(line_program_, "view_projection"), 1, GL_FALSE,
                         frame_projection_.data());
    gl_.Uniform2f(gl_.GetUniformLocation(line_program_, "viewport"), static_cast<float>(frame_w_),
                  static_cast<float>(frame_h_));
    gl_.Uniform1f(gl_.GetUniformLocation(line_program_, "depth_bias"), depth_bias);
    if (depth_test) gl_.Enable(GL_DEPTH_TEST);
    else gl_.Disable(GL_DEPTH_TEST);
    gl_.Enable(GL_BLEND);
    gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    gl_.DepthMask(GL_FALSE);
    gl_.BindVertexArray(line_vao_);
    gl_.BindBuffer(GL_ARRAY_BUFFER, line_vbo_);
    gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(LineVertex)), vertices.data(),
                   GL_STREAM_DRAW);
    gl_.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
    gl_.BindVertexArray(0);
    gl_.Disable(GL_BLEND);
    gl_.DepthMask(GL_TRUE);
}

}  // namespace collide::render
