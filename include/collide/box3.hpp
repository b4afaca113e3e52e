#pragma once
/// \file
/// The box of a 3D scene: [0, width] x [0, height] x [0, depth], walls or periodic, with the same
/// members as the 2D Box (contains, wrap, displacement) so that code generic over the dimension
/// (collide/space.hpp) reads the same for both.

#include <cmath>

#include "collide/box.hpp"
#include "collide/vec3.hpp"

namespace collide {

struct Box3 {
    double width = 1.0;   ///< > 0, simulation length units (x)
    double height = 1.0;  ///< > 0 (y)
    double depth = 1.0;   ///< > 0 (z)
    Boundary boundary = Boundary::walls;

    [[nodiscard]] constexpr double volume() const noexcept { return width * height * depth; }
    /// Total area of the six walls (pressure from wall impulses).
    [[nodiscard]] constexpr double wall_area() const noexcept {
        return 2.0 * (width * height + height * depth + depth * width);
    }
    [[nodiscard]] constexpr Vec3 extent() const noexcept { return {width, height, depth}; }

    /// True when a sphere of radius r centred at p lies entirely inside the box (walls only).
    [[nodiscard]] constexpr bool contains(Vec3 p, double r) const noexcept {
        if (boundary == Boundary::periodic) return true;
        return p.x - r >= 0.0 && p.x + r <= width && p.y - r >= 0.0 && p.y + r <= height &&
               p.z - r >= 0.0 && p.z + r <= depth;
    }

    /// Maps a position into the box (periodic boxes); identity for walls.
    [[nodiscard]] Vec3 wrap(Vec3 p) const noexcept {
        if (boundary != Boundary::periodic) return p;
        const auto fold = [](double v, double e) {
            v -= e * std::floor(v / e);
            return v >= e ? 0.0 : v;  // floor can leave v == e for tiny negative inputs
        };
        return {fold(p.x, width), fold(p.y, height), fold(p.z, depth)};
    }

    /// The shortest displacement from a to b (minimum image in periodic boxes).
    [[nodiscard]] Vec3 displacement(Vec3 a, Vec3 b) const noexcept {
        Vec3 d = b - a;
        if (boundary == Boundary::periodic) {
            d.x -= width * round_near_zero(d.x / width);
            d.y -= height * round_near_zero(d.y / height);
            d.z -= depth * round_near_zero(d.z / depth);
        }
        return d;
    }
};

}  // namespace collide
