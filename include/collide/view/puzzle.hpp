#pragma once
/// \file
/// What one frame of `collide puzzle` shows, as plain values: a heading and one or two panels,
/// each with its search tree's deepest rows of small boards, the front of its queue, counters,
/// and later its solution played back on a large board. The presentation layer
/// (collide/show/puzzle_program.hpp) fills it for frame k; the painter
/// (collide/render/puzzle_view.hpp) draws it. Std-only: no search types, no drawing.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "collide/view/code.hpp"

namespace collide::view {

/// How a small board is highlighted.
enum class PuzzleMark : std::uint8_t {
    plain,
    current,   ///< the board being expanded now
    goal,      ///< the goal, once found
    solution,  ///< on the solution path (shown once the search is done)
};

/// A board: side x side tiles row by row, 0 the blank.
struct PuzzleBoardView {
    int side = 3;
    std::vector<std::uint8_t> tiles;
    std::string label;  ///< under the board, e.g. "12 = 4+8" (priority = moves + estimate)
    PuzzleMark mark = PuzzleMark::plain;
    /// The row-above board this one was generated from (index in that row's boards), or -1 when
    /// it is not drawn.
    int parent = -1;
};

/// One depth of the search tree.
struct PuzzleRowView {
    std::string label;                    ///< e.g. "depth 7"
    std::string count;                    ///< e.g. "1,234 boards"
    std::vector<PuzzleBoardView> boards;  ///< the most recent ones, oldest first
};

/// Rows of the tree and boards per row drawn at most; queue entries shown at most.
/// (Few and large: a board's digits and label are lesson text, capitals 2.8 % of the frame.)
inline constexpr std::size_t max_puzzle_rows = 2;
inline constexpr std::size_t max_puzzle_row_boards = 2;
inline constexpr std::size_t max_puzzle_queue_shown = 2;

/// How many small boards a panel draws: rows of the tree, boards per row, queue entries.
struct PuzzleShown {
    std::size_t rows = max_puzzle_rows;
    std::size_t row_boards = max_puzzle_row_boards;
    std::size_t queue = max_puzzle_queue_shown;
};

/// What a panel of a `side` x `side` puzzle draws, `panels` side by side (`code`: beside the
/// code). A 15-puzzle's two-digit tiles need cells a third larger than one digit's, at the
/// lesson size: one row of the tree and one queue entry, two boards in the row only where one
/// panel has the frame's width.
[[nodiscard]] constexpr PuzzleShown puzzle_shown(int side, std::size_t panels, bool code) noexcept {
    if (side <= 3) return {};
    return {1, panels == 1 && !code ? std::size_t{2} : std::size_t{1}, 1};
}

/// A tile sliding during the playback: from cell `from` to cell `to`, t in [0, 1].
struct PuzzleSlideView {
    int from = -1;
    int to = -1;
    float t = 0.0F;
};

/// One method.
struct PuzzlePanelView {
    std::string title;                  ///< "BFS (FIFO queue)"
    std::vector<std::string> counters;  ///< e.g. {"expanded 120", "enqueued 240", ...}
    std::string status;                 ///< a line under the counters ("searching", "solved ...")
    bool playback = false;              ///< true: the large board instead of tree and queue

    // The search.
    std::string hidden_rows;             ///< a line above the rows for depths not drawn, or ""
    std::vector<PuzzleRowView> rows;     ///< the deepest rows drawn (at most shown.rows)
    std::string queue_title;             ///< "queue: next out first"
    std::vector<PuzzleBoardView> queue;  ///< its first entries (at most shown.queue)
    std::string queue_more;              ///< e.g. "+ 1,234 more"
    /// The places for boards the layout keeps (rows, boards per row, queue entries), filled or
    /// not: the boards keep their size as the search fills them.
    PuzzleShown shown;

    // The playback (and, before the search has expanded anything, the start in the tree's place).
    PuzzleBoardView board;  ///< the large board; no tiles: none
    PuzzleSlideView slide;  ///< the tile moving, if any
    std::string caption;    ///< "move 5 of 31: 6 up"
};

/// One frame: a heading and one or two panels, left to right.
struct PuzzleFrameView {
    std::string heading;
    std::vector<PuzzlePanelView> panels;
    /// `--code` (one panel): the search loop's pseudocode in a column right of the panel, the
    /// line under way marked; unset: no column.
    std::optional<CodeView> code;
};

}  // namespace collide::view
