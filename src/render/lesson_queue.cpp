// The event queue inside the collision video (`collide render --queue`): the next collisions
// drawn in the box, and a strip under the panel with the queue as what it is (a heap's top
// levels as a tree, an array's first slots as a row), the latest pops (stale ones greyed) and
// their counts. The picture comes from Snapshot::queue, every word and number (the events'
// labels and times to go too) from QueueWords (src/show); nothing here knows the engines.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lesson_painter.hpp"

namespace collide::render {

namespace {

/// The strip's line height and a node's height (two lines, label and time), in text heights:
/// tight enough that at the lesson's text size a 30 % strip holds the heading, two pops with
/// their counts and a heap's top two levels. A strip too short for two lines (the boxes keep
/// their share of the frame) sets a node's label and time side by side on one strip line.
constexpr float strip_line = 1.15F;
constexpr float node_lines = 2.0F;

/// The `i`th of a view's per-event words, empty where the view has fewer (a frame built by hand).
const std::string& nth(const std::vector<std::string>& words, std::size_t i) {
    static const std::string none;
    return i < words.size() ? words[i] : none;
}

/// Px between a disc's number plate outside its box and what the plate keeps clear of.
constexpr float plate_clear = 2.0F;

/// The size of a queue label's plate (a time to go, a disc's number, in the box or outside
/// it): the text and a fifth of a text height each side, one text height (and a little) tall.
struct PlateSize {
    float w = 0.0F;
    float h = 0.0F;
};
PlateSize label_plate(const FontAtlas& f, std::string_view text) {
    const float pad = std::round(0.2F * f.pixel_height());
    return {f.text_width(text) + 2.0F * pad, std::round(f.pixel_height() * 1.05F)};
}

Rgba8 mix(Rgba8 a, Rgba8 b, float t) {
    const auto lerp = [t](std::uint8_t x, std::uint8_t y) {
        return static_cast<std::uint8_t>(std::lround(x + (y - x) * std::clamp(t, 0.0F, 1.0F)));
    };
    return {lerp(a.r, b.r), lerp(a.g, b.g), lerp(a.b, b.b), lerp(a.a, b.a)};
}

}  // namespace

// The part of segment a-b inside r (Liang-Barsky); false when none is.
bool clip_to(RectF r, PointF& a, PointF& b) {
    double t0 = 0.0;
    double t1 = 1.0;
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x - r.x0, r.x1 - a.x, a.y - r.y0, r.y1 - a.y};
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0.0) {
            if (q[k] < 0.0) return false;
            continue;
        }
        const double t = q[k] / p[k];
        if (p[k] < 0.0) {
            t0 = std::max(t0, t);
        } else {
            t1 = std::min(t1, t);
        }
    }
    if (t0 > t1) return false;
    const PointF a0 = a;
    a = {static_cast<float>(a0.x + t0 * dx), static_cast<float>(a0.y + t0 * dy)};
    b = {static_cast<float>(a0.x + t1 * dx), static_cast<float>(a0.y + t1 * dy)};
    return true;
}

Rgba8 LessonPainter::next_color() const noexcept {
    return with_alpha(next_event_color(config_.theme), 255);
}

float LessonPainter::pop_highlight(const QueuedEvent& popped, double now) const noexcept {
    const double seconds = popped.stale ? pop_seconds_.stale : pop_seconds_.valid;
    if (!(speed_ > 0.0) || !(seconds > 0.0)) return 0.0F;
    const double age = (now - popped.t) / (seconds * speed_);
    return static_cast<float>(std::clamp(1.0 - age, 0.0, 1.0));
}

void LessonPainter::add_plate_label(Font font, PointF at, std::string_view text, Rgba8 color,
                                    RectF inside) {
    const FontAtlas& f = atlas(font);
    const auto [w, h] = label_plate(f, text);
    float x0 = std::clamp(at.x - 0.5F * w, inside.x0, std::max(inside.x0, inside.x1 - w));
    float y0 = std::clamp(at.y - 0.5F * h, inside.y0, std::max(inside.y0, inside.y1 - h));
    x0 = std::round(x0);
    y0 = std::round(y0);
    // Two events close together would print over each other: move the plate up or down to the
    // nearest free place (labels_ holds the plates placed in this box so far).
    const auto free_at = [&](float y) {
        const RectF r{x0, y, x0 + w, y + h};
        return std::none_of(labels_.begin(), labels_.end(),
                            [&](const RectF& o) { return overlaps(r, o); });
    };
    for (int k = 1; k <= 6 && !free_at(y0); ++k) {
        const float step =
            static_cast<float>((k + 1) / 2) * (h + 1.0F) * (k % 2 == 1 ? 1.0F : -1.0F);
        const float y = y0 + step;
        if (y >= inside.y0 && y + h <= inside.y1 && free_at(y)) {
            y0 = y;
            break;
        }
    }
    const RectF plate{x0, y0, x0 + w, y0 + h};
    labels_.push_back(plate);
    list_.over.add_rect(plate, with_alpha(rgb(palette_.box_fill), 215));
    draw_text(font, {TextRole::queue, -1, plate, f.pixel_height()}, text, color, Align::centre);
}

