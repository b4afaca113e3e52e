#include "heap_view_layout.hpp"

#include <algorithm>

namespace collide::render {

namespace {

/// Depth-first: leaves get consecutive x, parents the middle of their children.
float place(std::size_t i, std::size_t count, unsigned d, float& next_leaf,
            std::vector<PointF>& out) {
    const std::size_t first = d * i + 1;
    if (first >= count) {
        out[i].x = next_leaf;
        next_leaf += 1.0F;
        return out[i].x;
    }
    const std::size_t last = std::min(count, first + d) - 1;
    const float left = place(first, count, d, next_leaf, out);
    float right = left;
    for (std::size_t c = first + 1; c <= last; ++c) right = place(c, count, d, next_leaf, out);
    out[i].x = 0.5F * (left + right);
    return out[i].x;
}

}  // namespace

int tree_levels(std::size_t count, unsigned arity) noexcept {
    int levels = 0;
    std::size_t level_size = 1;
    std::size_t seen = 0;
    while (seen < count) {
        seen += level_size;
        level_size *= arity;
        ++levels;
    }
    return levels;
}

std::size_t tree_leaves(std::size_t count, unsigned arity) noexcept {
    std::size_t leaves = 0;
    for (std::size_t i = 0; i < count; ++i) leaves += arity * i + 1 >= count;
    return leaves;
}

std::vector<PointF> tree_positions(std::size_t count, unsigned arity) {
    std::vector<PointF> out(count);
    if (count == 0) return out;
    float next_leaf = 0.0F;
    place(0, count, arity, next_leaf, out);
    const float span = std::max(1.0F, next_leaf - 1.0F);
    const int levels = tree_levels(count, arity);
    std::size_t level_start = 0;
    std::size_t level_size = 1;
    for (int level = 0; level < levels; ++level) {
        const float y =
            levels == 1 ? 0.5F : static_cast<float>(level) / static_cast<float>(levels - 1);
        for (std::size_t i = level_start; i < std::min(count, level_start + level_size); ++i) {
            out[i].y = y;
            out[i].x = next_leaf <= 1.0F ? 0.5F : out[i].x / span;
        }
        level_start += level_size;
        level_size *= arity;
    }
    return out;
}

std::size_t panel_columns(std::size_t panels) noexcept {
    // One row: a tree needs height more than width, and a row keeps the lock-step easy to follow.
    return std::max<std::size_t>(panels, 1);
}

std::vector<RectF> panel_rects(std::size_t panels, RectF area, float gap) {
    std::vector<RectF> out;
    if (panels == 0) return out;
    const std::size_t columns = panel_columns(panels);
    const std::size_t rows = (panels + columns - 1) / columns;
    const float w =
        (area.width() - gap * static_cast<float>(columns - 1)) / static_cast<float>(columns);
    const float h = (area.height() - gap * static_cast<float>(rows - 1)) / static_cast<float>(rows);
    for (std::size_t p = 0; p < panels; ++p) {
        const auto c = static_cast<float>(p % columns);
        const auto r = static_cast<float>(p / columns);
        const float x0 = area.x0 + c * (w + gap);
        const float y0 = area.y0 + r * (h + gap);
        out.push_back({x0, y0, x0 + w, y0 + h});
    }
    return out;
}

}  // namespace collide::render
