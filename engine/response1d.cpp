// 1D collision response: bodies on a line, r = 0, n = +1 or -1 (from A towards B).
#include "engine/response.h"

namespace collide {

Response1 frictionless(const ImpactBody1& a, const ImpactBody1& b, double n, double e) {
    Response1 r;
    const double un = (b.v - a.v) * n;
    if (un >= 0.0) {
        r.separating = true;
    } else {
        r.P = (-(1.0 + e) * un / (a.inv_m + b.inv_m)) * n;
    }
    r.va = a.v - a.inv_m * r.P;
    r.vb = b.v + b.inv_m * r.P;
    return r;
}

Response1 stick(const ImpactBody1& a, const ImpactBody1& b, double n) {
    // Perfectly inelastic on a line is e = 0: both end with the common (centre of mass)
    // velocity (ma va + mb vb) / (ma + mb), or the static body's velocity.
    return frictionless(a, b, n, 0.0);
}

}  // namespace collide