void LessonPainter::add_queue_label(Font font, PointF at, PointF anchor, float anchor_radius,
                                    std::string_view text, Rgba8 color, RectF inside) {
    const FontAtlas& f = atlas(font);
    const auto [w, h] = label_plate(f, text);
    if (w > inside.width() || h > inside.height()) return;
    // A plate never covers a disc or another label: the nearest free place on rings round `at`
    // (labels_ and disc_rects_ hold what this box has so far).
    const auto plate_at = [&](float cx, float cy) {
        // Whole pixels, rounded down: a plate at the right or bottom edge stays inside.
        const float x0 = std::floor(std::clamp(cx - 0.5F * w, inside.x0, inside.x1 - w));
        const float y0 = std::floor(std::clamp(cy - 0.5F * h, inside.y0, inside.y1 - h));
        return RectF{x0, y0, x0 + w, y0 + h};
    };
    const auto clear_of_all = [&](const RectF& r) {
        const auto hit = [&r](const RectF& o) { return overlaps(r, o); };
        return std::none_of(labels_.begin(), labels_.end(), hit) &&
               std::none_of(disc_rects_.begin(), disc_rects_.end(), hit);
    };
    constexpr int directions = 12;
    const float step = 0.5F * h;
    const float reach = std::max(inside.width(), inside.height());
    std::optional<RectF> plate;
    for (float radius = 0.0F; !plate && radius <= reach; radius += step) {
        const int tries = radius == 0.0F ? 1 : directions;
        for (int k = 0; k < tries && !plate; ++k) {
            const double angle = 2.0 * std::numbers::pi * k / directions;
            const RectF r = plate_at(at.x + radius * static_cast<float>(std::cos(angle)),
                                     at.y + radius * static_cast<float>(std::sin(angle)));
            if (clear_of_all(r)) plate = r;
        }
    }
    if (!plate) return;  // a crowded box: the strip names the event
    labels_.push_back(*plate);
    // A leader line from the plate's edge to what it names, when the plate is not on it.
    // It stops at the disc's edge (anchor_radius), so that it crosses no disc it names.
    const PointF from{std::clamp(anchor.x, plate->x0, plate->x1),
                      std::clamp(anchor.y, plate->y0, plate->y1)};
    const float length = std::hypot(anchor.x - from.x, anchor.y - from.y);
    if (length - anchor_radius > 0.25F * h) {
        const float keep = anchor_radius / length;
        const PointF to{anchor.x + (from.x - anchor.x) * keep,
                        anchor.y + (from.y - anchor.y) * keep};
        list_.over.add_line(from, to, std::max(1.0F, std::round(h / 16.0F)), faded(color, 0.8F));
    }
    list_.over.add_rect(*plate, with_alpha(rgb(palette_.box_fill), 215));
    draw_text(font, {TextRole::queue, -1, *plate, f.pixel_height()}, text, color, Align::centre);
}

std::vector<RectF> LessonPainter::frame_obstacles(RectF own_box) const {
    // What a number outside the boxes keeps clear of: every box (the other panel's discs too),
    // the code listing, the queue strip, the caption, the column's graphics, and the text drawn
    // so far (add_frame_numbers runs after all of it): a line's slot from its left edge (a
    // title's swatch, a legend's marks) to its last glyph, clear by half a line; a note to the
    // end of its step indicator, which follows the words. A slot left empty (the energy line's
    // second line when one holds it) is free.
    const float clear = std::round(0.5F * body_font_->pixel_height());
    std::vector<RectF> out;
    // Another panel's box and the frame over and under it: a number there would read as that
    // panel's.
    const float m = std::max(2.0F, layout_.margin);
    for (const PanelLayout& panel : layout_.panels) {
        const RectF b = panel.box;
        const bool own =
            b.x0 == own_box.x0 && b.y0 == own_box.y0 && b.x1 == own_box.x1 && b.y1 == own_box.y1;
        out.push_back(own ? b
                          : RectF{b.x0 - m, 0.0F, b.x1 + m, static_cast<float>(config_.height)});
    }
    for (const RectF& r : {layout_.code, layout_.column.bars, layout_.column.legend_bar,
                           layout_.column.plot, layout_.queue_strip})
        if (r.width() > 0.0F && r.height() > 0.0F) out.push_back(r);
    for (const TextSlot& slot : layout_.text) {
        const RectF r = slot.rect;
        if (slot.role == TextRole::queue || slot.role == TextRole::caption ||
            slot.role == TextRole::code) {
            out.push_back(r);
            continue;
        }
        if (slot.role == TextRole::note) continue;  // notes_ below
        float ink = r.x0 - 1.0F;
        for (const TextRun& run : list_.text) {
            for (const GlyphBox& g : run.glyphs.glyphs()) {
                const RectF glyph{static_cast<float>(g.x), static_cast<float>(g.y),
                                  static_cast<float>(g.x + g.width),
                                  static_cast<float>(g.y + g.height)};
                // A glyph is the slot's whose middle is in it (descenders reach the next line).
                const float mid = 0.5F * (glyph.y0 + glyph.y1);
                if (mid >= r.y0 && mid < r.y1 && glyph.x1 > r.x0 && glyph.x0 < r.x1)
                    ink = std::max(ink, glyph.x1);
            }
        }
        if (ink >= r.x0) out.push_back({r.x0, r.y0, std::min(r.x1, ink + clear), r.y1});
    }
    for (const RectF& note : notes_) out.push_back({note.x0, note.y0, note.x1 + clear, note.y1});
    return out;
}

void LessonPainter::add_frame_numbers() {
    if (frame_numbers_.empty()) return;
    // Every number of a frame comes from the queue's panel: one box, one list of obstacles.
    const RectF box = frame_numbers_.front().box;
    const std::vector<RectF> obstacles = frame_obstacles(box);
    // First the column beside the box (stacked in order, no leader crosses another), then each
    // number it could not hold at the nearest free place of the frame.
    add_column_numbers(box, obstacles);
    for (const FrameNumber& n : frame_numbers_)
        add_frame_label(n.font, n.disc, n.radius, n.text, n.color, box, obstacles);
    frame_numbers_.clear();
}

