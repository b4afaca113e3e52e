#pragma once
/// \file
/// The one definition of the simulation box. Walls, validation, periodic wrapping and rendering
/// all derive from it (algs4 states the unit box in two places that disagree; we do not).

#include <cmath>

#include "collide/vec2.hpp"

namespace collide {

/// std::round(q), without the libm call where |q| < 1.5: two compares give -1, 0 or 1, the same
/// doubles (signed zeros included). Minimum-image quotients are such numbers (two images are
/// rarely more than a box apart), and the libm call was 2 % of a 2D collision's instructions at
/// 10^5 discs. NaN gives 0, where the difference it divides carries the NaN through.
[[nodiscard]] inline double round_near_zero(double q) noexcept {
    if (q >= 0.5) return q < 1.5 ? 1.0 : std::round(q);
    if (q <= -0.5) return q > -1.5 ? -1.0 : std::round(q);
    return std::copysign(0.0, q);
}

/// What happens at the edges of the box.
enum class Boundary {
    walls,     ///< elastic reflecting walls at x = 0, x = width, y = 0, y = height
    periodic,  ///< the box wraps around (torus); used for bulk measurements (pressure, Z)
};

/// An axis-aligned box [0, width] x [0, height] in simulation units (algs4 files: the unit box).
struct Box {
    double width = 1.0;   ///< > 0, simulation length units
    double height = 1.0;  ///< > 0, simulation length units
    Boundary boundary = Boundary::walls;

    [[nodiscard]] constexpr double area() const noexcept { return width * height; }

    /// True when a disc of radius r centred at p lies entirely inside the box (walls only:
    /// every position is inside a periodic box).
    [[nodiscard]] constexpr bool contains(Vec2 p, double r) const noexcept {
        if (boundary == Boundary::periodic) return true;
        return p.x - r >= 0.0 && p.x + r <= width && p.y - r >= 0.0 && p.y + r <= height;
    }

    /// Maps a position into [0, width) x [0, height) (periodic boxes); identity for walls.
    [[nodiscard]] Vec2 wrap(Vec2 p) const noexcept {
        if (boundary != Boundary::periodic) return p;
        p.x -= width * std::floor(p.x / width);
        p.y -= height * std::floor(p.y / height);
        // floor can leave p.x == width for tiny negative inputs; fold it back.
        if (p.x >= width) p.x = 0.0;
        if (p.y >= height) p.y = 0.0;
        return p;
    }

    /// The shortest displacement from a to b (minimum image in periodic boxes).
    [[nodiscard]] Vec2 displacement(Vec2 a, Vec2 b) const noexcept {
        Vec2 d = b - a;
        if (boundary == Boundary::periodic) {
            d.x -= width * round_near_zero(d.x / width);
            d.y -= height * round_near_zero(d.y / height);
        }
        return d;
    }
};

}  // namespace collide
