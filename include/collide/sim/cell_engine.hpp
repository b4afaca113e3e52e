#pragma once
/// \file
/// The cell-resident event-driven engine (issue 21): the fast engine's algorithm (cell grid,
/// local clocks, one pending event per disc in an indexed 4-ary heap, big discs apart, the
/// three-cell scan after a crossing) with a different data layout.
///
/// - Disc records live in their cell. Each cell has `slots_per_cell` inline 64-byte slots
///   holding its discs' hot data (position, velocity, local time, radius, id, last partner);
///   discs beyond those go to an overflow region of a shared pool, sized by powers of two and
///   recycled through free lists. The cell's first inline slot also holds the number of discs
///   in the cell and the offset of its overflow region, so a neighbour scan reads the cells'
///   first cache lines, whose addresses it computes without loading anything first (today's
///   fast engine loads a list head, then each disc's record, one after the other).
/// - A crossing moves the record to the neighbour cell: removed from the old cell by moving the
///   cell's last record into its place, appended to the new one. `loc_` (disc id -> cell and
///   position in it) follows each move; events, the heap, snapshots and measurements name discs
///   by id and reach their records through it.
/// - Cells are stored in tiles of tile x tile cells (row-major inside a tile, tiles row-major),
///   so that a 3 x 3 neighbourhood spans few pages.
///
/// The events are the fast engine's: the same predictions in the same order up to which disc of
/// a cell is scanned first (ties fall by EventLess, not by scan order), so classic and cell agree
/// event by event as classic and fast do.

#include <cstdint>
#include <vector>

#include "collide/scene.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/engine_support.hpp"
#include "collide/sim/event.hpp"
#include "collide/sim/kinematics.hpp"
#include "collide/sim/observables.hpp"
#include "collide/sim/pq/calendar_queue.hpp"
#include "collide/sim/pq/indexed_heap.hpp"

namespace collide::sim {

class CellEngine final : public Engine {
  public:
    /// Inline slots per cell. One: at packing fraction 0.5 a cell one diameter wide holds 0.64
    /// discs on average (1.57 cells per disc), and two slots would cost 200 bytes per disc alone.
    static constexpr std::uint32_t slots_per_cell = 1;
    /// Cells per tile side (storage order, see the file comment).
    static constexpr std::uint32_t tile = 4;

    /// Builds the grid and predicts every disc's first event: O(N) expected time and memory.
    /// Throws Error(input) when a periodic box is too small for a 3 x 3 grid.
    explicit CellEngine(const Scene& scene);

    /// Same rule as FastEngine::can_simulate.
    [[nodiscard]] static bool can_simulate(const Scene& scene);

    void advance_to(double t) override;
    [[nodiscard]] double time() const noexcept override { return now_; }
    [[nodiscard]] Snapshot snapshot() const override;
    [[nodiscard]] Measurements measurements() const override;
    void set_collision_listener(CollisionListener listener) override {
        listener_ = std::move(listener);
    }

    [[nodiscard]] std::uint32_t cells_x() const noexcept { return nx_; }
    [[nodiscard]] std::uint32_t cells_y() const noexcept { return ny_; }
    [[nodiscard]] std::size_t big_disc_count() const noexcept { return big_.size(); }
    /// Discs currently in overflow regions (not in their cell's inline slots).
    [[nodiscard]] std::size_t overflow_discs() const noexcept;
    /// Heap memory held by the engine's containers, in bytes (capacities, not sizes).
    [[nodiscard]] std::uint64_t bytes() const noexcept;
    /// O(N) consistency check (cell contents against loc_, heap invariants, one event per disc).
    [[nodiscard]] bool check_invariants() const;

