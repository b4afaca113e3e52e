#pragma once
/// \file
/// What a priority queue does, step by step, for whoever watches (the `collide heap` animation,
/// tests): every compare of two array slots, every exchange, the ordered array's shifts, the
/// removal of the last slot, and heapsort's sinks. Indices are 0-based positions in the queue's
/// array at the moment of the call, as if the algorithm exchanged items (the lecture's exch):
/// code that moves a hole instead (swim, sink) reports the moving item at the hole.
///
/// Zero cost when nobody watches: a queue's observer is a template parameter, NoObserver by
/// default, whose hooks are empty inline functions and whose `watching` is false, so the engines'
/// queues compile to the same code as before (bench/bench_pq.cpp and `collide bench engine`,
/// measured in docs/benchmarks.md). No virtual call, no branch, no storage
/// ([[no_unique_address]]).

#include <concepts>
#include <cstddef>
#include <vector>

namespace collide::pq {

/// An observer that watches nothing; every hook compiles away.
struct NoObserver {
    static constexpr bool watching = false;
    constexpr void compared(std::size_t /*i*/, std::size_t /*j*/) const noexcept {}
    constexpr void exchanged(std::size_t /*i*/, std::size_t /*j*/) const noexcept {}
    constexpr void shifted(std::size_t /*from*/, std::size_t /*to*/) const noexcept {}
    constexpr void removed(std::size_t /*i*/) const noexcept {}
    constexpr void sink_starts(std::size_t /*i*/, std::size_t /*heap_size*/) const noexcept {}
};

/// The hooks a queue calls. `watching` is true for any observer that records something.
template <class Obs>
concept QueueObserver = requires(Obs& o, std::size_t i) {
    { Obs::watching } -> std::convertible_to<bool>;
    o.compared(i, i);     ///< the items at i and j were compared (i is the one that moves)
    o.exchanged(i, i);    ///< the items at i and j swapped places
    o.shifted(i, i);      ///< ordered array: the item at `from` moved one slot to `to`, and the
                          ///< item being inserted moved from `to` into `from` (an exchange)
    o.removed(i);         ///< the item at i (always the last slot) left the queue
    o.sink_starts(i, i);  ///< heapsort: a sink of slot i in a heap of the first heap_size slots
};

/// One recorded step of a queue's algorithm on its array (not an event of the simulation: those
/// are sim::Event, and QueuedEvent in a queue's picture).
struct QueueStep {
    enum class Kind { compare, exchange, shift, remove, sink };
    Kind kind = Kind::compare;
    std::size_t i = 0;  ///< compare/exchange: first slot; shift: from; remove/sink: the slot
    std::size_t j = 0;  ///< compare/exchange: second slot; shift: to; sink: the heap size

    friend bool operator==(const QueueStep&, const QueueStep&) = default;
};

/// Appends every step to a log the caller owns (the log must outlive the recorder; copies of a
/// recorder append to the same log).
class QueueRecorder {
  public:
    static constexpr bool watching = true;

    explicit QueueRecorder(std::vector<QueueStep>* log = nullptr) noexcept : log_(log) {}

    void compared(std::size_t i, std::size_t j) const { add(QueueStep::Kind::compare, i, j); }
    void exchanged(std::size_t i, std::size_t j) const { add(QueueStep::Kind::exchange, i, j); }
    void shifted(std::size_t from, std::size_t to) const { add(QueueStep::Kind::shift, from, to); }
    void removed(std::size_t i) const { add(QueueStep::Kind::remove, i, 0); }
    void sink_starts(std::size_t i, std::size_t heap_size) const {
        add(QueueStep::Kind::sink, i, heap_size);
    }

  private:
    void add(QueueStep::Kind kind, std::size_t i, std::size_t j) const {
        if (log_ != nullptr) log_->push_back({kind, i, j});
    }
    std::vector<QueueStep>* log_;
};

static_assert(QueueObserver<NoObserver>);
static_assert(QueueObserver<QueueRecorder>);

}  // namespace collide::pq
