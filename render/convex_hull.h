// The convex hull of points in a plane: body outlines in the diagram (world, m) and the
// projected outlines of 3D bodies that labels keep off (screen, pixels).
#pragma once

#include <vector>

#include "engine/math.h"

namespace collide::render {

// Andrew's monotone chain: the hull's corners, counter-clockwise when y points up (clockwise
// on a screen whose y points down), starting from the lowest x (then lowest y); points on an
// edge are left out. Fewer than 3 points come back sorted, as they are.
std::vector<Vec2> convex_hull(std::vector<Vec2> points);

}  // namespace collide::render
