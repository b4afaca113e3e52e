// The lesson level's painter: its fonts and style, the phases of its frames and each panel's
// text (title with the engine's swatch, headline figures, the note with its step indicator).
#include "lesson_painter.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "code_panel.hpp"

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

float LessonPainter::number_column_width(const Snapshot& snapshot) const {
    // Discs covering this share of the box leave no room for a number between them: their
    // numbers go outside the box (add_frame_label). dense-fluid packs 0.7, gas about 0.06.
    constexpr double crowded_share = 0.4;
    const double box_area = snapshot.box.width * snapshot.box.height;
    double radii2 = 0.0;
    for (const DiscState& d : snapshot.discs) radii2 += d.radius * d.radius;
    const double covered = std::numbers::pi * radii2;
    if (snapshot.discs.empty() || !(box_area > 0.0) || covered < crowded_share * box_area)
        return 0.0F;
    // The widest number's plate (the next pair's, in the body font), clear of the box and the
    // text by add_frame_label's 2 px.
    const FontAtlas& f = *body_font_;
    const std::string widest = std::to_string(snapshot.discs.size() - 1);
    return std::ceil(f.text_width(widest) + 2.0F * std::round(0.2F * f.pixel_height()) + 4.0F);
}

FrameLayout LessonPainter::layout_for(const FrameContent& frame) const {
    LayoutInput input;
    input.width = config_.width;
    input.height = config_.height;
    input.boxes = panel_boxes(frame);
    for (const PanelContent& panel : frame.panels) {
        if (!panel.note.empty()) input.note_line = true;
        if (!panel.how.empty()) input.how_line = true;
        // A panel showing its queue says on that line what the lines in its box are.
        input.mark_lines.push_back(panel.mark_line ||
                                   (panel.snapshot != nullptr && panel.snapshot->queue));
    }
    input.cost_ratio = frame.panels.size() == 2;
    input.clock_unit = !frame.time_unit.empty();
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
    // The queue strip takes the height a how line would: its own words say how the queue works.
    if (input.queue_panel >= 0) input.how_line = false;
    if (frame.code) {
        input.code_rows = frame.code->lines.size() + (frame.code->title.empty() ? 0 : 1);
        input.code_width = code_panel_width(*frame.code, *body_font_);
    }
    if (input.queue_panel >= 0)
        input.number_column = number_column_width(*frame.panels[input.queue_panel].snapshot);
    return lesson_layout(input);
}

void LessonPainter::add_code(const view::CodeView& code) {
    const std::vector<const TextSlot*> rows = layout_.slots(TextRole::code);
    const CodeText draw = [&](std::size_t row, RectF, float x, std::string_view s, Rgba8 color) {
        if (row < rows.size()) (void)draw_text(Font::body, *rows[row], s, color, Align::left, x);
    };
    paint_code(code, layout_.code, atlas(Font::body), code_colors(palette_), list_.under, draw);
}

namespace {
bool shows_title_card(const FrameContent& frame) {
    return frame.intro_opacity > 0.0F && !frame.intro_title.empty();
}
bool shows_summary(const FrameContent& frame) {
    return !frame.summary.rows.empty() && frame.summary.opacity > 0.0F;
}
/// A scene's title for a line `room` wide: whole where it fits, else what it shows, its words
/// after a colon ("Alder and Wainwright, 1957: hard spheres freeze" -> "Hard spheres freeze");
/// what is still too wide is cut with "..." by draw_text.
std::string short_title(const FontAtlas& font, const std::string& title, RectF room) {
    if (font.text_width(title) <= room.width()) return title;
    const std::size_t colon = title.find(": ");
    if (colon == std::string::npos || colon + 2 >= title.size()) return title;
    std::string subject = title.substr(colon + 2);
    if (subject[0] >= 'a' && subject[0] <= 'z') subject[0] = static_cast<char>(subject[0] - 32);
    return subject;
}
}  // namespace

void LessonPainter::begin_frame(const FrameContent& frame) {
    video_time_ = frame.video_time;
    speed_ = frame.speed;
    pop_seconds_ = frame.pop_highlight;
    // A card covers this frame, the title card or the epilogue's summary: no other text.
    intro_ = shows_title_card(frame) || shows_summary(frame);
    frame_numbers_.clear();
    notes_.clear();
    if (layout_.queue_panel >= 0 && !small_font_) {
        // Loaded with the first frame that shows a queue, so other videos are unchanged.
        load_font(small_font_, std::round(body_font_->pixel_height() * queue_text_scale));
    }
}

