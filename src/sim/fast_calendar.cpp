// The fast engine's event queue: the calendar tuned to the scene, and the queue as a watched
// engine shows it (the discs' calendar as one indexed heap, the spheres' calendar).

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "fast_engine_internal.hpp"

namespace collide::sim {

namespace {

/// The event calendar (pq::CalendarQueue): blocks that hold this many events on
/// average (the heap of the current block stays small), and a ring of buckets reaching this
/// many mean event intervals ahead (later events wait in the overflow list).
constexpr double calendar_events_per_block = 8.0;
constexpr double calendar_horizon = 8.0;

}  // namespace

template <int D>
void BasicFastEngine<D>::tune_calendar() {
    if (D == 2 && watch_.on()) {
        // One heap of every pending event (a block of infinite width): the lecture's queue. Discs
        // use the calendar at every size otherwise: on the 2-core machine of 2026-11-30 (4 MiB of
        // L2 per core) it ran 1.01x the one-block heap at 10^5 discs and 1.06x at 10^6, with
        // 3,368 instructions per collision against 4,533 at 10^5 (docs/benchmarks-history.md,
        // issue 47; on the machine of 2026-11-29, 1 MiB of L2, it had lost 0.96x at 10^5).
        queue_.tune(std::numeric_limits<double>::infinity(), 2, now_);
        return;
    }
    // Each particle's next event is on average `mean` ahead, so the whole system has about
    // n / mean events per unit time.
    double sum = 0.0;
    std::size_t n = 0;
    queue_.for_each([&](std::uint32_t, const Key& k) {
        sum += k.t - now_;
        ++n;
    });
    if (n == 0 || !(sum > 0.0)) return;  // nothing moves: one block
    const double mean = sum / static_cast<double>(n);
    const double width = calendar_events_per_block * mean / static_cast<double>(n);
    const auto buckets = std::bit_ceil(std::max<std::size_t>(
        64, static_cast<std::size_t>(calendar_horizon * static_cast<double>(n) /
                                     calendar_events_per_block)));
    queue_.tune(width, buckets, now_);
}

template <int D>
QueuedEvent BasicFastEngine<D>::queued_event(std::uint32_t i, const Key& key) const noexcept {
    QueuedEvent e;
    e.t = key.t;
    e.kind = queued_kind(key.kind());
    e.a = scene_index(i);
    if (key.kind() == EventKind::pair) {
        const std::uint32_t j = key.b();
        e.b = scene_index(j);
        if (e.b < e.a) std::swap(e.a, e.b);
        e.stale = p_[j].count != cold_[i].pair_count;
    }
    return e;
}

// The calendar's heap (for watched discs: every pending event, one per disc): its top levels,
// and the next collisions of the whole calendar. O(N), only for watched engines.
template <int D>
QueueView BasicFastEngine<D>::queue_view() const {
    QueueView view;
    view.shape = QueueShape::heap;
    view.arity = 4;
    view.one_per_disc = true;
    const std::size_t n = queue_.size();
    view.size = n;
    std::vector<QueuedEvent> all;
    all.reserve(n);
    // The calendar's heap holds its next events (all of them for watched discs); the tree
    // shows that heap.
    view.name = D == 2 ? "indexed 4-ary heap" : "event calendar (next events: indexed 4-ary heap)";
    const std::size_t tree = queue_.near().size();
    queue_.for_each([&](std::uint32_t i, const Key& key) { all.push_back(queued_event(i, key)); });
    view.stale_entries = static_cast<std::uint64_t>(
        std::count_if(all.begin(), all.end(), [](const QueuedEvent& e) { return e.stale; }));
    view.levels = shown_tree_levels(view.arity, tree, watch_.limits());
    view.slots.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(shown_tree_slots(
                                                     view.arity, view.levels, tree)));
    keep_next_collisions(all, watch_.next_events());
    view.next = std::move(all);
    view.popped = watch_.popped();
    view.pops = core_.counters().queue.pops;
    view.stale_pops = core_.counters().queue.stale_pops;
    return view;
}

}  // namespace collide::sim
