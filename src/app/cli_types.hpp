#pragma once
/// \file
/// The value types `--help`, the man page and completion show for options whose values are words
/// of their own: the queue implementations, the heap's and pq's operations, a puzzle board. One
/// spelling each, shared by every command that takes them. A name in braces lists the choices
/// (cli_docs.cpp reads them for the man page and completion).

namespace collide::app {

/// A priority queue implementation (pq::parse_queue_kind): D is the arity, a whole number >= 2.
inline constexpr const char* queue_kind_type = "{unordered,ordered,binary,dary:D,indexed[:D]}";
/// `--ops`: operations separated by spaces ("P Q E * X A M *").
inline constexpr const char* operations_type = "OPS";
/// `--sort`: keys separated by spaces ("S O R T E X A M P L E").
inline constexpr const char* keys_type = "KEYS";
/// A puzzle board, row by row ("1 2 3 4 0 6 7 5 8"), or `random`.
inline constexpr const char* board_type = "BOARD";

}  // namespace collide::app
