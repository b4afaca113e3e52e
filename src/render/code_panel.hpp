#pragma once
// Internal: the pseudocode panel of `--code` (collide/view/code.hpp), painted into a rectangle
// of any lesson frame (the heap lesson's, the collision video's queue, the puzzle's). It paints
// what it is handed: the listing's lines at one font size, the current one on a plate with a
// chevron beside it (so that it reads without colour).

#include <functional>
#include <string_view>

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

/// Draws text: (font, x, baseline, text, colour); the painter records what it drew.
using CodeText = std::function<void(const FontAtlas&, float, float, std::string_view, Rgba8)>;

/// The width a panel needs for `code` in `font`, padding included (the widest line, indented).
[[nodiscard]] float code_panel_width(const view::CodeView& code, const FontAtlas& font);

/// Paints `code` into `area`: its fill (into `under`), the title and the lines in `font` (a
/// line wider than the panel is cut and ends in "..."; lines closer together, down to the
/// font's height, when the panel is short), the current line's plate and chevron.
void paint_code(const view::CodeView& code, RectF area, const FontAtlas& font,
                const CodeColors& colors, OverlayBatch& under, const CodeText& text);

}  // namespace collide::render
