// Level none: the boxes and discs only, with the expert failure marks.
#include "minimal_painter.hpp"

#include <algorithm>
#include <cmath>

namespace collide::render {

MinimalPainter::MinimalPainter(const RenderConfig& config) : Painter(config) {
    use_classic_style();
}

void MinimalPainter::use_classic_style() {
    style_.wall = std::max(1.0F, std::round(body_pixel_height() / 10.0F));
    style_.trail_width = std::max(1.0F, style_.wall * 1.5F);
}

FrameLayout MinimalPainter::layout_for(const FrameContent& frame) const {
    return classic_layout(config_.width, config_.height, false, panel_boxes(frame), 0.0F, 0);
}

// Overlapping discs get a halo each, missed collisions a flash the size of a few discs.
void MinimalPainter::add_marks(std::size_t /*index*/, const PanelContent& content,
                               const PanelLayout& panel) {
    const Snapshot& snapshot = *content.snapshot;
    const Box& box = snapshot.box;
    const float ring = std::max(1.5F, style_.wall * 1.5F);
    for (const auto& [a, b] : snapshot.overlapping_pairs) {
        for (const std::uint32_t index : {a, b}) {
            if (index >= snapshot.discs.size()) continue;  // defensive: bad marker data
            const DiscState& disc = snapshot.discs[index];
            const PointF c = panel.to_pixels(disc.position, box);
            const auto radius = static_cast<float>(disc.radius * panel.scale);
            list_.discs.push_back({c.x, c.y, radius + 2.0F * ring, ring, overlap_halo_color});
        }
    }
    if (!snapshot.missed_collisions.empty()) {
        double mean_radius = 0.0;
        for (const DiscState& d : snapshot.discs) mean_radius += d.radius;
        mean_radius /= static_cast<double>(std::max<std::size_t>(snapshot.discs.size(), 1));
        const float flash = std::max(8.0F, static_cast<float>(3.0 * mean_radius * panel.scale));
        for (const Vec2 where : snapshot.missed_collisions) {
            const PointF c = panel.to_pixels(where, box);
            list_.discs.push_back({c.x, c.y, flash, -1.0F, missed_flash_color});
        }
    }
}

}  // namespace collide::render
