#pragma once
/// \file
/// The bookkeeping every engine shares (classic, fast and time-driven): the time guard and the
/// wall clock of advance_to, the counters, the collision listener, the scene's appearance for
/// snapshots, and the assembly of Measurements. One copy, so that the engines count, report and
/// fail the same way and the side-by-side panels compare figure for figure.

#include <chrono>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "collide/scene.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/event.hpp"
#include "collide/sim/measurements.hpp"
#include "collide/sim/observables.hpp"
#include "collide/snapshot.hpp"

namespace collide::sim {

/// What a snapshot needs beyond positions and velocities, copied once from the scene.
struct Appearance {
    std::vector<Rgb8> colors;
    std::vector<std::uint8_t> tagged;  ///< 1 when the scene gave the disc a tag
    bool any_tagged = false;

    explicit Appearance(const Scene& scene);

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
void require_forward(double now, double t);

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
                                               std::uint32_t b) noexcept {
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

/// What every engine counts as it runs.
struct EngineCounters {
    std::uint64_t collisions_pair = 0;
    std::uint64_t collisions_xwall = 0;
    std::uint64_t collisions_ywall = 0;
    std::uint64_t cell_crossings = 0;  ///< fast engine only
    std::uint64_t predictions = 0;     ///< collision-time computations (pair + wall)
    QueueStats queue;                  ///< event-driven engines only
    ImpulseTally impulses;             ///< for pressure
    double wall_seconds = 0.0;         ///< inside advance_to
};

/// The shared part of an engine, held as a member by each: see the file comment.
class EngineCore {
  public:
    /// Copies the scene's box and appearance: O(N).
    explicit EngineCore(const Scene& scene);

    /// For the first line of advance_to(t) at engine time `now`: the time guard (require_forward:
    /// Error(input) unless now <= t < inf), then a clock that adds the call's wall time to the
    /// counters when it goes out of scope.
    [[nodiscard]] WallClock start_advance(double now, double t) {
        require_forward(now, t);
        return WallClock(counters_.wall_seconds);
    }

    [[nodiscard]] EngineCounters& counters() noexcept { return counters_; }
    [[nodiscard]] const EngineCounters& counters() const noexcept { return counters_; }

    void set_listener(CollisionListener listener) { listener_ = std::move(listener); }

    /// Counts a resolved collision by its kind and hands it to the listener, if any.
    void collided(const CollisionRecord& record) {
        switch (record.kind) {
            case CollisionKind::pair:
                ++counters_.collisions_pair;
                break;
            case CollisionKind::xwall:
                ++counters_.collisions_xwall;
                break;
            case CollisionKind::ywall:
                ++counters_.collisions_ywall;
                break;
        }
        if (listener_) listener_(record);
    }

    /// A snapshot at time t in scene order, with each disc's colour and tag filled in; the engine
    /// then sets each disc's motion with set_motion.
    [[nodiscard]] Snapshot start_snapshot(double t) const;

    /// A snapshot disc's position (within the box: periodic engines wrap it first), velocity,
    /// radius and mass.
    static void set_motion(DiscState& d, Vec2 position, Vec2 velocity, double radius,
                           double mass) noexcept {
        d.position = position;
        d.velocity = velocity;
        d.radius = radius;
        d.mass = mass;
    }

    /// The measurements every engine reports the same way, at time t: the counters, the queue,
    /// the thermodynamics from the discs' velocities, masses and radii (any order, the same for
    /// the three), and the cost (wall time, rate, `engine_bytes`). The engine adds what only it
    /// knows (max_overlap, msd, the time-driven figures).
    [[nodiscard]] Measurements measurements(double t, const std::vector<Vec2>& velocities,
                                            const std::vector<double>& masses,
                                            const std::vector<double>& radii,
                                            std::uint64_t engine_bytes) const;

    /// Mean squared displacement over the discs of Appearance::in_msd: `of(i)` returns disc i's
    /// scene index and its displacement since t = 0, for i in 0 .. n-1 (summed in that order).
    template <class DisplacementOf>
    [[nodiscard]] double mean_squared_displacement(std::size_t n, DisplacementOf&& of) const {
        double sum = 0.0;
        std::size_t counted = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const auto [scene_index, displacement] = of(i);
            if (!appearance_.in_msd(scene_index)) continue;
            sum += norm2(displacement);
            ++counted;
        }
        return counted > 0 ? sum / static_cast<double>(counted) : 0.0;
    }

    /// Heap memory held by the core (the appearance), bytes.
    [[nodiscard]] std::size_t bytes() const noexcept { return appearance_.bytes(); }

  private:
    Box box_;
    Appearance appearance_;
    EngineCounters counters_;
    CollisionListener listener_;
};

}  // namespace collide::sim
