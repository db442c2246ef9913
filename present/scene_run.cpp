#include "present/scene_run.h"

#include <algorithm>
#include <cstdio>
#include <type_traits>
#include <utility>
#include <variant>

#include "teach/step_output.h"
#include "teach/notation.h"

namespace collide {

using render::FrameState;
using render::ImpactMark;

namespace {

template <class F>
decltype(auto) visit_record(const SceneRun& run, F&& f) {
    return std::visit(std::forward<F>(f), run.record);
}

std::string num(double x) { return notation::num_data(x); }

// A CSV field as RFC 4180 writes it: quoted, with its quotes doubled, when it holds a comma or
// a quote (a body may be named "cart, left"); as it is otherwise.
std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

// data.csv: t, then per moving body its position, velocity, orientation and spin, then the
// kinetic energy and momentum of the moving bodies.
std::string csv_header(const Scene& s) {
    const int d = s.dimension;
    const char* axes[3] = {"x", "y", "z"};
    std::string h = "t";
    for (const SceneBody& b : s.bodies) {
        if (b.is_static()) continue;
        const auto col = [&](const std::string& what) { h += "," + csv_field(b.name + "." + what); };
        for (int k = 0; k < d; ++k) col(std::string("x") + (d > 1 ? std::string(".") + axes[k] : ""));
        for (int k = 0; k < d; ++k) col(std::string("v") + (d > 1 ? std::string(".") + axes[k] : ""));
        if (d == 2) {
            col("angle");
            col("w");
        }
        if (d == 3) {
            for (const char* q : {"q.w", "q.x", "q.y", "q.z"}) col(q);
            for (int k = 0; k < 3; ++k) col(std::string("w.") + axes[k]);
        }
    }
    h += ",kinetic_energy";
    for (int k = 0; k < d; ++k) h += std::string(",momentum") + (d > 1 ? std::string(".") + axes[k] : "");
    return h + "\n";
}

std::string csv_row(const Scene& s, const FrameState& f) {
    const int d = s.dimension;
    std::string r = num(f.t);
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        const SceneBody& b = s.bodies[i];
        if (b.is_static()) continue;
        const render::BodyState& x = f.bodies[i];
        const Vec3 pos = d == 1 ? Vec3(x.x.x(), 0, 0) : x.x;  // 1D: the drawn height is not data
        for (int k = 0; k < d; ++k) r += "," + num(pos[k]);
        for (int k = 0; k < d; ++k) r += "," + num(x.v[k]);
        if (d == 2) r += "," + num(x.angle) + "," + num(x.w.z());
        if (d == 3) {
            r += "," + num(x.q.w()) + "," + num(x.q.x()) + "," + num(x.q.y()) + "," + num(x.q.z());
            for (int k = 0; k < 3; ++k) r += "," + num(x.w[k]);
        }
    }
    const render::FrameTotals sums = render::frame_totals(s, f);
    r += "," + num(sums.kinetic);
    for (int k = 0; k < d; ++k) r += "," + num(sums.momentum[k]);
    return r + "\n";
}

std::string events_csv_header(int d) {
    if (d == 1) return "t,a,b,point,impulse,a.v.before,b.v.before,a.v.after,b.v.after\n";
    std::string h = "t,a,b";
    const char* axes[3] = {"x", "y", "z"};
    for (const char* what : {"point", "normal", "impulse"})
        for (int k = 0; k < d; ++k) h += std::string(",") + what + "." + axes[k];
    return h + "\n";
}

std::string events_csv_row(const Scene& s, const Event1& e) {
    return num(e.t) + "," + csv_field(s.bodies[e.a].name) + "," + csv_field(s.bodies[e.b].name) + "," + num(e.point) +
           "," + num(e.impulse) + "," + num(e.va_before) + "," + num(e.vb_before) + "," + num(e.va_after) + "," +
           num(e.vb_after) + "\n";
}
template <int D>
std::string events_csv_row(const Scene& s, const Event<D>& e) {
    std::string r = num(e.t) + "," + csv_field(s.bodies[e.a].name) + "," + csv_field(s.bodies[e.b].name);
    for (const auto* v : {&e.point, &e.normal, &e.impulse})
        for (int k = 0; k < D; ++k) r += "," + num((*v)[k]);
    return r + "\n";
}

double size_of(const Scene& scene, std::size_t i) {
    const SceneBody& b = scene.bodies[i];
    if (scene.dimension == 1) return b.length;
    if (scene.dimension == 2) return b.shape2.kind == Shape2::Kind::half_plane ? 0.0 : 2.0 * bounding_radius(b.shape2);
    return b.shape3.kind == Shape3::Kind::half_space ? 0.0 : 2.0 * bounding_radius(b.shape3);
}

// The two bodies of an event as they were just before its impulses (When::before) or are
// just after them (When::after); 1D: no spin.
enum class When { before, after };
void impulse_velocities(const Event1& e, When when, std::vector<BodyState>* bodies) {
    const bool after = when == When::after;
    (*bodies)[e.a].v = lift_line(after ? e.va_after : e.va_before);
    (*bodies)[e.b].v = lift_line(after ? e.vb_after : e.vb_before);
}
template <int D>
void impulse_velocities(const Event<D>& e, When when, std::vector<BodyState>* bodies) {
    const bool after = when == When::after;
    for (const auto& [body, u] :
         {std::pair(e.a, after ? e.after_a : e.before_a), std::pair(e.b, after ? e.after_b : e.before_b)}) {
        (*bodies)[body].v = lift(u.v);
        (*bodies)[body].w = lift_spin(u.w);
    }
}

// Every body's velocities just before the impacts of instants[which] (`pre`) and just after
// (`post`): a body in one of its events had the event's "before" velocities (the first event
// it is in, when it is in several); the others kept theirs through the instant.
template <class Recording>
void instant_velocities(const Scene& scene, const Recording& rec, std::size_t which, std::vector<BodyState>* pre,
                        std::vector<BodyState>* post) {
    const auto& instant = rec.instants[which];
    *post = render::frame_state(scene, instant.t, instant.bodies).bodies;
    *pre = *post;
    for (std::size_t k = instant.end; k-- > instant.first;) impulse_velocities(rec.events[k], When::before, pre);
}

// `frame` drawn with the velocities of `at` (the poses stay the frame's).
void with_velocities(const std::vector<BodyState>& at, FrameState* frame) {
    for (std::size_t i = 0; i < frame->bodies.size() && i < at.size(); ++i) {
        frame->bodies[i].v = at[i].v;
        frame->bodies[i].w = at[i].w;
    }
}

template <int D>
std::optional<Moments> moments_of(const Scene& scene, const SceneRun& run, const Recording<D>& rec,
                                  const CollisionPick& pick) {
    const std::optional<PairCollision> found = find_pick(rec, pick);
    if (!found) return std::nullopt;
    const std::size_t which = found->instant;
    std::size_t first_event = found->first, end_event = found->end;
    const typename Recording<D>::Instant& instant = rec.instants[which];
    const std::size_t event = first_event;  // the collision's first event (worked out)
    const auto& first = rec.events[event];
    const double te = instant.t;
    // A moment long enough for the bodies to move visibly: half the smaller body's size at
    // their approach speed (from the last sample before the collision).
    double speed = 0;
    for (const FrameState& f : run.frames)
        if (f.t <= te) speed = (f.bodies[first.b].v - f.bodies[first.a].v).norm();
    double size = 0;
    for (std::size_t i : {first.a, first.b}) {
        const double s = size_of(scene, i);
        if (s > 0) size = size == 0 ? s : std::min(size, s);
    }
    double dt = speed > 0 && size > 0 ? 0.5 * size / speed : 0.1 * scene.duration;
    dt = std::min(dt, 0.25 * scene.duration);
    // The next collision of either body, after this instant.
    double next = scene.duration;
    for (std::size_t k = instant.end; k < rec.events.size(); ++k) {
        const auto& e = rec.events[k];
        if (e.a == first.a || e.b == first.b || e.a == first.b || e.b == first.a) {
            next = e.t;
            break;
        }
    }
    const std::vector<double>& t = rec.times;
    Moments m;
    m.at = te;
    std::size_t kb = 0;  // the last sample at or before te - dt
    while (kb + 1 < t.size() && t[kb + 1] <= te - dt) ++kb;
    m.before = t[kb];
    m.states[0] = run.frames[kb];
    m.states[1] = render::frame_state(scene, te, instant.bodies);
    // The instant's impacts of this pair only (a cradle's next contact is its own figure),
    // or all of them for the whole instant.
    if (pick.whole_instant) {
        first_event = instant.first;
        end_event = instant.end;
    }
    for (std::size_t k = first_event; k < end_event; ++k) {
        const auto& e = rec.events[k];
        if (pick.whole_instant || (e.a == pick.a && e.b == pick.b) || (e.a == pick.b && e.b == pick.a))
            m.states[1].impacts.push_back(with_roles(run.impacts[k], pick.a, pick.b));
    }
    const double target = std::min({scene.duration, te + dt, te + 0.5 * (next - te)});
    std::size_t ka = 0;  // the first sample at or after the target, before the next collision
    while (ka < t.size() && t[ka] < target) ++ka;
    if (ka == t.size() || (t[ka] >= next && next < scene.duration)) {
        ka = t.size();
        for (std::size_t k = 0; k < t.size() && t[k] < next; ++k)
            if (t[k] > te) ka = k;
    }
    // A contact resolved in the same instant as others (a cradle's, one after another): the
    // bodies do not move between them, so before and after are drawn where they touch.
    const bool shared = !pick.whole_instant && (first_event > instant.first || end_event < instant.end);
    if (shared || pick.touching) {
        m.before = te;
        m.states[0] = render::frame_state(scene, te, instant.bodies);
        ka = t.size();
    }
    if (ka < t.size()) {
        m.after = t[ka];
        m.states[2] = run.frames[ka];
    } else {  // no sample between this collision and the next: the instant, after its impulses
        m.after = te;
        m.states[2] = render::frame_state(scene, te, instant.bodies);
    }
    // The numbers of the collision: "before" and "after" show the velocities just before and
    // just after its impacts (the page's meaning; with gravity the recorded frames' differ).
    // Within an instant resolved one contact after another, the contacts before this pair's
    // have acted already, and those after it not yet.
    std::vector<BodyState> pre, post;
    instant_velocities(scene, rec, which, &pre, &post);
    if (scene.policy == Policy::sequential)
        for (std::size_t k = instant.first; k < first_event; ++k) impulse_velocities(rec.events[k], When::after, &pre);
    impulse_velocities(first, When::before, &pre);
    post = pre;
    for (std::size_t k = first_event; k < end_event; ++k) impulse_velocities(rec.events[k], When::after, &post);
    with_velocities(pre, &m.states[0]);
    with_velocities(post, &m.states[2]);
    m.instant = with_roles(collision_instant(first), pick.a, pick.b);
    m.event = event;
    if (!pick.whole_instant) m.focus = {pick.a, pick.b};
    return m;
}

}  // namespace

