// Observables shared by the engines: overlap search, packing fraction, speed histogram, the
// big-disc split, and pressure / Z from accumulated impulses.

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "collide/error.hpp"
#include "collide/sim/observables.hpp"

using namespace collide;

TEST_CASE("max_overlap finds the deepest pair, across the seam of a periodic box") {
    const Box walls{1.0, 1.0, Boundary::walls};
    std::vector<Vec2> pos{{0.1, 0.5}, {0.25, 0.5}, {0.9, 0.9}};
    std::vector<double> r{0.1, 0.1, 0.05};
    CHECK(sim::max_overlap(pos, r, walls) == doctest::Approx(0.05));
    // across x = 0 / x = 1: centres 0.02 + 0.03 = 0.05 apart, radii sum 0.1
    const Box torus{1.0, 1.0, Boundary::periodic};
    std::vector<Vec2> seam{{0.02, 0.5}, {0.97, 0.5}};
    std::vector<double> rs{0.05, 0.05};
    CHECK(sim::max_overlap(seam, rs, torus) == doctest::Approx(0.05));
    CHECK(sim::max_overlap(seam, rs, walls) == 0.0);
    // unwrapped positions (classic engine) give the same answer
    std::vector<Vec2> unwrapped{{2.02, 0.5}, {-0.03, 0.5}};
    CHECK(sim::max_overlap(unwrapped, rs, torus) == doctest::Approx(0.05));
}

TEST_CASE("max_overlap sees a big disc overlapping small ones far from its centre cell") {
    const Box box{1.0, 1.0, Boundary::walls};
    std::vector<Vec2> pos;
    std::vector<double> r;
    for (int k = 0; k < 100; ++k) {
        pos.push_back({0.05 + 0.09 * (k % 10), 0.05 + 0.09 * (k / 10)});
        r.push_back(0.01);
    }
    pos.push_back({0.5, 0.5});
    r.push_back(0.2);
    CHECK(sim::big_radius_threshold(r) < 0.2);
    double expected = 0.0;
    for (int k = 0; k < 100; ++k)
        expected = std::max(expected, 0.21 - std::hypot(pos[k].x - 0.5, pos[k].y - 0.5));
    CHECK(sim::max_overlap(pos, r, box) == doctest::Approx(expected));
}

TEST_CASE("big_radius_threshold: none for equal or gently mixed radii, few big ones only") {
    CHECK(std::isinf(sim::big_radius_threshold({0.01, 0.01, 0.012, 0.01})));
    std::vector<double> many(100, 0.01);
    for (int k = 0; k < 50; ++k) many[k] = 0.1;  // half of them big: not "a few"
    CHECK(std::isinf(sim::big_radius_threshold(many)));
}

TEST_CASE("packing fraction and speed histogram") {
    const Box box{2.0, 1.0, Boundary::walls};
    CHECK(sim::packing_fraction({0.5}, box) == doctest::Approx(std::numbers::pi * 0.25 / 2.0));
    Snapshot s;
    for (double v : {0.1, 0.4, 0.6, 0.99, 1.0}) {
        DiscState d;
        d.velocity = {0.0, v};
        s.discs.push_back(d);
    }
    const auto h = sim::speed_histogram(s, 2, 1.0);
    REQUIRE(h.size() == 2);
    CHECK(h[0] == 2);
    CHECK(h[1] == 3);  // 1.0 == v_max goes to the last bin
    const auto auto_range = sim::speed_histogram(s, 4);
    CHECK(auto_range[3] == 2);
    CHECK_THROWS_AS((void)sim::speed_histogram(s, 0), Error);
}

TEST_CASE("fill_thermodynamics: temperature, virial Z and wall pressure") {
    Measurements m;
    m.t = 2.0;
    const std::vector<Vec2> v{{1.0, 0.0}, {0.0, -1.0}};
    const std::vector<double> mass{1.0, 3.0};
    const std::vector<double> r{0.1, 0.1};
    sim::ImpulseTally tally;
    tally.virial = 8.0;
    tally.wall_impulse = 16.0;
    sim::fill_thermodynamics(m, v, mass, r, Box{1.0, 1.0, Boundary::periodic}, tally);
    CHECK(m.kinetic_energy == doctest::Approx(2.0));
    CHECK(m.temperature == doctest::Approx(1.0));
    CHECK(m.momentum.y == doctest::Approx(-3.0));
    // Z = 1 + 8 / (2 * 2 * 1 * 2) = 2; P = Z N kT / A = 4
    CHECK(m.compressibility == doctest::Approx(2.0));
    CHECK(m.pressure == doctest::Approx(4.0));
    sim::fill_thermodynamics(m, v, mass, r, Box{1.0, 1.0, Boundary::walls}, tally);
    // P = 16 / (perimeter 4 * t 2) = 2; Z = P A / (N kT) = 1
    CHECK(m.pressure == doctest::Approx(2.0));
    CHECK(m.compressibility == doctest::Approx(1.0));
}
