#pragma once
/// \file
/// The fast event-driven engine: the same physics as the classic loop, organised so that an event
/// costs O(1) on average instead of O(N), whatever N.
///
/// - Cell grid. Cells are at least one small-disc diameter wide, so a small disc can only touch
///   discs in its own and the eight neighbouring cells. Crossing into another cell is an event of
///   its own (kind `cell`), after which the disc is predicted against its new neighbours: only
///   the three cells it newly borders, because each disc remembers the earliest pair event of
///   its scans since its last full scan (valid while that partner has not collided since).
/// - Local clocks. Each disc stores its state at its own last event time; nothing is advanced
///   unless it takes part in an event (no O(N) drift per event).
/// - One pending event per disc. The disc's earliest predicted event is its key (handle = disc
///   index) in an event calendar (pq::CalendarQueue: an indexed 4-ary heap for the current block
///   of time, unordered lists for later blocks) and is replaced in place, so the queue holds at
///   most N entries and nothing stale accumulates. A pair event held by i names its partner j and
///   j's collision count; if j has collided since, the pop re-predicts i (a "stale pop"). The
///   calendar pops in the order of one heap of all keys (a watched disc engine keeps it as that
///   one heap, the queue view's tree).
/// - Mixed radii. The grid is sized by the small discs. A few big discs (see
///   sim::big_radius_threshold) are kept out of the cell lists, in a separate list that every
///   small disc checks on each prediction (cheap: few of them); a big disc checks the small discs
///   in the ring of cells it can reach before it leaves its centre cell, and all other big discs.
///   This keeps the cells small (the small discs keep their speed) without registering a big disc
///   in hundreds of cells.
/// - Compact data: one 64-byte record per disc for the fields a neighbour scan reads, 32-bit
///   indices, intrusive cell lists, no allocation per event.
///
/// - Neighbour lists (3D; Smallenburg, Eur. Phys. J. E 45, 22, 2022). A sphere in a cell scan
///   meets ~26 candidates of which ~6 are near; instead each sphere keeps the list of spheres
///   whose list centres were within r_i + r_j + shell of its own when the later of the two was
///   built (the lists are symmetric), and predicts pairs against that list only. A sphere's list
///   expires when it has moved shell / 2 from its centre (an event of kind `cell`, "rebuild"):
///   two spheres outside each other's lists cannot touch before one of them rebuilds. Each entry
///   keeps the periodic image through which the pair meets, so a scan never works out the
///   nearest image. The grid then holds list centres, in cells at least 2 r_max + shell wide,
///   and has no crossing events. Used in 3D at packing fractions from 0.38 (below, a sphere would
///   rebuild several times between collisions) when no sphere is big and a periodic box has three
///   such cells per axis; otherwise, and in 2D, the cell crossings above.
///
/// Periodic boxes need at least three cells per axis (three small-disc diameters); the
/// constructor throws Error(input) naming `box.width` / `box.height` / `box.depth` otherwise.
///
/// One code for discs and spheres: BasicFastEngine<D> is a template over the dimension (its
/// Space: vector, box, scene) and the cell neighbourhood (3^D cells; a crossing scans the 3^(D-1)
/// cells it newly borders). FastEngine is the 2D engine (discs), FastSphereEngine the 3D one.

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

#include "collide/scene.hpp"
#include "collide/scene3.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/engine_core.hpp"
#include "collide/sim/engine_support.hpp"
#include "collide/sim/event.hpp"
#include "collide/sim/kinematics.hpp"
#include "collide/sim/observables.hpp"
#include "collide/sim/pq/cache_layout.hpp"
#include "collide/sim/pq/calendar_queue.hpp"
#include "collide/sim/pq/indexed_heap.hpp"
#include "collide/sim/queue_view.hpp"
#include "collide/space.hpp"

namespace collide::sim {

template <int D>
class BasicFastEngine final : public EngineOf<D> {
  public:
    using Space = collide::Space<D>;
    using Vec = typename Space::Vec;
    using BoxType = typename Space::Box;
    using SceneType = typename Space::Scene;

