#pragma once
// Internal: the renderer's theme module. The palettes of the two themes, the plots' colours in
// each, and the colour helpers every painter (frame builder, queue strip) shares. The public half
// (engine accents, the failure colour, the contrast rule) is declared in renderer.hpp.

#include <vector>

#include "collide/render/renderer.hpp"
#include "overlay_geometry.hpp"
#include "plots.hpp"

namespace collide::render {

/// Theme colours.
struct Palette {
    Rgba8 background;
    Rgba8 box_fill;
    Rgba8 wall;
    Rgba8 periodic_edge;  ///< full level: a periodic box's solid edge
    Rgba8 title;
    Rgba8 text;
    Rgba8 muted;
    Rgba8 failure;    ///< reserved for failures: no disc is ever drawn in it
    Rgba8 outline;    ///< around discs with too little contrast against the box
    Rgba8 wrap_edge;  ///< lesson: a periodic box's dashed edge (3:1 against page and box)
};
[[nodiscard]] Palette palette(Theme theme) noexcept;
/// A plot's text, axis, curve and zero-line colours in a theme (every level's plots use them).
[[nodiscard]] PlotColors plot_colors(Theme theme) noexcept;

/// The queue strip's colour for the next event (amber, far from the failure colour).
[[nodiscard]] Rgb8 next_event_color(Theme theme) noexcept;

/// Contrast the painters keep against what lies under: text (WCAG AA for body text), and marks,
/// trails, walls and edges (WCAG's 3:1 for graphics a reader must see).
inline constexpr double text_contrast = 4.5;
inline constexpr double mark_contrast = 3.0;

/// A colour a painter draws over a background, with the contrast it must keep.
struct ColorPair {
    const char* what;  ///< "text on the page", "fading failure ring on the box"
    Rgb8 color;        ///< as blended (a faded colour is listed at its faintest)
    Rgb8 background;
    double minimum;  ///< text_contrast or mark_contrast
};
/// Every colour pair the collision video's painters use in a theme (frame builder, queue strip,
/// plots, marks, trails at their faintest), for the test that checks them all.
[[nodiscard]] std::vector<ColorPair> color_pairs(Theme theme);

/// `color` over `background` at `opacity`, per 8-bit channel as the GL blend does.
[[nodiscard]] Rgb8 blend(Rgb8 color, Rgb8 background, float opacity) noexcept;
/// The least opacity (in 1/255 steps) at which `color` over `background` keeps `ratio`; 1 when
/// even the full colour does not.
[[nodiscard]] float least_opacity(Rgb8 color, Rgb8 background, double ratio) noexcept;
/// `color` moved towards black or white, whichever lies farther from `background`, until it
/// keeps `ratio` against it (unchanged when it already does).
[[nodiscard]] Rgb8 with_contrast(Rgb8 color, Rgb8 background, double ratio) noexcept;
/// The faintest a fading failure ring gets in a theme: it keeps mark_contrast with the box.
[[nodiscard]] float mark_floor(Theme theme) noexcept;
/// An engine's accent as text on the page (the cost label): the accent, moved until it keeps
/// text_contrast.
[[nodiscard]] Rgb8 accent_text(Rgb8 accent, Theme theme) noexcept;
/// A trail's colour and its faintest share of the trail alpha (lesson level): the disc's colour
/// moved until its faintest segment keeps mark_contrast with the box.
struct TrailLook {
    Rgb8 color;
    float min_share = 0.35F;
};
/// The trails' strongest alpha (TrailHistory::draw).
inline constexpr float trail_max_alpha = 200.0F;
[[nodiscard]] TrailLook trail_look(Rgb8 disc, Theme theme) noexcept;
/// Lesson trails: `out` gets `colors` with every tagged disc's (the trails drawn) replaced by its
/// trail_look colour; returns the faintest share that keeps all of them legible.
float legible_trails(const std::vector<Rgb8>& colors, const std::vector<DiscState>& discs,
                     Theme theme, std::vector<Rgb8>& out);

/// `c` with its alpha scaled by `opacity` (clamped to [0, 1]).
[[nodiscard]] Rgba8 faded(Rgba8 c, float opacity) noexcept;
/// The colour of `c` without its alpha.
[[nodiscard]] Rgb8 rgb(Rgba8 c) noexcept;

}  // namespace collide::render
