// Transcriptions of the page, errors kept. Do not fix anything here: the errata lesson shows
// these numbers beside the correct ones.
#include "engine/page.h"

#include <cmath>

namespace collide::page {

Listing3 listing(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e, ListingReading reading) {
    Listing3 L;
    const Mat3& IaInverse = a.inv_I;
    const Vec3 normal = n.normalized();
    L.angularVelChangea = normal;                             // normal.copy()
    L.angularVelChangea = L.angularVelChangea.cross(a.r);     // .cross(ra): n x ra
    L.angularVelChangea = IaInverse * L.angularVelChangea;    // IaInverse.transform(...)
    const Vec3 vaLinDueToR = L.angularVelChangea.cross(a.r);  // copy().cross(ra)
    L.scalar = a.inv_m + vaLinDueToR.dot(normal);             // 1/ma + ...
    const Mat3& IbInverse = b.inv_I;
    L.angularVelChangeb = normal;
    L.angularVelChangeb = L.angularVelChangeb.cross(b.r);
    L.angularVelChangeb = IbInverse * L.angularVelChangeb;
    const Vec3 vbLinDueToR = L.angularVelChangeb.cross(b.r);
    L.scalar += b.inv_m + vbLinDueToR.dot(normal);
    L.Jmod = (e + 1) * (a.v - b.v).norm() / L.scalar;  // (vai-vbi).magnitude()
    Vec3 J = normal * L.Jmod;                          // normal.mul(Jmod)
    L.J = J;
    if (reading.mul_in_place) {
        J *= a.inv_m;  // J.mul(1/ma) scales J
        L.vaf = a.v - J;
        J *= b.inv_m;  // and again by 1/mb
        L.vbf = b.v - J;
    } else {
        L.vaf = a.v - J * a.inv_m;  // vai - J.mul(1/ma)
        L.vbf = b.v - J * b.inv_m;  // vbi - J.mul(1/mb)
    }
    L.waf = a.w - L.angularVelChangea;  // wai - angularVelChangea
    L.wbf = b.w - L.angularVelChangeb;
    return L;
}

Listing1 listing(const ImpactBody1& a, const ImpactBody1& b, double n, double e, ListingReading reading) {
    // r = 0: the rotational terms vanish, the rest is the listing unchanged.
    Listing1 L;
    const double normal = n > 0 ? 1.0 : -1.0;
    L.scalar = a.inv_m + b.inv_m;
    L.Jmod = (e + 1) * std::abs(a.v - b.v) / L.scalar;
    double J = normal * L.Jmod;
    L.J = J;
    if (reading.mul_in_place) {
        J *= a.inv_m;
        L.vaf = a.v - J;
        J *= b.inv_m;
        L.vbf = b.v - J;
    } else {
        L.vaf = a.v - J * a.inv_m;
        L.vbf = b.v - J * b.inv_m;
    }
    return L;
}

Summary3 summary(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e) {
    Summary3 s;
    const Vec3 ran = a.r.cross(n), rbn = b.r.cross(n);
    s.J = -(1 + e) * ((a.v - b.v).dot(n) + ran.dot(a.w) - rbn.dot(b.w)) /
          (a.inv_m + b.inv_m + ran.dot(a.inv_I * ran) + rbn.dot(b.inv_I * rbn));
    const Vec3 J = s.J * n;
    s.vaf = a.v - J * a.inv_m;
    s.vbf = b.v + J * b.inv_m;
    s.waf = a.w - a.inv_I * J.cross(a.r);
    s.wbf = b.w + b.inv_I * J.cross(b.r);
    return s;
}

Vec3 delta_vp_as_written(const ImpactBody3& body, const Vec3& J) {
    return J * body.inv_m + (body.inv_I * J.cross(body.r)).cross(body.r);
}

Vec3 delta_vp(const ImpactBody3& body, const Vec3& J) {
    return J * body.inv_m + (body.inv_I * body.r.cross(J)).cross(body.r);
}

double restitution_as_written(double vai, double vbi, double vaf, double vbf) { return (vaf - vbf) / (vai - vbi); }

}  // namespace collide::page
