#include "time/pair_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide::detail {

namespace {

/// Pairs tested together before looking for hits: large enough for the vector loop to run at full
/// speed, small enough that rescanning a block with a hit (a few per row) stays cheap.
constexpr std::uint32_t block = 64;

/// Distance along one axis: |d|, or its minimum image min(|d|, period - |d|) when both coordinates
/// lie in [0, period). period = +inf (walls) leaves |d|. Branch-free, so it vectorises.
inline double axis_gap(double d, double period) noexcept {
    const double a = std::fabs(d);
    const double b = period - a;
    return b < a ? b : a;
}

/// The sweep proper: rows i, blocks of j > i. The first loop over a block only counts hits (no
/// branches, no stores: the compiler vectorises it); the rare block with a hit is scanned again
/// to list them. GCC builds an AVX2 copy next to the baseline x86-64 one and picks at load time
/// (function multi-versioning through an ifunc, no system call), so the binary runs on any x86-64.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
__attribute__((target_clones("avx2", "default")))
#endif
void sweep_rows(const double* x, const double* y, const double* reach, std::uint32_t n,
                double width, double height, std::vector<DiscPair>& out) {
    for (std::uint32_t i = 0; i < n; ++i) {
        const double xi = x[i];
        const double yi = y[i];
        const double ri = reach[i];
        for (std::uint32_t begin = i + 1; begin < n; begin += block) {
            const std::uint32_t end = std::min(n, begin + block);
            std::uint64_t hits = 0;
            for (std::uint32_t j = begin; j < end; ++j) {
                const double dx = axis_gap(x[j] - xi, width);
                const double dy = axis_gap(y[j] - yi, height);
                const double r = ri + reach[j];
                hits |= static_cast<std::uint64_t>(dx * dx + dy * dy < r * r);
            }
            if (hits == 0) {
                continue;
            }
            for (std::uint32_t j = begin; j < end; ++j) {
                const double dx = axis_gap(x[j] - xi, width);
                const double dy = axis_gap(y[j] - yi, height);
                const double r = ri + reach[j];
                if (dx * dx + dy * dy < r * r) {
                    out.emplace_back(i, j);
                }
            }
        }
    }
}

}  // namespace

void PairSweep::find(const Box& box, const std::vector<Vec2>& positions,
                     const std::vector<Vec2>& velocities, const std::vector<double>& radii,
                     double h, std::vector<DiscPair>& out) {
    out.clear();
    const std::size_t n = positions.size();
    x_.resize(n);
    y_.resize(n);
    reach_.resize(n);
    const double slack = sweep_absolute_margin * std::max(box.width, box.height);
    for (std::size_t i = 0; i < n; ++i) {
        // Wrapped copies in a periodic box (the engine's positions are unwrapped mid-step), so
        // that axis_gap's single fold gives the minimum image.
        const Vec2 p = box.wrap(positions[i]);
        x_[i] = p.x;
        y_[i] = p.y;
        reach_[i] = (radii[i] + norm(velocities[i]) * h) * (1.0 + sweep_relative_margin) + slack;
    }
    const bool periodic = box.boundary == Boundary::periodic;
    constexpr double unbounded = std::numeric_limits<double>::infinity();
    sweep_rows(x_.data(), y_.data(), reach_.data(), static_cast<std::uint32_t>(n),
               periodic ? box.width : unbounded, periodic ? box.height : unbounded, out);
}

}  // namespace collide::detail
