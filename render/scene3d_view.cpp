#include "render/scene3d_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "assets/shaders.h"  // generated from assets/shaders/ (cmake/embed.cmake)
#include "render/camera.h"
#include "render/imgui_layer.h"  // build_program
#include "render/mesh.h"
#include "render/scale.h"
#include "render/solid.h"

namespace collide::render {

namespace {

Vec3f f3(const Vec3& v) { return v.cast<float>(); }

Vec3f colour3(Colour c) {
    return Vec3f(static_cast<float>(c & 0xFF), static_cast<float>((c >> 8) & 0xFF),
                 static_cast<float>((c >> 16) & 0xFF)) / 255.0f;
}

struct LineVertex {
    float a[3], b[3], corner[2], colour[4], width;
};

// A mesh on the GPU, and its bounds in its own frame.
struct GpuMesh {
    GLuint vao = 0, vbo = 0;
    GLsizei count = 0;
    Vec3f lo = Vec3f::Zero(), hi = Vec3f::Zero();
};

// What above_bounds() gathers: the screen box of everything a pass would draw.
struct ScreenBox {
    float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
    bool everywhere = false;  // a point behind the eye: take the whole frame
    void add(float x, float y, float pad) {
        x0 = std::min(x0, x - pad);
        y0 = std::min(y0, y - pad);
        x1 = std::max(x1, x + pad);
        y1 = std::max(y1, y + pad);
    }
};

}  // namespace

struct Scene3dView::Impl {
    const Gl& gl;
    const Scene& scene;
    Style style;

    GLuint mesh_program = 0, line_program = 0, ground_program = 0, shadow_program = 0;
    std::vector<GpuMesh> body_meshes;            // per body (count 0: none, e.g. a plane)
    Solids solids;                            // the bodies' shapes in 3D (render/solid.h)
    GpuMesh cylinder, cone;
    GLuint line_vao = 0, line_vbo = 0, ground_vao = 0, ground_vbo = 0;
    std::vector<LineVertex> lines;

    Camera camera;
    Vec3f key_light, fill_light;
    double radius = 1.0;           // of the framed region (m)
    Vec3 centre = Vec3::Zero();
    double unit = 0.1;             // arrow thickness reference (m)
    double k_velocity = 0, k_impulse = 0, k_spin = 0, max_spin = 0;
    // The ground (the first upward plane, or a reference floor under the bodies).
    bool has_ground = false;
    Vec3 ground_origin = Vec3::Zero(), ground_u = Vec3::UnitX(), ground_v = -Vec3::UnitZ();
    Vec3 ground_normal = Vec3::UnitY();
    double ground_extent = 5.0, grid_spacing = 0.5;

    Impl(const Gl& g, const Scene& s, const Style& st) : gl(g), scene(s), style(st) {}

