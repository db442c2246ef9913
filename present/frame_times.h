// A scene sampled at a frame rate: the one rule that `collide render`, `collide gui`, the site
// and the WebAssembly module's Try-it panel share, so that a frame of one is a frame of each.
#pragma once

#include <vector>

#include "teach/step_output.h"  // output_times

namespace collide {

// The instants of a run at `fps` frames per simulated second: output_times of the scene with
// output_dt = 1 / fps (from 0 to the duration, the last one at the duration).
std::vector<double> frame_times(const Scene& scene, double fps);

}  // namespace collide
