#pragma once
// Internal: where everything goes in a frame. Pure arithmetic on the frame size, the boxes and
// the overlay level (no GL, no font file), so tests can check the rectangles directly and
// `--layout-json` can write them out.
//
// Levels (docs/renderer.md):
//  - none:    the boxes fill the frame, no text.
//  - lesson:  per panel a title line above its box and a row of headline figures (and an optional
//             note line) below it; a column between the boxes (beside a single box) for the clock,
//             the shared cost graphic, the energy line and a plot; a caption line across the
//             bottom. Capitals are at least 2.8 % of the frame height. Below compact_width the
//             compact form: boxes fill the frame under one line of text per panel.
//  - full:    today's expert layout: title and counter grid above each box, strip of plots below.

#include <string>
#include <utility>
#include <vector>

#include "collide/box.hpp"
#include "collide/render/renderer.hpp"
#include "overlay_geometry.hpp"

namespace collide::render {

/// Cap height of DejaVu Sans as a share of the pixel height stb_truetype bakes it at
/// (capital 1493 units over ascent 1901 + descent 483): text is sized from its capitals.
inline constexpr float cap_height_per_pixel_height = 1493.0F / 2384.0F;
/// Lesson text: capitals at least this share of the frame height (20 px at 720p).
inline constexpr float lesson_cap_share = 0.028F;
/// Headline figures are this much larger than body text.
inline constexpr float headline_scale = 1.3F;
/// Frames narrower than this use the compact lesson form (thumbnails).
inline constexpr int compact_width = 480;
/// Compact text: capitals at least this many pixels.
inline constexpr float compact_min_cap_px = 9.0F;

/// What a text slot is for (written to --layout-json).
enum class TextRole {
    title,
    figures,
    note,
    how,    ///< lesson, two panels: why the panel's work grows as it does (under its figures)
    marks,  ///< lesson: the failure marks' legend under a panel's figures (and note)
    caption,
    clock,
    cost_heading,
    cost_label,
    cost_value,
    cost_ratio,  ///< lesson, two panels: "131x less work" under the bars
    energy,
    legend,
    plot_title,
    counters,
    strip,
    queue,  ///< the event queue strip under a panel (its heading line; the strip is queue_strip)
    code    ///< lesson, --code: a line of the pseudocode column (its title first)
};
[[nodiscard]] const char* text_role_name(TextRole role) noexcept;

/// One line of text: its slot (nothing else is drawn there) and the font's pixel height.
struct TextSlot {
    TextRole role = TextRole::title;
    int panel = -1;  ///< the panel it belongs to, -1 for shared text
    RectF rect;
    float pixel_height = 0.0F;  ///< font size (stb pixel height)
    [[nodiscard]] float cap_height() const noexcept {
        return pixel_height * cap_height_per_pixel_height;
    }
};

/// One panel: its whole area, the header (full level: title and counters) and the box's pixel
/// rectangle.
struct PanelLayout {
    RectF area;
    RectF header;        // full level only
    RectF box;           // the box [0,W]x[0,H] in pixels, aspect ratio preserved
    double scale = 1.0;  // pixels per box unit
    /// A zoom (zoom_into): the box point drawn at the rectangle's top-left corner is
    /// (shift.x, height + shift.y); (0, 0) without a zoom.
    Vec2 shift{0.0, 0.0};
    bool zoomed = false;  // zoom_into enlarged the box: what lies outside it is not drawn

    /// Box coordinates (y up) to frame pixels (y down).
    [[nodiscard]] PointF to_pixels(Vec2 p, const Box& b) const noexcept {
        return {box.x0 + static_cast<float>((p.x - shift.x) * scale),
                box.y0 + static_cast<float>((b.height - (p.y - shift.y)) * scale)};
    }
    /// Shows the part of box `b` around `centre`, `magnification` times larger, in the same
    /// rectangle (a replay's zoom); a magnification of 1 or less changes nothing.
    void zoom_into(Vec2 centre, double magnification, const Box& b) noexcept;
};

/// The lesson column's pieces (empty rectangles when absent).
struct ColumnLayout {
    RectF area;        ///< the whole column
    RectF bars;        ///< the cost graphic's bars area
    RectF legend_bar;  ///< the colour bar (speed/mass colours), above its `legend` text slot
    RectF plot;        ///< what is left below: a plot (histogram) when one is shown; with
                       ///< small_plot it reaches down to the figures row's bottom (the room
                       ///< between the two boxes' figures is free)
};

struct FrameLayout {
    bool compact = false;
    std::vector<PanelLayout> panels;
    RectF strip;        // full level: the bottom strip
    RectF queue_strip;  // lesson level with --queue: under the panels, frame-wide
    int queue_panel = -1;
    ColumnLayout column;         // lesson level
    RectF code;                  // lesson level with --code: the pseudocode column
    std::vector<TextSlot> text;  // every text line (lesson, compact); full: header and strip
    float margin = 0.0F;
    float body_pixel_height = 0.0F;      ///< 0 at level none
    float headline_pixel_height = 0.0F;  ///< headline figures (lesson)

