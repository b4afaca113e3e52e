#include "time/pair_sweep.hpp"

#include <algorithm>
#include <cmath>

namespace collide::detail {

namespace {

/// Pairs tested together before looking for hits: large enough for the vector loop to run at full
/// speed, small enough that rescanning a block with a hit (a few per row) stays cheap.
constexpr std::uint32_t block = 64;

/// Squared distance between (dx, dy)-separated centres; in a periodic box (both coordinates in
/// [0, period)) the minimum image min(|d|, period - |d|) along each axis. Branch-free, so the
/// loops below vectorise.
template <bool periodic>
inline double gap2(double dx, double dy, double width, double height) noexcept {
    if constexpr (periodic) {
        const double ax = std::fabs(dx);
        const double ay = std::fabs(dy);
        const double bx = width - ax;
        const double by = height - ay;
        dx = bx < ax ? bx : ax;
        dy = by < ay ? by : ay;
    }
    return dx * dx + dy * dy;
}

/// The sweep proper: rows i, blocks of j > i. The first loop over a block only counts hits (no
/// branches, no stores: the compiler vectorises it); the rare block with a hit is scanned again
/// to list them. Inlined into the multi-versioned entry points below.
template <bool periodic>
[[gnu::always_inline]] inline void sweep_rows(const double* x, const double* y, const double* reach,
                                              std::uint32_t n, double width, double height,
                                              std::vector<DiscPair>& out) {
    for (std::uint32_t i = 0; i < n; ++i) {
        const double xi = x[i];
        const double yi = y[i];
        const double ri = reach[i];
        for (std::uint32_t begin = i + 1; begin < n; begin += block) {
            const std::uint32_t end = std::min(n, begin + block);
            std::uint64_t hits = 0;
            for (std::uint32_t j = begin; j < end; ++j) {
                const double r = ri + reach[j];
                hits |= static_cast<std::uint64_t>(
                    gap2<periodic>(x[j] - xi, y[j] - yi, width, height) < r * r);
            }
            if (hits == 0) {
                continue;
            }
            for (std::uint32_t j = begin; j < end; ++j) {
                const double r = ri + reach[j];
                if (gap2<periodic>(x[j] - xi, y[j] - yi, width, height) < r * r) {
                    out.emplace_back(i, j);
                }
            }
        }
    }
}

// GCC builds an AVX2 copy of each next to the baseline x86-64 one and picks at load time
// (function multi-versioning through an ifunc, no system call), so the binary runs on any x86-64.
// Walls and periodic boxes get separate loops: the minimum image costs six more operations a pair.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define COLLIDE_SWEEP_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define COLLIDE_SWEEP_CLONES
#endif

COLLIDE_SWEEP_CLONES
void sweep_rows_walls(const double* x, const double* y, const double* reach, std::uint32_t n,
                      std::vector<DiscPair>& out) {
    sweep_rows<false>(x, y, reach, n, 0.0, 0.0, out);
}

COLLIDE_SWEEP_CLONES
void sweep_rows_periodic(const double* x, const double* y, const double* reach, std::uint32_t n,
                         double width, double height, std::vector<DiscPair>& out) {
    sweep_rows<true>(x, y, reach, n, width, height, out);
}

#undef COLLIDE_SWEEP_CLONES

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
        // that gap2's single fold gives the minimum image.
        const Vec2 p = box.wrap(positions[i]);
        x_[i] = p.x;
        y_[i] = p.y;
        reach_[i] = (radii[i] + norm(velocities[i]) * h) * (1.0 + sweep_relative_margin) + slack;
    }
    const auto count = static_cast<std::uint32_t>(n);
    if (box.boundary == Boundary::periodic) {
        sweep_rows_periodic(x_.data(), y_.data(), reach_.data(), count, box.width, box.height, out);
    } else {
        sweep_rows_walls(x_.data(), y_.data(), reach_.data(), count, out);
    }
}

}  // namespace collide::detail
