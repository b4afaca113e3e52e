#pragma once
// Shared fixtures of the renderer tests: small deterministic snapshots and frame contents.

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "collide/render/renderer.hpp"
#include "collide/snapshot.hpp"

namespace collide::render::test {

/// `count` discs of radius `radius` on a jittered grid in a box, velocities from a fixed seed.
inline Snapshot gas_snapshot(std::size_t count, double radius, Box box, std::uint32_t seed,
                             double time = 0.0) {
    Snapshot s;
    s.time = time;
    s.box = box;
    std::mt19937 rng(seed);
    std::normal_distribution<double> velocity(0.0, 0.5);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(count))));
    for (std::size_t i = 0; i < count; ++i) {
        DiscState d;
        const double cx = (static_cast<double>(i % side) + 0.5 + jitter(rng)) / side;
        const double cy = (static_cast<double>(i / side) + 0.5 + jitter(rng)) / side;
        d.position = {cx * box.width, cy * box.height};
        d.velocity = {velocity(rng), velocity(rng)};
        d.radius = radius;
        d.mass = 1.0;
        d.color = {static_cast<std::uint8_t>(80 + (i * 37) % 170),
                   static_cast<std::uint8_t>(80 + (i * 91) % 170), 200};
        d.tagged = (i % 7 == 0);
        s.discs.push_back(d);
    }
    return s;
}

inline RenderConfig small_config(bool overlays) {
    RenderConfig config;
    config.width = 320;
    config.height = 180;
    config.overlays = overlays;
    return config;
}

}  // namespace collide::render::test
