#include "collide/sim/observables.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "collide/error.hpp"

namespace collide::sim {

double big_radius_threshold(const std::vector<double>& radii) {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    if (radii.size() < 2) return infinity;
    std::vector<double> sorted = radii;
    const auto mid = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
    std::nth_element(sorted.begin(), mid, sorted.end());
    const double threshold = 2.0 * *mid;
    const auto big_count = static_cast<std::size_t>(
        std::count_if(radii.begin(), radii.end(), [&](double r) { return r > threshold; }));
    const std::size_t allowed = std::max<std::size_t>(8, radii.size() / 64);
    if (big_count == 0 || big_count > allowed) return infinity;
    return threshold;
}

namespace {

/// Number of grid cells along an axis of length `extent` for cells at least `min_cell` wide,
/// capped so that the grid never has many more cells than discs (dilute scenes).
std::size_t cells_along(double extent, double min_cell, std::size_t cap) {
    const double n = std::floor(extent / min_cell);
    if (!(n >= 1.0)) return 1;
    return std::min<std::size_t>(static_cast<std::size_t>(std::min(n, 1e9)), cap);
}

/// The grid max_overlap builds, kept between calls on one thread. A video asks for the
/// measurements every frame: at 10^6 discs fresh buffers (about 40 MB a frame) cost more in page
/// faults and zeroing than the scan itself (docs/benchmarks.md, "A big video").
struct OverlapGrid {
    std::vector<Vec2> wrapped;
    std::vector<std::uint32_t> cell_of;
    std::vector<std::uint32_t> bigs;
    std::vector<std::uint32_t> start;
    std::vector<std::uint32_t> members;
    std::vector<std::uint32_t> fill;
};

OverlapGrid& overlap_grid() {
    thread_local OverlapGrid grid;
    return grid;
}

double overlap_of(const Box& box, Vec2 a, Vec2 b, double sigma) {
    const double dist = norm(box.displacement(a, b));
    return std::max(0.0, sigma - dist);
}

}  // namespace

double max_overlap(const std::vector<Vec2>& positions, const std::vector<double>& radii,
                   const Box& box) {
    const std::size_t n = positions.size();
    if (n < 2) return 0.0;
    const double big = big_radius_threshold(radii);
    double r_small = 0.0;
    for (double r : radii) {
        if (r <= big) r_small = std::max(r_small, r);
    }
    const std::size_t cap = static_cast<std::size_t>(std::sqrt(static_cast<double>(4 * n))) + 1;
    const std::size_t nx = cells_along(box.width, 2.0 * r_small, cap);
    const std::size_t ny = cells_along(box.height, 2.0 * r_small, cap);
    const double cw = box.width / static_cast<double>(nx);
    const double ch = box.height / static_cast<double>(ny);

    OverlapGrid& grid = overlap_grid();
    std::vector<Vec2>& wrapped = grid.wrapped;
    std::vector<std::uint32_t>& cell_of = grid.cell_of;
    std::vector<std::uint32_t>& bigs = grid.bigs;
    wrapped.resize(n);
    cell_of.resize(n);
    bigs.clear();
    for (std::size_t i = 0; i < n; ++i) {
        wrapped[i] = box.wrap(positions[i]);
        const auto cx =
            std::min(nx - 1, static_cast<std::size_t>(std::max(0.0, wrapped[i].x / cw)));
        const auto cy =
            std::min(ny - 1, static_cast<std::size_t>(std::max(0.0, wrapped[i].y / ch)));
        cell_of[i] = static_cast<std::uint32_t>(cy * nx + cx);
        if (radii[i] > big) bigs.push_back(static_cast<std::uint32_t>(i));
    }
    // Counting sort of the small discs by cell.
    std::vector<std::uint32_t>& start = grid.start;
    start.assign(nx * ny + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (radii[i] <= big) ++start[cell_of[i] + 1];
    }
    for (std::size_t c = 0; c < nx * ny; ++c) start[c + 1] += start[c];
    std::vector<std::uint32_t>& members = grid.members;
    members.resize(start.back());
    std::vector<std::uint32_t>& fill = grid.fill;
    fill.assign(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) {
        if (radii[i] <= big) members[fill[cell_of[i]]++] = static_cast<std::uint32_t>(i);
    }

    const bool periodic = box.boundary == Boundary::periodic;
    // Offsets that visit each neighbouring cell once even on grids narrower than 3 cells.
    const auto offsets = [&](std::size_t count) {
        std::vector<long> out;
        if (count < 3) {
            for (std::size_t k = 0; k < count; ++k) out.push_back(static_cast<long>(k));
            return std::pair{out, true};  // absolute indices
        }
        return std::pair{std::vector<long>{-1, 0, 1}, false};
    };
    const auto [ox_list, ox_absolute] = offsets(nx);
    const auto [oy_list, oy_absolute] = offsets(ny);

    double deepest = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        if (radii[i] > big) continue;
        const long cx = static_cast<long>(cell_of[i] % nx);
        const long cy = static_cast<long>(cell_of[i] / nx);
        for (long oy : oy_list) {
            long y = oy_absolute ? oy : cy + oy;
            if (y < 0 || y >= static_cast<long>(ny)) {
                if (!periodic) continue;
                y = (y + static_cast<long>(ny)) % static_cast<long>(ny);
            }
            for (long ox : ox_list) {
                long x = ox_absolute ? ox : cx + ox;
                if (x < 0 || x >= static_cast<long>(nx)) {
                    if (!periodic) continue;
                    x = (x + static_cast<long>(nx)) % static_cast<long>(nx);
                }
                const std::size_t c =
                    static_cast<std::size_t>(y) * nx + static_cast<std::size_t>(x);
                for (std::uint32_t k = start[c]; k < start[c + 1]; ++k) {
                    const std::uint32_t j = members[k];
                    if (j <= i) continue;
                    deepest = std::max(
                        deepest, overlap_of(box, wrapped[i], wrapped[j], radii[i] + radii[j]));
                }
            }
        }
    }
    for (std::uint32_t b : bigs) {
        for (std::size_t j = 0; j < n; ++j) {
            if (j == b) continue;
            deepest =
                std::max(deepest, overlap_of(box, wrapped[b], wrapped[j], radii[b] + radii[j]));
        }
    }
    return deepest;
}

