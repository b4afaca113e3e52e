#pragma once
/// \file
/// The bookkeeping every engine shares (classic, fast and time-driven): the time guard and the
/// wall clock of advance_to, the counters, the collision listener, the scene's appearance for
/// snapshots, and the assembly of Measurements. One copy, so that the engines count, report and
/// fail the same way and the side-by-side panels compare figure for figure.

#include <chrono>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "collide/scene.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/event.hpp"
#include "collide/sim/measurements.hpp"
#include "collide/sim/observables.hpp"
#include "collide/snapshot.hpp"
#include "collide/snapshot3.hpp"
#include "collide/space.hpp"

namespace collide::sim {

/// What a snapshot needs beyond positions and velocities, copied once from the scene.
struct Appearance {
    std::vector<Rgb8> colors;
    std::vector<std::uint8_t> tagged;  ///< 1 when the scene gave the disc a tag
    bool any_tagged = false;

    explicit Appearance(const Scene& scene) : Appearance(scene.discs) {}
    explicit Appearance(const SphereScene& scene) : Appearance(scene.spheres) {}
    /// From the scene's discs or spheres (anything with `color` and `tag`).
    template <class Particle>
    explicit Appearance(const std::vector<Particle>& particles) {
        colors.reserve(particles.size());
        tagged.reserve(particles.size());
        for (const Particle& p : particles) {
            colors.push_back(p.color);
            tagged.push_back(p.tag.empty() ? 0 : 1);
            any_tagged = any_tagged || !p.tag.empty();
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
        case EventKind::zwall:
            r.kind = CollisionKind::zwall;
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
    std::uint64_t collisions_zwall = 0;  ///< 3D only
    std::uint64_t cell_crossings = 0;    ///< fast engine only
    std::uint64_t list_rebuilds = 0;     ///< fast engine with neighbour lists (3D) only
    std::uint64_t predictions = 0;       ///< collision-time computations (pair + wall)
    QueueStats queue;                    ///< event-driven engines only
    ImpulseTally impulses;               ///< for pressure
    double wall_seconds = 0.0;           ///< inside advance_to
};

/// The snapshot type of dimension D (2: Snapshot of discs, 3: SphereSnapshot).
template <int D>
using SnapshotOf = std::conditional_t<D == 2, Snapshot, SphereSnapshot>;

/// The shared part of an engine, held as a member by each: see the file comment. Generic over
/// the dimension (EngineCore: discs; BasicEngineCore<3>: spheres).
template <int D>
class BasicEngineCore {
  public:
    using Space = collide::Space<D>;
    using Vec = typename Space::Vec;
    using BoxType = typename Space::Box;

    /// Copies the scene's box and appearance: O(N).
    explicit BasicEngineCore(const typename Space::Scene& scene)
        : box_(scene.box), appearance_(scene) {}

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
            case CollisionKind::zwall:
                ++counters_.collisions_zwall;
                break;
        }
        if (listener_) listener_(record);
    }

    /// A snapshot at time t in scene order, with each particle's colour and tag filled in; the
    /// engine then sets each one's motion with set_motion.
    [[nodiscard]] SnapshotOf<D> start_snapshot(double t) const {
        SnapshotOf<D> s;
        s.time = t;
        s.box = box_;
        auto& items = particles_of(s);
        items.resize(appearance_.colors.size());
        for (std::size_t k = 0; k < items.size(); ++k) {
            items[k].color = appearance_.colors[k];
            items[k].tagged = appearance_.tagged[k] != 0;
        }
        return s;
    }

    /// A snapshot particle's position (within the box: periodic engines wrap it first), velocity,
    /// radius and mass.
    template <class State>
    static void set_motion(State& d, Vec position, Vec velocity, double radius,
                           double mass) noexcept {
        d.position = position;
        d.velocity = velocity;
        d.radius = radius;
        d.mass = mass;
    }

    /// The measurements every engine reports the same way, at time t: the counters, the queue,
    /// the thermodynamics from the particles' velocities, masses and radii (any order, the same
    /// for every engine), and the cost (wall time, rate, `engine_bytes`). The engine adds what
    /// only it knows (max_overlap, msd, the time-driven figures).
    [[nodiscard]] Measurements measurements(double t, const std::vector<Vec>& velocities,
                                            const std::vector<double>& masses,
                                            const std::vector<double>& radii,
                                            std::uint64_t engine_bytes) const {
        const EngineCounters& c = counters_;
        Measurements m;
        m.t = t;
        m.collisions_pair = c.collisions_pair;
        m.collisions_xwall = c.collisions_xwall;
        m.collisions_ywall = c.collisions_ywall;
        m.collisions_zwall = c.collisions_zwall;
        m.collisions_wall = c.collisions_xwall + c.collisions_ywall + c.collisions_zwall;
        m.cell_crossings = c.cell_crossings;
        m.list_rebuilds = c.list_rebuilds;
        m.events = m.collisions_pair + m.collisions_wall + m.cell_crossings + m.list_rebuilds;
        m.predictions = c.predictions;
        m.queue = c.queue;
        fill_thermodynamics<D>(m, velocities, masses, radii, box_, c.impulses);
        m.wall_seconds = c.wall_seconds;
        if (c.wall_seconds > 0.0) {
            m.collisions_per_second =
                static_cast<double>(m.collisions_pair + m.collisions_wall) / c.wall_seconds;
        }
        m.engine_bytes = engine_bytes;
        return m;
    }

    /// Mean squared displacement over the particles of Appearance::in_msd: `of(i)` returns
    /// particle i's scene index and its displacement since t = 0, for i in 0 .. n-1 (summed in
    /// that order).
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
    static auto& particles_of(Snapshot& s) noexcept { return s.discs; }
    static auto& particles_of(SphereSnapshot& s) noexcept { return s.spheres; }

    BoxType box_;
    Appearance appearance_;
    EngineCounters counters_;
    CollisionListener listener_;
};

using EngineCore = BasicEngineCore<2>;

}  // namespace collide::sim