    /// Builds the grid and predicts every particle's first event: O(N) expected time and memory.
    /// Throws Error(input) when a periodic box is too small for a grid of 3 cells per axis.
    /// `stop` (set_stop_flag) is looked at between the phases and every few thousand particles
    /// within one: building 4 M spheres takes seconds, and a set flag throws Error(runtime,
    /// "simulation stopped") within milliseconds.
    explicit BasicFastEngine(const SceneType& scene, const std::atomic<bool>* stop = nullptr);

    /// False when the fast engine's grid cannot hold the scene (a periodic box narrower than
    /// three small-particle diameters along some axis); make_engine then falls back to the
    /// classic loop.
    [[nodiscard]] static bool can_simulate(const SceneType& scene);

    void advance_to(double t) override;
    [[nodiscard]] double time() const noexcept override { return now_; }
    [[nodiscard]] SnapshotOf<D> snapshot() const override;
    [[nodiscard]] Measurements measurements() const override;
    void set_collision_listener(CollisionListener listener) override {
        core_.set_listener(std::move(listener));
    }
    /// Discs watched show their queue as the one heap of every pending event (the calendar
    /// turned into one block: the same pops, the lecture's tree).
    bool watch_queue(const QueueViewLimits& limits) override {
        watch_.start(limits);
        if constexpr (D == 2) tune_calendar();
        return true;
    }
    /// See Engine::clone: a member-wise copy (the scene order, which the heap's order reads, is
    /// shared: it never changes after construction); the listener is dropped.
    [[nodiscard]] std::unique_ptr<EngineOf<D>> clone() const override;

    /// Grid cells along one axis (for tests and the benchmark report).
    [[nodiscard]] std::uint32_t cells_along(int axis) const noexcept { return n_[axis]; }
    /// Number of particles handled as big (separate list).
    [[nodiscard]] std::size_t big_disc_count() const noexcept { return big_.size(); }
    /// True when pairs are predicted from neighbour lists (see the file comment).
    [[nodiscard]] bool uses_neighbour_lists() const noexcept { return lists(); }
    /// Slots per neighbour list (they double when one overflows); 0 without lists.
    [[nodiscard]] std::uint32_t list_slots() const noexcept { return list_cap_; }
    /// Slots per grid cell of list centres (they double when a cell overflows); 0 without lists.
    [[nodiscard]] std::uint32_t cell_slots() const noexcept { return cell_slots_; }
    /// Heap memory held by the engine's containers, in bytes (capacities, not sizes).
    [[nodiscard]] std::uint64_t bytes() const noexcept;
    /// O(N) consistency check (cell membership, heap invariants, one event per disc); for tests,
    /// and run at the end of every advance_to() in COLLIDE_VALIDATE builds (Error(runtime) when
    /// it fails).
    [[nodiscard]] bool check_invariants() const;

  private:
    /// Through clone() only (it drops the listener a plain copy would share).
    BasicFastEngine(const BasicFastEngine&) = default;

    /// What a neighbour scan and an event on the particle read, in one cache line in 2D (80 bytes
    /// in 3D). Counters that each event reads for both particles sit here too: as separate arrays
    /// they cost a cache miss per particle and per array at large N (the access pattern jumps
    /// across the whole box).
    struct alignas(D == 2 ? 64 : 16) Particle {
        Vec x;                ///< position at local time t (periodic: within one cell of the box)
        Vec v;                ///< velocity
        double t;             ///< local clock: the time the position refers to
        double r;             ///< radius
        std::uint32_t next;   ///< next particle in the same cell list (no_disc ends it)
        std::uint32_t cell;   ///< cell of the centre (linear index), tracked by cell events
        std::uint32_t count;  ///< collisions of this particle (invalidates partners' events)
        std::uint32_t last_partner;  ///< see sim::just_collided_slack
    };
    static_assert(D != 2 || sizeof(Particle) == 64, "one cache line per disc");

