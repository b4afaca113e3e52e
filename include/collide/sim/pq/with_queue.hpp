#pragma once
/// \file
/// Dispatching a run-time queue choice (QueueKind) to a compile-time queue type, so engines stay
/// templates on the queue.

#include <utility>

#include "collide/error.hpp"
#include "collide/sim/pq/binary_heap.hpp"
#include "collide/sim/pq/dary_heap.hpp"
#include "collide/sim/pq/indexed_queue.hpp"
#include "collide/sim/pq/order.hpp"
#include "collide/sim/pq/ordered_array_pq.hpp"
#include "collide/sim/pq/queue.hpp"
#include "collide/sim/pq/queue_kind.hpp"
#include "collide/sim/pq/unordered_array_pq.hpp"

namespace collide::pq {

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
    throw_input_error("pq: unsupported queue '" + to_string(kind) + "'");
}

}  // namespace collide::pq
