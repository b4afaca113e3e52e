// The lesson level's column (clock, caption, the cost graphic, the energy line, the colour
// legend, a plot) and the title card drawn over the whole frame.
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "lesson_painter.hpp"
#include "plots.hpp"

namespace collide::render {

void LessonPainter::add_column(const FrameContent& frame) {
    const std::vector<const TextSlot*> clock = layout_.slots(TextRole::clock);
    if (!clock.empty()) draw_text(Font::body, *clock[0], frame.time_text, palette_.title);
    if (clock.size() > 1) draw_text(Font::body, *clock[1], frame.time_unit, palette_.muted);
    if (const TextSlot* slot = layout_.slot(TextRole::caption); slot && !frame.caption.empty()) {
        draw_text(Font::body, *slot, frame.caption, palette_.title, Align::centre);
    }
    // The cost graphic: one bar per engine on one scale, so N^2 against log N is seen; the
    // smaller bar keeps a visible stub at any ratio (the ratio under the bars says how small).
    double most = 0.0;
    for (const PanelContent& panel : frame.panels) most = std::max(most, panel.cost);
    if (const TextSlot* slot = layout_.slot(TextRole::cost_heading)) {
        draw_text(Font::body, *slot, frame.cost_heading, palette_.muted);
    }
    for (std::size_t i = 0; i < frame.panels.size(); ++i) {
        const PanelContent& panel = frame.panels[i];
        const int p = static_cast<int>(i);
        const TextSlot* label = layout_.slot(TextRole::cost_label, p);
        const TextSlot* value = layout_.slot(TextRole::cost_value, p);
        if (label == nullptr || value == nullptr) continue;
        draw_text(Font::body, *label, panel.cost_label,
                  with_alpha(accent_text(accent(panel), config_.theme), 255));
        const RectF track{label->rect.x0, label->rect.y1, label->rect.x1,
                          value->rect.y0 - std::round(0.6F * layout_.margin)};
        list_.over.add_rect(track, faded(palette_.muted, 0.35F));
        if (most > 0.0 && panel.cost > 0.0) {
            const float stub = std::max(3.0F, std::round(track.height()));
            const float w = std::max(std::min(stub, track.width()),
                                     static_cast<float>(panel.cost / most) * track.width());
            list_.over.add_rect({track.x0, track.y0, track.x0 + w, track.y1},
                                with_alpha(accent(panel), 255));
        }
        const Font value_font =
            value->pixel_height >= head_font_->pixel_height() ? Font::head : Font::body;
        if (atlas(value_font).text_width(panel.cost_text) > value->rect.width()) {
            // Too many digits for the column: in words, in the body font.
            draw_text(Font::body, *value, panel.cost_words, palette_.title);
        } else {
            draw_text(value_font, *value, panel.cost_text, palette_.title);
        }
    }
    const std::vector<const TextSlot*> ratio = layout_.slots(TextRole::cost_ratio);
    if (!ratio.empty() && !frame.cost_ratio.empty()) {
        const std::vector<std::string> lines =
            wrap_words(*body_font_, frame.cost_ratio, ratio.front()->rect.width());
        for (std::size_t k = 0; k < lines.size() && k < ratio.size(); ++k) {
            draw_text(Font::body, *ratio[k], lines[k], palette_.title);
        }
    }
    const std::vector<const TextSlot*> energy = layout_.slots(TextRole::energy);
    if (!energy.empty() && !frame.energy_line.empty()) {
        const std::vector<std::string> lines =
            wrap_words(*body_font_, frame.energy_line, energy.front()->rect.width());
        for (std::size_t k = 0; k < lines.size() && k < energy.size(); ++k) {
            draw_text(Font::body, *energy[k], lines[k],
                      frame.energy_plot ? palette_.failure : palette_.text);
        }
    }
    if (const TextSlot* slot = layout_.slot(TextRole::legend)) {
        // What the disc colours mean: the colormap, its ends named (slow .. fast, light .. heavy).
        const RectF bar = layout_.column.legend_bar;
        constexpr int segments = 32;
        for (int s = 0; s < segments; ++s) {
            const float x0 = bar.x0 + bar.width() * static_cast<float>(s) / segments;
            const float x1 = bar.x0 + bar.width() * static_cast<float>(s + 1) / segments;
            list_.over.add_rect({x0, bar.y0, x1 + 0.5F, bar.y1},
                                with_alpha(shown_colormap((s + 0.5) / segments), 255));
        }
        draw_text(Font::body, *slot, frame.color_key.low, palette_.text);
        draw_text(Font::body, *slot, frame.color_key.high, palette_.text, Align::right);
    }
    const RectF plot = layout_.column.plot;
    if (plot.width() <= 0.0F || plot.height() <= 0.0F) return;
    if (frame.histogram != PlotSize::none) {
        std::vector<const Snapshot*> snapshots;
        std::vector<Rgb8> colors;
        for (const PanelContent& panel : frame.panels) {
            snapshots.push_back(panel.snapshot);
            colors.push_back(accent(panel));
        }
        std::function<Rgb8(double)> axis_colors;
        if (config_.color_mode == ColorMode::speed) {
            axis_colors = [this](double t) { return shown_colormap(t); };
        }
        draw_moving_speed_plot(list_.over, list_.text[0].glyphs, *body_font_, plot, snapshots,
                               colors, config_.speed_min, config_.speed_max, frame.speed_plot,
                               plot_colors(config_.theme), axis_colors);
    } else if (frame.energy_plot) {
        draw_drift_plot(list_.over, list_.text[0].glyphs, *body_font_, plot, frame.energy_drift,
                        frame.drift_plot, accents(frame), plot_colors(config_.theme));
    }
}

void LessonPainter::add_intro(const FrameContent& frame) {
    const auto w = static_cast<float>(config_.width);
    const auto h = static_cast<float>(config_.height);
    const float opacity = std::clamp(frame.intro_opacity, 0.0F, 1.0F);
    list_.over.add_rect({0.0F, 0.0F, w, h}, faded(palette_.background, 0.9F * opacity));
    const FontAtlas& head = atlas(Font::head);
    const FontAtlas& body = atlas(Font::body);
    const float width = 0.8F * w;
    const std::vector<std::string> title = wrap_words(head, frame.intro_title, width);
    const std::vector<std::string> text = wrap_words(body, frame.intro_text, width);
    const float head_line = head.line_height();
    const float body_line = body.line_height() * 1.1F;
    const float total = static_cast<float>(title.size()) * head_line + 0.6F * head_line +
                        static_cast<float>(text.size()) * body_line;
    float y = std::round(0.5F * (h - total));
    const Rgba8 title_color = faded(palette_.title, opacity);
    const Rgba8 text_color = faded(palette_.text, opacity);
    for (const std::string& line : title) {
        const TextSlot slot{
            TextRole::caption, -1, {0.1F * w, y, 0.9F * w, y + head_line}, head.pixel_height()};
        draw_text(Font::head, slot, line, title_color, Align::centre);
        y += head_line;
    }
    y += 0.6F * head_line;
    for (const std::string& line : text) {
        const TextSlot slot{
            TextRole::caption, -1, {0.1F * w, y, 0.9F * w, y + body_line}, body.pixel_height()};
        draw_text(Font::body, slot, line, text_color, Align::centre);
        y += body_line;
    }
}

}  // namespace collide::render
