#pragma once
// Internal: the painter of overlay level lesson (docs/renderer.md): per panel a title line above
// its box and a row of headline figures below it, a column beside the boxes (clock, cost graphic,
// energy, colour legend, plot), a caption line, the title card, the failure marks chosen by the
// presentation layer (a ring, a cross, an arrow out of the edge) with their legend under the
// box, and the event queue (`--queue`). Below compact_width one line of text per panel. Its
// files: lesson_painter.cpp (the phases, panel text), lesson_layout.cpp (where things go),
// lesson_marks.cpp (the marks' style and legend), lesson_column.cpp (column and title card),
// lesson_queue.cpp (the event queue), lesson_replay.cpp (a replay's marks), lesson_next.cpp
// (the next collision line).

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "failure_marks.hpp"
#include "painter.hpp"

namespace collide::render {

/// The queue strip's small text against the lesson body text.
inline constexpr float queue_text_scale = 1.0F;

/// The part of segment a-b inside r (Liang-Barsky); false when none is.
bool clip_to(RectF r, PointF& a, PointF& b);

class LessonPainter : public Painter {
  public:
    /// Loads the body font (and the headline font outside the compact form). Throws
    /// collide::Error (runtime) when the font cannot be loaded.
    explicit LessonPainter(const RenderConfig& config);

    [[nodiscard]] FrameLayout layout_for(const FrameContent& frame) const override;

  private:
    /// The width of the column beside a crowded queue box for its discs' numbers (0: the box
    /// has room for them inside).
    [[nodiscard]] float number_column_width(const Snapshot& snapshot) const;
    void begin_frame(const FrameContent& frame) override;
    void add_marks(std::size_t index, const PanelContent& content,
                   const PanelLayout& panel) override;
    void add_panel_text(std::size_t index, const PanelContent& content,
                        const PanelLayout& panel) override;
    void finish_frame(const FrameContent& frame) override;