void LessonPainter::add_column_numbers(RectF box, const std::vector<RectF>& obstacles) {
    constexpr float clear = plate_clear;
    const float m = std::max(2.0F, layout_.margin);
    const auto frame_w = static_cast<float>(config_.width);
    const auto frame_h = static_cast<float>(config_.height);
    struct Plate {
        std::size_t number;  // in frame_numbers_
        float w;
        float h;
        float want;  // the top that puts the plate level with its disc
        float y0;
    };
    std::vector<Plate> all;
    float widest = 0.0F;
    for (std::size_t i = 0; i < frame_numbers_.size(); ++i) {
        const FrameNumber& n = frame_numbers_[i];
        const PlateSize size = label_plate(atlas(n.font), n.text);
        all.push_back({i, size.w, size.h, std::floor(n.disc.y - 0.5F * size.h), 0.0F});
        widest = std::max(widest, size.w);
    }
    const float x0 = box.x1 + clear;
    const float x1 = x0 + widest;
    if (x1 > frame_w - m) return;
    // The column's free stretches, level with the box (a leader then runs straight to its edge).
    const float top = std::ceil(std::max(box.y0, m));
    const float bottom = std::floor(std::min(box.y1, frame_h - m));
    std::vector<std::pair<float, float>> blocked;
    const auto block = [&](const RectF& o) {
        if (o.x1 + clear > x0 && o.x0 - clear < x1)
            blocked.emplace_back(std::floor(o.y0 - clear), std::ceil(o.y1 + clear));
    };
    // The own box among the obstacles never blocks: the column starts `clear` right of it.
    for (const RectF& o : obstacles) block(o);
    for (const RectF& o : labels_) block(o);
    std::sort(blocked.begin(), blocked.end());
    std::vector<std::pair<float, float>> free;
    float a = top;
    for (const auto& [b0, b1] : blocked) {
        if (std::min(b0, bottom) > a) free.emplace_back(a, std::min(b0, bottom));
        a = std::max(a, b1);
    }
    if (bottom > a) free.emplace_back(a, bottom);
    if (free.empty()) return;
    // The lowest place each plate of `order` (top down) can take: packed from the column's foot
    // up; false when they do not all fit.
    const auto lowest_places = [&](std::vector<Plate>& order) {
        std::size_t j = free.size();
        float pos = free.back().second;
        for (auto it = order.rbegin(); it != order.rend(); ++it) {
            float y = pos - it->h;
            while (j > 0) {
                y = std::min(y, free[j - 1].second - it->h);
                if (y >= free[j - 1].first) break;
                --j;
            }
            if (j == 0) return false;
            it->y0 = y;
            pos = y - clear;
        }
        return true;
    };
    // Top down, each plate level with its disc, or the first free place under the one above, but
    // never lower than leaves room for the ones under it.
    const auto pack = [&](std::vector<Plate>& order) {
        std::vector<Plate> lowest = order;
        if (!lowest_places(lowest)) return false;
        float pos = free.front().first;
        for (std::size_t i = 0; i < order.size(); ++i) {
            Plate& p = order[i];
            float y = std::max(p.want, pos);
            std::size_t j = 0;
            while (j < free.size() && std::max(y, free[j].first) + p.h > free[j].second) ++j;
            if (j < free.size()) y = std::max(y, free[j].first);
            p.y0 = j < free.size() ? std::min(y, lowest[i].y0) : lowest[i].y0;
            pos = p.y0 + p.h + clear;
        }
        return true;
    };
    const auto by_height = [&](const Plate& p, const Plate& q) {
        return frame_numbers_[p.number].disc.y < frame_numbers_[q.number].disc.y;
    };
    // As many as the column holds, the next pair's first (frame_numbers_'s order).
    std::vector<Plate> chosen;
    for (std::size_t k = all.size(); k > 0 && chosen.empty(); --k) {
        std::vector<Plate> order(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(k));
        std::sort(order.begin(), order.end(), by_height);
        if (pack(order)) chosen = order;
    }
    for (const Plate& p : chosen) {
        const FrameNumber& n = frame_numbers_[p.number];
        const RectF plate{x0, p.y0, x0 + p.w, p.y0 + p.h};
        const float mid = std::round(0.5F * (plate.y0 + plate.y1));
        labels_.push_back(plate);
        draw_frame_number(n.font, n.text, n.color, plate, {x0, mid}, {box.x1, mid}, n.disc,
                          n.radius);
    }
    // What is left (a column too short for all) goes to the nearest free places, in order.
    std::vector<FrameNumber> rest;
    for (std::size_t i = chosen.size(); i < frame_numbers_.size(); ++i)
        rest.push_back(frame_numbers_[i]);
    frame_numbers_ = std::move(rest);
}

void LessonPainter::draw_frame_number(Font font, std::string_view text, Rgba8 color, RectF plate,
                                      PointF from, PointF elbow, PointF disc, float radius) {
    const FontAtlas& f = atlas(font);
    const float h = plate.height();
    const float line_w = std::max(1.0F, std::round(h / 16.0F));
    if (std::hypot(elbow.x - from.x, elbow.y - from.y) > 0.5F)
        list_.over.add_line(from, elbow, line_w, faded(color, 0.8F));
    const float length = std::hypot(disc.x - elbow.x, disc.y - elbow.y);
    if (length > radius) {
        const float keep = radius / length;
        const PointF to{disc.x + (elbow.x - disc.x) * keep, disc.y + (elbow.y - disc.y) * keep};
        list_.over.add_line(elbow, to, line_w, faded(color, 0.8F));
    }
    list_.over.add_rect(plate, with_alpha(rgb(palette_.box_fill), 215));
    draw_text(font, {TextRole::queue, -1, plate, f.pixel_height()}, text, color, Align::centre);
}

