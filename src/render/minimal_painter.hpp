#pragma once
// Internal: the painter of overlay level none: the boxes fill the frame, no text. Failures are
// today's expert marks (a halo around overlapping discs, a flash where a collision was missed,
// a ring around an escaped disc); the full level (full_painter.hpp) adds its text to this.

#include "painter.hpp"

namespace collide::render {

class MinimalPainter : public Painter {
  public:
    explicit MinimalPainter(const RenderConfig& config);

    [[nodiscard]] FrameLayout layout_for(const FrameContent& frame) const override;

  protected:
    /// Wall and trails sized from the body font (1 px walls without one).
    void use_classic_style();
    void begin_frame(const FrameContent& /*frame*/) override {}
    void add_marks(std::size_t index, const PanelContent& content,
                   const PanelLayout& panel) override;
    void add_panel_text(std::size_t /*index*/, const PanelContent& /*content*/,
                        const PanelLayout& /*panel*/) override {}
    void finish_frame(const FrameContent& /*frame*/) override {}
};

}  // namespace collide::render
