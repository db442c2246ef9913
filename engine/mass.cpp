#include "engine/mass.h"

namespace collide {

Mat3 sphere_inertia(double m, double radius) { return Mat3::Identity() * (0.4 * m * radius * radius); }

Mat3 box_inertia(double m, const Vec3& size) {
    const Vec3 s2 = size.cwiseProduct(size);
    return Vec3(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y()).asDiagonal() * (m / 12.0);
}

Mat3 rod_inertia(double m, double length, double radius) {
    const double axial = 0.5 * m * radius * radius;
    const double transverse = m * (3.0 * radius * radius + length * length) / 12.0;
    return Vec3(axial, transverse, transverse).asDiagonal();
}

Mat3 disc_inertia(double m, double radius) {
    const double q = 0.25 * m * radius * radius;
    return Vec3(q, q, 2.0 * q).asDiagonal();
}

Mat3 rectangle_inertia(double m, double width, double height) {
    return Vec3(height * height, width * width, width * width + height * height).asDiagonal() * (m / 12.0);
}

double disc_inertia_2d(double m, double radius) { return 0.5 * m * radius * radius; }

double rectangle_inertia_2d(double m, double width, double height) {
    return m * (width * width + height * height) / 12.0;
}

double rod_inertia_2d(double m, double length) { return m * length * length / 12.0; }

}  // namespace collide
