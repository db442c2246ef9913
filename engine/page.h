// The page's formulas exactly as written, errors included (docs/errata.md, errata 1-8).
// Only for the errata lesson and its tests: the correct solvers are in response.h.
#pragma once

#include "engine/body.h"

namespace collide::page {

// How the listing's vector methods are read. `a.cross(b)` replaces a by a x b and returns it
// (otherwise the listing's `angularVelChangea.cross(ra);` would do nothing). `mul` either
// returns a scaled copy (default, the kinder reading) or scales in place, as such vector
// classes often do; then `J.mul(1/ma)` also changes J for the next line.
struct ListingReading {
    bool mul_in_place = false;
};

// What the listing computes, named as in the listing. Its output parameters are passed by
// value, so as literally written the caller receives none of these; we return them.
struct Listing3 {
    Vec3 angularVelChangea = Vec3::Zero(), angularVelChangeb = Vec3::Zero();
    double scalar = 0.0;  // the listing's denominator
    double Jmod = 0.0;
    Vec3 J = Vec3::Zero();
    Vec3 vaf = Vec3::Zero(), vbf = Vec3::Zero(), waf = Vec3::Zero(), wbf = Vec3::Zero();
};

// CollisionResponce(e, ma, mb, Ia, Ib, ra, rb, n, vai, vbi, wai, wbi, ...) as written.
// Ia.inverse() is taken as the body's world inverse inertia (zero for a static body, whose 1/m
// is zero too).
Listing3 listing(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e, ListingReading reading = {});

// The listing on a line (r = 0, n = +1 or -1).
struct Listing1 {
    double scalar = 0.0, Jmod = 0.0, J = 0.0, vaf = 0.0, vbf = 0.0;
};
Listing1 listing(const ImpactBody1& a, const ImpactBody1& b, double n, double e, ListingReading reading = {});

// The page's summary table as written:
//   J = -(1+e) ((va - vb).n + (ra x n).wa - (rb x n).wb)
//       / (1/ma + 1/mb + (ra x n).(Ia^-1 (ra x n)) + (rb x n).(Ib^-1 (rb x n)))
//   vaf = vai - J n/Ma, vbf = vbi + J n/Mb, waf = wai - Ia^-1 (J x ra), wbf = wbi + Ib^-1 (J x rb)
// (J taken along n). Errata 1 (sign of J) and 2 (J x r instead of r x J).
struct Summary3 {
    double J = 0.0;
    Vec3 vaf = Vec3::Zero(), vbf = Vec3::Zero(), waf = Vec3::Zero(), wbf = Vec3::Zero();
};
Summary3 summary(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e);

// The derivation's change of a point's velocity, as written: dVp = J/M + ([I]^-1 (J x r)) x r
// (erratum 4), and as it should read: J/M + ([I]^-1 (r x J)) x r.
Vec3 delta_vp_as_written(const ImpactBody3& body, const Vec3& J);
Vec3 delta_vp(const ImpactBody3& body, const Vec3& J);

// The derivation's definition as written: e = (vaf - vbf) / (vai - vbi), on the normal
// components of the contact-point velocities (erratum 3: a minus sign is missing).
double restitution_as_written(double vai, double vbi, double vaf, double vbf);

}  // namespace collide::page
