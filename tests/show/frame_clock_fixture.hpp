#pragma once
// A video's frame clock for the show tests: `frames` frames, `interval` simulation time apart,
// from time 0.

#include <cstdint>

#include "collide/show/collision.hpp"

namespace collide::test {

inline show::FrameClock clock_of(std::int64_t frames, double interval) {
    show::FrameClock clock;
    clock.interval = interval;
    clock.count = frames;
    clock.last_time = static_cast<double>(frames - 1) * interval;
    return clock;
}

}  // namespace collide::test
