// A replay's marks over a panel's (zoomed) box: the ghosts of the failing discs, the straight
// jump between two checks, the labels and the heading. What they are and say is the presentation
// layer's (show::replay_views); here they get their pixels.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "lesson_painter.hpp"

namespace collide::render {

namespace {

struct Circle {
    PointF centre;
    float radius = 0.0F;
};

/// Whether rectangle r comes within `margin` of the circle (pixels).
bool touches(RectF r, const Circle& c, float margin) {
    const float nx = std::clamp(c.centre.x, r.x0, r.x1);
    const float ny = std::clamp(c.centre.y, r.y0, r.y1);
    return std::hypot(nx - c.centre.x, ny - c.centre.y) < c.radius + margin;
}

/// The plate of half sizes (half_w, half_h) centred at `at`, kept inside `inside` as
/// add_plate_label keeps it.
RectF plate_at(PointF at, float half_w, float half_h, RectF inside) {
    const float w = 2.0F * half_w;
    const float h = 2.0F * half_h;
    const float x0 = std::clamp(at.x - half_w, inside.x0, std::max(inside.x0, inside.x1 - w));
    const float y0 = std::clamp(at.y - half_h, inside.y0, std::max(inside.y0, inside.y1 - h));
    return {x0, y0, x0 + w, y0 + h};
}

/// The centre of a plate `clear` pixels from p on `side`.
PointF beside(PointF p, LabelSide side, float clear, float half_w, float half_h) {
    switch (side) {
        case LabelSide::above:
            return {p.x, p.y - clear - half_h};
        case LabelSide::below:
            return {p.x, p.y + clear + half_h};
        case LabelSide::left:
            return {p.x - clear - half_w, p.y};
        case LabelSide::right:
            return {p.x + clear + half_w, p.y};
        case LabelSide::over:
            break;
    }
    return p;
}

/// Where a replay label goes: beside its point, on the side asked for if a plate there covers
/// no ghost and no plate placed before (`placed`), else the nearest such place going round the
/// point and farther out; a plate pushed back into the box by its edge must not land on a ghost
/// either. None free: the side asked for.
PointF label_place(PointF p, LabelSide side, float clear, float half_w, float half_h, RectF inside,
                   const std::vector<Circle>& ghosts, const std::vector<RectF>& placed,
                   float margin) {
    const std::array<LabelSide, 4> order = [&] {
        switch (side) {
            case LabelSide::above:
                return std::array{LabelSide::above, LabelSide::right, LabelSide::left,
                                  LabelSide::below};
            case LabelSide::below:
                return std::array{LabelSide::below, LabelSide::right, LabelSide::left,
                                  LabelSide::above};
            case LabelSide::left:
                return std::array{LabelSide::left, LabelSide::above, LabelSide::below,
                                  LabelSide::right};
            case LabelSide::right:
            case LabelSide::over:
                break;
        }
        return std::array{LabelSide::right, LabelSide::above, LabelSide::below, LabelSide::left};
    }();
    const auto free = [&](RectF r) {
        return std::none_of(ghosts.begin(), ghosts.end(),
                            [&](const Circle& c) { return touches(r, c, margin); }) &&
               std::none_of(placed.begin(), placed.end(),
                            [&](const RectF& o) { return overlaps(r, o); });
    };
    for (int ring = 0; ring < 6; ++ring) {
        const float d = clear + static_cast<float>(ring) * 2.0F * half_h;
        for (const LabelSide s : order) {
            const PointF at = beside(p, s, d, half_w, half_h);
            const RectF r = plate_at(at, half_w, half_h, inside);
            if (free(r)) return {0.5F * (r.x0 + r.x1), 0.5F * (r.y0 + r.y1)};
        }
    }
    return beside(p, side, clear, half_w, half_h);
}

/// Where a heading of half sizes (half_w, half_h) goes among `circles` (the discs it must not
/// cover) and `placed` (plates drawn before: a question's letters): the top of the box, its
/// middle first, where that is free; else the free place of the highest row, nearest the middle
/// (rows half a plate apart, each searched outwards from the middle); none free: the top middle.
PointF heading_place(RectF inside, float half_w, float half_h, const std::vector<Circle>& circles,
                     const std::vector<RectF>& placed, float margin) {
    // The circles that reach the row's band: a crowded box is searched fast.
    std::vector<Circle> row;
    const auto free = [&](RectF r) {
        return std::none_of(row.begin(), row.end(),
                            [&](const Circle& c) { return touches(r, c, margin); }) &&
               std::none_of(placed.begin(), placed.end(),
                            [&](const RectF& o) { return overlaps(r, o); });
    };
    const float middle = 0.5F * (inside.x0 + inside.x1);
    const float top = inside.y0 + half_h;
    const float bottom = std::max(top, inside.y1 - half_h);
    const float across = std::max(0.0F, 0.5F * inside.width() - half_w);
    const float step = std::max(1.0F, 0.5F * half_h);
    for (float y = top; y <= bottom + 0.5F; y += 2.0F * step) {
        const RectF band = plate_at({middle, y}, half_w, half_h, inside);
        row.clear();
        for (const Circle& c : circles) {
            if (c.centre.y + c.radius + margin > band.y0 &&
                c.centre.y - c.radius - margin < band.y1)
                row.push_back(c);
        }
        for (float dx = 0.0F; dx <= across + 0.5F; dx += step) {
            for (const float x : {middle - dx, middle + dx}) {
                const RectF r = plate_at({x, y}, half_w, half_h, inside);
                if (free(r)) return {0.5F * (r.x0 + r.x1), 0.5F * (r.y0 + r.y1)};
            }
        }
    }
    return {middle, top};
}

}  // namespace

void LessonPainter::add_replay(const ReplayView& replay, const PanelLayout& panel, const Box& box) {
    if (intro_) return;
    const float body = body_font_->pixel_height();
    const float stroke = std::max(2.0F, std::round(body / 7.0F));
    const RectF inside = panel.box;
    const auto color = [&](bool failure, float opacity, int tint = no_tint) {
        if (failure) return faded(palette_.failure, opacity);
        if (tint == no_tint) return faded(palette_.text, opacity);
        const Rgb8 c = candidate_color(tint, config_.theme);
        return faded({c.r, c.g, c.b, 255}, opacity);
    };
    // A question's contacts: thin, as the next collision's line (they join, they do not shout),
    // so that the arrows and letters over them stay legible where candidates sit close.
    const float thin = std::max(1.5F, std::round(body / 10.0F));
    // The jump: a thick line with an arrowhead where the move ends; a velocity the same in the
    // motion colour; a connector thin, without a head.
    for (const BoxLine& line : replay.lines) {
        PointF from = panel.to_pixels(line.from, box);
        PointF to = panel.to_pixels(line.to, box);
        const float dx = to.x - from.x;
        const float dy = to.y - from.y;
        const float length = std::hypot(dx, dy);
        Rgba8 c = color(line.failure, line.opacity, line.tint);
        if (line.style == LineStyle::motion && !line.failure) {
            const Rgb8 m = motion_arrow_color(config_.theme);
            c = faded({m.r, m.g, m.b, 255}, line.opacity);
        }
        const PointF tip = to;
        if (!clip_to(inside, from, to)) continue;
        if (line.style == LineStyle::connector) {
            list_.over.add_line(from, to, thin, c);
            continue;
        }
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
    std::vector<Circle> ghosts;
    for (const GhostDisc& ghost : replay.ghosts) {
        const PointF p = panel.to_pixels(ghost.where, box);
        const auto radius = static_cast<float>(ghost.radius * panel.scale);
        ghosts.push_back({p, radius});
        const Rgba8 c = color(ghost.failure, ghost.opacity);
        if (ghost.filled) {
            list_.discs.push_back({p.x, p.y, radius, 0.0F, faded(c, 0.85F)});
        } else {
            list_.discs.push_back(
                {p.x, p.y, radius, std::max(stroke, std::min(radius * 0.3F, 2.0F * stroke)), c});
        }
    }
    labels_.clear();
    // The heading first, at the top of the box: the labels keep clear of it. A heading that must
    // keep clear of discs (a question's) comes last, where neither discs nor labels are.
    const bool heading_clear_of_discs = !replay.keep_clear.empty();
    if (!replay.heading.empty() && !heading_clear_of_discs) {
        add_plate_label(Font::body, {0.5F * (inside.x0 + inside.x1), inside.y0 + 0.8F * body},
                        replay.heading, palette_.title, inside);
    }
    const FontAtlas& font = atlas(Font::body);
    // The plates' sizes as add_plate_label makes them.
    const float pad = std::round(0.2F * font.pixel_height());
    const float half_h = 0.5F * std::round(font.pixel_height() * 1.05F);
    for (const BoxLabel& label : replay.labels) {
        const PointF p = panel.to_pixels(label.at, box);
        const float clear = static_cast<float>(label.clear * panel.scale) + 0.3F * body;
        const float half_w = 0.5F * font.text_width(label.text) + pad;
        // Beside the ghosts, never on one: the class must see the discs the words are about.
        // `over`: on its point (show placed it clear of the discs: a question's letters).
        const PointF at = label.side == LabelSide::over
                              ? p
                              : label_place(p, label.side, clear, half_w, half_h, inside, ghosts,
                                            labels_, 0.15F * body);
        add_plate_label(Font::body, at, label.text, color(label.failure, label.opacity, label.tint),
                        inside);
    }
    if (!replay.heading.empty() && heading_clear_of_discs) {
        std::vector<Circle> discs;
        discs.reserve(replay.keep_clear.size());
        for (const BoxCircle& c : replay.keep_clear) {
            discs.push_back(
                {panel.to_pixels(c.centre, box), static_cast<float>(c.radius * panel.scale)});
        }
        const float half_w = 0.5F * font.text_width(replay.heading) + pad;
        // The labels' margin, and a pixel more: add_plate_label rounds the plate's corner.
        const PointF at =
            heading_place(inside, half_w, half_h, discs, labels_, 0.15F * body + 1.0F);
        add_plate_label(Font::body, at, replay.heading, palette_.title, inside);
    }
}

}  // namespace collide::render
