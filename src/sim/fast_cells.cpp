// The fast engine's cell grid: how fine it is, the order of the particles in memory and their
// first cells (docs/engines.md).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "collide/error.hpp"
#include "collide/sim/sphere_check.hpp"
#include "fast_engine_internal.hpp"

namespace collide::sim {

namespace {

using detail::cell_index;
using detail::cell_margin;
using detail::fit_cells;

/// Upper bound on grid cells per disc: enough for dense fluids (pi / (4 eta) cells per disc at
/// cells one diameter wide), and it stops dilute scenes from allocating millions of empty cells.
constexpr double max_cells_per_disc = 2.0;

/// A grid capped by max_cells_per_disc is refined while a particle's cell holds more than this
/// many particles on average (itself included): a crowd in a large box, such as a gas released
/// from one corner, would otherwise put hundreds in each cell, and every scan reads 3^D cells.
constexpr double crowded_cellmates = 8.0;

/// The refinement stops at this many cells (4 MiB of list heads), or at 16 per particle.
constexpr double crowded_max_cells = 1 << 20;

/// Slots per cell of list centres to start with (about three centres per cell at packing
/// 0.45); a cell that outgrows them doubles every cell's slots.
constexpr std::uint32_t initial_cell_slots = 8;

template <std::size_t D>
double cell_count(const std::array<std::uint32_t, D>& n) {
    double cells = 1.0;
    for (const std::uint32_t c : n) cells *= static_cast<double>(c);
    return cells;
}

/// `full` (cells per axis) scaled down alike on every axis to at most `cap` cells in all, each
/// axis keeping at least `floor_n`.
template <std::size_t D>
std::array<std::uint32_t, D> shrink_grid(const std::array<std::uint32_t, D>& full, double cap,
                                         std::uint32_t floor_n) {
    const double cells = cell_count(full);
    if (cells <= cap) return full;
    const double shrink = D == 2 ? std::sqrt(cap / cells) : std::cbrt(cap / cells);
    std::array<std::uint32_t, D> n{};
    for (std::size_t k = 0; k < D; ++k) {
        n[k] = std::max(floor_n, static_cast<std::uint32_t>(static_cast<double>(full[k]) * shrink));
    }
    return n;
}

/// The number of particles in a particle's cell (itself included), averaged over the particles
/// of radius at most `small_max` (bigger ones are in no cell), for `n` cells per axis over
/// `extent`.
template <class Particles, class Vec, std::size_t D>
double mean_cellmates(const Particles& particles, const Vec& extent,
                      const std::array<std::uint32_t, D>& n, double small_max) {
    Vec cw = extent;
    for (std::size_t k = 0; k < D; ++k) axis(cw, static_cast<int>(k)) /= n[k];
    std::vector<std::uint32_t> occupancy(static_cast<std::size_t>(cell_count(n)), 0);
    std::uint64_t placed = 0;
    for (const auto& p : particles) {
        if (p.radius > small_max) continue;
        ++occupancy[cell_index(p.position, cw, n)];
        ++placed;
    }
    if (placed == 0) return 0.0;
    double pairs = 0.0;  // sum over cells of occupancy^2 = sum over particles of their cell's
    for (const std::uint32_t c : occupancy) pairs += static_cast<double>(c) * c;
    return pairs / static_cast<double>(placed);
}

/// The big-particle threshold and the largest small radius of a scene's particles.
template <class Particles>
std::pair<double, double> split_radii(const Particles& particles) {
    std::vector<double> radii;
    radii.reserve(particles.size());
    for (const auto& d : particles) radii.push_back(d.radius);
    const double big = big_radius_threshold(radii);
    double small_max = 0.0;
    for (double r : radii) {
        if (r <= big) small_max = std::max(small_max, r);
    }
    return {big, small_max};
}

constexpr const char* box_side_names[] = {"box.width", "box.height", "box.depth"};

/// Interleaves the bits of x and y (Z-order / Morton code).
std::uint64_t morton2(std::uint32_t x, std::uint32_t y) noexcept {
    const auto spread = [](std::uint64_t v) {
        v &= 0xffffffffULL;
        v = (v | (v << 16)) & 0x0000ffff0000ffffULL;
        v = (v | (v << 8)) & 0x00ff00ff00ff00ffULL;
        v = (v | (v << 4)) & 0x0f0f0f0f0f0f0f0fULL;
        v = (v | (v << 2)) & 0x3333333333333333ULL;
        v = (v | (v << 1)) & 0x5555555555555555ULL;
        return v;
    };
    return spread(x) | (spread(y) << 1);
}

/// Interleaves the low 21 bits of x, y and z (3D Morton code).
std::uint64_t morton3(std::uint32_t x, std::uint32_t y, std::uint32_t z) noexcept {
    const auto spread = [](std::uint64_t v) {
        v &= 0x1fffffULL;
        v = (v | (v << 32)) & 0x001f00000000ffffULL;
        v = (v | (v << 16)) & 0x001f0000ff0000ffULL;
        v = (v | (v << 8)) & 0x100f00f00f00f00fULL;
        v = (v | (v << 4)) & 0x10c30c30c30c30c3ULL;
        v = (v | (v << 2)) & 0x1249249249249249ULL;
        return v;
    };
    return spread(x) | (spread(y) << 1) | (spread(z) << 2);
}

}  // namespace

std::uint32_t detail::fit_cells(double extent, double min_cell) {
    if (!(min_cell > 0.0)) return 1;
    const double n = std::floor(extent / min_cell);
    if (!(n >= 1.0)) return 1;
    return static_cast<std::uint32_t>(std::min(n, 65536.0));
}

void detail::double_slots(pq::BigVector<std::uint32_t>& table,
                          const pq::BigVector<std::uint32_t>& used, std::uint32_t& slots) {
    const std::uint32_t wider_slots = 2 * slots;
    pq::BigVector<std::uint32_t> wider(used.size() * wider_slots, no_disc);
    for (std::size_t row = 0; row < used.size(); ++row) {
        std::copy_n(table.begin() + static_cast<std::ptrdiff_t>(row * slots), used[row],
                    wider.begin() + static_cast<std::ptrdiff_t>(row * wider_slots));
    }
    table = std::move(wider);
    slots = wider_slots;
}

template <int D>
bool BasicFastEngine<D>::can_simulate(const SceneType& scene) {
    if (scene.box.boundary != Boundary::periodic) return true;
    const double min_cell = 2.0 * split_radii(Space::particles(scene)).second * (1.0 + cell_margin);
    const Vec extent = Space::extent(scene.box);
    for (int k = 0; k < D; ++k) {
        if (fit_cells(axis(extent, k), min_cell) < 3) return false;
    }
    return true;
}

template <int D>
void BasicFastEngine<D>::choose_grid(const SceneType& scene) {
    const auto& particles = Space::particles(scene);
    std::tie(big_threshold_, small_radius_max_) = split_radii(particles);
    choose_lists(scene);
    // Lists mode: the grid holds list centres, which pairs within r_i + r_j + shell may have.
    const double min_cell = (2.0 * small_radius_max_ + shell_) * (1.0 + cell_margin);
    std::array<std::uint32_t, D> n{};
    for (int k = 0; k < D; ++k) {
        n[k] = fit_cells(axis(extent_, k), min_cell);
        if (periodic_ && n[k] < 3) {
            throw_scene_error("", 0, box_side_names[k],
                              D == 2 ? "a periodic box must be at least three disc diameters wide "
                                       "and tall for the fast engine (the classic engine has no "
                                       "such limit)"
                                     : "a periodic box must be at least three sphere diameters "
                                       "wide, tall and deep");
        }
    }
    // Dilute scenes: fewer, larger cells (each must stay at least min_cell wide, so only shrink).
    const auto count = static_cast<double>(particles.size());
    double cap = std::max(D == 2 ? 9.0 : 27.0, max_cells_per_disc * count);
    const std::uint32_t floor_n = periodic_ ? 3U : 1U;
    std::array<std::uint32_t, D> grid = shrink_grid(n, cap, floor_n);
    // Unless the particles crowd into a part of the box: then finer cells, within a budget.
    const double budget = std::max(crowded_max_cells, 16.0 * count);
    while (cell_count(grid) < cell_count(n) && 2.0 * cap <= budget &&
           mean_cellmates(particles, extent_, grid, big_threshold_) > crowded_cellmates) {
        cap *= 2.0;
        grid = shrink_grid(n, cap, floor_n);
    }
    n_ = grid;
    std::size_t total = 1;
    for (int k = 0; k < D; ++k) {
        axis(cw_, k) = axis(extent_, k) / n_[k];
        total *= n_[k];
    }
    if (lists()) {
        cell_slots_ = initial_cell_slots;
        members_.assign(total * cell_slots_, no_disc);
        member_count_.assign(total, 0);
    } else {
        head_.assign(total, no_disc);
    }
}

template <int D>
std::vector<std::uint32_t> BasicFastEngine<D>::locality_order(const SceneType& scene) const {
    const auto& particles = Space::particles(scene);
    const std::size_t n = particles.size();
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(n);
    for (std::uint32_t k = 0; k < n; ++k) {
        const Coords c = coords_of(cell_of(box_.wrap(particles[k].position)));
        if constexpr (D == 2) {
            keyed[k] = {morton2(static_cast<std::uint32_t>(c[0]), static_cast<std::uint32_t>(c[1])),
                        k};
        } else {
            keyed[k] = {morton3(static_cast<std::uint32_t>(c[0]), static_cast<std::uint32_t>(c[1]),
                                static_cast<std::uint32_t>(c[2])),
                        k};
        }
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::uint32_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = keyed[i].second;
    return order;
}

template <int D>
void BasicFastEngine<D>::place_discs(const SceneType& scene) {
    const auto& particles = Space::particles(scene);
    const std::size_t n = particles.size();
    if (n >= Key::index_mask)
        throw_scene_error("", 0, D == 2 ? "discs" : "spheres",
                          D == 2 ? "too many discs for the fast engine (at most 2^29 - 2)"
                                 : "too many spheres for the fast engine (at most 2^29 - 2)");
    *scene_index_ = locality_order(scene);
    p_.resize(n);
    cold_.assign(n, Cold{});
    image_.assign(n, Image{});
    if (lists()) centre_.resize(n);
    start_.resize(n);
    queue_.reserve_handles(n);
    // The key and handle arrays are reserved but untouched yet (the position map is not).
    for (std::uint32_t i = 0; i < n; ++i) {
        const auto& d = particles[scene_index(i)];
        const Vec pos = box_.wrap(d.position);
        p_[i] = Particle{pos, d.velocity, 0.0, d.radius, no_disc, 0, 0, no_disc};
        cold_[i].m = d.mass;
        start_[i] = d.position;
        if (periodic_) {
            // Keep the unwrapped start: image counts measure wrapping from the wrapped position.
            for (int k = 0; k < D; ++k) {
                image_[i][k] =
                    static_cast<std::int32_t>(std::floor(axis(d.position, k) / axis(extent_, k)));
            }
        }
        const std::uint32_t cell = cell_of(pos);
        p_[i].cell = cell;
        if (lists()) centre_[i] = pos;
        if (is_big(i)) {
            big_.push_back(i);
        } else {
            link(i, cell);
        }
    }
}

}  // namespace collide::sim
