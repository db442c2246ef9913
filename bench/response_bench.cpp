// response/...: nanoseconds per collision response, for each model, with general (non-diagonal)
// world inertia tensors. Each iteration solves one collision from a fixed pool of random
// approaching pairs, so branch prediction and caches see realistic variety.
#include <cstdint>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/page.h"
#include "engine/response.h"
#include "engine/routh.h"

namespace {

using namespace collide;

constexpr int kPool = 256;  // pairs; about 120 KB, inside L2

struct Pair3 {
    ImpactBody3 a, b;
    Vec3 n;
};
struct Pair2 {
    ImpactBody2 a, b;
    Vec2 n;
};
struct Pair1 {
    ImpactBody1 a, b;
    double n;
};

Mat3 random_inertia(std::mt19937_64& rng, double m) {
    std::uniform_real_distribution<double> U(0.5, 1.0);
    const double i1 = U(rng), i2 = U(rng), i3 = std::min(i1 + i2, U(rng) + 0.5);  // I1 + I2 >= I3
    const Quat q = Quat(Eigen::Vector4d::Random()).normalized();
    const Mat3 R = q.toRotationMatrix();
    return m * R * Vec3(i1, i2, i3).asDiagonal() * R.transpose();
}

ImpactBody3 random_body3(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> U(-1.0, 1.0), M(0.5, 5.0);
    ImpactBody3 b;
    const double m = M(rng);
    b.inv_m = 1.0 / m;
    b.I = random_inertia(rng, m);
    b.inv_I = b.I.inverse();
    b.r = Vec3(U(rng), U(rng), U(rng));
    b.v = Vec3(U(rng), U(rng), U(rng));
    b.w = Vec3(U(rng), U(rng), U(rng));
    return b;
}

// A 3D body's motion in the xy plane: its mass, its zz moment, and the x, y parts of its lever
// arm and velocity with the z part of its spin.
ImpactBody2 flat(const ImpactBody3& b) {
    ImpactBody2 o;
    o.inv_m = b.inv_m;
    o.I = b.I(2, 2);
    o.inv_I = 1.0 / o.I;
    o.r = b.r.head<2>();
    o.v = b.v.head<2>();
    o.w = b.w.z();
    return o;
}

// The pair with n turned, if need be, so that its bodies approach along it.
template <class Pair>
Pair approaching(Pair c) {
    if (relative_velocity(c.a, c.b).dot(c.n) > 0) c.n = -c.n;
    return c;
}

Pair3 random_pair3(std::mt19937_64& rng) {
    return approaching(Pair3{random_body3(rng), random_body3(rng), Vec3::Random().normalized()});
}
Pair2 random_pair2(std::mt19937_64& rng) {
    const ImpactBody3 a = random_body3(rng), b = random_body3(rng);
    return approaching(Pair2{flat(a), flat(b), Vec2::Random().normalized()});
}

// kPool pairs made by make(rng) from `seed`, those that keep() accepts.
template <class Make, class Keep>
auto draw(std::uint64_t seed, Make make, Keep keep) {
    std::mt19937_64 rng(seed);
    std::vector<decltype(make(rng))> p;
    while (p.size() < kPool) {
        const auto c = make(rng);
        if (keep(c)) p.push_back(c);
    }
    return p;
}

// Each of `pool`'s pairs made another by make().
template <class Pool, class Make>
auto each(const Pool& pool, Make make) {
    std::vector<decltype(make(pool[0]))> p;
    for (const auto& c : pool) p.push_back(make(c));
    return p;
}

const std::vector<Pair3>& pool3() {
    static const std::vector<Pair3> pool = draw(42, random_pair3, [](const Pair3&) { return true; });
    return pool;
}

// pool3()'s pairs in the xy plane, each with a new random normal.
const std::vector<Pair2>& pool2() {
    static const std::vector<Pair2> pool = each(pool3(), [](const Pair3& c) {
        return approaching(Pair2{flat(c.a), flat(c.b), Vec2::Random().normalized()});
    });
    return pool;
}

// pool3()'s pairs along x.
const std::vector<Pair1>& pool1() {
    static const std::vector<Pair1> pool = each(pool3(), [](const Pair3& c) {
        Pair1 q{{c.a.inv_m, c.a.v.x()}, {c.b.inv_m, c.b.v.x()}, 1.0};
        if (q.b.v > q.a.v) q.n = -1.0;
        return q;
    });
    return pool;
}

// routh: pairs from the same generator kept only where, with Stronge's law and mu below, the
// slip stops during the impact and then sticks or reverses (two or more phases): the longer
// path of the model, and in 3D the integration of the turning slip up to its stop.
constexpr double e = 0.5, mu = 0.4;
constexpr double kRouthMu = mu;

template <class Pair>
bool slip_stops(const Pair& c) {
    RouthDetail d;
    routh(c.a, c.b, c.n, e, kRouthMu, RestitutionLaw::stronge, &d);
    return d.phases.size() >= 2;
}

const std::vector<Pair3>& pool3_slip_stops() {
    static const std::vector<Pair3> pool = draw(43, random_pair3, slip_stops<Pair3>);
    return pool;
}

const std::vector<Pair2>& pool2_slip_stops() {
    static const std::vector<Pair2> pool = draw(44, random_pair2, slip_stops<Pair2>);
    return pool;
}

template <class Pool, class Solve>
void run(benchmark::State& state, const Pool& pool, Solve solve) {
    std::size_t i = 0;
    for (auto _ : state) {
        const auto& c = pool[i++ & (kPool - 1)];
        auto r = solve(c);
        benchmark::DoNotOptimize(r);
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}

}  // namespace

#define RESPONSE_BENCH(NAME, POOL, EXPR)                                                                               \
    static void NAME(benchmark::State& s) {                                                                            \
        run(s, POOL(), [](const auto& c) { return EXPR; });                                                            \
    }

RESPONSE_BENCH(r3_frictionless, pool3, frictionless(c.a, c.b, c.n, e))
RESPONSE_BENCH(r3_coulomb, pool3, coulomb(c.a, c.b, c.n, e, mu))
RESPONSE_BENCH(r3_routh, pool3_slip_stops, routh(c.a, c.b, c.n, e, kRouthMu, RestitutionLaw::stronge))
RESPONSE_BENCH(r3_matrix, pool3, matrix(c.a, c.b, c.n, e))
RESPONSE_BENCH(r3_stick, pool3, stick(c.a, c.b, c.n))
RESPONSE_BENCH(r3_stick_ne, pool3, stick_newton_euler(c.a, c.b, c.n))
RESPONSE_BENCH(r3_page, pool3, page::listing(c.a, c.b, c.n, e))
RESPONSE_BENCH(r2_frictionless, pool2, frictionless(c.a, c.b, c.n, e))
RESPONSE_BENCH(r2_coulomb, pool2, coulomb(c.a, c.b, c.n, e, mu))
RESPONSE_BENCH(r2_routh, pool2_slip_stops, routh(c.a, c.b, c.n, e, kRouthMu, RestitutionLaw::stronge))
RESPONSE_BENCH(r2_matrix, pool2, matrix(c.a, c.b, c.n, e))
RESPONSE_BENCH(r2_stick, pool2, stick(c.a, c.b, c.n))
RESPONSE_BENCH(r1_frictionless, pool1, frictionless(c.a, c.b, c.n, e))
RESPONSE_BENCH(r1_stick, pool1, stick(c.a, c.b, c.n))

BENCHMARK(r3_frictionless)->Name("response/3d/frictionless");
BENCHMARK(r3_coulomb)->Name("response/3d/coulomb");
BENCHMARK(r3_routh)->Name("response/3d/routh");
BENCHMARK(r3_matrix)->Name("response/3d/matrix");
BENCHMARK(r3_stick)->Name("response/3d/stick");
BENCHMARK(r3_stick_ne)->Name("response/3d/stick-newton-euler");
BENCHMARK(r3_page)->Name("response/3d/page-listing");
BENCHMARK(r2_frictionless)->Name("response/2d/frictionless");
BENCHMARK(r2_coulomb)->Name("response/2d/coulomb");
BENCHMARK(r2_routh)->Name("response/2d/routh");
BENCHMARK(r2_matrix)->Name("response/2d/matrix");
BENCHMARK(r2_stick)->Name("response/2d/stick");
BENCHMARK(r1_frictionless)->Name("response/1d/frictionless");
BENCHMARK(r1_stick)->Name("response/1d/stick");
