#include "code_panel.hpp"

#include <algorithm>
#include <string>

namespace collide::render {

namespace {

/// Space inside the panel's edge, and the indentation per level, in font heights.
constexpr float pad_share = 0.6F;
constexpr float indent_share = 1.1F;
/// Room for the chevron left of the lines, in font heights.
constexpr float gutter_share = 0.9F;

float inset(const FontAtlas& f) {
    return f.pixel_height() * (pad_share + gutter_share);
}

/// `s` cut to `width` pixels, ending in "...".
std::string fitted(const FontAtlas& f, const std::string& s, float width) {
    if (f.text_width(s) <= width) return s;
    std::string out = s;
    while (!out.empty() && f.text_width(out + "...") > width) out.pop_back();
    return out + "...";
}

}  // namespace

float code_panel_width(const view::CodeView& code, const FontAtlas& font) {
    float widest = font.text_width(code.title);
    for (const view::CodeLineView& line : code.lines) {
        widest =
            std::max(widest, static_cast<float>(line.indent) * indent_share * font.pixel_height() +
                                 font.text_width(line.text));
    }
    return widest + inset(font) + pad_share * font.pixel_height();
}

void paint_code(const view::CodeView& code, RectF area, const FontAtlas& font,
                const CodeColors& colors, OverlayBatch& under, const CodeText& text) {
    under.add_rect(area, colors.panel);
    const float px = font.pixel_height();
    const float pad = pad_share * px;
    const float x0 = area.x0 + inset(font);
    const float right = area.x1 - pad;
    const std::size_t rows = code.lines.size() + (code.title.empty() ? 0 : 1);
    // Lines 1.2 font heights apart, closer when the panel is short (never overlapping).
    const float room = area.height() - 2.0F * pad;
    const float step = rows == 0
                           ? font.line_height()
                           : std::clamp(room / static_cast<float>(rows), px, font.line_height());
    float baseline = area.y0 + pad + font.ascent();
    if (!code.title.empty()) {
        text(font, area.x0 + pad, baseline, fitted(font, code.title, right - area.x0 - pad),
             colors.title);
        baseline += step;
    }
    for (std::size_t k = 0; k < code.lines.size(); ++k, baseline += step) {
        const view::CodeLineView& line = code.lines[k];
        const float x = x0 + static_cast<float>(std::max(line.indent, 0)) * indent_share * px;
        const std::string shown = fitted(font, line.text, std::max(right - x, 0.0F));
        const bool now = code.current && *code.current == k;
        if (now) {
            // The plate spans the listing's width, so that the line reads as a bar, not a word.
            const float top = baseline - font.ascent() - 0.08F * px;
            const RectF plate{x0 - 0.25F * px, top, right, top + step};
            under.add_rect(plate, colors.plate);
            under.add_frame(plate, std::max(1.0F, 0.1F * px), colors.plate_edge);
            // A chevron in the gutter: the line under way even without its colour.
            const float cx = area.x0 + pad - 0.1F * px;
            const float mid = top + 0.5F * step;
            const float h = 0.32F * px;
            const float w = std::max(2.0F, 0.14F * px);
            under.add_line({cx, mid - h}, {cx + 0.55F * px, mid}, w, colors.marker);
            under.add_line({cx + 0.55F * px, mid}, {cx, mid + h}, w, colors.marker);
        }
        text(font, x, baseline, shown, now ? colors.current : colors.text);
    }
}

}  // namespace collide::render
