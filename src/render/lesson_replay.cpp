// A replay's marks over a panel's (zoomed) box: the ghosts of the failing discs, the straight
// jump between two checks, the labels and the heading. What they are and say is the presentation
// layer's (show::replay_views); here they get their pixels.
#include <algorithm>
#include <cmath>

#include "lesson_painter.hpp"

namespace collide::render {

void LessonPainter::add_replay(const ReplayView& replay, const PanelLayout& panel, const Box& box) {
    if (intro_) return;
    const float body = body_font_->pixel_height();
    const float stroke = std::max(2.0F, std::round(body / 7.0F));
    const RectF inside = panel.box;
    const auto color = [&](bool failure, float opacity) {
        return faded(failure ? palette_.failure : palette_.text, opacity);
    };
    // The jump: a thick line with an arrowhead where the move ends.
    for (const BoxLine& line : replay.lines) {
        PointF from = panel.to_pixels(line.from, box);
        PointF to = panel.to_pixels(line.to, box);
        const float dx = to.x - from.x;
        const float dy = to.y - from.y;
        const float length = std::hypot(dx, dy);
        const Rgba8 c = color(line.failure, line.opacity);
        const PointF tip = to;
        if (!clip_to(inside, from, to)) continue;
        list_.over.add_line(from, to, stroke, c);
        const float head = std::min(2.5F * body / 2.0F, 0.5F * length);
        if (length > 0.0F && head > 2.0F * stroke && tip.x == to.x && tip.y == to.y) {
            const float ux = dx / length;
            const float uy = dy / length;
            const PointF back{tip.x - head * ux, tip.y - head * uy};
            const float side = 0.5F * head;
            list_.over.add_line(tip, {back.x - side * uy, back.y + side * ux}, stroke, c);
            list_.over.add_line(tip, {back.x + side * uy, back.y - side * ux}, stroke, c);
        }
    }
    // Ghosts are disc instances of the panel's group: scissored to its box like the discs.
    for (const GhostDisc& ghost : replay.ghosts) {
        const PointF p = panel.to_pixels(ghost.where, box);
        const auto radius = static_cast<float>(ghost.radius * panel.scale);
        const Rgba8 c = color(ghost.failure, ghost.opacity);
        if (ghost.filled) {
            list_.discs.push_back({p.x, p.y, radius, 0.0F, faded(c, 0.85F)});
        } else {
            list_.discs.push_back(
                {p.x, p.y, radius, std::max(stroke, std::min(radius * 0.3F, 2.0F * stroke)), c});
        }
    }
    labels_.clear();
    // The heading first: the labels keep clear of it.
    if (!replay.heading.empty()) {
        add_plate_label(Font::body, {0.5F * (inside.x0 + inside.x1), inside.y0 + 0.8F * body},
                        replay.heading, palette_.title, inside);
    }
    const FontAtlas& font = atlas(Font::body);
    for (const BoxLabel& label : replay.labels) {
        const PointF p = panel.to_pixels(label.at, box);
        const float clear = static_cast<float>(label.clear * panel.scale) + 0.3F * body;
        const float half_h = 0.55F * body;
        const float half_w = 0.5F * font.text_width(label.text) + 0.2F * body;
        PointF at = p;
        switch (label.side) {
            case LabelSide::above:
                at.y -= clear + half_h;
                break;
            case LabelSide::below:
                at.y += clear + half_h;
                break;
            case LabelSide::left:
                at.x -= clear + half_w;
                break;
            case LabelSide::right:
                at.x += clear + half_w;
                break;
            case LabelSide::over:
                break;
        }
        add_plate_label(Font::body, at, label.text, color(label.failure, label.opacity), inside);
    }
}

}  // namespace collide::render
