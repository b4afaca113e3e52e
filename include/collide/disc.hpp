#pragma once
/// \file
/// A disc as a scene describes it (initial state and appearance).

#include <cstdint>
#include <string>

#include "collide/vec2.hpp"

namespace collide {

/// An sRGB colour, 8 bits per channel (algs4 files give 0..255 integers).
struct Rgb8 {
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;
    friend constexpr bool operator==(Rgb8, Rgb8) noexcept = default;
};

/// A disc at least this many times heavier than the lightest disc of its scene counts as
/// immovable: a piece of a barrier or a wall of heavy discs (algs4's diffusion walls: 1e5). The
/// speed plots leave such discs out; a disc that passes through one between two time-driven
/// checks has tunnelled through the barrier.
inline constexpr double immovable_mass_ratio = 1000.0;

/// One hard disc. Units: box lengths, box lengths per time unit, arbitrary mass units.
struct Disc {
    Vec2 position;         ///< centre at t = 0
    Vec2 velocity;         ///< at t = 0
    double radius = 0.01;  ///< > 0
    double mass = 1.0;     ///< > 0 and finite (algs4's diffusion walls use 1e5 for "immovable")
    Rgb8 color{0, 0, 0};   ///< the scene's colour for this disc
    std::string tag;       ///< optional label ("tracer"): trails, mean squared displacement
};

}  // namespace collide
