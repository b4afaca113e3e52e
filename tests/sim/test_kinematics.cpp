#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "collide/box.hpp"
#include "collide/box3.hpp"
#include "collide/sim/kinematics.hpp"

using namespace collide;
using kinematics::never;

TEST_CASE("time_to_wall: the lecture's formulas per axis") {
    // (1 - s - r)/v moving right, (s - r)/|v| moving left, never at rest
    CHECK(kinematics::time_to_wall(0.5, 0.1, 0.1, 1.0) == doctest::Approx(4.0));
    CHECK(kinematics::time_to_wall(0.5, -0.1, 0.1, 1.0) == doctest::Approx(4.0));
    CHECK(kinematics::time_to_wall(0.5, 0.0, 0.1, 1.0) == never);
    // any box width
    CHECK(kinematics::time_to_wall(1.0, 0.5, 0.25, 3.0) == doctest::Approx(3.5));
}

TEST_CASE("time_to_wall never returns a time in the past") {
    // already overlapping the right wall while moving into it: collide now, not at t < 0
    CHECK(kinematics::time_to_wall(0.95, 0.1, 0.1, 1.0) == 0.0);
    CHECK(kinematics::time_to_wall(0.05, -0.1, 0.1, 1.0) == 0.0);
    // overlapping but moving away: the far wall
    CHECK(kinematics::time_to_wall(0.05, 0.1, 0.1, 1.0) == doctest::Approx(8.5));
}

TEST_CASE("time_to_hit: head-on approach") {
    // two discs r = 0.1 at x = 0.2 and 0.8, closing speed 0.2: gap 0.4 closes at t = 2
    const Vec2 dr{0.6, 0.0};
    const Vec2 dv{-0.2, 0.0};
    CHECK(kinematics::time_to_hit(dr, dv, 0.2) == doctest::Approx(2.0));
}

TEST_CASE("time_to_hit: never when separating or missing") {
    CHECK(kinematics::time_to_hit({0.6, 0.0}, {0.2, 0.0}, 0.2) == never);   // dv.dr > 0
    CHECK(kinematics::time_to_hit({0.6, 0.0}, {0.0, 0.1}, 0.2) == never);   // dv.dr == 0
    CHECK(kinematics::time_to_hit({0.6, 0.5}, {-0.2, 0.0}, 0.2) == never);  // passes by: d < 0
}

TEST_CASE("time_to_hit: glancing contact matches the geometric solution") {
    // j starts at (1, 0.15) moving left at speed 1 towards i at the origin, sigma = 0.2:
    // contact when x^2 + 0.15^2 = 0.2^2, i.e. x = sqrt(0.0175), t = 1 - x
    const double t = kinematics::time_to_hit({1.0, 0.15}, {-1.0, 0.0}, 0.2);
    CHECK(t == doctest::Approx(1.0 - std::sqrt(0.0175)).epsilon(1e-14));
}

TEST_CASE("time_to_hit: overlapping and approaching pairs collide now") {
    CHECK(kinematics::time_to_hit({0.15, 0.0}, {-0.1, 0.0}, 0.2) == 0.0);
}

TEST_CASE("resolve_pair: equal masses head-on exchange velocities") {
    Vec2 vi{1.0, 0.0};
    Vec2 vj{-1.0, 0.0};
    kinematics::resolve_pair(vi, vj, 1.0, 1.0, {0.2, 0.0});
    CHECK(vi.x == doctest::Approx(-1.0));
    CHECK(vj.x == doctest::Approx(1.0));
}

TEST_CASE("resolve_pair: unequal masses conserve momentum and energy (analytic 1D result)") {
    // 1D elastic: v1' = (m1-m2)/(m1+m2) v1 + 2 m2/(m1+m2) v2
    const double m1 = 1.0, m2 = 3.0;
    Vec2 vi{2.0, 0.0};
    Vec2 vj{-1.0, 0.0};
    kinematics::resolve_pair(vi, vj, m1, m2, {0.3, 0.0});
    CHECK(vi.x == doctest::Approx((m1 - m2) / (m1 + m2) * 2.0 + 2 * m2 / (m1 + m2) * -1.0));
    CHECK(vj.x == doctest::Approx((m2 - m1) / (m1 + m2) * -1.0 + 2 * m1 / (m1 + m2) * 2.0));
}

