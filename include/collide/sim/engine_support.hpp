#pragma once
/// \file
/// Bookkeeping shared by the event-driven engines: the scene's appearance (colours, tags) for
/// snapshots, the collision listener, wall-clock accounting, and argument checks.

#include <chrono>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "collide/error.hpp"
#include "collide/scene.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/event.hpp"

namespace collide::sim {

/// What a snapshot needs beyond positions and velocities, copied once from the scene.
struct Appearance {
    std::vector<Rgb8> colors;
    std::vector<std::uint8_t> tagged;  ///< 1 when the scene gave the disc a tag
    bool any_tagged = false;

    explicit Appearance(const Scene& scene) {
        colors.reserve(scene.discs.size());
        tagged.reserve(scene.discs.size());
        for (const Disc& d : scene.discs) {
            colors.push_back(d.color);
            tagged.push_back(d.tag.empty() ? 0 : 1);
            any_tagged = any_tagged || !d.tag.empty();
        }
    }

    /// Discs that enter the mean squared displacement: the tagged ones, or all when none is.
    [[nodiscard]] bool in_msd(std::size_t i) const noexcept {
        return !any_tagged || tagged[i] != 0;
    }

    [[nodiscard]] std::size_t bytes() const noexcept {
        return colors.capacity() * sizeof(Rgb8) + tagged.capacity();
    }
};

/// Checks a frame time given to Engine::advance_to. Throws Error(input) naming `until` when t is
/// not finite or lies before the engine's clock (time never runs backwards).
inline void require_forward(double now, double t) {
    if (!(t >= now)) {  // also false for NaN
        throw_input_error("", 0, "until",
                          "cannot advance to t = " + std::to_string(t) +
                              ": the simulation is at t = " + std::to_string(now) +
                              " and time never runs backwards");
    }
    if (t > std::numeric_limits<double>::max()) {
        throw_input_error("", 0, "until", "the end time must be finite");
    }
}

/// Accumulates wall-clock seconds spent inside an engine call (RAII over one call).
class WallClock {
  public:
    explicit WallClock(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
    ~WallClock() {
        total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    WallClock(const WallClock&) = delete;
    WallClock& operator=(const WallClock&) = delete;

  private:
    double& total_;
    std::chrono::steady_clock::time_point start_;
};

/// The record handed to listeners: pairs with a < b, walls with b = 0.
[[nodiscard]] inline CollisionRecord to_record(double t, EventKind kind, std::uint32_t a,
                                               std::uint32_t b) {
    CollisionRecord r;
    r.t = t;
    switch (kind) {
        case EventKind::xwall:
            r.kind = CollisionKind::xwall;
            r.a = a;
            break;
        case EventKind::ywall:
            r.kind = CollisionKind::ywall;
            r.a = a;
            break;
        default:
            r.kind = CollisionKind::pair;
            r.a = a < b ? a : b;
            r.b = a < b ? b : a;
            break;
    }
    return r;
}

}  // namespace collide::sim
