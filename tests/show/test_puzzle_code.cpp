// `collide puzzle --code` (collide/show/puzzle_code.hpp, PuzzleProgram with code): the search
// loop's listing, the walk of each expansion through it, and the marked line held against the
// board and queue the frame shows at the same moment (from the search's own record).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "collide/error.hpp"
#include "collide/show/puzzle_code.hpp"
#include "collide/show/puzzle_program.hpp"

using namespace collide;
using puzzle::Board;
using show::PuzzleProgram;
using show::SearchLine;

namespace {

std::vector<std::uint8_t> tiles_of(const Board& b) {
    std::vector<std::uint8_t> t;
    for (int i = 0; i < b.cells(); ++i) t.push_back(static_cast<std::uint8_t>(b.tile(i)));
    return t;
}

std::string line_text(const view::CodeView& code, SearchLine line) {
    return code.lines.at(static_cast<std::size_t>(line)).text;
}

/// The board marked `mark` in the panel's tree, if any.
std::optional<view::PuzzleBoardView> marked_in_tree(const view::PuzzlePanelView& p,
                                                    view::PuzzleMark mark) {
    for (const view::PuzzleRowView& row : p.rows) {
        for (const view::PuzzleBoardView& b : row.boards) {
            if (b.mark == mark) return b;
        }
    }
    return std::nullopt;
}

/// Entries taken out as stale just before expansion k (gone before it starts).
std::size_t stale_before(const puzzle::SearchResult& r, std::size_t k) {
    return static_cast<std::size_t>(std::count_if(
        r.nodes.begin(), r.nodes.end(), [k](const auto& n) { return n.stale && n.popped == k; }));
}

/// "in queue N" -> N.
std::size_t in_queue(const view::PuzzlePanelView& p) {
    REQUIRE(p.counters.size() == 2);
    const std::string& c = p.counters[1];
    REQUIRE(c.rfind("in queue ", 0) == 0);
    std::string digits;
    for (const char ch : c.substr(9)) {
        if (ch != ',') digits += ch;
    }
    return std::stoul(digits);
}

/// A board 12 moves from the goal whose A* takes a few dozen expansions (a fast middle).
const Board twelve = Board::parse("5 2 8 1 0 4 7 6 3", "board");

}  // namespace

TEST_CASE("puzzle code: the listings name the lecture's steps in their order") {
    const view::CodeView astar = show::search_code(puzzle::Method::astar);
    CHECK(line_text(astar, SearchLine::pop) == "b = delete the minimum");
    CHECK(line_text(astar, SearchLine::goal).find("goal") != std::string::npos);
    CHECK(line_text(astar, SearchLine::skip).find("previous") != std::string::npos);
    CHECK(line_text(astar, SearchLine::insert).find("moves + h") != std::string::npos);
    const view::CodeView bfs = show::search_code(puzzle::Method::bfs);
    CHECK(line_text(bfs, SearchLine::pop).find("oldest") != std::string::npos);
    CHECK(line_text(bfs, SearchLine::insert).find("back") != std::string::npos);
    CHECK(astar.lines.size() == static_cast<std::size_t>(SearchLine::insert) + 1);
    CHECK(bfs.lines.size() == astar.lines.size());
    CHECK_FALSE(astar.current.has_value());
}

TEST_CASE("puzzle code: each expansion walks its lines and the goal's walk ends at the test") {
    const puzzle::SearchResult r =
        puzzle::a_star(twelve, puzzle::Heuristic::manhattan, {pq::QueueFamily::binary, 2});
    REQUIRE(r.solved());
    // The start has no previous board to skip.
    CHECK(show::search_walk(r, 0) == std::vector<SearchLine>{SearchLine::pop, SearchLine::goal,
                                                             SearchLine::neighbours,
                                                             SearchLine::insert});
    CHECK(show::search_walk(r, 1) == std::vector<SearchLine>{SearchLine::pop, SearchLine::goal,
                                                             SearchLine::neighbours,
                                                             SearchLine::skip, SearchLine::insert});
    CHECK(show::search_walk(r, r.expansions.size() - 1) ==
          std::vector<SearchLine>{SearchLine::pop, SearchLine::goal});
}

TEST_CASE("puzzle code: only one search goes beside the code") {
    const std::vector<puzzle::SearchResult> two{
        puzzle::breadth_first(twelve),
        puzzle::a_star(twelve, puzzle::Heuristic::manhattan, {pq::QueueFamily::binary, 2})};
    CHECK_THROWS_AS(PuzzleProgram(twelve, two, true), Error);
    const PuzzleProgram plain(twelve, two);
    CHECK_FALSE(plain.shows_code());
    CHECK_FALSE(plain.frame_at(plain.search_start() + 1.0).code.has_value());
}

