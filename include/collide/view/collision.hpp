#pragma once
/// \file
/// The views of a collision video: what the renderer paints for one frame (render::Renderer),
/// filled by the presentation layer (src/show, collide_show) from the engines' snapshots and
/// measurements. Plain values (types layer): no GL, no simulation code.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "collide/disc.hpp"
#include "collide/render_options.hpp"
#include "collide/snapshot.hpp"
#include "collide/view/code.hpp"
#include "collide/view/plots.hpp"
#include "collide/view/spheres.hpp"

namespace collide {

/// A headline figure of the lesson level: a big number and its label in plain words.
struct Figure {
    std::string value;     ///< "1,234"
    std::string label;     ///< "collisions missed"
    bool failure = false;  ///< drawn in the failure colour when the value is not zero
};

/// The words of the queue strip (`--queue`) that say how the engine treats its queue: the fast
/// engine holds one event per disc and re-predicts, the classic one throws stale events away
/// (filled by show::queue_words from the snapshot's QueueView), and the label and time to go of
/// every event it draws.
struct QueueWords {
    std::string heading;        ///< "Event queue: binary heap, 1,234 entries, 56 stale"
    std::string legend;         ///< "Next 5 collisions, time to go" (the lines in the box)
    std::string stale_popped;   ///< after a stale event in the list of pops
    std::string stale_leaving;  ///< on a stale event leaving the root ("skipped")
    std::string counts;         ///< under the pops: "3 of 40 pops stale"
    /// The counts in two lines, for a list too narrow for them in one (beside one box, late in
    /// a long run): {"316,487 pops", "65,796 stale"}; the first alone where one line is left.
    std::vector<std::string> counts_lines;
    std::string popped_heading;   ///< over the pops: "Popped (newest first)"
    std::string resolved_popped;  ///< after a collision in the list of pops ("  resolved")
    std::string crossing_popped;  ///< after a cell crossing in the list of pops ("  crossing")
    std::string stale_slot;       ///< under a stale event in the queue, for its time ("stale")
    std::string fresh_leaving;    ///< on a valid event leaving the root ("popped")
    std::string below;            ///< beside a heap's top levels: "+1,178 below" (or empty)
    std::string row_caption;      ///< over an array queue's slots: where its next event is
    /// The heading and the pops' heading in fewer words, for a strip too narrow for them (beside
    /// one box at the small presets): "Binary heap, 1,234 entries", "Popped".
    std::string short_heading;
    std::string short_popped_heading;
    // Each event shown, in the order of the QueueView's lists: what it involves ("3-7",
    // "5 wall", "5 cell") and its time to go at the snapshot's time ("0.42", "3.1e-05").
    std::vector<std::string> next_times;  ///< in the box: one per QueueView::next
    /// In the box, under the next event's discs: their numbers ("14"; a pair's two).
    std::vector<std::string> next_discs;
    /// In the box, beside the discs of the other events listed (QueueView::next after the
    /// first), each disc once and none of the next event's: the disc and its number.
    struct NumberedDisc {
        std::uint32_t disc = 0;
        std::string number;
    };
    std::vector<NumberedDisc> listed_discs;
    std::vector<std::string> slot_labels;    ///< one per QueueView::slots
    std::vector<std::string> slot_times;     ///< one per QueueView::slots
    std::vector<std::string> popped_labels;  ///< one per QueueView::popped
};

/// What the disc colours mean, in words (filled by show::color_key from the colour mode and its
/// range): the lesson column's colour bar has its ends named, the full level's strip its range
/// under the bar, or its key of tagged discs. An empty string draws nothing.
struct ColorKeyWords {
    std::string low;         ///< lesson: at the bar's left end ("slow", "light")
    std::string high;        ///< lesson: at the bar's right end ("fast", "heavy")
    std::string quantity;    ///< full: under the bar's middle ("speed", "mass (log)")
    std::string low_value;   ///< full: under the bar's left end, the range's low ("0")
    std::string high_value;  ///< full: under the bar's right end, the range's high ("1.5")
    std::string tagged;      ///< full, tag colours: beside the key's swatch ("tagged")
};

/// One line of a summary card: a label, then one value per panel ("collisions missed", "48", "0").
struct SummaryRow {
    std::string label;
    std::vector<std::string> values;
};

/// The epilogue's card: the final figures of the panels side by side, for a lecturer to leave on
/// screen.
struct SummaryCard {
    std::string title;                 ///< "In the end, after t = 3.000"
    std::vector<std::string> columns;  ///< one heading per panel, in panel order
    std::vector<SummaryRow> rows;      ///< empty: no card
    std::string footer;                ///< one line under the table (the work ratio)
    /// One line under the footer saying why the collision counts differ ("" when they agree).
    std::string note;
    float opacity = 0.0F;  ///< fading in over its first half second
};

/// The kinds of failure a lesson marks, each with a mark of its own (the legend names them).
enum class FailureKind : std::uint8_t {
    missed,       ///< a collision the time-driven engine stepped over: a ring where it happened
    overlapping,  ///< two discs overlapping now: a cross on the pair
    left_box,     ///< a disc that left a walled box: an arrow out of the edge where it left
    tunnelled,    ///< a disc that went through a barrier between two checks: a diamond round it
};

/// How many kinds of failure there are (FailureKind's values, 0 .. failure_kinds - 1).
inline constexpr std::size_t failure_kinds = 4;

/// One failure mark in a panel's box (lesson level). Which failures get one is decided by the
/// presentation layer (show::FailureMarks); the renderer paints what it is handed.
struct FailureMark {
    FailureKind kind = FailureKind::missed;
    Vec2
        where;  ///< box coordinates: the collision, the pair's midpoint, the exit point on the edge
    Vec2 out;   ///< left_box: outward normal of the edge crossed, (+-1, 0) or (0, +-1)
    double size = 0.0;     ///< box units: the mark's radius (missed, overlapping)
    float opacity = 1.0F;  ///< 1 when new; a missed ring fades to 0 over its second of video
};

/// One entry of a panel's mark legend: a kind's mark and its name.
struct MarkLegendItem {
    FailureKind kind = FailureKind::missed;
    std::string name;  ///< "missed collision"
};

/// The words of a panel's mark legend (a line under its figures, outside the box).
struct MarkWords {
    std::vector<MarkLegendItem> items;  ///< the kinds marked so far, in order of first appearance
    std::string wraps;     ///< periodic box, said once (first panel): "edges wrap around"
    std::string unmarked;  ///< failures this frame without a mark: "and 12 more"
};

/// A part of a panel's box shown enlarged (a replay's zoom): the box point drawn at the centre
/// of the panel's box rectangle, and how many times larger than the whole box it is drawn.
struct BoxZoom {
    Vec2 centre;
    double magnification = 1.0;  ///< 1: the whole box, as always
    [[nodiscard]] bool active() const noexcept { return magnification > 1.0; }
};

/// A disc drawn where it was or where it went (a replay's ghosts), box coordinates.
struct GhostDisc {
    Vec2 where;
    double radius = 0.0;   ///< box units
    bool filled = false;   ///< filled (a disc in motion) or an outline (a state checked)
    bool failure = false;  ///< in the failure colour (else the text colour)
    float opacity = 1.0F;
};

/// How a BoxLine is drawn.
enum class LineStyle : std::uint8_t {
    jump,       ///< thick, an arrowhead at `to` (a replay's move), in the text colour
    motion,     ///< a question's disc velocity: an arrowhead at `to`, in the motion colour
    connector,  ///< thin, no head: a question's candidate contact, in its candidate's colour
};

/// No candidate's colour (BoxLine::tint, BoxLabel::tint).
inline constexpr int no_tint = -1;

/// A straight segment in the box (a replay's jump, a question's lines), box coordinates.
struct BoxLine {
    Vec2 from;
    Vec2 to;
    bool failure = false;  ///< in the failure colour (before any other)
    float opacity = 1.0F;
    LineStyle style = LineStyle::jump;
    /// A next-collision question's candidate (0: A, 1: B, ...): its lines and its letter share
    /// that candidate's colour, so that a class tells the candidates apart where they sit close.
    int tint = no_tint;
};

/// Where a label's plate sits around its point (`over`: centred on it, a place chosen clear of the
/// discs by the presentation layer).
enum class LabelSide : std::uint8_t { above, below, left, right, over };

/// Words at a point of the box (a replay's labels), drawn on a plate on one side of `at`, clear
/// of a disc of radius `clear` there.
struct BoxLabel {
    Vec2 at;
    std::string text;
    bool failure = false;  ///< in the failure colour (else the tint's, else the text colour)
    LabelSide side = LabelSide::above;
    float opacity = 1.0F;
    double clear = 0.0;  ///< box units: the plate keeps this far from `at`
    int tint = no_tint;  ///< a question's candidate: its letter in that candidate's colour
};

/// A disc's place in the box that words must not cover, box coordinates.
struct BoxCircle {
    Vec2 centre;
    double radius = 0.0;  ///< box units
};

/// The event-driven panel's next collision (lesson level, without the queue strip): one thin
/// line from a disc's centre to its partner's (periodic box: to the image it will meet, and from
/// the partner back to this disc's image, each cut at the box by the painter) or to the point of
/// the wall it will touch, with its time to go on a plate that keeps clear of the discs. Filled
/// by show::next_collision_view.
struct NextCollisionView {
    std::vector<BoxLine> lines;         ///< empty: nothing drawn
    std::string text;                   ///< "next hit in 0.42"
    std::string short_text;             ///< "in 0.42": where the box is too narrow for `text`
    Vec2 label_at;                      ///< the line's middle: the label's place when it is free
    std::vector<BoxCircle> keep_clear;  ///< the colliding discs: the label never covers them
    [[nodiscard]] bool empty() const noexcept { return lines.empty(); }
};

/// What a replay draws over one panel's box (lesson level): filled by show::replay_views.
struct ReplayView {
    std::string heading;  ///< at the top of the box ("Replay: one step, 9x enlarged")
    std::vector<GhostDisc> ghosts;
    std::vector<BoxLine> lines;
    std::vector<BoxLabel> labels;
    /// The failure's discs (Snapshot::discs indices): the others are drawn faint. Empty: none.
    std::vector<std::uint32_t> focus;
    /// Discs left out of the snapshot's picture (the ghosts show them instead).
    std::vector<std::uint32_t> hidden;
    /// Discs the heading must not cover (a question's: every disc of the frozen frame). Empty:
    /// the heading sits at the top of the box; else there where that plate is clear of these
    /// circles and of the labels, or at the nearest clear place (the painter measures the words).
    std::vector<BoxCircle> keep_clear;
    [[nodiscard]] bool empty() const noexcept {
        return heading.empty() && ghosts.empty() && lines.empty() && labels.empty() &&
               focus.empty() && hidden.empty();
    }
};

/// One simulation shown in one panel.
struct PanelContent {
    PanelContent() = default;
    /// The full level's content (what every level needs: the snapshot and a title).
    PanelContent(const Snapshot* snapshot_, std::string title_,
                 std::vector<std::string> counters_ = {})
        : snapshot(snapshot_), title(std::move(title_)), counters(std::move(counters_)) {}

