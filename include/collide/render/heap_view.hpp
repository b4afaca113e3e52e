#pragma once
/// \file
/// Frames of a priority-queue lesson (`collide heap`): each panel a queue drawn as its tree
/// (binary or d-ary heap: nodes with their keys, edges) above its array (slots with their
/// indices), or as the array alone (unordered and ordered arrays), with highlights for the keys
/// being compared, keys sliding along their edge and in the array during an exchange, a caption
/// and counters; the indexed heap's map from key to index beside its tree; a strip of the
/// operations on top with the current one marked. Rendered offscreen with OpenGL like the
/// collision video (same context backends, shaders and text blending), to RGBA images.
///
/// The module sees plain values only (no simulation types): the presentation layer
/// (collide/show/heap_program.hpp) fills a view::HeapFrameView (collide/view/heap.hpp) for every
/// frame.
///
///     HeapViewConfig config; config.width = 1280; config.height = 720;
///     HeapRenderer renderer(config);
///     view::HeapFrameView frame; frame.tokens = {"P", "Q", "*"}; frame.current_token = 1;
///     frame.panels.push_back(panel);   // slots, marks, an exchange under way, caption, counters
///     Image image = renderer.render(frame);

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "collide/image.hpp"
#include "collide/render/context.hpp"
#include "collide/render/drawn_text.hpp"
#include "collide/render/renderer.hpp"
#include "collide/view/heap.hpp"

namespace collide::render {

/// Everything fixed for a whole video.
struct HeapViewConfig {
    int width = 1280;  ///< frame width in pixels, min_frame_side..max_frame_side (renderer.hpp)
    int height = 720;  ///< frame height in pixels, as width
    /// The widest key of the video: node and slot text is sized so that it fits.
    std::string widest_key = "W";
    /// Every key of the video (HeapProgram::keys), if known: the widest of them in the drawing
    /// font replaces widest_key ("damson" is wider than "banana", as many letters).
    std::vector<std::string> keys;
    /// Every caption of the video (HeapProgram::captions), if known: each panel reserves the
    /// lines the longest of them wraps to at its width (at most three), and the tree gets the
    /// rest. Empty: room for ~70 characters, the longest the lesson writes.
    std::vector<std::string> captions;
    /// `--code`: every line of every listing the video shows, so that the code column is as
    /// wide as the widest of them in every frame (the tree keeps its place when the listing
    /// changes). Empty: each frame's own listing decides.
    std::vector<view::CodeLineView> code_lines;
    std::string font_path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    /// dark (screens) or light (projectors, print): the collision video's themes.
    Theme theme = Theme::dark;

    /// Throws Error(input) naming the first bad field.
    void validate() const;
};

/// Most panels in one frame.
inline constexpr std::size_t max_heap_panels = 6;

/// The most keys a queue may hold at once when `panels` queues share the frame (side by side)
/// and still be drawn legibly: 36 / panels (36 for one panel, 12 for three, 7 for five: the
/// lecture's trace holds 7), which keeps array slots over ~21 px wide and keys over ~13 px tall
/// at 854x480 (-q l), half as much again at 720p. With `code` (the pseudocode column takes 40 %
/// of the width) 21 / panels.
[[nodiscard]] std::size_t max_legible_keys(std::size_t panels, bool code = false) noexcept;

class HeapDrawTarget;  // internal: the GL half (src/render/heap_draw_target.hpp)

/// Draws lesson frames with a GL context it owns. Not thread-safe; one per thread.
class HeapRenderer {
  public:
    /// Creates the context and GL resources. Throws Error: input for a bad config, runtime when
    /// the context, shaders or font cannot be set up.
    explicit HeapRenderer(const HeapViewConfig& config, Backend backend = Backend::automatic,
                          const NoticeSink& notice = {});
    ~HeapRenderer();
    HeapRenderer(HeapRenderer&&) noexcept;
    HeapRenderer& operator=(HeapRenderer&&) noexcept;
    HeapRenderer(const HeapRenderer&) = delete;
    HeapRenderer& operator=(const HeapRenderer&) = delete;

    /// A renderer that lays frames out without drawing them: no context is made, so it costs
    /// no GL start-up and no pixels (tests that read only last_text go through thousands of
    /// frames). Only lay_out and last_text may be called; render fails an assertion. Throws as
    /// the constructor, less the context's errors.
    [[nodiscard]] static HeapRenderer layout_only(const HeapViewConfig& config);

    /// Draws one frame, width x height RGBA8, rows top-down, into `out` (resized as needed).
    /// Throws Error(input) for no panels, more than max_heap_panels, more slots than a panel's
    /// capacity or an exchange of slots that do not exist.
    void render(const view::HeapFrameView& frame, Image& out);
    [[nodiscard]] Image render(const view::HeapFrameView& frame);

    /// Lays `frame` out exactly as render does before it draws (the same function), without
    /// drawing: last_text then holds the text render would draw. Throws as render.
    void lay_out(const view::HeapFrameView& frame);

    /// Whether every panel of `frame` holds its parts at `config`'s size with every text at the
    /// lesson size: no two tree nodes touching, each key inside its node, the indexed heap's map
    /// and the counters in their place. Layout only: no context is made. Throws Error(input)
    /// for a bad config, runtime when the font cannot be read.
    [[nodiscard]] static bool fits(const HeapViewConfig& config, const view::HeapFrameView& frame);

    /// Every piece of text of the last frame drawn, in drawing order, with its size (for tests:
    /// nothing a class reads is smaller than the lesson size).
    [[nodiscard]] const std::vector<DrawnText>& last_text() const noexcept;

  private:
    struct Impl;
    explicit HeapRenderer(std::unique_ptr<Impl> impl);
    /// Draws through `target` (heap_view_gl.cpp's GL one), or none: layout only.
    HeapRenderer(const HeapViewConfig& config, std::unique_ptr<HeapDrawTarget> target);
    std::unique_ptr<Impl> impl_;
};

}  // namespace collide::render
