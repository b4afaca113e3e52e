#pragma once
// Internal: what every painter of the collision video shares. A painter turns a FrameContent into
// a DrawList for GlTarget; there is one per overlay level (minimal_painter.hpp: none,
// full_painter.hpp: full, lesson_painter.hpp: lesson), chosen once for a video by
// FrameBuilder (frame_builder.hpp). The base runs the phases of a frame, the same at every level
// (layout, per panel: box, trails, discs, marks, text; then the frame's own text), and holds the
// helpers they share (fonts and text, the box, disc colours, discs). No GL.

#include <cstddef>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include "collide/render/renderer.hpp"
#include "draw_list.hpp"
#include "failure_marks.hpp"
#include "font.hpp"
#include "layout.hpp"
#include "theme.hpp"
#include "trails.hpp"

namespace collide::render {

/// How a level draws a panel's box, trails and discs (filled once, by the painter's constructor).
struct PanelStyle {
    float wall = 1.0F;         ///< wall thickness, px
    float trail_width = 1.5F;  ///< px
    float trail_fade = 0.0F;   ///< TrailHistory::draw's fade
    /// Discs with too little contrast against the box get an outline.
    bool outline_faint_discs = false;
    /// Escaped discs are left out (the painter marks where they crossed the edge) rather than
    /// drawn at the panel's edge with a red ring.
    bool escaped_as_marks = false;
    /// Discs are clipped to the box (otherwise only in periodic boxes, at the seam; escaped discs
    /// then show outside a walled box).
    bool clip_to_box = false;
    /// A periodic box's edges are dashed (palette wrap_edge) rather than a solid frame.
    bool dashed_periodic_edges = false;
    /// Trails take a colour and fading floor that keep 3:1 against the box (legible_trails).
    bool legible_trails = false;
};

class Painter {
  public:
    virtual ~Painter() = default;
    Painter(const Painter&) = delete;
    Painter& operator=(const Painter&) = delete;
    Painter(Painter&&) = delete;
    Painter& operator=(Painter&&) = delete;

    /// Builds the draw list of one frame (frames in time order: trails and markers remember).
    const DrawList& build(const FrameContent& frame);
    /// The layout a frame gets at this painter's level (nothing drawn).
    [[nodiscard]] virtual FrameLayout layout_for(const FrameContent& frame) const = 0;

    [[nodiscard]] const FrameLayout& layout() const noexcept { return layout_; }
    /// The strings drawn in the last built frame, by text slot (`--layout-json`).
    [[nodiscard]] const SlotTexts& drawn_text() const noexcept { return drawn_; }
    [[nodiscard]] const DrawList& draw_list() const noexcept { return list_; }
    [[nodiscard]] const RenderConfig& config() const noexcept { return config_; }

  protected:
    /// Validates `config` (throws collide::Error, input). The derived painter loads its fonts
    /// (load_font) and fills style_.
    explicit Painter(const RenderConfig& config);

    // The level's phases (build calls them in this order).
    /// After the layout, before any panel.
    virtual void begin_frame(const FrameContent& frame) = 0;
    /// Over a panel's discs, in its disc group: failure marks (and the lesson's queue).
    virtual void add_marks(std::size_t index, const PanelContent& content,
                           const PanelLayout& panel) = 0;
    /// A panel's text, after its discs.
    virtual void add_panel_text(std::size_t index, const PanelContent& content,
                                const PanelLayout& panel) = 0;
    /// The frame's own text and graphics, after every panel.
    virtual void finish_frame(const FrameContent& frame) = 0;

    enum class Font { body, head, small };
    enum class Align { left, centre, right };

    /// Loads a font of `pixel_height` into `slot` and gives it a text run in the draw list.
    void load_font(std::optional<FontAtlas>& slot, float pixel_height);
    /// Remembers `text` as drawn in `slot` (draw_text does; text drawn otherwise says so):
    /// in the layout's slot it is, or lies in (a slot made for a part of one: a queue node, the
    /// note beside its step indicator), else as text of its own. `continues`: the rest of the
    /// slot's last string (a figure's label after its value).
    void record_text(const TextSlot& slot, std::string_view text, bool continues = false);
    /// One line of text in `slot`, cut with an ellipsis where it would spill out; starts at `x`
    /// when given (left aligned). Returns the x after the last glyph.
    float draw_text(Font font, const TextSlot& slot, std::string_view text, Rgba8 color,
                    Align align = Align::left, float x = -1.0F);
    [[nodiscard]] const FontAtlas& atlas(Font font) const;
    // Failure marks and their legend at the levels with text (painter_marks.cpp; the shapes:
    // failure_marks.hpp; which failures get a mark: show::FailureMarks).
    /// How the marks look at this frame's text size, wall, margin and theme.
    [[nodiscard]] MarkStyle mark_style() const;
    /// The legend in `slot` from `x`: each kind with its symbol, then the count of the unmarked
    /// (ending by `unmarked_x1`, else left out: it stays under the panel it counts), then the
    /// wrap note, each entry whole or not at all. Returns the x after the last entry.
    float add_mark_legend(const TextSlot& slot, const MarkWords& words, float x,
                          float unmarked_x1 = std::numeric_limits<float>::max());
    /// The body font's pixel height, 0 without text.
    [[nodiscard]] float body_pixel_height() const noexcept;
    /// The boxes of a frame's panels (only their shapes matter to a layout).
    [[nodiscard]] static std::vector<Box> panel_boxes(const FrameContent& frame);
    /// A panel's engine colour in this theme (title swatch, cost bar, histogram, plot series).
    [[nodiscard]] Rgb8 accent(const PanelContent& panel) const noexcept;
    /// The panels' accents, in panel order: the colours of their plot series.
    [[nodiscard]] std::vector<Rgb8> accents(const FrameContent& frame) const;
    /// A colour of the colormap's part in use (colormap_low_ .. colormap_high_), t in [0, 1].
    [[nodiscard]] Rgb8 shown_colormap(double t) const noexcept;

    RenderConfig config_;
    Palette palette_;
    PanelStyle style_;
    std::optional<FontAtlas> body_font_;
    std::optional<FontAtlas> head_font_;
    std::optional<FontAtlas> small_font_;
    FrameLayout layout_;
    SlotTexts drawn_;
    DrawList list_;
    double colormap_low_ = 0.0;  // the part of the colormap in use
    double colormap_high_ = 1.0;
    bool colormap_clear_ = false;  // every colour of [low, high] has 3:1 contrast with the box

  private:
    void paint_panel(std::size_t index, const PanelContent& content, const PanelLayout& panel);
    void add_box(const PanelLayout& panel, const Box& box);
    void add_box_fill(RectF box);
    void add_discs(const Snapshot& snapshot, const PanelLayout& panel, const ReplayView& replay);
    void add_periodic_images(const DiscState& disc, const PanelLayout& panel, const Box& box,
                             Rgba8 color, float style);
    [[nodiscard]] Rgb8 disc_color(const DiscState& disc) const noexcept;
    /// The colour of a disc or sphere in the colour mode: from its scene colour, speed, mass
    /// or tag.
    [[nodiscard]] Rgb8 particle_color(Rgb8 color, double speed, double mass,
                                      bool tagged) const noexcept;
    /// A panel of spheres: the box's back edges, the lit spheres, the front edges.
    void add_spheres(const SphereView& view, const PanelLayout& panel, const Box& screen);

    std::vector<TrailHistory> trails_;
    std::vector<Rgb8> colors_;        // per-frame scratch
    std::vector<Rgb8> trail_colors_;  // per-frame scratch: legible trails
};

}  // namespace collide::render