  private:
    /// What a neighbour scan reads of a disc.
    struct Body {
        double x, y;                 ///< position at local time t (periodic: within one cell)
        double vx, vy;               ///< velocity
        double t;                    ///< local clock
        double r;                    ///< radius
        std::uint32_t id;            ///< internal disc index
        std::uint32_t last_partner;  ///< see sim::just_collided_slack
    };
    /// One cache line: a body, and (first inline slot of a cell only) the cell's disc count and
    /// overflow region. Moving a record copies the body only.
    struct alignas(64) Slot {
        Body b;
        std::uint32_t fill;      ///< discs in the cell (inline + overflow)
        std::uint32_t overflow;  ///< offset of the cell's overflow region in pool_
    };
    static_assert(sizeof(Slot) == 64, "one cache line per slot");

    /// Where a disc's record is: its cell (column, row) and its position among
    /// the cell's discs (inline slots first); big discs: big_bit | index into bigs_.
    struct Loc {
        std::uint16_t cx;  ///< cell column (fit_cells allows at most 65536 cells per axis)
        std::uint16_t cy;  ///< cell row
        std::uint32_t pos;
    };
    static constexpr std::uint32_t big_bit = 1U << 31;

    /// What only the disc's own events read.
    struct Cold {
        double m = 0.0;  ///< mass
        /// The earliest pair event of the disc's scans since its last full prediction.
        double pair_t = kinematics::never;
        std::uint32_t pair_partner = no_disc;
        std::uint32_t pair_count = 0;  ///< the partner's collision count when pair_t was predicted
        std::uint32_t count = 0;       ///< collisions of this disc (invalidates partners' events)
        std::uint32_t instant_collisions = 0;  ///< see count_collision_now
    };
    static_assert(sizeof(Cold) == 32);

    /// The fast engine's 16-byte key (see FastEngine::Key).
    struct Key {
        static constexpr std::uint32_t index_mask = (1U << 30) - 1;
        double t;
        std::uint32_t a;
        std::uint32_t kind_b;

        static Key make(double t, std::uint32_t a, std::uint32_t b, EventKind kind) noexcept {
            return Key{t, a, (static_cast<std::uint32_t>(kind) << 30) | (b & index_mask)};
        }
        [[nodiscard]] EventKind kind() const noexcept {
            return static_cast<EventKind>(kind_b >> 30);
        }
        [[nodiscard]] std::uint32_t b() const noexcept { return kind_b & index_mask; }
    };
    struct KeyLess {
        const std::vector<std::uint32_t>* scene_index = nullptr;

        [[nodiscard]] bool operator()(const Key& x, const Key& y) const noexcept {
            return x.t < y.t || (x.t == y.t && tie_break(x, y));
        }
        [[nodiscard]] bool tie_break(const Key& x, const Key& y) const noexcept;
    };
    struct KeyOwner {
        [[nodiscard]] std::uint32_t operator()(const Key& k) const noexcept { return k.a; }
    };
#ifdef COLLIDE_CELL_CALENDAR
    using Heap = pq::IndexedCalendarQueue<Key, KeyLess, KeyOwner>;
#else
    using Heap = pq::IndexedDaryHeap<Key, pq::Orientation::min, 4, KeyLess, KeyOwner>;
#endif

    struct Image {
        std::int32_t x = 0;
        std::int32_t y = 0;
    };

    // --- construction
    void choose_grid(const Scene& scene);
    void place_discs(const Scene& scene);
    [[nodiscard]] std::vector<std::uint32_t> locality_order(const Scene& scene) const;
    [[nodiscard]] std::uint32_t cell_of(double x, double y) const noexcept;

    // --- cell storage
    [[nodiscard]] std::size_t first_slot(std::uint32_t cx, std::uint32_t cy) const noexcept;
    [[nodiscard]] Slot& slot_at(std::uint32_t cx, std::uint32_t cy, std::uint32_t pos) noexcept;
    [[nodiscard]] const Slot& slot_at(std::uint32_t cx, std::uint32_t cy,
                                      std::uint32_t pos) const noexcept;
    [[nodiscard]] Body& body(std::uint32_t i) noexcept;
    [[nodiscard]] const Body& body(std::uint32_t i) const noexcept;
    void insert(const Body& b, std::uint32_t cx, std::uint32_t cy);
    void remove(std::uint32_t i) noexcept;
    [[nodiscard]] std::uint32_t take_region(std::uint32_t size_class);
    void give_region(std::uint32_t offset, std::uint32_t size_class);