    /// What only the particle's own events read (mass at collisions, list links at crossings, its
    /// earliest pair event), kept out of the neighbour scans' cache lines.
    struct Cold {
        double m = 0.0;  ///< mass
        /// The earliest pair event found by the particle's scans since its last full prediction
        /// (+inf: none): the pair part of its pending event. A crossing keeps it and scans only
        /// the newly bordering cells, unless the partner has collided since (then all 3^D).
        double pair_t = kinematics::never;
        std::uint32_t pair_partner = no_disc;
        std::uint32_t pair_count = 0;  ///< the partner's collision count when pair_t was predicted
        /// Previous particle in the cell list (O(1) unlink); with neighbour lists, the particle's
        /// slot in its cell's members_.
        std::uint32_t prev = 0;
        /// Collisions in the particle's current instant (sim::same_instant), for the jam bound
        /// (see count_collision_now); fills the record's padding.
        std::uint32_t instant_collisions = 0;
    };
    static_assert(sizeof(Cold) == 32, "the jam counter fits in the padding");

    /// A particle's pending event in 16 bytes (four keys per cache line in the heap): the time,
    /// the particle that holds it (its heap handle, so the heap keeps no handle array), and the
    /// kind packed above the second index (pairs: the partner; walls: unused; cells: the axis).
    /// Hence at most 2^29 - 1 particles.
    struct Key {
        static constexpr std::uint32_t kind_shift = 29;
        static constexpr std::uint32_t index_mask = (1U << kind_shift) - 1;
        double t;
        std::uint32_t a;
        std::uint32_t kind_b;

        static Key make(double t, std::uint32_t a, std::uint32_t b, EventKind kind) noexcept {
            return Key{t, a, (static_cast<std::uint32_t>(kind) << kind_shift) | (b & index_mask)};
        }
        [[nodiscard]] EventKind kind() const noexcept {
            return static_cast<EventKind>(kind_b >> kind_shift);
        }
        [[nodiscard]] std::uint32_t b() const noexcept { return kind_b & index_mask; }
    };
    /// Time, then kind, then the particles' scene indices (pairs: smaller, larger; others:
    /// particle, b): the strict order of sim::EventLess, so ties fall as in the classic engine
    /// although the fast engine numbers particles internally in space-filling-curve order.
    struct KeyLess {
        const std::vector<std::uint32_t>* scene_index = nullptr;  ///< see scene_index_

        [[nodiscard]] bool operator()(const Key& x, const Key& y) const noexcept {
            // Same order as "times differ: earlier first; else tie_break", written so that the
            // common case is one compare the compiler can turn into a conditional move.
            return x.t < y.t || (x.t == y.t && tie_break(x, y));
        }
        [[nodiscard]] bool tie_break(const Key& x, const Key& y) const noexcept;
    };
    struct KeyOwner {
        [[nodiscard]] std::uint32_t operator()(const Key& k) const noexcept { return k.a; }
    };
    using Heap = pq::IndexedDaryHeap<Key, pq::Orientation::min, 4, KeyLess, KeyOwner>;
    /// An event calendar (most events are rescheduled far ahead, in O(1)); for discs since issue
    /// 47 (1.1x the one heap's speed up to 5x10^4 discs), run as one block, a plain heap, when
    /// there are more (it lost there) or when the queue is watched (tune_calendar).
    using Queue = pq::CalendarQueue<Key, KeyLess, KeyOwner>;

    /// Times the particle wrapped across the high (+) or low (-) edge, per axis.
    using Image = std::array<std::int32_t, D>;
    /// Cell coordinates of a linear cell index, or offsets from a cell.
    using Coords = std::array<std::int64_t, D>;

    // --- construction
    void choose_grid(const SceneType& scene);
    void place_discs(const SceneType& scene);
    [[nodiscard]] std::vector<std::uint32_t> locality_order(const SceneType& scene) const;
    [[nodiscard]] std::uint32_t cell_of(Vec x) const noexcept;
    [[nodiscard]] Coords coords_of(std::uint32_t cell) const noexcept;
    [[nodiscard]] std::uint32_t cell_at(const Coords& c) const noexcept;
    /// Offsets -1 and +1 along every axis: the 3^D cells around a cell.
    [[nodiscard]] static constexpr Coords neighbourhood_lo() noexcept {
        Coords c{};
        c.fill(-1);
        return c;
    }
    [[nodiscard]] static constexpr Coords neighbourhood_hi() noexcept {
        Coords c{};
        c.fill(1);
        return c;
    }

