#include "layout.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace collide::render {

// Pixels per scene unit: anything from ~1e-48 (a box of 1e50 units) to ~1e52 (1e-50 units); only
// a degenerate room could make it 0.
double fit_scale(const Box& box, float room_width, float room_height) {
    return std::max(std::numeric_limits<double>::min(),
                    std::min(static_cast<double>(std::max(room_width, 1.0F)) / box.width,
                             static_cast<double>(std::max(room_height, 1.0F)) / box.height));
}

void PanelLayout::zoom_into(Vec2 centre, double magnification, const Box& b) noexcept {
    if (!(magnification > 1.0)) return;
    scale *= magnification;
    shift = {centre.x - 0.5 * b.width / magnification,
             centre.y + 0.5 * b.height / magnification - b.height};
    zoomed = true;
}

RectF place_box(const Box& box, double scale, float x0, float x1, float y0) {
    const auto w = static_cast<float>(box.width * scale);
    const auto h = static_cast<float>(box.height * scale);
    const float left = std::round(x0 + 0.5F * ((x1 - x0) - w));
    const float top = std::round(y0);
    return {left, top, left + w, top + h};
}

// Today's layout: header (title + counter grid) above each box, strip below (or nothing).
FrameLayout classic_layout(int frame_width, int frame_height, bool with_text,
                           const std::vector<Box>& boxes, float line_height, int counter_rows) {
    FrameLayout layout;
    const auto width = static_cast<float>(frame_width);
    const auto height = static_cast<float>(frame_height);
    layout.margin = std::max(2.0F, std::round(std::min(width, height) * 0.01F));
    const float m = layout.margin;
    float panels_bottom = height;
    float header_height = 0.0F;
    if (with_text) {
        const float strip_height = std::round(std::max(4.2F * line_height, 0.22F * height));
        panels_bottom = height - strip_height;
        layout.strip = {0.0F, panels_bottom, width, height};
        header_height = static_cast<float>(1 + std::max(counter_rows, 0)) * line_height;
        layout.body_pixel_height = line_height / 1.2F;
    }
    const auto count = static_cast<float>(std::max<std::size_t>(boxes.size(), 1));
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        PanelLayout panel;
        panel.area = {std::round(width * static_cast<float>(i) / count), 0.0F,
                      std::round(width * static_cast<float>(i + 1) / count), panels_bottom};
        panel.header = {panel.area.x0 + m, m, panel.area.x1 - m, m + header_height};
        const RectF room{panel.area.x0 + m, panel.header.y1 + m, panel.area.x1 - m,
                         panels_bottom - m};
        panel.scale = fit_scale(boxes[i], room.width(), room.height());
        const auto box_w = static_cast<float>(boxes[i].width * panel.scale);
        const auto box_h = static_cast<float>(boxes[i].height * panel.scale);
        const float x0 = std::round(room.x0 + 0.5F * (room.width() - box_w));
        const float y0 = std::round(room.y0 + 0.5F * (room.height() - box_h));
        panel.box = {x0, y0, x0 + box_w, y0 + box_h};
        layout.panels.push_back(panel);
        if (with_text) {
            layout.text.push_back(
                {TextRole::counters, static_cast<int>(i), panel.header, layout.body_pixel_height});
        }
    }
    if (with_text)
        layout.text.push_back({TextRole::strip, -1, layout.strip, layout.body_pixel_height});
    return layout;
}

const char* text_role_name(TextRole role) noexcept {
    switch (role) {
        case TextRole::title:
            return "title";
        case TextRole::figures:
            return "figures";
        case TextRole::note:
            return "note";
        case TextRole::how:
            return "how";
        case TextRole::marks:
            return "marks";
        case TextRole::caption:
            return "caption";
        case TextRole::clock:
            return "clock";
        case TextRole::cost_heading:
            return "cost-heading";
        case TextRole::cost_label:
            return "cost-label";
        case TextRole::cost_value:
            return "cost-value";
        case TextRole::cost_ratio:
            return "cost-ratio";
        case TextRole::energy:
            return "energy";
        case TextRole::legend:
            return "legend";
        case TextRole::plot_title:
            return "plot-title";
        case TextRole::counters:
            return "counters";
        case TextRole::strip:
            return "strip";
        case TextRole::queue:
            return "queue";
        case TextRole::code:
            return "code";
    }
    return "text";
}

const TextSlot* FrameLayout::slot(TextRole role, int panel) const noexcept {
    for (const TextSlot& s : text) {
        if (s.role == role && s.panel == panel) return &s;
    }
    return nullptr;
}