    GpuMesh upload(const Mesh& v) {
        GpuMesh m;
        m.count = static_cast<GLsizei>(v.size());
        const Box3f box = render::bounds(v);
        m.lo = box.lo;
        m.hi = box.hi;
        gl.GenVertexArrays(1, &m.vao);
        gl.GenBuffers(1, &m.vbo);
        gl.BindVertexArray(m.vao);
        gl.BindBuffer(GL_ARRAY_BUFFER, m.vbo);
        gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(Vertex)), v.data(),
                      GL_STATIC_DRAW);
        for (GLuint a = 0; a < 3; ++a) {
            gl.EnableVertexAttribArray(a);
            gl.VertexAttribPointer(a, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                                   reinterpret_cast<const void*>(static_cast<std::size_t>(a) * 3 * sizeof(float)));
        }
        gl.BindVertexArray(0);
        return m;
    }

    void build() {
        // The embedded texts end in '\0': data() is a C string.
        mesh_program = build_program(gl, shaders::mesh_vert.data(), shaders::mesh_frag.data(), {});
        line_program = build_program(gl, shaders::line_vert.data(), shaders::line_frag.data(), {});
        ground_program = build_program(gl, shaders::ground_vert.data(), shaders::ground_frag.data(), {});
        shadow_program = build_program(gl, shaders::ground_vert.data(), shaders::shadow_frag.data(), {});
        cylinder = upload(arrow_shaft());
        cone = upload(arrow_head());

        solids = make_solids(scene);
        for (const Solid& solid : solids.bodies)
            body_meshes.push_back(solid.mesh.empty() ? GpuMesh{} : upload(solid.mesh));

        gl.GenVertexArrays(1, &line_vao);
        gl.GenBuffers(1, &line_vbo);
        gl.BindVertexArray(line_vao);
        gl.BindBuffer(GL_ARRAY_BUFFER, line_vbo);
        const auto attr = [&](GLuint index, int n, std::size_t offset) {
            gl.EnableVertexAttribArray(index);
            gl.VertexAttribPointer(index, n, GL_FLOAT, GL_FALSE, sizeof(LineVertex),
                                   reinterpret_cast<const void*>(offset));
        };
        attr(0, 3, offsetof(LineVertex, a));
        attr(1, 3, offsetof(LineVertex, b));
        attr(2, 2, offsetof(LineVertex, corner));
        attr(3, 4, offsetof(LineVertex, colour));
        attr(4, 1, offsetof(LineVertex, width));
        gl.GenVertexArrays(1, &ground_vao);
        gl.GenBuffers(1, &ground_vbo);
        gl.BindVertexArray(ground_vao);
        gl.BindBuffer(GL_ARRAY_BUFFER, ground_vbo);
        gl.EnableVertexAttribArray(0);
        gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
        gl.BindVertexArray(0);
        check_gl(gl, "building the 3D view");
    }

    ~Impl() {
        for (GpuMesh* m : {&cylinder, &cone}) {
            gl.DeleteBuffers(1, &m->vbo);
            gl.DeleteVertexArrays(1, &m->vao);
        }
        for (GpuMesh& m : body_meshes) {
            if (!m.count) continue;
            gl.DeleteBuffers(1, &m.vbo);
            gl.DeleteVertexArrays(1, &m.vao);
        }
        gl.DeleteBuffers(1, &line_vbo);
        gl.DeleteVertexArrays(1, &line_vao);
        gl.DeleteBuffers(1, &ground_vbo);
        gl.DeleteVertexArrays(1, &ground_vao);
        gl.DeleteProgram(mesh_program);
        gl.DeleteProgram(line_program);
        gl.DeleteProgram(ground_program);
        gl.DeleteProgram(shadow_program);
    }

    // Every body's points over the run (corners of its bounds), for framing.
    void bounds(const BodyState& s, std::size_t i, Vec3* lo, Vec3* hi) const {
        if (!body_meshes[i].count) return;
        const double r = 0.5 * solids.bodies[i].size;
        *lo = lo->cwiseMin(s.x - Vec3(r, r, r));
        *hi = hi->cwiseMax(s.x + Vec3(r, r, r));
    }

    Vec3 velocity_start(std::size_t i, const BodyState& s) const {
        const double v = s.v.norm();
        // From where the arrow leaves the surface, so that the body does not hide it.
        return v > 0 ? s.x + s.v / v * exit_distance(solids.bodies[i], s.q, s.v / v) : s.x;
    }
    // The projected outline of body i (screen points, convex), for label placement.
    std::vector<ImVec2> screen_outline(std::size_t i, const BodyState& s) const {
        std::vector<ImVec2> pts;
        if (solids.bodies[i].kind == Solid::Kind::sphere) {
            const ImVec2 c = camera.project(s.x);
            const Vec3 right = camera.right().cast<double>();
            const ImVec2 e = camera.project(s.x + right * solids.bodies[i].radius);
            const float r = std::hypot(e.x - c.x, e.y - c.y);
            for (int k = 0; k < 16; ++k) {
                const float a = 2.0f * static_cast<float>(kPi) * static_cast<float>(k) / 16.0f;
                pts.push_back(ImVec2(c.x + r * std::cos(a), c.y + r * std::sin(a)));
            }
            return pts;
        }
        std::vector<Vec2> screen;
        for (const auto& [a, b] : solids.bodies[i].edges)
            for (const Vec3f& p : {a, b}) {
                const ImVec2 q = camera.project(s.x + s.q * p.cast<double>());
                screen.push_back(Vec2(q.x, q.y));
            }
        // Convex hull (monotone chain).
        std::sort(screen.begin(), screen.end(), [](const Vec2& a, const Vec2& b) {
            return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
        });
        if (screen.size() < 3) return pts;
        std::vector<Vec2> h(2 * screen.size());
        std::size_t k = 0;
        const auto turn = [](const Vec2& o, const Vec2& a, const Vec2& b) {
            return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
        };
        for (std::size_t j = 0; j < screen.size(); ++j) {
            while (k >= 2 && turn(h[k - 2], h[k - 1], screen[j]) <= 0) --k;
            h[k++] = screen[j];
        }
        for (std::size_t j = screen.size() - 1, t = k + 1; j > 0; --j) {
            while (k >= t && turn(h[k - 2], h[k - 1], screen[j - 1]) <= 0) --k;
            h[k++] = screen[j - 1];
        }
        for (std::size_t j = 0; j + 1 < k; ++j)
            pts.push_back(ImVec2(static_cast<float>(h[j].x()), static_cast<float>(h[j].y())));
        return pts;
    }

    // Collecting (above_bounds): the screen box of what would be drawn, instead of drawing.
    ScreenBox* collect = nullptr;
    void collect_point(const Vec3f& p, float pad) const {
        if (!camera.in_front(p)) {
            collect->everywhere = true;
            return;
        }
        const ImVec2 q = camera.project(p.cast<double>());
        collect->add(q.x, q.y, pad);
    }

    // Thick lines (pixels) through the line program.
    void line(const Vec3& a, const Vec3& b, Colour colour, float width) {
        if (collect) {
            collect_point(f3(a), 0.5f * width + 2.0f);
            collect_point(f3(b), 0.5f * width + 2.0f);
            return;
        }
        const float col[4] = {static_cast<float>(colour & 0xFF) / 255.0f,
                              static_cast<float>((colour >> 8) & 0xFF) / 255.0f,
                              static_cast<float>((colour >> 16) & 0xFF) / 255.0f,
                              static_cast<float>((colour >> 24) & 0xFF) / 255.0f};
        const float corners[6][2] = {{0, -1}, {1, -1}, {1, 1}, {0, -1}, {1, 1}, {0, 1}};
        for (const auto& c : corners) {
            LineVertex v;
            for (int k = 0; k < 3; ++k) {
                v.a[k] = static_cast<float>(a[k]);
                v.b[k] = static_cast<float>(b[k]);
            }
            v.corner[0] = c[0];
            v.corner[1] = c[1];
            std::copy(col, col + 4, v.colour);
            v.width = width;
            lines.push_back(v);
        }
    }

    void flush_lines(bool depth_test, float bias) {
        if (lines.empty()) return;
        gl.UseProgram(line_program);
        gl.UniformMatrix4fv(gl.GetUniformLocation(line_program, "view_projection"), 1, GL_FALSE,
                            camera.frame_projection().data());
        gl.Uniform2f(gl.GetUniformLocation(line_program, "viewport"), static_cast<float>(camera.frame_width()),
                     static_cast<float>(camera.frame_height()));
        gl.Uniform1f(gl.GetUniformLocation(line_program, "depth_bias"), bias);
        if (depth_test) gl.Enable(GL_DEPTH_TEST);
        else gl.Disable(GL_DEPTH_TEST);
        gl.Enable(GL_BLEND);
        gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        // Lines do not write depth: their faded fringes would punch holes in what is drawn later.
        gl.DepthMask(GL_FALSE);
        gl.BindVertexArray(line_vao);
        gl.BindBuffer(GL_ARRAY_BUFFER, line_vbo);
        gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(lines.size() * sizeof(LineVertex)),
                      lines.data(), GL_STREAM_DRAW);
        gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(lines.size()));
        gl.BindVertexArray(0);
        gl.Disable(GL_BLEND);
        gl.DepthMask(GL_TRUE);
        lines.clear();
    }

    void use_mesh_program() {
        gl.UseProgram(mesh_program);
        gl.UniformMatrix4fv(gl.GetUniformLocation(mesh_program, "view_projection"), 1, GL_FALSE,
                            camera.frame_projection().data());
        const Vec3f& eye = camera.eye();
        gl.Uniform3f(gl.GetUniformLocation(mesh_program, "eye"), eye.x(), eye.y(), eye.z());
        gl.Uniform3f(gl.GetUniformLocation(mesh_program, "key_light"), key_light.x(), key_light.y(), key_light.z());
        gl.Uniform3f(gl.GetUniformLocation(mesh_program, "fill_light"), fill_light.x(), fill_light.y(), fill_light.z());
    }

    void draw_mesh(const GpuMesh& m, const Mat4f& model, const Mat3f& normal_matrix, Colour colour,
                   int pattern) {
        if (collect) {
            for (int k = 0; k < 8; ++k) {
                const Vec3f local((k & 1) ? m.hi.x() : m.lo.x(), (k & 2) ? m.hi.y() : m.lo.y(),
                                  (k & 4) ? m.hi.z() : m.lo.z());
                collect_point((model * local.homogeneous()).head<3>(), 2.0f);
            }
            return;
        }
        gl.UniformMatrix4fv(gl.GetUniformLocation(mesh_program, "model"), 1, GL_FALSE, model.data());
        gl.UniformMatrix3fv(gl.GetUniformLocation(mesh_program, "normal_matrix"), 1, GL_FALSE,
                            normal_matrix.data());
        const Vec3f c = colour3(colour);
        gl.Uniform3f(gl.GetUniformLocation(mesh_program, "base"), c.x(), c.y(), c.z());
        gl.Uniform1i(gl.GetUniformLocation(mesh_program, "pattern"), pattern);
        gl.BindVertexArray(m.vao);
        gl.DrawArrays(GL_TRIANGLES, 0, m.count);
    }

    // A shaded arrow from p along d (world vector); length |d|.
    void arrow(const Vec3& p, const Vec3& d, Colour colour, double thickness) {
        const double len = d.norm();
        if (len < 1e-9) return;
        double head = 4.5 * thickness, head_r = 2.2 * thickness;
        if (len < 1.5 * head) {
            head_r *= len / (1.5 * head);
            head = len / 1.5;
        }
        const Mat3f R = rotation_from_y(f3(d / len));
        const auto model = [&](const Vec3& at, float rx, float ly) {
            Mat4f m = Mat4f::Identity();
            m.block<3, 3>(0, 0) = R * Eigen::DiagonalMatrix<float, 3>(rx, ly, rx);
            m.block<3, 1>(0, 3) = f3(at);
            return m;
        };
        const double shaft = len - head;
        if (shaft > 0)
            draw_mesh(cylinder, model(p, static_cast<float>(thickness), static_cast<float>(shaft)), R, colour, 0);
        draw_mesh(cone, model(p + d / len * shaft, static_cast<float>(head_r), static_cast<float>(head)), R, colour, 0);
    }
};

