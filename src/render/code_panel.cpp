#include "code_panel.hpp"

#include <algorithm>
#include <string>

namespace collide::render {

namespace {

/// Space inside the panel's edge, and the indentation per level, in font heights: narrow enough
/// that the collision video's listing stands beside two boxes of 35 % of the frame (issue 44).
constexpr float pad_share = 0.4F;
constexpr float indent_share = 0.8F;
/// Room for the chevron left of the lines, in font heights.
constexpr float gutter_share = 0.8F;

float inset(float px) {
    return px * (pad_share + gutter_share);
}

/// `s` cut to `width` pixels, ending in "...".
std::string fitted(const FontAtlas& f, const std::string& s, float width) {
    if (f.text_width(s) <= width) return s;
    std::string out = s;
    while (!out.empty() && f.text_width(out + "...") > width) out.pop_back();
    return out + "...";
}

}  // namespace

std::vector<RectF> code_rows(RectF area, float pixel_height, std::size_t count) {
    std::vector<RectF> rows;
    if (count == 0) return rows;
    const float pad = pad_share * pixel_height;
    const float room = area.height() - 2.0F * pad;
    const float step =
        std::clamp(room / static_cast<float>(count), pixel_height, 1.2F * pixel_height);
    for (std::size_t k = 0; k < count; ++k) {
        // Whole pixels, each row ending where the next begins.
        const float y0 = std::round(area.y0 + pad + static_cast<float>(k) * step);
        const float y1 = std::round(area.y0 + pad + static_cast<float>(k + 1) * step);
        rows.push_back({area.x0 + pad, y0, area.x1 - pad, y1});
    }
    return rows;
}

float code_panel_width(const view::CodeView& code, const FontAtlas& font) {
    const float px = font.pixel_height();
    float widest = font.text_width(code.title);
    for (const view::CodeLineView& line : code.lines) {
        widest = std::max(widest, static_cast<float>(line.indent) * indent_share * px +
                                      font.text_width(line.text));
    }
    return widest + inset(px) + pad_share * px;
}

void paint_code(const view::CodeView& code, RectF area, const FontAtlas& font,
                const CodeColors& colors, OverlayBatch& under, const CodeText& text) {
    under.add_rect(area, colors.panel);
    const float px = font.pixel_height();
    const float pad = pad_share * px;
    const float x0 = area.x0 + inset(px);
    const float right = area.x1 - pad;
    const std::size_t first = code.title.empty() ? 0 : 1;
    const std::vector<RectF> rows = code_rows(area, px, code.lines.size() + first);
    if (first == 1) {
        text(0, rows[0], area.x0 + pad, fitted(font, code.title, right - area.x0 - pad),
             colors.title);
    }
    for (std::size_t k = 0; k < code.lines.size(); ++k) {
        const RectF row = rows[k + first];
        const view::CodeLineView& line = code.lines[k];
        const float x = x0 + static_cast<float>(std::max(line.indent, 0)) * indent_share * px;
        const std::string shown = fitted(font, line.text, std::max(right - x, 0.0F));
        const bool now = code.current && *code.current == k;
        if (now) {
            // The plate spans the listing's width, so that the line reads as a bar, not a word.
            const RectF plate{x0 - 0.25F * px, row.y0, right, row.y1};
            under.add_rect(plate, colors.plate);
            under.add_frame(plate, std::max(1.0F, 0.1F * px), colors.plate_edge);
            // A chevron in the gutter: the line under way even without its colour.
            const float cx = area.x0 + pad - 0.1F * px;
            const float mid = 0.5F * (row.y0 + row.y1);
            const float h = 0.32F * px;
            const float w = std::max(2.0F, 0.14F * px);
            under.add_line({cx, mid - h}, {cx + 0.55F * px, mid}, w, colors.marker);
            under.add_line({cx + 0.55F * px, mid}, {cx, mid + h}, w, colors.marker);
        }
        text(k + first, row, x, shown, now ? colors.current : colors.text);
    }
}

}  // namespace collide::render
