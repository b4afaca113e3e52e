#pragma once
/// \file
/// What `collide check` says about a 3D scene, and the work a run of it will take.

#include <string>

#include "collide/scene3.hpp"
#include "collide/sim/work_estimate.hpp"

namespace collide {

/// Sum of the spheres' volumes over the box's.
[[nodiscard]] double packing_fraction(const SphereScene& scene) noexcept;

/// Expected pair collisions per unit of simulation time: N/2 times the Enskog collision rate of
/// one sphere, 4 n sigma^2 g(sigma) sqrt(pi kT / m), with the Carnahan-Starling contact value
/// g(sigma) = (1 - eta / 2) / (1 - eta)^3 and the scene's mean diameter, mass and temperature
/// (kT = 2 KE / 3N). An estimate for the work limits, right within tens of percent for a fluid;
/// 0 when nothing moves.
[[nodiscard]] double collisions_per_time_unit(const SphereScene& scene) noexcept;

/// Cell crossings per unit of simulation time in the fast engine's grid of spheres: about
/// max(27, 2 N) cells, none narrower than a sphere diameter, crossed at |v_x| + |v_y| + |v_z|
/// over the cell side by each sphere. Events too (a lone sphere crosses cells forever). O(N).
[[nodiscard]] double sphere_crossing_rate(const SphereScene& scene) noexcept;

/// The work of `run` on a 3D scene (collide/sim/work_estimate.hpp): collisions from
/// collisions_per_time_unit, crossings from sphere_crossing_rate. O(N).
[[nodiscard]] WorkEstimate estimate_work(const SphereScene& scene, const RunShape& run) noexcept;

/// "N = 4000 spheres (3D), eta = 0.45, box 1 x 1 x 1, periodic, kT = 1, about 6.2e+05
/// collisions per time unit".
[[nodiscard]] std::string sphere_scene_summary(const SphereScene& scene);

}  // namespace collide
