// The event-driven panel's next collision (lesson level, without the queue strip): one thin line
// from the disc to what it will hit, and its time to go on a plate beside it that never covers
// the two discs. What comes next and the words are the presentation layer's
// (show::next_collision_view); here they get their pixels.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "lesson_painter.hpp"

namespace collide::render {

namespace {

/// Whether rectangle r comes within `margin` of any circle (pixels).
bool covers(RectF r, const std::vector<std::pair<PointF, float>>& circles, float margin) {
    return std::any_of(circles.begin(), circles.end(), [&](const std::pair<PointF, float>& c) {
        const float nx = std::clamp(c.first.x, r.x0, r.x1);
        const float ny = std::clamp(c.first.y, r.y0, r.y1);
        return std::hypot(nx - c.first.x, ny - c.first.y) < c.second + margin;
    });
}

}  // namespace

void LessonPainter::add_next_collision(const NextCollisionView& next, const PanelLayout& panel,
                                       const Box& box) {
    if (intro_ || next.empty()) return;
    const float body = body_font_->pixel_height();
    const RectF inside = panel.box;
    const Rgba8 color = next_color();
    // Thin (3 px at 720p, the queue's next event has 5): it points, it does not shout.
    const float width = std::max(1.5F, std::round(body / 10.0F));
    for (const BoxLine& line : next.lines) {
        PointF from = panel.to_pixels(line.from, box);
        PointF to = panel.to_pixels(line.to, box);
        if (clip_to(inside, from, to)) list_.over.add_line(from, to, width, color);
    }
    if (layout_.compact || next.text.empty()) return;
    // The plate: at the line's middle when that leaves the discs free, else beside them.
    std::vector<std::pair<PointF, float>> discs;
    for (const BoxCircle& c : next.keep_clear)
        discs.emplace_back(panel.to_pixels(c.centre, box),
                           static_cast<float>(c.radius * panel.scale));
    const FontAtlas& font = atlas(Font::body);
    const float pad = std::round(0.2F * body);
    // The whole line where the box has room for it (narrow boxes: a --dt list's), else the short.
    const bool whole = font.text_width(next.text) + 2.0F * pad <= inside.width();
    const std::string& text = whole || next.short_text.empty() ? next.text : next.short_text;
    const float w = font.text_width(text) + 2.0F * pad;
    const float h = std::round(body * 1.05F);
    const float margin = 0.25F * body;
    const PointF middle = panel.to_pixels(next.label_at, box);
    float top = middle.y;
    float bottom = middle.y;
    float left = middle.x;
    float right = middle.x;
    for (const auto& [c, r] : discs) {
        top = std::min(top, c.y - r);
        bottom = std::max(bottom, c.y + r);
        left = std::min(left, c.x - r);
        right = std::max(right, c.x + r);
    }
    const std::array<PointF, 5> places = {
        middle,
        PointF{middle.x, top - margin - 0.5F * h},
        PointF{middle.x, bottom + margin + 0.5F * h},
        PointF{right + margin + 0.5F * w, middle.y},
        PointF{left - margin - 0.5F * w, middle.y},
    };
    const auto plate_at = [&](PointF p) {
        // Where add_plate_label puts it: kept inside the box.
        const float x0 = std::clamp(p.x - 0.5F * w, inside.x0, std::max(inside.x0, inside.x1 - w));
        const float y0 = std::clamp(p.y - 0.5F * h, inside.y0, std::max(inside.y0, inside.y1 - h));
        return RectF{x0, y0, x0 + w, y0 + h};
    };
    PointF at = places[1];
    for (const PointF p : places) {
        if (!covers(plate_at(p), discs, margin)) {
            at = p;
            break;
        }
    }
    labels_.clear();
    add_plate_label(Font::body, at, text, color, inside);
}

}  // namespace collide::render
