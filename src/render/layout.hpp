#pragma once
// Internal: where everything goes in a frame. Pure arithmetic on the config and the box, so the
// tests can predict where a disc must land.

#include <vector>

#include "collide/box.hpp"
#include "collide/render/renderer.hpp"
#include "overlay_geometry.hpp"

namespace collide::render {

/// One panel: its whole area, the header (title and counters) and the box's pixel rectangle.
struct PanelLayout {
    RectF area;
    RectF header;        // empty when overlays are off
    RectF box;           // the box [0,W]x[0,H] in pixels, aspect ratio preserved
    double scale = 1.0;  // pixels per box unit

    /// Box coordinates (y up) to frame pixels (y down).
    [[nodiscard]] PointF to_pixels(Vec2 p, const Box& b) const noexcept {
        return {box.x0 + static_cast<float>(p.x * scale),
                box.y0 + static_cast<float>((b.height - p.y) * scale)};
    }
};

struct FrameLayout {
    std::vector<PanelLayout> panels;
    RectF strip;  // the bottom strip (empty when overlays are off)
    float margin = 0.0F;
};

/// The font size used for a frame height (px): legible at 480p, not huge at 1080p.
[[nodiscard]] float font_pixel_height(int frame_height) noexcept;

/// Columns of the counter grid under a panel title. It depends only on the panel width and the
/// font size, never on the counters' text, so the layout stays put while the numbers change.
[[nodiscard]] int counter_columns(float panel_width, float font_pixel_height) noexcept;

/// Lays out `boxes.size()` panels side by side (and the strip when overlays are on); each
/// header holds the title line and `counter_rows` rows of counters.
[[nodiscard]] FrameLayout compute_layout(const RenderConfig& config, const std::vector<Box>& boxes,
                                         float line_height, int counter_rows = 1);

}  // namespace collide::render
