// Scene validation: every rejection with its message, contacts accepted, and the O(N) grid
// agreeing with a brute-force pair check on random scenes.

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "../support/input_error.hpp"
#include "collide/error.hpp"
#include "collide/sim/scene_check.hpp"

using namespace collide;

namespace {

Disc disc(double x, double y, double r, double m = 1.0) {
    Disc d;
    d.position = {x, y};
    d.radius = r;
    d.mass = m;
    return d;
}

std::string validation_error(const Scene& scene, const SceneOrigin& origin = {}) {
    return test::input_error_message([&] { validate_scene(scene, origin); });
}

using collide::test::contains;

bool brute_force_overlap(const Scene& scene) {
    for (std::size_t i = 0; i < scene.discs.size(); ++i) {
        for (std::size_t j = i + 1; j < scene.discs.size(); ++j) {
            const Disc& a = scene.discs[i];
            const Disc& b = scene.discs[j];
            const double limit = (a.radius + b.radius) * (1.0 - contact_tolerance);
            if (norm2(scene.box.displacement(a.position, b.position)) < limit * limit) return true;
        }
    }
    return false;
}

}  // namespace

TEST_CASE("validation: a good scene passes, and measurements are right") {
    Scene s;
    s.discs = {disc(0.25, 0.25, 0.1, 2.0), disc(0.75, 0.75, 0.1)};
    s.discs[0].velocity = {1.0, 0.0};
    CHECK(validation_error(s).empty());
    CHECK(packing_fraction(s) == doctest::Approx(2.0 * M_PI * 0.01));
    CHECK(kinetic_energy(s) == doctest::Approx(1.0));
    CHECK(contains(scene_summary(s), "N = 2"));
    CHECK(contains(scene_summary(s), "walls"));
}

TEST_CASE("validation: bad values name the disc and the field") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    Scene s;
    s.discs = {disc(0.5, 0.5, 0.1)};
    s.discs[0].radius = 0.0;
    CHECK(contains(validation_error(s), "disc 1 radius: must be > 0 (got 0)"));
    s.discs[0].radius = -0.1;
    CHECK(contains(validation_error(s), "radius: must be > 0 (got -0.1)"));
    s.discs[0] = disc(0.5, 0.5, 0.1, 0.0);
    CHECK(contains(validation_error(s), "mass: must be > 0"));
    s.discs[0] = disc(0.5, 0.5, 0.1, inf);
    CHECK(contains(validation_error(s), "mass: not a finite number"));
    s.discs[0] = disc(0.5, nan, 0.1);
    CHECK(contains(validation_error(s), "position: not a finite number"));
    s.discs[0] = disc(0.5, 0.5, 0.1);
    s.discs[0].velocity = {inf, 0.0};
    CHECK(contains(validation_error(s), "velocity: not a finite number"));
    s.discs[0] = disc(0.5, 0.5, nan);
    CHECK(contains(validation_error(s), "radius: not a finite number"));
    s.discs[0] = disc(0.5, 0.5, 0.1);
    s.box.width = 0.0;
    CHECK(contains(validation_error(s), "box.width: must be a finite number > 0"));
    s.box.width = 1.0;
    s.box.height = nan;
    CHECK(contains(validation_error(s), "box.height"));
}

TEST_CASE("validation: magnitudes beyond what the collision formulas survive are refused") {
    Scene s;
    s.box = Box{1.0, 1.0, Boundary::periodic};
    const auto error_for = [&](const Disc& d) {
        s.discs = {d};
        return validation_error(s);
    };
    // 2 m_i m_j (dv . dr) at mass 1e200 overflows (a NaN velocity); at 1e-200 it underflows to 0
    // (no impulse: the discs would pass through each other).
    CHECK(contains(error_for(disc(0.5, 0.5, 0.1, 1e200)),
                   "disc 1 mass: 1e+200 is outside the range collide computes with ([1e-50, "
                   "1e+50])"));
    CHECK(contains(error_for(disc(0.5, 0.5, 0.1, 1e-200)), "disc 1 mass: 1e-200 is outside"));
    CHECK(contains(error_for(disc(0.5, 0.5, 1e-60)), "disc 1 radius: 1e-60 is outside"));
    Disc fast = disc(0.5, 0.5, 0.1);
    fast.velocity = {0.0, -1e308};
    CHECK(contains(error_for(fast),
                   "disc 1 velocity: -1e+308 is outside the range collide "
                   "computes with (at most 1e+50)"));
    Disc far = disc(0.5, 0.5, 0.1);
    far.position = {1e60, 0.5};
    CHECK(contains(error_for(far), "disc 1 position: 1e+60 is outside"));
    s.discs = {disc(0.5, 0.5, 0.1)};
    s.box.width = 1e60;
    CHECK(contains(validation_error(s), "box.width: 1e+60 is outside"));

    // The bounds themselves are accepted.
    s.box = Box{1e50, 1e50, Boundary::walls};
    Disc big = disc(5e49, 5e49, 1e49, max_scene_magnitude);
    big.velocity = {-max_scene_magnitude, max_scene_magnitude};
    s.discs = {big};
    CHECK_NOTHROW(validate_scene(s));
    s.box = Box{1.0, 1.0, Boundary::walls};
    s.discs = {disc(0.5, 0.5, min_scene_magnitude, min_scene_magnitude)};
    CHECK_NOTHROW(validate_scene(s));
}

