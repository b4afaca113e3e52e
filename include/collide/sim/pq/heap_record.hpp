#pragma once
/// \file
/// The record behind `collide heap`: priority-queue operations run on one or more
/// implementations, kept as small steps by kind (a key appears, two keys are compared, two keys
/// exchange or shift, a key leaves, a key changes, a sink starts), one panel per implementation,
/// with the array and the counts of compares and exchanges at every step. Pure computation on
/// values and neutral: no words, no timing, no drawing, no I/O. The presentation layer
/// (collide/show/heap_program.hpp) turns the record into captions, pacing and frames.
///
/// The steps come from the queues themselves: each implementation runs the operations with a
/// QueueRecorder (observer.hpp) and the record is replayed into steps; after every operation the
/// replayed array is checked against the queue's own array.
///
/// Operations (the `ops` field), the tokens of `collide pq` plus one:
///   - a key (a word of letters or an integer; all keys of one kind) inserts it;
///   - `*` removes the maximum (the minimum for a min-queue);
///   - `K^V` raises key K to V (increase-key, through the indexed heap's map from key to index;
///     only with `indexed`). With duplicate keys it raises the one inserted first.
/// The `sort` field takes keys only: heapsort, construction then sortdown.
///
/// Errors name the field they are about ("ops", "sort", "impl"); callers pass the name the user
/// knows (the app passes its option, "--ops").

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "collide/sim/pq/order.hpp"
#include "collide/sim/pq/queue_kind.hpp"
#include "collide/sim/pq/trace.hpp"

namespace collide::pq {

/// One operation of a lesson.
struct HeapOp {
    enum class Kind {
        insert,    ///< insert `key`
        remove,    ///< remove the max (min)
        increase,  ///< raise `key` to `new_key` (indexed only)
        build,     ///< heapsort's construction (HeapRecord::heapsort only; never parsed)
        sortdown,  ///< heapsort's sortdown (HeapRecord::heapsort only; never parsed)
    };
    Kind kind = Kind::insert;
    TraceKey key;
    TraceKey new_key;
    std::size_t token = 0;  ///< 1-based position in the operation string
    std::string spelling;   ///< the token as written
};

/// Splits `text` at white space into operations. Throws Error(input)
/// "<field>: token N 'x': why" for a token that is not a key, `*` or `K^V`, for a key of the
/// other kind than the first key (words and numbers do not mix), and for an empty sequence.
[[nodiscard]] std::vector<HeapOp> parse_heap_ops(std::string_view text,
                                                 std::string_view field = "ops");

/// The keys of a heapsort (no `*`, no `^`), with the same errors.
[[nodiscard]] std::vector<TraceKey> parse_sort_keys(std::string_view text,
                                                    std::string_view field = "sort");

/// The array of one panel at one moment.
struct ArrayState {
    std::vector<std::string> keys;     ///< the queue's array, slot 0 first
    std::vector<std::size_t> handles;  ///< indexed: each slot's handle (insertion number)
    /// Slots [heap_size, keys.size()) are heapsort's sorted part, set apart (= keys.size() for
    /// every queue).
    std::size_t heap_size = 0;
    std::uint64_t compares = 0;   ///< so far
    std::uint64_t exchanges = 0;  ///< so far (the ordered array's shifts count as exchanges)
};

/// One step of one panel: a state and what happens to it during the step.
struct HeapStep {
    enum class Kind {
        appear,    ///< a new key appears in slot i (already in `state`)
        compare,   ///< the keys in slots i and j are compared (`state` counts the compare)
        exchange,  ///< the keys in slots i and j exchange places (`state` is before)
        shift,     ///< ordered array: the key in slot i moves right to slot j, the key being
                   ///< inserted from j to i (`state` is before)
        remove,    ///< the key in slot i (the last) leaves (`state` is before)
        change,    ///< the key in slot i was changed from `from` (increase-key; `state` has the
                   ///< new key)
        sink,      ///< heapsort starts a sink at slot i in a heap of j slots (`state` has
                   ///< heap_size = j)
    };
    Kind kind = Kind::compare;
    std::size_t i = 0;
    std::size_t j = 0;
    std::optional<std::size_t> best;  ///< unordered array's scan: the max (min) so far
    /// compare: how the key in slot i orders against the key in slot j (< 0, 0, > 0); for
    /// i == j (increase-key) the new key against the old one, `from`.
    int order = 0;
    std::string from;  ///< change: the key before the change
    ArrayState state;
};

/// One operation in one panel: its steps, then the state it leaves.
struct PanelOp {
    std::vector<HeapStep> steps;
    ArrayState end;
    std::string removed;  ///< remove: the key that left
};

/// One panel: an implementation and its operations.
struct HeapPanel {
    QueueKind kind;
    bool tree = true;          ///< a heap (a tree over its array) rather than an array alone
    unsigned arity = 2;        ///< children per node when `tree` (1 for the arrays)
    bool shifts = false;       ///< the ordered array: its exchanges are shifts
    ArrayState start;          ///< before the first operation
    std::vector<PanelOp> ops;  ///< one per HeapRecord::ops entry
};

/// The whole lesson: panels in lock-step, operation by operation.
class HeapRecord {
  public:
    /// `ops` on each implementation (in the given order, one panel each). Throws Error(input)
    /// naming `field` and the token for a removal from an empty queue, an increase-key without
    /// an indexed heap (naming `impl_field`), of a key not in the queue or to a smaller key;
    /// Error(input) naming `impl_field` for a queue kind with_queue rejects.
    static HeapRecord operations(std::span<const HeapOp> ops, std::span<const QueueKind> impls,
                                 Orientation orientation, std::string_view field = "ops",
                                 std::string_view impl_field = "impl");
    /// Heapsort of `keys` (ascending for max, descending for min), one panel (a binary heap),
    /// two operations: HeapOp::Kind::build, then HeapOp::Kind::sortdown.
    static HeapRecord heapsort(std::span<const TraceKey> keys, Orientation orientation);

    [[nodiscard]] const std::vector<HeapPanel>& panels() const noexcept { return panels_; }
    /// The operations, the same for every panel.
    [[nodiscard]] const std::vector<HeapOp>& ops() const noexcept { return ops_; }
    [[nodiscard]] Orientation orientation() const noexcept { return orientation_; }
    /// True for a heapsort (build, sortdown), false for operations.
    [[nodiscard]] bool heapsort() const noexcept { return heapsort_; }
    /// The most items any panel holds at once.
    [[nodiscard]] std::size_t capacity() const noexcept { return capacity_; }

  private:
    std::vector<HeapPanel> panels_;
    std::vector<HeapOp> ops_;
    Orientation orientation_ = Orientation::max;
    bool heapsort_ = false;
    std::size_t capacity_ = 0;
};

}  // namespace collide::pq
