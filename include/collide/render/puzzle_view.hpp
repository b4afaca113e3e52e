#pragma once
/// \file
/// Frames of `collide puzzle`: breadth-first search against A* on the sliding puzzle, one panel
/// per method side by side. Each panel shows its search tree growing (one row per depth, the
/// most recent boards of each row drawn as small tile grids with their priority, edges to their
/// parents when those are drawn too), the front of its queue, its counters, and later its
/// solution played back on a large board. Drawn offscreen through the same GL path as the other
/// videos (GlTarget), to RGBA images.
///
/// The module sees plain values only (no search types): the presentation layer
/// (collide/show/puzzle_program.hpp) fills a view::PuzzleFrameView (collide/view/puzzle.hpp) from
/// the recorded searches for every frame.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "collide/image.hpp"
#include "collide/render/context.hpp"
#include "collide/render/drawn_text.hpp"
#include "collide/render/renderer.hpp"
#include "collide/view/puzzle.hpp"

namespace collide::render {

/// Everything fixed for a whole video.
struct PuzzleViewConfig {
    int width = 1280;  ///< frame width in pixels, 320..8192
    int height = 720;  ///< frame height in pixels, 180..8192
    std::string font_path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    /// dark (screens) or light (projectors, print): the collision video's themes.
    Theme theme = Theme::dark;

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
    void render(const view::PuzzleFrameView& frame, Image& out);
    [[nodiscard]] Image render(const view::PuzzleFrameView& frame);

    /// Every piece of text of the last frame drawn, in drawing order, with its size (for tests:
    /// nothing a class reads is smaller than the lesson size).
    [[nodiscard]] const std::vector<DrawnText>& last_text() const noexcept;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace collide::render
