#pragma once
// Internal: the painter of overlay level full, today's expert layout: above each box its title
// and a grid of counters, below the panels a strip with the clock, the colour legend, the speed
// histogram against the Maxwell-Boltzmann curve, the energy drift plot and a notice line. The
// boxes, discs and failure marks are level none's (minimal_painter.hpp).

#include <cstddef>

#include "minimal_painter.hpp"

namespace collide::render {

class FullPainter : public MinimalPainter {
  public:
    /// Loads the body font. Throws collide::Error (runtime) when it cannot be loaded.
    explicit FullPainter(const RenderConfig& config);

    [[nodiscard]] FrameLayout layout_for(const FrameContent& frame) const override;

  private:
    void begin_frame(const FrameContent& frame) override;
    void add_marks(std::size_t index, const PanelContent& content,
                   const PanelLayout& panel) override;
    void add_panel_text(std::size_t index, const PanelContent& content,
                        const PanelLayout& panel) override;
    void finish_frame(const FrameContent& frame) override;

    void add_legend(RectF info, const ColorKeyWords& words);
    /// The notice line: the failure marks' legend of every panel, then the frame's notes.
    void add_notice_line(const TextSlot& line, const FrameContent& frame);
    [[nodiscard]] int counter_rows(const FrameContent& frame) const;
    [[nodiscard]] Rgba8 counter_color() const noexcept;
    [[nodiscard]] int panel_counter_columns(std::size_t panels) const;

    int counter_rows_ = 0;
};

}  // namespace collide::render
