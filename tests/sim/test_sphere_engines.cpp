// Every engine in 3D (#32): the classic loop on any queue, the fast engine and the time-driven one
// run spheres with one code per method. The classic and fast engines agree event by event, energy
// is conserved to round-off, the time-driven engine's failures are measured in 3D as in 2D, and
// the speeds relax to the 3D Maxwell-Boltzmann law.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "collide/error.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/fast_engine.hpp"
#include "collide/sim/generate3.hpp"
#include "collide/sim/time_engine.hpp"
#include "same_events.hpp"
#include "sphere_fixtures.hpp"

using namespace collide;

namespace {

using collide::test::fcc_fluid;
using collide::test::require_same_events;
using collide::test::sphere;

/// Random spheres of two masses in a walled box that is not a cube (every wall kind occurs).
SphereScene walled_sphere_gas(std::uint64_t seed) {
    SphereScene scene;
    scene.name = "gas";
    scene.box = Box3{1.0, 0.8, 1.2, Boundary::walls};
    SphereGenerateSpec gen;
    gen.packing_fraction = 0.15;
    gen.radius = 0.05;
    gen.seed = seed;
    generate_spheres(scene, gen);
    for (std::size_t i = 0; i < scene.spheres.size(); i += 3) scene.spheres[i].mass = 2.5;
    return scene;
}

EngineOptions options_for(EngineKind kind, double dt = 0.01,
                          OverlapDetection detect = OverlapDetection::all_pairs) {
    EngineOptions o;
    o.engine = kind;
    o.dt = dt;
    o.td_detect = detect;
    return o;
}

/// The first `count` collisions of an engine on the scene.
std::vector<CollisionRecord> first_sphere_collisions(SphereEngine& engine, std::size_t count) {
    std::vector<CollisionRecord> out;
    engine.set_collision_listener([&](const CollisionRecord& r) { out.push_back(r); });
    while (out.size() < count) engine.advance_to(engine.time() + 0.01);
    out.resize(count);
    return out;
}

double kinetic_energy(const SphereSnapshot& s) {
    double e = 0.0;
    for (const SphereState& p : s.spheres) e += 0.5 * p.mass * norm2(p.velocity);
    return e;
}

Vec3 sphere_momentum(const SphereSnapshot& s) {
    Vec3 p{};
    for (const SphereState& q : s.spheres) p += q.mass * q.velocity;
    return p;
}

/// The 3D Maxwell-Boltzmann distribution of speeds at kT / m = a^2: P(speed <= v).
double maxwell_cdf(double v, double a) {
    const double x = v / a;
    return std::erf(x / std::numbers::sqrt2) -
           std::sqrt(2.0 / std::numbers::pi) * x * std::exp(-0.5 * x * x);
}

/// Kolmogorov-Smirnov distance between the sample's empirical distribution and maxwell_cdf.
double ks_distance(std::vector<double> speeds, double a) {
    std::sort(speeds.begin(), speeds.end());
    const auto n = static_cast<double>(speeds.size());
    double d = 0.0;
    for (std::size_t k = 0; k < speeds.size(); ++k) {
        const double f = maxwell_cdf(speeds[k], a);
        d = std::max({d, static_cast<double>(k + 1) / n - f, f - static_cast<double>(k) / n});
    }
    return d;
}

std::vector<double> speeds_of(const SphereSnapshot& s) {
    std::vector<double> out;
    for (const SphereState& p : s.spheres) out.push_back(norm(p.velocity));
    return out;
}

}  // namespace

/// The FCC fluid with every other sphere shrunk to 0.92 of the radius and 1.5 times as heavy:
/// packing 0.40, still on neighbour lists, whose rebuilds then read every radius.
SphereScene mixed_fluid() {
    SphereScene scene = fcc_fluid(3, 0.45, 13);
    scene.name = "mixed";
    for (std::size_t i = 0; i < scene.spheres.size(); i += 2) {
        scene.spheres[i].radius *= 0.92;
        scene.spheres[i].mass = 1.5;
    }
    return scene;
}