Scene3dView::Scene3dView(const Gl& gl, const Scene& scene, const Style& style)
    : impl_(std::make_unique<Impl>(gl, scene, style)) {
    impl_->build();
}

Scene3dView::~Scene3dView() = default;

void Scene3dView::fit(const std::vector<FrameState>& samples, const std::vector<ImpactMark>& impacts,
                      ImVec4 viewport, int frame_width, int frame_height) {
    Impl& I = *impl_;
    I.camera.set_viewport(viewport, frame_width, frame_height);
    const double inf = std::numeric_limits<double>::infinity();
    Vec3 lo(inf, inf, inf), hi(-inf, -inf, -inf);
    double max_speed = 0, max_impulse = 0;
    max_spin_ = 0;
    for (const FrameState& f : samples)
        for (std::size_t i = 0; i < f.bodies.size() && i < I.scene.bodies.size(); ++i) {
            I.bounds(f.bodies[i], i, &lo, &hi);
            if (I.scene.bodies[i].is_static()) continue;
            max_speed = std::max(max_speed, f.bodies[i].v.norm());
            max_spin_ = std::max(max_spin_, f.bodies[i].w.norm());
        }
    for (const ImpactMark& im : impacts) max_impulse = std::max(max_impulse, im.impulse.norm());
    if (!(lo.x() < inf)) {
        lo = Vec3(-1, -1, -1);
        hi = Vec3(1, 1, 1);
    }
    I.max_spin = max_spin_;
    std::vector<float> moving;
    for (std::size_t i = 0; i < I.solids.bodies.size(); ++i)
        if (!I.scene.bodies[i].is_static() && I.solids.bodies[i].size > 0) moving.push_back(I.solids.bodies[i].size);
    std::sort(moving.begin(), moving.end());
    const double body = moving.empty() ? 0.3 * (hi - lo).norm() : moving[moving.size() / 2];
    const double span = std::max(1e-6, (hi - lo).norm());
    I.unit = std::clamp(body, 0.05 * span, 0.4 * span);
    const double arrow_len = std::clamp(body * 1.1, 0.12 * span, 0.35 * span);
    I.k_velocity = max_speed > 0 ? arrow_len / max_speed : 0;
    I.k_impulse = max_impulse > 0 ? 0.9 * arrow_len / max_impulse : 0;
    for (const ImpactMark& im : impacts)  // none longer than half the smaller body
        for (std::size_t i : {im.a, im.b})
            if (i < I.solids.bodies.size() && I.solids.bodies[i].size > 0 && im.impulse.norm() > 0)
                I.k_impulse = std::min(I.k_impulse, 0.5 * I.solids.bodies[i].size / im.impulse.norm());
    I.k_spin = max_spin_ > 0 ? 0.8 * arrow_len / max_spin_ : 0;
    // Room for the velocity arrows.
    for (const FrameState& f : samples)
        for (std::size_t i = 0; i < f.bodies.size() && i < I.scene.bodies.size(); ++i) {
            if (I.scene.bodies[i].is_static() || !I.body_meshes[i].count) continue;
            const Vec3 tip = f.bodies[i].x + I.k_velocity * f.bodies[i].v +
                             (f.bodies[i].v.norm() > 0 ? Vec3(0.5 * I.solids.bodies[i].size * f.bodies[i].v.normalized()) : Vec3(Vec3::Zero()));
            lo = lo.cwiseMin(tip);
            hi = hi.cwiseMax(tip);
        }
    I.centre = 0.5 * (lo + hi);
    I.radius = std::max(1e-3, 0.5 * (hi - lo).norm());

    // The ground: the first plane facing up, else a floor under the lowest point.
    I.has_ground = false;
    for (const auto& [n, offset] : I.solids.planes) {
        if (n.y() < 0.7) continue;
        const double nn = n.norm();
        I.ground_normal = n / nn;
        const double o = offset / nn;
        I.ground_origin = I.centre - (I.ground_normal.dot(I.centre) - o) * I.ground_normal;
        I.has_ground = true;
        break;
    }
    if (!I.has_ground) {
        I.ground_normal = Vec3::UnitY();
        I.ground_origin = Vec3(I.centre.x(), lo.y(), I.centre.z());
    }
    // Plane coordinates: u along x where possible, v = n x u.
    I.ground_u = Vec3::UnitX() - Vec3::UnitX().dot(I.ground_normal) * I.ground_normal;
    if (I.ground_u.norm() < 0.3) I.ground_u = Vec3::UnitZ() - Vec3::UnitZ().dot(I.ground_normal) * I.ground_normal;
    I.ground_u.normalize();
    I.ground_v = I.ground_normal.cross(I.ground_u);
    // Include the ground's foot in the framing.
    lo = lo.cwiseMin(I.ground_origin);
    hi = hi.cwiseMax(I.ground_origin);
    I.centre = 0.5 * (lo + hi);
    I.radius = std::max(1e-3, 0.5 * (hi - lo).norm());
    I.ground_extent = 2.2 * I.radius;
    I.grid_spacing = round_value(I.radius / 5.0);

    // The camera on the box.
    I.camera.frame(lo, hi, I.centre, I.radius, camera_, I.scene.dimension);
    // Lights in the viewer's frame: the key from the upper left, the fill from the right.
    const Vec3f fwd = I.camera.forward(), right = I.camera.right(), up = I.camera.up();
    I.key_light = (-0.45f * right + 0.75f * up - 0.5f * fwd).normalized();
    I.fill_light = (0.8f * right + 0.1f * up - 0.4f * fwd).normalized();
}

