// The figures' colours for readers with colour blindness: every pair of arrow
// colours (velocity, spin, impulse, normal, r vectors), and each arrow over the first two bodies,
// must stay apart, in normal vision and as deuteranopes, protanopes and tritanopes see them.
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

// Normal vision and the three dichromacies (Machado et al. 2009, severity 1.0).
std::vector<std::pair<std::string, Matrix>> visions() {
    const Matrix identity = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    const Matrix deuteranopia = {
        {{0.367322, 0.860646, -0.227968}, {0.280085, 0.672501, 0.047413}, {-0.011820, 0.042940, 0.968881}}};
    const Matrix protanopia = {
        {{0.152286, 1.052583, -0.204868}, {0.114503, 0.786281, 0.099216}, {-0.003882, -0.048116, 1.051998}}};
    const Matrix tritanopia = {
        {{1.255528, -0.076749, -0.178779}, {-0.078411, 0.930809, 0.147602}, {0.004733, 0.691367, 0.303900}}};
    return {{"normal vision", identity},
            {"deuteranopia", deuteranopia},
            {"protanopia", protanopia},
            {"tritanopia", tritanopia}};
}

TEST(Palette, ArrowColoursStayApartForColourBlindness) {
    const Palette p;
    const std::vector<std::pair<std::string, Colour>> arrows = {
        {"velocity", p.velocity}, {"spin", p.spin}, {"impulse", p.impulse}, {"normal", p.normal}, {"lever", p.lever}};
    for (const auto& [vision, m] : visions())
        for (std::size_t i = 0; i < arrows.size(); ++i)
            for (std::size_t j = i + 1; j < arrows.size(); ++j) {
                const double d =
                    delta_e(lab(simulate(m, linear(arrows[i].second))), lab(simulate(m, linear(arrows[j].second))));
                EXPECT_GE(d, 15.0) << arrows[i].first << " and " << arrows[j].first << " in " << vision;
            }
}

// A colour darkened as the 3D view's shading does at its darkest lit faces (80 %).
Colour shaded(Colour c) {
    const auto ch = [c](int k) { return static_cast<int>(((c >> (8 * k)) & 0xFF) * 0.8); };
    return rgb(ch(0), ch(1), ch(2));
}

// The arrows are drawn over the bodies: over the pair of most figures (the first two fills,
// flat in 2D, shaded in 3D) each arrow colour stays 15 apart from the body, in every vision.
TEST(Palette, ArrowsStayApartFromTheBodiesTheyCross) {
    const Palette p;
    const std::vector<std::pair<std::string, Colour>> arrows = {
        {"velocity", p.velocity}, {"spin", p.spin}, {"impulse", p.impulse}, {"normal", p.normal}};
    const std::vector<std::pair<std::string, Colour>> bodies = {{"body A", p.fills[0]},
                                                                {"body B", p.fills[1]},
                                                                {"body A shaded", shaded(p.fills[0])},
                                                                {"body B shaded", shaded(p.fills[1])}};
    for (const auto& [vision, m] : visions())
        for (const auto& [arrow, a] : arrows)
            for (const auto& [body, b] : bodies) {
                const double d = delta_e(lab(simulate(m, linear(a))), lab(simulate(m, linear(b))));
                EXPECT_GE(d, 15.0) << arrow << " over " << body << " in " << vision;
            }
    // And the two bodies from each other.
    for (const auto& [vision, m] : visions())
        EXPECT_GE(delta_e(lab(simulate(m, linear(p.fills[0]))), lab(simulate(m, linear(p.fills[1])))), 15.0)
            << "bodies A and B in " << vision;
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
