// The two searches, written to be read next to the lecture's pseudo-code: take a board out of
// the queue; stop at the goal; otherwise enqueue its neighbours (but never its parent). The
// recording (nodes by id, the expansion order) is what lets the video replay the search.
#include "collide/sim/puzzle/search.hpp"

#include <algorithm>
#include <deque>

#include "board_table.hpp"
#include "collide/sim/pq/with_queue.hpp"

namespace collide::puzzle {

namespace {

/// A* queue entry: the node's priority and depth are copied in so the queue compares without
/// looking nodes up; 8 bytes.
struct AStarKey {
    std::uint16_t priority = 0;
    std::uint16_t moves = 0;
    std::uint32_t id = 0;
};

/// Lower priority first; among equal priorities the deeper board (smaller estimate left), then
/// the board enqueued first. A strict total order: every queue kind pops the same sequence.
struct AStarLess {
    bool operator()(const AStarKey& a, const AStarKey& b) const noexcept {
        if (a.priority != b.priority) return a.priority < b.priority;
        if (a.moves != b.moves) return a.moves > b.moves;
        return a.id < b.id;
    }
};

AStarKey key_of(const SearchNode& node, std::uint32_t id) noexcept {
    return {node.priority, node.moves, id};
}

/// The shared bookkeeping of both searches: nodes, expansion order, stats, the budget.
class Recorder {
  public:
    Recorder(SearchResult& result, const SearchLimits& limits) : r_(result), limits_(limits) {}

    /// Whether one more node fits in the budget; sets the status when it does not.
    [[nodiscard]] bool room_for_one_more() {
        if (r_.nodes.size() < limits_.max_nodes) return true;
        r_.status = SearchStatus::budget_exceeded;
        return false;
    }

    std::uint32_t add(const Board& board, std::uint32_t parent, int moves, int priority) {
        SearchNode node;
        node.board = board.packed();
        node.parent = parent;
        node.moves = static_cast<std::uint16_t>(moves);
        node.priority = static_cast<std::uint16_t>(priority);
        r_.nodes.push_back(node);
        ++r_.stats.enqueued;
        return static_cast<std::uint32_t>(r_.nodes.size() - 1);
    }

    void popped(std::uint32_t id, bool stale) {
        r_.nodes[id].popped = static_cast<std::uint32_t>(r_.expansions.size());
        r_.nodes[id].stale = stale;
        if (stale) {
            ++r_.stats.stale;
            return;
        }
        r_.expansions.push_back(id);
        ++r_.stats.expanded;
    }

    void queue_size(std::size_t size) { r_.stats.max_queue = std::max(r_.stats.max_queue, size); }

    void solved(std::uint32_t id) {
        r_.goal = id;
        r_.status = SearchStatus::solved;
    }

