// The sliding puzzle: board parsing and its errors, solvability, heuristics, random boards, and
// BFS and A* (every queue kind) against known shortest solutions and an independent reference.
#include <doctest/doctest.h>

#include <cstdint>
#include <deque>
#include <stdexcept>
#include <string>
#include <vector>

#include "../support/input_error.hpp"
#include "collide/error.hpp"
#include "collide/sim/puzzle/board.hpp"
#include "collide/sim/puzzle/search.hpp"

using namespace collide::puzzle;
using collide::pq::QueueFamily;
using collide::pq::QueueKind;
using collide::test::contains;
using collide::test::input_error_message;

namespace {

std::string board_error(const std::string& text) {
    return input_error_message([&] { (void)Board::parse(text); });
}

/// Shortest distances to the goal of every 3x3 board reachable from it, by a plain BFS written
/// here over digit strings: a reference that shares no code with the searches. Each board's
/// distance sits at its permutation's rank (its Lehmer code, 0..9!-1) in a flat table, so the
/// 181,440 boards take no allocation each: with a std::map of strings the table took 3 s to
/// build, in every test case that uses it (ctest runs each in its own process), and far longer
/// under the sanitizers.
class ReferenceDistances {
  public:
    ReferenceDistances() : distance_(362880, -1) {
        const std::string goal = "123456780";
        std::deque<std::string> fifo{goal};
        distance_[rank(goal)] = 0;
        reachable_ = 1;
        while (!fifo.empty()) {
            const std::string s = fifo.front();
            fifo.pop_front();
            const int b = static_cast<int>(s.find('0'));
            const int steps[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
            for (const auto& st : steps) {
                const int r = b / 3 + st[0];
                const int c = b % 3 + st[1];
                if (r < 0 || r > 2 || c < 0 || c > 2) continue;
                std::string t = s;
                std::swap(t[static_cast<std::size_t>(b)], t[static_cast<std::size_t>(r * 3 + c)]);
                int& d = distance_[rank(t)];
                if (d >= 0) continue;
                d = distance_[rank(s)] + 1;
                ++reachable_;
                fifo.push_back(t);
            }
        }
    }

    /// How many boards are reachable from the goal.
    std::size_t size() const { return reachable_; }
    /// 1 when `board` (nine digits) is reachable from the goal, else 0.
    std::size_t count(const std::string& board) const { return distance_[rank(board)] >= 0; }
    /// The shortest distance of `board` to the goal; std::out_of_range when it is unreachable.
    int at(const std::string& board) const {
        const int d = distance_[rank(board)];
        if (d < 0) throw std::out_of_range("not reachable from the goal: " + board);
        return d;
    }

  private:
    /// The rank of a permutation of the digits 0..8 among all 9! in lexicographic order.
    static std::size_t rank(const std::string& board) {
        std::size_t r = 0;
        for (std::size_t i = 0; i < 9; ++i) {
            std::size_t smaller_after = 0;
            for (std::size_t j = i + 1; j < 9; ++j) smaller_after += board[j] < board[i];
            r = r * (9 - i) + smaller_after;
        }
        return r;
    }

    std::vector<int> distance_;  ///< by rank; -1: not reachable
    std::size_t reachable_ = 0;
};

const ReferenceDistances& reference_distances() {
    static const ReferenceDistances distances;
    return distances;
}

std::string digits(const Board& b) {
    std::string s;
    for (int i = 0; i < b.cells(); ++i) s += static_cast<char>('0' + b.tile(i));
    return s;
}

const std::vector<QueueKind> all_queues = {{QueueFamily::unordered, 0}, {QueueFamily::ordered, 0},
                                           {QueueFamily::binary, 2},    {QueueFamily::dary, 3},
                                           {QueueFamily::dary, 5},      {QueueFamily::indexed, 4}};

/// The solution's boards follow each other by single moves and end at the goal.
void check_solution_is_legal(const SearchResult& r, const Board& start) {
    const std::vector<Board> boards = r.solution_boards();
    REQUIRE(!boards.empty());
    CHECK(boards.front() == start);
    CHECK(boards.back().is_goal());
    for (std::size_t i = 1; i < boards.size(); ++i) {
        bool adjacent = false;
        boards[i - 1].for_each_neighbour([&](const Board& n, int) { adjacent |= n == boards[i]; });
        CHECK(adjacent);
    }
    CHECK(r.solution_moves().size() + 1 == boards.size());
}

}  // namespace

TEST_CASE("puzzle board: parsing, blanks, sides and printing") {
    const Board b = Board::parse("1 2 3 4 0 6 7 5 8");
    CHECK(b.side() == 3);
    CHECK(b.blank() == 4);
    CHECK(b.tile(7) == 5);
    CHECK(b.to_string() == "1 2 3 4 0 6 7 5 8");
    CHECK(Board::parse("1 2 3 4 _ 6 7 5 8") == b);
    CHECK(Board::parse("  1\t2 3 4 0 6 7 5 8 ") == b);
    CHECK(Board::parse("1 2 3 0").side() == 2);
    const Board f = Board::parse("1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 0");
    CHECK(f.side() == 4);
    CHECK(f.is_goal());
    CHECK(f.tile(14) == 15);
    CHECK(Board::unpack(b.packed(), 3) == b);
    CHECK(Board::goal(3).to_string() == "1 2 3 4 5 6 7 8 0");
}

TEST_CASE("puzzle board: malformed boards name the token") {
    CHECK(contains(board_error("1 2 3 4 x 6 7 5 8"), "'x' (token 5) is not a tile"));
    CHECK(contains(board_error("1 2 3 4 9 6 7 5 0"), "'9' (token 5) is out of range"));
    CHECK(contains(board_error("1 2 3 4 0 6 7 5 123"), "'123' (token 9) is out of range"));
    CHECK(contains(board_error("1 2 3 4 0 6 7 5 -1"), "'-1' (token 9) is not a tile"));
    const std::string repeated = board_error("1 2 3 4 0 6 7 5 5");
    CHECK(contains(repeated, "'5' (token 9) is tile 5 again (first at token 8)"));
    CHECK(contains(repeated, "tile 8 is missing"));
    const std::string two_blanks = board_error("1 2 3 4 0 6 7 _ 8");
    CHECK(contains(two_blanks, "a second blank (first at token 5)"));
    CHECK(contains(two_blanks, "tile 5 is missing"));
    CHECK(contains(board_error("1 2 3 4 0 6 7 5"), "8 tokens"));
    CHECK(contains(board_error(""), "0 tokens"));
    const std::string long_board = board_error("1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 0 16");
    CHECK(contains(long_board, "17 tokens"));
    CHECK(contains(long_board, "the 17th token is '16'"));
    CHECK(board_error("1 2 3 4 0 6 7 5 8").empty());
    CHECK(contains(input_error_message([] { (void)Board::parse("1 1 3 0", "--start"); }),
                   "--start: "));
}

TEST_CASE("puzzle board: solvability by the parity of inversions") {
    CHECK(Board::parse("1 2 3 4 5 6 8 7 0").inversions() == 1);
    CHECK_FALSE(Board::parse("1 2 3 4 5 6 8 7 0").solvable());
    CHECK(contains(Board::parse("1 2 3 4 5 6 8 7 0").unsolvable_reason(), "1 inversion"));
    CHECK(Board::parse("8 6 7 2 5 4 3 0 1").solvable());
    CHECK(Board::parse("1 2 3 4 0 6 7 5 8").unsolvable_reason().empty());
    // Even sides: the blank's row counts too.
    CHECK(Board::parse("1 2 3 0").solvable());
    CHECK(Board::parse("1 0 3 2").solvable());  // one move away
    CHECK_FALSE(Board::parse("2 1 3 0").solvable());
    CHECK(contains(Board::parse("2 1 3 0").unsolvable_reason(), "row 1"));
    CHECK(Board::parse("1 2 3 4 5 6 7 8 9 10 11 12 13 14 0 15").solvable());
    CHECK_FALSE(Board::parse("1 2 3 4 5 6 7 8 9 10 11 12 13 15 14 0").solvable());
    // Against the reference: exactly the boards reachable from the goal are solvable.
    const Board odd = Board::parse("2 1 3 4 5 6 7 8 0");
    CHECK_FALSE(odd.solvable());
    CHECK(reference_distances().count(digits(odd)) == 0);
    CHECK(reference_distances().size() == 181440);
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
        const Board b = random_board(3, 40, seed);
        CHECK(b.solvable());
        CHECK(reference_distances().count(digits(b)) == 1);
    }
}

