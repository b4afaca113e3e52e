#pragma once
/// \file
/// The lecture's teaching trace of a priority queue: a sequence of operations ("P Q E * X ...":
/// a key inserts it, `*` removes the item that comes out next) run against several
/// implementations side by side, recording after each step the operation, its argument, the
/// value returned, the size and every implementation's array. Formatting the table (text, CSV,
/// Markdown) is the CLI's job (`collide pq`); this module only computes it.
///
/// The table is produced one row at a time (for_each_trace_row), each row showing at most the
/// first entries of every array: memory stays linear in the number of operations, however long
/// the sequence, and so does the table. run_trace collects every full row, for small traces.
///
/// Keys are either all words of ASCII letters (compared byte by byte, so "A" < "Z" < "a";
/// a single letter is the lecture's case) or all decimal integers (optional sign, compared as
/// numbers and printed in canonical form, so "007" prints as 7). A sequence that mixes the two
/// is refused, naming the first token of the other type.

#include <cstddef>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "collide/sim/pq/order.hpp"
#include "collide/sim/pq/queue_kind.hpp"

namespace collide::pq {

/// Bounds on a trace, far beyond a lecture's few dozen operations of one-letter keys, that keep
/// `collide pq`'s memory, time and output bounded (the elementary queues take O(N) per
/// operation, so a trace takes O(N^2) time; its table is O(N) rows of bounded width).
inline constexpr std::size_t max_trace_operations = 10'000;
/// Letters in a word key (integer keys are at most 20 characters anyway).
inline constexpr std::size_t max_trace_key_length = 32;

/// One key of a trace: a word of letters or an integer (a trace never mixes them).
struct TraceKey {
    bool numeric = false;
    long long number = 0;  ///< the value when numeric
    std::string word;      ///< the letters otherwise

    /// Numbers by value, words byte by byte (numbers before words, though parsing never mixes).
    friend bool operator<(const TraceKey& a, const TraceKey& b) {
        if (a.numeric != b.numeric) return a.numeric;
        return a.numeric ? a.number < b.number : a.word < b.word;
    }
    friend bool operator==(const TraceKey& a, const TraceKey& b) {
        return a.numeric == b.numeric && (a.numeric ? a.number == b.number : a.word == b.word);
    }

    /// The key as printed in the table.
    [[nodiscard]] std::string text() const { return numeric ? std::to_string(number) : word; }
};

/// One operation of a trace, with where it came from for error messages.
struct TraceOp {
    bool remove = false;    ///< `*`: remove the item that comes out next
    TraceKey key;           ///< the key inserted (insert only)
    std::size_t token = 0;  ///< 1-based position in the operation string
    std::string spelling;   ///< the token as written
};

/// Splits `ops` at white space into operations. Throws Error(input) "<option>: token N 'x': why"
/// for a token that is neither `*`, a word of letters nor an integer (or overflows a 64-bit
/// integer), for a word longer than max_trace_key_length, for a key whose type differs from the
/// first key's, and Error(input) naming `option` for an empty sequence or one of more than
/// max_trace_operations operations.
[[nodiscard]] std::vector<TraceOp> parse_trace_ops(std::string_view ops,
                                                   std::string_view option = "ops");

/// One line of the lecture's table: the state after one operation.
struct TraceRow {
    std::string operation;  ///< "insert", "remove max" or "remove min"
    std::string argument;   ///< the key inserted, empty for a removal
    std::string returned;   ///< the key removed, empty for an insert
    std::size_t size = 0;   ///< items in the queue afterwards (in every implementation)
    /// Per queue (same order as the queues asked for): its array from index 0, at most the
    /// entries asked for; the other size - contents[q].size() entries are not shown.
    std::vector<std::vector<std::string>> contents;
};

/// The whole table.
struct Trace {
    std::vector<QueueKind> queues;  ///< the implementations, one column each
    std::vector<TraceRow> rows;     ///< one per operation
};

/// The implementations shown when none is chosen: unordered, ordered, binary, dary:3, indexed.
[[nodiscard]] std::vector<QueueKind> default_trace_queues();

/// The most items the queue holds at once during `ops` (so whether rows will be cut short).
/// Throws Error(input) "<option>: token N '*': removes from an empty queue". O(N), no allocation.
[[nodiscard]] std::size_t peak_trace_size(std::span<const TraceOp> ops,
                                          std::string_view option = "ops");

/// Receives each row of a trace in order; the row is valid during the call only.
using TraceVisitor = std::function<void(const TraceRow&)>;

/// Every array entry (no row cut short).
inline constexpr std::size_t all_trace_entries = std::numeric_limits<std::size_t>::max();

/// Runs `ops` on a fresh queue of each kind, all in step (and on a reference model that fills
/// the operation, argument, return and size columns), calling `visit` after each operation with
/// the row, whose arrays hold at most `max_entries` entries each. Nothing is kept between rows:
/// memory is O(queues x (N + max_entries)). The whole sequence is checked first, so an input
/// error comes before the first call: Error(input) naming the token of a removal from an empty
/// queue; Error(runtime) if an implementation returns something other than the model (a bug,
/// not an input problem). Also for step-by-step animations of the heaps.
void for_each_trace_row(std::span<const TraceOp> ops, Orientation orientation,
                        std::span<const QueueKind> queues, std::size_t max_entries,
                        const TraceVisitor& visit, std::string_view option = "ops");

/// The whole table with every array in full (for_each_trace_row collected): memory grows with
/// the square of the number of operations, so this is for short traces and tests. Throws as
/// for_each_trace_row.
[[nodiscard]] Trace run_trace(std::span<const TraceOp> ops, Orientation orientation,
                              std::span<const QueueKind> queues, std::string_view option = "ops");

}  // namespace collide::pq
