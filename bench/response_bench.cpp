// response/...: nanoseconds per collision response, for each model, with general (non-diagonal)
// world inertia tensors. Each iteration solves one collision from a fixed pool of random
// approaching pairs, so branch prediction and caches see realistic variety.
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

const std::vector<Pair3>& pool3() {
    static const std::vector<Pair3> pool = [] {
        std::mt19937_64 rng(42);
        std::vector<Pair3> p;
        while (p.size() < kPool) {
            Pair3 c{random_body3(rng), random_body3(rng), Vec3::Random().normalized()};
            if (relative_velocity(c.a, c.b).dot(c.n) > 0) c.n = -c.n;  // approaching
            p.push_back(c);
        }
        return p;
    }();
    return pool;
}

const std::vector<Pair2>& pool2() {
    static const std::vector<Pair2> pool = [] {
        std::vector<Pair2> p;
        for (const Pair3& c : pool3()) {
            auto flat = [](const ImpactBody3& b) {
                ImpactBody2 o;
                o.inv_m = b.inv_m;
                o.I = b.I(2, 2);
                o.inv_I = 1.0 / o.I;
                o.r = b.r.head<2>();
                o.v = b.v.head<2>();
                o.w = b.w.z();
                return o;
            };
            Pair2 q{flat(c.a), flat(c.b), Vec2::Random().normalized()};
            if (relative_velocity(q.a, q.b).dot(q.n) > 0) q.n = -q.n;
            p.push_back(q);
        }
        return p;
    }();
    return pool;
}

const std::vector<Pair1>& pool1() {
    static const std::vector<Pair1> pool = [] {
        std::vector<Pair1> p;
        for (const Pair3& c : pool3()) {
            Pair1 q{{c.a.inv_m, c.a.v.x()}, {c.b.inv_m, c.b.v.x()}, 1.0};
            if (q.b.v > q.a.v) q.n = -1.0;
            p.push_back(q);
        }
        return p;
    }();
    return pool;
}

// routh: pairs from the same generator kept only where, with Stronge's law and mu below, the
// slip stops during the impact and then sticks or reverses (two or more phases): the longer
// path of the model, and in 3D the integration of the turning slip up to its stop.
constexpr double e = 0.5, mu = 0.4;
constexpr double kRouthMu = mu;

const std::vector<Pair3>& pool3_slip_stops() {
    static const std::vector<Pair3> pool = [] {
        std::mt19937_64 rng(43);
        std::vector<Pair3> p;
        RouthDetail d;
        while (p.size() < kPool) {
            Pair3 c{random_body3(rng), random_body3(rng), Vec3::Random().normalized()};
            if (relative_velocity(c.a, c.b).dot(c.n) > 0) c.n = -c.n;
            routh(c.a, c.b, c.n, e, kRouthMu, RestitutionLaw::stronge, &d);
            if (d.phases.size() >= 2) p.push_back(c);
        }
        return p;
    }();
    return pool;
}

const std::vector<Pair2>& pool2_slip_stops() {
    static const std::vector<Pair2> pool = [] {
        std::mt19937_64 rng(44);
        std::vector<Pair2> p;
        RouthDetail d;
        while (p.size() < kPool) {
            const ImpactBody3 a = random_body3(rng), b = random_body3(rng);
            auto flat = [](const ImpactBody3& x) {
                ImpactBody2 o;
                o.inv_m = x.inv_m;
                o.I = x.I(2, 2);
                o.inv_I = 1.0 / o.I;
                o.r = x.r.head<2>();
                o.v = x.v.head<2>();
                o.w = x.w.z();
                return o;
            };
            Pair2 q{flat(a), flat(b), Vec2::Random().normalized()};
            if (relative_velocity(q.a, q.b).dot(q.n) > 0) q.n = -q.n;
            routh(q.a, q.b, q.n, e, kRouthMu, RestitutionLaw::stronge, &d);
            if (d.phases.size() >= 2) p.push_back(q);
        }
        return p;
    }();
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
