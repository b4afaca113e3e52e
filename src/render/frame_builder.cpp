// The frame builder: layout, discs, failure markers, trails, text, cost graphic and plots as a
// DrawList (the GL target draws it). Everything here is plain CPU arithmetic.
#include "frame_builder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

#include "collide/assert.hpp"
#include "collide/error.hpp"
#include "plots.hpp"

namespace collide::render {

namespace {

constexpr Rgb8 tagged_color{250, 160, 40};
constexpr Rgb8 untagged_color{120, 122, 135};
constexpr Rgba8 overlap_halo_color{240, 45, 45, 255};  // full level (today's look)
constexpr Rgba8 missed_flash_color{255, 235, 110, 235};
constexpr Rgba8 escaped_ring_color{255, 70, 70, 255};

std::string join(const std::vector<std::string>& parts, const char* separator) {
    std::string out;
    for (const std::string& part : parts) {
        if (!out.empty()) out += separator;
        out += part;
    }
    return out;
}

}  // namespace

CaptionFit fit_caption(const RenderConfig& config, std::string_view caption) {
    if (config.overlays != OverlayLevel::lesson || config.width < compact_width) return {};
    LayoutInput input;
    input.width = config.width;
    input.height = config.height;
    input.boxes = {Box{}};  // the caption line spans the frame whatever the panels
    const FrameLayout layout = compute_layout(input);
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

namespace {
/// The panels' accents, in panel order: the colours of their plot series.
std::vector<Rgb8> accents(const FrameContent& frame) {
    std::vector<Rgb8> out;
    out.reserve(frame.panels.size());
    for (const PanelContent& panel : frame.panels) out.push_back(panel.accent);
    return out;
}
}  // namespace

// ---------------------------------------------------------------------------------------------
// Markers

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

// ---------------------------------------------------------------------------------------------
// Builder

FrameBuilder::FrameBuilder(const RenderConfig& config)
    : config_(config), palette_(palette(config.theme)) {
    config_.validate();
    switch (config_.overlays) {
        case OverlayLevel::none:
            break;
        case OverlayLevel::full:
            body_font_.emplace(config_.font_path, font_pixel_height(config_.height));
            break;
        case OverlayLevel::lesson: {
            const float body = lesson_pixel_height(config_.width, config_.height);
            body_font_.emplace(config_.font_path, body);
            if (config_.width >= compact_width) {
                head_font_.emplace(config_.font_path, std::round(body * headline_scale));
            }
            break;
        }
    }
    list_.background = palette_.background;
    list_.fill_color = palette_.box_fill;
    choose_colormap_range();
    if (body_font_) list_.text.push_back({&*body_font_, {}});
    if (head_font_) list_.text.push_back({&*head_font_, {}});
}

const FontAtlas& FrameBuilder::atlas(Font font) const {
    if (font == Font::head && head_font_) return *head_font_;
    if (font == Font::small && small_font_) return *small_font_;
    return *body_font_;
}

FrameLayout FrameBuilder::layout_for(const FrameContent& frame) const {
    LayoutInput input;
    input.width = config_.width;
    input.height = config_.height;
    input.level = config_.overlays;
    for (const PanelContent& panel : frame.panels) {
        input.boxes.push_back(panel.snapshot != nullptr ? panel.snapshot->box : Box{});
        if (!panel.note.empty()) input.note_line = true;
        input.mark_lines.push_back(panel.mark_line);
    }
    input.large_plot = frame.histogram == PlotSize::large;
    input.small_plot = frame.histogram == PlotSize::small;
    // Speed colours beside a speed plot: the plot's axis is the colour bar (speed_axis_colors).
    input.color_legend =
        config_.color_mode == ColorMode::mass ||
        (config_.color_mode == ColorMode::speed &&
         (frame.histogram == PlotSize::none || config_.overlays != OverlayLevel::lesson));
    input.counter_rows = config_.overlays == OverlayLevel::full ? counter_rows(frame) : 0;
    for (std::size_t i = 0; i < frame.panels.size(); ++i) {
        const Snapshot* snapshot = frame.panels[i].snapshot;
        if (snapshot != nullptr && snapshot->queue && input.queue_panel < 0)
            input.queue_panel = static_cast<int>(i);
    }
    return compute_layout(input);
}

const DrawList& FrameBuilder::build(const FrameContent& frame) {
    COLLIDE_ASSERT(!frame.panels.empty() && frame.panels.size() <= 2, "a frame has 1 or 2 panels");
    for (const PanelContent& panel : frame.panels) {
        COLLIDE_ASSERT(panel.snapshot != nullptr, "every panel has a snapshot");
    }
    list_.clear();
    video_time_ = frame.video_time;
    speed_ = frame.speed;
    intro_ = config_.overlays == OverlayLevel::lesson && frame.intro_opacity > 0.0F &&
             !frame.intro_title.empty();
    counter_rows_ = config_.overlays == OverlayLevel::full ? counter_rows(frame) : 0;
    layout_ = layout_for(frame);
    if (layout_.queue_panel >= 0 && !small_font_) {
        // Loaded with the first frame that shows a queue, so other videos are unchanged.
        small_font_.emplace(config_.font_path,
                            std::round(body_font_->pixel_height() * queue_text_scale));
        list_.text.push_back({&*small_font_, {}});
    }
    if (trails_.size() != frame.panels.size()) {
        trails_.assign(frame.panels.size(),
                       TrailHistory(config_.trail_length, config_.trail_whole_path));
        markers_.assign(frame.panels.size(), MarkerMemory{});
    }
    for (std::size_t i = 0; i < frame.panels.size(); ++i) {
        build_panel(i, frame.panels[i], layout_.panels[i]);
    }
    if (config_.overlays == OverlayLevel::full) add_full_strip(frame);
    if (config_.overlays == OverlayLevel::lesson && !layout_.compact && !intro_) add_column(frame);
    if (intro_) add_intro(frame);
    return list_;
}

void FrameBuilder::build_panel(std::size_t index, const PanelContent& content,
                               const PanelLayout& panel) {
    const Snapshot& snapshot = *content.snapshot;
    const Box& box = snapshot.box;
    const float text_px = body_font_ ? body_font_->pixel_height() : 0.0F;
    const float wall = std::max(
        1.0F, std::round(text_px / (config_.overlays == OverlayLevel::lesson ? 12.0F : 10.0F)));
    add_box(panel, box, wall);

    colors_.resize(snapshot.discs.size());
    for (std::size_t k = 0; k < snapshot.discs.size(); ++k) {
        colors_[k] = disc_color(snapshot.discs[k]);
    }
    if (config_.trails) {
        trails_[index].update(snapshot);
        const auto to_pixels = [&](Vec2 p) { return panel.to_pixels(p, box); };
        const float width = config_.overlays == OverlayLevel::lesson
                                ? std::max(2.0F, std::round(text_px / 8.0F))
                                : std::max(1.0F, wall * 1.5F);
        const bool lesson = config_.overlays == OverlayLevel::lesson;
        if (lesson) {  // every trail keeps 3:1 against the box down to its faintest segment
            const float share =
                legible_trails(colors_, snapshot.discs, config_.theme, trail_colors_);
            trails_[index].draw(list_.under, box, to_pixels, trail_colors_, width, share);
        } else {
            trails_[index].draw(list_.under, box, to_pixels, colors_, width, 0.0F);
        }
    }
    add_discs(snapshot, panel);
    if (snapshot.queue && config_.overlays == OverlayLevel::lesson && body_font_) {
        add_queue_in_box(snapshot, panel);
        if (layout_.queue_panel == static_cast<int>(index) && !intro_)
            add_queue_strip(snapshot, content.queue_words, layout_.queue_strip);
    }
    if (config_.overlays == OverlayLevel::lesson) {
        add_lesson_marks(content, panel);  // chosen by the presentation layer
    } else {
        add_classic_failures(snapshot, panel, wall);
    }
    // Lesson: everything of a panel stays inside its box (nothing reaches the text). Today's
    // levels: periodic images stop at the seam, escaped discs show outside a walled box.
    const bool clip_to_box =
        config_.overlays == OverlayLevel::lesson || box.boundary == Boundary::periodic;
    list_.disc_groups.push_back({list_.discs.size(), clip_to_box ? panel.box : panel.area});
    if (config_.overlays == OverlayLevel::full) {
        add_full_header(content, panel, layout_.panels.size());
    } else if (config_.overlays == OverlayLevel::lesson && !intro_) {
        add_lesson_panel_text(index, content);
        add_mark_legend(index, content);  // under the figures, outside the box
    }
}

void FrameBuilder::add_box(const PanelLayout& panel, const Box& box, float wall) {
    add_box_fill(panel.box);
    const RectF outline{panel.box.x0 - wall, panel.box.y0 - wall, panel.box.x1 + wall,
                        panel.box.y1 + wall};
    if (box.boundary == Boundary::periodic && config_.overlays == OverlayLevel::lesson) {
        // Dashed: the edges are no walls, discs pass through and come back on the other side.
        add_dashed_frame(list_.under, outline, wall, edge_dash(wall), palette_.wrap_edge);
        return;
    }
    list_.under.add_frame(outline, wall,
                          box.boundary == Boundary::walls ? palette_.wall : palette_.periodic_edge);
}

// The opaque box background, as if drawn with under.add_rect(box, fill). Shading ~0.7 Mpx of
// blended quad cost llvmpipe ~1.8 ms CPU per 720p frame; clearing the interior is a memory fill
// (GlTarget::clear_background). A quad covers the pixels whose centres lie inside it: every
// pixel of the integer interior [ceil x0, floor x1) x [ceil y0, floor y1) is at least half a
// pixel inside, so the clear paints the same pixels there; the strips outside the interior keep
// the quad's own (possibly fractional) outer edges, so the rasteriser decides those pixels.
void FrameBuilder::add_box_fill(RectF box) {
    const RectF inner{std::ceil(box.x0), std::ceil(box.y0), std::floor(box.x1), std::floor(box.y1)};
    if (!(inner.x0 < inner.x1 && inner.y0 < inner.y1)) {
        list_.under.add_rect(box, palette_.box_fill);
        return;
    }
    list_.fill_clears.push_back(inner);
    const auto strip = [&](RectF r) {
        if (r.x0 < r.x1 && r.y0 < r.y1) list_.under.add_rect(r, palette_.box_fill);
    };
    strip({box.x0, box.y0, inner.x0, box.y1});      // left, full height
    strip({inner.x1, box.y0, box.x1, box.y1});      // right, full height
    strip({inner.x0, box.y0, inner.x1, inner.y0});  // top, between the two
    strip({inner.x0, inner.y1, inner.x1, box.y1});  // bottom, between the two
}

Rgb8 FrameBuilder::disc_color(const DiscState& disc) const noexcept {
    switch (config_.color_mode) {
        case ColorMode::scene:
            return away_from_failure_color(disc.color);
        case ColorMode::speed:
            return shown_colormap((norm(disc.velocity) - config_.speed_min) /
                                  (config_.speed_max - config_.speed_min));
        case ColorMode::mass: {
            if (!(config_.mass_max > config_.mass_min)) return shown_colormap(0.5);
            return shown_colormap(std::log(disc.mass / config_.mass_min) /
                                  std::log(config_.mass_max / config_.mass_min));
        }
        case ColorMode::tag:
            return disc.tagged ? tagged_color : untagged_color;
    }
    return disc.color;
}

Rgb8 FrameBuilder::shown_colormap(double t) const noexcept {
    if (!(t > 0.0)) t = 0.0;
    if (t > 1.0) t = 1.0;
    return colormap(colormap_low_ + (colormap_high_ - colormap_low_) * t);
}

// The part of the colormap every colour of which keeps 3:1 contrast with the box (lesson level):
// on the dark theme its darkest violet is cut, on the light theme its palest yellow, so discs
// need no outline and the colour bar shows what the discs show.
void FrameBuilder::choose_colormap_range() {
    if (config_.overlays != OverlayLevel::lesson) return;
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

void FrameBuilder::add_discs(const Snapshot& snapshot, const PanelLayout& panel) {
    const Box& box = snapshot.box;
    const bool periodic = box.boundary == Boundary::periodic;
    const bool lesson = config_.overlays == OverlayLevel::lesson;
    const Rgb8 fill = rgb(palette_.box_fill);
    // Outlines only where a colour is too close to the box (contrast is checked once per colour
    // run: scenes have a handful of colours, colormaps change slowly).
    // Colormap colours are all clear of the box already (choose_colormap_range) unless no part of
    // the map was: then, and for scene and tag colours, each colour is checked.
    const bool mapped =
        config_.color_mode == ColorMode::speed || config_.color_mode == ColorMode::mass;
    const bool check = lesson && !(mapped && colormap_clear_);
    Rgb8 last_color{0, 0, 0};
    bool last_needs_outline = check && contrast_ratio(last_color, fill) < min_disc_contrast;
    for (std::size_t k = 0; k < snapshot.discs.size(); ++k) {
        const DiscState& disc = snapshot.discs[k];
        if (lesson && disc.escaped) continue;  // counted and marked at the box edge instead
        const Rgb8 c = colors_[k];
        if (check && (c.r != last_color.r || c.g != last_color.g || c.b != last_color.b)) {
            last_color = c;
            last_needs_outline = contrast_ratio(c, fill) < min_disc_contrast;
        }
        const Rgba8 color = with_alpha(c, 255);
        const auto radius = static_cast<float>(disc.radius * panel.scale);
        Vec2 position = disc.position;
        if (disc.escaped) {
            const double slack_x = (panel.box.x0 - panel.area.x0) / panel.scale - disc.radius;
            const double slack_y = (panel.box.y0 - panel.area.y0) / panel.scale - disc.radius;
            position.x =
                std::clamp(position.x, -std::max(0.0, slack_x), box.width + std::max(0.0, slack_x));
            position.y = std::clamp(position.y, -std::max(0.0, slack_y),
                                    box.height + std::max(0.0, slack_y));
        }
        const PointF p = panel.to_pixels(position, box);
        list_.discs.push_back({p.x, p.y, radius, 0.0F, color});
        if (periodic) add_periodic_images(disc, panel, box, color, 0.0F);
        if (lesson && last_needs_outline && radius >= 2.0F) {
            const float ring = std::max(1.0F, std::min(2.0F, radius * 0.2F));
            list_.discs.push_back({p.x, p.y, radius, ring, palette_.outline});
            if (periodic) add_periodic_images(disc, panel, box, palette_.outline, ring);
        }
        if (!lesson && disc.escaped) {
            list_.discs.push_back(
                {p.x, p.y, radius + 3.0F, std::max(1.5F, radius * 0.25F), escaped_ring_color});
        }
    }
}

// A disc straddling an edge of a periodic box shows on both sides (scissored to the box).
void FrameBuilder::add_periodic_images(const DiscState& disc, const PanelLayout& panel,
                                       const Box& box, Rgba8 color, float style) {
    const double r = disc.radius;
    const Vec2 p = disc.position;
    const int sx = p.x - r < 0.0 ? 1 : (p.x + r > box.width ? -1 : 0);
    const int sy = p.y - r < 0.0 ? 1 : (p.y + r > box.height ? -1 : 0);
    const auto radius = static_cast<float>(r * panel.scale);
    const auto add = [&](int ix, int iy) {
        const PointF c = panel.to_pixels({p.x + ix * box.width, p.y + iy * box.height}, box);
        list_.discs.push_back({c.x, c.y, radius, style, color});
    };
    if (sx != 0) add(sx, 0);
    if (sy != 0) add(0, sy);
    if (sx != 0 && sy != 0) add(sx, sy);
}

void FrameBuilder::add_classic_failures(const Snapshot& snapshot, const PanelLayout& panel,
                                        float wall) {
    const Box& box = snapshot.box;
    const float ring = std::max(1.5F, wall * 1.5F);
    for (const auto& [a, b] : snapshot.overlapping_pairs) {
        for (const std::uint32_t index : {a, b}) {
            if (index >= snapshot.discs.size()) continue;  // defensive: bad marker data
            const DiscState& disc = snapshot.discs[index];
            const PointF c = panel.to_pixels(disc.position, box);
            const auto radius = static_cast<float>(disc.radius * panel.scale);
            list_.discs.push_back({c.x, c.y, radius + 2.0F * ring, ring, overlap_halo_color});
        }
    }
    if (!snapshot.missed_collisions.empty()) {
        double mean_radius = 0.0;
        for (const DiscState& d : snapshot.discs) mean_radius += d.radius;
        mean_radius /= static_cast<double>(std::max<std::size_t>(snapshot.discs.size(), 1));
        const float flash = std::max(8.0F, static_cast<float>(3.0 * mean_radius * panel.scale));
        for (const Vec2 where : snapshot.missed_collisions) {
            const PointF c = panel.to_pixels(where, box);
            list_.discs.push_back({c.x, c.y, flash, -1.0F, missed_flash_color});
        }
    }
}

// Lesson failures in the reserved colour, newest first, at most max_markers: overlapping pairs
// (a ring around the pair's midpoint), missed collisions (a ring that fades over a second of
// video) and escaped discs (a ring where they crossed the edge). Returns how many were not drawn.
std::size_t FrameBuilder::add_lesson_failures(std::size_t index, const Snapshot& snapshot,
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
void FrameBuilder::add_unmarked_note(const PanelLayout& panel, std::size_t hidden) {
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

// ---------------------------------------------------------------------------------------------
// Text

float FrameBuilder::draw_text(Font font, const TextSlot& slot, std::string_view text, Rgba8 color,
                              Align align, float x) {
    const FontAtlas& f = atlas(font);
    std::string shown(text);
    const float room = slot.rect.x1 - (x >= 0.0F ? x : slot.rect.x0);
    if (f.text_width(shown) > room) {  // never spill out of the slot: cut with an ellipsis
        while (!shown.empty() && f.text_width(shown + "...") > room) shown.pop_back();
        shown = shown.empty() ? std::string() : shown + "...";
    }
    const float width = f.text_width(shown);
    float left = x >= 0.0F ? x : slot.rect.x0;
    if (align == Align::centre) left = slot.rect.x0 + 0.5F * (slot.rect.width() - width);
    if (align == Align::right) left = slot.rect.x1 - width;
    // Baseline: text of this size centred in the slot (ascent above, the rest below).
    const float baseline =
        slot.rect.y0 + 0.5F * (slot.rect.height() - f.pixel_height()) + f.ascent();
    auto run = std::find_if(list_.text.begin(), list_.text.end(),
                            [&](const TextRun& r) { return r.font == &f; });
    return f.add_text(run->glyphs, left, baseline, shown, color);
}

void FrameBuilder::add_lesson_panel_text(std::size_t index, const PanelContent& content) {
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
}

void FrameBuilder::add_column(const FrameContent& frame) {
    if (const TextSlot* slot = layout_.slot(TextRole::clock)) {
        draw_text(Font::body, *slot, frame.time_text, palette_.title);
    }
    if (const TextSlot* slot = layout_.slot(TextRole::caption); slot && !frame.caption.empty()) {
        draw_text(Font::body, *slot, frame.caption, palette_.title, Align::centre);
    }
    // The cost graphic: one bar per engine on one scale, so N^2 against log N is seen.
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
                  with_alpha(accent_text(panel.accent, config_.theme), 255));
        const RectF track{label->rect.x0, label->rect.y1, label->rect.x1,
                          value->rect.y0 - std::round(0.6F * layout_.margin)};
        list_.over.add_rect(track, faded(palette_.muted, 0.35F));
        if (most > 0.0 && panel.cost > 0.0) {
            const float w = std::max(2.0F, static_cast<float>(panel.cost / most) * track.width());
            list_.over.add_rect({track.x0, track.y0, track.x0 + w, track.y1},
                                with_alpha(panel.accent, 255));
        }
        const auto count = static_cast<long long>(std::llround(std::min(panel.cost, 9.0e18)));
        std::string shown = with_separators(count);
        const Font value_font =
            value->pixel_height >= head_font_->pixel_height() ? Font::head : Font::body;
        if (atlas(value_font).text_width(shown) > value->rect.width()) {
            // Too many digits for the column: in words, in the body font.
            char words[48];
            const double c = panel.cost;
            std::snprintf(words, sizeof words, c >= 1e9 ? "%.3g billion" : "%.3g million",
                          c >= 1e9 ? c / 1e9 : c / 1e6);
            draw_text(Font::body, *value, words, palette_.title);
        } else {
            draw_text(value_font, *value, shown, palette_.title);
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
        // What the disc colours mean: the colormap from slow (light) to fast (heavy).
        const RectF bar = layout_.column.legend_bar;
        constexpr int segments = 32;
        for (int s = 0; s < segments; ++s) {
            const float x0 = bar.x0 + bar.width() * static_cast<float>(s) / segments;
            const float x1 = bar.x0 + bar.width() * static_cast<float>(s + 1) / segments;
            list_.over.add_rect({x0, bar.y0, x1 + 0.5F, bar.y1},
                                with_alpha(shown_colormap((s + 0.5) / segments), 255));
        }
        const bool speed = config_.color_mode == ColorMode::speed;
        draw_text(Font::body, *slot, speed ? "slow" : "light", palette_.text);
        draw_text(Font::body, *slot, speed ? "fast" : "heavy", palette_.text, Align::right);
    }
    const RectF plot = layout_.column.plot;
    if (plot.width() <= 0.0F || plot.height() <= 0.0F) return;
    if (frame.histogram != PlotSize::none) {
        std::vector<const Snapshot*> snapshots;
        std::vector<Rgb8> colors;
        for (const PanelContent& panel : frame.panels) {
            snapshots.push_back(panel.snapshot);
            colors.push_back(panel.accent);
        }
        std::function<Rgb8(double)> axis_colors;
        if (config_.color_mode == ColorMode::speed) {
            axis_colors = [this](double t) { return shown_colormap(t); };
        }
        draw_moving_speed_plot(list_.over, list_.text[0].glyphs, *body_font_, plot, snapshots,
                               colors, config_.speed_min, config_.speed_max,
                               plot_colors(config_.theme), axis_colors);
    } else if (frame.energy_plot) {
        draw_drift_plot(list_.over, list_.text[0].glyphs, *body_font_, plot, frame.energy_drift,
                        accents(frame), plot_colors(config_.theme));
    }
}

void FrameBuilder::add_intro(const FrameContent& frame) {
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

// ---------------------------------------------------------------------------------------------
// Full level (today's expert layout)

Rgba8 FrameBuilder::counter_color() const noexcept {
    // The full level's dimmer counter grey on dark; the theme's text colour on light.
    return config_.theme == Theme::dark ? Rgba8{190, 190, 200, 255} : palette_.text;
}

int FrameBuilder::panel_counter_columns(std::size_t panels) const {
    const float panel_width =
        static_cast<float>(config_.width) / static_cast<float>(std::max<std::size_t>(panels, 1));
    return counter_columns(panel_width, body_font_ ? body_font_->pixel_height() : 1.0F);
}

/// Rows of the counter grid: enough for the panel with the most counters, but the header never
/// takes more than about 30% of the frame height (counters come most important first).
int FrameBuilder::counter_rows(const FrameContent& frame) const {
    const auto columns = static_cast<std::size_t>(panel_counter_columns(frame.panels.size()));
    std::size_t rows = 0;
    for (const PanelContent& panel : frame.panels) {
        rows = std::max(rows, (panel.counters.size() + columns - 1) / columns);
    }
    const float line = body_font_ ? body_font_->line_height() : 1.0F;
    const auto fit = static_cast<std::size_t>(
        std::max(0.0F, std::floor(0.30F * static_cast<float>(config_.height) / line) - 1.0F));
    return static_cast<int>(std::min(rows, fit));
}

void FrameBuilder::add_full_header(const PanelContent& content, const PanelLayout& panel,
                                   std::size_t panels) {
    const FontAtlas& font = *body_font_;
    OverlayBatch& text = list_.text[0].glyphs;
    const float baseline = panel.header.y0 + font.ascent();
    font.add_text(text, panel.header.x0, baseline, content.title, palette_.title);
    const int columns = panel_counter_columns(panels);
    const float column_width = (panel.header.x1 - panel.header.x0) / static_cast<float>(columns);
    const std::size_t shown =
        std::min(content.counters.size(),
                 static_cast<std::size_t>(columns) * static_cast<std::size_t>(counter_rows_));
    for (std::size_t k = 0; k < shown; ++k) {
        const auto column = static_cast<float>(k % static_cast<std::size_t>(columns));
        const auto row = static_cast<float>(1 + k / static_cast<std::size_t>(columns));
        font.add_text(text, panel.header.x0 + column * column_width,
                      baseline + row * font.line_height(), content.counters[k], counter_color());
    }
}

void FrameBuilder::add_full_strip(const FrameContent& frame) {
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
    add_legend(info);
    std::vector<const Snapshot*> snapshots;
    for (const PanelContent& panel : frame.panels) snapshots.push_back(panel.snapshot);
    // Each panel's series in its engine's accent, whichever panels the frame has.
    const std::vector<Rgb8> series_colors = accents(frame);
    draw_speed_plot(list_.over, text, font, histogram, snapshots, series_colors, config_.speed_min,
                    config_.speed_max, plot_colors(config_.theme));
    draw_drift_plot(list_.over, text, font, drift, frame.energy_drift, series_colors,
                    plot_colors(config_.theme));
    const float notes_baseline = strip.y1 - m * 0.5F - line + font.ascent();
    font.add_text(text, columns.x0, notes_baseline, join(frame.notes, "   \xC2\xB7   "),
                  counter_color());
}

// Colour bar with its fixed range (speed or mass modes) or the tag key.
void FrameBuilder::add_legend(RectF info) {
    const FontAtlas& font = *body_font_;
    OverlayBatch& text = list_.text[0].glyphs;
    const Rgba8 counter = counter_color();
    const float line = font.line_height();
    float y = info.y0 + line * 1.3F;
    if (config_.color_mode == ColorMode::speed || config_.color_mode == ColorMode::mass) {
        const bool speed = config_.color_mode == ColorMode::speed;
        const double low = speed ? config_.speed_min : config_.mass_min;
        const double high = speed ? config_.speed_max : config_.mass_max;
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
        char low_text[32];
        char high_text[32];
        std::snprintf(low_text, sizeof low_text, "%.3g", low);
        std::snprintf(high_text, sizeof high_text, "%.3g", high);
        font.add_text(text, info.x0, y, low_text, counter);
        const std::string caption = speed ? "speed" : "mass (log)";
        font.add_text(text, info.x0 + 0.5F * (bar_width - font.text_width(caption)), y, caption,
                      counter);
        font.add_text(text, info.x1 - font.text_width(high_text), y, high_text, counter);
    } else if (config_.color_mode == ColorMode::tag) {
        const float size = std::round(line * 0.6F);
        list_.over.add_rect({info.x0, y, info.x0 + size, y + size}, with_alpha(tagged_color, 255));
        font.add_text(text, info.x0 + size * 1.5F, y + size, "tagged", counter);
    }
}

}  // namespace collide::render
