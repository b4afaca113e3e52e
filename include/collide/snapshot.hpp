#pragma once
/// \file
/// What an engine hands to the renderer at a frame time: every disc's state at exactly `time`,
/// plus the time-driven method's failure markers. The renderer sees nothing else of the engines.

#include <cstdint>
#include <utility>
#include <vector>

#include "collide/box.hpp"
#include "collide/disc.hpp"
#include "collide/vec2.hpp"

namespace collide {

struct DiscState {
    Vec2 position;  ///< at `Snapshot::time`; wrapped into the box for periodic boundaries
    Vec2 velocity;
    double radius = 0.0;
    double mass = 0.0;
    Rgb8 color;
    bool tagged = false;   ///< the scene gave it a tag (trails are drawn for tagged discs)
    bool escaped = false;  ///< time-driven only: entirely outside a walled box (tunnelled out)
};

struct Snapshot {
    double time = 0.0;  ///< simulation time of this state
    Box box;
    std::vector<DiscState> discs;  ///< same order as the scene's discs
    /// Time-driven failure markers (empty for the event-driven engines).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> overlapping_pairs;
    std::vector<Vec2> missed_collisions;  ///< where a collision went undetected since last frame
};

}  // namespace collide
