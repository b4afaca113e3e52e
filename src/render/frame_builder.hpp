#pragma once
// Internal: the CPU half of the renderer. Turns a FrameContent into a DrawList for GlTarget:
// computes the layout (layout.hpp), places the discs and the failure markers (which persist and
// fade over about a second of video), trails, text, the cost graphic and the plots. No GL.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "collide/render/renderer.hpp"
#include "draw_list.hpp"
#include "failure_marks.hpp"
#include "font.hpp"
#include "layout.hpp"
#include "plots.hpp"
#include "theme.hpp"
#include "trails.hpp"

namespace collide::render {

/// How long a failure marker stays on screen, in seconds of video (fading out).
inline constexpr double marker_seconds = 1.0;
/// At most this many failure markers per panel; the rest are counted ("+N more").
inline constexpr std::size_t max_markers = 30;

/// How long an event popped off a panel's queue stays highlighted, in seconds of video.
inline constexpr double queue_pop_seconds = 0.8;
/// The queue strip's small text against the lesson body text.
inline constexpr float queue_text_scale = 0.7F;

/// A failure marker remembered across frames (lesson level).
struct Marker {
    Vec2 where;         ///< box coordinates
    double born = 0.0;  ///< video seconds when it appeared
};

/// Failure markers of one panel, kept across frames so they persist and fade with video time.
class MarkerMemory {
  public:
    /// Adds the snapshot's missed collisions if the snapshot is a new state (its time changed;
    /// a held time-driven state is not counted again) and forgets markers older than
    /// marker_seconds at `video_time`.
    void update(const Snapshot& snapshot, double video_time);
    /// Markers alive at the last update, oldest first.
    [[nodiscard]] const std::vector<Marker>& markers() const noexcept { return markers_; }
    /// Opacity in [0, 1] of a marker at `video_time` (1 when new, 0 after marker_seconds).
    [[nodiscard]] static float opacity(const Marker& marker, double video_time) noexcept;

  private:
    std::vector<Marker> markers_;
    std::optional<double> last_time_;
};

class FrameBuilder {
  public:
    /// Loads the fonts the level needs. Throws collide::Error (input) for a bad config, (runtime)
    /// when the font cannot be loaded.
    explicit FrameBuilder(const RenderConfig& config);

    /// Builds the draw list of one frame (frames in time order: trails and markers remember).
    /// Throws collide::Error (input) when there are not 1 or 2 panels or one has no snapshot.
    const DrawList& build(const FrameContent& frame);

    /// The layout of the last built frame.
    [[nodiscard]] const FrameLayout& layout() const noexcept { return layout_; }
    /// The draw list of the last built frame.
    [[nodiscard]] const DrawList& draw_list() const noexcept { return list_; }
    /// The layout a frame would get (same rules as build, nothing drawn).
    [[nodiscard]] FrameLayout layout_for(const FrameContent& frame) const;
    [[nodiscard]] const RenderConfig& config() const noexcept { return config_; }

  private:
    enum class Font { body, head, small };
    enum class Align { left, centre, right };
    void build_panel(std::size_t index, const PanelContent& content, const PanelLayout& panel);
    void add_box(const PanelLayout& panel, const Box& box, float wall);
    void add_box_fill(RectF box);
    void add_discs(const Snapshot& snapshot, const PanelLayout& panel);
    void add_periodic_images(const DiscState& disc, const PanelLayout& panel, const Box& box,
                             Rgba8 color, float style);
    void add_classic_failures(const Snapshot& snapshot, const PanelLayout& panel, float wall);
    std::size_t add_lesson_failures(std::size_t index, const Snapshot& snapshot,
                                    const PanelLayout& panel);
    void add_full_header(const PanelContent& content, const PanelLayout& panel, std::size_t panels);
    void add_full_strip(const FrameContent& frame);
    void add_legend(RectF info);
    void add_lesson_panel_text(std::size_t index, const PanelContent& content);
    void add_unmarked_note(const PanelLayout& panel, std::size_t hidden);
    // The lesson's failure marks and their legend (failure_marks.cpp).
    [[nodiscard]] MarkStyle mark_style() const;
    void add_lesson_marks(const PanelContent& content, const PanelLayout& panel);
    void add_mark_legend(std::size_t index, const PanelContent& content);
    [[nodiscard]] static float edge_dash(float wall) noexcept;
    void add_column(const FrameContent& frame);
    // The event queue (Snapshot::queue; frame_builder_queue.cpp).
    void add_queue_in_box(const Snapshot& snapshot, const PanelLayout& panel);
    void add_queue_strip(const Snapshot& snapshot, const QueueWords& words, RectF strip);
    void add_popped(const QueueView& queue, const QueueWords& words, double now, RectF area);
    void add_queue_tree(const QueueView& queue, const QueueWords& words, double now, RectF area);
    void add_queue_row(const QueueView& queue, const QueueWords& words, double now, RectF area);
    void add_leaving_root(const QueueView& queue, const QueueWords& words, double now, PointF root,
                          float node_w, float node_h);
    void add_queue_node(const QueuedEvent& event, const QueueWords& words, double now, RectF node,
                        Rgba8 frame_color, bool stale);
    /// A label centred at `at` on a plate of the box colour, kept inside `inside`.
    void add_plate_label(Font font, PointF at, std::string_view text, Rgba8 color, RectF inside);
    [[nodiscard]] float pop_highlight(const QueuedEvent& popped, double now) const noexcept;
    [[nodiscard]] Rgba8 next_color() const noexcept;
    /// A queue node as wide as the widest label among `events` (and a time to go).
    [[nodiscard]] float node_width(const std::vector<QueuedEvent>& events) const;
    void add_intro(const FrameContent& frame);
    float draw_text(Font font, const TextSlot& slot, std::string_view text, Rgba8 color,
                    Align align = Align::left, float x = -1.0F);
    [[nodiscard]] const FontAtlas& atlas(Font font) const;
    [[nodiscard]] int counter_rows(const FrameContent& frame) const;
    [[nodiscard]] Rgba8 counter_color() const noexcept;
    [[nodiscard]] int panel_counter_columns(std::size_t panels) const;
    [[nodiscard]] Rgb8 disc_color(const DiscState& disc) const noexcept;
    [[nodiscard]] Rgb8 shown_colormap(double t) const noexcept;
    void choose_colormap_range();

    RenderConfig config_;
    Palette palette_;
    std::optional<FontAtlas> body_font_;
    std::optional<FontAtlas> head_font_;
    std::optional<FontAtlas> small_font_;  // loaded with the first queue to draw
    std::vector<TrailHistory> trails_;
    std::vector<MarkerMemory> markers_;
    FrameLayout layout_;
    DrawList list_;
    std::vector<Rgb8> colors_;        // per-frame scratch
    std::vector<Rgb8> trail_colors_;  // per-frame scratch: lesson trails (legible_trails)
    double video_time_ = 0.0;
    double speed_ = 0.0;         // simulation time per second of video (FrameContent::speed)
    std::vector<RectF> labels_;  // queue labels placed in the current box (add_plate_label)
    double colormap_low_ = 0.0;  // the part of the colormap in use (choose_colormap_range)
    double colormap_high_ = 1.0;
    bool colormap_clear_ = false;  // every colour of [low, high] has 3:1 contrast with the box
    bool intro_ = false;           // the title card covers this frame: no other text
    int counter_rows_ = 0;
};

}  // namespace collide::render
