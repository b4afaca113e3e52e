#pragma once
/// \file
/// The time-driven engine's all-pairs test, made cheap without skipping a pair: a branch-free,
/// vectorised pass over all N(N-1)/2 pairs keeps only the pairs that may touch during the step
/// (a conservative distance bound), and the engine runs its exact tests on those alone. At
/// N = 2000 a step holds about 2 M pairs and a few thousand candidates. One code for discs and
/// spheres: BasicPairSweep<D> over D coordinates (PairSweep: discs).

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "collide/space.hpp"

namespace collide::sim::detail {

/// A pair of disc ids, i < j.
using DiscPair = std::pair<std::uint32_t, std::uint32_t>;

/// Relative widening of each disc's swept reach: it must cover the rounding of the engine's exact
/// tests, whose worst case (a grazing pair, where b^2 - a c cancels) is about sqrt(6 eps) ~ 4e-8
/// of the pair's distance. 1e-6 is 25x that and adds only a sliver of candidates.
inline constexpr double sweep_relative_margin = 1e-6;
/// Absolute widening, in units of the box's larger side: covers the rounding of the wrapped copies
/// of positions in a periodic box (~1e-16 of the box).
inline constexpr double sweep_absolute_margin = 1e-9;

/// Pairs between two looks at the stop flag: a few microseconds of sweeping, so a look (one load,
/// once per row when rows are longer) costs nothing measurable.
inline constexpr std::uint64_t sweep_stop_poll_pairs = 4096;

template <int D>
class BasicPairSweep {
  public:
    using Vec = typename Space<D>::Vec;
    using BoxType = typename Space<D>::Box;

    /// Appends to `out` (cleared first), in increasing (i, j) order, every pair i < j of discs
    /// that may touch at some moment of a step of length h that ended at `positions`: those whose
    /// (minimum-image) distance now is below (r_i + |v_i| h) + (r_j + |v_j| h), widened by the
    /// margins above; a few farther pairs may come too, none closer is left out. Every one of the
    /// N(N-1)/2 pairs is tested. h = 0 gives the pairs overlapping now. O(N^2) time, O(N) memory.
    /// Looks at `stop` (may be null) every sweep_stop_poll_pairs pairs or so and returns false,
    /// with `out` incomplete, once it is set (at 10^6 discs one sweep takes a minute); else true.
    bool find(const BoxType& box, const std::vector<Vec>& positions,
              const std::vector<Vec>& velocities, const std::vector<double>& radii, double h,
              std::vector<DiscPair>& out, const std::atomic<bool>* stop = nullptr);

    /// Heap memory held (capacity), bytes.
    [[nodiscard]] std::size_t bytes() const noexcept {
        return (x_.capacity() + y_.capacity() + z_.capacity() + reach_.capacity()) *
                   sizeof(double) +
               (x32_.capacity() + y32_.capacity() + z32_.capacity() + reach32_.capacity()) *
                   sizeof(float);
    }

  private:
    // Structure of arrays, so the inner loops read contiguous values and vectorise.
    std::vector<double> x_;
    std::vector<double> y_;
    std::vector<double> z_;      ///< 3D only
    std::vector<double> reach_;  ///< widened r_i + |v_i| h
    // The same rounded to float, reaches padded for that rounding: the counting pass's copy.
    std::vector<float> x32_;
    std::vector<float> y32_;
    std::vector<float> z32_;
    std::vector<float> reach32_;
};

extern template class BasicPairSweep<2>;
extern template class BasicPairSweep<3>;

using PairSweep = BasicPairSweep<2>;

}  // namespace collide::sim::detail
