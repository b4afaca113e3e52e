// The event-driven panel's next collision (lesson level, without the queue strip): one thin line
// from the disc to what it will hit, and its time to go on a plate beside it that never covers
// the two discs and as few others as it can. What comes next and the words are the presentation
// layer's (show::next_collision_view); here they get their pixels.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "lesson_painter.hpp"

namespace collide::render {

namespace {

/// Whether rectangle r comes within `margin` of the circle at c of radius `radius` (pixels).
bool overlaps(RectF r, PointF c, float radius, float margin) {
    const float nx = std::clamp(c.x, r.x0, r.x1);
    const float ny = std::clamp(c.y, r.y0, r.y1);
    return std::hypot(nx - c.x, ny - c.y) < radius + margin;
}

/// Whether rectangle r comes within `margin` of any circle (pixels).
bool covers(RectF r, const std::vector<std::pair<PointF, float>>& circles, float margin) {
    return std::any_of(circles.begin(), circles.end(), [&](const std::pair<PointF, float>& c) {
        return overlaps(r, c.first, c.second, margin);
    });
}

/// How much of the picture rectangle r hides: the squared radii of the circles it overlaps
/// (pixels), so that covering one big disc (a Brownian tracer) weighs as much as many small ones.
float covered_weight(RectF r, const std::vector<std::pair<PointF, float>>& circles) {
    float weight = 0.0F;
    for (const auto& [c, radius] : circles) {
        if (overlaps(r, c, radius, 0.0F)) weight += radius * radius;
    }
    return weight;
}

}  // namespace

void LessonPainter::add_next_collision(const NextCollisionView& next,
                                       const std::vector<DiscState>& all_discs,
                                       const PanelLayout& panel, const Box& box) {
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
    // The plate: never on the pair, and hiding as little of the other discs as it can (below).
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
    // Where the plate may go: the line's middle, beside the pair (above, below, right, left) and
    // at its corners, and a grid around the middle up to a plate's width and three of its
    // heights away.
    const float above = top - margin - 0.5F * h;
    const float below = bottom + margin + 0.5F * h;
    const float after = right + margin + 0.5F * w;
    const float before = left - margin - 0.5F * w;
    std::vector<PointF> places = {
        middle,
        PointF{middle.x, above},
        PointF{middle.x, below},
        PointF{after, middle.y},
        PointF{before, middle.y},
        PointF{after, above},
        PointF{before, above},
        PointF{after, below},
        PointF{before, below},
    };
    for (int row = -3; row <= 3; ++row) {
        for (int column = -2; column <= 2; ++column) {
            places.push_back({middle.x + 0.5F * w * static_cast<float>(column),
                              middle.y + (h + margin) * static_cast<float>(row)});
        }
    }
    const auto plate_at = [&](PointF p) {
        // Where add_plate_label puts it: kept inside the box.
        const float x0 = std::clamp(p.x - 0.5F * w, inside.x0, std::max(inside.x0, inside.x1 - w));
        const float y0 = std::clamp(p.y - 0.5F * h, inside.y0, std::max(inside.y0, inside.y1 - h));
        return RectF{x0, y0, x0 + w, y0 + h};
    };
    std::vector<RectF> plates;
    plates.reserve(places.size());
    for (const PointF p : places) plates.push_back(plate_at(p));
    // The discs near any of the plates (one pass over them all, however many there are).
    RectF reach = plates[0];
    for (const RectF& r : plates) {
        reach = {std::min(reach.x0, r.x0), std::min(reach.y0, r.y0), std::max(reach.x1, r.x1),
                 std::max(reach.y1, r.y1)};
    }
    std::vector<std::pair<PointF, float>> nearby;
    for (const DiscState& d : all_discs) {
        const PointF c = panel.to_pixels(d.position, box);
        const auto r = static_cast<float>(d.radius * panel.scale);
        if (overlaps(reach, c, r, 0.0F)) nearby.emplace_back(c, r);
    }
    // Of the places that keep the pair free, the one that hides the least of the other discs (a
    // break's rack, a cradle's row, a Brownian tracer: the label must not hide what the class is
    // watching), and of those the nearest to the middle; none keeps the pair free: above it.
    PointF at = places[1];
    float fewest = std::numeric_limits<float>::max();
    float nearest = std::numeric_limits<float>::max();
    for (std::size_t k = 0; k < places.size(); ++k) {
        const RectF& r = plates[k];
        if (covers(r, discs, margin)) continue;
        const float covered = covered_weight(r, nearby);
        const float away =
            std::hypot(0.5F * (r.x0 + r.x1) - middle.x, 0.5F * (r.y0 + r.y1) - middle.y);
        if (covered < fewest || (covered == fewest && away < nearest)) {
            fewest = covered;
            nearest = away;
            at = places[k];
        }
    }
    labels_.clear();
    add_plate_label(Font::body, at, text, color, inside);
}

}  // namespace collide::render
