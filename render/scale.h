// Round values for what a reader measures against: legend arrows and ground grids.
#pragma once

#include <cmath>

namespace collide::render {

// A round value 1, 2 or 5 x 10^k near x (x > 0; 0 for anything else). The mantissa m = x / 10^k
// in [1, 10) goes to 1 below 1.5, 2 below 3.5, 5 below 7.5, else to 10 (the next decade).
inline double round_value(double x) {
    if (!(x > 0)) return 0.0;
    const double p = std::pow(10.0, std::floor(std::log10(x)));
    const double m = x / p;
    return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * p;
}

}  // namespace collide::render
