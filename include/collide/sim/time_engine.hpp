#pragma once
/// \file
/// The lecture's naive, time-driven method, built faithfully so that its failures are real and
/// visible: discretise time in quanta dt, move every disc, check pairs for overlap, roll colliding
/// pairs back to contact, resolve, continue. Collisions that happen entirely inside one quantum
/// (fast discs passing through each other, or through a wall) are not fixed: they are measured.
///
/// Step k ends at exactly k dt (computed as k * dt from t = 0, never as a running sum), whoever
/// calls advance_to and however often: a video at any frame rate, a thumbnail, `simulate` and the
/// events log see the same state, bit for bit, after the same step. Between steps the engine has
/// no state: advance_to(t) takes the whole steps that end at or before t, and snapshots and
/// measurements describe the latest one (time() is t, Snapshot::time and Measurements::t the
/// step's time).
///
/// One step of length h (dt, up to the rounding of k dt - (k - 1) dt):
///  1. drift    every disc moves in a straight line for h.
///  2. detect   every pair is tested once for overlap (all-pairs: N(N-1)/2 tests, counted in
///              Measurements::overlap_checks; `grid`: only pairs in neighbouring cells, with the
///              same outcome). All-pairs tests every pair in a vectorised sweep against a
///              conservative bound (could it have touched during the step?) and runs the exact
///              tests below on the few pairs it keeps, in the plain loop's order.
///              A pair that overlaps and approaches (dv.dr < 0) becomes a contact.
///              A disc that straddles a wall line of a walled box and moves outwards becomes a wall
///              contact. A disc entirely past a wall is not touching it: it is not reflected and
///              keeps flying (it has escaped; Measurements::escaped, DiscState::escaped).
///  3. resolve  contacts are processed one at a time in a deterministic order: by the contact
///              time estimated at detection, then kind (pair, x wall, y wall), then disc ids.
///              "Roll back to contact" means, for a pair, with the discs' *current* positions p
///              and velocities v at the end of the step: reconstruct where their straight paths
///              were at the start of the step (p - h v), solve the pair's quadratic from there
///              with kinematics::time_to_hit to get the contact time t_c in [0, h] (clamped; a pair
///              already overlapping at the start of the step is rolled back the whole step), move
///              both discs back by s = h - t_c along their current velocities, resolve with
///              kinematics::resolve_pair, and move both forward by s with the new velocities.
///              Walls likewise with kinematics::time_to_wall and a reflected velocity component.
///              A disc in several contacts is handled pair by pair in that order, each time with
///              its velocity as updated by the earlier ones (so its reconstructed history is only
///              approximate: that is the naive method). A contact that no longer overlaps or no
///              longer approaches when its turn comes is skipped. Overlaps created by a
///              resolution are seen only at the next step.
///  4. wrap     positions are folded back into a periodic box.
///
/// Reporting only (it changes nothing): a pair that does not overlap at the end of a step but whose
/// straight paths from the start of the step touch at a time in [0, h) (kinematics::time_to_hit on
/// the step's start positions and velocities) is a missed collision; so is a pair apart at the
/// start of the step that overlaps at its end but already parts (a glancing contact, in and
/// turning out between two checks: nothing resolves a parting overlap), counted once, at the
/// step it went in. Each is counted in Measurements::missed_collisions and its contact point is
/// kept as a marker in Snapshot::missed_collisions. Wall tunnelling is reported through `escaped`
/// instead. A missed pair of a disc and an immovable one (immovable_mass_ratio times the lightest
/// disc: a piece of a barrier) means the disc went through the barrier: it is flagged
/// (DiscState::tunnelled) and counted with the escaped discs in Measurements::tunnelled.
///
/// Reporting only, too: the first few steps in which the method failed (a pair missed as above,
/// or a disc that crossed a wall line of a walled box during the step and ended entirely past
/// it) are kept as StepFailure records, one per step, so that a lesson can show that step again:
/// of the step's missed pairs (in id order; else its escaped discs, in id order) the first whose
/// discs were in no contact of the step (their state after it is where the drift took them),
/// else the first.
///
/// After each advance_to() a census finds the pairs overlapping now (by more than
/// TimeEngine::contact_slack of their contact distance) and the deepest overlap; snapshot() and
/// measurements() report them. Missed-collision markers accumulate during one advance_to() call
/// and are cleared when the next call starts, so each snapshot (one per frame) carries the misses
/// since the previous frame.
///
/// One code for discs and spheres: BasicTimeEngine<D> is a template over the dimension (its
/// Space: vector, box, scene), with a wall contact per axis (zwall in 3D), the all-pairs sweep
/// over D coordinates and a grid of 3^D-cell neighbourhoods. TimeEngine is the 2D engine (discs),
/// TimeSphereEngine the 3D one.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>
#include <utility>
#include <vector>

#include "collide/scene.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/engine_core.hpp"
#include "collide/space.hpp"

namespace collide {

/// Throws Error(input) unless options.dt is finite and > 0, naming `dt_field`. The time-driven
/// engine calls it on construction.
void validate_time_driven_options(const EngineOptions& options, std::string_view dt_field = "dt");

}  // namespace collide

