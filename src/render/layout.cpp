#include "layout.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
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
    layout.level = with_text ? OverlayLevel::full : OverlayLevel::none;
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

FrameLayout compute_layout(const LayoutInput& input) {
    switch (input.level) {
        case OverlayLevel::lesson:
            return lesson_layout(input);
        case OverlayLevel::full:
            return classic_layout(input.width, input.height, true, input.boxes,
                                  font_pixel_height(input.height) * 1.2F, input.counter_rows);
        case OverlayLevel::none:
            break;
    }
    return classic_layout(input.width, input.height, false, input.boxes, 0.0F, 0);
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
/// `text` as a JSON string: quotes, backslashes and control characters escaped (UTF-8 as is).
std::string json_string(std::string_view text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            out += fmt::format("\\u{:04x}", static_cast<unsigned>(c));
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string json_strings(const std::vector<std::string>& strings) {
    std::string out = "[";
    for (std::size_t k = 0; k < strings.size(); ++k) {
        out += (k == 0 ? "" : ", ") + json_string(strings[k]);
    }
    return out + "]";
}
}  // namespace

std::string layout_json(const FrameLayout& layout, int width, int height, const SlotTexts* drawn) {
    const auto rect = [](RectF r) {
        return fmt::format("[{:g}, {:g}, {:g}, {:g}]", r.x0, r.y0, r.x1, r.y1);
    };
    std::string out = fmt::format(
        "{{\n  \"width\": {}, \"height\": {}, \"level\": \"{}\", "
        "\"compact\": {},\n  \"panels\": [",
        width, height, overlay_level_name(layout.level), layout.compact ? "true" : "false");
    for (std::size_t i = 0; i < layout.panels.size(); ++i) {
        const PanelLayout& p = layout.panels[i];
        out += fmt::format("{}\n    {{\"area\": {}, \"box\": {}, \"pixels_per_unit\": {:g}}}",
                           i == 0 ? "" : ",", rect(p.area), rect(p.box), p.scale);
    }
    out += "\n  ],\n  \"column\": " + rect(layout.column.area) + ",\n  \"text\": [";
    for (std::size_t i = 0; i < layout.text.size(); ++i) {
        const TextSlot& t = layout.text[i];
        const std::string strings = drawn != nullptr && i < drawn->in_slots.size()
                                        ? ", \"text\": " + json_strings(drawn->in_slots[i])
                                        : std::string();
        out += fmt::format(
            "{}\n    {{\"role\": \"{}\", \"panel\": {}, \"rect\": {}, "
            "\"pixel_height\": {:g}, \"cap_height\": {:.1f}{}}}",
            i == 0 ? "" : ",", text_role_name(t.role), t.panel, rect(t.rect), t.pixel_height,
            t.cap_height(), strings);
    }
    out += "\n  ]";
    if (drawn != nullptr) {
        // Text in no slot of the layout: the title card, labels inside a box, the queue's nodes.
        out += ",\n  \"other_text\": [";
        for (std::size_t i = 0; i < drawn->elsewhere.size(); ++i) {
            const auto& [slot, text] = drawn->elsewhere[i];
            out += fmt::format(
                "{}\n    {{\"role\": \"{}\", \"panel\": {}, \"rect\": {}, "
                "\"pixel_height\": {:g}, \"text\": {}}}",
                i == 0 ? "" : ",", text_role_name(slot.role), slot.panel, rect(slot.rect),
                slot.pixel_height, json_string(text));
        }
        out += "\n  ]";
    }
    out += "\n}\n";
    return out;
}

}  // namespace collide::render
