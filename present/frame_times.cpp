#include "present/frame_times.h"

namespace collide {

std::vector<double> frame_times(const Scene& scene, double fps) {
    Scene timing = scene;
    timing.output_dt = 1.0 / fps;
    return output_times(timing);
}

}  // namespace collide
