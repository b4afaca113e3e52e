#pragma once
/// \file
/// What the event-driven engines (classic and fast) share beyond the engine core
/// (engine_core.hpp): the bound that catches a jammed disc.

#include <cstdint>
#include <string>

#include "collide/error.hpp"
#include "collide/vec2.hpp"

namespace collide::sim {

/// How far (relative to its radius) a disc may move between two of its collisions for both to count
/// as one instant in the jam bound below. Not exact time equality: discs "touching" in a scene
/// file are usually a rounding error apart (positions such as 1/6 + 1/3), so a wedged disc's
/// collisions come 1e-17 apart, time creeps on, and it would take 10^16 of them to reach t = 1.
/// The scene check calls discs within contact_tolerance (1e-9) of each other touching; the same
/// fraction of the radius here.
inline constexpr double same_instant_travel = 1e-9;

/// True when a disc of radius r, moving at v for dt since its previous event, is still at that
/// event's instant (it moved less than same_instant_travel r).
template <class Vec = Vec2>
[[nodiscard]] inline bool same_instant(double dt, Vec v, double r) noexcept {
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
    throw_scene_error("", 0, "disc " + std::to_string(disc + 1),
                      "jammed at t = " + std::to_string(t) + ": more than " +
                          std::to_string(limit) +
                          " collisions at one instant (it moved less than 1e-9 of its radius "
                          "between them). A disc that cannot move (as wide as the box, or wedged "
                          "wall to wall between touching discs) but has a velocity along the "
                          "blocked axis collides forever; leave a gap, or give those discs no "
                          "velocity along that axis");
}

}  // namespace collide::sim
