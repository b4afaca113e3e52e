#pragma once
/// \file
/// How the event-driven engines fill Snapshot::queue (`collide render --queue`): a record of the
/// latest pops, and a description of any queue of the lecture (heap, d-ary heap, indexed heap,
/// ordered and unordered array) as what it is. Nothing here runs unless a caller asked for the
/// view (Engine::watch_queue): an engine that is not watched pays one predictable branch per pop.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "collide/sim/event.hpp"
#include "collide/sim/pq/binary_heap.hpp"
#include "collide/sim/pq/dary_heap.hpp"
#include "collide/sim/pq/indexed_queue.hpp"
#include "collide/sim/pq/ordered_array_pq.hpp"
#include "collide/sim/pq/unordered_array_pq.hpp"
#include "collide/snapshot.hpp"

namespace collide::sim {

/// Most events one view asks for (`--queue K`): more would not be legible in a box.
inline constexpr std::size_t max_watched_events = 20;
/// Popped events a view carries (the latest ones).
inline constexpr std::size_t watched_pops = 8;

/// The kind a queue picture shows: queue views are drawn in 2D, where a 3D engine's front or
/// back wall (zwall) is shown as a wall of the y axis.
[[nodiscard]] constexpr EventKind queued_kind(EventKind kind) noexcept {
    return kind == EventKind::zwall ? EventKind::ywall : kind;
}

/// The classic engine's event as the view shows it.
[[nodiscard]] inline QueuedEvent queued(const Event& e, bool stale) noexcept {
    return {e.t, queued_kind(e.kind), e.a, e.kind == EventKind::pair ? e.b : 0, stale};
}

/// Whether a view was asked for, how many events it shows, and the latest pops (a ring).
class QueueWatch {
  public:
    /// Starts watching: later views carry what `limits` says. Throws Error(input) naming the
    /// field `queue` (the app says `--queue`) unless 1 <= limits.next_events <= max_watched_events.
    void start(const QueueViewLimits& limits);
    [[nodiscard]] bool on() const noexcept { return limits_.next_events > 0; }
    [[nodiscard]] std::size_t next_events() const noexcept { return limits_.next_events; }
    [[nodiscard]] const QueueViewLimits& limits() const noexcept { return limits_; }

    void record_pop(const QueuedEvent& e) noexcept {
        ring_[recorded_ % watched_pops] = e;
        ++recorded_;
    }
    /// The latest pops, oldest first.
    [[nodiscard]] std::vector<QueuedEvent> popped() const;

