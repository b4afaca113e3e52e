// The lesson level's painter: its fonts and style, the phases of its frames and each panel's
// text (title with the engine's swatch, headline figures, the note with its step indicator).
#include "lesson_painter.hpp"

#include <cmath>
#include <string>

namespace collide::render {

CaptionFit fit_caption(const RenderConfig& config, std::string_view caption) {
    if (config.overlays != OverlayLevel::lesson || config.width < compact_width) return {};
    LayoutInput input;
    input.width = config.width;
    input.height = config.height;
    input.boxes = {Box{}};  // the caption line spans the frame whatever the panels
    const FrameLayout layout = lesson_layout(input);
    const TextSlot* slot = layout.slot(TextRole::caption);
    if (slot == nullptr) return {};
    const FontAtlas font(config.font_path, slot->pixel_height);
    const std::string text(caption);
    if (font.text_width(text) <= slot->rect.width()) return {};
    // Characters (UTF-8 lead bytes) of the longest prefix that fits.
    CaptionFit fit{false, 0};
    std::size_t characters = 0;
    for (std::size_t i = 1; i <= text.size(); ++i) {
        const bool ends_character =
            i == text.size() || (static_cast<unsigned char>(text[i]) & 0xC0U) != 0x80U;
        if (!ends_character) continue;
        if (font.text_width(text.substr(0, i)) > slot->rect.width()) break;
        fit.max_characters = ++characters;
    }
    return fit;
}

LessonPainter::LessonPainter(const RenderConfig& config) : Painter(config) {
    const float body = lesson_pixel_height(config_.width, config_.height);
    load_font(body_font_, body);
    if (config_.width >= compact_width) load_font(head_font_, std::round(body * headline_scale));
    style_.wall = std::max(1.0F, std::round(body / 12.0F));
    style_.trail_width = std::max(2.0F, std::round(body / 8.0F));
    style_.trail_fade = 0.35F;
    style_.outline_faint_discs = true;
    style_.escaped_as_marks = true;
    style_.clip_to_box = true;  // everything of a panel stays inside its box, clear of the text
    style_.dashed_periodic_edges = true;
    style_.legible_trails = true;
    choose_colormap_range();
}

// The part of the colormap every colour of which keeps 3:1 contrast with the box: on the dark
// theme its darkest violet is cut, on the light theme its palest yellow, so discs need no outline
// and the colour bar shows what the discs show.
void LessonPainter::choose_colormap_range() {
    const Rgb8 fill = rgb(palette_.box_fill);
    constexpr int steps = 200;
    const auto ok = [&](int i) {
        return contrast_ratio(colormap(static_cast<double>(i) / steps), fill) >= min_disc_contrast;
    };
    int low = 0;
    while (low < steps && !ok(low)) ++low;
    int high = steps;
    while (high > low && !ok(high)) --high;
    if (high - low < steps / 3) return;  // nothing usable: keep the whole map (outlines)
    colormap_low_ = static_cast<double>(low) / steps;
    colormap_high_ = static_cast<double>(high) / steps;
    colormap_clear_ = true;
}

FrameLayout LessonPainter::layout_for(const FrameContent& frame) const {
    LayoutInput input;
    input.width = config_.width;
    input.height = config_.height;
    input.level = OverlayLevel::lesson;
    input.boxes = panel_boxes(frame);
    for (const PanelContent& panel : frame.panels) {
        if (!panel.note.empty()) input.note_line = true;
        input.mark_lines.push_back(panel.mark_line);
    }
    input.large_plot = frame.histogram == PlotSize::large;
    input.small_plot = frame.histogram == PlotSize::small;
    // Speed colours beside a speed plot: the plot's axis is the colour bar (speed_axis_colors).
    input.color_legend =
        config_.color_mode == ColorMode::mass ||
        (config_.color_mode == ColorMode::speed && frame.histogram == PlotSize::none);
    input.counter_rows = 0;
    for (std::size_t i = 0; i < frame.panels.size(); ++i) {
        const Snapshot* snapshot = frame.panels[i].snapshot;
        if (snapshot != nullptr && snapshot->queue && input.queue_panel < 0)
            input.queue_panel = static_cast<int>(i);
    }
    return lesson_layout(input);
}

void LessonPainter::begin_frame(const FrameContent& frame) {
    video_time_ = frame.video_time;
    speed_ = frame.speed;
    intro_ = frame.intro_opacity > 0.0F && !frame.intro_title.empty();
    if (layout_.queue_panel >= 0 && !small_font_) {
        // Loaded with the first frame that shows a queue, so other videos are unchanged.
        load_font(small_font_, std::round(body_font_->pixel_height() * queue_text_scale));
    }
}

void LessonPainter::add_marks(std::size_t index, const PanelContent& content,
                              const PanelLayout& panel) {
    const Snapshot& snapshot = *content.snapshot;
    if (snapshot.queue) {
        add_queue_in_box(snapshot, panel);
        if (layout_.queue_panel == static_cast<int>(index) && !intro_)
            add_queue_strip(snapshot, content.queue_words, layout_.queue_strip);
    }
    // The marks the presentation layer chose (show::FailureMarks), each kind its own shape.
    paint_failure_marks(list_, content.marks, panel, snapshot.box, mark_style());
}

void LessonPainter::finish_frame(const FrameContent& frame) {
    if (!layout_.compact && !intro_) add_column(frame);
    if (intro_) add_intro(frame);
}

void LessonPainter::add_panel_text(std::size_t index, const PanelContent& content,
                                   const PanelLayout& panel) {
    if (intro_) return;  // the title card covers the frame
    const int p = static_cast<int>(index);
    const Rgba8 accent = with_alpha(content.accent, 255);
    if (layout_.compact) {
        if (const TextSlot* slot = layout_.slot(TextRole::figures, p)) {
            const float sw = std::round(0.6F * body_font_->pixel_height());
            const float cy = 0.5F * (slot->rect.y0 + slot->rect.y1);
            list_.over.add_rect({slot->rect.x0, cy - 0.5F * sw, slot->rect.x0 + sw, cy + 0.5F * sw},
                                accent);
            draw_text(Font::body, *slot, content.compact_line, palette_.title, Align::left,
                      slot->rect.x0 + 1.5F * sw);
        }
        return;
    }
    if (const TextSlot* slot = layout_.slot(TextRole::title, p)) {
        // The swatch is the legend: the engine's colour, also used by its bar and histogram.
        const float sw = std::round(0.7F * body_font_->pixel_height());
        const float cy = 0.5F * (slot->rect.y0 + slot->rect.y1);
        list_.over.add_rect({slot->rect.x0, cy - 0.5F * sw, slot->rect.x0 + sw, cy + 0.5F * sw},
                            accent);
        draw_text(Font::body, *slot, content.title, palette_.title, Align::left,
                  slot->rect.x0 + 1.6F * sw);
    }
    if (const TextSlot* slot = layout_.slot(TextRole::figures, p)) {
        float x = slot->rect.x0;
        const float gap = head_font_->pixel_height();
        for (const Figure& figure : content.figures) {
            const float need =
                head_font_->text_width(figure.value) + body_font_->text_width(" " + figure.label);
            if (x + need > slot->rect.x1) break;  // the least important figures go first
            const bool alarm = figure.failure && figure.value != "0";
            x = draw_text(Font::head, *slot, figure.value,
                          alarm ? palette_.failure : palette_.title, Align::left, x);
            // Body text on the headline's baseline.
            const float baseline = slot->rect.y0 +
                                   0.5F * (slot->rect.height() - head_font_->pixel_height()) +
                                   head_font_->ascent();
            x = body_font_->add_text(list_.text[0].glyphs, x, baseline, " " + figure.label,
                                     palette_.text);
            x += gap;
        }
    }
    if (const TextSlot* slot = layout_.slot(TextRole::note, p); slot && !content.note.empty()) {
        float right = slot->rect.x1;
        if (content.step_period > 1 && content.step_period <= 16) {
            // The step indicator: one square per frame of a step, the current one filled.
            const float s = std::round(0.45F * body_font_->pixel_height());
            const float cy = 0.5F * (slot->rect.y0 + slot->rect.y1);
            const auto n = static_cast<float>(content.step_period);
            float x = slot->rect.x1 - n * 1.5F * s;
            right = x - s;
            for (int k = 0; k < content.step_period; ++k) {
                const RectF r{x, cy - 0.5F * s, x + s, cy + 0.5F * s};
                if (k == content.step_phase) {
                    list_.over.add_rect(r, accent);
                } else {
                    list_.over.add_frame(r, std::max(1.0F, std::round(s / 6.0F)), palette_.muted);
                }
                x += 1.5F * s;
            }
        }
        TextSlot shortened = *slot;
        shortened.rect.x1 = right;
        draw_text(Font::body, shortened, content.note, palette_.text);
    }
    add_mark_legend(index, content);  // under the figures, outside the box
}

}  // namespace collide::render