void LessonPainter::add_frame_label(Font font, PointF disc, float radius, std::string_view text,
                                    Rgba8 color, RectF box, const std::vector<RectF>& obstacles) {
    const auto [w, h] = label_plate(atlas(font), text);
    const float m = std::max(2.0F, layout_.margin);
    const auto frame_w = static_cast<float>(config_.width);
    const auto frame_h = static_cast<float>(config_.height);
    if (w > frame_w - 2.0F * m || h > frame_h - 2.0F * m) return;
    constexpr float clear = plate_clear;
    // The leader line: from the plate to the nearest point of the box's edge, then inside the
    // box to the disc's edge, so that it crosses no text on its way (the first part is checked).
    struct Place {
        RectF plate;
        PointF from;   // on the plate's edge
        PointF elbow;  // on the box's edge
        float cost = 0.0F;
    };
    // The elbow is the nearest point of the box's edge, or moved along that edge by `shift`
    // (px): a slanting leader that passes between plates nearer the box.
    const auto place_at = [&](float x0, float y0, float shift) {
        Place p;
        p.plate = {std::floor(x0), std::floor(y0), std::floor(x0) + w, std::floor(y0) + h};
        const PointF centre{0.5F * (p.plate.x0 + p.plate.x1), 0.5F * (p.plate.y0 + p.plate.y1)};
        p.elbow = {std::clamp(centre.x, box.x0, box.x1), std::clamp(centre.y, box.y0, box.y1)};
        if (p.elbow.y == box.y0 || p.elbow.y == box.y1) {
            p.elbow.x = std::clamp(p.elbow.x + shift, box.x0, box.x1);
        } else {
            p.elbow.y = std::clamp(p.elbow.y + shift, box.y0, box.y1);
        }
        p.from = {std::clamp(p.elbow.x, p.plate.x0, p.plate.x1),
                  std::clamp(p.elbow.y, p.plate.y0, p.plate.y1)};
        p.cost = std::hypot(p.elbow.x - p.from.x, p.elbow.y - p.from.y) +
                 std::hypot(disc.x - p.elbow.x, disc.y - p.elbow.y);
        return p;
    };
    // A leader keeps a third of a plate's height from text, so that it never reads as an
    // underline; it may pass close by another plate, never through it.
    const float line_clear = std::round(h / 3.0F);
    const auto crosses = [](const RectF& o, PointF a, PointF b, float margin) {
        PointF u = a;
        PointF v = b;
        return clip_to({o.x0 - margin, o.y0 - margin, o.x1 + margin, o.y1 + margin}, u, v);
    };
    const auto leader_clear = [&](const Place& p) {
        const auto hit_obstacle = [&](const RectF& o) {
            const bool own_box =
                o.x0 == box.x0 && o.y0 == box.y0 && o.x1 == box.x1 && o.y1 == box.y1;
            return !own_box && crosses(o, p.from, p.elbow, line_clear);
        };
        const auto hit_plate = [&](const RectF& o) { return crosses(o, p.from, p.elbow, -0.5F); };
        return std::none_of(obstacles.begin(), obstacles.end(), hit_obstacle) &&
               std::none_of(labels_.begin(), labels_.end(), hit_plate);
    };
    // Rows of the frame half a plate apart; in each, the places left free by what lies in the
    // row (plate left edges), and of those the nearest to the disc along the leader.
    std::optional<Place> best;
    std::vector<std::pair<float, float>> blocked;
    const float step = std::max(1.0F, std::round(0.5F * h));
    for (float y0 = m; y0 + h <= frame_h - m; y0 += step) {
        blocked.clear();
        const auto block = [&](const RectF& o) {
            if (o.y1 + clear > y0 && o.y0 - clear < y0 + h)
                blocked.emplace_back(o.x0 - clear - w, o.x1 + clear);
        };
        for (const RectF& o : obstacles) block(o);
        for (const RectF& o : labels_) block(o);
        std::sort(blocked.begin(), blocked.end());
        float a = m;
        const float last = frame_w - m - w;
        const auto try_at = [&](float x) {
            for (const float shift : {0.0F, -0.5F, 0.5F, -1.0F, 1.0F, -2.0F, 2.0F}) {
                const Place p = place_at(x, y0, shift * w);
                if ((!best || p.cost < best->cost) && leader_clear(p)) best = p;
            }
        };
        const auto consider = [&](float lo, float hi) {
            if (hi < lo) return;
            for (const float x : {lo, hi, std::clamp(disc.x - 0.5F * w, lo, hi)}) try_at(x);
            // Where the leader passes beside a plate placed nearer the box (rows of numbers
            // under or beside it), and a quarter plate apart in between.
            for (const RectF& o : labels_) {
                for (const float centre : {o.x0 - clear, o.x1 + clear}) {
                    const float x = centre - 0.5F * w;
                    if (x >= lo && x <= hi) try_at(x);
                }
            }
            for (float x = lo + 0.25F * w; x < hi; x += 0.25F * w) try_at(x);
        };
        for (const auto& [b0, b1] : blocked) {
            consider(a, std::min(b0, last));
            a = std::max(a, b1);
        }
        consider(a, last);
    }
    if (!best) return;  // no free place in the frame: the strip names the event
    labels_.push_back(best->plate);
    draw_frame_number(font, text, color, best->plate, best->from, best->elbow, disc, radius);
}