    const Snapshot* snapshot = nullptr;  ///< not owned; must stay valid during render()
    /// A panel of spheres (3D scene): drawn instead of the snapshot's discs, which then stand in
    /// for the spheres (projected positions, the spheres' speeds) and its box is the screen box
    /// the camera sees. nullptr for discs. Not owned; must stay valid during render().
    const SphereView* spheres = nullptr;
    std::string title;  ///< e.g. "Event-driven: priority queue of collisions"
    /// Lesson level: drawn instead of `title` where that does not fit its line (empty: none).
    std::string short_title;
    std::vector<std::string> counters;  ///< full level: lines under the title ("collisions 1234")
    std::vector<Figure> figures;        ///< lesson level: two or three, most important first
    std::string compact_line;           ///< compact lesson form: the one line (failure count)
    std::string note;                   ///< lesson level: a line under the figures (dt > frame)
    /// Lesson level, two panels: why this engine's work grows as it does, a line under the
    /// figures ("Each step tests all N^2/2 pairs").
    std::string how;
    /// Step indicator beside the note: the time-driven state changes every `step_period` frames
    /// and this frame is `step_phase` (0 = a new step) of them. Period 1 draws none.
    int step_period = 1;
    int step_phase = 0;
    std::string cost_label;  ///< the cost graphic's label ("pair tests")
    double cost = 0.0;       ///< work done so far, on the graphic's shared scale
    std::string cost_text;   ///< the cost under its bar: "12,345,678"
    std::string cost_words;  ///< instead, where its digits do not fit: "12.3 million"
    /// Which engine: the time-driven one, or the event-driven one. The painter draws each in its
    /// theme's colour (title swatch, bar, histogram, plot series).
    bool time_driven = true;
    QueueWords queue_words;  ///< the queue strip's words (snapshot->queue set)
    /// The listed events' disc numbers and times in the box (snapshot->queue set). A question
    /// leaves them out: they would tell its answer and lie under its letters.
    bool queue_in_box = true;
    /// Lesson level: the failure marks in the box (the full level marks from the snapshot).
    std::vector<FailureMark> marks;
    MarkWords mark_words;    ///< the mark legend's words
    bool mark_line = false;  ///< reserve the legend's line (the same on every frame of a video)
    /// Lesson level, during a replay: the part of the box drawn enlarged (inactive: all of it)
    /// and what the replay draws over it.
    BoxZoom zoom;
    ReplayView replay;
    /// Lesson level, event-driven panel: the collision it resolves next (empty: none drawn).
    NextCollisionView next_collision;
};

/// One sample of an energy drift series: relative drift (E(t) - E(0)) / E(0) at time t.
struct DriftPoint {
    double time = 0.0;
    double drift = 0.0;
};

/// The most panels a frame holds: four time-driven steps (a --dt list) beside the event-driven one.
inline constexpr std::size_t max_frame_panels = 5;

/// Everything drawn in one frame. Panels are laid out left to right in the given order (1 to
/// max_frame_panels; convention: time-driven left, event-driven right). Full level: failure markers
/// are drawn for any panel whose snapshot carries them (overlapping_pairs, missed_collisions,
/// escaped discs); lesson level: the panel's `marks`.
/// How long a popped event stays highlighted on a panel's queue, in seconds of video (the
/// presentation layer decides: show::pop_highlight_seconds); 0: not at all.
struct PopHighlight {
    double valid = 0.0;  ///< an event that was resolved
    double stale = 0.0;  ///< an event thrown away as invalidated
};

struct FrameContent {
    std::vector<PanelContent> panels;
    std::string time_text;  ///< e.g. "t = 3.25   (x0.5 speed)"
    std::string time_unit;  ///< lesson level: a line under the clock ("time units"; "" for none)
    /// One series per panel (same order as `panels`; may be empty or shorter), oldest first.
    std::vector<std::vector<DriftPoint>> energy_drift;
    std::vector<std::string> notes;  ///< full level: notice line(s) at the bottom
    std::string caption;             ///< lesson level: the caption line at the bottom
    std::string energy_line;         ///< lesson level: "Energy conserved" (empty: the drift plot)
    std::string cost_heading;  ///< lesson level, one panel: the cost graphic's heading ("" none)
    ColorKeyWords color_key;   ///< what the disc colours mean (colour bar or tag key)
    /// Under the bars, two panels: "168x less work" (show::work_ratio of the panels' costs).
    std::string cost_ratio;
    double video_time = 0.0;  ///< seconds of video at this frame: failure markers fade by it
    /// Simulation time per second of video (0: unknown). A panel's queue (Snapshot::queue) keeps
    /// a popped event highlighted for `pop_highlight` seconds of video by it.
    double speed = 0.0;
    PopHighlight pop_highlight;
    /// Lesson level: the speed histogram of moving discs in the column (large: it is the subject).
    PlotSize histogram = PlotSize::none;
    bool energy_plot = false;   ///< lesson level: the energy drift plot (energy not conserved)
    SpeedPlotWords speed_plot;  ///< the speed plot's words (the video's, fixed)
    DriftPlotWords drift_plot;  ///< the drift plot's scale and title (of `energy_drift`)
    /// The scene's title card (intro): drawn over the frame with this opacity (0 = none).
    std::string intro_title;
    std::string intro_text;
    float intro_opacity = 0.0F;
    /// The epilogue's summary card, drawn over the frame (empty rows: none).
    SummaryCard summary;
    /// Lesson level, `--code`: the event-driven loop's pseudocode in a column on the right, the
    /// line under way marked; unset: no column (the frame as without the option).
    std::optional<view::CodeView> code;
};

}  // namespace collide
