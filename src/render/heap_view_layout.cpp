#include "heap_view_layout.hpp"

#include <algorithm>

namespace collide::render {

namespace {

/// Depth-first: leaves get consecutive columns, every node the centre of its subtree's columns.
/// Returns the first column after the subtree.
float place(std::size_t i, std::size_t count, unsigned d, float next_leaf,
            std::vector<PointF>& out) {
    const std::size_t first = d * i + 1;
    if (first >= count) {
        out[i].x = next_leaf;
        return next_leaf + 1.0F;
    }
    const std::size_t last = std::min(count, first + d) - 1;
    const float left = next_leaf;
    for (std::size_t c = first; c <= last; ++c) next_leaf = place(c, count, d, next_leaf, out);
    out[i].x = 0.5F * (left + next_leaf - 1.0F);
    return next_leaf;
}

std::size_t power(unsigned d, int e) noexcept {
    std::size_t p = 1;
    for (int k = 0; k < e; ++k) p *= d;
    return p;
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

std::size_t tree_columns(std::size_t count, unsigned arity, bool complete) noexcept {
    if (!complete) return tree_leaves(count, arity);
    return count == 0 ? 0 : power(arity, tree_levels(count, arity) - 1);
}

std::vector<PointF> tree_positions(std::size_t count, unsigned arity, bool complete) {
    std::vector<PointF> out(count);
    if (count == 0) return out;
    const float columns = static_cast<float>(tree_columns(count, arity, complete));
    if (!complete) (void)place(0, count, arity, 0.0F, out);
    const float span = std::max(1.0F, columns - 1.0F);
    const int levels = tree_levels(count, arity);
    std::size_t level_start = 0;
    std::size_t level_size = 1;
    for (int level = 0; level < levels; ++level) {
        const float y =
            levels == 1 ? 0.5F : static_cast<float>(level) / static_cast<float>(levels - 1);
        // Complete: a node of this level spans columns / level_size columns.
        const float slot = columns / static_cast<float>(level_size);
        for (std::size_t i = level_start; i < std::min(count, level_start + level_size); ++i) {
            if (complete) {
                out[i].x =
                    (static_cast<float>(i - level_start) + 0.5F) * slot - 0.5F;  // in columns
            }
            out[i].y = y;
            out[i].x = columns <= 1.0F ? 0.5F : out[i].x / span;
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

std::vector<RectF> panel_rects_by_need(const std::vector<float>& needs, RectF area, float gap) {
    std::vector<RectF> out = panel_rects(needs.size(), area, gap);
    if (needs.empty()) return out;
    const float total = area.width() - gap * static_cast<float>(needs.size() - 1);
    float sum = 0.0F;
    for (const float n : needs) sum += std::max(n, 0.0F);
    std::vector<float> widths(needs.size(), total / static_cast<float>(needs.size()));
    // More than the row holds: equal widths (every panel as cramped as its neighbour, none
    // sacrificed to another).
    if (sum > total) return out;
    {
        // Water filling: the panels that need more than an equal share of what is left get
        // their need, until every other panel's need fits the share.
        std::vector<bool> fixed(needs.size(), false);
        for (bool changed = true; changed;) {
            changed = false;
            float left = total;
            std::size_t free = 0;
            for (std::size_t i = 0; i < needs.size(); ++i) {
                if (fixed[i]) {
                    left -= needs[i];
                } else {
                    ++free;
                }
            }
            const float share = free > 0 ? left / static_cast<float>(free) : 0.0F;
            for (std::size_t i = 0; i < needs.size(); ++i) {
                if (!fixed[i] && needs[i] > share) {
                    fixed[i] = true;
                    changed = true;
                }
            }
            for (std::size_t i = 0; i < needs.size(); ++i) widths[i] = fixed[i] ? needs[i] : share;
        }
    }
    float x0 = area.x0;
    for (std::size_t i = 0; i < needs.size(); ++i) {
        out[i].x0 = x0;
        out[i].x1 = x0 + widths[i];
        x0 = out[i].x1 + gap;
    }
    return out;
}

}  // namespace collide::render