TEST_CASE("3D: the classic loop and the fast engine agree event by event") {
    // Packing 0.45 and the mixed fluid: the fast engine's neighbour lists (0.3 and the walled
    // gas: cell crossings).
    for (const SphereScene& scene :
         {walled_sphere_gas(7), fcc_fluid(3, 0.3, 11), fcc_fluid(3, 0.45, 11), mixed_fluid()}) {
        CAPTURE(scene.name);
        CAPTURE(scene.spheres.front().radius);
        REQUIRE(scene.spheres.size() > 100);
        if (scene.name == "mixed") REQUIRE(sim::FastSphereEngine(scene).uses_neighbour_lists());
        auto classic = make_engine(scene, options_for(EngineKind::classic));
        auto fast = make_engine(scene, options_for(EngineKind::fast));
        // The engines round differently (local clocks against one clock for all), and a hard
        // sphere gas is chaotic: the difference starts at 1e-15 and grows about tenfold every
        // 150 collisions of ~100 spheres, so past ~1500 collisions the same physics gives other
        // events. 1000 stay within 1e-9 (1e-10 measured).
        const std::vector<CollisionRecord> a = first_sphere_collisions(*classic, 1000);
        const std::vector<CollisionRecord> b = first_sphere_collisions(*fast, 1000);
        require_same_events(a, b, 1e-9);
        const auto zwalls = std::count_if(a.begin(), a.end(), [](const CollisionRecord& r) {
            return r.kind == CollisionKind::zwall;
        });
        if (scene.box.boundary == Boundary::walls) CHECK(zwalls > 0);
    }
}

TEST_CASE("3D: a crowd in one corner of a large box gets cells for the crowd, same events") {
    // A gas about to expand into an empty box: 300 spheres fill 1/1000 of its volume. Cells for
    // the mean density (2 per sphere: 8 per axis) would put them all in one cell, and every
    // prediction would test all 300.
    SphereScene scene;
    scene.name = "corner";
    scene.box = Box3{10.0, 10.0, 10.0, Boundary::walls};
    SphereGenerateSpec gen;
    gen.count = 300;
    gen.radius = 0.05;
    gen.region_max = Vec3{1.0, 1.0, 1.0};
    gen.seed = 5;
    generate_spheres(scene, gen);
    sim::FastSphereEngine fast(scene);
    for (int k = 0; k < 3; ++k) CHECK(fast.cells_along(k) >= 32);
    CHECK(fast.cells_along(0) <= 100);  // no finer than the spheres' reach: 1e6 cells
    auto classic = make_engine(scene, options_for(EngineKind::classic));
    const std::vector<CollisionRecord> a = first_sphere_collisions(*classic, 300);
    std::vector<CollisionRecord> b;
    fast.set_collision_listener([&](const CollisionRecord& r) { b.push_back(r); });
    while (b.size() < a.size()) {
        fast.advance_to(fast.time() + 0.01);
        REQUIRE(fast.check_invariants());
    }
    b.resize(a.size());
    require_same_events(a, b, 1e-9);
}

TEST_CASE(
    "3D: every queue of the lecture drives the classic loop to the same events, bit for bit") {
    const SphereScene scene = walled_sphere_gas(3);
    EngineOptions binary = options_for(EngineKind::classic);
    const std::vector<CollisionRecord> reference =
        first_sphere_collisions(*make_engine(scene, binary), 500);
    for (const char* kind : {"unordered", "ordered", "dary:4", "indexed"}) {
        CAPTURE(kind);
        EngineOptions o = binary;
        o.pq = pq::parse_queue_kind(kind);
        const std::vector<CollisionRecord> got =
            first_sphere_collisions(*make_engine(scene, o), 500);
        for (std::size_t k = 0; k < got.size(); ++k) {
            REQUIRE(got[k].t == reference[k].t);
            REQUIRE(got[k].a == reference[k].a);
            REQUIRE(got[k].b == reference[k].b);
        }
    }
}

