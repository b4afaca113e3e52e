#pragma once
/// \file
/// Random disc generators (std-only, deterministic for a seed). Implemented with the scenes issue.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "collide/scene.hpp"

namespace collide {

/// One `[[generate]]` block: discs of one radius and mass, placed at random in a region without
/// overlapping anything placed before, with Maxwell-Boltzmann velocities of zero total momentum.
struct GenerateSpec {
    std::size_t count = 0;          ///< number of discs; 0 => derived from packing_fraction
    double packing_fraction = 0.0;  ///< target area fraction of the region (used when count == 0)
    double radius = 0.005;          ///< > 0, box units
    double mass = 1.0;              ///< > 0
    double temperature = 1.0;       ///< kT (k_B = 1) of the Maxwell-Boltzmann velocities, >= 0
    /// When set (>= 0): every disc gets this speed in a random direction instead of
    /// Maxwell-Boltzmann velocities (pairs move in opposite directions: zero total momentum for
    /// an even count). Used to show the relaxation to Maxwell-Boltzmann.
    std::optional<double> speed;
    Vec2 region_min{0.0, 0.0};       ///< region corners; default = the whole box
    std::optional<Vec2> region_max;  ///< unset => (box.width, box.height)
    Rgb8 color{48, 96, 224};         ///< colour of the generated discs
    bool color_by_speed = false;     ///< colour = "speed": renderer colours these by speed
    std::string tag;                 ///< tag given to every generated disc (may be empty)
    std::uint64_t seed = 1;          ///< same seed, same discs

    /// Throws Error(input) naming the bad field (`field_prefix` + name, e.g. "generate[0].radius").
    void validate(const std::string& field_prefix = "generate") const;
};

/// Highest packing fraction (of its region) one block may ask for: a triangular lattice with a
/// few percent of room between neighbours, which the dynamics then melts.
inline constexpr double max_generated_packing_fraction = 0.85;

/// Up to this total packing fraction of the region, discs are placed at random (random
/// sequential addition jams near 0.547 and slows down sharply well before); above it they
/// start on a jittered triangular lattice with random vacancies.
inline constexpr double random_placement_limit = 0.45;

/// Most discs one block may generate (guards memory against a typo like radius = 1e-9).
inline constexpr std::size_t max_generated_discs = 20'000'000;

/// Appends the generated discs to scene.discs (they avoid every disc already there, and lie
/// entirely inside the region; a region equal to a periodic box wraps around). Random
/// placement where it works; a triangular lattice where it cannot reach the density (up to
/// packing fraction 0.85). Velocities: Maxwell-Boltzmann at exactly `temperature` (kinetic
/// temperature of the block) with zero total momentum, or a fixed `speed`.
/// Deterministic: std::mt19937_64 with the spec's seed and our own distributions.
/// Complexity O(N) expected (cell grid) for N = existing + generated discs.
/// Throws Error(input) naming `field_prefix` for a bad spec, a region outside the box, or a
/// request that cannot fit.
void generate_discs(Scene& scene, const GenerateSpec& spec,
                    const std::string& field_prefix = "generate");

}  // namespace collide
