// `collide puzzle` as a class sees it (collide/show/puzzle_program.hpp): the shared clock of the
// searches, the tree rows and the queue's front at a moment, the playback of the solutions.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "collide/show/puzzle_program.hpp"

using namespace collide;
using puzzle::Board;
using show::PuzzleProgram;

namespace {

std::vector<puzzle::SearchResult> both(const Board& start) {
    return {puzzle::breadth_first(start),
            puzzle::a_star(start, puzzle::Heuristic::manhattan, {pq::QueueFamily::binary, 2})};
}

std::vector<std::uint8_t> board_tiles(const Board& b) {
    std::vector<std::uint8_t> t;
    for (int i = 0; i < b.cells(); ++i) t.push_back(static_cast<std::uint8_t>(b.tile(i)));
    return t;
}

}  // namespace

TEST_CASE("puzzle lesson: thousands separators") {
    CHECK(show::with_thousands(0) == "0");
    CHECK(show::with_thousands(999) == "999");
    CHECK(show::with_thousands(1000) == "1,000");
    CHECK(show::with_thousands(181439) == "181,439");
    CHECK(show::with_thousands(1234567) == "1,234,567");
}

TEST_CASE("puzzle lesson: one clock, the cheaper search finishes first, both end together") {
    const Board start = Board::parse("8 1 3 4 0 2 7 6 5");
    const auto results = both(start);
    const PuzzleProgram frames(start, results);
    CHECK(frames.step_at(0, 0.0) == 0);
    CHECK(frames.step_at(1, frames.search_start()) == 0);
    CHECK(frames.step_at(0, frames.search_end()) == results[0].expansions.size());
    CHECK(frames.step_at(1, frames.search_end()) == results[1].expansions.size());
    // Never backwards, and the same number on both sides until A* (fewer expansions) is done.
    std::size_t previous = 0;
    for (double t = 0.0; t <= frames.search_end(); t += 0.05) {
        const std::size_t bfs = frames.step_at(0, t);
        const std::size_t astar = frames.step_at(1, t);
        CHECK(bfs >= previous);
        CHECK(astar == std::min(bfs, results[1].expansions.size()));
        previous = bfs;
    }
    CHECK(frames.playback_start() > frames.search_end());
    CHECK(frames.duration() > frames.playback_start());
}

TEST_CASE("puzzle lesson: the start, the tree rows and the queue's front during the search") {
    const Board start = Board::parse("8 1 3 4 0 2 7 6 5");
    const auto results = both(start);
    const PuzzleProgram frames(start, results);
    const view::PuzzleFrameView first = frames.frame_at(0.0);
    REQUIRE(first.panels.size() == 2);
    CHECK(first.heading.find("8 1 3 4 0 2 7 6 5") != std::string::npos);
    for (const view::PuzzlePanelView& p : first.panels) {
        CHECK_FALSE(p.playback);
        CHECK(p.rows.empty());
        REQUIRE(p.queue.size() == 1);  // the start waits in the queue
        CHECK(p.queue.front().tiles == board_tiles(start));
        CHECK(p.board.tiles == board_tiles(start));  // drawn large until the first expansion
        CHECK(p.caption == "start: Manhattan 10, Hamming 5");
    }
    // Mid-search: rows are consecutive depths, at most max_puzzle_rows, the newest board marked.
    const double mid = (frames.search_start() + frames.search_end()) / 2.0;
    const view::PuzzlePanelView bfs = frames.frame_at(mid).panels[0];
    REQUIRE_FALSE(bfs.rows.empty());
    CHECK(bfs.rows.size() <= view::max_puzzle_rows);
    const view::PuzzleRowView& last = bfs.rows.back();
    REQUIRE_FALSE(last.boards.empty());
    CHECK(last.boards.back().mark == view::PuzzleMark::current);
    CHECK(bfs.queue.size() == view::max_puzzle_queue_shown);
    CHECK(bfs.queue_more.find("more") != std::string::npos);
    for (const view::PuzzleRowView& row : bfs.rows) {
        CHECK(row.boards.size() <= view::max_puzzle_row_boards);
        for (const view::PuzzleBoardView& b : row.boards) CHECK(b.tiles.size() == 9);
    }
}

TEST_CASE("puzzle lesson: headings and titles in words, not option syntax") {
    const Board start = Board::parse("1 2 3 4 0 6 7 5 8");
    const auto results = both(start);
    const view::PuzzleFrameView f = PuzzleProgram(start, results).frame_at(0.0);
    CHECK(f.heading == "8-puzzle 1 2 3 4 0 6 7 5 8: breadth-first search against A*");
    CHECK(f.panels[0].title == "Breadth-first search");
    CHECK(f.panels[1].title == "A*, Manhattan distance, binary heap");
    for (const view::PuzzlePanelView& p : f.panels) {
        CHECK(p.title.find("--") == std::string::npos);
        CHECK(p.queue_title.find("--") == std::string::npos);
    }
}

TEST_CASE("puzzle lesson: once solved the path is marked and the playback ends on the goal") {
    const Board start = Board::parse("1 2 3 4 0 6 7 5 8");
    const auto results = both(start);
    const PuzzleProgram frames(start, results);
    const view::PuzzleFrameView done = frames.frame_at(frames.search_end() + 0.1);
    for (const view::PuzzlePanelView& p : done.panels) {
        CHECK(p.status.find("solved: 2 moves") != std::string::npos);
        REQUIRE(p.rows.size() == view::max_puzzle_rows);  // depths 1 and 2; 0 counted above
        CHECK(p.hidden_rows == "depth 0 not shown");
        const auto& last = p.rows.back().boards;
        CHECK(std::count_if(last.begin(), last.end(), [](const view::PuzzleBoardView& b) {
                  return b.mark == view::PuzzleMark::goal;
              }) == 1);
        CHECK(p.rows.front().boards.front().mark == view::PuzzleMark::solution);
    }
    // One solution at a time, a second a move: BFS's first while A* waits on its start.
    CHECK(frames.seconds_per_move() >= 1.0);
    const view::PuzzleFrameView first = frames.frame_at(frames.playback_start() + 0.1);
    CHECK(first.panels[0].caption == "move 1 of 2: 5 slides up");
    CHECK(first.panels[1].caption == "its 2 moves come next");
    CHECK(first.panels[1].board.tiles == board_tiles(start));
    CHECK(frames.playback_turn(1) >= frames.playback_start() + 2.0 * frames.seconds_per_move());
    const view::PuzzleFrameView second = frames.frame_at(frames.playback_turn(1) + 0.1);
    CHECK(second.panels[0].caption == "solved in 2 moves");
    const view::PuzzlePanelView moving = second.panels[1];
    CHECK(moving.playback);
    CHECK(moving.caption == "move 1 of 2: 5 slides up");
    CHECK(moving.slide.from == 7);  // 5 leaves the bottom row for the centre
    CHECK(moving.slide.to == 4);
    const view::PuzzlePanelView end = frames.frame_at(frames.duration()).panels[0];
    CHECK(end.board.tiles == board_tiles(Board::goal(3)));
    CHECK(end.caption == "solved in 2 moves");
}