// Lines between the discs of the next collisions, ticks on the walls, each with its time to go;
// the next one thick and in the highlight colour, the later ones thinner and fainter.
void LessonPainter::add_queue_in_box(const Snapshot& snapshot, const QueueWords& words,
                                     const PanelLayout& panel) {
    if (intro_) return;
    const QueueView& queue = *snapshot.queue;
    const Box& box = snapshot.box;
    const float body = body_font_->pixel_height();
    const bool labels = !layout_.compact && small_font_.has_value();
    const RectF inside = panel.box;
    labels_.clear();
    disc_rects_.clear();
    for (const DiscState& disc : snapshot.discs) {
        const PointF c = panel.to_pixels(disc.position, box);
        const auto r = static_cast<float>(disc.radius * panel.scale);
        const RectF rect{c.x - r, c.y - r, c.x + r, c.y + r};
        if (overlaps(rect, inside)) disc_rects_.push_back(rect);
    }
    // Per event: where its time label goes and the point it names (its leader line's end).
    std::vector<std::pair<std::pair<PointF, PointF>, bool>> pending(queue.next.size());
    // Latest first, so that the next event's line and label end up on top.
    for (std::size_t r = queue.next.size(); r-- > 0;) {
        const QueuedEvent& e = queue.next[r];
        if (e.a >= snapshot.discs.size()) continue;  // defensive: bad view data
        const bool first = r == 0;
        const Rgba8 color = first ? next_color() : faded(palette_.text, 0.75F);
        // Wide enough to be seen from the back of a lecture hall: 5 and 3 px at 720p.
        const float width = first ? std::max(3.0F, std::round(body / 6.0F))
                                  : std::max(1.5F, std::round(body / 10.0F));
        const DiscState& a = snapshot.discs[e.a];
        const double dt = e.t - snapshot.time;
        PointF label_at;
        PointF anchor;
        if (first) {
            // Rings around the discs of the next event.
            for (const std::uint32_t k : {e.a, e.b}) {
                if (k >= snapshot.discs.size() || (k == e.b && e.kind != EventKind::pair)) continue;
                const DiscState& disc = snapshot.discs[k];
                const PointF c = panel.to_pixels(disc.position, box);
                const auto radius = static_cast<float>(disc.radius * panel.scale);
                list_.discs.push_back({c.x, c.y, radius + 0.8F * width, width, color});
            }
        }
        if (e.kind == EventKind::pair) {
            if (e.b >= snapshot.discs.size()) continue;
            // The nearest images (periodic boxes: the pair may meet across the seam, and then
            // the line is drawn from each disc to the seam, cut at the box).
            const Vec2 pa = a.position;
            const Vec2 d = box.displacement(pa, snapshot.discs[e.b].position);
            const PointF qa = panel.to_pixels(pa, box);
            const PointF qb = panel.to_pixels(pa + d, box);
            label_at = {0.5F * (qa.x + qb.x), 0.5F * (qa.y + qb.y)};
            anchor = label_at;
            const auto line = [&](Vec2 from, Vec2 to) {
                PointF u = panel.to_pixels(from, box);
                PointF v = panel.to_pixels(to, box);
                if (clip_to(inside, u, v)) list_.over.add_line(u, v, width, color);
            };
            line(pa, pa + d);
            if (box.boundary == Boundary::periodic) {
                const Vec2 pb = snapshot.discs[e.b].position;
                line(pb, pb - d);
            }
        } else if (e.kind == EventKind::xwall || e.kind == EventKind::ywall) {
            // Where the disc's centre will be, and the wall point it touches.
            const Vec2 centre = a.position + a.velocity * dt;
            const bool x = e.kind == EventKind::xwall;
            Vec2 hit = centre;
            if (x) hit.x = a.velocity.x > 0.0 ? box.width : 0.0;
            if (!x) hit.y = a.velocity.y > 0.0 ? box.height : 0.0;
            const PointF from = panel.to_pixels(a.position, box);
            const PointF to = panel.to_pixels(hit, box);
            list_.over.add_line(from, to, std::max(1.0F, 0.5F * width), faded(color, 0.6F));
            const float half = std::max(static_cast<float>(a.radius * panel.scale), 0.6F * body);
            const float tick = first ? 2.0F * width : 1.6F * width;
            if (x) {
                list_.over.add_line({to.x, to.y - half}, {to.x, to.y + half}, tick, color);
            } else {
                list_.over.add_line({to.x - half, to.y}, {to.x + half, to.y}, tick, color);
            }
            // The label sits inside the box, a little away from the wall.
            const float off = 1.2F * body;
            label_at = {x ? to.x + (a.velocity.x > 0.0 ? -off : off) : to.x,
                        x ? to.y : to.y + (a.velocity.y > 0.0 ? off : -off)};
            anchor = to;
        } else {
            continue;  // cell crossings are bookkeeping, not collisions
        }
        pending[r] = {{label_at, anchor}, true};
    }
    if (!labels) return;
    // Labels after all lines: the next event's first so that it keeps its place, then its discs'
    // numbers (the ones the strip names: "14 wall", "3-7") just under them, then the others.
    const auto time_label = [&](std::size_t r) {
        if (!pending[r].second) return;
        const bool first = r == 0;
        add_queue_label(first ? Font::body : Font::small, pending[r].first.first,
                        pending[r].first.second, 0.0F, nth(words.next_times, r),
                        first ? next_color() : palette_.text, inside);
    };
    // A disc's number just under it (or the nearest free place), a leader line to its edge.
    // A box too crowded for a free place (dense-fluid) numbers its discs in the nearest place of
    // the frame clear of every box, text and the code, once all of the frame's text is drawn
    // (add_frame_numbers).
    const auto number = [&](std::uint32_t k, std::string_view text, Font font, Rgba8 color) {
        if (k >= snapshot.discs.size()) return;
        const DiscState& disc = snapshot.discs[k];
        const PointF c = panel.to_pixels(disc.position, box);
        const auto radius = static_cast<float>(disc.radius * panel.scale);
        const std::size_t placed = labels_.size();
        add_queue_label(font, {c.x, c.y + radius + 0.7F * body}, c, radius, text, color, inside);
        if (labels_.size() == placed)
            frame_numbers_.push_back({font, c, radius, std::string(text), color, inside});
    };
    if (queue.next.empty()) return;
    time_label(0);
    const QueuedEvent& e = queue.next.front();
    for (std::size_t j = 0; j < words.next_discs.size(); ++j)
        number(j == 0 ? e.a : e.b, words.next_discs[j], Font::body, next_color());
    for (std::size_t r = 1; r < queue.next.size(); ++r) time_label(r);
    for (const QueueWords::NumberedDisc& d : words.listed_discs)
        number(d.disc, d.number, Font::small, palette_.text);
}

