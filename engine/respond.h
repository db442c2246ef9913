// One collision answered by a model: the one place that maps a Model (response.h) to its
// formula. The world answers each contact point with it (engine/world.cpp, resolve_point) and
// `collide solve` its worked example (teach/solve.cpp), so the two can never disagree.
#pragma once

#include "engine/response.h"
#include "engine/routh.h"

namespace collide {

// The collision of a and b at one contact point (n from A into B, +P on B, -P on A:
// docs/conventions.md) answered by `model`: frictionless (e), coulomb (e, mu), matrix (e),
// stick, routh (e, mu, law; its phases into *detail when given) or page_listing (3D: the
// listing's velocities, listing_response below). mu, law and detail are read only by the
// models that use them.
Response3 respond(Model model, const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e, double mu,
                  RestitutionLaw law, RouthDetail* detail = nullptr);
// 2D: the page's listing is 3D code; page_listing throws std::logic_error here (the world
// refuses it in 2D scenes; `collide solve` reads the listing itself, page::listing).
Response2 respond(Model model, const ImpactBody2& a, const ImpactBody2& b, const Vec2& n, double e, double mu,
                  RestitutionLaw law, RouthDetail* detail = nullptr);

// The page's listing as written (engine/page.h, errata 5-8) as a response: the velocities it
// computes, and as P the impulse b actually receives, mb (vbf - vbi) (erratum 7: not the
// opposite of a's). 3D only: the listing is 3D code.
Response3 listing_response(const ImpactBody3& a, const ImpactBody3& b, const Vec3& n, double e);

}  // namespace collide
