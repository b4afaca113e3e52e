#include "time/pair_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide::sim::detail {

namespace {

struct SweepCoordinates {
    const double* x;
    const double* y;
    const double* reach;
};

/// The float copy, in units of a power of two near the scene's extent (see PairSweep::find).
struct SweepCoordinates32 {
    const float* x;
    const float* y;
    const float* reach;
    float width;  ///< the periodic box's sides in the same units (unused with walls)
    float height;
};

/// Pairs tested together before looking for hits: large enough for the vector loop to run at full
/// speed, small enough that rescanning a block with a hit (a few per row) stays cheap.
constexpr std::uint32_t block = 64;

/// Squared distance between (dx, dy)-separated centres; in a periodic box (both coordinates in
/// [0, period)) the minimum image min(|d|, period - |d|) along each axis. Branch-free, so the
/// loops below vectorise. T = float in the counting pass, double in the listing pass.
template <bool periodic, typename T>
inline T gap2(T dx, T dy, T width, T height) noexcept {
    if constexpr (periodic) {
        const T ax = std::fabs(dx);
        const T ay = std::fabs(dy);
        const T bx = width - ax;
        const T by = height - ay;
        dx = bx < ax ? bx : ax;
        dy = by < ay ? by : ay;
    }
    return dx * dx + dy * dy;
}

/// The sweep proper: rows i, blocks of j > i. The first loop over a block only counts hits (no
/// branches, no stores: the compiler vectorises it), in float with padded reaches (see
/// PairSweep::find): a superset of the double test's hits, twice as many pairs per vector. The
/// rare block with a hit is scanned again with the double test to list them, so the result is
/// exactly the double test's. Inlined into the multi-versioned entry points below.
/// Returns false when it stopped early because `stop` was set (looked at before a row once
/// sweep_stop_poll_pairs pairs have been tested since the previous look).
template <bool periodic>
[[gnu::always_inline]] inline bool sweep_rows(const SweepCoordinates& d,
                                              const SweepCoordinates32& f, std::uint32_t n,
                                              double width, double height,
                                              std::vector<DiscPair>& out,
                                              const std::atomic<bool>* stop) {
    const float width_f = f.width;
    const float height_f = f.height;
    std::uint64_t unpolled = 0;  // pairs tested since the last look at the stop flag
    for (std::uint32_t i = 0; i < n; ++i) {
        if (unpolled >= sweep_stop_poll_pairs) {
            unpolled = 0;
            if (stop != nullptr && stop->load(std::memory_order_relaxed)) return false;
        }
        unpolled += n - i - 1;
        const float xi_f = f.x[i];
        const float yi_f = f.y[i];
        const float ri_f = f.reach[i];
        for (std::uint32_t begin = i + 1; begin < n; begin += block) {
            const std::uint32_t end = std::min(n, begin + block);
            std::uint32_t hits = 0;
            for (std::uint32_t j = begin; j < end; ++j) {
                const float r = ri_f + f.reach[j];
                hits |= static_cast<std::uint32_t>(
                    gap2<periodic>(f.x[j] - xi_f, f.y[j] - yi_f, width_f, height_f) < r * r);
            }
            if (hits == 0) {
                continue;
            }
            const double xi = d.x[i];
            const double yi = d.y[i];
            const double ri = d.reach[i];
            for (std::uint32_t j = begin; j < end; ++j) {
                const double r = ri + d.reach[j];
                if (gap2<periodic>(d.x[j] - xi, d.y[j] - yi, width, height) < r * r) {
                    out.emplace_back(i, j);
                }
            }
        }
    }
    return true;
}

// GCC builds AVX-512 and AVX2 copies of each next to the baseline x86-64 one and picks at load
// time (function multi-versioning through an ifunc, no system call), so the binary runs on any
// x86-64: the wide copies are what makes the all-pairs step affordable at a few thousand discs
// (docs/benchmarks.md).
// Walls and periodic boxes get separate loops: the minimum image costs six more operations a pair.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define COLLIDE_SWEEP_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define COLLIDE_SWEEP_CLONES
#endif

COLLIDE_SWEEP_CLONES
bool sweep_rows_walls(const SweepCoordinates& d, const SweepCoordinates32& f, std::uint32_t n,
                      std::vector<DiscPair>& out, const std::atomic<bool>* stop) {
    // No periodic fold: the box sides are unused.
    return sweep_rows<false>(d, f, n, 0.0, 0.0, out, stop);
}

COLLIDE_SWEEP_CLONES
bool sweep_rows_periodic(const SweepCoordinates& d, const SweepCoordinates32& f, std::uint32_t n,
                         double width, double height, std::vector<DiscPair>& out,
                         const std::atomic<bool>* stop) {
    return sweep_rows<true>(d, f, n, width, height, out, stop);
}

#undef COLLIDE_SWEEP_CLONES

}  // namespace