    void choose_colormap_range();
    /// The headline figures in `slot`; when some continued on `overflow` (the how line), the x
    /// where they end there, else nothing.
    std::optional<float> add_figures(const std::vector<Figure>& figures, const TextSlot& slot,
                                     const TextSlot* overflow);
    /// A panel's mark legend on its own line under the figures (the look: Painter).
    void add_mark_legend(std::size_t index, const PanelContent& content);
    // The column and the title card (lesson_column.cpp).
    void add_column(const FrameContent& frame);
    /// --code: the pseudocode column (code_panel.hpp) in the layout's `code` rectangle.
    void add_code(const view::CodeView& code);
    void add_intro(const FrameContent& frame);
    void add_summary(const FrameContent& frame);  // the epilogue's card (lesson_summary.cpp)
    // The event queue (Snapshot::queue; lesson_queue.cpp).
    void add_queue_in_box(const Snapshot& snapshot, const QueueWords& words,
                          const PanelLayout& panel);
    void add_queue_strip(const Snapshot& snapshot, const QueueWords& words, RectF strip);
    void add_popped(const QueueView& queue, const QueueWords& words, double now, RectF area);
    /// The width the latest pops' words need in a list `height` px tall (heading, pops, counts).
    [[nodiscard]] float popped_width(const QueueView& queue, const QueueWords& words,
                                     float height) const;
    /// The list's heading: the whole one where it fits `room` px, else the short one.
    [[nodiscard]] const std::string& popped_heading(const QueueWords& words, float room) const;
    void add_queue_tree(const QueueView& queue, const QueueWords& words, double now, RectF area);
    void add_queue_row(const QueueView& queue, const QueueWords& words, RectF area);
    /// The event just popped, in `node` left of the heap's root node `root`.
    void add_leaving_root(const QueueView& queue, const QueueWords& words, double now, RectF root,
                          RectF node);
    /// The width of the node of the event just popped; 0 when none is shown.
    [[nodiscard]] float leaving_width(const QueueView& queue, const QueueWords& words, double now,
                                      bool one_line) const;
    /// A slot of the queue: the event's label over its time to go (or the stale word).
    void add_queue_node(std::string_view label, std::string_view time, RectF node,
                        Rgba8 frame_color, bool stale);
    /// A replay's ghosts, jump and labels over a (zoomed) box (lesson_replay.cpp).
    void add_replay(const ReplayView& replay, const PanelLayout& panel, const Box& box);
    /// The event-driven panel's next collision: a thin line and its time to go (lesson_next.cpp),
    /// the label placed clear of `all_discs` where it can be.
    void add_next_collision(const NextCollisionView& next, const std::vector<DiscState>& all_discs,
                            const PanelLayout& panel, const Box& box);
    /// A label centred at `at` on a plate of the box colour, kept inside `inside`.
    void add_plate_label(Font font, PointF at, std::string_view text, Rgba8 color, RectF inside);
    /// A queue label on a plate near `at`, clear of every disc and earlier label in `inside`,
    /// with a leader line towards `anchor` (stopping `anchor_radius` short: a disc's edge) when
    /// it had to move away; none where no free place is near (the strip names the event).
    void add_queue_label(Font font, PointF at, PointF anchor, float anchor_radius,
                         std::string_view text, Rgba8 color, RectF inside);
    /// Where a number outside `own_box` must not go: the boxes (another panel's with the frame
    /// over and under it), the code, the strip, the column's graphics and the text drawn so far.
    [[nodiscard]] std::vector<RectF> frame_obstacles(RectF own_box) const;
    /// The numbers add_queue_in_box could not place in their box, placed in the frame
    /// (add_frame_label) after every other text of the frame is drawn.
    void add_frame_numbers();
    /// The numbers of frame_numbers_ that fit whole in the column right of `box` (beside it,
    /// clear of `obstacles`), stacked in the order of their discs' heights so that the leaders
    /// do not cross, each as near its disc's height as the others let it; the others (a column
    /// too short for all) keep their place in frame_numbers_, the next pair's placed first.
    void add_column_numbers(RectF box, const std::vector<RectF>& obstacles);
    /// A number's plate outside its box, with its leader: from the plate (`from`) to the box's
    /// edge (`elbow`), then inside the box to the disc's edge.
    void draw_frame_number(Font font, std::string_view text, Rgba8 color, RectF plate, PointF from,
                           PointF elbow, PointF disc, float radius);
    /// A disc's number in the frame outside the boxes (a box too crowded for a free place
    /// beside the disc): the place nearest the disc clear of `obstacles` and earlier labels,
    /// with a leader line to the nearest point of `box`'s edge, then inside it to the disc's
    /// edge; none where the frame has no such place. O(rows x obstacles).
    void add_frame_label(Font font, PointF disc, float radius, std::string_view text, Rgba8 color,
                         RectF box, const std::vector<RectF>& obstacles);
    [[nodiscard]] float pop_highlight(const QueuedEvent& popped, double now) const noexcept;
    [[nodiscard]] Rgba8 next_color() const noexcept;
    /// A queue node as wide as the widest of `labels` (and a time to go: beside the label when
    /// `one_line`, else under it).
    [[nodiscard]] float node_width(const std::vector<std::string>& labels, bool one_line) const;
    /// Whether queue nodes `height` px tall set label and time on one line (a short strip).
    [[nodiscard]] bool one_line_nodes(float height) const;

    double video_time_ = 0.0;
    double speed_ = 0.0;             // simulation time per second of video (FrameContent::speed)
    PopHighlight pop_seconds_;       // how long a pop stays lit (FrameContent::pop_highlight)
    std::vector<RectF> labels_;      // queue labels placed in the current box (add_plate_label)
    std::vector<RectF> disc_rects_;  // the discs of the current box, which labels keep clear of
    /// A disc's number waiting for a place outside its box (add_frame_numbers).
    struct FrameNumber {
        Font font;
        PointF disc;   // the disc's centre (px)
        float radius;  // px
        std::string text;
        Rgba8 color;
        RectF box;  // the disc's box
    };
    std::vector<FrameNumber> frame_numbers_;
    /// The notes drawn in this frame, each from its slot's left edge to the end of its step
    /// indicator (or its words): what a number keeps clear of in a note's row.
    std::vector<RectF> notes_;
    bool intro_ = false;  // the title card covers this frame: no other text
};

}  // namespace collide::render