ImVec2 Scene3dView::to_screen(const Vec3& world) const { return impl_->camera.project(world); }

double Scene3dView::pixels_per_metre() const {
    const Impl& I = *impl_;
    const Vec3 right = I.camera.right().cast<double>();
    const ImVec2 a = I.camera.project(I.centre), b = I.camera.project(I.centre + right);
    return std::hypot(b.x - a.x, b.y - a.y);
}

DiagramView::Legend Scene3dView::velocity_legend() const {
    const Impl& I = *impl_;
    if (!(I.k_velocity > 0)) return {};
    // Pixels per metre at the scene's centre, across the view.
    const Vec3 right = I.camera.right().cast<double>();
    const float ppm = std::abs(I.camera.project(I.centre + right).x - I.camera.project(I.centre).x);
    const double px_per_unit = I.k_velocity * ppm;
    const double value = round_value(I.style.px(70.0f) / px_per_unit);
    return {value, static_cast<float>(value * px_per_unit)};
}

DiagramView::Legend Scene3dView::impulse_legend() const {
    const Impl& I = *impl_;
    if (!(I.k_impulse > 0)) return {};
    const Vec3 right = I.camera.right().cast<double>();
    const float ppm = std::abs(I.camera.project(I.centre + right).x - I.camera.project(I.centre).x);
    const double px_per_unit = I.k_impulse * ppm;
    const double value = round_value(I.style.px(70.0f) / px_per_unit);
    return {value, static_cast<float>(value * px_per_unit)};
}

