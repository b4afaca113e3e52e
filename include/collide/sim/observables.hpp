#pragma once
/// \file
/// Observables computed from disc states: energy, momentum, packing fraction, the deepest
/// overlap, the speed histogram, and turning accumulated impulses into pressure and Z.
/// Shared by every engine so that they report the same quantity the same way.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "collide/box.hpp"
#include "collide/sim/measurements.hpp"
#include "collide/snapshot.hpp"
#include "collide/space.hpp"
#include "collide/vec2.hpp"

namespace collide::sim {

/// Radius above which a disc counts as "big" for cell grids (algs4's brownian.txt: one disc of
/// radius 0.1 among 999 of 0.0025). Big discs are few (at most max(8, N/64)) and more than twice
/// the median radius; sizing the grid by them would put hundreds of small discs in every cell.
/// Returns +infinity when there are no big discs. O(N log N).
[[nodiscard]] double big_radius_threshold(const std::vector<double>& radii);

/// Deepest overlap max(0, r_i + r_j - |r_ij|) over all pairs (minimum image in periodic boxes;
/// positions may be unwrapped). Uses a temporary cell grid: O(N) for equal discs, plus
/// O(N) per big disc. Allocates.
[[nodiscard]] double max_overlap(const std::vector<Vec2>& positions,
                                 const std::vector<double>& radii, const Box& box);

/// Sum of pi r^2 over the box area.
[[nodiscard]] double packing_fraction(const std::vector<double>& radii, const Box& box);

/// Counts of disc speeds in `bins` equal bins over [0, v_max); speeds >= v_max go to the last bin.
/// v_max <= 0 means "the largest speed in the snapshot". Compare with the 2D Maxwell-Boltzmann
/// (Rayleigh) density f(v) = (m v / kT) exp(-m v^2 / 2kT). Throws Error(input) for bins == 0.
[[nodiscard]] std::vector<std::uint64_t> speed_histogram(const Snapshot& snapshot, std::size_t bins,
                                                         double v_max = 0.0);

/// What an engine accumulates as it resolves collisions, for pressure.
struct ImpulseTally {
    double virial = 0.0;        ///< sum over pair collisions of |r_ij . dp_i| (length x momentum)
    double wall_impulse = 0.0;  ///< sum over wall collisions of |dp| given to the walls
};

/// Fills the thermodynamic fields of m (kinetic_energy, momentum, temperature, pressure,
/// compressibility, packing_fraction) from the particles' velocities and masses at time m.t,
/// with impulses accumulated over [0, m.t], in D dimensions (D degrees of freedom per particle:
/// kT = 2 KE / (D N)). Periodic boxes use the collision virial, Z = 1 + virial / (D N kT t),
/// P = Z N kT / V; walled boxes the wall impulse per unit wall length (2D) or area (3D) and time.
template <int D>
void fill_thermodynamics(Measurements& m, const std::vector<typename Space<D>::Vec>& velocities,
                         const std::vector<double>& masses, const std::vector<double>& radii,
                         const typename Space<D>::Box& box, const ImpulseTally& tally);

/// The 2D form: fill_thermodynamics<2>.
inline void fill_thermodynamics(Measurements& m, const std::vector<Vec2>& velocities,
                                const std::vector<double>& masses, const std::vector<double>& radii,
                                const Box& box, const ImpulseTally& tally) {
    fill_thermodynamics<2>(m, velocities, masses, radii, box, tally);
}

/// Sum of the particles' areas (2D) or volumes (3D) over the box's.
template <int D>
[[nodiscard]] double packing_fraction_of(const std::vector<double>& radii,
                                         const typename Space<D>::Box& box);

/// 3D: the deepest overlap max(0, r_i + r_j - |r_ij|) over all pairs of spheres (minimum image
/// in periodic boxes), through a temporary cell grid sized by the largest sphere: O(N) for
/// spheres of similar sizes. Allocates.
[[nodiscard]] double max_overlap(const std::vector<Vec3>& positions,
                                 const std::vector<double>& radii, const Box3& box);

}  // namespace collide::sim
