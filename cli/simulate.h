// A scene's run sampled at output instants, shared by `collide render` (frames, data files)
// and `collide gui` (its playback): the world steps to each instant in turn, and every
// collision on the way is handed over before the state at that instant.
#pragma once

#include <cstddef>
#include <vector>

#include "cli/step.h"

namespace collide {

// on_event(event) for each collision, in time order; on_frame(t, bodies) at each of `times`.
template <int D, class OnEvent, class OnFrame>
void simulate_each(const Scene& scene, const std::vector<double>& times, OnEvent&& on_event, OnFrame&& on_frame) {
    typename Stepping<D>::World world(scene);
    std::vector<typename Stepping<D>::Event> events;
    for (double t : times) {
        const std::size_t first = events.size();
        world.advance_to(t, &events);
        for (std::size_t k = first; k < events.size(); ++k) on_event(events[k]);
        on_frame(t, world.bodies());
    }
}

}  // namespace collide
