// Generators: determinism, reached packing fraction, velocities, avoidance, impossible requests.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "../support/input_error.hpp"
#include "collide/error.hpp"
#include "collide/sim/generate.hpp"
#include "collide/sim/scene_check.hpp"

using namespace collide;

namespace {

Scene make_box(Boundary boundary, double width = 1.0, double height = 1.0) {
    Scene s;
    s.box = {width, height, boundary};
    return s;
}

std::string generate_error(Scene scene, const GenerateSpec& spec) {
    return test::input_error_message([&] { generate_discs(scene, spec); });
}

using collide::test::contains;

Vec2 momentum(const Scene& s) {
    Vec2 p{};
    for (const Disc& d : s.discs) p += d.mass * d.velocity;
    return p;
}

}  // namespace

TEST_CASE("generate: same seed, same scene, another seed, another scene") {
    for (double eta : {0.3, 0.7}) {
        GenerateSpec g;
        g.packing_fraction = eta;
        g.radius = 0.02;
        g.seed = 7;
        Scene a = make_box(Boundary::walls);
        Scene b = make_box(Boundary::walls);
        generate_discs(a, g);
        generate_discs(b, g);
        REQUIRE(a.discs.size() == b.discs.size());
        bool same = true;
        for (std::size_t i = 0; i < a.discs.size(); ++i) {
            same = same && a.discs[i].position == b.discs[i].position &&
                   a.discs[i].velocity == b.discs[i].velocity;
        }
        CHECK(same);
        g.seed = 8;
        Scene c = make_box(Boundary::walls);
        generate_discs(c, g);
        CHECK(c.discs[0].position != a.discs[0].position);
    }
}

TEST_CASE("generate: positions are pinned for a seed (the same on every standard library)") {
    // Random placement uses only mt19937_64 and our own uniform mapping: no libm, no std
    // distributions, so these bits are the same everywhere.
    GenerateSpec g;
    g.count = 3;
    g.radius = 0.01;
    g.seed = 42;
    Scene s = make_box(Boundary::walls);
    generate_discs(s, g);
    std::mt19937_64 reference(42);
    const double u1 = static_cast<double>(reference() >> 11) * 0x1.0p-53;
    const double u2 = static_cast<double>(reference() >> 11) * 0x1.0p-53;
    const Vec2 first_placed{0.01 + 0.98 * u1, 0.01 + 0.98 * u2};
    // the block is then sorted in space: the first disc placed is somewhere in it
    CHECK(std::any_of(s.discs.begin(), s.discs.end(),
                      [&](const Disc& d) { return d.position == first_placed; }));
}

TEST_CASE(
    "generate: the requested packing fraction is reached, random and lattice, walls and periodic") {
    for (Boundary boundary : {Boundary::walls, Boundary::periodic}) {
        for (double eta : {0.2, 0.45, 0.5, 0.7, 0.85}) {
            CAPTURE(eta);
            CAPTURE(static_cast<int>(boundary));
            Scene s = make_box(boundary);
            GenerateSpec g;
            g.packing_fraction = eta;
            g.radius = 0.01;
            generate_discs(s, g);
            const double expected_n = std::round(eta / (std::numbers::pi * 0.01 * 0.01));
            CHECK(static_cast<double>(s.discs.size()) == expected_n);
            CHECK(packing_fraction(s) == doctest::Approx(eta).epsilon(1e-3));
            CHECK_NOTHROW(validate_scene(s));
        }
    }
}

TEST_CASE("generate: Maxwell-Boltzmann velocities at exactly kT, zero total momentum") {
    Scene s = make_box(Boundary::periodic);
    GenerateSpec g;
    g.count = 2000;
    g.radius = 0.004;
    g.mass = 2.0;
    g.temperature = 1.5;
    generate_discs(s, g);
    const double kT = kinetic_energy(s) / static_cast<double>(s.discs.size());
    CHECK(kT == doctest::Approx(1.5));
    CHECK(std::abs(momentum(s).x) < 1e-9);
    CHECK(std::abs(momentum(s).y) < 1e-9);
    // Gaussian components: the fraction within one sigma is about 68 %
    const double sigma = std::sqrt(1.5 / 2.0);
    int inside = 0;
    for (const Disc& d : s.discs) inside += std::abs(d.velocity.x) < sigma ? 1 : 0;
    CHECK(inside / 2000.0 == doctest::Approx(0.683).epsilon(0.05));
}

