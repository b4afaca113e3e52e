#pragma once
/// \file
/// Choosing a priority queue at run time (`--pq unordered|ordered|binary|dary:D|indexed`): the
/// choice as a value, parsed once where the user typed it. Light on purpose (no queue code), so
/// that option structs can hold a QueueKind; with_queue.hpp turns it into a queue type.

#include <string>
#include <string_view>

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
/// Throws Error(input) naming `option`, what it expected and the bad token, e.g.
/// `pq: expected a queue: unordered, ordered, binary, dary:D or indexed[:D], got 'x'`.
[[nodiscard]] QueueKind parse_queue_kind(std::string_view text, std::string_view option = "pq");

/// The canonical spelling of a kind (`unordered`, `ordered`, `binary`, `dary:3`, `indexed:4`);
/// parse_queue_kind(to_string(k)) == k.
[[nodiscard]] std::string to_string(const QueueKind& kind);

}  // namespace collide::pq
