#include "engine/record.h"

namespace collide {

template <int D>
Recording<D> record(const Scene& scene, const std::vector<double>& times, const RecordOptions& options) {
    Recording<D> r;
    typename Stepping<D>::World world(scene);
    std::size_t seen = 0;  // events before the latest impact's
    // An impact's events are appended just before the hook: those since the last call.
    const auto on_impact = [&](double t) {
        if (!r.instants.empty() && r.instants.back().t == t) {  // more of the same instant
            r.instants.back().end = r.events.size();
            r.instants.back().bodies = world.bodies_at(t);
        } else if (r.instants.size() < options.instants) {
            r.instants.push_back({t, seen, r.events.size(), world.bodies_at(t)});
        }
        seen = r.events.size();
    };
    r.times = times;
    r.states.reserve(times.size());
    for (double t : times) {
        world.advance_to(t, &r.events, on_impact);
        r.states.push_back(world.bodies());
        r.events_upto.push_back(r.events.size());
        if (options.on_sample) options.on_sample(t);
    }
    return r;
}

template Recording<1> record<1>(const Scene&, const std::vector<double>&, const RecordOptions&);
template Recording<2> record<2>(const Scene&, const std::vector<double>&, const RecordOptions&);
template Recording<3> record<3>(const Scene&, const std::vector<double>&, const RecordOptions&);

AnyRecording record_any(const Scene& scene, const std::vector<double>& times, const RecordOptions& options) {
    if (scene.dimension == 1) return record<1>(scene, times, options);
    if (scene.dimension == 2) return record<2>(scene, times, options);
    return record<3>(scene, times, options);
}

}  // namespace collide