void LessonPainter::add_marks(std::size_t index, const PanelContent& content,
                              const PanelLayout& panel) {
    const Snapshot& snapshot = *content.snapshot;
    if (snapshot.queue) {
        // Zoomed in (a replay), the queue's lines would reach out of the box.
        if (!panel.zoomed && content.queue_in_box)
            add_queue_in_box(snapshot, content.queue_words, panel);
        if (layout_.queue_panel == static_cast<int>(index) && !intro_)
            add_queue_strip(snapshot, content.queue_words, layout_.queue_strip);
    }
    // The marks the presentation layer chose (show::FailureMarks), each kind its own shape;
    // during a replay, the replay's own marks instead.
    if (!panel.zoomed) paint_failure_marks(list_, content.marks, panel, snapshot.box, mark_style());
    // The next collision line, where the queue's picture does not draw the next events already.
    if (!panel.zoomed && !snapshot.queue)
        add_next_collision(content.next_collision, snapshot.discs, panel, snapshot.box);
    if (!content.replay.empty()) add_replay(content.replay, panel, snapshot.box);
}

void LessonPainter::add_mark_legend(std::size_t index, const PanelContent& content) {
    const TextSlot* slot = layout_.slot(TextRole::marks, static_cast<int>(index));
    if (slot == nullptr) return;
    // "and 55 more not drawn" counts this panel's failures: never under another panel's box,
    // where it would read as that panel's (left out where it does not fit whole before it: the
    // figures row counts every failure).
    float own_x1 = slot->rect.x1;
    for (std::size_t i = 0; i < layout_.panels.size(); ++i) {
        const RectF& box = layout_.panels[i].box;
        if (i != index && box.x0 > slot->rect.x0)
            own_x1 = std::min(own_x1, box.x0 - layout_.margin);
    }
    float x = Painter::add_mark_legend(*slot, content.mark_words, slot->rect.x0, own_x1);
    // The queue's lines in the box ("Next 4 collisions, time to go": the lines in the box).
    const std::string& queue_legend = content.queue_words.legend;
    if (content.snapshot->queue && !queue_legend.empty() &&
        x + body_font_->text_width(queue_legend) <= slot->rect.x1)
        (void)draw_text(Font::body, *slot, queue_legend, palette_.muted, Align::left, x);
}

void LessonPainter::finish_frame(const FrameContent& frame) {
    if (layout_.compact && !intro_) {
        // The compact form (a thumbnail) has no card and no caption: its top line names the
        // scene, by its short title where the whole one is wider than the frame.
        const TextSlot* slot = layout_.slot(TextRole::title, -1);
        if (slot != nullptr && !frame.intro_title.empty()) {
            draw_text(Font::body, *slot, short_title(*body_font_, frame.intro_title, slot->rect),
                      palette_.title, Align::left);
        }
    }
    if (!layout_.compact && !intro_) add_column(frame);
    if (frame.code && !intro_ && layout_.code.width() > 0.0F) add_code(*frame.code);
    add_frame_numbers();  // clear of every text drawn above
    if (shows_title_card(frame)) add_intro(frame);
    if (shows_summary(frame)) add_summary(frame);
}

void LessonPainter::add_panel_text(std::size_t index, const PanelContent& content,
                                   const PanelLayout& /*panel*/) {
    if (intro_) return;  // the title card covers the frame
    const int p = static_cast<int>(index);
    const Rgba8 accent = with_alpha(Painter::accent(content), 255);
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
        const float x = slot->rect.x0 + 1.6F * sw;
        const bool long_title = !content.short_title.empty() &&
                                body_font_->text_width(content.title) > slot->rect.x1 - x;
        draw_text(Font::body, *slot, long_title ? content.short_title : content.title,
                  palette_.title, Align::left, x);
    }
    const TextSlot* how = layout_.slot(TextRole::how, p);
    std::optional<float> how_taken;
    if (const TextSlot* slot = layout_.slot(TextRole::figures, p)) {
        how_taken = add_figures(content.figures, *slot, how);
    }
    if (how != nullptr && !content.how.empty()) {
        if (!how_taken) {
            draw_text(Font::body, *how, content.how, palette_.text);
        } else {
            // Failures that continued on the how line come first; the why follows them when it
            // fits whole (brownian: "44 left the box   Each step: all N²/2 pairs").
            const float x = *how_taken + std::round(0.6F * body_font_->pixel_height());
            if (x + body_font_->text_width(content.how) <= how->rect.x1)
                draw_text(Font::body, *how, content.how, palette_.text, Align::left, x);
        }
    }
    if (const TextSlot* slot = layout_.slot(TextRole::note, p); slot && !content.note.empty()) {
        float right = slot->rect.x1;
        // Where the note and its indicator end: a crowded box's numbers may take the rest of
        // its row (frame_obstacles).
        float ink_end = slot->rect.x0 + body_font_->text_width(content.note);
        if (content.step_period > 1 && content.step_period <= 16) {
            // The step indicator: one square per frame of a step, the current one filled.
            const float s = std::round(0.45F * body_font_->pixel_height());
            const float cy = 0.5F * (slot->rect.y0 + slot->rect.y1);
            const auto n = static_cast<float>(content.step_period);
            // Right after the note, which it illustrates (the right panel's line may share the
            // row: two lines of note, marks and how at most, layout.hpp).
            const float after_note = slot->rect.x0 + body_font_->text_width(content.note) + s;
            float x = std::min(after_note + s, slot->rect.x1 - n * 1.5F * s);
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
            ink_end = x;
        }
        notes_.push_back(
            {slot->rect.x0, slot->rect.y0, std::min(ink_end, slot->rect.x1), slot->rect.y1});
        TextSlot shortened = *slot;
        shortened.rect.x1 = right;
        draw_text(Font::body, shortened, content.note, palette_.text);
    }
    add_mark_legend(index, content);  // under the figures, outside the box
}

