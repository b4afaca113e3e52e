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
    Vec2 region_min{0.0, 0.0};      ///< region corners; default = the whole box
    std::optional<Vec2> region_max; ///< unset => (box.width, box.height)
    Rgb8 color{48, 96, 224};        ///< colour of the generated discs
    bool color_by_speed = false;    ///< colour = "speed": renderer colours these by speed
    std::string tag;                ///< tag given to every generated disc (may be empty)
    std::uint64_t seed = 1;         ///< same seed, same discs

    /// Throws Error(input) naming the bad field (`field_prefix` + name, e.g. "generate[0].radius").
    void validate(const std::string& field_prefix = "generate") const;
};

/// Appends the generated discs to scene.discs (they avoid every disc already there). Random
/// placement where it works; a triangular lattice where it cannot reach the density (up to
/// packing fraction 0.85). Throws Error(input) for an impossible request.
void generate_discs(Scene& scene, const GenerateSpec& spec);

}  // namespace collide