namespace {

void begin_pass(const Gl& gl, int width, int height) {
    gl.Viewport(0, 0, width, height);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LEQUAL);
    gl.DepthMask(GL_TRUE);
    gl.Disable(GL_BLEND);
    gl.Disable(GL_CULL_FACE);
}

}  // namespace

void Scene3dView::draw(const FrameState& frame, const Decor& decor) {
    draw_ground(frame);
    draw_above(frame, decor);
}

bool Scene3dView::above_bounds(const FrameState& frame, const Decor& decor, ImVec4* rect) {
    ScreenBox box;
    impl_->collect = &box;
    draw_above(frame, decor);
    impl_->collect = nullptr;
    if (box.everywhere) {
        *rect = ImVec4(0, 0, static_cast<float>(impl_->camera.frame_width()),
                       static_cast<float>(impl_->camera.frame_height()));
        return true;
    }
    if (!(box.x0 <= box.x1)) return false;
    *rect = ImVec4(box.x0, box.y0, box.x1, box.y1);
    return true;
}

void Scene3dView::draw_ground(const FrameState& frame) {
    Impl& I = *impl_;
    const Gl& gl = I.gl;
    const Palette& pal = I.style.colours;
    begin_pass(gl, I.camera.frame_width(), I.camera.frame_height());
    const std::size_t n = std::min(frame.bodies.size(), I.scene.bodies.size());

    // The ground, its grid and the bodies' shadows.
    {
        const float e = static_cast<float>(I.ground_extent);
        const float quad[12] = {-e, -e, e, -e, e, e, -e, -e, e, e, -e, e};
        gl.UseProgram(I.ground_program);
        const auto u3 = [&](const char* name, const Vec3f& v) {
            gl.Uniform3f(gl.GetUniformLocation(I.ground_program, name), v.x(), v.y(), v.z());
        };
        const Vec3 o = I.ground_origin;
        u3("origin", f3(o));
        u3("axis_u", f3(I.ground_u));
        u3("axis_v", f3(I.ground_v));
        u3("paper", colour3(pal.background));
        u3("ground", colour3(rgb(238, 238, 233)));
        u3("line_colour", colour3(rgb(168, 170, 174)));
        gl.UniformMatrix4fv(gl.GetUniformLocation(I.ground_program, "view_projection"), 1, GL_FALSE,
                            I.camera.frame_projection().data());
        gl.Uniform1f(gl.GetUniformLocation(I.ground_program, "spacing"), static_cast<float>(I.grid_spacing));
        gl.Uniform1f(gl.GetUniformLocation(I.ground_program, "fade"), e);
        gl.BindVertexArray(I.ground_vao);
        gl.BindBuffer(GL_ARRAY_BUFFER, I.ground_vbo);
        gl.BufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STREAM_DRAW);
        gl.Enable(GL_POLYGON_OFFSET_FILL);
        gl.PolygonOffset(2.0f, 2.0f);
        gl.DrawArrays(GL_TRIANGLES, 0, 6);

        // Shadows: one soft disc under each body, darker and smaller the nearer it is.
        gl.UseProgram(I.shadow_program);
        gl.UniformMatrix4fv(gl.GetUniformLocation(I.shadow_program, "view_projection"), 1, GL_FALSE,
                            I.camera.frame_projection().data());
        gl.Uniform3f(gl.GetUniformLocation(I.shadow_program, "axis_u"), static_cast<float>(I.ground_u.x()),
                     static_cast<float>(I.ground_u.y()), static_cast<float>(I.ground_u.z()));
        gl.Uniform3f(gl.GetUniformLocation(I.shadow_program, "axis_v"), static_cast<float>(I.ground_v.x()),
                     static_cast<float>(I.ground_v.y()), static_cast<float>(I.ground_v.z()));
        gl.Enable(GL_BLEND);
        gl.BlendFuncSeparate(GL_ZERO, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);  // dst *= 1 - a
        gl.DepthMask(GL_FALSE);
        gl.PolygonOffset(1.0f, 1.0f);
        for (std::size_t i = 0; i < n; ++i) {
            if (!I.body_meshes[i].count) continue;
            const Vec3 d = frame.bodies[i].x - o;
            const double height = d.dot(I.ground_normal);
            const double r = 0.5 * I.solids.bodies[i].size;
            if (height < -0.5 * r) continue;
            const double radius = r * (1.0 + 0.25 * std::max(0.0, height) / std::max(r, 1e-9));
            const double strength = 0.30 * std::exp(-std::max(0.0, height - r) / (3 * r));
            const Vec3 foot = frame.bodies[i].x - height * I.ground_normal;
            const float q = static_cast<float>(radius);
            const float sq[12] = {-q, -q, q, -q, q, q, -q, -q, q, q, -q, q};
            gl.Uniform3f(gl.GetUniformLocation(I.shadow_program, "origin"), static_cast<float>(foot.x()),
                         static_cast<float>(foot.y()), static_cast<float>(foot.z()));
            gl.Uniform1f(gl.GetUniformLocation(I.shadow_program, "radius"), q);
            gl.Uniform1f(gl.GetUniformLocation(I.shadow_program, "strength"), static_cast<float>(strength));
            gl.BufferData(GL_ARRAY_BUFFER, sizeof sq, sq, GL_STREAM_DRAW);
            gl.DrawArrays(GL_TRIANGLES, 0, 6);
        }
        gl.DepthMask(GL_TRUE);
        gl.Disable(GL_BLEND);
    }
    gl.Disable(GL_POLYGON_OFFSET_FILL);
    gl.BindVertexArray(0);
    check_gl(gl, "drawing the 3D view's ground");
}

