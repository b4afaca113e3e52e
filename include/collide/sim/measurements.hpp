#pragma once
/// \file
/// What an engine reports about its run: physics observables and algorithmic cost. One struct for
/// every engine so that the side-by-side panels compare figure for figure and `collide simulate
/// --json` prints the same keys whatever the engine (fields an engine does not measure stay 0).

#include <cstdint>

#include "collide/vec2.hpp"

namespace collide {

/// Priority-queue traffic of an event-driven engine.
struct QueueStats {
    std::uint64_t pushes = 0;
    std::uint64_t pops = 0;
    std::uint64_t stale_pops = 0;  ///< popped events invalidated since they were predicted
    /// Entries re-ordered or removed in place (the fast engine's indexed heap changes a disc's
    /// key instead of pushing a new event): a sift of log N steps each, like a push or a pop.
    std::uint64_t updates = 0;
    std::uint64_t max_size = 0;  ///< largest number of entries held at once
};

struct Measurements {
    // --- time and counts
    double t = 0.0;                      ///< simulation time
    std::uint64_t events = 0;            ///< events processed (collisions + engine-internal events)
    std::uint64_t collisions_pair = 0;   ///< disc-disc collisions resolved
    std::uint64_t collisions_wall = 0;   ///< disc-wall collisions resolved (x and y walls)
    std::uint64_t predictions = 0;       ///< collision-time computations (pair + wall)
    std::uint64_t collisions_xwall = 0;  ///< of collisions_wall: left/right walls
    std::uint64_t collisions_ywall = 0;  ///< of collisions_wall: bottom/top walls
    std::uint64_t collisions_zwall = 0;  ///< of collisions_wall: front/back walls (3D only)
    std::uint64_t cell_crossings = 0;    ///< fast engine: cell-crossing events (part of `events`)
    std::uint64_t list_rebuilds = 0;     ///< fast engine, 3D: neighbour-list rebuilds (`events`)
    QueueStats queue;

    // --- physics (k_B = 1)
    double kinetic_energy = 0.0;    ///< sum of m v^2 / 2
    Vec2 momentum;                  ///< sum of m v (x and y)
    double momentum_z = 0.0;        ///< 3D only: z component of the sum of m v
    double temperature = 0.0;       ///< kT = KE / N (two degrees of freedom per disc)
    double pressure = 0.0;          ///< virial (periodic) or wall impulse per length per time
    double compressibility = 0.0;   ///< Z = P A / (N k T)
    double packing_fraction = 0.0;  ///< sum of pi r^2 / A
    double max_overlap = 0.0;       ///< deepest current overlap between two discs (length units)
    double msd = 0.0;               ///< mean squared displacement of tagged discs (all if none)

    // --- cost
    double wall_seconds = 0.0;           ///< wall-clock time spent inside the engine
    double collisions_per_second = 0.0;  ///< (pair + wall collisions) / wall_seconds
    std::uint64_t engine_bytes = 0;      ///< heap memory held by the engine's containers (capacity)

    // --- time-driven comparison figures
    std::uint64_t overlap_checks = 0;     ///< pair overlap tests performed
    std::uint64_t missed_collisions = 0;  ///< contacts inside a step that went undetected
    std::uint64_t escaped = 0;            ///< discs entirely outside a walled box (tunnelled)
    /// Discs that tunnelled: went through a wall (escaped) or through a barrier (a missed
    /// collision with an immovable disc, immovable_mass_ratio) at least once.
    std::uint64_t tunnelled = 0;
    std::uint64_t overlapping_pairs = 0;  ///< pairs overlapping now
    /// Discs found overlapping another after any advance (each frame of a video) since t = 0,
    /// each counted once: the overlaps a viewer saw, also after they ended.
    std::uint64_t discs_overlapped = 0;
    double energy_drift = 0.0;           ///< (KE - KE0) / KE0
    std::uint64_t steps = 0;             ///< time quanta taken: the state is at steps * dt
    double max_overlap_seen = 0.0;       ///< deepest overlap any check found before rollback
    double seconds_per_time_unit = 0.0;  ///< wall_seconds / t: cost of one simulated time unit
};

}  // namespace collide