TEST_CASE("3D: energy conserved to round-off by the classic and time-driven engines") {
    // 32 spheres: the classic loop's queue holds O(N^2) events, and the sanitizer build checks
    // the whole heap after every change, so a larger system takes minutes there.
    const SphereScene scene = fcc_fluid(2, 0.3, 5);
    for (const EngineKind kind : {EngineKind::classic, EngineKind::time}) {
        CAPTURE(to_string(kind));
        auto engine = make_engine(scene, options_for(kind, 0.002));
        const SphereSnapshot before = engine->snapshot();
        engine->advance_to(4.0);
        const SphereSnapshot after = engine->snapshot();
        const Measurements m = engine->measurements();
        CHECK(m.collisions_pair > 1000);  // about 2,450 for both engines
        CHECK(std::abs(kinetic_energy(after) - kinetic_energy(before)) <
              1e-12 * kinetic_energy(before));
        CHECK(norm(sphere_momentum(after) - sphere_momentum(before)) < 1e-11);
        CHECK(m.temperature == doctest::Approx(1.0).epsilon(1e-9));  // three degrees of freedom
        if (kind == EngineKind::time) {
            CHECK(std::abs(m.energy_drift) < 1e-12);
        } else {
            CHECK(m.max_overlap <= 1e-9);
        }
    }
}

TEST_CASE("3D time-driven: a head-on collision along a diagonal, rolled back to contact") {
    SphereScene scene;
    scene.box = Box3{2.0, 2.0, 2.0, Boundary::walls};
    const Vec3 u = (1.0 / std::sqrt(3.0)) * Vec3{1.0, 1.0, 1.0};
    scene.spheres = {sphere(Vec3{1.0, 1.0, 1.0} - 0.5 * u, 0.5 * u, 0.1),
                     sphere(Vec3{1.0, 1.0, 1.0} + 0.5 * u, -0.5 * u, 0.1)};
    for (const OverlapDetection detect : {OverlapDetection::all_pairs, OverlapDetection::grid}) {
        sim::TimeSphereEngine engine(scene, options_for(EngineKind::time, 0.013, detect));
        std::vector<CollisionRecord> hits;
        engine.set_collision_listener([&](const CollisionRecord& r) { hits.push_back(r); });
        engine.advance_to(1.2);
        REQUIRE(hits.size() == 1);
        CHECK(hits[0].t == doctest::Approx(0.8).epsilon(1e-9));  // 0.4 apart closing at speed 1
        const SphereSnapshot s = engine.snapshot();
        CHECK(norm(s.spheres[0].velocity + 0.5 * u) < 1e-12);  // equal masses swap velocities
        CHECK(norm(s.spheres[1].velocity - 0.5 * u) < 1e-12);
        CHECK(s.overlapping_pairs.empty());
    }
}

TEST_CASE(
    "3D time-driven: a sphere bounces off the front and back walls, or escapes when too fast") {
    SphereScene scene;
    scene.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    scene.spheres = {sphere({0.5, 0.5, 0.5}, {0.0, 0.0, 1.0}, 0.1)};
    sim::TimeSphereEngine slow(scene, options_for(EngineKind::time, 0.01));
    slow.advance_to(1.5);
    Measurements m = slow.measurements();
    CHECK(m.collisions_zwall == 2);  // the back wall at t = 0.4, the front one at 1.2
    CHECK(m.collisions_xwall + m.collisions_ywall == 0);
    CHECK(m.escaped == 0);
    scene.spheres[0].velocity = {0.0, 0.0, 100.0};  // 1 box per step: through the wall
    sim::TimeSphereEngine fast(scene, options_for(EngineKind::time, 0.01));
    fast.advance_to(0.01);
    m = fast.measurements();
    CHECK(m.escaped == 1);
    CHECK(fast.snapshot().spheres[0].escaped);
}

TEST_CASE("3D time-driven: spheres passing through each other in one step are a missed collision") {
    SphereScene scene;
    scene.box = Box3{2.0, 2.0, 2.0, Boundary::periodic};
    scene.spheres = {sphere({0.7, 1.0, 1.0}, {30.0, 0.0, 0.0}, 0.05),
                     sphere({1.3, 1.0, 1.0}, {-30.0, 0.0, 0.0}, 0.05)};
    sim::TimeSphereEngine engine(scene, options_for(EngineKind::time, 0.02));
    engine.advance_to(0.02);
    const Measurements m = engine.measurements();
    CHECK(m.missed_collisions == 1);
    CHECK(m.collisions_pair == 0);
    const SphereSnapshot s = engine.snapshot();
    REQUIRE(s.missed_collisions.size() == 1);
    CHECK(s.missed_collisions[0].x == doctest::Approx(1.0));  // they met in the middle
    CHECK(s.missed_collisions[0].z == doctest::Approx(1.0));
}

