// Stuck bodies (the stick model; "Stuck bodies" in engine/world.h): bodies welded together
// move as one rigid body, the compound, and each member is placed on it from its pose in the
// compound's frame. The world's welds are made and moved in engine/weld.cpp.
#pragma once

#include <cstddef>
#include <vector>

#include "engine/space.h"

namespace collide {

// Bodies stuck together, moving as one rigid body.
template <int D>
struct Weld {
    using Body = typename Space<D>::Body;
    std::vector<std::size_t> members;
    std::vector<typename Space<D>::Pose> rel;  // each member's pose in the compound's frame
    std::vector<double> reach;                 // each member's |d| + its bounding radius (m)
    Body body;                                 // the compound at time t (its frame: the world's at welding)
    double t = 0.0;
    Body anchor;  // the compound when its velocity last changed, at anchor_t
    double anchor_t = 0.0;
    double inv_min_moment = 0.0;
};

// A member placed on its compound c from its pose rel in c's frame: x = xc + R d, its own frame
// turned with c's, and the rigid motion v = vc + wc x (x - xc), w = wc.
void place_on(const Body2& c, const Pose2& rel, Body2* b);
void place_on(const Body3& c, const Pose3& rel, Body3* b);

}  // namespace collide
