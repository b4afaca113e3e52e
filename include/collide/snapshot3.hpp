#pragma once
/// \file
/// A 3D engine's state at a time: every sphere, in scene order (SphereEngine::snapshot). The 3D
/// counterpart of Snapshot, for measurements and tests until spheres are rendered.

#include <cstdint>
#include <utility>
#include <vector>

#include "collide/box3.hpp"
#include "collide/disc.hpp"
#include "collide/vec3.hpp"

namespace collide {

struct SphereState {
    Vec3 position;  ///< at SphereSnapshot::time; wrapped into the box for periodic boundaries
    Vec3 velocity;
    double radius = 0.0;
    double mass = 0.0;
    Rgb8 color;
    bool tagged = false;
    bool escaped = false;    ///< time-driven only: entirely outside a walled box (tunnelled out)
    bool tunnelled = false;  ///< time-driven only: went through a barrier (as DiscState)
};

struct SphereSnapshot {
    double time = 0.0;
    Box3 box;
    std::vector<SphereState> spheres;  ///< same order as the scene's spheres
    // Time-driven engine only: what it got wrong (see Snapshot).
    /// Pairs (i < j) overlapping now by more than the contact slack.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> overlapping_pairs;
    std::vector<Vec3> missed_collisions;  ///< where a collision went undetected since last frame
};

}  // namespace collide
