#pragma once
// Two engines (classic and fast, 2D or 3D) agree event by event: the same collisions in the same
// order, the same particles, at times within a tolerance.

#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "collide/sim/engine.hpp"

namespace collide::test {

/// Requires x and y to hold the same collisions (kind, both particles) in the same order, each
/// at times at most `time_tolerance` apart.
inline void require_same_events(const std::vector<CollisionRecord>& x,
                                const std::vector<CollisionRecord>& y, double time_tolerance) {
    REQUIRE(x.size() == y.size());
    for (std::size_t k = 0; k < x.size(); ++k) {
        INFO("collision #" << k << " at t = " << x[k].t);
        REQUIRE(x[k].kind == y[k].kind);
        REQUIRE(x[k].a == y[k].a);
        REQUIRE(x[k].b == y[k].b);  // walls: both the record's default
        REQUIRE(std::abs(x[k].t - y[k].t) <= time_tolerance);
    }
}

}  // namespace collide::test
