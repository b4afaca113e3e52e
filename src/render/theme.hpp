#pragma once
// Internal: the renderer's theme module. The palettes of the two themes, the plots' colours in
// each, and the colour helpers every painter (frame builder, queue strip) shares. The public half
// (engine accents, the failure colour, the contrast rule) is declared in renderer.hpp.

#include "collide/render/renderer.hpp"
#include "overlay_geometry.hpp"
#include "plots.hpp"

namespace collide::render {

/// Theme colours.
struct Palette {
    Rgba8 background;
    Rgba8 box_fill;
    Rgba8 wall;
    Rgba8 periodic_edge;
    Rgba8 title;
    Rgba8 text;
    Rgba8 muted;
    Rgba8 failure;  ///< reserved for failures: no disc is ever drawn in it
    Rgba8 outline;  ///< around discs with too little contrast against the box
};
[[nodiscard]] Palette palette(Theme theme) noexcept;
/// A plot's text, axis, curve and zero-line colours in a theme (every level's plots use them).
[[nodiscard]] PlotColors plot_colors(Theme theme) noexcept;

/// `c` with its alpha scaled by `opacity` (clamped to [0, 1]).
[[nodiscard]] Rgba8 faded(Rgba8 c, float opacity) noexcept;
/// The colour of `c` without its alpha.
[[nodiscard]] Rgb8 rgb(Rgba8 c) noexcept;

}  // namespace collide::render
