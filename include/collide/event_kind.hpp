#pragma once
/// \file
/// What an event-driven engine's event does: one enumeration for the engines' queues
/// (sim::Event, the fast engine's keys) and for the picture of a queue the renderer draws
/// (QueuedEvent in snapshot.hpp). A resolved collision has its own, narrower kind (CollisionKind,
/// collide/sim/engine.hpp): a cell crossing is queued like a collision but is never one.

#include <cstdint>

namespace collide {

/// The order of the enumerators is the tie-break order at equal times; the values are packed
/// into the fast engine's keys.
enum class EventKind : std::uint8_t {
    pair = 0,   ///< two discs touch (a and b)
    xwall = 1,  ///< a disc touches the left or right wall
    ywall = 2,  ///< a disc touches the bottom or top wall
    zwall = 3,  ///< 3D only: a sphere touches the front or back wall
    cell = 4,   ///< fast engine only: a centre leaves its grid cell (bookkeeping, no collision;
                ///< in the engine b = axis, 0 x / 1 y / 2 z)
};

}  // namespace collide