int pair_collisions(const SceneRun& run, std::size_t a, std::size_t b) {
    return visit_record(run, [&](const auto& rec) {
        int n = 0;
        while (find_pick(rec, CollisionPick{a, b, n + 1})) ++n;
        return n;
    });
}

render::ImpactMark with_roles(const render::ImpactMark& mark, std::size_t a, std::size_t b) {
    if (mark.a != b || mark.b != a) return mark;
    render::ImpactMark out = mark;
    out.a = mark.b;
    out.b = mark.a;
    out.normal = -mark.normal;
    out.impulse = -mark.impulse;
    return out;
}

SceneRun run_scene(const Scene& scene, const std::vector<double>& times, const std::function<void(double t)>& on_sample,
                   const std::vector<RecordOptions::Keep>& keep) {
    SceneRun run;
    RecordOptions options;
    options.on_sample = on_sample;
    options.keep = keep;
    run.record = record_any(scene, times, options);
    visit_record(run, [&](const auto& rec) {
        for (std::size_t k = 0; k < rec.times.size(); ++k)
            run.frames.push_back(render::frame_state(scene, rec.times[k], rec.states[k]));
        for (const auto& e : rec.events) run.impacts.push_back(render::impact_mark(scene, e));
    });
    return run;
}

DataFiles data_files(const Scene& scene, const SceneRun& run) {
    DataFiles out;
    out.csv = csv_header(scene);
    out.events_csv = events_csv_header(scene.dimension);
    visit_record(run, [&](const auto& rec) {
        for (const FrameState& f : run.frames) out.csv += csv_row(scene, f);
        for (std::size_t k = 0; k < rec.times.size(); ++k) {
            if (k > 0) out.json_frames += ",\n";
            out.json_frames += state_json(scene, rec.times[k], rec.states[k]);
        }
        const std::vector<bool> gains = energy_gains(scene, rec.events);
        for (std::size_t k = 0; k < rec.events.size(); ++k) {
            if (k > 0) out.json_events += ",\n";
            out.json_events += event_json(scene, rec.events[k], gains[k]);
            out.events_csv += events_csv_row(scene, rec.events[k]);
        }
    });
    return out;
}

