// The lesson level's failure markers: overlapping pairs, missed collisions (remembered so that
// they fade over a second of video) and escaped discs in the reserved failure colour, at most
// max_markers per panel, and a note in the box when there are more.
#include <algorithm>
#include <cmath>
#include <string>

#include "lesson_painter.hpp"

namespace collide::render {

void MarkerMemory::update(const Snapshot& snapshot, double video_time) {
    const bool new_state = !last_time_ || *last_time_ != snapshot.time;
    if (last_time_ && snapshot.time < *last_time_) markers_.clear();  // a seek or a new video
    last_time_ = snapshot.time;
    if (new_state) {
        for (const Vec2 where : snapshot.missed_collisions) markers_.push_back({where, video_time});
    }
    std::erase_if(markers_, [&](const Marker& m) { return video_time - m.born >= marker_seconds; });
}

float MarkerMemory::opacity(const Marker& marker, double video_time) noexcept {
    const double age = video_time - marker.born;
    return static_cast<float>(std::clamp(1.0 - age / marker_seconds, 0.0, 1.0));
}

// Lesson failures in the reserved colour, newest first, at most max_markers: overlapping pairs
// (a ring around the pair's midpoint), missed collisions (a ring that fades over a second of
// video) and escaped discs (a ring where they crossed the edge). Returns how many were not drawn.
std::size_t LessonPainter::add_failures(std::size_t index, const Snapshot& snapshot,
                                        const PanelLayout& panel) {
    const Box& box = snapshot.box;
    double mean_radius = 0.0;
    for (const DiscState& d : snapshot.discs) mean_radius += d.radius;
    mean_radius /= static_cast<double>(std::max<std::size_t>(snapshot.discs.size(), 1));
    const float text_px = body_font_ ? body_font_->pixel_height() : 8.0F;
    const float size =
        std::max(0.45F * text_px, static_cast<float>(2.5 * mean_radius * panel.scale));
    const float ring = std::max(2.0F, std::round(text_px / 9.0F));
    std::size_t drawn = 0;
    std::size_t hidden = 0;
    const auto mark = [&](Vec2 where, float opacity, float radius) {
        if (drawn >= max_markers) {
            ++hidden;
            return;
        }
        ++drawn;
        const PointF c = panel.to_pixels(where, box);
        list_.discs.push_back({c.x, c.y, radius, ring, faded(palette_.failure, opacity)});
    };
    const auto& markers = markers_[index].markers();
    for (auto it = markers.rbegin(); it != markers.rend(); ++it) {
        mark(it->where, MarkerMemory::opacity(*it, video_time_), size);
    }
    for (const auto& [a, b] : snapshot.overlapping_pairs) {
        if (a >= snapshot.discs.size() || b >= snapshot.discs.size()) continue;
        const DiscState& da = snapshot.discs[a];
        const DiscState& db = snapshot.discs[b];
        const Vec2 mid = box.boundary == Boundary::periodic
                             ? da.position + 0.5 * box.displacement(da.position, db.position)
                             : 0.5 * (da.position + db.position);
        const auto radius = static_cast<float>(std::max(da.radius, db.radius) * 2.0 * panel.scale);
        mark(mid, 1.0F, std::max(radius + ring, 0.35F * text_px));
    }
    for (const DiscState& disc : snapshot.discs) {
        if (!disc.escaped) continue;
        const Vec2 edge{std::clamp(disc.position.x, 0.0, box.width),
                        std::clamp(disc.position.y, 0.0, box.height)};
        mark(edge, 1.0F, size);
    }
    return hidden;
}

// More failures than markers: say so inside the box, on a plate along its top edge. The figures
// row has no room left once the failure counts are in it (a dense fluid's "223 missed
// 733 overlapping" fills it), and a class must not think the circles are all there is.
void LessonPainter::add_unmarked_note(const PanelLayout& panel, std::size_t hidden) {
    const std::string text =
        "+" + with_separators(static_cast<long long>(hidden)) + " more not circled";
    const FontAtlas& f = atlas(Font::body);
    const float pad = std::round(0.3F * f.pixel_height());
    const float width = std::min(f.text_width(text) + 2.0F * pad, panel.box.width());
    const RectF plate{panel.box.x1 - width, panel.box.y0, panel.box.x1,
                      panel.box.y0 + f.pixel_height() + 2.0F * pad};
    list_.over.add_rect(plate, faded(palette_.box_fill, 0.9F));
    TextSlot slot;
    slot.panel = -1;
    slot.rect = {plate.x0 + pad, plate.y0, plate.x1 - pad, plate.y1};
    slot.pixel_height = f.pixel_height();
    draw_text(Font::body, slot, text, palette_.failure);
}

}  // namespace collide::render
