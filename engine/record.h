// One run of a scene, kept: the states sampled at the instants asked for, every collision
// event (with the bodies' poses at its instant), and every body at the first few collision
// instants. Everything the teaching code shows of a run (answers, the before / at / after
// figure, the worked example, data files, frames) reads it, so a scene is run once.
//
//   scene --record()--> Recording: times[k], states[k]   every body at each sampled instant
//                                  events                every collision, in time order
//                                  instants              every body at the first collisions
#pragma once

#include <cstddef>
#include <functional>
#include <variant>
#include <vector>

#include "engine/scene.h"
#include "engine/world.h"
#include "engine/world1d.h"

namespace collide {

// The world, event and body types of each dimension (1D has its own world).
template <int D>
struct Stepping {
    using World = collide::World<D>;
    using Event = collide::Event<D>;
    using Body = typename Space<D>::Body;
};
template <>
struct Stepping<1> {
    using World = World1;
    using Event = Event1;
    using Body = Body1;
};

template <int D>
struct Recording {
    static constexpr int dimension = D;
    using Body = typename Stepping<D>::Body;
    using Event = typename Stepping<D>::Event;

    // Every body at one collision instant, after all of that instant's impulses; the events
    // [first, end) happened there.
    struct Instant {
        double t = 0.0;  // s
        std::size_t first = 0, end = 0;
        std::vector<Body> bodies;
    };

    std::vector<double> times;              // s: the sampled instants, as asked
    std::vector<std::vector<Body>> states;  // every body at times[k]
    std::vector<std::size_t> events_upto;   // events[0, events_upto[k]) happened by times[k]
    std::vector<Event> events;              // every collision of the run, in time order
    std::vector<Instant> instants;          // the first RecordOptions::instants instants

    // The instant of events[k], when it is among `instants`; else nullptr.
    const Instant* instant_of(std::size_t k) const {
        for (const Instant& i : instants)
            if (k >= i.first && k < i.end) return &i;
        return nullptr;
    }
};

struct RecordOptions {
    std::size_t instants = 16;  // collision instants whose every body is kept
    // Kept too, wherever they fall: the instants of the first `count` collisions of each of
    // these pairs (a collision of a pair: an instant at which they collide, in time order). A
    // lesson's figure of "the first strike of domino 1 on domino 2" may come after many
    // collisions of other bodies.
    struct Keep {
        std::size_t a = 0, b = 0;
        int count = 1;
    };
    std::vector<Keep> keep;
    // Called after each sampled instant with its time (s), once the world has reached it: a
    // caller can show how far the run got, and stop it by throwing (record then throws that).
    // The samples are where the world is asked to stop anyway, so the run is the same with or
    // without it.
    std::function<void(double t)> on_sample;
};

// Runs `scene` once, sampling it at `times` (increasing, from >= 0). Throws what the world
// throws (std::invalid_argument, std::runtime_error).
template <int D>
Recording<D> record(const Scene& scene, const std::vector<double>& times, const RecordOptions& options = {});

// The same for a scene of any dimension.
using AnyRecording = std::variant<Recording<1>, Recording<2>, Recording<3>>;
AnyRecording record_any(const Scene& scene, const std::vector<double>& times, const RecordOptions& options = {});

}  // namespace collide
