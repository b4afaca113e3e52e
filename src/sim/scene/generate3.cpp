// Sphere generators: an FCC lattice at a packing fraction, random sequential addition, and
// Maxwell-Boltzmann velocities in three dimensions.

#include "collide/sim/generate3.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "collide/error.hpp"
#include "scene/generator_errors.hpp"
#include "scene/random.hpp"

namespace collide {

namespace {

using detail::Rng;

using detail::fail;
using detail::num;

void check_common(const std::string& prefix, double mass, double temperature) {
    if (!(mass > 0.0 && std::isfinite(mass))) fail(prefix, "mass", "must be finite and > 0");
    if (!(temperature >= 0.0 && std::isfinite(temperature)))
        fail(prefix, "temperature", "must be finite and >= 0");
}

/// Gaussian velocities of variance kT / m per component, then shifted to zero momentum and
/// scaled to exactly kT = 2 KE / (3 N) over spheres first .. end.
void thermal_velocities(std::vector<Sphere>& spheres, std::size_t first, double kT, Rng& rng) {
    const std::size_t n = spheres.size() - first;
    if (n == 0) return;
    Vec3 momentum{};
    double mass = 0.0;
    for (std::size_t i = first; i < spheres.size(); ++i) {
        const double sigma = std::sqrt(kT / spheres[i].mass);
        spheres[i].velocity = {sigma * rng.normal(), sigma * rng.normal(), sigma * rng.normal()};
        momentum += spheres[i].mass * spheres[i].velocity;
        mass += spheres[i].mass;
    }
    const Vec3 drift = (1.0 / mass) * momentum;
    double energy = 0.0;
    for (std::size_t i = first; i < spheres.size(); ++i) {
        if (n > 1) spheres[i].velocity -= drift;
        energy += 0.5 * spheres[i].mass * norm2(spheres[i].velocity);
    }
    const double target = 1.5 * kT * static_cast<double>(n);
    const double scale = energy > 0.0 ? std::sqrt(target / energy) : 0.0;
    for (std::size_t i = first; i < spheres.size(); ++i) spheres[i].velocity *= scale;
}

/// Every sphere first .. end at `speed` in a direction uniform over the sphere of directions.
void same_speed(std::vector<Sphere>& spheres, std::size_t first, double speed, Rng& rng) {
    for (std::size_t i = first; i < spheres.size(); ++i) {
        Vec3 d{};
        double length = 0.0;
        while (!(length > 1e-12)) {  // a normal triple has an isotropic direction
            d = {rng.normal(), rng.normal(), rng.normal()};
            length = norm(d);
        }
        spheres[i].velocity = (speed / length) * d;
    }
}

}  // namespace

void generate_fcc(SphereScene& scene, const FccSpec& spec, const std::string& prefix) {
    check_common(prefix, spec.mass, spec.temperature);
    double total = 4.0;
    for (std::size_t k = 0; k < 3; ++k) {
        if (spec.cells[k] < 1 || spec.cells[k] > 1000)
            fail(prefix, "cells", "each count of unit cells must be from 1 to 1000");
        total *= static_cast<double>(spec.cells[k]);
    }
    if (total > static_cast<double>(max_generated_spheres))
        fail(prefix, "cells",
             num(total) + " spheres is more than the limit of " +
                 num(static_cast<double>(max_generated_spheres)));
    if (!scene.spheres.empty())
        fail(prefix, "cells", "an FCC lattice fills the whole box: put it before any sphere");
    const Box3& box = scene.box;
    const Vec3 a{box.width / static_cast<double>(spec.cells[0]),
                 box.height / static_cast<double>(spec.cells[1]),
                 box.depth / static_cast<double>(spec.cells[2])};
    const double eta = spec.packing_fraction;
    if (!(eta > 0.0 && eta < fcc_close_packing))
        fail(prefix, "packing_fraction",
             "must be in (0, " + num(fcc_close_packing) + "), the FCC close packing");
    // eta = N (4/3) pi r^3 / V.
    const double r = std::cbrt(eta * box.volume() / (total * 4.0 / 3.0 * std::numbers::pi));
    // Nearest neighbours: half a face diagonal. A non-cubic cell brings some closer; keep a
    // relative gap of 1e-6 so that no two spheres start in contact.
    const double nearest = std::min({0.5 * std::hypot(a.x, a.y), 0.5 * std::hypot(a.y, a.z),
                                     0.5 * std::hypot(a.z, a.x), a.x, a.y, a.z});
    if (!(2.0 * r * (1.0 + 1e-6) < nearest))
        fail(prefix, "packing_fraction",
             "packing " + num(eta) + " is too dense to generate in this box: with " + num(total) +
                 " spheres in unit cells of " + num(a.x) + " x " + num(a.y) + " x " + num(a.z) +
                 " neighbours would overlap (the most it allows is " +
                 num(eta * std::pow(nearest / (2.0 * r * (1.0 + 1e-6)), 3.0)) + ")");
    // Walls: the outer sites are a quarter cell from the walls.
    const double wall_gap = 0.25 * std::min({a.x, a.y, a.z});
    if (box.boundary == Boundary::walls && !(r < wall_gap))
        fail(prefix, "packing_fraction",
             "packing " + num(eta) +
                 " is too dense to generate in a walled box: the outer spheres "
                 "would cross the walls (a lattice filling a walled box allows at most " +
                 num(eta * std::pow(wall_gap / r, 3.0) * (1.0 - 1e-9)) +
                 "; use a periodic box for a dense fluid)");
    static constexpr std::array<Vec3, 4> basis{Vec3{0.25, 0.25, 0.25}, Vec3{0.75, 0.75, 0.25},
                                               Vec3{0.75, 0.25, 0.75}, Vec3{0.25, 0.75, 0.75}};
    const std::size_t first = scene.spheres.size();
    scene.spheres.reserve(first + static_cast<std::size_t>(total));
    for (std::size_t z = 0; z < spec.cells[2]; ++z) {
        for (std::size_t y = 0; y < spec.cells[1]; ++y) {
            for (std::size_t x = 0; x < spec.cells[0]; ++x) {
                for (const Vec3& b : basis) {
                    Sphere s;
                    s.position = {(static_cast<double>(x) + b.x) * a.x,
                                  (static_cast<double>(y) + b.y) * a.y,
                                  (static_cast<double>(z) + b.z) * a.z};
                    s.radius = r;
                    s.mass = spec.mass;
                    s.color = spec.color;
                    s.tag = spec.tag;
                    scene.spheres.push_back(s);
                }
            }
        }
    }
    Rng rng(spec.seed);
    thermal_velocities(scene.spheres, first, spec.temperature, rng);
}

namespace {

/// Where a [[generate]] block places its spheres: the region's corners and volume.
struct Region {
    Vec3 lo;
    Vec3 hi;
    double volume = 0.0;
    bool wraps = false;  ///< the region is the whole periodic box: centres anywhere
};

/// The block's region (the whole box by default), checked: finite corners, the second above the
/// first along every axis, both inside the box.
Region resolve_region(const Box3& box, const SphereGenerateSpec& spec, const std::string& prefix) {
    const Vec3 lo = spec.region_min;
    const Vec3 hi = spec.region_max.value_or(box.extent());
    const auto finite = [](Vec3 v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    if (!finite(lo) || !finite(hi)) fail(prefix, "region", "corners must be finite numbers");
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
        fail(prefix, "region",
             "the second corner must lie above the first along x, y and z (a box: "
             "[[x0, y0, z0], [x1, y1, z1]])");
    if (lo.x < 0.0 || lo.y < 0.0 || lo.z < 0.0 || hi.x > box.width || hi.y > box.height ||
        hi.z > box.depth)
        fail(prefix, "region",
             "the region must lie inside the box [0, " + num(box.width) + "] x [0, " +
                 num(box.height) + "] x [0, " + num(box.depth) + "]");
    Region r{lo, hi, (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z), false};
    r.wraps = box.boundary == Boundary::periodic && lo == Vec3{} && hi == box.extent();
    return r;
}

}  // namespace

void generate_spheres(SphereScene& scene, const SphereGenerateSpec& spec,
                      const std::string& prefix) {
    check_common(prefix, spec.mass, spec.temperature);
    if (spec.speed && !(*spec.speed >= 0.0 && std::isfinite(*spec.speed)))
        fail(prefix, "speed", "must be finite and >= 0");
    if (!(spec.radius > 0.0 && std::isfinite(spec.radius)))
        fail(prefix, "radius", "must be finite and > 0");
    const Box3& box = scene.box;
    const Region where = resolve_region(box, spec, prefix);
    const double volume = 4.0 / 3.0 * std::numbers::pi * spec.radius * spec.radius * spec.radius;
    double wanted = static_cast<double>(spec.count);
    if (spec.count == 0) {
        if (!(spec.packing_fraction > 0.0))
            fail(prefix, "count", "give a count or a packing_fraction > 0");
        wanted = std::round(spec.packing_fraction * where.volume / volume);
    }
    if (wanted > static_cast<double>(max_generated_spheres))
        fail(prefix, spec.count == 0 ? "packing_fraction" : "count",
             num(wanted) + " spheres is more than the limit of " +
                 num(static_cast<double>(max_generated_spheres)));
    const auto count = static_cast<std::size_t>(wanted);
    double occupied = 0.0;
    double r_max = spec.radius;
    for (const Sphere& s : scene.spheres) {
        occupied += 4.0 / 3.0 * std::numbers::pi * s.radius * s.radius * s.radius;
        r_max = std::max(r_max, s.radius);
    }
    // The block's own packing of its region, and the box's with it: neither above the limit.
    const double eta_region = static_cast<double>(count) * volume / where.volume;
    const double eta_box = (occupied + static_cast<double>(count) * volume) / box.volume();
    const double eta = std::max(eta_region, eta_box);
    if (eta > max_random_sphere_packing)
        fail(prefix, spec.count == 0 ? "packing_fraction" : "count",
             "packing " + num(eta) + (eta_region > eta_box ? " of the region" : "") +
                 " is too dense to generate at random (at most " + num(max_random_sphere_packing) +
                 "): start a dense fluid from [[fcc]]");
    const bool periodic = box.boundary == Boundary::periodic;
    // Centres anywhere in a region that is the whole periodic box; else a radius inside it.
    const double margin = where.wraps ? 0.0 : spec.radius;
    const Vec3 lo = where.lo + Vec3{margin, margin, margin};
    const Vec3 hi = where.hi - Vec3{margin, margin, margin};
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
        fail(prefix, "radius",
             "a sphere of radius " + num(spec.radius) + " does not fit the " +
                 (spec.region_max || spec.region_min != Vec3{} ? "region" : "box"));
    // A hash grid of cells at least 2 r_max wide over every sphere placed.
    const double cell = 2.0 * r_max;
    const auto key = [&](Vec3 p) {
        const auto c = [&](double v) { return static_cast<std::int64_t>(std::floor(v / cell)); };
        return std::array<std::int64_t, 3>{c(p.x), c(p.y), c(p.z)};
    };
    const auto pack = [](const std::array<std::int64_t, 3>& k) {
        return (static_cast<std::uint64_t>(k[0] & 0x1fffff) << 42) |
               (static_cast<std::uint64_t>(k[1] & 0x1fffff) << 21) |
               static_cast<std::uint64_t>(k[2] & 0x1fffff);
    };
    std::unordered_multimap<std::uint64_t, std::size_t> grid;
    grid.reserve(scene.spheres.size() + count);
    const std::array<std::int64_t, 3> cells_per_axis{
        std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor(box.width / cell))),
        std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor(box.height / cell))),
        std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor(box.depth / cell)))};
    // Periodic boxes: cells wrap, so use exactly cells_per_axis cells of width side / count.
    const auto cell_key = [&](Vec3 p) {
        if (!periodic) return key(p);
        const Vec3 w = box.wrap(p);
        return std::array<std::int64_t, 3>{
            std::min(cells_per_axis[0] - 1,
                     static_cast<std::int64_t>(w.x / box.width * cells_per_axis[0])),
            std::min(cells_per_axis[1] - 1,
                     static_cast<std::int64_t>(w.y / box.height * cells_per_axis[1])),
            std::min(cells_per_axis[2] - 1,
                     static_cast<std::int64_t>(w.z / box.depth * cells_per_axis[2]))};
    };
    const auto insert = [&](std::size_t i) {
        grid.emplace(pack(cell_key(scene.spheres[i].position)), i);
    };
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) insert(i);
    const auto free_at = [&](Vec3 p, double r) {
        const auto c = cell_key(p);
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
            for (std::int64_t dy = -1; dy <= 1; ++dy) {
                for (std::int64_t dx = -1; dx <= 1; ++dx) {
                    std::array<std::int64_t, 3> k{c[0] + dx, c[1] + dy, c[2] + dz};
                    if (periodic) {
                        for (int d = 0; d < 3; ++d)
                            k[d] =
                                (k[d] % cells_per_axis[d] + cells_per_axis[d]) % cells_per_axis[d];
                    }
                    const auto range = grid.equal_range(pack(k));
                    for (auto it = range.first; it != range.second; ++it) {
                        const Sphere& o = scene.spheres[it->second];
                        const double sigma = (r + o.radius) * (1.0 + 1e-6);
                        if (norm2(box.displacement(p, o.position)) < sigma * sigma) return false;
                    }
                }
            }
        }
        return true;
    };
    Rng rng(spec.seed);
    const std::size_t first = scene.spheres.size();
    const double attempts_allowed = 200.0 * static_cast<double>(count) + 1000.0;
    double attempts = 0.0;
    while (scene.spheres.size() - first < count) {
        if (++attempts > attempts_allowed)
            fail(prefix, spec.count == 0 ? "packing_fraction" : "count",
                 "could place only " + num(static_cast<double>(scene.spheres.size() - first)) +
                     " of " + num(static_cast<double>(count)) +
                     " spheres at random: lower the packing or use [[fcc]]");
        const Vec3 p{rng.uniform(lo.x, hi.x), rng.uniform(lo.y, hi.y), rng.uniform(lo.z, hi.z)};
        if (!free_at(p, spec.radius)) continue;
        Sphere s;
        s.position = p;
        s.radius = spec.radius;
        s.mass = spec.mass;
        s.color = spec.color;
        s.tag = spec.tag;
        scene.spheres.push_back(s);
        insert(scene.spheres.size() - 1);
    }
    if (spec.speed) {
        same_speed(scene.spheres, first, *spec.speed, rng);
    } else {
        thermal_velocities(scene.spheres, first, spec.temperature, rng);
    }
}

}  // namespace collide
