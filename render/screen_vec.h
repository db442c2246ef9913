// Small geometry of the 2D diagram's drawing and labelling (diagram_draw.cpp,
// diagram_annotate.cpp): the front view of a world vector, and screen vectors in pixels.
#pragma once

#include <cmath>

#include <imgui.h>

#include "engine/body.h"

namespace collide::render {
namespace screen {

// The front view of a world point or vector (m): its x and y.
inline Vec2 xy(const Vec3& v) { return Vec2(v.x(), v.y()); }

// Screen vector arithmetic (pixels).
inline float dot(ImVec2 a, ImVec2 b) { return a.x * b.x + a.y * b.y; }
inline ImVec2 operator+(ImVec2 a, ImVec2 b) { return ImVec2(a.x + b.x, a.y + b.y); }
inline ImVec2 operator-(ImVec2 a, ImVec2 b) { return ImVec2(a.x - b.x, a.y - b.y); }
inline ImVec2 operator*(ImVec2 a, float s) { return ImVec2(a.x * s, a.y * s); }
inline float norm(ImVec2 a) { return std::sqrt(dot(a, a)); }
inline ImVec2 unit(ImVec2 a) {
    const float n = norm(a);
    return n > 1e-6f ? a * (1.0f / n) : ImVec2(0.0f, -1.0f);
}

}  // namespace screen
}  // namespace collide::render
