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

/// How far (relative to its radius) a disc may move between two of its collisions for both to count
/// as one instant in the jam bound below. Not exact time equality: discs "touching" in a scene
/// file are usually a rounding error apart (positions such as 1/6 + 1/3), so a wedged disc's
/// collisions come 1e-17 apart, time creeps on, and it would take 10^16 of them to reach t = 1.
/// The scene check calls discs within contact_tolerance (1e-9) of each other touching; the same
/// fraction of the radius here.
inline constexpr double same_instant_travel = 1e-9;

/// True when a disc of radius r, moving at v for dt since its previous event, is still at that
/// event's instant (it moved less than same_instant_travel r).
[[nodiscard]] inline bool same_instant(double dt, Vec2 v, double r) noexcept {
    const double reach = same_instant_travel * r;
    return dt * dt * norm2(v) <= reach * reach;
}

/// Collisions one disc may take part in at a single instant before an event-driven engine calls
/// it jammed. Why a bound: a disc that cannot move along an axis (as wide as the box, or wedged
/// wall to wall in a straight row of touching discs) but has a velocity along it collides again
/// and again at the same time, forever. validate_scene refuses the straight rows it can see; this
/// catches whatever it cannot. Cascades through touching discs end below it, though no bound can
/// separate them from a jam for every choice of masses: in a touching row of N equal discs each
/// takes part in at most N - 1 collisions at one instant (a row of 1000 with masses from 0.1 to 10:
/// at most 5124), and the cascade of Galperin's billiard (a light disc between a heavy one and a
/// wall) needs about pi sqrt(M / m), so 1000 + 16 N allows mass ratios up to about 10^5 at any N.
/// A jam is caught after about 1000 + 16 N collisions of each disc it holds.
[[nodiscard]] inline std::uint64_t instant_collision_limit(std::size_t discs) noexcept {
    return 1000 + 16 * static_cast<std::uint64_t>(discs);
}

/// Throws Error(input) for disc `disc` (0-based, named 1-based as in validation messages), found
/// jammed at time t by the bound above.
[[noreturn]] inline void throw_jammed(std::size_t disc, double t, std::uint64_t limit) {
    throw_input_error("", 0, "disc " + std::to_string(disc + 1),
                      "jammed at t = " + std::to_string(t) + ": more than " +
                          std::to_string(limit) +
                          " collisions at one instant (it moved less than 1e-9 of its radius "
                          "between them). A disc that cannot move (as wide as the box, or wedged "
                          "wall to wall between touching discs) but has a velocity along the "
                          "blocked axis collides forever; leave a gap, or give those discs no "
                          "velocity along that axis");
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
