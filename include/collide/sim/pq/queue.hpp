#pragma once
/// \file
/// The one interface every plain priority queue of the lecture satisfies, so an engine can be
/// written once and run on any of them (`--pq unordered|ordered|binary|dary:D|indexed`).
///
/// Ties. Each implementation is deterministic on its own, but two implementations may hand out
/// items that tie under `Less` in different orders (an unordered array scans, a heap sinks). When
/// `Less` is a strict total order on the items pushed (no two distinct items tie, e.g. an event
/// key (time, kind, a, b)), every implementation hands out the one sorted sequence, so engines
/// built on different queues produce identical event sequences. Event keys must therefore break
/// time ties with further fields; tests/sim/test_pq.cpp checks the agreement.

#include <concepts>
#include <cstddef>
#include <utility>

namespace collide::pq {

/// A priority queue of values: push, pop (returns the item that comes out next), top, size, empty.
/// pop() and top() on an empty queue are precondition violations (not checked).
template <class Q>
concept Queue = requires(Q q, const Q cq, typename Q::value_type x) {
    typename Q::value_type;
    q.push(std::move(x));
    { q.pop() } -> std::same_as<typename Q::value_type>;
    { cq.top() } -> std::convertible_to<const typename Q::value_type&>;
    { cq.size() } -> std::same_as<std::size_t>;
    { cq.empty() } -> std::same_as<bool>;
};

}  // namespace collide::pq