TEST_CASE("resolve_pair: glancing collision only changes the normal components") {
    Vec2 vi{0.0, 0.0};
    Vec2 vj{-1.0, 0.0};
    const Vec2 dr{std::sqrt(0.02), std::sqrt(0.02)};  // contact normal at 45 degrees
    kinematics::resolve_pair(vi, vj, 1.0, 1.0, dr);
    // equal masses: i takes j's normal component (-0.5, -0.5), j keeps the tangential one
    CHECK(vi.x == doctest::Approx(-0.5));
    CHECK(vi.y == doctest::Approx(-0.5));
    CHECK(vj.x == doctest::Approx(-0.5));
    CHECK(vj.y == doctest::Approx(0.5));
}

TEST_CASE("resolve_pair: a very heavy disc (algs4 diffusion wall) acts as a wall") {
    Vec2 vi{0.0, 0.0};
    Vec2 vj{-1.0, 0.0};
    kinematics::resolve_pair(vi, vj, 1e5, 1.0, {0.04, 0.0});
    CHECK(vj.x == doctest::Approx(1.0).epsilon(1e-4));
    CHECK(vi.x == doctest::Approx(-2e-5).epsilon(1e-3));
}

TEST_CASE("Box: periodic wrap and minimum image") {
    const Box box{2.0, 1.0, Boundary::periodic};
    const Vec2 w = box.wrap({-0.5, 1.25});
    CHECK(w.x == doctest::Approx(1.5));
    CHECK(w.y == doctest::Approx(0.25));
    const Vec2 d = box.displacement({0.1, 0.1}, {1.9, 0.9});
    CHECK(d.x == doctest::Approx(-0.2));
    CHECK(d.y == doctest::Approx(-0.2));
    CHECK(box.contains({-5.0, 7.0}, 0.1));
    const Box walls{2.0, 1.0, Boundary::walls};
    CHECK(walls.contains({1.0, 0.5}, 0.5));
    CHECK_FALSE(walls.contains({1.0, 0.5}, 0.51));
}

TEST_CASE("round_near_zero: the same doubles as std::round, signed zeros included") {
    // Every quotient a minimum image can meet: the shortcut's range (|q| < 1.5), its edges,
    // and beyond it, where it hands over to std::round.
    std::vector<double> qs{0.0,    -0.0,   0.49999999999999994,
                           0.5,    -0.5,   1.4999999999999998,
                           1.5,    -1.5,   2.5,
                           -2.5,   1e300,  -1e300,
                           1e-300, -1e-300};
    for (int k = -4000; k <= 4000; ++k) qs.push_back(k / 1000.0);
    for (const double q : qs) {
        CAPTURE(q);
        const double expected = std::round(q);
        CHECK(round_near_zero(q) == expected);
        CHECK(std::signbit(round_near_zero(q)) == std::signbit(expected));
    }
    CHECK(round_near_zero(std::numeric_limits<double>::infinity()) ==
          std::numeric_limits<double>::infinity());
}

TEST_CASE("Box3: minimum image in every axis") {
    const Box3 box{2.0, 1.0, 4.0, Boundary::periodic};
    const Vec3 d = box.displacement({0.1, 0.1, 3.9}, {1.9, 0.9, 0.1});
    CHECK(d.x == doctest::Approx(-0.2));
    CHECK(d.y == doctest::Approx(-0.2));
    CHECK(d.z == doctest::Approx(0.2));
    const Box3 walls{2.0, 1.0, 4.0, Boundary::walls};
    CHECK(walls.displacement({0.1, 0.1, 3.9}, {1.9, 0.9, 0.1}).z == doctest::Approx(-3.8));
}