TEST_CASE("puzzle code: the marked line follows the board and the queue on screen") {
    for (const bool bfs : {false, true}) {
        CAPTURE(bfs);
        const std::vector<puzzle::SearchResult> results{
            bfs ? puzzle::breadth_first(twelve)
                : puzzle::a_star(twelve, puzzle::Heuristic::manhattan,
                                 {pq::QueueFamily::binary, 2})};
        const puzzle::SearchResult& r = results.front();
        const PuzzleProgram lesson(twelve, results, true);
        REQUIRE(lesson.shows_code());
        const std::size_t total = r.expansions.size();
        REQUIRE(total > show::walked_expansions + 1);  // a fast middle to skip

        // The lines marked over the search, in order, each once per walked expansion.
        std::vector<std::pair<std::size_t, SearchLine>> seen;
        const double dt = show::search_line_seconds / 4.0;
        for (double t = 0.0; t < lesson.playback_start(); t += dt) {
            CAPTURE(t);
            const PuzzleProgram::CodeMoment m = lesson.code_at(t);
            const view::PuzzleFrameView f = lesson.frame_at(t);
            REQUIRE(f.panels.size() == 1);
            REQUIRE(f.code.has_value());
            REQUIRE(m.line.has_value());
            CHECK(f.code->current == static_cast<std::size_t>(*m.line));
            CHECK(lesson.step_at(0, t) == m.shown);
            const view::PuzzlePanelView& p = f.panels.front();
            if (t < lesson.search_start()) {
                CHECK(*m.line == SearchLine::start);
                CHECK(m.shown == 0);
                continue;
            }
            if (t >= lesson.search_end()) {  // stopped at the goal
                CHECK(*m.line == SearchLine::goal);
                CHECK(m.shown == total);
                continue;
            }
            REQUIRE(m.shown >= 1);
            const std::size_t k = m.shown - 1;  // the expansion under way
            if (*m.line != SearchLine::loop) {
                if (seen.empty() || seen.back() != std::pair{k, *m.line})
                    seen.emplace_back(k, *m.line);
                // The tree marks the board this expansion took out (as the goal once tested).
                const bool found = k + 1 == total && *m.line == SearchLine::goal;
                const std::optional<view::PuzzleBoardView> now =
                    marked_in_tree(p, found ? view::PuzzleMark::goal : view::PuzzleMark::current);
                REQUIRE(now.has_value());
                CHECK(now->tiles == tiles_of(r.board_of(r.expansions[k])));
            }
            switch (*m.line) {
                case SearchLine::pop:
                    // Still at the front of the queue, marked as it leaves.
                    REQUIRE_FALSE(p.queue.empty());
                    CHECK(p.queue.front().mark == view::PuzzleMark::current);
                    CHECK(p.queue.front().tiles == tiles_of(r.board_of(r.expansions[k])));
                    break;
                case SearchLine::goal:
                case SearchLine::neighbours:
                case SearchLine::skip:
                    // Out of the queue; its neighbours not in yet.
                    for (const view::PuzzleBoardView& b : p.queue)
                        CHECK(b.mark != view::PuzzleMark::current);
                    if (k + 1 == total && *m.line == SearchLine::goal) {
                        CHECK(p.status.rfind("solved", 0) == 0);  // the search stops here
                    } else {
                        CHECK(in_queue(p) == r.queue_size(k) - 1 - stale_before(r, k));
                    }
                    break;
                case SearchLine::insert:
                case SearchLine::loop:
                    CHECK(in_queue(p) == r.queue_size(m.shown));
                    break;
                case SearchLine::start:
                    FAIL("the start's line after the search started");
                    break;
            }
        }
        // The walks: the first expansions and the goal's, line after line, nothing skipped.
        std::vector<std::pair<std::size_t, SearchLine>> expected;
        for (std::size_t k = 0; k < show::walked_expansions; ++k) {
            for (const SearchLine l : show::search_walk(r, k)) expected.emplace_back(k, l);
        }
        for (const SearchLine l : show::search_walk(r, total - 1))
            expected.emplace_back(total - 1, l);
        CHECK(seen == expected);
        // After the search: the playback, no line marked.
        CHECK_FALSE(lesson.frame_at(lesson.playback_start() + 0.5).code->current.has_value());
    }
}
