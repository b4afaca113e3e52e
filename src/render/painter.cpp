// What every painter shares: the phases of a frame, fonts and text, the box, disc colours and
// discs. Everything here is plain CPU arithmetic.
#include "painter.hpp"

#include <algorithm>
#include <cmath>

#include "collide/assert.hpp"
#include "failure_marks.hpp"

namespace collide::render {

namespace {

/// A segment from a to b drawn as dashes about `dash` long, a dash at both ends.
void add_dashed_segment(OverlayBatch& batch, PointF a, PointF b, float width, float dash,
                        Rgba8 color) {
    const float length = std::hypot(b.x - a.x, b.y - a.y);
    if (!(length > 0.0F) || !(dash > 0.0F)) return;
    int pieces = std::max(1, static_cast<int>(std::lround(length / dash)));
    if (pieces % 2 == 0) ++pieces;
    const auto at = [&](int k) {
        const float t = static_cast<float>(k) / static_cast<float>(pieces);
        return PointF{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    };
    for (int k = 0; k < pieces; k += 2) batch.add_line(at(k), at(k + 1), width, color);
}

}  // namespace

Painter::Painter(const RenderConfig& config) : config_(config), palette_(palette(config.theme)) {
    config_.validate();
    list_.background = palette_.background;
    list_.fill_color = palette_.box_fill;
}

void Painter::load_font(std::optional<FontAtlas>& slot, float pixel_height) {
    slot.emplace(config_.font_path, pixel_height);
    list_.text.push_back({&*slot, {}});
}

const FontAtlas& Painter::atlas(Font font) const {
    if (font == Font::head && head_font_) return *head_font_;
    if (font == Font::small && small_font_) return *small_font_;
    return *body_font_;
}

float Painter::body_pixel_height() const noexcept {
    return body_font_ ? body_font_->pixel_height() : 0.0F;
}

std::vector<Box> Painter::panel_boxes(const FrameContent& frame) {
    std::vector<Box> boxes;
    for (const PanelContent& panel : frame.panels) {
        boxes.push_back(panel.snapshot != nullptr ? panel.snapshot->box : Box{});
    }
    return boxes;
}

Rgb8 Painter::accent(const PanelContent& panel) const noexcept {
    return panel_accent(panel.time_driven, config_.theme);
}

std::vector<Rgb8> Painter::accents(const FrameContent& frame) const {
    std::vector<Rgb8> out;
    out.reserve(frame.panels.size());
    for (const PanelContent& panel : frame.panels) out.push_back(accent(panel));
    return out;
}

// ---------------------------------------------------------------------------------------------
// The phases of a frame

const DrawList& Painter::build(const FrameContent& frame) {
    COLLIDE_ASSERT(!frame.panels.empty() && frame.panels.size() <= max_frame_panels,
                   "a frame has 1 to max_frame_panels panels");
    for (const PanelContent& panel : frame.panels) {
        COLLIDE_ASSERT(panel.snapshot != nullptr, "every panel has a snapshot");
    }
    list_.clear();
    layout_ = layout_for(frame);
    drawn_.in_slots.assign(layout_.text.size(), {});
    drawn_.elsewhere.clear();
    drawn_.ink.clear();
    begin_frame(frame);
    if (trails_.size() != frame.panels.size()) {
        trails_.assign(frame.panels.size(),
                       TrailHistory(config_.trail_length, config_.trail_whole_path));
    }
    for (std::size_t i = 0; i < frame.panels.size(); ++i) {
        // A replay's zoom: the same rectangle shows a part of the box, enlarged.
        const PanelContent& panel = frame.panels[i];
        if (panel.zoom.active())
            layout_.panels[i].zoom_into(panel.zoom.centre, panel.zoom.magnification,
                                        panel.snapshot->box);
        paint_panel(i, panel, layout_.panels[i]);
    }
    finish_frame(frame);
    return list_;
}

void Painter::paint_panel(std::size_t index, const PanelContent& content,
                          const PanelLayout& panel) {
    const Snapshot& snapshot = *content.snapshot;
    const Box& box = snapshot.box;
    if (content.spheres != nullptr) {  // a 3D panel: the snapshot's box is the screen box
        add_box_fill(panel.box);
        add_spheres(*content.spheres, panel, box);
        add_marks(index, content, panel);
        list_.disc_groups.push_back({list_.discs.size(), panel.box});
        add_panel_text(index, content, panel);
        return;
    }
    add_box(panel, box);
    colors_.resize(snapshot.discs.size());
    for (std::size_t k = 0; k < snapshot.discs.size(); ++k) {
        colors_[k] = disc_color(snapshot.discs[k]);
    }
    // Trails are triangles under the discs, not clipped: a zoomed box leaves them out.
    if (config_.trails && !panel.zoomed) {
        trails_[index].update(snapshot);
        const auto to_pixels = [&](Vec2 p) { return panel.to_pixels(p, box); };
        if (style_.legible_trails) {  // every trail keeps 3:1 down to its faintest segment
            const float fade =
                legible_trails(colors_, snapshot.discs, config_.theme, trail_colors_);
            trails_[index].draw(list_.under, box, to_pixels, trail_colors_, style_.trail_width,
                                std::max(fade, style_.trail_fade));
        } else {
            trails_[index].draw(list_.under, box, to_pixels, colors_, style_.trail_width,
                                style_.trail_fade);
        }
    }
    add_discs(snapshot, panel, content.replay);
    add_marks(index, content, panel);
    const bool clip_to_box =
        style_.clip_to_box || box.boundary == Boundary::periodic || panel.zoomed;
    list_.disc_groups.push_back({list_.discs.size(), clip_to_box ? panel.box : panel.area});
    add_panel_text(index, content, panel);
}

// ---------------------------------------------------------------------------------------------
// The box

void Painter::add_box(const PanelLayout& panel, const Box& box) {
    add_box_fill(panel.box);
    const float wall = style_.wall;
    const RectF outline{panel.box.x0 - wall, panel.box.y0 - wall, panel.box.x1 + wall,
                        panel.box.y1 + wall};
    if (box.boundary == Boundary::periodic && style_.dashed_periodic_edges) {
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
void Painter::add_box_fill(RectF box) {
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

// ---------------------------------------------------------------------------------------------
// Discs

Rgb8 Painter::disc_color(const DiscState& disc) const noexcept {
    return particle_color(disc.color, norm(disc.velocity), disc.mass, disc.tagged);
}

Rgb8 Painter::particle_color(Rgb8 color, double speed, double mass, bool tagged) const noexcept {
    switch (config_.color_mode) {
        case ColorMode::scene:
            return away_from_failure_color(color);
        case ColorMode::speed:
            return shown_colormap((speed - config_.speed_min) /
                                  (config_.speed_max - config_.speed_min));
        case ColorMode::mass: {
            if (!(config_.mass_max > config_.mass_min)) return shown_colormap(0.5);
            return shown_colormap(std::log(mass / config_.mass_min) /
                                  std::log(config_.mass_max / config_.mass_min));
        }
        case ColorMode::tag:
            return tagged ? tagged_color : untagged_color;
    }
    return color;
}

Rgb8 Painter::shown_colormap(double t) const noexcept {
    if (!(t > 0.0)) t = 0.0;
    if (t > 1.0) t = 1.0;
    return colormap(colormap_low_ + (colormap_high_ - colormap_low_) * t);
}

void Painter::add_discs(const Snapshot& snapshot, const PanelLayout& panel,
                        const ReplayView& replay) {
    const auto listed = [](const std::vector<std::uint32_t>& list, std::size_t k) {
        return std::find(list.begin(), list.end(), k) != list.end();
    };
    const Box& box = snapshot.box;
    const bool periodic = box.boundary == Boundary::periodic;
    const Rgb8 fill = rgb(palette_.box_fill);
    // Outlines only where a colour is too close to the box (contrast is checked once per colour
    // run: scenes have a handful of colours, colormaps change slowly).
    // Colormap colours are all clear of the box already (LessonPainter::choose_colormap_range)
    // unless no part of the map was: then, and for scene and tag colours, each colour is checked.
    const bool mapped =
        config_.color_mode == ColorMode::speed || config_.color_mode == ColorMode::mass;
    const bool check = style_.outline_faint_discs && !(mapped && colormap_clear_);
    Rgb8 last_color{0, 0, 0};
    bool last_needs_outline = check && contrast_ratio(last_color, fill) < min_disc_contrast;
    for (std::size_t k = 0; k < snapshot.discs.size(); ++k) {
        const DiscState& disc = snapshot.discs[k];
        if (style_.escaped_as_marks && disc.escaped) continue;  // marked at the box edge instead
        if (!replay.hidden.empty() && listed(replay.hidden, k)) continue;  // a replay's ghost
        const Rgb8 c = colors_[k];
        if (check && (c.r != last_color.r || c.g != last_color.g || c.b != last_color.b)) {
            last_color = c;
            last_needs_outline = contrast_ratio(c, fill) < min_disc_contrast;
        }
        // A replay draws the eye to its discs: the others faint.
        const bool faint = !replay.focus.empty() && !listed(replay.focus, k);
        const Rgba8 color = with_alpha(c, faint ? 70 : 255);
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
        if (last_needs_outline && radius >= 2.0F) {
            const float ring = std::max(1.0F, std::min(2.0F, radius * 0.2F));
            list_.discs.push_back({p.x, p.y, radius, ring, palette_.outline});
            if (periodic) add_periodic_images(disc, panel, box, palette_.outline, ring);
        }
        if (disc.escaped) {
            list_.discs.push_back(
                {p.x, p.y, radius + 3.0F, std::max(1.5F, radius * 0.25F), escaped_ring_color});
        }
    }
}

// Spheres, as the camera (show::SphereCamera) placed them: the box's edges that lie behind them
// under, the ones in front over; the spheres far to near in their own group, lit in the shader.
void Painter::add_spheres(const SphereView& view, const PanelLayout& panel, const Box& screen) {
    const float edge_width = std::max(1.0F, style_.wall);
    Rgba8 front = palette_.wall;
    front.a = 150;  // over the spheres: present, but not hiding them
    // A periodic box's edges are no walls: dashed, as in 2D (the legend says "edges wrap").
    const bool dashed = screen.boundary == Boundary::periodic && style_.dashed_periodic_edges;
    const Rgba8 back = dashed ? palette_.wrap_edge : palette_.wall;
    if (dashed) front = Rgba8{back.r, back.g, back.b, 150};
    for (const BoxEdge& e : view.edges) {
        const PointF a = panel.to_pixels(e.from, screen);
        const PointF b = panel.to_pixels(e.to, screen);
        OverlayBatch& batch = e.front ? list_.over : list_.under;
        const Rgba8 color = e.front ? front : back;
        if (dashed) {
            add_dashed_segment(batch, a, b, edge_width, edge_dash(edge_width), color);
        } else {
            batch.add_line(a, b, edge_width, color);
        }
    }
    const auto scale = static_cast<float>(panel.scale);
    for (const SphereSprite& sphere : view.spheres) {
        const PointF p = panel.to_pixels(sphere.at, screen);
        const PointF foot = panel.to_pixels(sphere.plane_at, screen);
        const Rgb8 c = particle_color(sphere.color, sphere.speed, sphere.mass, sphere.tagged);
        list_.spheres.push_back({p.x, p.y, static_cast<float>(sphere.radius * panel.scale),
                                 static_cast<float>(sphere.depth),
                                 static_cast<float>(sphere.radius_depth), with_alpha(c, 255),
                                 foot.x, foot.y, static_cast<float>(sphere.height) * scale,
                                 static_cast<float>(sphere.ball_radius) * scale});
    }
    SphereLight light;
    light.x = static_cast<float>(view.light_x);
    light.y = static_cast<float>(view.light_y);
    light.z = static_cast<float>(view.light_z);
    light.ambient = static_cast<float>(view.ambient);
    light.depth_cue = static_cast<float>(view.depth_cue);
    light.cue_color = palette_.box_fill;
    if (view.eye_distance > 0.0) {
        const PointF eye = panel.to_pixels(view.eye_at, screen);
        light.eye_x = eye.x;
        light.eye_y = eye.y;
        light.eye_z = static_cast<float>(view.eye_distance) * scale;
    }
    list_.sphere_groups.push_back({list_.spheres.size(), panel.box, light});
}

// A disc straddling an edge of a periodic box shows on both sides (scissored to the box).
void Painter::add_periodic_images(const DiscState& disc, const PanelLayout& panel, const Box& box,
                                  Rgba8 color, float style) {
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

// ---------------------------------------------------------------------------------------------
// Text

void Painter::record_text(const TextSlot& slot, std::string_view text, bool continues) {
    if (text.empty()) return;
    std::vector<TextSlot>& slots = layout_.text;
    std::size_t at = slots.size();
    if (!slots.empty() && &slot >= slots.data() && &slot < slots.data() + slots.size()) {
        at = static_cast<std::size_t>(&slot - slots.data());
    } else {
        const auto holds = [&](const TextSlot& s) {
            return s.role == slot.role && (s.panel == slot.panel || slot.panel == -1) &&
                   slot.rect.x0 >= s.rect.x0 && slot.rect.x0 < s.rect.x1 &&
                   slot.rect.y0 >= s.rect.y0 && slot.rect.y0 < s.rect.y1;
        };
        at = static_cast<std::size_t>(std::find_if(slots.begin(), slots.end(), holds) -
                                      slots.begin());
    }
    if (at == slots.size()) {
        drawn_.elsewhere.emplace_back(slot, std::string(text));
        return;
    }
    if (drawn_.in_slots.size() < slots.size()) drawn_.in_slots.resize(slots.size());
    std::vector<std::string>& strings = drawn_.in_slots[at];
    if (continues && !strings.empty()) {
        strings.back() += text;
    } else {
        strings.emplace_back(text);
    }
}

float Painter::draw_text(Font font, const TextSlot& slot, std::string_view text, Rgba8 color,
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
    record_text(slot, shown);
    if (!shown.empty()) {
        const float top = baseline - f.ascent();
        drawn_.ink.push_back({slot.role, {left, top, left + width, top + f.pixel_height()}, shown});
    }
    return f.add_text(run->glyphs, left, baseline, shown, color);
}

}  // namespace collide::render