  private:
    SearchResult& r_;
    const SearchLimits& limits_;
};

SearchResult start_result(Method method, const Board& start) {
    SearchResult r;
    r.method = method;
    r.side = start.side();
    if (!start.solvable()) r.status = SearchStatus::unsolvable;
    return r;
}

/// Whether `next` is the board the expanded node came from (the assignment's optimisation).
bool is_parent(const SearchResult& r, std::uint32_t id, const Board& next) noexcept {
    const std::uint32_t parent = r.nodes[id].parent;
    return parent != no_node && r.nodes[parent].board == next.packed();
}

bool is_array_queue(const pq::QueueKind& kind) noexcept {
    return kind.family == pq::QueueFamily::unordered || kind.family == pq::QueueFamily::ordered;
}

template <class Queue>
void run_a_star(SearchResult& r, const Board& start, const SearchLimits& limits, Queue queue) {
    Recorder rec(r, limits);
    BoardTable best;  // board -> the node with the fewest moves to it so far
    const bool counts_scans = is_array_queue(r.queue);
    std::uint64_t scan_work = 0;
    const auto h = [&r](const Board& b) { return estimate(r.heuristic, b); };

    const std::uint32_t first = rec.add(start, no_node, 0, h(start));
    best.insert(start.packed(), first);
    queue.push(key_of(r.nodes[first], first));
    rec.queue_size(queue.size());
    while (!queue.empty()) {
        if (counts_scans && (scan_work += queue.size()) > limits.max_scan_work) {
            r.status = SearchStatus::work_exceeded;
            return;
        }
        const std::uint32_t id = queue.pop().id;
        const Board board = r.board_of(id);
        const bool stale = *best.find(board.packed()) != id;  // a shorter path replaced it
        rec.popped(id, stale);
        if (stale) continue;
        if (board.is_goal()) {
            rec.solved(id);
            return;
        }
        const int moves = r.nodes[id].moves + 1;
        bool out_of_room = false;
        board.for_each_neighbour([&](const Board& next, int) {
            if (out_of_room) return;
            if (is_parent(r, id, next)) {
                ++r.stats.parent_skips;
                return;
            }
            std::uint32_t* known = best.find(next.packed());
            // Expanded already (a consistent heuristic expands a board first along a shortest
            // path), or queued along a path at least as short: nothing to gain.
            if (known != nullptr &&
                (r.nodes[*known].popped != no_node || r.nodes[*known].moves <= moves)) {
                return;
            }
            if (!rec.room_for_one_more()) {
                out_of_room = true;
                return;
            }
            const std::uint32_t child = rec.add(next, id, moves, moves + h(next));
            if (known != nullptr) {
                *known = child;  // the older entry is left in the queue and skipped as stale
            } else {
                best.insert(next.packed(), child);
            }
            if (counts_scans && (scan_work += queue.size()) > limits.max_scan_work) {
                r.status = SearchStatus::work_exceeded;
                out_of_room = true;
                return;
            }
            queue.push(key_of(r.nodes[child], child));
        });
        if (out_of_room) return;
        rec.queue_size(queue.size());
    }
}

}  // namespace

std::string_view to_string(Method method) noexcept {
    return method == Method::bfs ? "BFS" : "A*";
}

SearchResult breadth_first(const Board& start, const SearchLimits& limits) {
    SearchResult r = start_result(Method::bfs, start);
    if (r.status == SearchStatus::unsolvable) return r;
    Recorder rec(r, limits);
    BoardTable seen;  // every board ever enqueued: BFS reaches each first along a shortest path
    std::deque<std::uint32_t> fifo;

    const std::uint32_t first = rec.add(start, no_node, 0, 0);
    seen.insert(start.packed(), first);
    fifo.push_back(first);
    rec.queue_size(fifo.size());
    while (!fifo.empty()) {
        const std::uint32_t id = fifo.front();
        fifo.pop_front();
        rec.popped(id, false);
        const Board board = r.board_of(id);
        if (board.is_goal()) {
            rec.solved(id);
            return r;
        }
        const int moves = r.nodes[id].moves + 1;
        bool out_of_room = false;
        board.for_each_neighbour([&](const Board& next, int) {
            if (out_of_room) return;
            if (is_parent(r, id, next)) {
                ++r.stats.parent_skips;
                return;
            }
            if (seen.find(next.packed()) != nullptr) return;
            if (!rec.room_for_one_more()) {
                out_of_room = true;
                return;
            }
            const std::uint32_t child = rec.add(next, id, moves, moves);
            seen.insert(next.packed(), child);
            fifo.push_back(child);
        });
        if (out_of_room) return r;
        rec.queue_size(fifo.size());
    }
    // Not reached for a solvable board (the goal is in its component); never claim a solution.
    r.status = SearchStatus::unsolvable;
    return r;
}

SearchResult a_star(const Board& start, Heuristic heuristic, const pq::QueueKind& queue,
                    const SearchLimits& limits) {
    SearchResult r = start_result(Method::astar, start);
    r.heuristic = heuristic;
    r.queue = queue;
    if (r.status == SearchStatus::unsolvable) return r;
    pq::with_queue<AStarKey, pq::Orientation::min, AStarLess>(
        queue, [&](auto q) { run_a_star(r, start, limits, std::move(q)); });
    return r;
}

int SearchResult::solution_length() const noexcept {
    return nodes[goal].moves;
}

std::vector<std::uint32_t> SearchResult::solution_path() const {
    std::vector<std::uint32_t> path;
    for (std::uint32_t id = goal; id != no_node; id = nodes[id].parent) path.push_back(id);
    std::reverse(path.begin(), path.end());
    return path;
}

std::vector<Board> SearchResult::solution_boards() const {
    std::vector<Board> boards;
    for (std::uint32_t id : solution_path()) boards.push_back(board_of(id));
    return boards;
}

std::vector<Move> SearchResult::solution_moves() const {
    const std::vector<Board> boards = solution_boards();
    std::vector<Move> moves;
    for (std::size_t i = 1; i < boards.size(); ++i)
        moves.push_back(boards[i - 1].move_to(boards[i]));
    return moves;
}

std::size_t SearchResult::enqueued_at(std::uint32_t id) const noexcept {
    const std::uint32_t parent = nodes[id].parent;
    return parent == no_node ? 0 : static_cast<std::size_t>(nodes[parent].popped) + 1;
}

namespace {

bool in_queue_at(const SearchResult& r, std::uint32_t id, std::size_t step) noexcept {
    const std::uint32_t popped = r.nodes[id].popped;
    return r.enqueued_at(id) <= step && (popped == no_node || step <= popped);
}

}  // namespace

std::size_t SearchResult::queue_size(std::size_t step) const {
    std::size_t size = 0;
    for (std::uint32_t id = 0; id < nodes.size(); ++id)
        size += in_queue_at(*this, id, step) ? 1 : 0;
    return size;
}

std::vector<std::uint32_t> SearchResult::queue_front(std::size_t step, std::size_t count) const {
    std::vector<std::uint32_t> live;
    for (std::uint32_t id = 0; id < nodes.size(); ++id) {
        if (in_queue_at(*this, id, step)) live.push_back(id);
    }
    const auto comes_first = [this](std::uint32_t a, std::uint32_t b) {
        if (method == Method::bfs) return a < b;  // FIFO: enqueued first, out first
        return AStarLess{}(key_of(nodes[a], a), key_of(nodes[b], b));
    };
    const std::size_t shown = std::min(count, live.size());
    std::partial_sort(live.begin(), live.begin() + static_cast<std::ptrdiff_t>(shown), live.end(),
                      comes_first);
    live.resize(shown);
    return live;
}

}  // namespace collide::puzzle
