#include "engine/record.h"

namespace collide {

template <int D>
Recording<D> record(const Scene& scene, const std::vector<double>& times, const RecordOptions& options) {
    Recording<D> r;
    typename Stepping<D>::World world(scene);
    std::size_t seen = 0;           // events before the latest impact's
    double instant_t = -1.0;        // s: the latest impact's instant
    std::size_t instant_first = 0;  // its first event
    // Per RecordOptions::keep pair: its collisions so far (instants) and the latest one's time.
    std::vector<int> kept(options.keep.size(), 0);
    std::vector<double> kept_t(options.keep.size(), -1.0);
    // Whether the events [seen, end) include one of the first `count` collisions of a kept pair.
    const auto wanted = [&](double t) {
        bool want = false;
        for (std::size_t p = 0; p < options.keep.size(); ++p) {
            const RecordOptions::Keep& K = options.keep[p];
            for (std::size_t k = seen; k < r.events.size(); ++k) {
                const auto& e = r.events[k];
                if ((e.a != K.a || e.b != K.b) && (e.a != K.b || e.b != K.a)) continue;
                if (kept_t[p] != t) ++kept[p], kept_t[p] = t;
                want = want || kept[p] <= K.count;
                break;
            }
        }
        return want;
    };
    // An impact's events are appended just before the hook: those since the last call.
    const auto on_impact = [&](double t) {
        if (t != instant_t) instant_t = t, instant_first = seen;
        const bool want = wanted(t);
        if (!r.instants.empty() && r.instants.back().t == t) {  // more of the same instant
            r.instants.back().end = r.events.size();
            r.instants.back().bodies = world.bodies_at(t);
        } else if (r.instants.size() < options.instants || want) {
            r.instants.push_back({t, instant_first, r.events.size(), world.bodies_at(t)});
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