namespace collide::sim {

/// What went wrong in a step (StepFailure).
enum class StepFailureKind {
    missed_pair,  ///< two discs' straight paths touched during the step, no check saw it
    left_box,     ///< a disc crossed a wall line during the step and ended entirely past it
};

/// One step of the time-driven method that failed, as the engine saw it: the step from
/// step * dt to (step + 1) * dt and the discs involved (b: pairs only), with their states at
/// both ends of the step. Plain data, neutral: a lesson decides what to draw of it.
template <int D>
struct BasicStepFailure {
    using Vec = typename Space<D>::Vec;
    StepFailureKind kind = StepFailureKind::missed_pair;
    std::uint64_t step = 0;  ///< k: the state before is at k dt, after at (k + 1) dt
    std::uint32_t a = 0;
    std::uint32_t b = 0;  ///< pairs only (a < b)
    /// Positions at k dt (the straight paths traced back over the step: p - h v).
    Vec before_a{};
    Vec before_b{};
    /// Positions at (k + 1) dt: the engine's state after the step (wrapped, resolved).
    Vec after_a{};
    Vec after_b{};
    /// The straight move of each disc during the step (h v, not wrapped): before + motion is
    /// where the drift took it, before any contact of the step was resolved.
    Vec motion_a{};
    Vec motion_b{};
    double radius_a = 0.0;
    double radius_b = 0.0;
    /// Time into the step at which the straight paths touched (pair) or the disc's centre
    /// crossed the wall line (left_box), in [0, h].
    double contact = 0.0;
    /// Where: the contact point of the two discs (pair), the centre's crossing of the wall line
    /// (left_box), at `contact` along the straight paths (not wrapped).
    Vec where{};
};

namespace detail {
template <int D>
class BasicCellGrid;
template <int D>
class BasicPairSweep;
}  // namespace detail

/// The time-driven engine (`--engine time`). Deterministic: the same scene and options give the
/// same snapshots and the same collision records. Cost per step: all-pairs O(N^2), grid about
/// O(N) for a gas (cells are at least 2 r_max + 2 v_max h wide, so fast discs make them large).
template <int D>
class BasicTimeEngine final : public EngineOf<D> {
  public:
    using Space = collide::Space<D>;
    using Vec = typename Space::Vec;
    using BoxType = typename Space::Box;
    using SceneType = typename Space::Scene;

    /// Relative tolerance on the contact distance sigma under which two discs count as touching,
    /// not overlapping, in the census: rollback leaves a pair at contact up to rounding (~1e-16).
    static constexpr double contact_slack = 1e-9;
    /// At most this many missed-collision markers are kept per advance_to() call, so that a
    /// silly dt cannot exhaust memory; the count in Measurements stays exact.
    static constexpr std::size_t max_markers_per_frame = 100000;

    /// The scene must be valid (positive radii and masses, finite values). Throws Error(input)
    /// naming `dt` for a bad time step (validate_time_driven_options).
    BasicTimeEngine(const SceneType& scene, const EngineOptions& options);
    ~BasicTimeEngine() override;

    /// A step that would end within this fraction of dt after t still counts as ending at or
    /// before t: frame times (multiples of 1/30, say) that are whole numbers of steps are not
    /// exact multiples of dt in floating point.
    static constexpr double landing_tolerance = 1e-6;

    /// The number of whole steps of dt that end at or before t (step k ends at k * dt, within
    /// landing_tolerance dt): 0 for t <= 0. O(1).
    [[nodiscard]] static std::uint64_t whole_steps(double t, double dt) noexcept;

    /// Takes the steps of dt that end at or before t (whole_steps(t, dt)), so that the state is
    /// the latest whole step's; time() becomes t. Throws Error(input) (sim::require_forward) if
    /// t < time() or t is not finite.
    void advance_to(double t) override;
    /// The time asked for by the latest advance_to (the state is at the latest step before it).
    [[nodiscard]] double time() const noexcept override { return clock_; }
    /// Discs at the latest whole step (Snapshot::time = k dt), with the escaped flags, the pairs
    /// overlapping now and the markers of the collisions missed during the last advance_to() call.
    [[nodiscard]] SnapshotOf<D> snapshot() const override;
    /// Everything measured so far; O(N).
    [[nodiscard]] Measurements measurements() const override;
    /// Called for every resolved contact, in processing order, with the contact time solved in the
    /// step (for walls, b = 0).
    void set_collision_listener(CollisionListener listener) override;

    /// At most this many StepFailure records are kept (the earliest failing steps).
    static constexpr std::size_t max_failure_records = 8;
    /// The earliest steps that failed so far, one record per step, in step order (at most
    /// max_failure_records). O(1).
    [[nodiscard]] const std::vector<BasicStepFailure<D>>& failures() const noexcept {
        return failures_;
    }
    /// Forgets the records kept so far, so that the next failing steps are recorded again (a
    /// lesson looking for a failure after a given moment). O(1).
    void forget_failures() noexcept { failures_.clear(); }

