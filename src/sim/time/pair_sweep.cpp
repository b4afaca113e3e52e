#include "time/pair_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide::sim::detail {

namespace {

struct SweepCoordinates {
    const double* x;
    const double* y;
    const double* z;  ///< 3D only
    const double* reach;
};

/// The float copy, in units of a power of two near the scene's extent (see PairSweep::find).
struct SweepCoordinates32 {
    const float* x;
    const float* y;
    const float* z;  ///< 3D only
    const float* reach;
    float width;  ///< the periodic box's sides in the same units (unused with walls)
    float height;
    float depth;  ///< 3D only
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

/// gap2 for spheres: the same fold along z.
template <bool periodic, typename T>
inline T gap3(T dx, T dy, T dz, T width, T height, T depth) noexcept {
    if constexpr (periodic) {
        const T az = std::fabs(dz);
        const T bz = depth - az;
        dz = bz < az ? bz : az;
    }
    return gap2<periodic>(dx, dy, width, height) + dz * dz;
}

/// The squared (minimum-image) distance from particle i's copy (xi, yi, zi) to particle j's in
/// the coordinates c (double or float): gap2 for discs, gap3 for spheres.
template <int D, bool periodic, typename T, typename Coordinates>
[[gnu::always_inline]] inline T gap_to(const Coordinates& c, std::uint32_t j, T xi, T yi, T zi,
                                       T width, T height, T depth) noexcept {
    if constexpr (D == 2) {
        return gap2<periodic>(c.x[j] - xi, c.y[j] - yi, width, height);
    } else {
        return gap3<periodic>(c.x[j] - xi, c.y[j] - yi, c.z[j] - zi, width, height, depth);
    }
}

/// The sweep proper: rows i, blocks of j > i. The first loop over a block only counts hits (no
/// branches, no stores: the compiler vectorises it), in float with padded reaches (see
/// PairSweep::find): a superset of the double test's hits, twice as many pairs per vector. The
/// rare block with a hit is scanned again with the double test to list them, so the result is
/// exactly the double test's. Inlined into the multi-versioned entry points below.
/// Returns false when it stopped early because `stop` was set (looked at before a row once
/// sweep_stop_poll_pairs pairs have been tested since the previous look).
template <int D, bool periodic>
[[gnu::always_inline]] inline bool sweep_rows(const SweepCoordinates& d,
                                              const SweepCoordinates32& f, std::uint32_t n,
                                              double width, double height, double depth,
                                              std::vector<DiscPair>& out,
                                              const std::atomic<bool>* stop) {
    const float width_f = f.width;
    const float height_f = f.height;
    const float depth_f = f.depth;
    std::uint64_t unpolled = 0;  // pairs tested since the last look at the stop flag
    for (std::uint32_t i = 0; i < n; ++i) {
        if (unpolled >= sweep_stop_poll_pairs) {
            unpolled = 0;
            if (stop != nullptr && stop->load(std::memory_order_relaxed)) return false;
        }
        unpolled += n - i - 1;
        const float xi_f = f.x[i];
        const float yi_f = f.y[i];
        const float zi_f = D == 3 ? f.z[i] : 0.0F;
        const float ri_f = f.reach[i];
        for (std::uint32_t begin = i + 1; begin < n; begin += block) {
            const std::uint32_t end = std::min(n, begin + block);
            std::uint32_t hits = 0;
            for (std::uint32_t j = begin; j < end; ++j) {
                const float r = ri_f + f.reach[j];
                hits |=
                    static_cast<std::uint32_t>(gap_to<D, periodic>(f, j, xi_f, yi_f, zi_f, width_f,
                                                                   height_f, depth_f) < r * r);
            }
            if (hits == 0) {
                continue;
            }
            const double xi = d.x[i];
            const double yi = d.y[i];
            const double zi = D == 3 ? d.z[i] : 0.0;
            const double ri = d.reach[i];
            for (std::uint32_t j = begin; j < end; ++j) {
                const double r = ri + d.reach[j];
                if (gap_to<D, periodic>(d, j, xi, yi, zi, width, height, depth) < r * r) {
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
    return sweep_rows<2, false>(d, f, n, 0.0, 0.0, 0.0, out, stop);
}

COLLIDE_SWEEP_CLONES
bool sweep_rows_periodic(const SweepCoordinates& d, const SweepCoordinates32& f, std::uint32_t n,
                         double width, double height, std::vector<DiscPair>& out,
                         const std::atomic<bool>* stop) {
    return sweep_rows<2, true>(d, f, n, width, height, 0.0, out, stop);
}

COLLIDE_SWEEP_CLONES
bool sweep_rows_walls3(const SweepCoordinates& d, const SweepCoordinates32& f, std::uint32_t n,
                       std::vector<DiscPair>& out, const std::atomic<bool>* stop) {
    return sweep_rows<3, false>(d, f, n, 0.0, 0.0, 0.0, out, stop);
}

COLLIDE_SWEEP_CLONES
bool sweep_rows_periodic3(const SweepCoordinates& d, const SweepCoordinates32& f, std::uint32_t n,
                          double width, double height, double depth, std::vector<DiscPair>& out,
                          const std::atomic<bool>* stop) {
    return sweep_rows<3, true>(d, f, n, width, height, depth, out, stop);
}

#undef COLLIDE_SWEEP_CLONES

}  // namespace

template <int D>
bool BasicPairSweep<D>::find(const BoxType& box, const std::vector<Vec>& positions,
                             const std::vector<Vec>& velocities, const std::vector<double>& radii,
                             double h, std::vector<DiscPair>& out, const std::atomic<bool>* stop) {
    out.clear();
    const std::size_t n = positions.size();
    const std::size_t nz = D == 3 ? n : 0;
    x_.resize(n);
    y_.resize(n);
    z_.resize(nz);
    reach_.resize(n);
    x32_.resize(n);
    y32_.resize(n);
    z32_.resize(nz);
    reach32_.resize(n);
    const Vec sides = Space<D>::extent(box);
    double largest_side = std::max(box.width, box.height);
    if constexpr (D == 3) largest_side = std::max(largest_side, box.depth);
    const double slack = sweep_absolute_margin * largest_side;
    double extent = largest_side;  // largest |coordinate| or period
    double max_reach = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        // Wrapped copies in a periodic box (the engine's positions are unwrapped mid-step), so
        // that gap2's single fold gives the minimum image.
        const Vec p = box.wrap(positions[i]);
        x_[i] = p.x;
        y_[i] = p.y;
        reach_[i] = (radii[i] + norm(velocities[i]) * h) * (1.0 + sweep_relative_margin) + slack;
        extent = std::max({extent, std::fabs(p.x), std::fabs(p.y)});
        if constexpr (D == 3) {
            z_[i] = p.z;
            extent = std::max(extent, std::fabs(p.z));
        }
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
        if constexpr (D == 3) z32_[i] = static_cast<float>(z_[i] * unit);
        reach32_[i] = static_cast<float>((reach_[i] + pad) * unit);
    }
    const auto count = static_cast<std::uint32_t>(n);
    const SweepCoordinates d{x_.data(), y_.data(), z_.data(), reach_.data()};
    const double depth = D == 3 ? axis(sides, D - 1) : 0.0;
    const SweepCoordinates32 f{x32_.data(),
                               y32_.data(),
                               z32_.data(),
                               reach32_.data(),
                               static_cast<float>(box.width * unit),
                               static_cast<float>(box.height * unit),
                               static_cast<float>(depth * unit)};
    const bool periodic = box.boundary == Boundary::periodic;
    if constexpr (D == 2) {
        if (periodic) return sweep_rows_periodic(d, f, count, box.width, box.height, out, stop);
        return sweep_rows_walls(d, f, count, out, stop);
    } else {
        if (periodic) {
            return sweep_rows_periodic3(d, f, count, box.width, box.height, depth, out, stop);
        }
        return sweep_rows_walls3(d, f, count, out, stop);
    }
}

template class BasicPairSweep<2>;
template class BasicPairSweep<3>;

}  // namespace collide::sim::detail