TEST_CASE("3D time-driven: the grid and all-pairs detections give identical runs") {
    for (const SphereScene& scene : {walled_sphere_gas(5), fcc_fluid(3, 0.3, 2)}) {
        CAPTURE(scene.name);
        sim::TimeSphereEngine all(scene, options_for(EngineKind::time, 0.004));
        sim::TimeSphereEngine grid(scene,
                                   options_for(EngineKind::time, 0.004, OverlapDetection::grid));
        all.advance_to(0.5);
        grid.advance_to(0.5);
        const SphereSnapshot a = all.snapshot();
        const SphereSnapshot b = grid.snapshot();
        const Measurements ma = all.measurements();
        const Measurements mb = grid.measurements();
        CHECK(ma.collisions_pair > 100);
        CHECK(ma.collisions_pair == mb.collisions_pair);
        CHECK(ma.missed_collisions == mb.missed_collisions);
        CHECK(mb.overlap_checks < ma.overlap_checks);
        for (std::size_t i = 0; i < a.spheres.size(); ++i) {
            REQUIRE(a.spheres[i].position == b.spheres[i].position);
            REQUIRE(a.spheres[i].velocity == b.spheres[i].velocity);
        }
        const auto n = static_cast<std::uint64_t>(scene.spheres.size());
        CHECK(ma.overlap_checks == ma.steps * n * (n - 1) / 2);
    }
}

TEST_CASE("3D: a periodic box under three diameters wide runs on the classic loop") {
    SphereScene scene;
    scene.box = Box3{1.0, 1.0, 1.0, Boundary::periodic};
    // Head-on along x, the same drift along y and z: they meet again and again across the seam.
    scene.spheres = {sphere({0.3, 0.5, 0.5}, {1.0, 0.2, -0.3}, 0.2),
                     sphere({0.75, 0.5, 0.5}, {-1.0, 0.2, -0.3}, 0.2)};
    auto engine = make_engine(scene, options_for(EngineKind::fast));
    engine->advance_to(5.0);
    const Measurements m = engine->measurements();
    // Gaps of 0.05 and then 0.2 at a closing speed of 2: a collision every 0.1 time units, the
    // second one through the seam right after the first (see the classic loop's nearest image).
    CHECK(m.collisions_pair == 50);
    CHECK(m.max_overlap <= 1e-9);
}

TEST_CASE("3D: equal speeds relax to the Maxwell-Boltzmann law (Kolmogorov-Smirnov)") {
    // 864 spheres at packing 0.3, every one with the same speed sqrt(3 kT / m) in its own
    // direction: far from Maxwell-Boltzmann at t = 0, on it after some 20 collisions each.
    SphereScene scene = fcc_fluid(6, 0.3, 17);
    for (Sphere& s : scene.spheres) {
        s.velocity = (std::sqrt(3.0) / norm(s.velocity)) * s.velocity;
    }
    const double a = 1.0;  // kT / m = 1: sqrt(kT / m)
    // 1.63 / sqrt(N): the KS distance the 1% level allows (asymptotic Kolmogorov).
    const double allowed = 1.63 / std::sqrt(static_cast<double>(scene.spheres.size()));
    auto engine = make_engine(scene, options_for(EngineKind::fast));
    CHECK(ks_distance(speeds_of(engine->snapshot()), a) > 3.0 * allowed);  // the test can fail
    engine->advance_to(1.0);
    const Measurements m = engine->measurements();
    CHECK(static_cast<double>(m.collisions_pair) >
          10.0 * static_cast<double>(scene.spheres.size()));
    CHECK(m.temperature == doctest::Approx(1.0).epsilon(1e-9));
    const double d = ks_distance(speeds_of(engine->snapshot()), a);
    CAPTURE(d);
    CHECK(d < allowed);
}