TEST_CASE("puzzle board: heuristics") {
    const Board b = Board::parse("8 1 3 4 0 2 7 6 5");
    CHECK(hamming(b) == 5);
    CHECK(manhattan(b) == 10);
    CHECK(hamming(Board::goal(4)) == 0);
    CHECK(manhattan(Board::goal(4)) == 0);
    CHECK(manhattan(Board::parse("0 1 2 3")) == 4);  // 1: one column; 2: a row and a column; 3: one
    CHECK(estimate(Heuristic::hamming, b) == 5);
    CHECK(parse_heuristic("hamming") == Heuristic::hamming);
    CHECK(contains(input_error_message([] { (void)parse_heuristic("euclid"); }),
                   "heuristic: unknown heuristic 'euclid'"));
    // Never more than the true distance (so A* stays optimal).
    for (std::uint64_t seed = 0; seed < 30; ++seed) {
        const Board r = random_board(3, 25, seed);
        const int d = reference_distances().at(digits(r));
        CHECK(manhattan(r) <= d);
        CHECK(hamming(r) <= d);
    }
}

TEST_CASE("puzzle board: random boards are deterministic and bounded") {
    CHECK(random_board(3, 20, 3) == random_board(3, 20, 3));
    CHECK_FALSE(random_board(3, 20, 3) == random_board(3, 20, 4));
    CHECK(random_board(4, 0, 7).is_goal());
    CHECK(random_board(3, 1, 7).is_goal() == false);
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        CHECK(reference_distances().at(digits(random_board(3, 12, seed))) <= 12);
    }
    CHECK(
        contains(input_error_message([] { (void)random_board(3, -1, 0); }), "moves: must be 0.."));
    CHECK(contains(input_error_message([] { (void)random_board(3, -1, 0, "--moves"); }),
                   "--moves: must be 0.."));
    CHECK(contains(input_error_message([] { (void)random_board(5, 3, 0); }), "side 5"));
}

