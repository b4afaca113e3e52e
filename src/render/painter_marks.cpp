// The failure marks' style at a frame's size and the legend that names each kind with its mark,
// counts the failures left unmarked and says when a periodic box's edges wrap around: shared by
// the levels with text (the lesson's line under a panel's figures, the full level's notice
// line). Which failures get a mark is the presentation layer's choice (show::FailureMarks); the
// shapes are failure_marks.cpp's.
#include <algorithm>
#include <cmath>

#include "painter.hpp"

namespace collide::render {

MarkStyle Painter::mark_style() const {
    const float text_px = body_font_ ? body_font_->pixel_height() : 8.0F;
    MarkStyle style;
    style.min_radius = 0.45F * text_px;
    style.stroke = std::max(2.0F, std::round(text_px / 9.0F));
    // An arrow's tip (with its chevron's joint) stops inside the box, at the wall drawn outside
    // it: no mark ever reaches the text beside the box (brownian's column).
    style.reach = std::ceil(0.5F * style.stroke) + 1.0F;
    style.color = palette_.failure;
    style.floor = mark_floor(config_.theme);
    return style;
}

float Painter::add_mark_legend(const TextSlot& slot, const MarkWords& words, float x,
                               float unmarked_x1) {
    const FontAtlas& font = atlas(Font::body);
    const MarkStyle style = mark_style();
    const float symbol = std::round(0.75F * font.pixel_height());
    const float space = std::round(0.35F * font.pixel_height());
    const float gap = std::round(0.7F * font.pixel_height());
    const float cy = 0.5F * (slot.rect.y0 + slot.rect.y1);
    const auto fits = [&](float width) { return x + width <= slot.rect.x1; };
    for (const MarkLegendItem& item : words.items) {
        const float need = symbol + space + font.text_width(item.name);
        if (!fits(need)) return x;
        paint_mark_symbol(list_.over, item.kind, {x + 0.5F * symbol, cy}, symbol, style);
        draw_text(Font::body, slot, item.name, palette_.text, Align::left, x + symbol + space);
        x += need + gap;
    }
    if (!words.unmarked.empty()) {
        const float need = font.text_width(words.unmarked);
        if (fits(need) && x + need <= unmarked_x1) {
            draw_text(Font::body, slot, words.unmarked, palette_.failure, Align::left, x);
            x += need + gap;
        }
    }
    if (!words.wraps.empty()) {
        const float sample = 2.0F * symbol;
        const float need = sample + space + font.text_width(words.wraps);
        if (!fits(need)) return x;
        add_dashed_line(list_.over, x, x + sample, cy, style_.wall, edge_dash(style_.wall),
                        palette_.wrap_edge);
        draw_text(Font::body, slot, words.wraps, palette_.text, Align::left, x + sample + space);
        x += need + gap;
    }
    return x;
}

}  // namespace collide::render
