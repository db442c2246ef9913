// The switch over Model (respond.h): each model's formula is in response*.cpp and routh.cpp.
#include "engine/respond.h"

#include <stdexcept>

#include "engine/page.h"

namespace collide {

Response3 listing_response(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e) {
    const page::Listing3 L = page::listing(a, b, n, e);
    Response3 r;
    r.va = L.vaf;
    r.vb = L.vbf;
    r.wa = L.waf;
    r.wb = L.wbf;
    r.P = b.is_static() ? Vec3::Zero() : Vec3((L.vbf - b.v) / b.inv_m);
    return r;
}

namespace {

Response2 listing_response(const ImpactBody2&, const ImpactBody2&, const Vec2&, double) {
    throw std::logic_error("the page's listing runs in 3D worlds only");
}

// The 2D and 3D answers are the same switch over (overloaded) formulas.
template <class IB, class V>
auto respond_with(Model model, const IB& a, const IB& b, const V& n, double e, double mu, RestitutionLaw law,
                  RouthDetail* detail) {
    switch (model) {
        case Model::frictionless: break;
        case Model::coulomb: return coulomb(a, b, n, e, mu);
        case Model::matrix: return matrix(a, b, n, e);
        case Model::stick: return stick(a, b, n);
        case Model::page_listing: return listing_response(a, b, n, e);
        case Model::routh: return routh(a, b, n, e, mu, law, detail);
    }
    return frictionless(a, b, n, e);
}

}  // namespace

Response3 respond(Model model, const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e, double mu,
                  RestitutionLaw law, RouthDetail* detail) {
    return respond_with(model, a, b, n, e, mu, law, detail);
}

Response2 respond(Model model, const ImpactBody2& a, const ImpactBody2& b, const Vec2& n, double e, double mu,
                  RestitutionLaw law, RouthDetail* detail) {
    return respond_with(model, a, b, n, e, mu, law, detail);
}

}  // namespace collide
