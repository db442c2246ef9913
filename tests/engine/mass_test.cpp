// Mass properties (engine/mass.h) against textbook values, and the world inertia R I R^T.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

#include "engine/body.h"
#include "engine/mass.h"
#include "tests/engine/random_bodies.h"

namespace {

using namespace collide;
using collide_test::kPi;

constexpr double kAtol = 1e-14;
constexpr double kRtol = 1e-13;

// Inertia tensor of point masses about the origin: I = sum m (|x|^2 E - x x^T).
Mat3 point_masses_inertia(const std::vector<Vec3>& xs, double m_each) {
    Mat3 I = Mat3::Zero();
    for (const Vec3& x : xs) I += m_each * (x.squaredNorm() * Mat3::Identity() - x * x.transpose());
    return I;
}

// Centres of an N-cell grid along an edge of length s: x_k = s ((k + 1/2)/N - 1/2).
std::vector<double> grid(int n, double s) {
    std::vector<double> xs;
    for (int k = 0; k < n; ++k) xs.push_back(s * ((k + 0.5) / n - 0.5));
    return xs;
}

// Solid sphere: I = 2/5 m R^2 about every axis. m = 3 kg, R = 0.5 m: 0.3 kg m^2.
TEST(MassSphere, TwoFifthsMR2) {
    EXPECT_NEAR_ABS_REL(sphere_inertia(3.0, 0.5), Mat3(0.3 * Mat3::Identity()), kAtol, kRtol);
}

// Box with edges (1, 2, 3) m, m = 12 kg: Ixx = m (b^2 + c^2)/12 = 4 + 9 = 13, Iyy = 1 + 9 = 10,
// Izz = 1 + 4 = 5 kg m^2, no products of inertia.
TEST(MassBox, TextbookEdges) {
    EXPECT_NEAR_ABS_REL(box_inertia(12.0, Vec3(1, 2, 3)), Mat3(Vec3(13, 10, 5).asDiagonal()), kAtol, kRtol);
}

// A grid of Nx Ny Nz equal point masses at the cell centres of an a x b x c box. Along an edge of
// length s with N cells, sum_k x_k^2 = s^2 (N^2 - 1) / (12 N), so the grid's tensor is exactly
// the solid box's formula with edges s sqrt(1 - 1/N^2). This checks box_inertia (and the zero
// products of inertia) against an independent sum over point masses.
TEST(MassBox, EqualsPointMassGridSum) {
    const double m = 2.5;
    const Vec3 size(0.7, 1.3, 2.1);
    const int nx = 4, ny = 5, nz = 7;
    std::vector<Vec3> xs;
    for (double x : grid(nx, size.x()))
        for (double y : grid(ny, size.y()))
            for (double z : grid(nz, size.z())) xs.emplace_back(x, y, z);
    const Mat3 grid_I = point_masses_inertia(xs, m / (nx * ny * nz));
    auto shrink = [](double s, int n) { return s * std::sqrt(1.0 - 1.0 / (n * n)); };
    const Vec3 effective(shrink(size.x(), nx), shrink(size.y(), ny), shrink(size.z(), nz));
    EXPECT_NEAR_ABS_REL(box_inertia(m, effective), grid_I, kAtol, 1e-12);
}

// Rod (solid cylinder) along x, m = 6 kg, L = 2 m, R = 0.5 m: Ixx = m R^2/2 = 0.75,
// Iyy = Izz = m (3 R^2 + L^2)/12 = 6 (0.75 + 4)/12 = 2.375 kg m^2.
// Thin rod (R = 0): Ixx = 0, Iyy = Izz = m L^2/12 = 2 kg m^2.
TEST(MassRod, SolidAndThin) {
    EXPECT_NEAR_ABS_REL(rod_inertia(6.0, 2.0, 0.5), Mat3(Vec3(0.75, 2.375, 2.375).asDiagonal()), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(rod_inertia(6.0, 2.0), Mat3(Vec3(0.0, 2.0, 2.0).asDiagonal()), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(rod_inertia_2d(6.0, 2.0), 2.0, kAtol, kRtol);
}

// A row of N point masses along x (cell centres of a rod of length L) has
// sum x_k^2 = L^2 (N^2 - 1)/(12 N): the thin rod's formula with length L sqrt(1 - 1/N^2).
TEST(MassRod, ThinRodEqualsPointMassRow) {
    const double m = 1.7, L = 1.9;
    const int n = 9;
    std::vector<Vec3> xs;
    for (double x : grid(n, L)) xs.emplace_back(x, 0.0, 0.0);
    EXPECT_NEAR_ABS_REL(rod_inertia(m, L * std::sqrt(1.0 - 1.0 / (n * n))), point_masses_inertia(xs, m / n), kAtol,
                        1e-12);
}

// Thin disc, m = 4 kg, R = 0.5 m: Izz = m R^2/2 = 0.5, Ixx = Iyy = m R^2/4 = 0.25 kg m^2
// (perpendicular-axis theorem: Izz = Ixx + Iyy). The 2D disc is its Izz.
TEST(MassDisc, TextbookAndMatches2D) {
    const Mat3 I = disc_inertia(4.0, 0.5);
    EXPECT_NEAR_ABS_REL(I, Mat3(Vec3(0.25, 0.25, 0.5).asDiagonal()), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(disc_inertia_2d(4.0, 0.5), 0.5, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(disc_inertia_2d(4.0, 0.5), I(2, 2), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(I(2, 2), I(0, 0) + I(1, 1), kAtol, kRtol);
}

// Thin plate w x h = 2 x 3 m in the xy plane, m = 12 kg: Ixx = m h^2/12 = 9, Iyy = m w^2/12 = 4,
// Izz = m (w^2 + h^2)/12 = 13 kg m^2. The 2D rectangle is its Izz.
TEST(MassRectangle, TextbookAndMatches2D) {
    const Mat3 I = rectangle_inertia(12.0, 2.0, 3.0);
    EXPECT_NEAR_ABS_REL(I, Mat3(Vec3(9, 4, 13).asDiagonal()), kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(rectangle_inertia_2d(12.0, 2.0, 3.0), 13.0, kAtol, kRtol);
    EXPECT_NEAR_ABS_REL(rectangle_inertia_2d(12.0, 2.0, 3.0), I(2, 2), kAtol, kRtol);
}

// A plate is a box with zero thickness; a point-mass grid in the plane z = 0 gives the plate
// formula with the shrunken edges (as in MassBox.EqualsPointMassGridSum).
TEST(MassRectangle, EqualsPointMassGridSum) {
    const double m = 3.0, w = 1.1, h = 0.6;
    const int nx = 6, ny = 3;
    std::vector<Vec3> xs;
    for (double x : grid(nx, w))
        for (double y : grid(ny, h)) xs.emplace_back(x, y, 0.0);
    EXPECT_NEAR_ABS_REL(
        rectangle_inertia(m, w * std::sqrt(1.0 - 1.0 / (nx * nx)), h * std::sqrt(1.0 - 1.0 / (ny * ny))),
        point_masses_inertia(xs, m / (nx * ny)), kAtol, 1e-12);
}

// World inertia R I R^T: a solid rod along body x (Ixx = 0.75 axial, 2.375 transverse) turned
// 90 degrees about z lies along world y: diag(2.375, 0.75, 2.375).
// Turned 90 degrees about y instead, body x goes to world -z: diag(2.375, 2.375, 0.75).
TEST(MassWorldInertia, RodTurnedAboutZLiesAlongY) {
    Body3 rod;
    rod.mass = 6.0;
    rod.inertia = rod_inertia(6.0, 2.0, 0.5);
    rod.orientation = Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitZ()));
    EXPECT_NEAR_ABS_REL(rod.inertia_world(), Mat3(Vec3(2.375, 0.75, 2.375).asDiagonal()), kAtol, kRtol);
    rod.orientation = Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitY()));
    EXPECT_NEAR_ABS_REL(rod.inertia_world(), Mat3(Vec3(2.375, 2.375, 0.75).asDiagonal()), kAtol, kRtol);
}

// diag(1, 2, 3) turned 45 degrees about z: with c = s = 1/sqrt2,
// Ixx = 1 c^2 + 2 s^2 = 1.5, Iyy = 1 s^2 + 2 c^2 = 1.5, Ixy = (1 - 2) c s = -0.5, Izz = 3.
TEST(MassWorldInertia, FortyFiveDegreesHasProductOfInertia) {
    Body3 b;
    b.inertia = Vec3(1, 2, 3).asDiagonal();
    b.orientation = Quat(Eigen::AngleAxisd(kPi / 4, Vec3::UnitZ()));
    Mat3 expected;
    expected << 1.5, -0.5, 0, -0.5, 1.5, 0, 0, 0, 3;
    EXPECT_NEAR_ABS_REL(b.inertia_world(), expected, kAtol, kRtol);
}

// For any rotation R, each rotated principal axis R e_i is an eigenvector of the world tensor
// with the body moment I_i; the world inverse is the inverse of the world tensor; the rotational
// kinetic energy does not depend on the frame: w.Iworld w = (R^T w).Ibody (R^T w).
TEST(MassWorldInertia, RandomRotationsKeepPrincipalMoments) {
    collide_test::Random rng(101);
    for (int i = 0; i < 200; ++i) {
        Body3 b;
        b.mass = rng.mass();
        const Vec3 moments = rng.principal_moments(b.mass);
        b.inertia = moments.asDiagonal();
        b.orientation = rng.rotation();
        const Mat3 R = b.rotation();
        const Mat3 I = b.inertia_world();
        for (int k = 0; k < 3; ++k) {
            const Vec3 axis = R.col(k);
            EXPECT_NEAR_ABS_REL(Vec3(I * axis), Vec3(moments[k] * axis), kAtol, 1e-12);
        }
        EXPECT_NEAR_ABS_REL(Mat3(b.inv_inertia_world() * I), Mat3(Mat3::Identity()), kAtol, 1e-12);
        const Vec3 w = rng.vec3(-3, 3);
        const Vec3 wb = R.transpose() * w;
        EXPECT_NEAR_ABS_REL(w.dot(I * w), wb.dot(b.inertia * wb), kAtol, 1e-12);
    }
}

// Thin rod, m = 6 kg, L = 2 m: I = diag(0, 2, 2), singular. The pseudo-inverse leaves the zero
// moment at zero: diag(0, 1/2, 1/2). Along a world axis a it is (E - a a^T)/2 (every direction
// across the rod has the moment 2), and it obeys the Moore-Penrose identities I P I = I,
// P I P = P.
TEST(MassPseudoInverse, ThinRod) {
    const Mat3 I = rod_inertia(6.0, 2.0);
    EXPECT_NEAR_ABS_REL(inertia_pseudo_inverse(I), Mat3(Vec3(0.0, 0.5, 0.5).asDiagonal()), kAtol, kRtol);
    Body3 rod;
    rod.mass = 6.0;
    rod.inertia = I;
    const double angle = 30.0 * kPi / 180.0;
    rod.orientation = Quat(Eigen::AngleAxisd(angle, Vec3::UnitZ()));
    const Vec3 a(std::cos(angle), std::sin(angle), 0.0);
    const Mat3 P = rod.inv_inertia_world();
    EXPECT_NEAR_ABS_REL(P, Mat3(0.5 * (Mat3::Identity() - a * a.transpose())), kAtol, 1e-12);
    const Mat3 Iw = rod.inertia_world();
    EXPECT_NEAR_ABS_REL(Mat3(Iw * P * Iw), Iw, kAtol, 1e-12);
    EXPECT_NEAR_ABS_REL(Mat3(P * Iw * P), P, kAtol, 1e-12);
}

// For an invertible tensor the pseudo-inverse is the inverse.
TEST(MassPseudoInverse, EqualsInverseWhenInvertible) {
    collide_test::Random rng(102);
    for (int i = 0; i < 100; ++i) {
        const Mat3 I = rng.inertia_body(rng.mass());
        EXPECT_NEAR_ABS_REL(Mat3(inertia_pseudo_inverse(I) * I), Mat3(Mat3::Identity()), kAtol, 1e-12);
    }
}

// The shared generator makes physical tensors: symmetric, eigenvalues > 0 and every pair of
// principal moments at least the third (I1 + I2 >= I3).
TEST(MassRandomBodies, GeneratorIsPhysical) {
    collide_test::Random rng(103);
    for (int i = 0; i < 1000; ++i) {
        const Mat3 I = rng.inertia_body(rng.mass());
        EXPECT_NEAR_ABS_REL(I, Mat3(I.transpose()), 0.0, 1e-14);
        Eigen::SelfAdjointEigenSolver<Mat3> eig(I);
        const Vec3 l = eig.eigenvalues();
        EXPECT_GT(l.minCoeff(), 0.0);
        EXPECT_GE(l[0] + l[1], l[2] * (1.0 - 1e-12));
    }
}

}  // namespace
