// The puzzle view (puzzle_view.hpp): input checks, highlights by pixel colour, and frames that
// repeat exactly.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "../support/assert_death.hpp"
#include "../support/input_error.hpp"
#include "../support/skip.hpp"
#include "collide/assert.hpp"
#include "collide/error.hpp"
#include "collide/render/puzzle_view.hpp"
#include "render_fixtures.hpp"

namespace collide::render {
namespace {

view::PuzzleBoardView board(std::vector<std::uint8_t> tiles,
                            view::PuzzleMark mark = view::PuzzleMark::plain) {
    view::PuzzleBoardView b;
    b.side = 3;
    b.tiles = std::move(tiles);
    b.mark = mark;
    b.label = "1+3=4";
    return b;
}

view::PuzzlePanelView search_panel(view::PuzzleMark newest) {
    view::PuzzlePanelView p;
    p.title = "A* (manhattan, --pq binary)";
    p.counters = {"expanded 2", "enqueued 5", "in queue 3"};
    p.status = "lowest priority first";
    view::PuzzleRowView root;
    root.label = "depth 0";
    root.count = "1 board";
    root.boards.push_back(board({1, 2, 3, 4, 0, 6, 7, 5, 8}));
    view::PuzzleRowView next;
    next.label = "depth 1";
    next.count = "1 board";
    next.boards.push_back(board({1, 2, 3, 4, 5, 6, 7, 0, 8}, newest));
    next.boards.back().parent = 0;
    p.rows = {root, next};
    p.queue_title = "binary PQ";
    p.queue.push_back(board({1, 2, 3, 4, 5, 6, 7, 8, 0}));
    p.queue_more = "+ 2 more";
    return p;
}

PuzzleViewConfig config_of(int width, int height) {
    PuzzleViewConfig c;
    c.width = width;
    c.height = height;
    return c;
}

constexpr Rgb8 amber{240, 170, 40};
constexpr Rgb8 tile{222, 224, 232};

}  // namespace

TEST_CASE("puzzle view: a bad config is an input error, a bad frame a failed assertion") {
    CHECK_THROWS_AS(config_of(100, 720).validate(), Error);
    // Frames come from collide's own code: a broken one is a programmer error (assert.hpp).
    if (!asserts_enabled) COLLIDE_SKIP_TEST("assertions are off in this build type");
    using collide::test::assertion_failure;
    using collide::test::contains;
    PuzzleRenderer renderer(config_of(854, 480), test::test_backend());
    const auto failure = [&](const view::PuzzleFrameView& f) {
        return assertion_failure([&] { (void)renderer.render(f); });
    };
    view::PuzzleFrameView none;
    CHECK(contains(failure(none), "a puzzle frame has 1 or 2 panels"));
    view::PuzzleFrameView three;
    three.panels.assign(3, search_panel(view::PuzzleMark::plain));
    CHECK(contains(failure(three), "a puzzle frame has 1 or 2 panels"));
    view::PuzzleFrameView wrong;
    wrong.panels.push_back(search_panel(view::PuzzleMark::plain));
    wrong.panels[0].queue[0].tiles.pop_back();  // 8 tiles on a 3x3 board
    CHECK(contains(failure(wrong), "a board of side 2 to 4 with side * side tiles"));
}

TEST_CASE("puzzle view: tiles, the board being expanded in amber, frames repeat exactly") {
    PuzzleRenderer renderer(config_of(854, 480), test::test_backend());
    view::PuzzleFrameView plain;
    plain.heading = "8-puzzle 1 2 3 4 0 6 7 5 8";
    plain.panels = {search_panel(view::PuzzleMark::plain), search_panel(view::PuzzleMark::plain)};
    view::PuzzleFrameView marked = plain;
    marked.panels[1].rows[1].boards[0].mark = view::PuzzleMark::current;
    const Image a = renderer.render(plain);
    const Image b = renderer.render(marked);
    REQUIRE(a.width == 854);
    REQUIRE(a.height == 480);
    CHECK(test::count_near(a, tile, 6) > 2000);  // 24 small tiles and more
    CHECK(test::count_near(a, amber, 30) < test::count_near(b, amber, 30) - 40);
    // Only the right half changed.
    CHECK(test::count_near(a, amber, 30, 0, 0, 427, 480) ==
          test::count_near(b, amber, 30, 0, 0, 427, 480));
    CHECK(renderer.render(marked).rgba == b.rgba);
}

TEST_CASE("puzzle view: the playback draws a large board with its sliding tile in amber") {
    PuzzleRenderer renderer(config_of(854, 480), test::test_backend());
    view::PuzzlePanelView p;
    p.title = "Breadth-first search";
    p.playback = true;
    p.board = board({1, 2, 3, 4, 5, 6, 7, 0, 8});
    p.caption = "move 1 of 2: 5 slides up";
    view::PuzzleFrameView still;
    still.panels = {p};
    view::PuzzleFrameView sliding = still;
    sliding.panels[0].slide = {7, 4, 0.5F};
    const Image a = renderer.render(still);
    const Image b = renderer.render(sliding);
    CHECK(test::count_near(a, amber, 20) < 100);
    CHECK(test::count_near(b, amber, 20) > 2000);  // one large tile, half way
}

}  // namespace collide::render