// The strip: a heading, the latest pops on the left, the queue itself on the right.
void LessonPainter::add_queue_strip(const Snapshot& snapshot, const QueueWords& words,
                                    RectF strip) {
    const QueueView& queue = *snapshot.queue;
    const FontAtlas& small = *small_font_;
    const float line = std::round(small.pixel_height() * strip_line);
    const float m = std::round(0.5F * small.pixel_height());
    list_.over.add_frame(strip, 1.0F, faded(palette_.muted, 0.6F));
    const RectF inner{strip.x0 + m, strip.y0 + 0.5F * m, strip.x1 - m, strip.y1 - 0.5F * m};
    // The heading in fewer words where the whole one would be cut (a strip beside one box).
    const std::string& heading =
        small.text_width(words.heading) <= inner.width() || words.short_heading.empty()
            ? words.heading
            : words.short_heading;
    const TextSlot heading_slot{
        TextRole::queue, -1, {inner.x0, inner.y0, inner.x1, inner.y0 + line}, small.pixel_height()};
    // The legend of the box's lines is on the panel's legend line (add_panel_text): at the
    // lesson's text size the heading takes the strip's width.
    const float heading_end = draw_text(Font::small, heading_slot, heading, palette_.title);
    const RectF body{inner.x0, inner.y0 + line + 0.5F * m, inner.x1, inner.y1};
    // The pops take a third of the width, or what their words need where the queue keeps room
    // for a node (a narrow strip: the queue shows fewer nodes, no pop is cut).
    // A heap keeps its root (add_queue_tree shows no children where they do not fit whole), an
    // array a node as wide as its widest.
    const bool one_line = one_line_nodes(body.height());
    const float queue_min = node_width(queue.shape == QueueShape::heap
                                           ? std::vector<std::string>{nth(words.slot_labels, 0)}
                                           : words.slot_labels,
                                       one_line) +
                            m;
    const float popped_w = std::round(
        std::max(0.33F * inner.width(),
                 std::min(popped_width(queue, words, body.height()), inner.width() - queue_min)));
    // An array's caption, where its row has no line for it (a short strip), after the heading
    // when it fits there.
    const bool row_caption_above = queue.shape != QueueShape::heap && body.height() < 2.0F * line;
    if (row_caption_above && !words.row_caption.empty() &&
        heading_end + m + small.text_width(words.row_caption) <= inner.x1)
        draw_text(Font::small, heading_slot, words.row_caption, palette_.muted, Align::right);
    add_popped(queue, words, snapshot.time, {body.x0, body.y0, body.x0 + popped_w, body.y1});
    const RectF right{body.x0 + popped_w + m, body.y0, body.x1, body.y1};
    if (queue.shape == QueueShape::heap) {
        add_queue_tree(queue, words, snapshot.time, right);
    } else {
        add_queue_row(queue, words, right);
    }
}

float LessonPainter::popped_width(const QueueView& queue, const QueueWords& words,
                                  float height) const {
    const FontAtlas& small = *small_font_;
    const float line = std::round(small.pixel_height() * strip_line);
    float widest = small.text_width(words.counts);
    if (std::floor(height / line) >= 4.0F)
        widest = std::max(widest, small.text_width(popped_heading(words, 0.0F)));
    for (std::size_t k = 0; k < queue.popped.size(); ++k) {
        const QueuedEvent& e = queue.popped[k];
        const std::string& tail = e.stale                     ? words.stale_popped
                                  : e.kind == EventKind::cell ? words.crossing_popped
                                                              : words.resolved_popped;
        widest = std::max(widest, small.text_width(nth(words.popped_labels, k) + tail));
    }
    return std::ceil(widest) + 2.0F;
}

const std::string& LessonPainter::popped_heading(const QueueWords& words, float room) const {
    // room 0: the heading popped_width makes room for (the short one, which always fits)
    const bool whole = room > 0.0F && small_font_->text_width(words.popped_heading) <= room;
    return whole || words.short_popped_heading.empty() ? words.popped_heading
                                                       : words.short_popped_heading;
}

// The latest pops, newest first: the one just popped in the highlight colour (fading), stale
// ones greyed with the engine's words (QueueWords, from collide/show); the counts at the bottom.
void LessonPainter::add_popped(const QueueView& queue, const QueueWords& words, double now,
                               RectF area) {
    const FontAtlas& small = *small_font_;
    const float line = std::round(small.pixel_height() * strip_line);
    const auto slot = [&](float y) {
        return TextSlot{TextRole::queue, -1, {area.x0, y, area.x1, y + line}, small.pixel_height()};
    };
    float y = area.y0;
    // A short strip (the boxes keep their share of the frame) shows the latest pop and the
    // counts, without the heading.
    const float lines = std::floor(area.height() / line);
    if (lines >= 4.0F) {
        draw_text(Font::small, slot(y), popped_heading(words, area.width()), palette_.muted);
        y += line;
    }
    // The counts on one line where they fit; else on two (late in a long run beside one box:
    // "316,487 pops" over "65,796 stale"), or the pops alone where one line is all there is
    // for them: said whole, never cut.
    std::vector<std::string> counts{words.counts};
    if (small.text_width(words.counts) > area.width() && !words.counts_lines.empty()) {
        counts = words.counts_lines;
        if (lines < 3.0F) counts.resize(1);
    }
    const float count_rows = lines >= 2.0F ? static_cast<float>(counts.size()) : 0.0F;
    const float bottom = area.y1 - count_rows * line;
    for (std::size_t k = queue.popped.size(); k-- > 0 && y + line <= bottom;) {
        const QueuedEvent& e = queue.popped[k];
        const float glow = pop_highlight(e, now);
        std::string text = nth(words.popped_labels, k);
        Rgba8 color = palette_.text;
        if (e.stale) {
            text += words.stale_popped;
            color = palette_.muted;  // muted, not faded: text keeps 4.5:1 (theme.cpp)
        } else {
            text += e.kind == EventKind::cell ? words.crossing_popped : words.resolved_popped;
        }
        if (glow > 0.0F) {
            // Just removed: a plate in the highlight colour behind it, fading out.
            const RectF plate{area.x0 - 2.0F, y + 1.0F, area.x1, y + line - 1.0F};
            const Rgba8 tint = e.stale ? palette_.muted : next_color();
            list_.over.add_rect(plate, faded(tint, 0.35F * glow));
            if (!e.stale) color = mix(color, next_color(), glow);
        }
        draw_text(Font::small, slot(y), text, color);
        y += line;
    }
    if (count_rows > 0.0F)
        for (std::size_t k = 0; k < counts.size(); ++k)
            draw_text(Font::small, slot(bottom + static_cast<float>(k) * line), counts[k],
                      palette_.muted);
}

float LessonPainter::node_width(const std::vector<std::string>& labels, bool one_line) const {
    const FontAtlas& small = *small_font_;
    const float time = small.text_width("0.0000");  // the longest time to go, "stale"
    float widest = one_line ? 0.0F : time;
    for (const std::string& label : labels) widest = std::max(widest, small.text_width(label));
    // One line: the label, a space of 0.8 text heights, the time.
    return std::round(
        widest + (one_line ? time + 1.6F * small.pixel_height() : 0.8F * small.pixel_height()));
}

