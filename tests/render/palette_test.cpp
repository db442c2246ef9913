// The figures' colours for readers with red-green colour blindness: every pair of arrow
// colours (velocity, spin, impulse, normal, r vectors) must stay apart, in normal vision and
// as deuteranopes and protanopes see them.
//
// Simulation: Machado, Oliveira and Fernandes (2009), severity 1.0, matrices on linear RGB;
// distance: CIELAB ΔE (CIE 1976, D65 white). ΔE of about 2 is the smallest difference seen
// side by side; 15 keeps two thin arrows apart at a glance.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "render/style.h"

namespace collide::render {
namespace {

using Rgb = std::array<double, 3>;
using Matrix = std::array<std::array<double, 3>, 3>;

Rgb linear(Colour c) {
    Rgb out;
    for (int k = 0; k < 3; ++k) {
        const double v = static_cast<double>((c >> (8 * k)) & 0xFF) / 255.0;
        out[static_cast<std::size_t>(k)] = v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    }
    return out;
}

Rgb simulate(const Matrix& m, const Rgb& c) {
    Rgb out;
    for (std::size_t i = 0; i < 3; ++i) {
        double s = 0;
        for (std::size_t j = 0; j < 3; ++j) s += m[i][j] * c[j];
        out[i] = std::clamp(s, 0.0, 1.0);
    }
    return out;
}

Rgb lab(const Rgb& l) {
    const double X = (0.4124 * l[0] + 0.3576 * l[1] + 0.1805 * l[2]) / 0.95047;
    const double Y = 0.2126 * l[0] + 0.7152 * l[1] + 0.0722 * l[2];
    const double Z = (0.0193 * l[0] + 0.1192 * l[1] + 0.9505 * l[2]) / 1.08883;
    const auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; };
    return {116 * f(Y) - 16, 500 * (f(X) - f(Y)), 200 * (f(Y) - f(Z))};
}

double delta_e(const Rgb& a, const Rgb& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

TEST(Palette, ArrowColoursStayApartForRedGreenColourBlindness) {
    const Matrix identity = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    const Matrix deuteranopia = {
        {{0.367322, 0.860646, -0.227968}, {0.280085, 0.672501, 0.047413}, {-0.011820, 0.042940, 0.968881}}};
    const Matrix protanopia = {
        {{0.152286, 1.052583, -0.204868}, {0.114503, 0.786281, 0.099216}, {-0.003882, -0.048116, 1.051998}}};
    const Palette p;
    const std::vector<std::pair<std::string, Colour>> arrows = {
        {"velocity", p.velocity}, {"spin", p.spin}, {"impulse", p.impulse}, {"normal", p.normal}, {"lever", p.lever}};
    for (const auto& [vision, m] : {std::pair<const char*, Matrix>{"normal vision", identity},
                                    {"deuteranopia", deuteranopia},
                                    {"protanopia", protanopia}})
        for (std::size_t i = 0; i < arrows.size(); ++i)
            for (std::size_t j = i + 1; j < arrows.size(); ++j) {
                const double d =
                    delta_e(lab(simulate(m, linear(arrows[i].second))), lab(simulate(m, linear(arrows[j].second))));
                EXPECT_GE(d, 15.0) << arrows[i].first << " and " << arrows[j].first << " in " << vision;
            }
}

// The simulation itself: pure red and pure green, far apart in normal vision, come close for
// a deuteranope; a grey is unchanged (each matrix's rows sum to 1).
TEST(Palette, TheSimulationMergesRedAndGreenAndKeepsGrey) {
    const Matrix deuteranopia = {
        {{0.367322, 0.860646, -0.227968}, {0.280085, 0.672501, 0.047413}, {-0.011820, 0.042940, 0.968881}}};
    const Rgb red = linear(rgb(200, 60, 40)), green = linear(rgb(90, 140, 40));
    EXPECT_GT(delta_e(lab(red), lab(green)), 60.0);
    EXPECT_LT(delta_e(lab(simulate(deuteranopia, red)), lab(simulate(deuteranopia, green))), 20.0);
    const Rgb grey = linear(rgb(128, 128, 128));
    EXPECT_LT(delta_e(lab(simulate(deuteranopia, grey)), lab(grey)), 0.5);
}

}  // namespace
}  // namespace collide::render
