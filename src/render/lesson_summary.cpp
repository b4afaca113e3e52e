// The lesson level's summary card (the video's epilogue): the final figures of the panels side
// by side in a table, each panel's column headed in its engine's colour, the work ratio below
// and, when the collision counts differ, why.
#include <algorithm>
#include <cmath>
#include <string>

#include "lesson_painter.hpp"
#include "overlay_geometry.hpp"
#include "theme.hpp"

namespace collide::render {

void LessonPainter::add_summary(const FrameContent& frame) {
    const SummaryCard& card = frame.summary;
    const auto w = static_cast<float>(config_.width);
    const auto h = static_cast<float>(config_.height);
    const float opacity = std::clamp(card.opacity, 0.0F, 1.0F);
    list_.over.add_rect({0.0F, 0.0F, w, h}, faded(palette_.background, 0.9F * opacity));
    const FontAtlas& head = atlas(Font::head);
    const FontAtlas& body = atlas(Font::body);
    const float head_line = head.line_height();
    const float row_line = body.line_height() * 1.25F;
    const float table_rows = static_cast<float>(card.rows.size() + 1);  // the headings too
    const float footer = card.footer.empty() ? 0.0F : 0.5F * row_line + row_line;
    const float note = card.note.empty() ? 0.0F : (card.footer.empty() ? 1.5F : 1.0F) * row_line;
    const float total = head_line + 0.6F * head_line + table_rows * row_line + footer + note;
    float y = std::round(0.5F * (h - total));
    const auto line_slot = [](const FontAtlas& font, float x0, float x1, float top, float height) {
        return TextSlot{TextRole::caption, -1, {x0, top, x1, top + height}, font.pixel_height()};
    };
    draw_text(Font::head, line_slot(head, 0.05F * w, 0.95F * w, y, head_line), card.title,
              faded(palette_.title, opacity), Align::centre);
    y += 1.6F * head_line;

    // Labels on the left 40 %, one value column per panel over the rest, right-aligned.
    const std::size_t columns = std::max<std::size_t>(1, card.columns.size());
    // Beyond two columns (a --dt list) the table spans the footer's width and the values take
    // more of it, but never a label's room: "spheres that ever overlapped" is drawn whole.
    const bool wide = columns > 2;
    const float label_x0 = (wide ? 0.04F : 0.08F) * w;
    float widest_label = 0.0F;
    for (const SummaryRow& row : card.rows)
        widest_label = std::max(widest_label, body.text_width(row.label));
    const float values_x0 =
        std::max((wide ? 0.36F : 0.48F) * w, std::ceil(label_x0 + widest_label + 0.02F * w));
    const float values_x1 = (wide ? 0.96F : 0.92F) * w;
    const float column_width = (values_x1 - values_x0) / static_cast<float>(columns);
    const auto column_slot = [&](std::size_t c, float top) {
        const float x0 = values_x0 + column_width * static_cast<float>(c);
        return line_slot(body, x0, x0 + column_width, top, row_line);
    };
    for (std::size_t c = 0; c < card.columns.size(); ++c) {
        const Rgb8 colour =
            c < frame.panels.size() ? accent(frame.panels[c]) : summary_column_fallback;
        draw_text(Font::body, column_slot(c, y), card.columns[c],
                  faded(with_alpha(colour, 255), opacity), Align::right);
    }
    y += row_line;
    for (const SummaryRow& row : card.rows) {
        draw_text(Font::body, line_slot(body, label_x0, values_x0, y, row_line), row.label,
                  faded(palette_.text, opacity), Align::left);
        for (std::size_t c = 0; c < row.values.size() && c < columns; ++c) {
            draw_text(Font::body, column_slot(c, y), row.values[c], faded(palette_.title, opacity),
                      Align::right);
        }
        y += row_line;
    }
    if (!card.footer.empty()) {
        y += 0.5F * row_line;
        draw_text(Font::body, line_slot(body, 0.05F * w, 0.95F * w, y, row_line), card.footer,
                  faded(palette_.title, opacity), Align::centre);
        y += row_line;
    }
    if (!card.note.empty()) {
        if (card.footer.empty()) y += 0.5F * row_line;
        draw_text(Font::body, line_slot(body, 0.05F * w, 0.95F * w, y, row_line), card.note,
                  faded(palette_.text, opacity), Align::centre);
    }
}

}  // namespace collide::render
