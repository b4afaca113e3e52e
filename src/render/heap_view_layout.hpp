#pragma once
// Internal: where the pieces of a priority-queue lesson frame go (heap_view.hpp), in frame pixels
// with y down. Pure geometry, no GL: unit-tested.

#include <cstddef>
#include <vector>

#include "overlay_geometry.hpp"

namespace collide::render {

/// Node centres of a d-ary heap of `count` nodes in a unit box: x in [0, 1], y in [0, 1] (root at
/// y = 0, deepest level at y = 1; a single level sits at y = 0.5), x = 0 and 1 the centres of the
/// outermost columns (tree_columns). `complete`: the textbook picture, every level spread as if
/// it were full, so each parent sits over its middle child; it needs d^(levels-1) columns.
/// Otherwise the compact form: leaves spread evenly in depth-first order, each node centred over
/// its subtree, as wide as the leaves (no two nodes overlap however deep the tree is).
[[nodiscard]] std::vector<PointF> tree_positions(std::size_t count, unsigned arity,
                                                 bool complete = false);

/// Columns of the layout above: d^(levels-1) when complete, else the leaves.
[[nodiscard]] std::size_t tree_columns(std::size_t count, unsigned arity, bool complete) noexcept;

/// Levels of a d-ary heap of `count` nodes (0 for none).
[[nodiscard]] int tree_levels(std::size_t count, unsigned arity) noexcept;

/// Leaves of a d-ary heap of `count` nodes (the tree's width in nodes).
[[nodiscard]] std::size_t tree_leaves(std::size_t count, unsigned arity) noexcept;

/// Panels of a frame, side by side in one row inside `area`, `gap` pixels apart.
[[nodiscard]] std::vector<RectF> panel_rects(std::size_t panels, RectF area, float gap);

/// Panels side by side in one row inside `area`, `gap` pixels apart, each at least as wide as
/// its entry in `needs` (pixels) where the row allows: equal widths when every panel fits its
/// equal share (as panel_rects), else the panels that need more get it and the others share the
/// rest equally (never under their own need); when the needs add up to more than the row, equal
/// widths again (no panel is given up for another).
[[nodiscard]] std::vector<RectF> panel_rects_by_need(const std::vector<float>& needs, RectF area,
                                                     float gap);

/// Columns of the panel grid for `panels` panels.
[[nodiscard]] std::size_t panel_columns(std::size_t panels) noexcept;

}  // namespace collide::render
