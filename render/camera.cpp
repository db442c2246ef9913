#include "render/camera.h"

#include <algorithm>
#include <cmath>

namespace collide::render {

namespace {

// World to eye coordinates (OpenGL's: the eye at the origin looking down -z, y up).
Mat4f look_at(const Vec3f& eye, const Vec3f& target, const Vec3f& up) {
    const Vec3f f = (target - eye).normalized();
    const Vec3f s = f.cross(up).normalized();
    const Vec3f u = s.cross(f);
    Mat4f m = Mat4f::Identity();
    m.block<1, 3>(0, 0) = s.transpose();
    m.block<1, 3>(1, 0) = u.transpose();
    m.block<1, 3>(2, 0) = -f.transpose();
    m(0, 3) = -s.dot(eye);
    m(1, 3) = -u.dot(eye);
    m(2, 3) = f.dot(eye);
    return m;
}

// Eye to clip coordinates: fovy (rad) vertical, aspect = width / height, near and far (m).
Mat4f perspective(float fovy, float aspect, float near, float far) {
    const float t = 1.0f / std::tan(0.5f * fovy);
    Mat4f m = Mat4f::Zero();
    m(0, 0) = t / aspect;
    m(1, 1) = t;
    m(2, 2) = (far + near) / (near - far);
    m(2, 3) = 2.0f * far * near / (near - far);
    m(3, 2) = -1.0f;
    return m;
}

}  // namespace

double default_azimuth(int dimension) { return dimension < 3 ? 20.0 : 32.0; }
double default_elevation(int dimension) { return dimension < 3 ? 16.0 : 24.0; }

void Camera::set_viewport(ImVec4 viewport, int width, int height) {
    viewport_ = viewport;
    frame_w_ = width;
    frame_h_ = height;
}

void Camera::look(const Vec3f& dir, float distance, const Vec3f& look, double radius) {
    const float vw = viewport_.z - viewport_.x, vh = viewport_.w - viewport_.y;
    target_ = look;
    eye_ = look + dir * distance;
    const float near = std::max(0.01f * distance, distance - 4.0f * static_cast<float>(radius));
    const float far = distance + 8.0f * static_cast<float>(radius);
    view_projection_ =
        perspective(static_cast<float>(kFovY), vw / vh, near, far) * look_at(eye_, target_, Vec3f(0, 1, 0));
    // Viewport clip coordinates -> frame clip coordinates (x right, y up).
    const float W = static_cast<float>(frame_w_), H = static_cast<float>(frame_h_);
    Mat4f to_frame = Mat4f::Identity();
    to_frame(0, 0) = vw / W;
    to_frame(0, 3) = (2.0f * viewport_.x + vw) / W - 1.0f;
    to_frame(1, 1) = vh / H;
    to_frame(1, 3) = 1.0f - (2.0f * viewport_.y + vh) / H;
    frame_projection_ = to_frame * view_projection_;
}

void Camera::frame(const Vec3& lo, const Vec3& hi, const Vec3& centre, double radius, const CameraRequest& request,
                   int dimension) {
    // The default: from the front (+z), turned 32 degrees to the right and raised 24; 2D and
    // 1D scenes a little more from the front. Then the distance and the aim are adjusted so
    // that the box's projection fills the viewport.
    const double az = request.azimuth.value_or(default_azimuth(dimension)) * kPi / 180.0;
    const double el = request.elevation.value_or(default_elevation(dimension)) * kPi / 180.0;
    const Vec3f dir(static_cast<float>(std::sin(az) * std::cos(el)), static_cast<float>(std::sin(el)),
                    static_cast<float>(std::cos(az) * std::cos(el)));
    float distance = static_cast<float>(radius / std::sin(0.5 * kFovY));
    Vec3f look_at_point = centre.cast<float>();
    if (request.target) look_at_point = request.target->cast<float>();
    if (request.distance) distance = static_cast<float>(*request.distance);
    const float vw = viewport_.z - viewport_.x, vh = viewport_.w - viewport_.y;
    for (int iteration = 0; iteration < 4 && !(request.target && request.distance); ++iteration) {
        look(dir, distance, look_at_point, radius);
        float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f;
        for (int k = 0; k < 8; ++k) {
            const Vec3 p((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(), (k & 4) ? hi.z() : lo.z());
            const ImVec2 s = project(p);
            x0 = std::min(x0, s.x);
            x1 = std::max(x1, s.x);
            y0 = std::min(y0, s.y);
            y1 = std::max(y1, s.y);
        }
        const float fill = std::max((x1 - x0) / vw, (y1 - y0) / vh) / 0.8f;
        // Re-aim at the projected box's centre (a shift in the view plane).
        const float dx = (0.5f * (x0 + x1) - (viewport_.x + 0.5f * vw)) / vw;
        const float dy = (0.5f * (y0 + y1) - (viewport_.y + 0.5f * vh)) / vh;
        const Vec3f fwd = -dir;
        const Vec3f right = fwd.cross(Vec3f(0, 1, 0)).normalized();
        const Vec3f up = right.cross(fwd);
        const float half_h = distance * std::tan(0.5f * static_cast<float>(kFovY));
        const float half_w = half_h * vw / vh;
        if (!request.target) look_at_point += right * (2.0f * dx * half_w) - up * (2.0f * dy * half_h);
        if (!request.distance) distance *= std::clamp(fill, 0.3f, 3.0f);
    }
    look(dir, distance / static_cast<float>(request.zoom), look_at_point, radius);
}

ImVec2 Camera::project(const Vec3& p) const {
    const Eigen::Vector4f c = view_projection_ * Eigen::Vector4f(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                                                 static_cast<float>(p.z()), 1.0f);
    const float w = std::abs(c.w()) > 1e-9f ? c.w() : 1e-9f;
    const float vw = viewport_.z - viewport_.x, vh = viewport_.w - viewport_.y;
    return ImVec2(viewport_.x + (c.x() / w * 0.5f + 0.5f) * vw, viewport_.y + (0.5f - c.y() / w * 0.5f) * vh);
}

bool Camera::in_front(const Vec3f& p) const {
    const Eigen::Vector4f c = view_projection_ * Eigen::Vector4f(p.x(), p.y(), p.z(), 1.0f);
    return c.w() > 1e-6f;
}

}  // namespace collide::render
