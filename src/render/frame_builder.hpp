#pragma once
// Internal: the CPU half of the renderer. Turns a FrameContent into a DrawList for GlTarget with
// the painter of the video's overlay level, chosen once (painter.hpp: minimal_painter.hpp for
// none, full_painter.hpp for full, lesson_painter.hpp for lesson). No GL.

#include <memory>

#include "collide/render/renderer.hpp"
#include "draw_list.hpp"
#include "layout.hpp"
#include "lesson_painter.hpp"
#include "painter.hpp"

namespace collide::render {

/// The painter of `config.overlays`. Throws collide::Error (input) for a bad config, (runtime)
/// when a font cannot be loaded.
[[nodiscard]] std::unique_ptr<Painter> make_painter(const RenderConfig& config);

class FrameBuilder {
  public:
    /// Chooses the level's painter and loads the fonts it needs. Throws collide::Error (input)
    /// for a bad config, (runtime) when the font cannot be loaded.
    explicit FrameBuilder(const RenderConfig& config) : painter_(make_painter(config)) {}

    /// Builds the draw list of one frame (frames in time order: trails and markers remember).
    const DrawList& build(const FrameContent& frame) { return painter_->build(frame); }

    /// The layout of the last built frame.
    [[nodiscard]] const FrameLayout& layout() const noexcept { return painter_->layout(); }
    /// The strings drawn in the last built frame, by text slot.
    [[nodiscard]] const SlotTexts& drawn_text() const noexcept { return painter_->drawn_text(); }
    /// The draw list of the last built frame.
    [[nodiscard]] const DrawList& draw_list() const noexcept { return painter_->draw_list(); }
    /// The layout a frame would get (same rules as build, nothing drawn).
    [[nodiscard]] FrameLayout layout_for(const FrameContent& frame) const {
        return painter_->layout_for(frame);
    }
    [[nodiscard]] const RenderConfig& config() const noexcept { return painter_->config(); }

  private:
    std::unique_ptr<Painter> painter_;
};

}  // namespace collide::render