    /// The first slot with this role (and panel), or nullptr.
    [[nodiscard]] const TextSlot* slot(TextRole role, int panel = -1) const noexcept;
    /// Every slot with this role (and panel, -1 = any).
    [[nodiscard]] std::vector<const TextSlot*> slots(TextRole role, int panel = -1) const;
};

/// The strings a frame drew, for `--layout-json`: per slot of FrameLayout::text (same order),
/// and the text drawn outside every slot (the title card, labels inside a box).
struct SlotTexts {
    std::vector<std::vector<std::string>> in_slots;
    std::vector<std::pair<TextSlot, std::string>> elsewhere;
    /// Every string draw_text set, where its glyphs went (its advance across, the font's line
    /// height up and down): what a test checks for text over text.
    struct Ink {
        TextRole role;
        RectF rect;
        std::string text;
    };
    std::vector<Ink> ink;
};

/// What the layout needs to know of a frame besides its size.
struct LayoutInput {
    int width = 1280;
    int height = 720;
    std::vector<Box> boxes;   ///< 1 to 5 panels, left to right (only their shapes matter)
    bool note_line = false;   ///< lesson: a note line under the figures (dt > frame)
    bool how_line = false;    ///< lesson: a line under each panel's figures (PanelContent::how)
    bool cost_ratio = false;  ///< lesson: the cost ratio under the bars (two panels)
    bool clock_unit = false;  ///< lesson: a second clock line for the time's unit
    /// Lesson: per panel, a legend line for its failure marks (under the note). The left one of
    /// two panels takes the frame's width when the right one has none.
    std::vector<bool> mark_lines;
    bool large_plot = false;    ///< lesson: the plot is the subject: a wider column
    bool small_plot = false;    ///< lesson: a plot below the column's text, reaching down
                                ///< beside the figures row so it is tall enough to read
    bool color_legend = false;  ///< lesson: a colour bar (speed or mass colours) in the column
    int counter_rows = 1;       ///< full: rows of the counter grid
    int queue_panel = -1;       ///< lesson: this panel shows its event queue in a strip below it
    /// Lesson, --code: rows of the pseudocode column on the right (its title included; 0: no
    /// column) and the column's width in pixels; everything else lays out in what is left.
    std::size_t code_rows = 0;
    float code_width = 0.0F;
    /// Lesson, a queue panel too crowded to number its discs inside the box (dense-fluid): the
    /// width (px) of a column for its numbers kept free beside it: with one box between it and
    /// its text, with two under the --code listing when it is the right box (0: none).
    float number_column = 0.0F;
};

/// Lesson level: the event queue strip's largest share of the frame height.
inline constexpr float queue_strip_share = 0.3F;
/// ... and its smallest: a heading and one line of the queue's nodes (label and time to go side by
/// side; a taller strip gives them two lines), so that two boxes over the strip keep 35 % of a
/// 16:9 frame under three rows of text (figures, note, marks).
inline constexpr float queue_strip_min_share = 0.142F;
/// With the queue strip the boxes keep at least this share of the frame's area (issue 44: 35 %),
/// where the strip's smallest height allows it: the strip takes what they leave.
inline constexpr float queue_boxes_share = 0.36F;

/// The font size used for a frame height at the full level (px): today's H / 34.
[[nodiscard]] float font_pixel_height(int frame_height) noexcept;
/// Lesson body text size: capitals >= 2.8 % of the height (>= 9 px in the compact form).
[[nodiscard]] float lesson_pixel_height(int frame_width, int frame_height) noexcept;

/// Columns of the counter grid under a panel title (full level). It depends only on the panel
/// width and the font size, never on the counters' text, so the layout stays put.
[[nodiscard]] int counter_columns(float panel_width, float font_pixel_height) noexcept;

/// The lesson level's layout (lesson_layout.cpp; the compact form below compact_width). Pure and
/// cheap (a few dozen rectangles).
[[nodiscard]] FrameLayout lesson_layout(const LayoutInput& input);

/// The layout of levels full (`with_text`) and none: `boxes.size()` panels side by side; with
/// text each header holds the title and `counter_rows` rows of counters (lines of
/// `line_height`), and a strip runs below the panels.
[[nodiscard]] FrameLayout classic_layout(int frame_width, int frame_height, bool with_text,
                                         const std::vector<Box>& boxes, float line_height,
                                         int counter_rows);

/// The full/none layout of `config`'s size and level (tests): classic_layout.
[[nodiscard]] FrameLayout compute_layout(const RenderConfig& config, const std::vector<Box>& boxes,
                                         float line_height, int counter_rows = 1);

/// Pixels per scene unit for a box in a room of this size (never 0 for a usable room).
[[nodiscard]] double fit_scale(const Box& box, float room_width, float room_height);
/// A box of `scale` centred horizontally in [x0, x1] with its top at y0 (whole pixels).
[[nodiscard]] RectF place_box(const Box& box, double scale, float x0, float x1, float y0);

/// The rectangles as JSON (frame size, level, panels with box and scale, every text slot), with
/// the strings drawn in each slot ("text") when `drawn` is given, and the text drawn elsewhere.
[[nodiscard]] std::string layout_json(const FrameLayout& layout, OverlayLevel level, int width,
                                      int height, const SlotTexts* drawn = nullptr);

/// True when the two rectangles share interior area.
[[nodiscard]] bool overlaps(RectF a, RectF b) noexcept;

}  // namespace collide::render