bool LessonPainter::one_line_nodes(float height) const {
    return height < std::round(node_lines * small_font_->pixel_height());
}

void LessonPainter::add_queue_node(std::string_view label, std::string_view time, RectF node,
                                   Rgba8 frame_color, bool stale) {
    const FontAtlas& small = *small_font_;
    list_.over.add_rect(node, palette_.box_fill);
    list_.over.add_frame(node, frame_color.a == 255 && !stale ? 2.0F : 1.0F, frame_color);
    const Rgba8 text = stale ? palette_.muted : palette_.title;
    const Rgba8 time_color = stale ? text : faded(palette_.text, 0.85F);
    if (one_line_nodes(node.height())) {
        // Label on the left, time on the right: a strip of one line.
        const float pad = std::round(0.4F * small.pixel_height());
        const TextSlot row{TextRole::queue,
                           -1,
                           {node.x0 + pad, node.y0, node.x1 - pad, node.y1},
                           small.pixel_height()};
        draw_text(Font::small, row, label, text, Align::left);
        draw_text(Font::small, row, time, time_color, Align::right);
        return;
    }
    const float half = 0.5F * node.height();
    draw_text(
        Font::small,
        {TextRole::queue, -1, {node.x0, node.y0, node.x1, node.y0 + half}, small.pixel_height()},
        label, text, Align::centre);
    draw_text(
        Font::small,
        {TextRole::queue, -1, {node.x0, node.y0 + half, node.x1, node.y1}, small.pixel_height()},
        time, time_color, Align::centre);
}

/// The event just popped, in a node as wide as its words (the label, and on two lines the
/// leaving word under it): its width, or 0 when nothing is leaving (no pop, or its highlight over).
float LessonPainter::leaving_width(const QueueView& queue, const QueueWords& words, double now,
                                   bool one_line) const {
    if (queue.popped.empty() || pop_highlight(queue.popped.back(), now) <= 0.0F) return 0.0F;
    const FontAtlas& small = *small_font_;
    float widest = small.text_width(nth(words.popped_labels, queue.popped.size() - 1));
    if (!one_line) {
        const std::string& word =
            queue.popped.back().stale ? words.stale_leaving : words.fresh_leaving;
        widest = std::max(widest, small.text_width(word));
    }
    return std::round(widest + 0.8F * small.pixel_height());
}

// The event just popped, beside the root it was a moment ago, fading out with an arrow away
// from the tree: "remove the min = get next collision", seen as it happens. `node` is its place
// left of `root` (add_queue_tree leaves the room between them for the arrow).
void LessonPainter::add_leaving_root(const QueueView& queue, const QueueWords& words, double now,
                                     RectF root, RectF node) {
    const QueuedEvent& e = queue.popped.back();
    const float glow = pop_highlight(e, now);
    const FontAtlas& small = *small_font_;
    const bool one_line = one_line_nodes(node.height());
    const std::string& label = nth(words.popped_labels, queue.popped.size() - 1);
    const Rgba8 color = e.stale ? palette_.muted : next_color();
    list_.over.add_rect(node, faded(color, 0.25F * glow));
    list_.over.add_frame(node, 2.0F, faded(color, glow));
    const float ay = std::round(0.5F * (root.y0 + root.y1));
    const float gap = root.x0 - node.x1;
    const float ax0 = root.x0 - 0.15F * gap;
    const float ax1 = node.x1 + 0.15F * gap;
    list_.over.add_line({ax0, ay}, {ax1, ay}, 2.0F, faded(color, glow));
    const float head = std::min((one_line ? 0.3F : 0.18F) * node.height(), 0.4F * gap);
    list_.over.add_line({ax1, ay}, {ax1 + head, ay - head}, 2.0F, faded(color, glow));
    list_.over.add_line({ax1, ay}, {ax1 + head, ay + head}, 2.0F, faded(color, glow));
    const Rgba8 text = faded(e.stale ? palette_.muted : palette_.title, glow);
    if (one_line) {
        draw_text(Font::small, {TextRole::queue, -1, node, small.pixel_height()}, label, text,
                  Align::centre);
        return;
    }
    const float half = 0.5F * node.height();
    draw_text(
        Font::small,
        {TextRole::queue, -1, {node.x0, node.y0, node.x1, node.y0 + half}, small.pixel_height()},
        label, text, Align::centre);
    draw_text(
        Font::small,
        {TextRole::queue, -1, {node.x0, node.y0 + half, node.x1, node.y1}, small.pixel_height()},
        e.stale ? words.stale_leaving : words.fresh_leaving, text, Align::centre);
}

