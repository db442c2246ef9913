// Mass properties of the basic shapes: inertia about the centre of mass, body frame.
//
// Sizes are full edge lengths (not half extents). 3D flat shapes (disc, rectangle) lie in the
// body xy plane, so that spinning about z they match their 2D counterparts; a rod lies along
// the body x axis.
#pragma once

#include "engine/math.h"

namespace collide {

// Solid sphere: I = 2/5 m R^2 about every axis.
Mat3 sphere_inertia(double m, double radius);
// Solid box with edges (a, b, c): Ixx = m (b^2 + c^2) / 12, and cyclically.
Mat3 box_inertia(double m, const Vec3& size);
// Rod (solid cylinder) along x, length L, radius R: Ixx = m R^2 / 2,
// Iyy = Izz = m (3 R^2 + L^2) / 12. R = 0: the thin rod, Ixx = 0 (singular).
Mat3 rod_inertia(double m, double length, double radius = 0.0);
// Thin disc of radius R in the xy plane: Izz = m R^2 / 2, Ixx = Iyy = m R^2 / 4.
Mat3 disc_inertia(double m, double radius);
// Thin rectangular plate w x h in the xy plane: Ixx = m h^2/12, Iyy = m w^2/12,
// Izz = m (w^2 + h^2) / 12.
Mat3 rectangle_inertia(double m, double width, double height);

// 2D moments about the centre of mass (the z axis).
// Disc: m R^2 / 2.
double disc_inertia_2d(double m, double radius);
// Rectangle w x h: m (w^2 + h^2) / 12.
double rectangle_inertia_2d(double m, double width, double height);
// Thin rod of length L: m L^2 / 12.
double rod_inertia_2d(double m, double length);

}  // namespace collide
