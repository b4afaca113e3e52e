#pragma once
/// \file
/// Sphere generators for 3D scenes (std-only, deterministic for a seed): a face-centred-cubic
/// lattice at a packing fraction, and random placement. Velocities are Maxwell-Boltzmann at
/// exactly the asked temperature (three degrees of freedom) with zero total momentum.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "collide/scene3.hpp"

namespace collide {

/// Densest packing of equal spheres, reached by the FCC lattice: pi / (3 sqrt 2) = 0.7405.
inline constexpr double fcc_close_packing = 0.74048048969306104;

/// Random sequential addition of spheres jams near packing 0.38 and slows down sharply well
/// before: random placement is offered up to here; denser fluids start from an FCC lattice.
inline constexpr double max_random_sphere_packing = 0.30;

/// Most spheres one generator may make (guards memory against a typo).
inline constexpr std::size_t max_generated_spheres = 20'000'000;

/// One `[[fcc]]` block: the whole box filled with cells[0] x cells[1] x cells[2] FCC unit cells
/// (4 spheres each), the radius chosen for the packing fraction.
struct FccSpec {
    std::array<std::size_t, 3> cells{4, 4, 4};  ///< unit cells along x, y, z (>= 1)
    double packing_fraction = 0.45;             ///< of the box, (0, close packing)
    double mass = 1.0;                          ///< > 0
    double temperature = 1.0;                   ///< kT (k_B = 1), >= 0
    Rgb8 color{48, 96, 224};
    std::string tag;
    std::uint64_t seed = 1;
};

/// One `[[generate]]` block of a 3D scene: spheres of one radius and mass at random positions in
/// a region of the box (a box itself: two opposite corners; the whole box by default), without
/// overlaps.
struct SphereGenerateSpec {
    std::size_t count = 0;          ///< spheres; 0 => derived from packing_fraction
    double packing_fraction = 0.0;  ///< of the region (used when count == 0)
    double radius = 0.05;           ///< > 0
    double mass = 1.0;
    double temperature = 1.0;
    /// Every sphere at this speed in a random direction instead of Maxwell-Boltzmann velocities
    /// (a gas far from equilibrium, to watch it relax); >= 0. Unset: the temperature's.
    std::optional<double> speed;
    Vec3 region_min{0.0, 0.0, 0.0};  ///< region corners; default = the whole box
    std::optional<Vec3> region_max;  ///< unset => (width, height, depth)
    Rgb8 color{48, 96, 224};
    std::string tag;
    std::uint64_t seed = 1;
};

/// Appends the FCC lattice to scene.spheres (the scene must have no spheres yet: the lattice
/// fills the box). Throws Error(input) naming `prefix`.field: cells out of range, a packing
/// fraction at or beyond what the lattice allows in this box (neighbours would overlap), more
/// than max_generated_spheres. O(N).
void generate_fcc(SphereScene& scene, const FccSpec& spec, const std::string& prefix = "fcc");

/// Appends randomly placed spheres that avoid every sphere already there and lie entirely inside
/// the region (a region equal to a periodic box wraps around). Throws Error(input) naming
/// `prefix`.field for a bad spec (`region`: corners not finite, not ordered, or outside the box),
/// a packing fraction of the region or of the box above max_random_sphere_packing ("too dense to
/// generate at random: use [[fcc]]") or a placement that fails. O(N) expected (cell grid).
void generate_spheres(SphereScene& scene, const SphereGenerateSpec& spec,
                      const std::string& prefix = "generate");

}  // namespace collide
