#pragma once
/// \file
/// How much work a run will be, estimated before it starts (std-only, pure): the CLI refuses runs
/// that cannot finish in any sensible time (`--dt 1e-300`, `--until 1e300`, a disc at 1e50 units
/// per second) with a message that gives the estimate, instead of running until killed.
///
/// The estimates are orders of magnitude, not predictions: collisions come from the kinetic
/// theory of a hard-disc gas (see collision_rate), steps from span / dt.

#include <cstddef>
#include <string>

#include "collide/scene.hpp"

namespace collide {

/// Expected collisions per unit of simulation time in a scene, from kinetic theory.
struct CollisionRate {
    double pairs = 0.0;  ///< disc-disc collisions per time unit
    double walls = 0.0;  ///< disc-wall collisions per time unit (0 in a periodic box)
    [[nodiscard]] double total() const noexcept { return pairs + walls; }
};

/// The collision rate of `scene` at t = 0 (speeds are conserved on average, so the rate holds for
/// the whole run). Pairs: a disc moving at |v_i| through discs of number density
/// n = (N - 1) / area sweeps a width 2 d (d = 2 * mean radius: centres pass within d) and meets
/// 2 d n |v_i| others per time unit, raised by the contact value of the pair correlation g(eta)
/// (Henderson's 2D equation of state: g = (1 - 7 eta / 16) / (1 - eta)^2, eta capped at 0.9);
/// in total g * n * 2 d * sum |v_i| / sqrt(2) (two discs per collision; the relative speed is
/// sqrt(2) times the mean speed in a thermal gas). Walls: the 2D kinetic flux n <v> / pi per unit
/// of wall length, times the crowding at the wall (1 + 2 eta g), over the perimeter:
/// (1 + 2 eta g) * (2 / pi) * sum |v_i| * (1 / width + 1 / height). Within 10 % of the engines'
/// counts for melted gases at eta = 0.05..0.5 (tests/sim/test_work_estimate.cpp). O(N); infinite
/// when a speed is so large that the sum overflows.
[[nodiscard]] CollisionRate collision_rate(const Scene& scene) noexcept;

/// Cell crossings per unit of simulation time in the fast engine's grid (collide/sim/
/// fast_engine.hpp): about max(9, 2 N) cells, none narrower than a disc diameter, and a disc at
/// velocity v crosses |v_x| / cell width + |v_y| / cell height cell walls per time unit. These are
/// events too: a lone disc in a periodic box never collides but crosses cells forever. O(N).
[[nodiscard]] double cell_crossing_rate(const Scene& scene) noexcept;

/// What a run is asked to do.
struct RunShape {
    double span = 0.0;          ///< simulation time from the start to the end of the run
    bool event_driven = false;  ///< an event-driven engine runs over the span
    bool cell_grid = false;     ///< that engine is the fast one, whose events include crossings
    bool time_driven = false;   ///< a time-driven engine runs over the span
    double dt = 0.0;            ///< the time-driven step
    bool all_pairs = true;      ///< time-driven overlap checks: all pairs, else a cell grid
    double frames = 0.0;        ///< frames taken (0 for a run without frames)
    /// The event-driven engine is the classic one, which predicts each event's two discs against
    /// all N discs: O(N) work per event where the fast engine's cell grid does O(1).
    bool classic = false;
    /// Its queue is an array (unordered or ordered) whose remove or insert costs O(queue size).
    bool array_queue = false;
};

/// The share of the classic engine's predictions that are finite and pushed: 0.9 % (brownian,
/// diffusion) to 7 % (dense-fluid) and 10 % (gas) measured with `collide simulate --json`
/// (pq_pushes / predictions); the lowest is taken, so the estimate errs on the side of running.
inline constexpr double classic_finite_fraction = 0.01;

/// The estimated work of a run; every field is >= 0 and may be +inf.
struct WorkEstimate {
    double collisions = 0.0;   ///< event-driven collisions expected over the span
    double crossings = 0.0;    ///< the fast engine's cell crossings over the span
    double steps = 0.0;        ///< time-driven steps: span / dt
    double pair_checks = 0.0;  ///< time-driven overlap checks: steps * N (N - 1) / 2, or with a
                               ///< grid steps * N * grid_checks_per_disc
    double frames = 0.0;       ///< frames, as given
    /// The classic engine's pair predictions: N (N - 1) / 2 at the start, then 2 N per event.
    double predictions = 0.0;
    /// Entries an array queue walks over. With lazy invalidation the queue keeps every event
    /// pushed until its time comes: it starts with about N entries and every event adds the
    /// finite predictions of its two discs, p = max(2, classic_finite_fraction * 2 N), so event k
    /// costs about N + k p steps: in total events * N + p * events^2 / 2.
    double queue_steps = 0.0;
    /// span + dt == span: the time-driven engine's clock cannot move by dt at the run's end, so
    /// the run could never finish, however long one waits.
    bool dt_below_resolution = false;
};

/// A cell-grid step checks each disc against about this many neighbours (the 3x3 cells around it
/// at the densities the generators make); only an order of magnitude matters.
inline constexpr double grid_checks_per_disc = 10.0;

/// Estimates the work of `run` on `scene`. O(N) (one pass for the collision rate).
[[nodiscard]] WorkEstimate estimate_work(const Scene& scene, const RunShape& run) noexcept;

/// What estimate_work does once it has the scene's rates: the work of `run` on `particles`
/// discs or spheres that collide collisions_per_time times and cross cells crossings_per_time
/// times per time unit. The part that does not depend on the dimension (3D: sphere_check.hpp).
[[nodiscard]] WorkEstimate estimate_work_at_rates(double collisions_per_time,
                                                  double crossings_per_time, std::size_t particles,
                                                  const RunShape& run) noexcept;

/// The most work a run may take without the user insisting (`--no-limits`): each limit is about
/// an hour or more of computing on a laptop core, far beyond any lesson's video.
struct WorkLimits {
    double events = 1e10;       ///< collisions and cell crossings: a few million per second,
                                ///< so about an hour
    double steps = 1e9;         ///< time-driven steps, whatever their size
    double pair_checks = 1e13;  ///< at ~10^9 checks per second: about three hours
    double frames = 1e7;        ///< frames a run goes through (a still passes all before its own)
    double predictions = 1e11;  ///< the classic engine's, at ~3 * 10^7 a second: about an hour
    double queue_steps = 3e12;  ///< an array queue's, at ~10^9 a second (a scan): about an hour
};

/// Which limit a run exceeds, and by how much.
struct WorkExcess {
    std::string what;       ///< "collisions", "time-driven steps", "overlap checks", "frames"
    double estimate = 0.0;  ///< the estimate of that quantity
    double limit = 0.0;     ///< its limit
    /// limit / estimate: multiply the span (or the frame count) by this to fit. In (0, 1).
    [[nodiscard]] double fitting_fraction() const noexcept { return limit / estimate; }
};

/// The limit `work` exceeds the most (largest estimate / limit); `what` is empty when none is
/// exceeded.
[[nodiscard]] WorkExcess first_excess(const WorkEstimate& work, const WorkLimits& limits = {});

/// "3.2e+12" for big estimates, "4500" for small ones: numbers for messages.
[[nodiscard]] std::string rough_number(double value);

}  // namespace collide