void Scene3dView::draw_above(const FrameState& frame, const Decor& decor) {
    Impl& I = *impl_;
    const Gl& gl = I.gl;
    const Palette& pal = I.style.colours;
    begin_pass(gl, I.camera.frame_width(), I.camera.frame_height());
    const std::size_t n = std::min(frame.bodies.size(), I.scene.bodies.size());
    const float outline = I.style.lw(I.style.outline);

    // Bodies (pushed back a little in depth so that their outlines win).
    gl.Enable(GL_POLYGON_OFFSET_FILL);
    gl.PolygonOffset(1.0f, 1.0f);
    I.use_mesh_program();
    int order = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const bool is_static = I.scene.bodies[i].is_static();
        const int colour_index = order;
        if (!is_static) ++order;
        if (!I.body_meshes[i].count) continue;
        const BodyState& s = frame.bodies[i];
        const Mat3f R = s.q.cast<float>().toRotationMatrix();
        Mat4f model = Mat4f::Identity();
        model.block<3, 3>(0, 0) = R;
        model.block<3, 1>(0, 3) = f3(s.x);
        I.draw_mesh(I.body_meshes[i], model, R,
                    is_static ? pal.static_fill : pal.fills[colour_index % Palette::kFills],
                    I.solids.bodies[i].kind == Solid::Kind::sphere ? 1 : 0);
    }
    gl.Disable(GL_POLYGON_OFFSET_FILL);

    // Arrows: velocities, spins (on the axis), impulses.
    const double thick = 0.03 * I.unit;
    if (decor.velocities) {
        for (std::size_t i = 0; i < n; ++i) {
            if (I.scene.bodies[i].is_static() || !I.body_meshes[i].count) continue;
            const BodyState& s = frame.bodies[i];
            I.arrow(I.velocity_start(i, s), I.k_velocity * s.v, pal.velocity, thick);
            if (I.k_spin > 0 && s.w.norm() > 1e-9 * I.max_spin && s.w.norm() > 1e-12) {
                // From the surface along the axis.
                const Vec3 axis = s.w.normalized();
                const Vec3 start = s.x + axis * (0.5 * I.solids.bodies[i].size * 0.9);
                I.arrow(start, I.k_spin * s.w, pal.spin, thick * 0.8);
            }
        }
    }

    // Outlines: box edges, prism edges, the silhouettes of spheres and cylinders.
    for (std::size_t i = 0; i < n; ++i) {
        if (!I.body_meshes[i].count) continue;
        const BodyState& s = frame.bodies[i];
        for (const auto& [a, b] : I.solids.bodies[i].edges)
            I.line(s.x + s.q * a.cast<double>(), s.x + s.q * b.cast<double>(), pal.ink, outline);
        const Vec3 to_eye = I.camera.eye().cast<double>() - s.x;
        const double d = to_eye.norm();
        const double r = I.solids.bodies[i].radius;
        if (I.solids.bodies[i].kind == Solid::Kind::sphere && d > r) {
            // The silhouette circle of a sphere seen from the eye.
            const Vec3 u = to_eye / d;
            const Vec3 c = s.x + u * (r * r / d);
            const double rs = r * std::sqrt(1.0 - r * r / (d * d));
            Vec3 e1 = u.cross(Vec3::UnitY());
            if (e1.norm() < 1e-6) e1 = u.cross(Vec3::UnitX());
            e1.normalize();
            const Vec3 e2 = u.cross(e1);
            const int segs = 96;
            for (int k = 0; k < segs; ++k) {
                const double a0 = 2 * kPi * k / segs, a1 = 2 * kPi * (k + 1) / segs;
                I.line(c + rs * (std::cos(a0) * e1 + std::sin(a0) * e2),
                       c + rs * (std::cos(a1) * e1 + std::sin(a1) * e2), pal.ink, outline);
            }
            // The equator, so that spin shows in the outline too.
            for (int k = 0; k < segs; ++k) {
                const double a0 = 2 * kPi * k / segs, a1 = 2 * kPi * (k + 1) / segs;
                const Vec3 p0 = s.x + s.q * Vec3(r * std::cos(a0), 0, r * std::sin(a0));
                const Vec3 p1 = s.x + s.q * Vec3(r * std::cos(a1), 0, r * std::sin(a1));
                I.line(p0, p1, with_alpha(pal.ink, 0.45f), outline * 0.6f);
            }
        } else if (I.solids.bodies[i].kind == Solid::Kind::cylinder) {
            // A cylinder (z axis): its two side silhouette lines.
            const Vec3 axis = s.q * Vec3::UnitZ();
            Vec3 side = axis.cross(to_eye);
            if (side.norm() > 1e-9) {
                side.normalize();
                const double h = 0.5 * I.solids.extrude;
                for (double sg : {-1.0, 1.0})
                    I.line(s.x + sg * r * side - h * axis, s.x + sg * r * side + h * axis, pal.ink, outline);
            }
        }
    }
    // Trails.
    if (decor.trails)
        for (std::size_t i = 0; i < n && i < frame.trails.size(); ++i) {
            const auto& trail = frame.trails[i];
            if (I.scene.bodies[i].is_static() || trail.size() < 2) continue;
            int colour_index = 0;
            for (std::size_t j = 0; j < i; ++j) colour_index += I.scene.bodies[j].is_static() ? 0 : 1;
            const double span = std::max(1e-9, trail.back().t - trail.front().t);
            for (std::size_t k = 1; k < trail.size(); ++k) {
                const double age = (frame.t - trail[k].t) / span;
                I.line(trail[k - 1].x, trail[k].x,
                       with_alpha(pal.darks[colour_index % Palette::kFills],
                                  static_cast<float>(0.55 * std::clamp(1.0 - age, 0.0, 1.0))),
                       I.style.lw(2.0f));
            }
        }
    // Spin curls: three quarters of a circle (radius rc, in the plane e1, e2 about `centre`)
    // around the spin arrow near its tip; false for bodies that show none.
    struct Curl {
        Vec3 centre, e1, e2;
        double rc;
    };
    const auto curl_of = [&](std::size_t i, Curl* c) {
        const BodyState& s = frame.bodies[i];
        if (I.scene.bodies[i].is_static() || !(I.k_spin > 0) || s.w.norm() < 1e-9 * I.max_spin ||
            s.w.norm() < 1e-12)
            return false;
        const Vec3 axis = s.w.normalized();
        c->centre = s.x + axis * (0.5 * I.solids.bodies[i].size * 0.9 + 0.6 * I.k_spin * s.w.norm());
        c->e1 = axis.cross(Vec3::UnitY());
        if (c->e1.norm() < 1e-6) c->e1 = axis.cross(Vec3::UnitX());
        c->e1.normalize();
        c->e2 = axis.cross(c->e1);
        c->rc = 0.22 * I.unit;
        return true;
    };
    if (decor.velocities)
        for (std::size_t i = 0; i < n; ++i) {
            Curl curl;
            if (!curl_of(i, &curl)) continue;
            const auto& [centre, e1, e2, rc] = curl;
            const int segs = 40;
            for (int k = 0; k < segs; ++k) {
                const double a0 = 1.5 * kPi * k / segs, a1 = 1.5 * kPi * (k + 1) / segs;
                I.line(centre + rc * (std::cos(a0) * e1 + std::sin(a0) * e2),
                       centre + rc * (std::cos(a1) * e1 + std::sin(a1) * e2), pal.spin,
                       I.style.lw(2.5f));
            }
        }
    I.flush_lines(true, 0.0005f);

    // Spin curl heads, shaded.
    I.use_mesh_program();
    gl.Enable(GL_DEPTH_TEST);
    if (decor.velocities)
        for (std::size_t i = 0; i < n; ++i) {
            Curl curl;
            if (!curl_of(i, &curl)) continue;
            const auto& [centre, e1, e2, rc] = curl;
            const double a = 1.5 * kPi;
            const Vec3 end = centre + rc * (std::cos(a) * e1 + std::sin(a) * e2);
            const Vec3 tangent = (-std::sin(a) * e1 + std::cos(a) * e2);
            I.arrow(end - tangent * (0.12 * I.unit), tangent * (0.16 * I.unit), pal.spin, thick * 0.6);
        }
    // Over everything (they start inside the bodies): at a collision the r vectors, the normal
    // and the impulses.
    if (decor.impacts && !frame.impacts.empty()) {
        for (const ImpactMark& im : frame.impacts) {
            for (std::size_t i : {im.a, im.b})
                if (i < n && I.body_meshes[i].count)
                    I.line(frame.bodies[i].x, im.point, with_alpha(pal.lever, 0.9f), I.style.lw(I.style.thin));
            I.line(im.point, im.point + 0.75 * I.unit * im.normal, pal.normal, I.style.lw(2.0f));
        }
        I.flush_lines(false, 0.0f);
        if (!I.collect) gl.Clear(GL_DEPTH_BUFFER_BIT);
        I.use_mesh_program();
        for (const ImpactMark& im : frame.impacts) {
            I.arrow(im.point, I.k_impulse * im.impulse, pal.impulse, thick * 1.2);
            if (im.a < n && !I.scene.bodies[im.a].is_static())
                I.arrow(im.point, -I.k_impulse * im.impulse, pal.impulse, thick);
            I.arrow(im.point + 0.75 * I.unit * im.normal, 0.2 * I.unit * im.normal, pal.normal, thick * 0.6);
        }
    }
    gl.Disable(GL_DEPTH_TEST);
    gl.BindVertexArray(0);
    check_gl(gl, "drawing the 3D view");
}