// A heap's top levels: slot i's children are d i + 1 .. d i + d; the root (the next pop) framed
// in the highlight colour, stale entries greyed. Nodes keep their full width: a narrow strip
// shows fewer of them, never squeezed or on top of each other. First the root and the event
// just popped beside it, then the root's first children that fit, then "+N below" right of the
// root where it fits whole (else left out).
void LessonPainter::add_queue_tree(const QueueView& queue, const QueueWords& words, double now,
                                   RectF area) {
    if (queue.slots.empty() || queue.levels == 0) return;
    const FontAtlas& small = *small_font_;
    const float h = small.pixel_height();
    const std::size_t d = std::max<unsigned>(queue.arity, 2);
    const bool one_line = one_line_nodes(area.height());
    const float node_h = one_line ? std::floor(area.height()) : std::round(node_lines * h);
    const float full_w = node_width(words.slot_labels, one_line);
    const float node_w = std::min(full_w, area.width());
    constexpr float node_gap = 4.0F;
    // The levels that fit the strip's height (a view may hold more than the show's budget
    // allows here), and the children under the root that fit its width.
    const auto fit = static_cast<unsigned>(
        std::max(1.0F, std::floor((area.height() + node_gap) / (node_h + node_gap))));
    const std::size_t fit_across =
        static_cast<std::size_t>(std::floor((area.width() + node_gap) / (node_w + node_gap)));
    // Nodes narrower than their widest label (a narrow strip's pops took the room) show the
    // root alone, whose label add_queue_strip left room for.
    const std::size_t children =
        node_w < full_w ? 0 : std::min({d, queue.slots.size() - 1, fit_across});
    const bool two_levels = std::min(queue.levels, fit) >= 2 && children > 0;
    const float level_gap = two_levels ? std::max(node_gap, area.height() - 2.0F * node_h) : 0.0F;
    const auto node_at = [&](float cx, float y0) {
        const float x0 = std::round(std::clamp(cx - 0.5F * node_w, area.x0, area.x1 - node_w));
        return RectF{x0, std::round(y0), x0 + node_w, std::round(y0 + node_h)};
    };
    // The children spread over the strip's width, each over the middle of its share.
    std::vector<RectF> nodes;
    const float child_y = area.y0 + node_h + level_gap;
    const float span = area.width() / static_cast<float>(std::max<std::size_t>(children, 1));
    float root_x = area.x0 + 0.5F * area.width();
    // The event just popped and the arrow left of the root: four text heights where the strip
    // has room, two at least; no room for that, the latest pops' list shows it alone.
    float leaving = leaving_width(queue, words, now, one_line);
    const float arrow = std::min(4.0F * h, area.width() - leaving - node_w);
    if (arrow < 2.0F * h) leaving = 0.0F;
    if (leaving > 0.0F) root_x = std::max(root_x, area.x0 + leaving + arrow + 0.5F * node_w);
    nodes.push_back(node_at(root_x, area.y0));
    if (two_levels) {
        for (std::size_t p = 0; p < children; ++p)
            nodes.push_back(node_at(area.x0 + (static_cast<float>(p) + 0.5F) * span, child_y));
    }
    const RectF& root = nodes.front();
    for (std::size_t i = 1; i < nodes.size(); ++i) {
        const RectF& c = nodes[i];
        list_.over.add_line({0.5F * (root.x0 + root.x1), root.y1}, {0.5F * (c.x0 + c.x1), c.y0},
                            1.5F, faded(palette_.muted, 0.8F));
    }
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const QueuedEvent& e = queue.slots[i];
        const Rgba8 frame =
            i == 0 ? next_color() : (e.stale ? faded(palette_.muted, 0.6F) : palette_.muted);
        add_queue_node(nth(words.slot_labels, i),
                       e.stale ? words.stale_slot : nth(words.slot_times, i), nodes[i], frame,
                       e.stale);
    }
    if (leaving > 0.0F)
        add_leaving_root(queue, words, now, root,
                         {root.x0 - arrow - leaving, root.y0, root.x0 - arrow, root.y1});
    // "+N below" on the root's line, right of it, when it fits there whole.
    const float below_x0 = root.x1 + h;
    if (!words.below.empty() && below_x0 + small.text_width(words.below) <= area.x1) {
        const float y0 = std::round(0.5F * (root.y0 + root.y1) - 0.5F * strip_line * h);
        draw_text(Font::small,
                  {TextRole::queue,
                   -1,
                   {below_x0, y0, area.x1, y0 + std::round(strip_line * h)},
                   small.pixel_height()},
                  words.below, palette_.muted, Align::right);
    }
}

// An array queue's first slots in a row: the ordered array from its top (the next event first),
// the unordered array as stored, with where its next event lies (every pop scans for it).
void LessonPainter::add_queue_row(const QueueView& queue, const QueueWords& words, RectF area) {
    const FontAtlas& small = *small_font_;
    const float line = std::round(small.pixel_height() * strip_line);
    const bool ordered = queue.shape == QueueShape::ordered_array;
    // Under its caption where the strip has room for it and a line of nodes; else the caption
    // is on the heading's line (add_queue_strip) and the nodes take the row.
    const bool caption = area.height() >= 2.0F * line;
    if (caption) {
        draw_text(Font::small,
                  {TextRole::queue,
                   -1,
                   {area.x0, area.y0, area.x1, area.y0 + line},
                   small.pixel_height()},
                  words.row_caption, palette_.muted);
    }
    if (queue.slots.empty()) return;
    const float top = caption ? area.y0 + line : area.y0;
    const bool one_line = one_line_nodes(area.y1 - top);
    const float node_h =
        one_line ? std::floor(area.y1 - top) : std::round(node_lines * small.pixel_height());
    // The slots that fit whole (one-line nodes are wider): the first ones, and the one a pop
    // of the unordered array will find in the last place when it lies further on.
    const float full_w = node_width(words.slot_labels, one_line);
    const auto fit =
        static_cast<std::size_t>(std::max(1.0F, std::floor(area.width() / (full_w + 3.0F))));
    std::vector<std::size_t> shown;
    for (std::size_t i = 0; i < queue.slots.size() && shown.size() < fit; ++i) shown.push_back(i);
    if (!ordered && queue.top_index < queue.slots.size() &&
        std::find(shown.begin(), shown.end(), queue.top_index) == shown.end())
        shown.back() = queue.top_index;
    const auto n = static_cast<float>(shown.size());
    const float node_w = std::min(full_w, area.width() / n - 3.0F);
    const float y0 = std::round(top + 0.5F * (area.y1 - top - node_h));
    for (std::size_t k = 0; k < shown.size(); ++k) {
        const std::size_t i = shown[k];
        const QueuedEvent& e = queue.slots[i];
        const float x0 = std::round(area.x0 + static_cast<float>(k) * (area.width() / n));
        const bool next = ordered ? i == 0 : i == queue.top_index;
        const Rgba8 frame =
            next ? next_color() : (e.stale ? faded(palette_.muted, 0.6F) : palette_.muted);
        add_queue_node(nth(words.slot_labels, i),
                       e.stale ? words.stale_slot : nth(words.slot_times, i),
                       {x0, y0, x0 + node_w, y0 + node_h}, frame, e.stale);
    }
}

}  // namespace collide::render
