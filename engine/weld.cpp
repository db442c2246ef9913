// Stuck bodies (the stick model; "Stuck bodies" in docs/stepping.md): the compound two or more
// welded bodies form, its members placed on it, and the world's welds made, moved and undone.
#include "engine/weld.h"

#include <algorithm>
#include <utility>

#include "engine/toi.h"
#include "engine/world.h"

namespace collide {

namespace {

// Stuck bodies (docs/stepping.md): two bodies as one rigid body, combined_body's parallel-axis sums with
// momentum and angular momentum kept. The compound's frame is the world's at this instant
// (2D angle 0; 3D orientation identity, so its body-frame inertia is the world one).
template <class B>  // Body2 or Body3
B compound(const B& a, const B& b) {
    const auto p = a.position;  // the reference point of the sums (any point will do)
    const auto c = combined_body(at_contact(a, p), at_contact(b, p));
    B r;
    r.mass = c.M;
    r.inertia = c.I;
    r.position = p + c.xc;
    r.v = c.v;
    r.w = c.w;
    return r;
}
// A member's pose in the frame of a compound just formed (compound()).
Pose2 relative_pose(const Body2& c, const Body2& b) { return Pose2{b.position - c.position, b.angle - c.angle}; }
Pose3 relative_pose(const Body3& c, const Body3& b) {
    return Pose3{c.orientation.conjugate() * (b.position - c.position), c.orientation.conjugate() * b.orientation};
}

}  // namespace

// A member placed on its compound c: x = xc + R d, its own frame turned with c's, and the rigid
// motion v = vc + wc x (x - xc), w = wc.
void place_on(const Body2& c, const Pose2& rel, Body2* b) {
    b->angle = c.angle + rel.angle;
    b->position = pose_of(c).apply(rel.x);
    b->w = c.w;
    b->v = c.v + spin_cross(c.w, b->position - c.position);
}
void place_on(const Body3& c, const Pose3& rel, Body3* b) {
    b->orientation = (c.orientation * rel.q).normalized();
    b->position = pose_of(c).apply(rel.x);
    b->w = c.w;
    b->v = c.v + spin_cross(c.w, b->position - c.position);
}

// ---- The world's welds ----

template <int D>
bool World<D>::same_weld(std::size_t i, std::size_t j) const {
    return welds_.of[i] >= 0 && welds_.of[i] == welds_.of[j];
}

template <int D>
void World<D>::weld_to(Weld* w, double t) const {
    if (t == w->t) return;
    if (t < w->t) {  // (not expected: clocks only go forward) again from the anchor
        w->body = w->anchor;
        w->t = w->anchor_t;
    }
    Track free;
    free.a = gravity();
    free.alpha = zero<Spin>();
    move(&w->body, free, t - w->t);
    w->t = t;
}

template <int D>
void World<D>::place(std::size_t i) {
    const Weld& w = welds_.all[welds_.of[i]];
    const auto at = std::find(w.members.begin(), w.members.end(), i) - w.members.begin();
    place_on(w.body, w.rel[at], &bodies_[i]);
}

template <int D>
typename World<D>::Body* World<D>::mobile(std::size_t i) {
    if (welds_.of[i] < 0) return &bodies_[i];
    Weld& w = welds_.all[welds_.of[i]];
    weld_to(&w, track_[i].t);
    return &w.body;
}

template <int D>
void World<D>::moved(std::size_t i) {
    if (welds_.of[i] < 0) return;
    Weld& w = welds_.all[welds_.of[i]];
    w.anchor = w.body;
    w.anchor_t = w.t;
    for (std::size_t m : w.members) {
        place(m);
        track_[m].t = w.t;
    }
}

template <int D>
void World<D>::weld(std::size_t a, std::size_t b, double t) {
    // Everything already stuck to a or b comes along.
    std::vector<std::size_t> members;
    for (std::size_t k : {a, b}) {
        if (welds_.of[k] < 0) {
            members.push_back(k);
            continue;
        }
        Weld& old = welds_.all[welds_.of[k]];
        members.insert(members.end(), old.members.begin(), old.members.end());
        for (std::size_t m : old.members) welds_.of[m] = -1;
        old.members.clear();
    }
    for (std::size_t m : members) drift(m, t);
    Weld w;
    w.body = bodies_[members[0]];
    for (std::size_t q = 1; q < members.size(); ++q) w.body = compound(w.body, bodies_[members[q]]);
    w.t = w.anchor_t = t;
    w.anchor = w.body;
    w.inv_min_moment = inverse_smallest_moment(w.body);
    w.members = members;
    for (std::size_t m : members) {
        w.rel.push_back(relative_pose(w.body, bodies_[m]));
        w.reach.push_back(w.rel.back().x.norm() + shapes_.radius[m]);
        welds_.of[m] = static_cast<int>(welds_.all.size());
    }
    welds_.all.push_back(std::move(w));
    for (std::size_t m : members) {
        place(m);  // the compound's rigid motion (the stick response gave it already, to round-off)
        track_[m].t = t;
    }
    ++counters_.welds;
}

template <int D>
void World<D>::unweld(std::size_t i) {
    if (welds_.of[i] < 0) return;
    Weld& w = welds_.all[welds_.of[i]];
    for (std::size_t m : w.members) welds_.of[m] = -1;
    w.members.clear();
}

// The members defined here, for World<2> and World<3>.
#define COLLIDE_INSTANTIATE_WELD(D)                                                                                    \
    template bool World<D>::same_weld(std::size_t, std::size_t) const;                                                 \
    template void World<D>::weld_to(Weld*, double) const;                                                              \
    template void World<D>::place(std::size_t);                                                                        \
    template World<D>::Body* World<D>::mobile(std::size_t);                                                            \
    template void World<D>::moved(std::size_t);                                                                        \
    template void World<D>::weld(std::size_t, std::size_t, double);                                                    \
    template void World<D>::unweld(std::size_t);
COLLIDE_INSTANTIATE_WELD(2)
COLLIDE_INSTANTIATE_WELD(3)
#undef COLLIDE_INSTANTIATE_WELD

}  // namespace collide