template <int D>
double packing_fraction_of(const std::vector<double>& radii, const typename Space<D>::Box& box) {
    double covered = 0.0;
    for (double r : radii) covered += Space<D>::particle_measure(r);
    return covered / Space<D>::measure(box);
}

template double packing_fraction_of<2>(const std::vector<double>&, const Box&);
template double packing_fraction_of<3>(const std::vector<double>&, const Box3&);

double packing_fraction(const std::vector<double>& radii, const Box& box) {
    return packing_fraction_of<2>(radii, box);
}

double max_overlap(const std::vector<Vec3>& positions, const std::vector<double>& radii,
                   const Box3& box) {
    const std::size_t n = positions.size();
    if (n < 2) return 0.0;
    double r_max = 0.0;
    for (double r : radii) r_max = std::max(r_max, r);
    // Cells at least one largest diameter wide, at most about 2 per sphere.
    const auto cap = static_cast<std::size_t>(std::cbrt(2.0 * static_cast<double>(n))) + 1;
    const std::array<std::size_t, 3> cells{cells_along(box.width, 2.0 * r_max, cap),
                                           cells_along(box.height, 2.0 * r_max, cap),
                                           cells_along(box.depth, 2.0 * r_max, cap)};
    const Vec3 extent = box.extent();
    std::vector<Vec3> wrapped(n);
    std::vector<std::array<std::size_t, 3>> coords(n);
    std::vector<std::size_t> cell_of(n);
    for (std::size_t i = 0; i < n; ++i) {
        wrapped[i] = box.wrap(positions[i]);
        for (int k = 0; k < 3; ++k) {
            const double w = axis(extent, k) / static_cast<double>(cells[k]);
            coords[i][k] = std::min(
                cells[k] - 1, static_cast<std::size_t>(std::max(0.0, axis(wrapped[i], k) / w)));
        }
        cell_of[i] = (coords[i][2] * cells[1] + coords[i][1]) * cells[0] + coords[i][0];
    }
    const std::size_t total = cells[0] * cells[1] * cells[2];
    std::vector<std::uint32_t> start(total + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++start[cell_of[i] + 1];
    for (std::size_t c = 0; c < total; ++c) start[c + 1] += start[c];
    std::vector<std::uint32_t> members(n);
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) members[fill[cell_of[i]]++] = static_cast<std::uint32_t>(i);
    const bool periodic = box.boundary == Boundary::periodic;
    // The neighbouring cells' coordinates along one axis, each once (grids under 3 cells wide).
    const auto neighbours = [&](std::size_t c, std::size_t count) {
        std::vector<std::size_t> out;
        for (long o = -1; o <= 1; ++o) {
            long x = static_cast<long>(c) + o;
            if (x < 0 || x >= static_cast<long>(count)) {
                if (!periodic) continue;
                x = (x + static_cast<long>(count)) % static_cast<long>(count);
            }
            if (std::find(out.begin(), out.end(), static_cast<std::size_t>(x)) == out.end())
                out.push_back(static_cast<std::size_t>(x));
        }
        return out;
    };
    double deepest = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t z : neighbours(coords[i][2], cells[2])) {
            for (std::size_t y : neighbours(coords[i][1], cells[1])) {
                for (std::size_t x : neighbours(coords[i][0], cells[0])) {
                    const std::size_t c = (z * cells[1] + y) * cells[0] + x;
                    for (std::uint32_t k = start[c]; k < start[c + 1]; ++k) {
                        const std::uint32_t j = members[k];
                        if (j <= i) continue;
                        const double dist = norm(box.displacement(wrapped[i], wrapped[j]));
                        deepest = std::max(deepest, radii[i] + radii[j] - dist);
                    }
                }
            }
        }
    }
    return deepest;
}