TEST_CASE("generate: speed = v gives every disc the same speed and zero momentum") {
    Scene s = make_box(Boundary::walls);
    GenerateSpec g;
    g.count = 100;
    g.radius = 0.01;
    g.speed = 0.3;
    generate_discs(s, g);
    for (const Disc& d : s.discs) CHECK(norm(d.velocity) == doctest::Approx(0.3));
    CHECK(std::abs(momentum(s).x) < 1e-12);
    CHECK(std::abs(momentum(s).y) < 1e-12);
}

TEST_CASE("generate: discs stay in their region and avoid what is already there") {
    Scene s = make_box(Boundary::walls, 2.0, 1.0);
    Disc big;
    big.position = {0.5, 0.5};
    big.radius = 0.2;
    s.discs.push_back(big);
    for (double eta : {0.3, 0.7}) {
        GenerateSpec g;
        g.packing_fraction = eta;
        g.radius = 0.01;
        g.region_min = {0.0, 0.0};
        g.region_max = Vec2{1.0, 1.0};
        g.tag = "left";
        Scene t = s;
        generate_discs(t, g);
        CHECK_NOTHROW(validate_scene(t));
        CHECK(t.discs.size() ==
              1 + static_cast<std::size_t>(std::round(eta / (std::numbers::pi * 1e-4))));
        for (std::size_t i = 1; i < t.discs.size(); ++i) {
            const Disc& d = t.discs[i];
            CHECK(d.position.x + d.radius <= 1.0);
            CHECK(d.tag == "left");
        }
    }
}

TEST_CASE("generate: impossible or malformed requests are refused, naming the field") {
    Scene s = make_box(Boundary::walls);
    GenerateSpec g;
    g.packing_fraction = 0.9;
    CHECK(
        contains(generate_error(s, g), "generate.packing_fraction: 0.9 is above the maximum 0.85"));
    g.packing_fraction = 0.0;
    CHECK(contains(generate_error(s, g), "generate.count: give count > 0 or packing_fraction > 0"));
    g.count = 10;
    g.packing_fraction = 0.3;
    CHECK(contains(generate_error(s, g), "not both"));
    g.packing_fraction = 0.0;
    g.radius = -1.0;
    CHECK(contains(generate_error(s, g), "generate.radius: must be a finite number > 0"));
    g.radius = 0.01;
    g.mass = 0.0;
    CHECK(contains(generate_error(s, g), "generate.mass"));
    g.mass = 1.0;
    g.temperature = -1.0;
    CHECK(contains(generate_error(s, g), "generate.temperature"));
    g.temperature = 1.0;
    g.count = 3000;  // eta = 0.94
    CHECK(contains(generate_error(s, g),
                   "generate.count: 3000 discs of radius 0.01 give packing fraction"));
    g.count = 10;
    g.region_max = Vec2{1.5, 1.0};
    CHECK(contains(generate_error(s, g),
                   "generate.region: [[0, 0], [1.5, 1]] extends outside the box"));
    g.region_max = Vec2{0.0, 1.0};
    CHECK(contains(generate_error(s, g), "generate.region"));
    // below 0.85 of the region, but the walls leave no room for a lattice of this many
    GenerateSpec tight;
    tight.radius = 0.05;
    tight.packing_fraction = 0.85;
    CHECK(contains(generate_error(s, tight), "cannot place 108 discs of radius 0.05"));
}

TEST_CASE("generate: a second block fills around the first at lattice density") {
    Scene s = make_box(Boundary::periodic);
    GenerateSpec first;
    first.count = 50;
    first.radius = 0.03;
    first.seed = 1;
    generate_discs(s, first);
    GenerateSpec second;
    second.packing_fraction = 0.5;
    second.radius = 0.005;
    second.seed = 2;
    generate_discs(s, second);
    CHECK_NOTHROW(validate_scene(s));
    CHECK(s.discs.size() > 50 + 5000);
}
