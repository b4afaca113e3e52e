// The jam a row of spheres makes (toml_text.hpp): the check of explicit [[sphere]] tables that
// the reader runs once the spheres are placed.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "collide/sim/scene_check.hpp"
#include "collide/space.hpp"
#include "toml_text.hpp"

namespace collide::toml_text {

// A sphere in a straight row of touching spheres from wall to wall (or alone as wide as the
// box) that moves along the row: the row cannot move, so the engines would collide at t = 0
// forever. Named at its velocity, as 2D scenes name such discs (scene_check.cpp). Walled
// boxes only; other jams (rings around a periodic box, bent rows) are caught by the engines
// (sim::instant_collision_limit).
std::optional<SphereJam> find_sphere_jam(
    const SphereScene& s, const std::vector<std::pair<std::size_t, std::size_t>>& contacts) {
    if (s.box.boundary != Boundary::walls) return std::nullopt;
    const std::size_t n = s.spheres.size();
    const double straight = std::sqrt(contact_tolerance);  // as rows of discs
    for (int k = 0; k < 3; ++k) {
        std::vector<std::size_t> parent(n);
        for (std::size_t i = 0; i < n; ++i) parent[i] = i;
        const auto find = [&](std::size_t i) {
            while (parent[i] != i) i = parent[i] = parent[parent[i]];
            return i;
        };
        for (const auto& [i, j] : contacts) {
            Vec3 d = s.spheres[j].position - s.spheres[i].position;
            axis(d, k) = 0.0;  // what is left is the offset across the row
            if (norm(d) > straight * (s.spheres[i].radius + s.spheres[j].radius)) continue;
            parent[std::max(find(i), find(j))] = std::min(find(i), find(j));
        }
        std::vector<std::uint8_t> walls(n, 0);  // 1: touches the low wall, 2: the high one
        std::vector<std::size_t> size(n, 0);
        const double extent = axis(s.box.extent(), k);
        for (std::size_t i = 0; i < n; ++i) {
            const Sphere& q = s.spheres[i];
            const double slack = contact_tolerance * q.radius;
            const std::size_t root = find(i);
            if (axis(q.position, k) - q.radius <= slack) walls[root] |= 1;
            if (axis(q.position, k) + q.radius >= extent - slack) walls[root] |= 2;
            ++size[root];
        }
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t root = find(i);
            if (walls[root] != 3 || axis(s.spheres[i].velocity, k) == 0.0) continue;
            const std::string name(1, "xyz"[k]);
            const std::string where =
                size[root] == 1 ? "it is as wide as the box along " + name
                                : "it is wedged between the walls " + name + " = 0 and " + name +
                                      " = " + num(extent) + " in a straight row of " +
                                      std::to_string(size[root]) + " touching spheres";
            return SphereJam{i,
                             "jammed: " + where + ", so it cannot move along " + name +
                                 ", but its velocity has a " + name +
                                 " component (the engines would collide at t = 0 forever); leave a "
                                 "gap, or give it no velocity along " +
                                 name};
        }
    }
    return std::nullopt;
}

}  // namespace collide::toml_text