TEST_CASE("validation: every disc outside a walled box is listed with its origin") {
    Scene s;
    s.discs = {disc(0.5, 0.5, 0.1), disc(0.95, 0.5, 0.1), disc(0.5, -0.2, 0.1)};
    SceneOrigin origin;
    origin.add({0, 3, "f.txt", {2, 3, 4}, 0, "disc"});
    const std::string msg = validation_error(s, origin);
    CHECK(contains(msg, "2 discs lie outside the box [0, 1] x [0, 1]"));
    CHECK(contains(msg,
                   "f.txt:3: disc 2: centre (0.95, 0.5), radius 0.1: right edge at x = 1.05 > 1"));
    CHECK(contains(msg, "f.txt:4: disc 3"));
    CHECK(!contains(msg, "f.txt:2:"));
    // a periodic box has no outside
    s.box.boundary = Boundary::periodic;
    s.discs = {disc(1.5, -0.5, 0.1)};
    CHECK(validation_error(s).empty());
}

TEST_CASE("validation: long lists of problems are cut short") {
    Scene s;
    for (int i = 0; i < 20; ++i) s.discs.push_back(disc(2.0 + i, 0.5, 0.1));
    const std::string msg = validation_error(s);
    CHECK(contains(msg, "20 discs lie outside"));
    CHECK(contains(msg, "and 15 more"));
}

TEST_CASE("validation: overlaps name the pair, contacts are fine") {
    Scene s;
    s.discs = {disc(0.2, 0.5, 0.1), disc(0.4, 0.5, 0.1), disc(0.59, 0.5, 0.1)};
    SceneOrigin origin;
    origin.add({0, 3, "g.txt", {5, 6, 7}, 0, "disc"});
    const std::string msg = validation_error(s, origin);
    CHECK(contains(msg, "g.txt:7: disc 3: overlaps g.txt:6: disc 2 at t = 0"));
    s.discs[2].position.x = 0.6;  // exactly touching: a contact, allowed
    CHECK(validation_error(s, origin).empty());
}

TEST_CASE("validation: overlaps across a periodic boundary are found") {
    Scene s;
    s.box.boundary = Boundary::periodic;
    s.discs = {disc(0.02, 0.5, 0.05), disc(0.95, 0.5, 0.05)};
    CHECK(contains(validation_error(s), "disc 2: overlaps disc 1"));
    s.discs[1].position.x = 0.90;
    CHECK(validation_error(s).empty());
}

TEST_CASE("validation: discs too large for a periodic box are refused") {
    Scene s;
    s.box.boundary = Boundary::periodic;
    s.discs = {disc(0.5, 0.5, 0.3)};
    CHECK(contains(validation_error(s), "too large for the periodic box"));
}

TEST_CASE("validation: a big disc among many small ones (one tracer) is checked against all") {
    Scene s;
    // small discs on a grid, away from the centre, then one big disc just clear of the nearest
    double nearest = 1.0;
    for (int i = 0; i < 40; ++i) {
        for (int j = 0; j < 40; ++j) {
            const double x = 0.0125 + 0.025 * i;
            const double y = 0.0125 + 0.025 * j;
            const double distance = std::hypot(x - 0.5, y - 0.5);
            if (distance < 0.25) continue;
            nearest = std::min(nearest, distance);
            s.discs.push_back(disc(x, y, 0.005));
        }
    }
    s.discs.push_back(disc(0.5, 0.5, nearest - 0.005 - 1e-6));
    CHECK(validation_error(s).empty());
    s.discs.back().radius = nearest - 0.005 + 1e-6;
    const std::string msg = validation_error(s);
    CHECK(contains(msg, "disc " + std::to_string(s.discs.size()) + ": overlaps"));
}

TEST_CASE("validation: the grid agrees with the brute-force pair check on random scenes") {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);  // test-only: portability not needed
    for (int trial = 0; trial < 60; ++trial) {
        Scene s;
        s.box.width = 1.0 + trial % 3;
        s.box.boundary = trial % 2 == 0 ? Boundary::walls : Boundary::periodic;
        const int n = 5 + trial;
        for (int i = 0; i < n; ++i) {
            const double r = 0.005 + 0.05 * u(rng) * u(rng);  // mostly small, a few big
            Disc d =
                disc(r + (s.box.width - 2 * r) * u(rng), r + (s.box.height - 2 * r) * u(rng), r);
            s.discs.push_back(d);
        }
        CAPTURE(trial);
        CHECK(brute_force_overlap(s) == !validation_error(s).empty());
    }
}
