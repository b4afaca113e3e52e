#pragma once
/// \file
/// The pseudocode of `collide puzzle --code`: the search loop of the lecture (A* from a priority
/// queue, breadth-first search from a FIFO queue) in the project's own words, and the lines an
/// expansion walks through. PuzzleProgram (puzzle_program.hpp) paces its frames by these walks
/// and marks the line under way; this header lets tests hold the walk against the record.
/// Pure: no drawing.

#include <cstddef>
#include <vector>

#include "collide/sim/puzzle/search.hpp"
#include "collide/view/code.hpp"

namespace collide::show {

/// Seconds of video each line of an expansion's walk stays marked: long enough for a class to
/// read the line and see the board or queue it acts on.
inline constexpr double search_line_seconds = 0.6;

/// The lines of the listing, in order.
enum class SearchLine : std::size_t {
    start = 0,   ///< "insert the start"
    loop,        ///< "while the queue is not empty:" (marked while the search runs fast)
    pop,         ///< "b = delete the minimum" (BFS: the oldest)
    goal,        ///< "if b is the goal: stop"
    neighbours,  ///< "for each neighbour n of b:"
    skip,        ///< "if n is b's previous board: skip it" (BFS: seen before)
    insert,      ///< "insert n with priority moves + h(n)" (BFS: at the back)
};

/// The listing of `method` (its lines in SearchLine's order) with no line marked.
[[nodiscard]] view::CodeView search_code(puzzle::Method method);

/// The lines expansion `k` of `r` walks through, in order: the pop and the goal test; then,
/// unless it is the goal, the neighbours' loop, the skip (when the board has a previous one or,
/// in BFS, any neighbour was seen before) and the insert. Precondition: k < r.expansions.size().
[[nodiscard]] std::vector<SearchLine> search_walk(const puzzle::SearchResult& r, std::size_t k);

}  // namespace collide::show
