#pragma once
/// \file
/// Breadth-first search and A* on the sliding puzzle, recorded so that a video can replay them.
///
/// Both searches take boards out of a queue until the goal comes out: BFS from a FIFO queue (so
/// level by level), A* from one of the lecture's priority queues (`--pq`, the same
/// implementations as the engines) ordered by priority = moves so far + heuristic. Neither puts
/// a neighbour back in the queue when it is the board its node came from (the assignment's
/// "critical optimisation"); beyond that BFS never enqueues a board it has seen, and A* enqueues a
/// board again only along a shorter path and skips (as stale) a board already expanded. Both
/// find a shortest solution (the heuristics never overestimate and are consistent).
///
/// Memory is bounded by a node budget (SearchLimits): a search that would store more boards
/// stops and reports `budget_exceeded` instead of running out of memory; the caller says what to
/// try. A node costs about bytes_per_node bytes.
///
///     const SearchResult bfs = breadth_first(board);
///     const SearchResult astar = a_star(board, Heuristic::manhattan, {QueueFamily::binary, 2});
///     astar.solution_length() == bfs.solution_length();

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

#include "collide/sim/pq/queue_kind.hpp"
#include "collide/sim/puzzle/board.hpp"

namespace collide::puzzle {

/// "No such index" in node links.
inline constexpr std::uint32_t no_node = std::numeric_limits<std::uint32_t>::max();

/// One board the search put in its queue: a node of the search tree.
struct SearchNode {
    std::uint64_t board = 0;         ///< Board::packed()
    std::uint32_t parent = no_node;  ///< the node it was generated from (no_node: the start)
    /// Position in the expansion order when it left the queue (expanded, or skipped as stale just
    /// before that expansion); no_node while still queued when the search ended.
    std::uint32_t popped = no_node;
    std::uint16_t moves = 0;     ///< moves from the start (its depth in the tree)
    std::uint16_t priority = 0;  ///< moves + heuristic (A*); moves (BFS)
    bool stale = false;          ///< left the queue without being expanded (A*: a shorter path won)
};

/// Which search.
enum class Method : std::uint8_t { bfs, astar };

[[nodiscard]] std::string_view to_string(Method method) noexcept;

/// What the search cost.
struct SearchStats {
    std::size_t expanded = 0;      ///< boards taken from the queue and expanded (the goal included)
    std::size_t enqueued = 0;      ///< boards put in the queue (the start included)
    std::size_t max_queue = 0;     ///< the queue's largest size
    std::size_t stale = 0;         ///< A*: boards taken from the queue but already expanded
    std::size_t parent_skips = 0;  ///< neighbours not enqueued because they are the parent board
};

/// How a search ended.
enum class SearchStatus : std::uint8_t {
    solved,
    budget_exceeded,  ///< it would have stored more than SearchLimits::max_nodes boards
    work_exceeded,    ///< an array queue's scans would have exceeded SearchLimits::max_scan_work
    unsolvable,       ///< the board's inversion parity rules the goal out (nothing searched)
};

/// Budgets that keep a search bounded in memory and time.
struct SearchLimits {
    /// Boards stored (enqueued) at most. The 8-puzzle has 181,440 solvable boards, so every 3x3
    /// search fits in the default; a 15-puzzle BFS does not.
    std::size_t max_nodes = 2'000'000;
    /// Entries an unordered or ordered array queue may scan or shift in all (their operations
    /// are O(N)): about 3 s for the unordered array, 1 s for the ordered one. A 31-move 8-puzzle
    /// with Manhattan needs 2% of it; with Hamming, more. Heaps are not limited by it.
    std::uint64_t max_scan_work = 1'000'000'000ULL;
};

/// Largest max_nodes accepted (about bytes_per_node x this in memory).
inline constexpr std::size_t max_node_budget = 20'000'000;
/// Memory per stored board at most, all structures included (node, hash slot, queue entry, and
/// the spare capacity of arrays that grow by doubling): measured 100 at 2 million boards, 68 at
/// 8 million (peak resident size of a 15-puzzle BFS, docs/puzzle.md).
inline constexpr std::size_t bytes_per_node = 100;

/// A finished (or stopped) search: every node, the order they were expanded in, and its costs.
struct SearchResult {
    Method method = Method::bfs;
    Heuristic heuristic = Heuristic::manhattan;  ///< A* only
    pq::QueueKind queue{};                       ///< A* only
    SearchStatus status = SearchStatus::solved;
    int side = 3;
    std::vector<SearchNode> nodes;          ///< by id, in the order they were enqueued
    std::vector<std::uint32_t> expansions;  ///< node ids in the order they were expanded
    std::uint32_t goal = no_node;           ///< the goal's node (solved only)
    SearchStats stats;

    [[nodiscard]] bool solved() const noexcept { return status == SearchStatus::solved; }
    /// Moves of the solution found. Precondition: solved().
    [[nodiscard]] int solution_length() const noexcept;
    /// Node ids from the start to the goal. Precondition: solved().
    [[nodiscard]] std::vector<std::uint32_t> solution_path() const;
    /// The boards from the start to the goal. Precondition: solved().
    [[nodiscard]] std::vector<Board> solution_boards() const;
    /// The moves from the start to the goal. Precondition: solved().
    [[nodiscard]] std::vector<Move> solution_moves() const;
    [[nodiscard]] Board board_of(std::uint32_t id) const {
        return Board::unpack(nodes[id].board, side);
    }

    /// The first `count` entries of the queue (the next to come out first) after `step`
    /// expansions (0 <= step <= expansions.size()), in the order they come out. O(nodes).
    [[nodiscard]] std::vector<std::uint32_t> queue_front(std::size_t step, std::size_t count) const;
    /// How many boards the queue held after `step` expansions. O(nodes).
    [[nodiscard]] std::size_t queue_size(std::size_t step) const;
    /// The expansion index after which node `id` was in the queue (0 for the start).
    [[nodiscard]] std::size_t enqueued_at(std::uint32_t id) const noexcept;
};

/// Breadth-first search from `start` with a FIFO queue. Never throws for a valid board; an
/// unsolvable one returns status unsolvable without searching.
[[nodiscard]] SearchResult breadth_first(const Board& start, const SearchLimits& limits = {});

/// A* from `start` with priority = moves + `heuristic`, on a priority queue of kind `queue`.
/// Ties of priority go to the deeper board (nearer the goal by the estimate), then to the board
/// enqueued first: a strict order, so every queue kind expands the same boards in the same order.
/// Throws Error(input) for a queue kind parse_queue_kind would reject.
[[nodiscard]] SearchResult a_star(const Board& start, Heuristic heuristic,
                                  const pq::QueueKind& queue, const SearchLimits& limits = {});

}  // namespace collide::puzzle
