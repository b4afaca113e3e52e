// The lesson's failure marks by kind, the legend's symbols, and dashed periodic edges.
#include "failure_marks.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "theme.hpp"

namespace collide::render {

namespace {

/// A fading mark's colour: from full down to the floor that keeps it legible, never below.
Rgba8 mark_color(const MarkStyle& style, float opacity) {
    const float o = std::clamp(opacity, 0.0F, 1.0F);
    return faded(style.color, style.floor + (1.0F - style.floor) * o);
}

/// A diamond (a square on its corner) of half-diagonal `half` round c.
void add_diamond(OverlayBatch& batch, PointF c, float half, float width, Rgba8 color) {
    const PointF top{c.x, c.y - half};
    const PointF right{c.x + half, c.y};
    const PointF bottom{c.x, c.y + half};
    const PointF left{c.x - half, c.y};
    batch.add_line(top, right, width, color);
    batch.add_line(right, bottom, width, color);
    batch.add_line(bottom, left, width, color);
    batch.add_line(left, top, width, color);
}

void add_cross(OverlayBatch& batch, PointF c, float arm, float width, Rgba8 color) {
    batch.add_line({c.x - arm, c.y - arm}, {c.x + arm, c.y + arm}, width, color);
    batch.add_line({c.x - arm, c.y + arm}, {c.x + arm, c.y - arm}, width, color);
}

/// An arrow from `from` to `tip`: a shaft and a chevron head.
void add_arrow(OverlayBatch& batch, PointF from, PointF tip, float width, Rgba8 color) {
    const float dx = tip.x - from.x;
    const float dy = tip.y - from.y;
    const float length = std::sqrt(dx * dx + dy * dy);
    if (length <= 0.0F) return;
    const float ux = dx / length;
    const float uy = dy / length;
    const float head = 0.45F * length;
    batch.add_line(from, tip, width, color);
    // The head's two strokes, 40 degrees either side of the shaft, ending a little past the tip
    // so the joint is closed.
    const float back_x = -ux * head;
    const float back_y = -uy * head;
    const float side_x = -uy * head * 0.84F;
    const float side_y = ux * head * 0.84F;
    const PointF end{tip.x + ux * 0.3F * width, tip.y + uy * 0.3F * width};
    batch.add_line(end, {tip.x + back_x + side_x, tip.y + back_y + side_y}, width, color);
    batch.add_line(end, {tip.x + back_x - side_x, tip.y + back_y - side_y}, width, color);
}

}  // namespace

void add_ring(OverlayBatch& batch, PointF centre, float radius, float width, Rgba8 color) {
    constexpr int segments = 24;
    const float r = radius - 0.5F * width;
    for (int k = 0; k < segments; ++k) {
        const double a0 = 2.0 * std::numbers::pi * k / segments;
        const double a1 = 2.0 * std::numbers::pi * (k + 1) / segments;
        // A little past each joint, so the ring has no cracks.
        batch.add_line({centre.x + r * static_cast<float>(std::cos(a0)),
                        centre.y + r * static_cast<float>(std::sin(a0))},
                       {centre.x + r * static_cast<float>(std::cos(a1 + 0.02)),
                        centre.y + r * static_cast<float>(std::sin(a1 + 0.02))},
                       width, color);
    }
}

void paint_failure_marks(DrawList& list, const std::vector<FailureMark>& marks,
                         const PanelLayout& panel, const Box& box, const MarkStyle& style) {
    for (const FailureMark& mark : marks) {
        const PointF c = panel.to_pixels(mark.where, box);
        const float size = std::max(style.min_radius, static_cast<float>(mark.size * panel.scale));
        switch (mark.kind) {
            case FailureKind::missed:
                list.discs.push_back(
                    {c.x, c.y, size, style.stroke, mark_color(style, mark.opacity)});
                break;
            case FailureKind::overlapping: {
                // Arms of a cross as long as the pair is wide, the whole cross inside the box.
                const float arm =
                    std::min(0.8F * size, 0.5F * std::min(panel.box.width(), panel.box.height()));
                const float reach = arm + style.stroke;
                const PointF at{std::clamp(c.x, panel.box.x0 + reach, panel.box.x1 - reach),
                                std::clamp(c.y, panel.box.y0 + reach, panel.box.y1 - reach)};
                add_cross(list.over, at, arm, style.stroke, mark_color(style, mark.opacity));
                break;
            }
            case FailureKind::tunnelled: {
                // Round the disc (a diamond holds a circle of radius half / sqrt 2), at least as
                // big as the smallest mark, the whole diamond inside the box.
                const float disc = static_cast<float>(mark.size * panel.scale);
                const float half = std::min(std::max(style.min_radius, 1.42F * disc + style.stroke),
                                            0.5F * std::min(panel.box.width(), panel.box.height()));
                const float reach = half + style.stroke;
                const PointF at{std::clamp(c.x, panel.box.x0 + reach, panel.box.x1 - reach),
                                std::clamp(c.y, panel.box.y0 + reach, panel.box.y1 - reach)};
                add_diamond(list.over, at, half, style.stroke, mark_color(style, mark.opacity));
                break;
            }
            case FailureKind::left_box: {
                // From inside the box to the edge where the disc left, the tip (its chevron's
                // joint too) just inside: the wall outside the box stops it, clear of any text.
                const auto ox = static_cast<float>(mark.out.x);
                const auto oy = static_cast<float>(-mark.out.y);  // pixels: y down
                const float length = 2.0F * style.min_radius;
                const float back = -style.reach;
                const PointF tip{c.x + ox * back, c.y + oy * back};
                const PointF from{tip.x - ox * length, tip.y - oy * length};
                add_arrow(list.over, from, tip, style.stroke, mark_color(style, mark.opacity));
                break;
            }
        }
    }
}

void paint_mark_symbol(OverlayBatch& batch, FailureKind kind, PointF centre, float size,
                       const MarkStyle& style) {
    const float half = 0.5F * size;
    switch (kind) {
        case FailureKind::missed:
            add_ring(batch, centre, half, style.stroke, style.color);
            break;
        case FailureKind::overlapping:
            add_cross(batch, centre, 0.8F * half, style.stroke, style.color);
            break;
        case FailureKind::tunnelled:
            add_diamond(batch, centre, half, style.stroke, style.color);
            break;
        case FailureKind::left_box:
            // Pointing up and out, as from the box's top edge (the legend sits under the box:
            // a sideways arrow would read as "next").
            add_arrow(batch, {centre.x, centre.y + half}, {centre.x, centre.y - half}, style.stroke,
                      style.color);
            break;
    }
}

void add_dashed_line(OverlayBatch& batch, float x0, float x1, float y, float width, float dash,
                     Rgba8 color) {
    const float length = x1 - x0;
    if (length <= 0.0F || dash <= 0.0F) return;
    // An odd number of pieces, dashes at both ends.
    int pieces = std::max(1, static_cast<int>(std::lround(length / dash)));
    if (pieces % 2 == 0) ++pieces;
    const float step = length / static_cast<float>(pieces);
    for (int k = 0; k < pieces; k += 2) {
        const float a = x0 + step * static_cast<float>(k);
        batch.add_rect({a, y - 0.5F * width, a + step, y + 0.5F * width}, color);
    }
}

void add_dashed_frame(OverlayBatch& batch, RectF r, float width, float dash, Rgba8 color) {
    const auto side = [&](float length, auto&& piece) {
        int pieces = std::max(1, static_cast<int>(std::lround(length / dash)));
        if (pieces % 2 == 0) ++pieces;
        const float step = length / static_cast<float>(pieces);
        for (int k = 0; k < pieces; k += 2) {
            piece(step * static_cast<float>(k), step * static_cast<float>(k + 1));
        }
    };
    side(r.width(), [&](float a, float b) {
        batch.add_rect({r.x0 + a, r.y0, r.x0 + b, r.y0 + width}, color);  // top
        batch.add_rect({r.x0 + a, r.y1 - width, r.x0 + b, r.y1}, color);  // bottom
    });
    side(r.height(), [&](float a, float b) {
        batch.add_rect({r.x0, r.y0 + a, r.x0 + width, r.y0 + b}, color);  // left
        batch.add_rect({r.x1 - width, r.y0 + a, r.x1, r.y0 + b}, color);  // right
    });
}

float edge_dash(float wall) noexcept {
    return std::max(4.0F, 3.0F * wall);
}

}  // namespace collide::render
