// The full level (today's expert layout): a header of title and counters above each box, a strip
// of clock, legend and plots below the panels.
#include "full_painter.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "plots.hpp"

namespace collide::render {

namespace {

std::string join(const std::vector<std::string>& parts, const char* separator) {
    std::string out;
    for (const std::string& part : parts) {
        if (!out.empty()) out += separator;
        out += part;
    }
    return out;
}

}  // namespace

FullPainter::FullPainter(const RenderConfig& config) : MinimalPainter(config) {
    load_font(body_font_, font_pixel_height(config_.height));
    use_classic_style();
    // As at the lesson level: each failure its own mark (a disc that left the box is an arrow
    // at the edge it crossed, not a disc drawn over the counters outside), nothing of a panel
    // outside its box, periodic edges dashed, trails legible.
    style_.escaped_as_marks = true;
    style_.clip_to_box = true;
    style_.dashed_periodic_edges = true;
    style_.legible_trails = true;
}

FrameLayout FullPainter::layout_for(const FrameContent& frame) const {
    return classic_layout(config_.width, config_.height, true, panel_boxes(frame),
                          font_pixel_height(config_.height) * 1.2F, counter_rows(frame));
}

void FullPainter::begin_frame(const FrameContent& frame) {
    counter_rows_ = counter_rows(frame);
}

// The marks the presentation layer chose (show::FailureMarks), each kind its own shape.
void FullPainter::add_marks(std::size_t /*index*/, const PanelContent& content,
                            const PanelLayout& panel) {
    paint_failure_marks(list_, content.marks, panel, content.snapshot->box, mark_style());
}

Rgba8 FullPainter::counter_color() const noexcept {
    // The full level's dimmer counter grey on dark; the theme's text colour on light.
    return config_.theme == Theme::dark ? full_counter_dark : palette_.text;
}

int FullPainter::panel_counter_columns(std::size_t panels) const {
    const float panel_width =
        static_cast<float>(config_.width) / static_cast<float>(std::max<std::size_t>(panels, 1));
    return counter_columns(panel_width, body_font_->pixel_height());
}

/// Rows of the counter grid: enough for the panel with the most counters, but the header never
/// takes more than about 30% of the frame height (counters come most important first).
int FullPainter::counter_rows(const FrameContent& frame) const {
    const auto columns = static_cast<std::size_t>(panel_counter_columns(frame.panels.size()));
    std::size_t rows = 0;
    for (const PanelContent& panel : frame.panels) {
        rows = std::max(rows, (panel.counters.size() + columns - 1) / columns);
    }
    const float line = body_font_->line_height();
    const auto fit = static_cast<std::size_t>(
        std::max(0.0F, std::floor(0.30F * static_cast<float>(config_.height) / line) - 1.0F));
    return static_cast<int>(std::min(rows, fit));
}

// The header: the title, then the counters in a grid, row by row.
void FullPainter::add_panel_text(std::size_t index, const PanelContent& content,
                                 const PanelLayout& panel) {
    const FontAtlas& font = *body_font_;
    OverlayBatch& text = list_.text[0].glyphs;
    const float baseline = panel.header.y0 + font.ascent();
    font.add_text(text, panel.header.x0, baseline, content.title, palette_.title);
    const TextSlot* header = layout_.slot(TextRole::counters, static_cast<int>(index));
    if (header != nullptr) record_text(*header, content.title);
    const int columns = panel_counter_columns(layout_.panels.size());
    const float column_width = (panel.header.x1 - panel.header.x0) / static_cast<float>(columns);
    const std::size_t shown =
        std::min(content.counters.size(),
                 static_cast<std::size_t>(columns) * static_cast<std::size_t>(counter_rows_));
    for (std::size_t k = 0; k < shown; ++k) {
        const auto column = static_cast<float>(k % static_cast<std::size_t>(columns));
        const auto row = static_cast<float>(1 + k / static_cast<std::size_t>(columns));
        font.add_text(text, panel.header.x0 + column * column_width,
                      baseline + row * font.line_height(), content.counters[k], counter_color());
        if (header != nullptr) record_text(*header, content.counters[k]);
    }
}

// The strip: clock and legend, the speed histogram, the energy drift plot, the notice line.
void FullPainter::finish_frame(const FrameContent& frame) {
    const FontAtlas& font = *body_font_;
    OverlayBatch& text = list_.text[0].glyphs;
    const RectF strip = layout_.strip;
    const float m = layout_.margin * 1.5F;
    const float line = font.line_height();
    const RectF columns{strip.x0 + m, strip.y0 + m * 0.5F, strip.x1 - m,
                        strip.y1 - m * 0.5F - line};
    const float info_width = 0.26F * columns.width();
    const float plot_width = 0.5F * (columns.width() - info_width) - m;
    const RectF info{columns.x0, columns.y0, columns.x0 + info_width - m, columns.y1};
    const RectF histogram{info.x1 + m, columns.y0, info.x1 + m + plot_width, columns.y1};
    const RectF drift{histogram.x1 + 2.0F * m, columns.y0, columns.x1, columns.y1};

    font.add_text(text, info.x0, info.y0 + font.ascent(), frame.time_text, palette_.title);
    const TextSlot* strip_slot = layout_.slot(TextRole::strip);
    if (strip_slot != nullptr) record_text(*strip_slot, frame.time_text);
    add_legend(info, frame.color_key);
    std::vector<const Snapshot*> snapshots;
    for (const PanelContent& panel : frame.panels) snapshots.push_back(panel.snapshot);
    // Each panel's series in its engine's accent, whichever panels the frame has.
    const std::vector<Rgb8> series_colors = accents(frame);
    draw_speed_plot(list_.over, text, font, histogram, snapshots, series_colors, config_.speed_min,
                    config_.speed_max, frame.speed_plot, plot_colors(config_.theme));
    draw_drift_plot(list_.over, text, font, drift, frame.energy_drift, frame.drift_plot,
                    series_colors, plot_colors(config_.theme));
    if (strip_slot != nullptr) {
        TextSlot notice = *strip_slot;
        notice.rect = {columns.x0, strip.y1 - m * 0.5F - line, columns.x1, strip.y1 - m * 0.5F};
        add_notice_line(notice, frame);
    }
}

void FullPainter::add_notice_line(const TextSlot& line, const FrameContent& frame) {
    float x = line.rect.x0;
    for (const PanelContent& panel : frame.panels) x = add_mark_legend(line, panel.mark_words, x);
    const std::string notes = join(frame.notes, "   \xC2\xB7   ");
    if (!notes.empty()) (void)draw_text(Font::body, line, notes, counter_color(), Align::left, x);
}

// Colour bar with its fixed range (speed or mass modes) or the tag key, with the show's words.
void FullPainter::add_legend(RectF info, const ColorKeyWords& words) {
    const FontAtlas& font = *body_font_;
    OverlayBatch& text = list_.text[0].glyphs;
    const Rgba8 counter = counter_color();
    const float line = font.line_height();
    float y = info.y0 + line * 1.3F;
    if (config_.color_mode == ColorMode::speed || config_.color_mode == ColorMode::mass) {
        const float bar_height = std::max(4.0F, std::round(line * 0.5F));
        constexpr int segments = 32;
        const float bar_width = info.width();
        for (int s = 0; s < segments; ++s) {
            const float x0 = info.x0 + bar_width * static_cast<float>(s) / segments;
            const float x1 = info.x0 + bar_width * static_cast<float>(s + 1) / segments;
            const Rgb8 c = colormap((s + 0.5) / segments);
            list_.over.add_rect({x0, y, x1 + 0.5F, y + bar_height}, with_alpha(c, 255));
        }
        y += bar_height + font.ascent();
        font.add_text(text, info.x0, y, words.low_value, counter);
        font.add_text(text, info.x0 + 0.5F * (bar_width - font.text_width(words.quantity)), y,
                      words.quantity, counter);
        font.add_text(text, info.x1 - font.text_width(words.high_value), y, words.high_value,
                      counter);
    } else if (config_.color_mode == ColorMode::tag) {
        const float size = std::round(line * 0.6F);
        list_.over.add_rect({info.x0, y, info.x0 + size, y + size}, with_alpha(tagged_color, 255));
        font.add_text(text, info.x0 + size * 1.5F, y + size, words.tagged, counter);
    }
}

}  // namespace collide::render