std::vector<InstantTotals> instant_totals(const Scene& scene, const SceneRun& run) {
    std::vector<InstantTotals> out;
    visit_record(run, [&](const auto& rec) {
        for (std::size_t k = 0; k < rec.instants.size(); ++k) {
            std::vector<BodyState> pre, post;
            instant_velocities(scene, rec, k, &pre, &post);
            FrameState f;
            f.t = rec.instants[k].t;
            f.bodies = pre;
            const render::FrameTotals before = render::frame_totals(scene, f);
            f.bodies = post;
            out.push_back({f.t, before, render::frame_totals(scene, f)});
        }
    });
    return out;
}

PlotTotals plot_totals(const Scene& scene, const SceneRun& run) {
    const std::vector<InstantTotals> exact = instant_totals(scene, run);
    PlotTotals out;
    std::size_t next = 0;
    for (const FrameState& f : run.frames) {
        while (next < exact.size() && exact[next].t <= f.t) {
            out.t.insert(out.t.end(), {exact[next].t, exact[next].t});
            out.totals.insert(out.totals.end(), {exact[next].before, exact[next].after});
            ++next;
        }
        if (!out.t.empty() && out.t.back() == f.t) continue;
        out.t.push_back(f.t);
        out.totals.push_back(render::frame_totals(scene, f));
    }
    return out;
}

