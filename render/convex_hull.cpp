#include "render/convex_hull.h"

#include <algorithm>

namespace collide::render {

std::vector<Vec2> convex_hull(std::vector<Vec2> p) {
    std::sort(p.begin(), p.end(),
              [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
    if (p.size() < 3) return p;
    std::vector<Vec2> h(2 * p.size());
    std::size_t k = 0;
    // > 0 when o -> a -> b turns counter-clockwise.
    const auto turn = [](const Vec2& o, const Vec2& a, const Vec2& b) {
        return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
    };
    // The lower hull left to right, then the upper hull right to left.
    for (std::size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && turn(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
        h[k++] = p[i - 1];
    }
    h.resize(k - 1);  // the last point is the first again
    return h;
}

}  // namespace collide::render
