// The 3D view's camera (render/camera.h), without GL: framing a box in the viewport, and what
// a scenario's [view] fixes staying fixed.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "render/camera.h"

namespace collide::render {
namespace {

// The screen box of the corners of lo..hi: x0, y0, x1, y1.
ImVec4 projected_box(const Camera& camera, const Vec3& lo, const Vec3& hi) {
    ImVec4 r(1e9f, 1e9f, -1e9f, -1e9f);
    for (int k = 0; k < 8; ++k) {
        const ImVec2 s =
            camera.project(Vec3((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(), (k & 4) ? hi.z() : lo.z()));
        r = ImVec4(std::min(r.x, s.x), std::min(r.y, s.y), std::max(r.z, s.x), std::max(r.w, s.y));
    }
    return r;
}

TEST(CameraTest, FramesTheBoxInTheViewport) {
    const Vec3 lo(-1.0, 0.0, -0.5), hi(3.0, 1.5, 0.5);
    const ImVec4 viewport(100, 50, 740, 410);  // 640 x 360, off the frame's corner
    for (int dimension : {2, 3}) {
        Camera camera;
        camera.set_viewport(viewport, 960, 540);
        camera.frame(lo, hi, 0.5 * (lo + hi), 0.5 * (hi - lo).norm(), CameraRequest{}, dimension);
        const ImVec4 r = projected_box(camera, lo, hi);
        // Inside the viewport, centred on it, filling 80% of it along the tighter side.
        EXPECT_GE(r.x, viewport.x);
        EXPECT_GE(r.y, viewport.y);
        EXPECT_LE(r.z, viewport.z);
        EXPECT_LE(r.w, viewport.w);
        const float fill = std::max((r.z - r.x) / 640.0f, (r.w - r.y) / 360.0f);
        EXPECT_NEAR(fill, 0.8f, 0.02f) << dimension << "D";
        EXPECT_NEAR(0.5f * (r.x + r.z), 420.0f, 3.0f);
        EXPECT_NEAR(0.5f * (r.y + r.w), 230.0f, 3.0f);
        // Seen from above and from the right of the front, at the default angles.
        const Vec3f to_eye = (camera.eye() - camera.target()).normalized();
        EXPECT_NEAR(std::asin(to_eye.y()) * 180.0 / kPi, default_elevation(dimension), 1e-3);
        EXPECT_NEAR(std::atan2(to_eye.x(), to_eye.z()) * 180.0 / kPi, default_azimuth(dimension), 1e-3);
    }
}

TEST(CameraTest, WhatTheRequestSetsStaysSet) {
    CameraRequest request;
    request.azimuth = -45.0;
    request.elevation = 10.0;
    request.target = Vec3(1.0, 2.0, 3.0);
    request.distance = 12.0;
    request.zoom = 2.0;
    Camera camera;
    camera.set_viewport(ImVec4(0, 0, 800, 600), 800, 600);
    camera.frame(Vec3(-1, -1, -1), Vec3(1, 1, 1), Vec3::Zero(), std::sqrt(3.0), request, 3);
    EXPECT_LT((camera.target() - Vec3f(1, 2, 3)).norm(), 1e-6f);
    EXPECT_NEAR((camera.eye() - camera.target()).norm(), 12.0f / 2.0f, 1e-5f);
    // The target projects to the viewport's centre; the view's axes are orthonormal.
    const ImVec2 c = camera.project(Vec3(1, 2, 3));
    EXPECT_NEAR(c.x, 400.0f, 1e-3f);
    EXPECT_NEAR(c.y, 300.0f, 1e-3f);
    EXPECT_NEAR(camera.right().dot(camera.up()), 0.0f, 1e-6f);
    EXPECT_NEAR(camera.right().dot(camera.forward()), 0.0f, 1e-6f);
    EXPECT_NEAR(camera.up().y(), std::cos(10.0 * kPi / 180.0), 1e-5);
}

TEST(CameraTest, PointsBehindTheEyeDoNotProject) {
    Camera camera;
    camera.set_viewport(ImVec4(0, 0, 640, 480), 640, 480);
    camera.frame(Vec3(-1, -1, -1), Vec3(1, 1, 1), Vec3::Zero(), std::sqrt(3.0), CameraRequest{}, 3);
    EXPECT_TRUE(camera.in_front(camera.target()));
    const Vec3f behind = camera.eye() - camera.forward();
    EXPECT_FALSE(camera.in_front(behind));
}

}  // namespace
}  // namespace collide::render
