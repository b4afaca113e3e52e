#include "layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide::render {

float font_pixel_height(int frame_height) noexcept {
    return std::clamp(std::round(static_cast<float>(frame_height) / 34.0F), 11.0F, 48.0F);
}

int counter_columns(float panel_width, float font_pixel_height) noexcept {
    // About 14 em per column keeps a short "label  value" counter on one line.
    const float em = std::max(font_pixel_height, 1.0F);
    return std::clamp(static_cast<int>(panel_width / (14.0F * em)), 1, 4);
}

FrameLayout compute_layout(const RenderConfig& config, const std::vector<Box>& boxes,
                           float line_height, int counter_rows) {
    FrameLayout layout;
    const auto width = static_cast<float>(config.width);
    const auto height = static_cast<float>(config.height);
    layout.margin = std::max(2.0F, std::round(std::min(width, height) * 0.01F));
    const float m = layout.margin;
    float panels_bottom = height;
    float header_height = 0.0F;
    if (config.overlays) {
        const float strip_height = std::round(std::max(4.2F * line_height, 0.22F * height));
        panels_bottom = height - strip_height;
        layout.strip = {0.0F, panels_bottom, width, height};
        header_height = static_cast<float>(1 + std::max(counter_rows, 0)) * line_height;
    }
    const auto count = static_cast<float>(std::max<std::size_t>(boxes.size(), 1));
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        PanelLayout panel;
        panel.area = {std::round(width * static_cast<float>(i) / count), 0.0F,
                      std::round(width * static_cast<float>(i + 1) / count), panels_bottom};
        panel.header = {panel.area.x0 + m, m, panel.area.x1 - m, m + header_height};
        const RectF room{panel.area.x0 + m, panel.header.y1 + m, panel.area.x1 - m,
                         panels_bottom - m};
        // Pixels per scene unit: anything from ~1e-48 (a box of 1e50 units) to ~1e52 (1e-50
        // units); only a degenerate room could make it 0.
        const double scale =
            std::max(std::numeric_limits<double>::min(),
                     std::min(static_cast<double>(room.width()) / boxes[i].width,
                              static_cast<double>(room.height()) / boxes[i].height));
        const auto box_w = static_cast<float>(boxes[i].width * scale);
        const auto box_h = static_cast<float>(boxes[i].height * scale);
        const float x0 = std::round(room.x0 + 0.5F * (room.width() - box_w));
        const float y0 = std::round(room.y0 + 0.5F * (room.height() - box_h));
        panel.box = {x0, y0, x0 + box_w, y0 + box_h};
        panel.scale = scale;
        layout.panels.push_back(panel);
    }
    return layout;
}

}  // namespace collide::render
