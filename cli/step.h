// `collide step`: runs a scenario and prints its states at each output step, or its collision
// events. Formats: README.md. (1D scenes for now; 2D and 3D join as their worlds land.)
#pragma once

#include <iosfwd>

#include "engine/scene.h"

namespace collide {

struct StepOptions {
    bool json = false;    // one JSON object per line instead of the aligned table
    bool events = false;  // only the collision events
};

// Writes the run of `scene` to out. Throws std::runtime_error for what the world cannot do yet.
void write_steps(const Scene& scene, const StepOptions& options, std::ostream& out);

}  // namespace collide