bool PairSweep::find(const Box& box, const std::vector<Vec2>& positions,
                     const std::vector<Vec2>& velocities, const std::vector<double>& radii,
                     double h, std::vector<DiscPair>& out, const std::atomic<bool>* stop) {
    out.clear();
    const std::size_t n = positions.size();
    x_.resize(n);
    y_.resize(n);
    reach_.resize(n);
    x32_.resize(n);
    y32_.resize(n);
    reach32_.resize(n);
    const double slack = sweep_absolute_margin * std::max(box.width, box.height);
    double extent = std::max(box.width, box.height);  // largest |coordinate| or period
    double max_reach = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        // Wrapped copies in a periodic box (the engine's positions are unwrapped mid-step), so
        // that gap2's single fold gives the minimum image.
        const Vec2 p = box.wrap(positions[i]);
        x_[i] = p.x;
        y_[i] = p.y;
        reach_[i] = (radii[i] + norm(velocities[i]) * h) * (1.0 + sweep_relative_margin) + slack;
        extent = std::max({extent, std::fabs(p.x), std::fabs(p.y)});
        max_reach = std::max(max_reach, reach_[i]);
    }
    // The float pass must keep every pair the double test keeps. Rounding the coordinates to float
    // moves a computed distance by at most ~2.2 float epsilons of the extent, and the float sums
    // and squares add ~3 epsilons relative; padding each reach by 16 epsilons of (extent + the
    // largest reach) covers both with room to spare and lets only a sliver more pairs through to
    // the double test. (Non-finite data make the pad non-finite: then every block is rescanned.)
    const double pad = 16.0 * std::numeric_limits<float>::epsilon() * (extent + max_reach);
    // Floats only reach 3e38 and lose precision below 1e-38, and scenes go from 1e-50 to 1e50:
    // the float copy counts in units of the power of two at or below the extent, so that its
    // coordinates lie within +-2. A power of two scales exactly, so the rounding (and the pad,
    // relative to the extent) is as above.
    const double unit = std::isfinite(extent) ? std::ldexp(1.0, -std::ilogb(extent)) : 1.0;
    for (std::size_t i = 0; i < n; ++i) {
        x32_[i] = static_cast<float>(x_[i] * unit);
        y32_[i] = static_cast<float>(y_[i] * unit);
        reach32_[i] = static_cast<float>((reach_[i] + pad) * unit);
    }
    const auto count = static_cast<std::uint32_t>(n);
    const SweepCoordinates d{x_.data(), y_.data(), reach_.data()};
    const SweepCoordinates32 f{x32_.data(), y32_.data(), reach32_.data(),
                               static_cast<float>(box.width * unit),
                               static_cast<float>(box.height * unit)};
    if (box.boundary == Boundary::periodic) {
        return sweep_rows_periodic(d, f, count, box.width, box.height, out, stop);
    }
    return sweep_rows_walls(d, f, count, out, stop);
}

}  // namespace collide::sim::detail