    // --- the loop's phases
    void process(std::uint32_t i, const Key& key);
    void process_pair(std::uint32_t i, std::uint32_t j, double t);
    void process_wall(std::uint32_t i, EventKind kind, double t);
    void process_cell(std::uint32_t i, std::uint32_t axis);
    /// Counts a collision of particle i at now_, before it is advanced; throws when i is jammed
    /// (sim::instant_collision_limit).
    void count_collision_now(std::uint32_t i);

    // --- prediction
    void predict(std::uint32_t i);
    /// i's earliest event (its pair remembered), not yet queued: predict(i) without enqueue.
    [[nodiscard]] Key next_event(std::uint32_t i);
    void predict_after_crossing(std::uint32_t i, std::uint32_t axis);
    /// The earliest of pair and i's walls and crossings (the pair remembered).
    [[nodiscard]] Key schedule(std::uint32_t i, const Particle& pi, Vec xi, const Key& pair);
    /// With lists: the earliest of i's walls, list expiry and listed pairs.
    [[nodiscard]] Key predict_listed(std::uint32_t i, const Particle& pi, Vec xi);
    /// Keeps i's earliest pair (never: none) in cold_ (the stale check and crossings read it).
    [[gnu::always_inline]] void remember_pair(std::uint32_t i, const Key& pair) noexcept;
    /// Makes best i's one queued event (none when best.t is never).
    [[gnu::always_inline]] void enqueue(std::uint32_t i, const Key& best);
    /// True when the pair cannot have an event before best_t (cheap bound, no sqrt or division).
    [[nodiscard]] bool cannot_beat(Vec dr, Vec dv, double sigma, double best_t) const noexcept;
    /// cannot_beat's allowance for rounding: the interval to best_t, widened by relative 1e-9
    /// of itself and 1e-14 of the time (a pair may be skipped when c > -2 b times this).
    [[nodiscard]] double beat_margin(double best_t) const noexcept;
    void consider_pair(std::uint32_t i, const Particle& pi, Vec xi, std::uint32_t j, Vec shift,
                       Key& best);
    void consider_pair_images(std::uint32_t i, const Particle& pi, Vec xi, std::uint32_t j,
                              Key& best);
    void scan_small_neighbours(std::uint32_t i, const Particle& pi, Vec xi, Key& best);
    /// Scans the cells at offsets lo[k] .. hi[k] along each axis k from pi's cell.
    void scan_cells(std::uint32_t i, const Particle& pi, Vec xi, const Coords& lo, const Coords& hi,
                    Key& best);
    /// A cell's linear index and the image shift of its wrap, as plain members: Vec's default
    /// member initialisers would zero all 3^D entries on every call (tens of instructions per
    /// prediction for entries never read).
    struct CellVisit {
        std::uint32_t cell;
        std::array<double, D> shift;
    };
    using CellVisits = std::array<CellVisit, D == 2 ? 9 : 27>;  // callers scan at most 3^D cells
    /// Records the non-empty cells at offsets lo .. hi from pi's cell, calling prefetch(cell) on
    /// each, before any list is read: beyond the caches every cell's first record is a miss, and
    /// asking for all of them first overlaps those misses (docs/benchmarks.md). Returns the count.
    template <typename Prefetch>
    std::size_t occupied_cells(const Particle& pi, const Coords& lo, const Coords& hi,
                               CellVisits& visits, Prefetch&& prefetch) const;
    /// Calls visit(cell, shift) for each non-empty cell at offsets lo .. hi from pi's
    /// cell (shift: the periodic image of a wrapped-around cell). The last axis is the outer
    /// loop.
    template <typename Visit>
    void for_each_cell(const Particle& pi, const Coords& lo, const Coords& hi, Visit&& visit) const;
    void scan_list(std::uint32_t i, const Particle& pi, Vec xi, std::uint32_t first, Vec shift,
                   Key& best);
    void scan_ring(std::uint32_t i, const Particle& pi, Vec xi, Key& best);
    /// Offers i's wall events (a walled box) and, without lists, its cell crossings.
    void consider_walls_and_cells(std::uint32_t i, const Particle& pi, Vec xi, Key& best);
    // --- neighbour lists (lists_)
    /// lists_, known false at compile time in 2D (the discs' loop keeps its code as it was).
    [[nodiscard]] bool lists() const noexcept { return D == 3 && lists_; }
    /// Decides lists_ (and the shell) before the grid is sized.
    void choose_lists(const SceneType& scene);
    /// Builds every list from the initial positions.
    void build_all_lists();
    /// Adds to i's list (and i to theirs) the particles whose centres are within reach of i's,
    /// among those in the 3^D cells around i's; `only_after`: only j > i (the first build).
    void gather_neighbours(std::uint32_t i, bool only_after);
    /// Adds j to i's list, seen through periodic image `image` (see list_image_shift).
    void add_neighbour(std::uint32_t i, std::uint32_t j, std::uint32_t image);
    /// Doubles every list's slots (a list is full).
    [[gnu::noinline]] void widen_lists();
    /// Asks the cache for what predict(i) reads from the lists (see prefetch_records_).
    void prefetch_list(std::uint32_t i) const noexcept;
    void remove_neighbour(std::uint32_t i, std::uint32_t j) noexcept;
    void process_rebuild(std::uint32_t i);
    void scan_neighbour_list(std::uint32_t i, const Particle& pi, Vec xi, Key& best);
    /// The image code of shift s (each component 0 or +-the box side): sum of (sign + 1) 3^k.
    [[nodiscard]] static std::uint32_t image_code(const std::array<double, D>& shift) noexcept;
    /// The image code of the shift from j's centre to its nearest image around i's centre.
    [[nodiscard]] std::uint32_t nearest_image_code(std::uint32_t i, std::uint32_t j) const noexcept;
    /// Time until particle i, at xi now, is shell / 2 from its list centre (never at rest).
    [[nodiscard, gnu::always_inline]] double time_to_expiry(std::uint32_t i, const Particle& pi,
                                                            Vec xi) const noexcept;
    [[nodiscard]] bool check_lists() const;

