#include "engine/body.h"

#include <Eigen/Eigenvalues>

namespace collide {

Mat3 inertia_pseudo_inverse(const Mat3& inertia) {
    if (inertia.isDiagonal(0.0)) {  // principal axes (boxes, spheres, rods): no eigen-solve
        const double tiny = 1e-14 * inertia.diagonal().cwiseAbs().maxCoeff();
        Mat3 inv = Mat3::Zero();
        for (int i = 0; i < 3; ++i)
            if (inertia(i, i) > tiny) inv(i, i) = 1.0 / inertia(i, i);
        return inv;
    }
    Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia);
    const Vec3& lambda = eig.eigenvalues();
    const double tiny = 1e-14 * lambda.cwiseAbs().maxCoeff();
    Vec3 inv = Vec3::Zero();
    for (int i = 0; i < 3; ++i)
        if (lambda[i] > tiny) inv[i] = 1.0 / lambda[i];
    return eig.eigenvectors() * inv.asDiagonal() * eig.eigenvectors().transpose();
}

Mat3 Body3::inertia_world() const {
    if (is_static) return Mat3::Zero();
    const Mat3 R = rotation();
    return R * inertia * R.transpose();
}

Mat3 Body3::inv_inertia_world() const {
    if (is_static) return Mat3::Zero();
    const Mat3 R = rotation();
    return R * inertia_pseudo_inverse(inertia) * R.transpose();
}

ImpactBody3 at_contact(const Body3& body, const Vec3& p) {
    ImpactBody3 b;
    b.inv_m = body.inv_mass();
    b.inv_I = body.inv_inertia_world();
    b.I = body.inertia_world();
    b.r = p - body.position;
    b.v = body.v;
    b.w = body.w;
    return b;
}

ImpactBody2 at_contact(const Body2& body, const Vec2& p) {
    ImpactBody2 b;
    b.inv_m = body.inv_mass();
    b.inv_I = body.inv_inertia();
    b.I = body.is_static ? 0.0 : body.inertia;
    b.r = p - body.position;
    b.v = body.v;
    b.w = body.w;
    return b;
}

ImpactBody1 at_contact(const Body1& body) {
    ImpactBody1 b;
    b.inv_m = body.inv_mass();
    b.v = body.v;
    return b;
}

}  // namespace collide
