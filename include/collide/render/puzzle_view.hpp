#pragma once
/// \file
/// Frames of `collide puzzle`: breadth-first search against A* on the sliding puzzle, one panel
/// per method side by side. Each panel shows its search tree growing (one row per depth, the
/// most recent boards of each row drawn as small tile grids with their priority, edges to their
/// parents when those are drawn too), the front of its queue, its counters, and later its
/// solution played back on a large board. Drawn offscreen through the same GL path as the other
/// videos (GlTarget), to RGBA images.
///
/// The module sees plain values only (no search types): the app fills a PuzzleFrameView from the
/// recorded searches (collide/sim/puzzle/search.hpp) for every frame.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "collide/image.hpp"
#include "collide/render/context.hpp"

namespace collide::render {

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
    std::vector<PuzzleRowView> rows;     ///< the deepest rows drawn (at most max_puzzle_rows)
    std::string queue_title;             ///< "queue: next out first"
    std::vector<PuzzleBoardView> queue;  ///< its first entries (at most max_puzzle_queue_shown)
    std::string queue_more;              ///< e.g. "+ 1,234 more"

    // The playback (and, before the search has expanded anything, the start in the tree's place).
    PuzzleBoardView board;  ///< the large board; no tiles: none
    PuzzleSlideView slide;  ///< the tile moving, if any
    std::string caption;    ///< "move 5 of 31: 6 up"
};

/// One frame: a heading and one or two panels, left to right.
struct PuzzleFrameView {
    std::string heading;
    std::vector<PuzzlePanelView> panels;
};

/// Rows of the tree and boards per row drawn at most; queue entries shown at most.
inline constexpr std::size_t max_puzzle_rows = 5;
inline constexpr std::size_t max_puzzle_row_boards = 5;
inline constexpr std::size_t max_puzzle_queue_shown = 5;

/// Everything fixed for a whole video.
struct PuzzleViewConfig {
    int width = 1280;  ///< frame width in pixels, 320..8192
    int height = 720;  ///< frame height in pixels, 180..8192
    std::string font_path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

    /// Throws Error(input) naming the first bad field.
    void validate() const;
};

/// Draws puzzle frames with a GL context it owns. Not thread-safe; one per thread.
class PuzzleRenderer {
  public:
    /// Creates the context and GL resources. Throws Error: input for a bad config, runtime when
    /// the context, shaders or font cannot be set up.
    explicit PuzzleRenderer(const PuzzleViewConfig& config, Backend backend = Backend::automatic,
                            const NoticeSink& notice = {});
    ~PuzzleRenderer();
    PuzzleRenderer(PuzzleRenderer&&) noexcept;
    PuzzleRenderer& operator=(PuzzleRenderer&&) noexcept;
    PuzzleRenderer(const PuzzleRenderer&) = delete;
    PuzzleRenderer& operator=(const PuzzleRenderer&) = delete;

    /// Draws one frame, width x height RGBA8, rows top-down, into `out` (resized as needed).
    /// Throws Error(input) for no panels or more than two, or a board whose tiles do not match
    /// its side.
    void render(const PuzzleFrameView& frame, Image& out);
    [[nodiscard]] Image render(const PuzzleFrameView& frame);

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace collide::render