    // --- the loop's phases
    void process(std::uint32_t i, const Key& key);
    void process_pair(std::uint32_t i, std::uint32_t j, double t);
    void process_wall(std::uint32_t i, EventKind kind, double t);
    void process_cell(std::uint32_t i, std::uint32_t axis);
    void count_collision_now(std::uint32_t i, const Body& bi);

    // --- prediction
    void predict(std::uint32_t i);
    void predict_after_crossing(std::uint32_t i, std::uint32_t axis);
    void schedule(std::uint32_t i, const Body& bi, Loc cell, double xi, double yi, const Key& pair);
    [[nodiscard]] bool cannot_beat(Vec2 dr, Vec2 dv, double sigma, double best_t) const noexcept;
    void consider_pair(const Body& bi, double xi, double yi, const Body& bj, double shift_x,
                       double shift_y, Key& best);
    void consider_pair_images(const Body& bi, double xi, double yi, const Body& bj, Key& best);
    void scan_cells(const Body& bi, Loc cell, double xi, double yi, std::int64_t x0,
                    std::int64_t x1, std::int64_t y0, std::int64_t y1, Key& best);
    void scan_cell(const Body& bi, double xi, double yi, const Slot* first, double shift_x,
                   double shift_y, Key& best);
    void scan_ring(const Body& bi, Loc cell, double xi, double yi, Key& best);
    void consider_walls_and_cells(std::uint32_t i, const Body& bi, Loc cell, double xi, double yi,
                                  Key& best);

    // --- bookkeeping
    void advance_disc(Body& b) const noexcept;
    [[nodiscard]] bool is_big(std::uint32_t i) const noexcept {
        return (loc_[i].pos & big_bit) != 0;
    }
    [[nodiscard]] Vec2 position_at_now(const Body& b) const noexcept;

    Box box_;
    bool periodic_ = false;
    Appearance appearance_;
    double now_ = 0.0;

    // grid
    std::uint32_t nx_ = 1;
    std::uint32_t ny_ = 1;
    std::uint32_t tiles_x_ = 1;  ///< tiles per row of the storage order
    double cw_ = 1.0;
    double ch_ = 1.0;
    double big_threshold_ = 0.0;
    double small_radius_max_ = 0.0;
    std::vector<Slot> slots_;  ///< inline slots, slots_per_cell per cell, in tile order
    std::vector<Slot> pool_;   ///< overflow regions (fill and overflow unused there)
    /// Free overflow regions by size class (class k holds 2^k slots).
    std::vector<std::vector<std::uint32_t>> free_regions_;
    std::uint64_t overflow_discs_ = 0;

    // discs, by internal id
    std::vector<Loc> loc_;
    std::vector<Body> bigs_;  ///< records of the big discs (in no cell)
    std::vector<Cold> cold_;
    std::vector<Image> image_;
    std::vector<Vec2> start_;
    std::vector<std::uint32_t> scene_index_;  ///< see FastEngine::scene_index_
    std::vector<std::uint32_t> big_;          ///< ids of big discs

    KeyLess key_less_{&scene_index_};
    Heap heap_{0, key_less_};
    QueueStats stats_;
    ImpulseTally tally_;
    std::uint64_t collisions_pair_ = 0;
    std::uint64_t collisions_xwall_ = 0;
    std::uint64_t collisions_ywall_ = 0;
    std::uint64_t cell_crossings_ = 0;
    std::uint64_t predictions_ = 0;
    double wall_seconds_ = 0.0;
    std::uint64_t instant_limit_ = 0;
    CollisionListener listener_;
};

}  // namespace collide::sim
