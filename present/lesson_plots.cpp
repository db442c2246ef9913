#include "present/lesson_plots.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>

#include "render/frame_state.h"
#include "teach/notation.h"

namespace collide {

namespace {

using Kind = PlotQuantity::Kind;

std::string sig3(double x) { return notation::sig_text(x, 3); }

std::string with_unit(const std::string& name, const std::string& unit) {
    return unit.empty() ? name : name + " (" + unit + ")";
}

// One sample quantity at one sampled instant.
double sample_value(const PlotQuantity& q, const Lesson& lesson, const Scene& scene, const render::FrameState& f) {
    if (q.kind == Kind::time) return f.t;
    if (q.kind == Kind::kinetic || q.kind == Kind::potential || q.kind == Kind::energy || q.kind == Kind::momentum ||
        q.kind == Kind::angular_momentum) {
        const render::FrameTotals s = q.body >= 0 ? render::body_totals(scene, f, static_cast<std::size_t>(q.body))
                                                  : render::frame_totals(scene, f);
        if (q.kind == Kind::kinetic) return s.kinetic;
        if (q.kind == Kind::potential) return s.potential;
        if (q.kind == Kind::energy) return s.kinetic + s.potential;
        if (q.kind == Kind::momentum) return s.momentum[q.component];
        return s.angular_momentum[q.component];
    }
    const BodyState& b = f.bodies[static_cast<std::size_t>(q.body)];
    // A [[mark]]: the point fixed in the body, at q r from its centre; its velocity v + w x q r.
    const Vec3 r = q.mark >= 0 ? Vec3(b.q * lesson.view.marks[static_cast<std::size_t>(q.mark)].at) : Vec3::Zero();
    switch (q.kind) {
        case Kind::position: return (b.x + r)[q.component];
        case Kind::velocity: return (b.v + b.w.cross(r))[q.component];
        case Kind::spin: return b.w[q.component];
        case Kind::angle: return b.angle;
        default: return 0.0;
    }
}

struct Hit {
    double t = 0;
    std::size_t a = 0, b = 0;
    double impulse = 0;  // N s, the size of the impulse on b
};

std::vector<Hit> hits_of(const SceneRun& run) {
    std::vector<Hit> out;
    std::visit(
        [&](const auto& rec) {
            for (const auto& e : rec.events) {
                if constexpr (std::is_same_v<std::decay_t<decltype(e)>, Event1>)
                    out.push_back({e.t, e.a, e.b, std::abs(e.impulse)});
                else out.push_back({e.t, e.a, e.b, lift(e.impulse).norm()});
            }
        },
        run.record);
    return out;
}

bool same_pair(const Hit& h, std::size_t i, std::size_t j) { return (h.a == i && h.b == j) || (h.a == j && h.b == i); }

// A collision's words: "ball and floor", "domino 3 strikes domino 4".
std::string hit_words(const Scene& s, const Hit& h) { return s.bodies[h.a].name + " and " + s.bodies[h.b].name; }

// Several quantities of one unit on one axis: what they are, if they are of one kind
// ("velocity (m/s)"), else the unit alone.
std::string plot_kind_words(const std::vector<PlotQuantity>& y) {
    const std::string unit = y.front().unit;
    const Kind kind = y.front().kind;
    const bool one_kind = std::all_of(y.begin(), y.end(), [&](const PlotQuantity& q) { return q.kind == kind; });
    if (!one_kind) return unit;
    switch (kind) {
        case Kind::position: return with_unit("position", unit);
        case Kind::velocity: return with_unit("velocity", unit);
        case Kind::spin: return with_unit("angular velocity", unit);
        case Kind::angle: return with_unit("angle", unit);
        case Kind::momentum: return with_unit("momentum", unit);
        default: return unit;
    }
}

}  // namespace

std::string plot_quantity_words(const PlotQuantity& q, const Lesson& lesson, bool per_collision,
                                const std::string& counting, bool unit) {
    const Scene& scene = lesson.scene;
    const auto done = [&](const std::string& words) { return unit ? with_unit(words, q.unit) : words; };
    if (per_collision) {
        if (q.name == "collision") return counting + " number";
        if (q.name == "interval") return done("time since the previous " + counting);
        if (q.name == "impulse") return done("impulse");
        return done("time t");
    }
    const std::string axis = q.component == 0 ? "x" : q.component == 1 ? "y" : "z";
    const std::string body = q.body >= 0 ? scene.bodies[static_cast<std::size_t>(q.body)].name : std::string();
    const std::string whose = q.body >= 0 ? body + ": " : "total ";
    switch (q.kind) {
        case Kind::time: return done("time t");
        case Kind::kinetic: return done(whose + "kinetic energy");
        case Kind::potential: return done(whose + "potential energy");
        case Kind::energy: return done(whose + "energy (kinetic + potential)");
        case Kind::momentum: return done(whose + (scene.dimension == 1 ? "momentum" : "momentum, " + axis));
        case Kind::angular_momentum:
            return done(whose + "angular momentum about the origin" + (scene.dimension == 3 ? ", " + axis : ""));
        default: break;
    }
    const std::string point =
        q.mark >= 0 ? lesson.view.marks[static_cast<std::size_t>(q.mark)].name : std::string("centre");
    // Along y against gravity (gravity along -y only): a height.
    const bool up = q.component == 1 && scene.gravity.y() < 0 && scene.gravity.x() == 0 && scene.gravity.z() == 0;
    const std::string along = scene.dimension == 1 ? "" : ", " + axis;
    switch (q.kind) {
        case Kind::position: return done(body + ": " + (up ? "height" : "position") + " of " + point + along);
        case Kind::velocity: return done(body + ": velocity of " + point + along);
        case Kind::spin: return done(body + ": angular velocity" + (scene.dimension == 3 ? ", " + axis : ""));
        case Kind::angle: return done(body + ": angle");
        default: return done(q.name);
    }
}

std::vector<PlotData> lesson_plots(const Lesson& lesson, const Scene& scene, const SceneRun& run) {
    std::vector<PlotData> out;
    std::vector<render::FrameState> states;  // the per-sample plots' instants (plot_states)
    for (const LessonPlot& P : lesson.plots) {
        PlotData D;
        D.title = P.title;
        D.per_collision = P.per == PlotPer::collision;
        if (!D.per_collision) {
            D.x_unit = P.x.unit;
            D.y_unit = P.y.front().unit;
            D.x_label = P.x.kind == Kind::time ? with_unit("t", P.x.unit) : plot_quantity_words(P.x, lesson, false);
            D.y_label = P.y.size() == 1 ? plot_quantity_words(P.y.front(), lesson, false) : plot_kind_words(P.y);
            if (states.empty()) states = plot_states(scene, run);
            for (const PlotQuantity& q : P.y) {
                PlotSeriesData S{q.name, plot_quantity_words(q, lesson, false, "", false), {}, {}, {}};
                for (const render::FrameState& f : states) {
                    S.x.push_back(sample_value(P.x, lesson, scene, f));
                    S.y.push_back(sample_value(q, lesson, scene, f));
                }
                D.series.push_back(std::move(S));
            }
            if (P.fit == PlotFit::none) {
                // What it shows in words: each series' range and its last value.
                std::string what = P.title + ": " + std::to_string(states.size()) + " instants of the run.";
                for (std::size_t s = 0; s < D.series.size(); ++s) {
                    const PlotSeriesData& S = D.series[s];
                    if (S.y.empty()) continue;
                    const auto [lo, hi] = std::minmax_element(S.y.begin(), S.y.end());
                    what += " " + S.words + " from " + sig3(*lo) + " to " + sig3(*hi) + " " + D.y_unit + ", " +
                            sig3(S.y.back()) + " " + D.y_unit + " at " + P.x.name + " = " + sig3(S.x.back()) + " " +
                            D.x_unit + ".";
                }
                D.summary = what;
                out.push_back(std::move(D));
                continue;
            }
        }
        // Per collision: the collisions chosen, numbered from 1.
        std::vector<Hit> rows;
        std::vector<int> numbers;
        const std::vector<Hit> hits = hits_of(run);
        if (D.per_collision) {
            if (!P.chain_index.empty()) {
                for (std::size_t k = 0; k + 1 < P.chain_index.size(); ++k) {
                    const std::size_t i = P.chain_index[k], j = P.chain_index[k + 1];
                    const auto it =
                        std::find_if(hits.begin(), hits.end(), [&](const Hit& h) { return same_pair(h, i, j); });
                    if (it == hits.end()) {
                        D.missing.push_back(P.chain[k] + " never strikes " + P.chain[k + 1]);
                        continue;
                    }
                    rows.push_back(*it);
                    numbers.push_back(static_cast<int>(k + 1));
                    D.row_numbers.push_back(numbers.back());
                    D.row_times.push_back(it->t);
                    D.row_names.push_back(P.chain[k] + " strikes " + P.chain[k + 1]);
                }
            } else {
                // instant: the time of the first collision of its two bodies (none: no rows).
                std::optional<double> when;
                if (P.instant_index.size() == 2) {
                    const auto it = std::find_if(hits.begin(), hits.end(), [&](const Hit& h) {
                        return same_pair(h, P.instant_index[0], P.instant_index[1]);
                    });
                    if (it == hits.end()) D.missing.push_back(P.instant[0] + " never collides with " + P.instant[1]);
                    else when = it->t;
                }
                for (const Hit& h : hits) {
                    if (P.pair_index.size() == 2 && !same_pair(h, P.pair_index[0], P.pair_index[1])) continue;
                    if (P.instant_index.size() == 2 && !(when && h.t == *when)) continue;
                    rows.push_back(h);
                    numbers.push_back(static_cast<int>(rows.size()));
                    D.row_numbers.push_back(numbers.back());
                    D.row_times.push_back(h.t);
                    D.row_names.push_back(hit_words(scene, h));
                }
            }
            D.x_unit = P.x.unit;
            D.y_unit = P.y.front().unit;
            D.x_label = P.x.name == "collision" ? P.counting + " number" : with_unit("t", "s");
            for (const PlotQuantity& q : P.y) {
                PlotSeriesData S{q.name, plot_quantity_words(q, lesson, true, P.counting, false), {}, {}, {}};
                for (std::size_t k = 0; k < rows.size(); ++k) {
                    double y = 0;
                    if (q.name == "t") y = rows[k].t;
                    else if (q.name == "impulse") y = rows[k].impulse;
                    else if (k == 0) continue;  // interval: from the collision before
                    else y = rows[k].t - rows[k - 1].t;
                    S.x.push_back(P.x.name == "t" ? rows[k].t : numbers[k]);
                    S.number.push_back(numbers[k]);
                    S.y.push_back(y);
                }
                D.series.push_back(std::move(S));
            }
            D.y_label = P.y.size() == 1 ? plot_quantity_words(P.y.front(), lesson, true, P.counting) : D.y_unit;
        }
        const PlotSeriesData& S = D.series.front();
        std::string what = P.title + ": ";
        if (P.fit == PlotFit::line) {
            PlotData::Line L;
            double sx = 0, sy = 0, sxx = 0, sxy = 0;
            bool first = true;
            for (std::size_t k = 0; k < S.x.size(); ++k) {
                // Per collision: only the collisions numbered from fit_from.
                if (D.per_collision && S.number[k] < P.fit_from) continue;
                sx += S.x[k];
                sy += S.y[k];
                sxx += S.x[k] * S.x[k];
                sxy += S.x[k] * S.y[k];
                L.x0 = first ? S.x[k] : std::min(L.x0, S.x[k]);
                L.x1 = first ? S.x[k] : std::max(L.x1, S.x[k]);
                first = false;
                ++L.points;
            }
            const double n = L.points, den = n * sxx - sx * sx;
            if (L.points >= 2 && std::abs(den) > 0) {
                L.slope = (n * sxy - sx * sy) / den;
                L.intercept = (sy - L.slope * sx) / n;
                L.slope_unit = D.y_unit + (P.x.name == "collision" ? " per " + P.counting : "/" + D.x_unit);
                what += "a straight line fitted to " + std::to_string(L.points) + " points" +
                        (P.fit_from > 1 ? " (from " + P.counting + " " + std::to_string(P.fit_from) + " on)" : "") +
                        ", slope " + sig3(L.slope) + " " + L.slope_unit;
                if (!P.chain_index.empty() && P.x.name == "collision" && P.y.front().name == "t" && L.slope > 0) {
                    double d = 0;
                    const auto& b0 = run.frames.front().bodies;
                    for (std::size_t k = 0; k + 1 < P.chain_index.size(); ++k)
                        d += (b0[P.chain_index[k + 1]].x - b0[P.chain_index[k]].x).norm();
                    L.spacing = d / static_cast<double>(P.chain_index.size() - 1);
                    L.speed = L.spacing / L.slope;
                    what += "; with " + sig3(L.spacing) + " m between neighbours, a wave speed of " + sig3(*L.speed) +
                            " m/s";
                }
                what += ".";
                D.line = L;
            } else {
                what += "too few points for a line (" + std::to_string(L.points) + ").";
            }
        } else if (P.fit == PlotFit::ratio) {
            PlotData::Ratio R;
            std::vector<double> finite;
            for (std::size_t k = 1; k < S.y.size(); ++k) {
                R.ratios.push_back(S.y[k - 1] != 0 ? S.y[k] / S.y[k - 1] : std::nan(""));
                if (std::isfinite(R.ratios.back())) finite.push_back(R.ratios.back());
            }
            if (!finite.empty()) {
                R.lo = *std::min_element(finite.begin(), finite.end());
                R.hi = *std::max_element(finite.begin(), finite.end());
                for (double r : finite) R.mean += r / static_cast<double>(finite.size());
            }
            if (P.pair_index.size() == 2) R.restitution = scene.pair_restitution(P.pair_index[0], P.pair_index[1]);
            what +=
                std::to_string(S.y.size()) + " values; each is " +
                (finite.empty() ? std::string("(too few to compare)")
                                : sig3(R.mean) + " times the one before" +
                                      (sig3(R.lo) == sig3(R.hi) ? " (every one of them, to 3 figures)"
                                                                : " (from " + sig3(R.lo) + " to " + sig3(R.hi) + ")")) +
                (R.restitution ? ", and e = " + sig3(*R.restitution) : std::string()) + ".";
            D.ratio = R;
            D.log_y = !S.y.empty() && std::all_of(S.y.begin(), S.y.end(), [](double y) { return y > 0; });
            if (D.log_y)
                D.y_label = P.y.size() == 1 ? plot_quantity_words(P.y.front(), lesson, true, P.counting, false) + " (" +
                                                  D.y_unit + ", log scale)"
                                            : D.y_unit + ", log scale";
        } else if (!S.y.empty()) {
            // The largest and the smallest, with the collisions they belong to.
            const auto name_of = [&](std::size_t i) {
                for (std::size_t r = 0; r < numbers.size(); ++r)
                    if (numbers[r] == S.number[i]) return D.row_names[r];
                return std::string();
            };
            const auto lo = static_cast<std::size_t>(std::min_element(S.y.begin(), S.y.end()) - S.y.begin());
            const auto hi = static_cast<std::size_t>(std::max_element(S.y.begin(), S.y.end()) - S.y.begin());
            what += std::to_string(S.y.size()) + " values of " +
                    plot_quantity_words(P.y.front(), lesson, true, P.counting, false) + ", the largest " +
                    sig3(S.y[hi]) + " " + D.y_unit + " (" + name_of(hi) + "), the smallest " + sig3(S.y[lo]) + " " +
                    D.y_unit + " (" + name_of(lo) + ").";
        } else {
            what += "no collision of these in the run.";
        }
        if (!D.missing.empty()) {
            what += " Not in the run:";
            for (const std::string& m : D.missing) what += " " + m + ";";
        }
        D.summary = what;
        out.push_back(std::move(D));
    }
    return out;
}

}  // namespace collide