    // --- the queue
    /// Brings the earliest event to the queue's top; false when no event is pending.
    bool settle_queue();
    /// Sizes the calendar's blocks from the pending events (one block, a plain heap, for many
    /// discs or discs whose queue is watched).
    void tune_calendar();

    // --- the queue view (watch_queue)
    /// Particle i's pending event as the view shows it (scene indices; stale when its partner
    /// has collided since it was predicted).
    [[nodiscard]] QueuedEvent queued_event(std::uint32_t i, const Key& key) const noexcept;
    [[nodiscard]] QueueView queue_view() const;

    // --- bookkeeping
    void advance_disc(std::uint32_t i) noexcept;
    void link(std::uint32_t i, std::uint32_t cell);
    void unlink(std::uint32_t i) noexcept;
    /// Doubles every cell's slots in members_ (lists_).
    void widen_cells();
    /// True when the cell holds a particle (its list, or with lists_ its members).
    [[nodiscard]] bool occupied(std::uint32_t cell) const noexcept {
        return lists() ? member_count_[cell] != 0 : head_[cell] != no_disc;
    }
    [[nodiscard]] bool is_big(std::uint32_t i) const noexcept { return p_[i].r > big_threshold_; }
    [[nodiscard]] Vec position_at_now(std::uint32_t i) const noexcept;

    [[nodiscard]] QueueStats& stats() noexcept { return core_.counters().queue; }

    BasicEngineCore<D> core_;
    BoxType box_;
    Vec extent_;  ///< the box's sides (width, height[, depth])
    bool periodic_ = false;
    double now_ = 0.0;