std::vector<const TextSlot*> FrameLayout::slots(TextRole role, int panel) const {
    std::vector<const TextSlot*> out;
    for (const TextSlot& s : text) {
        if (s.role == role && (panel == -1 || s.panel == panel)) out.push_back(&s);
    }
    return out;
}

float font_pixel_height(int frame_height) noexcept {
    return std::clamp(std::round(static_cast<float>(frame_height) / 34.0F), 11.0F, 48.0F);
}

float lesson_pixel_height(int frame_width, int frame_height) noexcept {
    const float cap = frame_width < compact_width
                          ? compact_min_cap_px
                          : lesson_cap_share * static_cast<float>(frame_height);
    return std::ceil(std::max(cap, compact_min_cap_px) / cap_height_per_pixel_height);
}

int counter_columns(float panel_width, float font_pixel_height) noexcept {
    // About 14 em per column keeps a short "label  value" counter on one line.
    const float em = std::max(font_pixel_height, 1.0F);
    return std::clamp(static_cast<int>(panel_width / (14.0F * em)), 1, 4);
}

FrameLayout compute_layout(const RenderConfig& config, const std::vector<Box>& boxes,
                           float line_height, int counter_rows) {
    return classic_layout(config.width, config.height, config.overlays != OverlayLevel::none, boxes,
                          line_height, counter_rows);
}

bool overlaps(RectF a, RectF b) noexcept {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

namespace {

using Json = nlohmann::ordered_json;

/// `x` as the layout has always written it (six significant digits, "{:g}"): the same value
/// whatever the JSON writer's own precision; a whole number of pixels as an integer.
Json six_digits(double x) {
    const double rounded = std::stod(fmt::format("{:g}", x));
    constexpr double exact_integers = 9007199254740992.0;  // 2^53
    if (std::abs(rounded) < exact_integers && rounded == std::trunc(rounded))
        return static_cast<std::int64_t>(rounded);
    return rounded;
}

Json rect_json(RectF r) {
    return Json::array({six_digits(r.x0), six_digits(r.y0), six_digits(r.x1), six_digits(r.y1)});
}

}  // namespace

std::string layout_json(const FrameLayout& layout, OverlayLevel level, int width, int height,
                        const SlotTexts* drawn) {
    Json out;
    out["width"] = width;
    out["height"] = height;
    out["level"] = overlay_level_name(level);
    out["compact"] = layout.compact;
    Json panels = Json::array();
    for (const PanelLayout& p : layout.panels) {
        panels.push_back({{"area", rect_json(p.area)},
                          {"box", rect_json(p.box)},
                          {"pixels_per_unit", six_digits(p.scale)}});
    }
    out["panels"] = std::move(panels);
    out["column"] = rect_json(layout.column.area);
    // The column's plot (a histogram): with a large plot the subject beside the boxes.
    if (layout.column.plot.width() > 0.0F && layout.column.plot.height() > 0.0F)
        out["plot"] = rect_json(layout.column.plot);
    Json text = Json::array();
    for (std::size_t i = 0; i < layout.text.size(); ++i) {
        const TextSlot& t = layout.text[i];
        Json slot = {{"role", text_role_name(t.role)},
                     {"panel", t.panel},
                     {"rect", rect_json(t.rect)},
                     {"pixel_height", six_digits(t.pixel_height)},
                     {"cap_height", std::stod(fmt::format("{:.1f}", t.cap_height()))}};
        if (drawn != nullptr && i < drawn->in_slots.size()) slot["text"] = drawn->in_slots[i];
        text.push_back(std::move(slot));
    }
    out["text"] = std::move(text);
    if (drawn != nullptr) {
        // Text in no slot of the layout: the title card, labels inside a box, the queue's nodes.
        Json other = Json::array();
        for (const auto& [slot, words] : drawn->elsewhere) {
            other.push_back({{"role", text_role_name(slot.role)},
                             {"panel", slot.panel},
                             {"rect", rect_json(slot.rect)},
                             {"pixel_height", six_digits(slot.pixel_height)},
                             {"text", words}});
        }
        out["other_text"] = std::move(other);
        Json ink = Json::array();
        for (const SlotTexts::Ink& i : drawn->ink)
            ink.push_back(
                {{"role", text_role_name(i.role)}, {"rect", rect_json(i.rect)}, {"text", i.text}});
        out["text_ink"] = std::move(ink);
    }
    // Strings are any bytes a scene wrote: invalid UTF-8 becomes U+FFFD rather than an error.
    return out.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace collide::render
