#pragma once
// Internal: the pseudocode panel of `--code` (collide/view/code.hpp), painted into a rectangle
// of a lesson frame (the heap lesson's, the collision video's beside its queue). It paints what
// it is handed: the listing's lines at one font size, the current one on a plate with a chevron
// beside it (so that it reads without colour).

#include <cstddef>
#include <functional>
#include <string_view>
#include <vector>

#include "collide/view/code.hpp"
#include "font.hpp"
#include "overlay_geometry.hpp"

namespace collide::render {

/// The panel's colours (theme.cpp lists each pair for the contrast test).
struct CodeColors {
    Rgba8 panel;    ///< the panel's fill
    Rgba8 title;    ///< the title over the listing
    Rgba8 text;     ///< the lines not under way
    Rgba8 current;  ///< the current line's text, on `plate`
    Rgba8 plate;    ///< behind the current line
    /// The plate's outline: the plate's colour moved until it keeps 3:1 on the panel (the plate
    /// itself where it already does), so the bar stands out in either theme.
    Rgba8 plate_edge;
    Rgba8 marker;  ///< the chevron beside the current line, on `panel`
};

/// Draws one row's text: (row index, the row's rectangle, x where the text starts, the text
/// (already cut to fit), colour); the text sits in the row as Painter::draw_text centres it
/// (baseline = y0 + (height - pixel height) / 2 + ascent). The painter records what it drew.
using CodeText = std::function<void(std::size_t, RectF, float, std::string_view, Rgba8)>;

/// The rows of a panel of `count` rows (the title's included) in `area`, for text of
/// `pixel_height`: 1.2 heights apart, closer (down to one height) when the area is short. Pure:
/// layouts call it for their text slots, paint_code for its text.
[[nodiscard]] std::vector<RectF> code_rows(RectF area, float pixel_height, std::size_t count);

/// The width a panel needs for `code` in `font`, padding included (the widest line, indented).
[[nodiscard]] float code_panel_width(const view::CodeView& code, const FontAtlas& font);

/// Paints `code` into `area`: its fill (into `under`), the title and the lines in `font` (a line
/// wider than the panel is cut and ends in "..."), the current line's plate and chevron.
void paint_code(const view::CodeView& code, RectF area, const FontAtlas& font,
                const CodeColors& colors, OverlayBatch& under, const CodeText& text);

}  // namespace collide::render