  private:
    /// A contact found by the overlap checks of one step, waiting to be resolved.
    struct Contact {
        double t_estimate = 0.0;  ///< contact time within the step, from the detection state
        CollisionKind kind = CollisionKind::pair;
        std::uint32_t a = 0;
        std::uint32_t b = 0;  ///< pairs only
    };

    void step(double h);
    void drift(double h);
    void detect_pair_contacts(double h);
    void detect_wall_contacts(double h);
    void resolve_contacts(double h);
    void resolve_pair_contact(const Contact& contact, double h);
    void resolve_wall_contact(const Contact& contact, double h);
    void wrap_positions();
    void take_census();
    /// Records disc i as the step's failure if it went through a wall during the step.
    void record_escape(std::uint32_t i, double h);
    /// The step's failure record (if the step failed and records are still kept) gets the
    /// states after the step.
    void finish_failure_record();
    /// True while failing steps are still recorded.
    [[nodiscard]] bool recording_failures() const noexcept {
        return failures_.size() < max_failure_records;
    }
    /// COLLIDE_VALIDATE builds, after every step: finite state, kinetic energy conserved (every
    /// resolution is elastic). Throws Error(runtime) naming the broken invariant. O(N).
    void validate_state() const;
    void move(std::uint32_t i, Vec delta);
    /// Entirely past a wall line along some axis (an escape, in a walled box).
    [[nodiscard]] bool is_outside(Vec p, double r) const noexcept;
    [[nodiscard]] double max_speed() const noexcept;
    [[nodiscard]] double kinetic_energy() const noexcept;
    /// Heap memory held by the engine's containers (capacity), for Measurements::engine_bytes.
    [[nodiscard]] std::uint64_t bytes() const noexcept;

    /// Calls visit(i, j), i < j, for every pair that may have touched during the step of length h
    /// that just ended, and some farther ones; the visitor makes the exact tests. Adds the pairs
    /// tested (all-pairs: N(N-1)/2) to overlap_checks_.
    template <typename PairVisitor>
    void for_each_candidate_pair(double h, PairVisitor&& visit);

    BasicEngineCore<D> core_;
    BoxType box_;
    Vec extent_;  ///< the box's sides (width, height[, depth])
    double dt_;
    bool use_grid_;
    double max_radius_ = 0.0;
    double initial_energy_ = 0.0;

    // Per-disc state, in scene order.
    std::vector<Vec> position_;
    std::vector<Vec> velocity_;
    std::vector<Vec> displacement_;  ///< unwrapped displacement since t = 0 (mean squared displ.)
    std::vector<double> radius_;
    std::vector<double> mass_;
    std::vector<bool> escaped_;
    std::vector<bool> through_barrier_;  ///< went through an immovable disc at least once
    double immovable_mass_ = 0.0;        ///< from this mass on a disc is immovable (a barrier)

    double time_ = 0.0;        ///< the state's time: steps_ * dt
    double clock_ = 0.0;       ///< the time asked for by the latest advance_to (time_ is at most
                               ///< landing_tolerance dt later)
    double step_start_ = 0.0;  ///< simulation time at which the current step began
    std::vector<Contact> contacts_;
    std::unique_ptr<detail::BasicCellGrid<D>> grid_;
    std::unique_ptr<detail::BasicPairSweep<D>> sweep_;                 ///< all-pairs detection
    std::vector<std::pair<std::uint32_t, std::uint32_t>> candidates_;  ///< from sweep_, reused

    // Failure markers and census (recomputed after each advance_to).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> overlapping_pairs_;
    std::vector<Vec> missed_markers_;
    double max_overlap_ = 0.0;
    std::uint64_t escaped_count_ = 0;
    std::uint64_t tunnelled_count_ = 0;  ///< discs escaped or through a barrier
    /// Discs the census has found overlapping at the end of some advance_to: a failure the
    /// video showed stays counted after the pair has parted (Measurements::discs_overlapped).
    std::vector<bool> overlapped_;
    std::uint64_t overlapped_count_ = 0;
    std::vector<BasicStepFailure<D>> failures_;
    /// The current step's failures, while records are kept (at most max_step_candidates).
    std::vector<BasicStepFailure<D>> step_candidates_;
    static constexpr std::size_t max_step_candidates = 64;
    bool step_failed_ = false;  ///< the current step failed (step_candidates_ holds its failures)

    // Counters.
    std::uint64_t steps_ = 0;  ///< steps taken since t = 0: the state is at steps_ * dt
    std::uint64_t overlap_checks_ = 0;
    std::uint64_t missed_ = 0;
    double max_overlap_seen_ = 0.0;
};

extern template class BasicTimeEngine<2>;
extern template class BasicTimeEngine<3>;

/// The time-driven engine of discs (`--engine time`).
using TimeEngine = BasicTimeEngine<2>;
/// A failed step of the time-driven engine of discs.
using StepFailure = BasicStepFailure<2>;
/// The time-driven engine of spheres (3D scenes).
using TimeSphereEngine = BasicTimeEngine<3>;

}  // namespace collide::sim
