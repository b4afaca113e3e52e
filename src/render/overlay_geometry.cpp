#include "overlay_geometry.hpp"

#include <cmath>

namespace collide::render {
void OverlayBatch::add_quad(PointF a, PointF b, PointF c, PointF d, Rgba8 color) {
    // a-b along the top edge, d-c along the bottom; two triangles a b c, a c d.
    const OverlayVertex va{a.x, a.y, color};
    const OverlayVertex vb{b.x, b.y, color};
    const OverlayVertex vc{c.x, c.y, color};
    const OverlayVertex vd{d.x, d.y, color};
    vertices_.insert(vertices_.end(), {va, vb, vc, va, vc, vd});
}

void OverlayBatch::add_rect(RectF r, Rgba8 color) {
    add_quad({r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}, color);
}

void OverlayBatch::add_frame(RectF r, float width, Rgba8 color) {
    add_rect({r.x0, r.y0, r.x1, r.y0 + width}, color);
    add_rect({r.x0, r.y1 - width, r.x1, r.y1}, color);
    add_rect({r.x0, r.y0 + width, r.x0 + width, r.y1 - width}, color);
    add_rect({r.x1 - width, r.y0 + width, r.x1, r.y1 - width}, color);
}

void OverlayBatch::add_line(PointF a, PointF b, float width, Rgba8 color) {
    const float dx = b.x - a.x;
    const float dy = b.y - a.y;
    const float length = std::sqrt(dx * dx + dy * dy);
    if (length <= 0.0F) return;
    // Half-width normal; segments overlap a little at joints, which reads as a continuous line.
    const float nx = -dy / length * width * 0.5F;
    const float ny = dx / length * width * 0.5F;
    add_quad({a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny}, {a.x - nx, a.y - ny},
             color);
}

}  // namespace collide::render
