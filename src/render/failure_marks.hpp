#pragma once
// Internal: the lesson's failure marks, each kind its own shape (a ring for a missed collision,
// a cross on an overlapping pair, an arrow to the edge where a disc left the box, a diamond
// round a disc that went through a barrier), the
// legend's symbols, and the dashed edge of a periodic box. The presentation layer chooses the
// marks (show::FailureMarks); this paints them. No GL.

#include <vector>

#include "collide/box.hpp"
#include "collide/view/collision.hpp"
#include "draw_list.hpp"
#include "layout.hpp"

namespace collide::render {

/// How the marks of a frame look (lesson level), from its text size and theme.
struct MarkStyle {
    float min_radius = 8.0F;  ///< px: the smallest ring or cross (legible at any disc size)
    float stroke = 2.0F;      ///< px: line width of rings, crosses and arrows
    float reach = 4.0F;       ///< px: how far inside the box an arrow's tip stops
    Rgba8 color;              ///< the failure colour
    float floor = 0.0F;       ///< least opacity of a fading ring (keeps 3:1 against the box)
};

/// Paints `marks` of a panel: rings into `list.discs` (the caller closes the panel's disc group,
/// scissored to the box), crosses and arrows into `list.over`, every mark within the box (the
/// text is outside it).
void paint_failure_marks(DrawList& list, const std::vector<FailureMark>& marks,
                         const PanelLayout& panel, const Box& box, const MarkStyle& style);

/// A legend's symbol of `kind` in a square of side `size` centred at `centre` (triangles only).
void paint_mark_symbol(OverlayBatch& batch, FailureKind kind, PointF centre, float size,
                       const MarkStyle& style);

/// A ring of triangles (for symbols outside any disc group).
void add_ring(OverlayBatch& batch, PointF centre, float radius, float width, Rgba8 color);

/// A rectangle outline `width` pixels thick inside `r`, dashed: every side starts and ends with
/// a dash (the corners drawn), dashes and gaps about `dash` long.
void add_dashed_frame(OverlayBatch& batch, RectF r, float width, float dash, Rgba8 color);

/// The dash (and gap) length of a periodic edge `wall` pixels thick.
[[nodiscard]] float edge_dash(float wall) noexcept;

/// A horizontal dashed segment from (x0, y) to (x1, y), `width` thick (the legend's sample).
void add_dashed_line(OverlayBatch& batch, float x0, float x1, float y, float width, float dash,
                     Rgba8 color);

}  // namespace collide::render