std::vector<std::uint64_t> speed_histogram(const Snapshot& snapshot, std::size_t bins,
                                           double v_max) {
    if (bins == 0) throw_scene_error("", 0, "bins", "a speed histogram needs at least one bin");
    if (v_max <= 0.0) {
        for (const DiscState& d : snapshot.discs) v_max = std::max(v_max, norm(d.velocity));
    }
    std::vector<std::uint64_t> counts(bins, 0);
    if (v_max <= 0.0) {
        counts[0] = snapshot.discs.size();
        return counts;
    }
    for (const DiscState& d : snapshot.discs) {
        const double bin = std::floor(norm(d.velocity) / v_max * static_cast<double>(bins));
        const auto k = bin >= static_cast<double>(bins) ? bins - 1 : static_cast<std::size_t>(bin);
        ++counts[k];
    }
    return counts;
}

template <int D>
void fill_thermodynamics(Measurements& m, const std::vector<typename Space<D>::Vec>& velocities,
                         const std::vector<double>& masses, const std::vector<double>& radii,
                         const typename Space<D>::Box& box, const ImpulseTally& tally) {
    using Vec = typename Space<D>::Vec;
    double kinetic = 0.0;
    Vec momentum{};
    for (std::size_t i = 0; i < velocities.size(); ++i) {
        kinetic += 0.5 * masses[i] * norm2(velocities[i]);
        momentum += masses[i] * velocities[i];
    }
    const auto n = static_cast<double>(velocities.size());
    m.kinetic_energy = kinetic;
    m.momentum = {momentum.x, momentum.y};
    if constexpr (D == 3) m.momentum_z = momentum.z;
    // D degrees of freedom: kT = 2 KE / (D N) (in 2D exactly KE / N: the factors 2 are exact).
    m.temperature = n > 0 ? 2.0 * kinetic / (D * n) : 0.0;
    m.packing_fraction = packing_fraction_of<D>(radii, box);
    m.pressure = 0.0;
    m.compressibility = 0.0;
    const double nkt = n * m.temperature;
    if (m.t <= 0.0 || nkt <= 0.0) return;
    if (box.boundary == Boundary::periodic) {
        m.compressibility = 1.0 + tally.virial / (D * nkt * m.t);
        m.pressure = m.compressibility * nkt / Space<D>::measure(box);
    } else {
        m.pressure = tally.wall_impulse / (Space<D>::wall_measure(box) * m.t);
        m.compressibility = m.pressure * Space<D>::measure(box) / nkt;
    }
}

template void fill_thermodynamics<2>(Measurements&, const std::vector<Vec2>&,
                                     const std::vector<double>&, const std::vector<double>&,
                                     const Box&, const ImpulseTally&);
template void fill_thermodynamics<3>(Measurements&, const std::vector<Vec3>&,
                                     const std::vector<double>&, const std::vector<double>&,
                                     const Box3&, const ImpulseTally&);

}  // namespace collide::sim
