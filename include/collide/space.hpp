#pragma once
/// \file
/// What code written once for 2 and 3 dimensions needs to know about a dimension: its vector,
/// box, particle and scene types, how to measure them (area or volume), and component access.
/// The engines, kinematics and observables are templates over a Space; 2D is Space<2> (discs,
/// collide::Scene), 3D Space<3> (spheres, SphereScene).

#include <numbers>
#include <vector>

#include "collide/box.hpp"
#include "collide/box3.hpp"
#include "collide/disc.hpp"
#include "collide/scene.hpp"
#include "collide/scene3.hpp"
#include "collide/vec2.hpp"
#include "collide/vec3.hpp"

namespace collide {

template <int D>
struct Space;

template <>
struct Space<2> {
    static constexpr int dim = 2;
    using Vec = Vec2;
    using Box = collide::Box;
    using Particle = Disc;
    using Scene = collide::Scene;

    [[nodiscard]] static const std::vector<Disc>& particles(const Scene& s) noexcept {
        return s.discs;
    }
    /// Area of the box.
    [[nodiscard]] static constexpr double measure(const Box& b) noexcept { return b.area(); }
    /// Length of the walls (pressure = wall impulse / (wall measure x time)).
    [[nodiscard]] static constexpr double wall_measure(const Box& b) noexcept {
        return 2.0 * (b.width + b.height);
    }
    /// Area of a disc of radius r.
    [[nodiscard]] static constexpr double particle_measure(double r) noexcept {
        return std::numbers::pi * r * r;
    }
    [[nodiscard]] static constexpr Vec extent(const Box& b) noexcept { return {b.width, b.height}; }
};

template <>
struct Space<3> {
    static constexpr int dim = 3;
    using Vec = Vec3;
    using Box = Box3;
    using Particle = Sphere;
    using Scene = SphereScene;

    [[nodiscard]] static const std::vector<Sphere>& particles(const Scene& s) noexcept {
        return s.spheres;
    }
    [[nodiscard]] static constexpr double measure(const Box& b) noexcept { return b.volume(); }
    [[nodiscard]] static constexpr double wall_measure(const Box& b) noexcept {
        return b.wall_area();
    }
    [[nodiscard]] static constexpr double particle_measure(double r) noexcept {
        return 4.0 / 3.0 * std::numbers::pi * r * r * r;
    }
    [[nodiscard]] static constexpr Vec extent(const Box& b) noexcept { return b.extent(); }
};

using Space2 = Space<2>;
using Space3 = Space<3>;

/// Component k (0 = x, 1 = y, 2 = z) of a vector; k is a constant in every caller, so this
/// compiles to a plain member access.
[[nodiscard]] constexpr double& axis(Vec2& v, int k) noexcept {
    return k == 0 ? v.x : v.y;
}
[[nodiscard]] constexpr double axis(const Vec2& v, int k) noexcept {
    return k == 0 ? v.x : v.y;
}
[[nodiscard]] constexpr double& axis(Vec3& v, int k) noexcept {
    return k == 0 ? v.x : (k == 1 ? v.y : v.z);
}
[[nodiscard]] constexpr double axis(const Vec3& v, int k) noexcept {
    return k == 0 ? v.x : (k == 1 ? v.y : v.z);
}

}  // namespace collide
