#pragma once
// Internal: the renderer's theme module. The palettes of the two themes (the collision video's,
// the heap lesson's and the puzzle's), the plots' colours in each, the lessons' highlight
// colours, and the colour helpers every painter (frame builder, queue strip, heap and puzzle
// views) shares. The public half (engine accents, the failure colour, the contrast rule) is
// declared in renderer.hpp.

#include <array>
#include <cstddef>
#include <vector>

#include "code_panel.hpp"
#include "collide/render/renderer.hpp"
#include "collide/view/heap.hpp"
#include "collide/view/puzzle.hpp"
#include "overlay_geometry.hpp"
#include "plots.hpp"

namespace collide::render {

// ---------------------------------------------------------------------------------------------
// The collision video's named colours (each painter takes its colours from here).

/// The engines' colours on the dark theme (panel_accent darkens them on the light one until
/// they keep 3:1 on the page): time-driven orange, event-driven blue, the same in every video.
inline constexpr Rgb8 time_driven_accent{240, 150, 60};
inline constexpr Rgb8 event_driven_accent{90, 175, 245};
/// A summary card's column heading without a panel of its own (never drawn today: a card has a
/// column per panel).
inline constexpr Rgb8 summary_column_fallback{200, 200, 200};
/// The tag colour mode's colour of a tagged disc (and of the full level's tag key), and of the
/// others.
inline constexpr Rgb8 tagged_color{250, 160, 40};
inline constexpr Rgb8 untagged_color{120, 122, 135};
/// The full level's ring around a disc that left its box.
inline constexpr Rgba8 escaped_ring_color{255, 70, 70, 255};
/// The full level's counters on the dark theme: dimmer than its text (the light theme's are
/// its text colour).
inline constexpr Rgba8 full_counter_dark{190, 190, 200, 255};
/// Level none: a red halo around overlapping discs, a yellow flash where a collision was missed.
inline constexpr Rgba8 overlap_halo_color{240, 45, 45, 255};
inline constexpr Rgba8 missed_flash_color{255, 235, 110, 235};
/// The queue strip's colour for the next event: amber, far from the failure magenta; darker on
/// the light theme, where the bright one has too little contrast against white.
inline constexpr Rgb8 next_event_dark{255, 196, 40};
inline constexpr Rgb8 next_event_light{150, 80, 0};
/// The plots' text, axes, reference curve and zero line on the dark theme (plot_colors).
inline constexpr PlotColors dark_plot_colors{
    {210, 210, 215, 255}, {150, 150, 160, 255}, {250, 250, 250, 255}, {90, 90, 100, 255}};

/// A next-collision question's candidates, each with its own colour for its line, its leader
/// and its letter (A sky blue, B green, C violet, D salmon): none amber (the gas's discs, the
/// next event), none magenta (the failure colour: the reveal's answer), none grey (the velocity
/// arrows'). The light theme's are darker (D a wine red), each keeping text_contrast on the box.
inline constexpr std::size_t candidate_tints = 4;
inline constexpr std::array<Rgb8, candidate_tints> candidate_dark{
    {{95, 185, 255}, {110, 215, 120}, {175, 120, 255}, {255, 150, 120}}};
inline constexpr std::array<Rgb8, candidate_tints> candidate_light{
    {{0, 100, 190}, {0, 130, 50}, {115, 70, 200}, {160, 40, 80}}};

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

/// The pseudocode column of `render --queue --code` (code_panel.hpp): the box's fill as its
/// panel, the current line on the heap lesson's amber plate with dark text.
[[nodiscard]] CodeColors code_colors(const Palette& palette) noexcept;

/// The queue strip's colour for the next event (amber, far from the failure colour).
[[nodiscard]] Rgb8 next_event_color(Theme theme) noexcept;

/// Candidate `tint`'s colour in a theme (candidate_dark, candidate_light; cycling past the last).
[[nodiscard]] Rgb8 candidate_color(int tint, Theme theme) noexcept;
/// A question's velocity arrows: the text colour, which no candidate's lines take, so that an
/// arrow never reads as a line between two discs.
[[nodiscard]] Rgb8 motion_arrow_color(Theme theme) noexcept;

/// Contrast the painters keep against what lies under: text (WCAG AA for body text), and marks,
/// trails, walls and edges (WCAG's 3:1 for graphics a reader must see).
inline constexpr double text_contrast = 4.5;
inline constexpr double mark_contrast = 3.0;
/// WCAG's 3:1 for large text (18 pt and up): the heap's keys, its largest text.
inline constexpr double large_text_contrast = 3.0;

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

// ---------------------------------------------------------------------------------------------
// The priority-queue lesson (heap_view.cpp): the collision video's page colours; highlights
// chosen to stay apart for colour-blind viewers (amber / blue / green / purple / red differ in
// lightness too), the same in both themes (their text is chosen against the highlight, not the
// page).

/// A heap lesson's colours in one theme.
struct HeapPalette {
    Rgba8 background;
    Rgba8 panel;
    Rgba8 title;
    Rgba8 counter;
    Rgba8 caption;
    Rgba8 edge;
    Rgba8 slot;          ///< a plain slot's fill
    Rgba8 slot_outline;  ///< around a slot holding a key
    Rgba8 empty;         ///< outlines of the capacity's empty places (nodes and slots)
    Rgba8 node;          ///< a plain node's fill
    Rgba8 index;
    Rgba8 node_outline;
    Rgba8 sorted_fill;  ///< heapsort's sorted part: set apart by its fill, never dimmed
    Rgba8 sorted_text;  ///< (a sorted array is the result: as legible as any key)
    Rgba8 token_done;
    Rgba8 token_todo;
    Rgba8 map_header;
};
[[nodiscard]] HeapPalette heap_palette(Theme theme) noexcept;

/// The operation under way in the heap lesson's strip: an amber tab with dark text.
inline constexpr Rgba8 heap_token_now_fill{240, 170, 40, 255};
/// Text on the light highlights (amber, green, teal).
inline constexpr Rgba8 highlight_dark_text{20, 20, 24, 255};

/// A highlighted key: its fill (slot and node) and its text.
struct KeyStyle {
    Rgba8 fill;
    Rgba8 text;
};
/// How a key marked `mark` is drawn; plain keys take the palette's slot and title colours.
[[nodiscard]] KeyStyle heap_mark_style(view::SlotMark mark, const HeapPalette& palette) noexcept;
/// A tree edge lit in `mark`'s colour: the fill, darkened or lightened until it keeps 3:1 on
/// the panel (the light theme's amber and green are too faint on white as lines).
[[nodiscard]] Rgba8 heap_lit_edge(view::SlotMark mark, const HeapPalette& palette) noexcept;
/// The pseudocode column of `collide heap --code` (code_panel.hpp): the panel's colours, the
/// current line on the strip's amber tab with its dark text, the chevron in the title's colour.
[[nodiscard]] CodeColors heap_code_colors(const HeapPalette& palette) noexcept;
/// The map's entry being updated, small text on the moving blue: dark (white keeps only 3.2:1).
inline constexpr Rgba8 heap_map_update_text{20, 20, 24, 255};

// ---------------------------------------------------------------------------------------------
// The puzzle (puzzle_view.cpp). Tiles are light with dark numbers (the most legible pair at a
// distance); highlights differ in lightness as well as hue, for colour-blind viewers.

/// The puzzle's colours in one theme.
struct PuzzlePalette {
    Rgba8 background;
    Rgba8 panel;
    Rgba8 title;
    Rgba8 counter;
    Rgba8 status;
    Rgba8 label;
    Rgba8 edge;
    Rgba8 edge_unlinked;  ///< a tree edge whose parent board is not drawn
    Rgba8 queue_fill;     ///< behind the queue's front
    Rgba8 tile;
    Rgba8 tile_text;
    Rgba8 blank;  ///< the board's frame and its blank cell
    Rgba8 sliding_tile;
    Rgba8 current;   ///< the board being expanded
    Rgba8 goal;      ///< the goal, once found
    Rgba8 solution;  ///< boards on the solution path
};
[[nodiscard]] PuzzlePalette puzzle_palette(Theme theme) noexcept;
/// The pseudocode column of `collide puzzle --code` (code_panel.hpp): the panel's colours, the
/// current line on the sliding tile's amber with dark text, the chevron in the title's colour.
[[nodiscard]] CodeColors puzzle_code_colors(const PuzzlePalette& palette) noexcept;
/// The frame around a board marked `mark` (plain: the edge colour).
[[nodiscard]] Rgba8 puzzle_mark_color(view::PuzzleMark mark, const PuzzlePalette& palette) noexcept;

/// Every colour pair the heap lesson's and the puzzle's painters use in a theme (heap_view.cpp,
/// puzzle_view.cpp), for the test that checks them all, as color_pairs does for collisions.
[[nodiscard]] std::vector<ColorPair> heap_color_pairs(Theme theme);
[[nodiscard]] std::vector<ColorPair> puzzle_color_pairs(Theme theme);

// ---------------------------------------------------------------------------------------------
// Helpers

/// `c` with its alpha scaled by `opacity` (clamped to [0, 1]).
[[nodiscard]] Rgba8 faded(Rgba8 c, float opacity) noexcept;
/// The colour of `c` without its alpha.
[[nodiscard]] Rgb8 rgb(Rgba8 c) noexcept;

}  // namespace collide::render