void Scene3dView::annotate(ImDrawList* dl, const FontSet& fonts, const FrameState& frame,
                           const Decor& decor, LabelPlacer* labels) const {
    const Impl& I = *impl_;
    const Palette& c = I.style.colours;
    const std::size_t n = std::min(frame.bodies.size(), I.scene.bodies.size());
    // Centre-of-mass markers, seen through the bodies.
    if (decor.com)
        for (std::size_t i = 0; i < n; ++i)
            if (!I.scene.bodies[i].is_static() && I.body_meshes[i].count)
                draw_com_marker(dl, I.camera.project(frame.bodies[i].x), I.style.lw(I.style.com * 0.85f), c.ink,
                                c.background, 0.0f);
    // Axes: where x, y and z point, in the view's lower left corner.
    {
        const ImVec4& vp = I.camera.viewport();
        const ImVec2 o(vp.x + I.style.px(50.0f), vp.w - I.style.px(50.0f));
        const Vec3f right = I.camera.right(), up = I.camera.up();
        const Colour axis_colours[3] = {rgb(200, 50, 50), rgb(40, 150, 60), rgb(40, 90, 200)};
        const char* names[3] = {"x", "y", "z"};
        for (int k = 0; k < 3; ++k) {
            Vec3f e = Vec3f::Zero();
            e[k] = 1.0f;
            const ImVec2 d(e.dot(right), -e.dot(up));
            const float L = I.style.px(34.0f);
            const ImVec2 tip(o.x + d.x * L, o.y + d.y * L);
            draw_arrow(dl, o, tip, axis_colours[k], I.style.px(2.0f), I.style.px(9.0f), I.style.px(7.0f));
            dl->AddText(fonts.small, fonts.small->FontSize,
                        ImVec2(tip.x + d.x * I.style.px(8.0f) - 0.3f * fonts.small->FontSize,
                               tip.y + d.y * I.style.px(8.0f) - 0.5f * fonts.small->FontSize),
                        axis_colours[k], names[k]);
        }
    }
    if (!decor.labels || !labels) return;
    for (std::size_t i = 0; i < n; ++i)
        if (I.body_meshes[i].count) labels->avoid(I.screen_outline(i, frame.bodies[i]));
    struct Pending {
        ImVec2 anchor, direction;
        std::string text;
        Colour colour;
        ImFont* font;
    };
    std::vector<Pending> pending;
    if (decor.impacts)
        for (const ImpactMark& im : frame.impacts) {
            const ImVec2 p = I.camera.project(im.point);
            const ImVec2 tip = I.camera.project(im.point + I.k_impulse * im.impulse);
            pending.push_back({tip, ImVec2(tip.x - p.x, tip.y - p.y),
                               "P = " + format_number(im.impulse.norm()) + " N s", c.impulse, fonts.text});
            const ImVec2 nt = I.camera.project(im.point + 0.95 * I.unit * im.normal);
            pending.push_back({nt, ImVec2(nt.x - p.x, nt.y - p.y), "n", c.normal, fonts.text});
            const std::pair<std::size_t, const char*> ends[2] = {{im.a, "r_{a}"}, {im.b, "r_{b}"}};
            for (const auto& [i, name] : ends) {
                if (i >= n || !I.body_meshes[i].count) continue;
                const ImVec2 from = I.camera.project(frame.bodies[i].x);
                pending.push_back({ImVec2(0.5f * (from.x + p.x), 0.5f * (from.y + p.y)),
                                   ImVec2(-(p.y - from.y), p.x - from.x), name, c.lever, fonts.text});
            }
        }
    if (decor.velocities)
        for (std::size_t i = 0; i < n; ++i) {
            if (I.scene.bodies[i].is_static() || !I.body_meshes[i].count) continue;
            const BodyState& s = frame.bodies[i];
            const ImVec2 from = I.camera.project(s.x);
            if (s.v.norm() * I.k_velocity > 1e-3 * I.unit) {
                const ImVec2 tip = I.camera.project(I.velocity_start(i, s) + I.k_velocity * s.v);
                pending.push_back({tip, ImVec2(tip.x - from.x, tip.y - from.y),
                                   "v = " + format_number(s.v.norm()) + " m s\u207B\u00B9", c.velocity, fonts.text});
            }
            if (I.k_spin > 0 && s.w.norm() > 1e-9 * I.max_spin && s.w.norm() > 1e-12) {
                const Vec3 axis = s.w.normalized();
                const ImVec2 tip = I.camera.project(s.x + axis * (0.5 * I.solids.bodies[i].size * 0.9) + I.k_spin * s.w);
                pending.push_back({tip, ImVec2(tip.x - from.x, tip.y - from.y),
                                   "\u03C9 = " + format_number(s.w.norm()) + " rad s\u207B\u00B9", c.spin, fonts.text});
            }
        }
    for (std::size_t i = 0; i < n; ++i) {
        if (!I.body_meshes[i].count) continue;
        const ImVec2 top = I.camera.project(frame.bodies[i].x + Vec3(0, 0.5 * I.solids.bodies[i].size, 0));
        pending.push_back({top, ImVec2(0, -1), I.scene.bodies[i].name, c.ink, fonts.small});
    }
    const float pad = I.style.px(3.0f);
    for (const Pending& p : pending) {
        place_label(dl, fonts, labels, p.font, p.anchor, p.direction, p.text, p.colour,
                    with_alpha(c.background, 0.85f), pad, I.style.px(6.0f));
    }
}

}  // namespace collide::render
