#pragma once
/// \file
/// Choosing a priority queue at run time (`--pq unordered|ordered|binary|dary:D|indexed`) and
/// dispatching that choice to a compile-time queue type, so engines stay templates on the queue.

#include <string>
#include <string_view>
#include <utility>

#include "collide/sim/pq/binary_heap.hpp"
#include "collide/sim/pq/dary_heap.hpp"
#include "collide/sim/pq/indexed_queue.hpp"
#include "collide/sim/pq/order.hpp"
#include "collide/sim/pq/ordered_array_pq.hpp"
#include "collide/sim/pq/queue.hpp"
#include "collide/sim/pq/unordered_array_pq.hpp"

namespace collide::pq {

/// The lecture's priority-queue implementations.
enum class QueueFamily {
    unordered,  ///< UnorderedArrayPQ: insert O(1), remove O(N)
    ordered,    ///< OrderedArrayPQ: insert O(N), remove O(1)
    binary,     ///< BinaryHeap (d = 2)
    dary,       ///< DaryHeap with d children per node
    indexed,    ///< IndexedHeapQueue over IndexedDaryHeap with d children per node
};

/// A queue implementation chosen at run time.
struct QueueKind {
    QueueFamily family = QueueFamily::binary;
    unsigned d = 2;  ///< children per node for dary and indexed (2 for binary; unused for arrays)

    friend bool operator==(const QueueKind&, const QueueKind&) = default;
};

/// Arity of `indexed` written without `:D` (the engines' default).
inline constexpr unsigned default_indexed_arity = 4;

/// Parses `unordered`, `ordered`, `binary`, `dary:D` (2 <= D <= 64; 2, 3, 4 and 8 are compiled
/// specially, others use a run-time arity) or `indexed[:D]` (D in 2, 3, 4, 8; default 4).
/// Throws Error(input) naming `option` and the bad token, e.g.
/// `--pq: unknown queue 'x' (expected unordered|ordered|binary|dary:D|indexed)`.
[[nodiscard]] QueueKind parse_queue_kind(std::string_view text, std::string_view option = "--pq");

/// The canonical spelling of a kind (`unordered`, `ordered`, `binary`, `dary:3`, `indexed:4`);
/// parse_queue_kind(to_string(k)) == k.
[[nodiscard]] std::string to_string(const QueueKind& kind);

/// Calls f with a freshly constructed queue of value type T, orientation O and order Less of the
/// kind asked for (an rvalue: f may take it by value, `auto&&`, and move it into an engine), and
/// returns what f returns. f is instantiated for every implementation, so every branch must
/// return the same type. Throws Error(input) for a kind parse_queue_kind would reject.
template <class T, Orientation O, class Less, class F>
decltype(auto) with_queue(const QueueKind& kind, F&& f) {
    switch (kind.family) {
        case QueueFamily::unordered:
            return std::forward<F>(f)(UnorderedArrayPQ<T, O, Less>{});
        case QueueFamily::ordered:
            return std::forward<F>(f)(OrderedArrayPQ<T, O, Less>{});
        case QueueFamily::binary:
            return std::forward<F>(f)(BinaryHeap<T, O, Less>{});
        case QueueFamily::dary:
            switch (kind.d) {
                case 2:
                    return std::forward<F>(f)(DaryHeap<T, O, 2, Less>{});
                case 3:
                    return std::forward<F>(f)(DaryHeap<T, O, 3, Less>{});
                case 4:
                    return std::forward<F>(f)(DaryHeap<T, O, 4, Less>{});
                case 8:
                    return std::forward<F>(f)(DaryHeap<T, O, 8, Less>{});
                default:
                    break;
            }
            if (kind.d < 2 || kind.d > DaryHeap<T, O, 0, Less>::max_runtime_arity) break;
            return std::forward<F>(f)(DaryHeap<T, O, 0, Less>(kind.d));
        case QueueFamily::indexed:
            switch (kind.d) {
                case 2:
                    return std::forward<F>(f)(IndexedHeapQueue<T, O, 2, Less>{});
                case 3:
                    return std::forward<F>(f)(IndexedHeapQueue<T, O, 3, Less>{});
                case 4:
                    return std::forward<F>(f)(IndexedHeapQueue<T, O, 4, Less>{});
                case 8:
                    return std::forward<F>(f)(IndexedHeapQueue<T, O, 8, Less>{});
                default:
                    break;
            }
            break;
    }
    throw_input_error("--pq: unsupported queue '" + to_string(kind) + "'");
}

}  // namespace collide::pq
