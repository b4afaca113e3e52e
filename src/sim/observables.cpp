#include "collide/sim/observables.hpp"

#include <algorithm>
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

    std::vector<Vec2> wrapped(n);
    std::vector<std::uint32_t> cell_of(n);
    std::vector<std::uint32_t> bigs;
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
    std::vector<std::uint32_t> start(nx * ny + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (radii[i] <= big) ++start[cell_of[i] + 1];
    }
    for (std::size_t c = 0; c < nx * ny; ++c) start[c + 1] += start[c];
    std::vector<std::uint32_t> members(start.back());
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
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

double packing_fraction(const std::vector<double>& radii, const Box& box) {
    double covered = 0.0;
    for (double r : radii) covered += std::numbers::pi * r * r;
    return covered / box.area();
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

void fill_thermodynamics(Measurements& m, const std::vector<Vec2>& velocities,
                         const std::vector<double>& masses, const std::vector<double>& radii,
                         const Box& box, const ImpulseTally& tally) {
    double kinetic = 0.0;
    Vec2 momentum{};
    for (std::size_t i = 0; i < velocities.size(); ++i) {
        kinetic += 0.5 * masses[i] * norm2(velocities[i]);
        momentum += masses[i] * velocities[i];
    }
    const auto n = static_cast<double>(velocities.size());
    m.kinetic_energy = kinetic;
    m.momentum = momentum;
    m.temperature = n > 0 ? kinetic / n : 0.0;
    m.packing_fraction = packing_fraction(radii, box);
    m.pressure = 0.0;
    m.compressibility = 0.0;
    const double nkt = n * m.temperature;
    if (m.t <= 0.0 || nkt <= 0.0) return;
    if (box.boundary == Boundary::periodic) {
        m.compressibility = 1.0 + tally.virial / (2.0 * nkt * m.t);
        m.pressure = m.compressibility * nkt / box.area();
    } else {
        const double perimeter = 2.0 * (box.width + box.height);
        m.pressure = tally.wall_impulse / (perimeter * m.t);
        m.compressibility = m.pressure * box.area() / nkt;
    }
}

}  // namespace collide::sim