std::vector<FrameState> plot_states(const Scene& scene, const SceneRun& run) {
    std::vector<FrameState> out;
    visit_record(run, [&](const auto& rec) {
        std::size_t next = 0;
        for (const FrameState& f : run.frames) {
            while (next < rec.instants.size() && rec.instants[next].t <= f.t) {
                std::vector<BodyState> pre, post;
                instant_velocities(scene, rec, next, &pre, &post);
                FrameState s;
                s.t = rec.instants[next].t;
                s.bodies = std::move(pre);
                out.push_back(s);
                s.bodies = std::move(post);
                out.push_back(std::move(s));
                ++next;
            }
            if (!out.empty() && out.back().t == f.t) continue;
            FrameState s;
            s.t = f.t;
            s.bodies = f.bodies;
            out.push_back(std::move(s));
        }
    });
    return out;
}

std::optional<Moments> page_moments(const Scene& scene, const SceneRun& run, const std::vector<CollisionPick>& picks) {
    return visit_record(run, [&](const auto& rec) -> std::optional<Moments> {
        const std::optional<CollisionPick> pick = page_pick(picks, rec);
        if (!pick) return std::nullopt;
        return moments_of(scene, run, rec, *pick);
    });
}

std::optional<Moments> first_moments(const Scene& scene, const SceneRun& run) { return page_moments(scene, run, {}); }

std::optional<Moments> collision_moments(const Scene& scene, const SceneRun& run, const CollisionPick& pick) {
    return visit_record(run, [&](const auto& rec) { return moments_of(scene, run, rec, pick); });
}

}  // namespace collide