namespace {
/// The figures to show: all that fit `room` in order; failures are never dropped (item 2 of issue
/// #28), the others go first, least important (last) first.
std::vector<const Figure*> figures_within(const std::vector<Figure>& figures, float room,
                                          const std::function<float(const Figure&)>& width) {
    std::vector<const Figure*> kept;
    for (const Figure& f : figures) kept.push_back(&f);
    const auto total = [&] {
        float sum = 0.0F;
        for (const Figure* f : kept) sum += width(*f);
        return sum;
    };
    while (total() > room) {
        const auto other =
            std::find_if(kept.rbegin(), kept.rend(), [](const Figure* f) { return !f->failure; });
        if (other == kept.rend()) break;
        kept.erase(std::next(other).base());
    }
    return kept;
}
}  // namespace

std::optional<float> LessonPainter::add_figures(const std::vector<Figure>& figures,
                                                const TextSlot& slot, const TextSlot* overflow) {
    // Headline values while every failure fits the row that way; else body-sized values, and
    // failures that still do not fit continue on the how line (`overflow`), which they take.
    const float gap = head_font_->pixel_height();
    const auto width_in = [&](const FontAtlas& value_font) {
        return [&value_font, this, gap](const Figure& f) {
            return value_font.text_width(f.value) + body_font_->text_width(" " + f.label) + gap;
        };
    };
    const float room = slot.rect.width() + gap;  // no gap after the last figure
    std::vector<const Figure*> shown = figures_within(figures, room, width_in(*head_font_));
    Font value_font = Font::head;
    const auto fits = [&](const std::vector<const Figure*>& list, const FontAtlas& font) {
        float sum = 0.0F;
        for (const Figure* f : list) sum += width_in(font)(*f);
        return sum <= room;
    };
    if (!fits(shown, *head_font_)) {
        value_font = Font::body;
        shown = figures_within(figures, room, width_in(*body_font_));
    }
    if (overflow == nullptr) {
        // No line to continue on (the left panel beside a note and a legend): a failure that
        // did not happen ("0 overlapping") gives its place to one that did ("12 tunnelled").
        while (!fits(shown, atlas(value_font))) {
            const auto zero = std::find_if(shown.rbegin(), shown.rend(), [](const Figure* f) {
                return f->failure && f->value == "0";
            });
            if (zero == shown.rend()) break;
            shown.erase(std::next(zero).base());
        }
    }
    bool overflowed = false;
    float x = slot.rect.x0;
    const TextSlot* row = &slot;
    for (const Figure* figure : shown) {
        const FontAtlas& vf = atlas(value_font);
        const float need = width_in(vf)(*figure) - gap;
        if (x + need > row->rect.x1) {
            if (row != &slot || overflow == nullptr) break;  // no room left anywhere
            row = overflow;  // the next line: failures are never dropped
            x = row->rect.x0;
            overflowed = true;
        }
        const bool alarm = figure->failure && figure->value != "0";
        x = draw_text(value_font, *row, figure->value, alarm ? palette_.failure : palette_.title,
                      Align::left, x);
        // Body text on the value's baseline.
        const float baseline =
            row->rect.y0 + 0.5F * (row->rect.height() - vf.pixel_height()) + vf.ascent();
        const std::string label = " " + figure->label;
        x = body_font_->add_text(list_.text[0].glyphs, x, baseline, label, palette_.text);
        record_text(*row, label, true);
        x += gap;
    }
    if (!overflowed) return std::nullopt;
    return x - gap;
}

}  // namespace collide::render