  private:
    QueueViewLimits limits_;
    std::array<QueuedEvent, watched_pops> ring_{};
    std::uint64_t recorded_ = 0;
};

/// Levels of a d-ary heap of `size` entries shown as a tree: down to the deepest level with at
/// most limits.tree_level_nodes nodes, at most limits.tree_levels (at least the root when not
/// empty).
[[nodiscard]] unsigned shown_tree_levels(std::size_t arity, std::size_t size,
                                         const QueueViewLimits& limits) noexcept;
/// Slots in those levels (1 + d + d^2 + ..., at most size).
[[nodiscard]] std::size_t shown_tree_slots(std::size_t arity, unsigned levels,
                                           std::size_t size) noexcept;

/// Sorts `events` by time (then kind and discs), drops stale entries, cell crossings and
/// repeats of one collision, and keeps the first `k`.
void keep_next_collisions(std::vector<QueuedEvent>& events, std::size_t k);

/// Fills the name, shape and slots of `view` for a queue of the lecture holding sim::Event, and
/// its `next` collisions, counting stale entries with `stale(event)`, as much as `limits` asks.
/// O(entries): only for watched engines, once per frame.
template <class Queue, class IsStale>
void describe_queue(const Queue& queue, const QueueViewLimits& limits, IsStale&& stale,
                    QueueView& view);

// ---------------------------------------------------------------------------------------------

namespace detail {

template <class Q>
struct QueueTraits;  // which queue of the lecture Q is

template <class T, pq::Orientation O, unsigned D, class Less, class Obs>
struct QueueTraits<pq::DaryHeap<T, O, D, Less, Obs>> {
    static constexpr QueueShape shape = QueueShape::heap;
    static constexpr bool indexed = false;
    static std::size_t arity(const pq::DaryHeap<T, O, D, Less, Obs>& q) { return q.d(); }
    static const T& at(const pq::DaryHeap<T, O, D, Less, Obs>& q, std::size_t i) {
        return q.array()[i];
    }
};

template <class T, pq::Orientation O, unsigned D, class Less>
struct QueueTraits<pq::IndexedHeapQueue<T, O, D, Less>> {
    static constexpr QueueShape shape = QueueShape::heap;
    static constexpr bool indexed = true;
    static std::size_t arity(const pq::IndexedHeapQueue<T, O, D, Less>& /*q*/) { return D; }
    static const T& at(const pq::IndexedHeapQueue<T, O, D, Less>& q, std::size_t i) {
        return q.heap().key_at(i);
    }
};

template <class T, pq::Orientation O, class Less, class Obs>
struct QueueTraits<pq::OrderedArrayPQ<T, O, Less, Obs>> {
    static constexpr QueueShape shape = QueueShape::ordered_array;
    static constexpr bool indexed = false;
    static std::size_t arity(const pq::OrderedArrayPQ<T, O, Less, Obs>& /*q*/) { return 1; }
    static const T& at(const pq::OrderedArrayPQ<T, O, Less, Obs>& q, std::size_t i) {
        return q.array()[i];
    }
};

template <class T, pq::Orientation O, class Less, class Obs>
struct QueueTraits<pq::UnorderedArrayPQ<T, O, Less, Obs>> {
    static constexpr QueueShape shape = QueueShape::unordered_array;
    static constexpr bool indexed = false;
    static std::size_t arity(const pq::UnorderedArrayPQ<T, O, Less, Obs>& /*q*/) { return 1; }
    static const T& at(const pq::UnorderedArrayPQ<T, O, Less, Obs>& q, std::size_t i) {
        return q.array()[i];
    }
};

[[nodiscard]] std::string queue_name(QueueShape shape, std::size_t arity, bool indexed);

}  // namespace detail

template <class Queue, class IsStale>
void describe_queue(const Queue& queue, const QueueViewLimits& limits, IsStale&& stale,
                    QueueView& view) {
    using Traits = detail::QueueTraits<Queue>;
    const std::size_t n = queue.size();
    const std::size_t arity = Traits::arity(queue);
    view.shape = Traits::shape;
    view.arity = static_cast<unsigned>(arity);
    view.name = detail::queue_name(Traits::shape, arity, Traits::indexed);
    view.size = n;
    const auto shown = [&](std::size_t i) {
        const Event& e = Traits::at(queue, i);
        return queued(e, stale(e));
    };
    std::vector<QueuedEvent> all;
    all.reserve(n);
    for (std::size_t i = 0; i < n; ++i) all.push_back(shown(i));
    view.stale_entries = static_cast<std::uint64_t>(
        std::count_if(all.begin(), all.end(), [](const QueuedEvent& e) { return e.stale; }));
    view.slots.clear();
    switch (Traits::shape) {
        case QueueShape::heap: {
            view.levels = shown_tree_levels(arity, n, limits);
            const std::size_t m = shown_tree_slots(arity, view.levels, n);
            view.slots.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(m));
            break;
        }
        case QueueShape::ordered_array:  // the next event is the last slot
            for (std::size_t k = 0; k < std::min(n, limits.array_slots); ++k)
                view.slots.push_back(all[n - 1 - k]);
            break;
        case QueueShape::unordered_array: {
            const std::size_t m = std::min(n, limits.array_slots);
            view.slots.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(m));
            if (n > 0) {
                std::size_t best = 0;
                const EventLess less;
                for (std::size_t i = 1; i < n; ++i) {
                    if (less(Traits::at(queue, i), Traits::at(queue, best))) best = i;
                }
                view.top_index = best;
            }
            break;
        }
    }
    keep_next_collisions(all, limits.next_events);
    view.next = std::move(all);
}

}  // namespace collide::sim
