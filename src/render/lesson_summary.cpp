// The lesson level's summary card (the video's epilogue): the final figures of the panels side
// by side in a table, each panel's column headed in its engine's colour, the work ratio below
// and, when the collision counts differ, why.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "lesson_painter.hpp"
#include "overlay_geometry.hpp"
#include "theme.hpp"

namespace collide::render {

namespace {

/// `label` in two lines, broken at the space nearest its middle ("spheres that ever" /
/// "overlapped"); a label without a space stays one line.
std::vector<std::string> split_in_two(const std::string& label) {
    std::size_t best = std::string::npos;
    for (std::size_t k = label.find(' '); k != std::string::npos; k = label.find(' ', k + 1)) {
        const auto off = [&](std::size_t i) {
            return std::abs(2.0 * static_cast<double>(i) - static_cast<double>(label.size()));
        };
        if (best == std::string::npos || off(k) < off(best)) best = k;
    }
    if (best == std::string::npos) return {label};
    return {label.substr(0, best), label.substr(best + 1)};
}

}  // namespace

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
    // Labels on the left 40 %, one value column per panel over the rest, right-aligned.
    const std::size_t columns = std::max<std::size_t>(1, card.columns.size());
    const bool wide = columns > 2;
    const float label_x0 = (wide ? 0.04F : 0.08F) * w;
    const float values_x1 = (wide ? 0.96F : 0.92F) * w;
    const float gap = 0.02F * w;
    float widest_label = 0.0F;
    for (const SummaryRow& row : card.rows)
        widest_label = std::max(widest_label, body.text_width(row.label));
    // Beyond two columns (a --dt list) each column takes the width its heading and values need
    // and the labels what is left, on two lines where one is too long for it: every word and
    // every figure drawn whole, at the lesson's text size.
    std::vector<float> column_width(columns, 0.0F);
    float values_need = 0.0F;
    if (wide) {
        for (std::size_t c = 0; c < columns; ++c) {
            float widest = c < card.columns.size() ? body.text_width(card.columns[c]) : 0.0F;
            for (const SummaryRow& row : card.rows)
                if (c < row.values.size())
                    widest = std::max(widest, body.text_width(row.values[c]));
            column_width[c] = std::ceil(widest) + gap;
            values_need += column_width[c];
        }
    }
    // The room the columns leave the labels; a label longer than that takes two lines.
    const float label_room = wide ? values_x1 - values_need - gap - label_x0 : widest_label;
    std::vector<std::vector<std::string>> labels;
    float label_width = 0.0F;
    for (const SummaryRow& row : card.rows) {
        labels.push_back(body.text_width(row.label) > label_room
                             ? split_in_two(row.label)
                             : std::vector<std::string>{row.label});
        for (const std::string& line : labels.back())
            label_width = std::max(label_width, body.text_width(line));
    }
    const float values_x0 =
        wide ? std::min(std::max(0.36F * w, std::ceil(label_x0 + label_width + gap)),
                        values_x1 - values_need)
             : std::max(0.48F * w, std::ceil(label_x0 + widest_label + gap));
    if (wide) {
        // What the columns do not need is shared out evenly.
        const float spare = (values_x1 - values_x0 - values_need) / static_cast<float>(columns);
        for (float& width : column_width) width += spare;
    } else {
        std::fill(column_width.begin(), column_width.end(),
                  (values_x1 - values_x0) / static_cast<float>(columns));
    }
    const float table_rows = static_cast<float>(card.rows.size() + 1);  // the headings too
    const float footer = card.footer.empty() ? 0.0F : 0.5F * row_line + row_line;
    const float note = card.note.empty() ? 0.0F : (card.footer.empty() ? 1.5F : 1.0F) * row_line;
    float wrapped_lines = 0.0F;  // the labels' second lines
    for (const auto& label : labels) wrapped_lines += static_cast<float>(label.size() - 1);
    const float total = head_line + 0.6F * head_line + table_rows * row_line +
                        wrapped_lines * body.line_height() + footer + note;
    float y = std::round(0.5F * (h - total));
    const auto line_slot = [](const FontAtlas& font, float x0, float x1, float top, float height) {
        return TextSlot{TextRole::caption, -1, {x0, top, x1, top + height}, font.pixel_height()};
    };
    draw_text(Font::head, line_slot(head, 0.05F * w, 0.95F * w, y, head_line), card.title,
              faded(palette_.title, opacity), Align::centre);
    y += 1.6F * head_line;

    const auto column_slot = [&](std::size_t c, float top) {
        float x0 = values_x0;
        for (std::size_t k = 0; k < c; ++k) x0 += column_width[k];
        return line_slot(body, x0, x0 + column_width[c], top, row_line);
    };
    for (std::size_t c = 0; c < card.columns.size(); ++c) {
        const Rgb8 colour =
            c < frame.panels.size() ? accent(frame.panels[c]) : summary_column_fallback;
        draw_text(Font::body, column_slot(c, y), card.columns[c],
                  faded(with_alpha(colour, 255), opacity), Align::right);
    }
    y += row_line;
    for (std::size_t r = 0; r < card.rows.size(); ++r) {
        const SummaryRow& row = card.rows[r];
        // A label on two lines: its values stand on its last line, where the words end.
        for (std::size_t k = 0; k + 1 < labels[r].size(); ++k) {
            draw_text(Font::body, line_slot(body, label_x0, values_x0, y, row_line), labels[r][k],
                      faded(palette_.text, opacity), Align::left);
            y += body.line_height();
        }
        draw_text(Font::body, line_slot(body, label_x0, values_x0, y, row_line), labels[r].back(),
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