    // grid
    std::array<std::uint32_t, D> n_{};  ///< cells per axis
    Vec cw_{};                          ///< cell sides
    double big_threshold_ = 0.0;        ///< radius above which a particle is big (+inf: none)
    double small_radius_max_ = 0.0;
    pq::BigVector<std::uint32_t> head_;  ///< first particle of each cell list (no_disc: empty)
    /// With neighbour lists the cells hold list centres in arrays instead of linked lists: a
    /// rebuild reads all 27 cells' members at once (cell_slots_ per cell, member_count_ used).
    std::uint32_t cell_slots_ = 0;
    pq::BigVector<std::uint32_t> members_;
    pq::BigVector<std::uint32_t> member_count_;

    // particles
    pq::BigVector<Particle> p_;
    pq::BigVector<Cold> cold_;
    pq::BigVector<Image> image_;  ///< periodic unwrapping (mean squared displacement)
    pq::BigVector<Vec> start_;    ///< positions at t = 0
    /// Particles are numbered internally along a Z-order curve over the cells, so that
    /// neighbours in space are mostly neighbours in memory (at 10^5 discs in scene order every
    /// neighbour was a cache miss). scene_index(i) is the scene's index of internal particle i.
    /// Filled by the constructor and never changed after, so a clone shares it: the heap's order
    /// (KeyLess) holds a pointer to it, and a member-wise copy of that pointer stays valid for
    /// as long as either engine lives.
    std::shared_ptr<std::vector<std::uint32_t>> scene_index_ =
        std::make_shared<std::vector<std::uint32_t>>();
    [[nodiscard]] std::uint32_t scene_index(std::uint32_t i) const noexcept {
        return (*scene_index_)[i];
    }
    std::vector<std::uint32_t> big_;  ///< indices of big particles
    // neighbour lists (lists_ only; see the file comment)
    bool lists_ = false;
    double shell_ = 0.0;   ///< pairs whose centres are within r_i + r_j + shell_ are listed
    double expiry_ = 0.0;  ///< a list expires this far from its centre (shell / 2, a hair less)
    std::uint32_t list_cap_ = 0;  ///< slots per particle in nbr_
    bool equal_radii_ = false;    ///< all particles alike: a rebuild need not read their radii
    /// Records beyond the caches: scans prefetch the listed records, events the lists to scan.
    bool prefetch_records_ = false;
    pq::BigVector<Vec> centre_;  ///< where each particle's list was built
    /// list_cap_ slots per particle, each a neighbour's index and, in the bits from
    /// list_image_shift up, the code of the periodic image through which the particle sees it
    /// (image_shift_): the image is fixed while both lists last (positions wrap only at
    /// rebuilds), so a scan adds the stored shift instead of working out the nearest image.
    pq::BigVector<std::uint32_t> nbr_;
    /// A list entry: the neighbour's index in the low bits, its image code above.
    static constexpr std::uint32_t list_image_shift = 27;
    static constexpr std::uint32_t list_index_mask = (1U << list_image_shift) - 1;
    /// The shift of each image code (3^D codes; the one of no shift is (3^D - 1) / 2).
    std::array<Vec, D == 2 ? 9 : 27> image_shift_{};
    pq::BigVector<std::uint32_t> nbr_count_;  ///< used slots per particle
    /// Per particle, 1 when its list may hold a neighbour seen through a periodic image (set
    /// when such an entry is added, cleared when the particle rebuilds): a scan of a list
    /// without one adds no shifts (about half of all scans at 4000 spheres).
    pq::BigVector<std::uint8_t> wraps_;
    /// The image code of no shift.
    static constexpr std::uint32_t no_image_shift = D == 2 ? 4 : 13;

    KeyLess key_less_{scene_index_.get()};
    Queue queue_{0, key_less_};
    std::uint64_t instant_limit_ = 0;  ///< see count_collision_now
    QueueWatch watch_;  ///< off unless a teaching video asked for the queue (watch_queue)
};

extern template class BasicFastEngine<2>;
extern template class BasicFastEngine<3>;

/// The fast engine of discs (`--engine fast`).
using FastEngine = BasicFastEngine<2>;
/// The fast engine of spheres (3D scenes).
using FastSphereEngine = BasicFastEngine<3>;

}  // namespace collide::sim
