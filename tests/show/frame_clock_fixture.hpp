#pragma once
// A video's frame clock for the show tests: `frames` frames, `interval` simulation time apart,
// from time 0.

#include <cstdint>

#include "collide/show/collision.hpp"
#include "collide/show/questions.hpp"

namespace collide::test {

inline show::FrameClock clock_of(std::int64_t frames, double interval) {
    show::FrameClock clock;
    clock.interval = interval;
    clock.count = frames;
    clock.last_time = static_cast<double>(frames - 1) * interval;
    return clock;
}

/// The times of the frames after frame `k`, as a question asked there looks ahead.
inline show::FramesAfter after_frame(const show::FrameClock& clock, std::int64_t k) {
    return [clock, k](std::int64_t i) { return clock.time(k + i); };
}

}  // namespace collide::test