TEST_CASE("puzzle search: the hardest 8-puzzles take 31 moves, BFS and A* alike") {
    for (const char* text : {"8 6 7 2 5 4 3 0 1", "6 4 7 8 5 0 3 2 1"}) {
        CAPTURE(text);
        const Board start = Board::parse(text);
        const SearchResult bfs = breadth_first(start);
        REQUIRE(bfs.solved());
        CHECK(bfs.solution_length() == 31);
        check_solution_is_legal(bfs, start);
        // BFS of a farthest board sees (nearly) every one of the 181,440 boards.
        CHECK(bfs.stats.expanded > 180'000);
        CHECK(bfs.stats.enqueued == bfs.nodes.size());
        CHECK(bfs.stats.enqueued <= 181'440);
        // Hamming solves these too (docs/puzzle.md), but with 120,000 expansions on a queue of
        // 26,000, too slowly for the validating builds (a heap check after every operation).
        for (Heuristic h : {Heuristic::manhattan}) {
            const SearchResult astar = a_star(start, h, {QueueFamily::binary, 2});
            REQUIRE(astar.solved());
            CHECK(astar.solution_length() == 31);
            check_solution_is_legal(astar, start);
            CHECK(astar.stats.expanded < bfs.stats.expanded);
        }
    }
}

TEST_CASE("puzzle search: shortest solutions against the reference, every queue kind") {
    for (std::uint64_t seed = 0; seed < 8; ++seed) {
        const Board start = random_board(3, 8 + static_cast<int>(seed) * 3, seed);
        const int expected = reference_distances().at(digits(start));
        CAPTURE(start.to_string());
        const SearchResult bfs = breadth_first(start);
        REQUIRE(bfs.solved());
        CHECK(bfs.solution_length() == expected);
        const SearchResult first = a_star(start, Heuristic::manhattan, all_queues.front());
        for (const QueueKind& kind : all_queues) {
            CAPTURE(collide::pq::to_string(kind));
            const SearchResult astar = a_star(start, Heuristic::manhattan, kind);
            REQUIRE(astar.solved());
            CHECK(astar.solution_length() == expected);
            // A strict order of queue entries: every kind expands the same boards in order.
            CHECK(astar.expansions == first.expansions);
            CHECK(astar.stats.enqueued == first.stats.enqueued);
            CHECK(astar.stats.max_queue == first.stats.max_queue);
        }
        CHECK(a_star(start, Heuristic::hamming, {QueueFamily::dary, 4}).solution_length() ==
              expected);
    }
}

TEST_CASE("puzzle search: bookkeeping (counts, parent skips, priorities, the queue over time)") {
    const Board start = Board::parse("8 1 3 4 0 2 7 6 5");
    const SearchResult astar = a_star(start, Heuristic::manhattan, {QueueFamily::binary, 2});
    REQUIRE(astar.solved());
    CHECK(astar.stats.expanded == astar.expansions.size());
    CHECK(astar.stats.enqueued == astar.nodes.size());
    CHECK(astar.stats.parent_skips > 0);
    CHECK(astar.stats.max_queue >= 1);
    // A consistent heuristic: priorities come out of the queue in non-decreasing order.
    for (std::size_t k = 1; k < astar.expansions.size(); ++k) {
        CHECK(astar.nodes[astar.expansions[k - 1]].priority <=
              astar.nodes[astar.expansions[k]].priority);
    }
    // No node's child is its parent board.
    for (const SearchNode& n : astar.nodes) {
        if (n.parent == no_node || astar.nodes[n.parent].parent == no_node) continue;
        CHECK(n.board != astar.nodes[astar.nodes[n.parent].parent].board);
    }
    // The queue replayed: its front at step k is what comes out next.
    for (const SearchResult* r : {&astar}) {
        for (std::size_t k = 0; k < r->expansions.size(); ++k) {
            const std::vector<std::uint32_t> front = r->queue_front(k, 3);
            REQUIRE(!front.empty());
            const SearchNode& next = r->nodes[front.front()];
            CHECK((front.front() == r->expansions[k] || (next.stale && next.popped == k)));
        }
    }
    const SearchResult bfs = breadth_first(start);
    REQUIRE(bfs.solved());
    CHECK(bfs.queue_front(0, 5) == std::vector<std::uint32_t>{0});
    std::size_t largest = 0;
    // Every 7th step: each check scans all nodes, and the validating builds are slow.
    for (std::size_t k = 0; k < bfs.expansions.size(); k += 7) {
        CHECK(bfs.queue_front(k, 1).front() == bfs.expansions[k]);
        largest = std::max(largest, bfs.queue_size(k + 1));
    }
    CHECK(largest <= bfs.stats.max_queue);
    // Level by level: BFS expands in non-decreasing depth.
    for (std::size_t k = 1; k < bfs.expansions.size(); ++k) {
        CHECK(bfs.nodes[bfs.expansions[k - 1]].moves <= bfs.nodes[bfs.expansions[k]].moves);
    }
}

TEST_CASE("puzzle search: the goal, unsolvable boards and 2x2") {
    const SearchResult done = breadth_first(Board::goal(3));
    REQUIRE(done.solved());
    CHECK(done.solution_length() == 0);
    CHECK(done.stats.expanded == 1);
    CHECK(a_star(Board::goal(4), Heuristic::manhattan, {}).solution_length() == 0);
    const Board bad = Board::parse("1 2 3 4 5 6 8 7 0");
    CHECK(breadth_first(bad).status == SearchStatus::unsolvable);
    CHECK(a_star(bad, Heuristic::manhattan, {}).status == SearchStatus::unsolvable);
    CHECK(a_star(bad, Heuristic::manhattan, {}).stats.expanded == 0);
    const SearchResult small = breadth_first(Board::parse("0 3 2 1"));
    REQUIRE(small.solved());
    CHECK(small.solution_length() ==
          a_star(Board::parse("0 3 2 1"), Heuristic::hamming, {}).solution_length());
}

TEST_CASE("puzzle search: the node budget stops a 15-puzzle BFS instead of exhausting memory") {
    const Board start = random_board(4, 60, 5);
    SearchLimits limits;
    limits.max_nodes = 50'000;
    const SearchResult bfs = breadth_first(start, limits);
    CHECK(bfs.status == SearchStatus::budget_exceeded);
    CHECK(bfs.nodes.size() <= limits.max_nodes);
    CHECK(bfs.stats.enqueued == limits.max_nodes);
    // A* with Manhattan solves a 4x4 board of 30 random moves within the default budget.
    const Board near = random_board(4, 30, 2);
    const SearchResult astar = a_star(near, Heuristic::manhattan, {QueueFamily::dary, 4});
    REQUIRE(astar.solved());
    CHECK(astar.solution_length() <= 30);
    check_solution_is_legal(astar, near);
    // The array queues' O(N) scans have their own budget.
    SearchLimits scans;
    scans.max_scan_work = 1000;
    CHECK(a_star(start, Heuristic::hamming, {QueueFamily::unordered, 0}, scans).status ==
          SearchStatus::work_exceeded);
}
