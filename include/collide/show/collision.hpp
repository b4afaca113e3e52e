#pragma once
/// \file
/// The collision video's program (`collide render` / `collide thumbnail`): every word and number
/// a class reads beside the discs, from the engines' measurements. Titles, the counters of the
/// full level, the lesson level's figures and compact line, the cost graphic's label, the step
/// note, the energy line and the clock. Pure functions of their arguments (unit-tested in
/// tests/show): the same measurements give the same strings, on any thread.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "collide/render_options.hpp"
#include "collide/scene.hpp"
#include "collide/show/timeline.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/measurements.hpp"
#include "collide/snapshot.hpp"
#include "collide/view/collision.hpp"

namespace collide::show {

/// When each frame is taken, in simulation time. Frame k is at exactly k * interval, except the
/// last one, which is at `last_time` (a thumbnail at a time between two frame times).
struct FrameClock {
    double interval = 1.0 / 30.0;  ///< simulation time between frames = speed / fps
    std::int64_t count = 1;        ///< frames, >= 1
    double last_time = 0.0;        ///< time of frame count - 1

    [[nodiscard]] double time(std::int64_t k) const noexcept {
        return k + 1 == count ? last_time : static_cast<double>(k) * interval;
    }
};

/// Relative tolerance for "dt divides the frame interval": far above rounding (1e-16) and far
/// below anything a viewer could see.
inline constexpr double divide_tolerance = 1e-6;

/// True when `dt` divides `interval` into a whole number of steps (relative tolerance 1e-6),
/// i.e. the time-driven engine lands on every frame time without a shorter final step.
[[nodiscard]] bool divides(double dt, double interval) noexcept;

/// dt as a class reads it: three significant digits ("0.05", "0.0125") where they are exact,
/// else a whole fraction when dt is one ("1/30" rather than "0.0333").
[[nodiscard]] std::string dt_text(double dt);

/// Panel titles of the full level.
[[nodiscard]] std::string time_panel_title(double dt);
[[nodiscard]] std::string event_panel_title(const EngineOptions& options);
/// Lesson-level titles, in plain words.
[[nodiscard]] std::string time_lesson_title(double dt);
[[nodiscard]] std::string event_lesson_title(const EngineOptions& options);
/// The title of a panel at an overlay level (the lesson's plain words, else the full level's).
/// `beside_code`: two panels share the width left of `--code`'s listing, so the lesson's titles
/// are short ("Time-driven: dt = 1/30", "Event-driven": the queue strip names the queue).
[[nodiscard]] std::string panel_title(bool time_driven, OverlayLevel level,
                                      const EngineOptions& options, bool beside_code = false);
/// The title of one of the time-driven panels a --dt list compares, at an overlay level: its
/// step in the full level's words ("Time-driven, dt = 0.01"), short enough for a third of the
/// frame's width.
[[nodiscard]] std::string compared_step_title(double dt, OverlayLevel level);
/// Its title where that does not fit: the step alone ("dt = 0.01"), the swatch saying which
/// engine.
[[nodiscard]] std::string compared_step_short_title(double dt);
/// The caption of a --dt list's video, in place of the scene's (which speak of two panels).
inline constexpr const char* step_list_caption =
    "Longer steps miss more collisions; shorter ones cost more work";
/// The event-driven panel's title beside them where its own does not fit.
inline constexpr const char* event_short_title = "Event-driven";
/// The cost graphic's label of such a panel: which step's pair tests the bar counts
/// ("dt = 0.01"; the heading above the bars says what work is).
[[nodiscard]] std::string compared_cost_label(double dt);
/// The note under the time-driven figures when dt is longer than a frame (empty otherwise): what
/// a class sees happen, "Moves only every 2nd frame", or "Moves on 2 of every 3 frames" when a
/// step is one and a half frames long.
[[nodiscard]] std::string step_note(double dt, double frame_interval);
/// Frames per step for the step indicator: n when a step is exactly n > 1 frames, else 1 (no
/// indicator: with 1.5 frames a step, the held frames do not repeat in a fixed pattern of one).
[[nodiscard]] int whole_frames_per_step(double dt, double frame_interval) noexcept;

/// A count on screen, in the one format of cards, panels and plots (collide::count_text):
/// "57,213", "1,234,567"; beyond 10^15, and for rates below one half, three significant digits
/// ("2.39e+17", "0.00042").
[[nodiscard]] std::string short_count(double value);

/// The clock's unit, under the lesson's clock: scenes are written in units of their own (a box 1
/// wide, speeds in box widths per time unit), so the clock says "time units", never seconds.
inline constexpr const char* time_unit = "time units";

/// The cost graphic's heading where no ratio of two engines stands under its bars (one panel).
inline constexpr const char* cost_heading = "Work so far";

/// The on-screen clock "t = 12.345   (1/s)": three decimals while they tell one frame from the
/// next and stay short (frame interval >= 1e-3, last frame before 1e6), else as many significant
/// digits as tell frames apart ("t = 4.9667e-11"): scenes in SI units span picoseconds, and
/// scenes in astronomical units 1e45 time units.
[[nodiscard]] std::string clock_label(double t, const FrameClock& clock, double speed);
/// The clock as a level shows it: the lesson column is narrow and the playback rate is no
/// lesson, so it shows the time alone ("t = 12.35": as many decimals as tell one frame from the
/// next, at most three; time_unit is a line of its own); the full level adds the rate.
[[nodiscard]] std::string clock_text(double t, const FrameClock& clock, double speed,
                                     OverlayLevel level);

/// The on-screen counter lines of one engine (full level).
[[nodiscard]] std::vector<std::string> time_driven_counters(const Measurements& m,
                                                            double energy_drift);
[[nodiscard]] std::vector<std::string> event_driven_counters(const Measurements& m,
                                                             double energy_drift);

/// Discs that tunnelled so far: out through a wall (`walls`: the box has walls) or through a
/// barrier of immovable discs (Measurements::tunnelled counts both; escaped discs alone count
/// where only they are known).
[[nodiscard]] std::uint64_t tunnelled_discs(const Measurements& m, bool walls) noexcept;

/// The lesson level's figures in plain words. `walls`: the box has walls (discs can leave it).
/// Discs that tunnelled (through a wall or a barrier) are a figure once there are any.
[[nodiscard]] std::vector<Figure> time_driven_figures(const Measurements& m, bool walls);
[[nodiscard]] std::vector<Figure> event_driven_figures(const Measurements& m);

/// Below this relative drift the energy is conserved up to round-off.
inline constexpr double round_off_drift = 1e-9;
/// One panel's largest relative energy drift so far.
struct EngineDrift {
    bool time_driven = false;
    double largest = 0.0;
};
/// The lesson level's energy line, naming the engine when the two panels differ: "Energy
/// conserved" (one panel), "Both conserve energy", "Time-driven: energy drifts", "Neither
/// conserves energy" (drift beyond round-off counts as not conserved); beyond two panels (a --dt
/// list) "All conserve energy" and "None conserves energy".
[[nodiscard]] std::string energy_line(const std::vector<EngineDrift>& panels);

/// The work of the cost graphic, in one unit on both sides: pair computations. The time-driven
/// engine's pair overlap tests (N(N-1)/2 a step) and its contact-time computations; the
/// event-driven engine's predictions (a collision time of a disc with a disc or a wall) and its
/// queue operations (pushes, pops and in-place updates, each a sift of up to log N levels). The
/// time-driven engine's per-disc wall checks (N a step, a comparison each) are not counted: that
/// leaves the ratio on the cautious side.
[[nodiscard]] double work_done(const Measurements& m, bool time_driven) noexcept;
/// The time-driven work as its panel's cost graphic shows it (work_done, in the panel's digits
/// and under its label), then what it is made of, for a summary printed beside the picture:
/// "3,056,956 pair tests: 3,056,625 overlap checks + 331 contact-time computations".
[[nodiscard]] std::string time_driven_work_line(const Measurements& m);
/// "168x less work": how many times less the event-driven engine did (`time_work` /
/// `event_work`, two significant digits below 10, a whole number above: one narrow line),
/// "2.5x more work"
/// when it did more, "" when either is zero (nothing to compare yet).
[[nodiscard]] std::string work_ratio(double time_work, double event_work);

/// What one panel says at one frame, from its engine's measurements.
struct PanelWords {
    std::vector<std::string> counters;  ///< full level
    std::vector<Figure> figures;        ///< lesson level
    std::string compact_line;           ///< compact lesson form: the one line
    std::string cost_label;             ///< the cost graphic's label
    double cost = 0.0;                  ///< the work it counts (work_done)
    std::string cost_text;              ///< the work in digits (cost_text, plot_words.hpp)
    std::string cost_words;             ///< the work in words (cost_in_words)
    std::string how;  ///< lesson level: why its work grows as it does (under the figures)
};
/// `drift`: the relative energy drift now; `walls`: the box has walls; `engine`: which
/// event-driven engine (the classic one predicts against every disc, the fast one its
/// neighbours).
[[nodiscard]] PanelWords panel_words(const Measurements& m, bool time_driven, bool walls,
                                     double drift, EngineKind engine = EngineKind::fast);

/// The scene's story and the lesson level's choices, resolved once for the whole video.
struct LessonPlan {
    std::string title;              ///< the intro card's title
    std::string description;        ///< the intro card's text
    double intro_seconds = 0.0;     ///< how long the card shows (0: none; videos only)
    double epilogue_seconds = 0.0;  ///< the summary card at the end (0: none; videos only)
    std::string caption;            ///< [render] caption, shown when no scripted caption applies
    /// The summary card's caption as the timeline (subtitles, chapters) has it, before the run's
    /// figures are known; the card itself says what they mean (show::epilogue_caption).
    std::string epilogue_caption = "In the end: the final figures";
    std::vector<CaptionCue> captions;  ///< [[render.captions]] within the video
    PlotSize histogram = PlotSize::none;
    int frames_per_step = 1;  ///< time-driven: the step indicator's period (whole_frames_per_step)
    std::string step_note;    ///< time-driven: the step note (step_note; empty: dt <= a frame)
    /// Failures replayed (show/replay.hpp: replay_cues), simulation frames increasing.
    std::vector<TimelineReplay> replays;
    /// Questions asked (show/questions.hpp), `at` increasing, with their answers once the
    /// engines have given them (until then, placeholders of the same timing).
    std::vector<TimelineQuestion> questions;
    /// Each question's cue as the scene wrote it (kind, words, where): one per `questions`.
    std::vector<QuestionCue> question_cues;

    /// The caption at `video_seconds`: the last cue at or before it, else `caption`.
    [[nodiscard]] const std::string& caption_at(double video_seconds) const noexcept;
    /// Seconds at the intro card's end over which it fades out (half a second, less on a short
    /// card; 0 without one).
    [[nodiscard]] double intro_fade_seconds() const noexcept;
    /// Opacity of the intro card at `video_seconds` (1, fading to 0 over intro_fade_seconds).
    [[nodiscard]] float intro_opacity(double video_seconds) const noexcept;
};

/// The collision video's timeline (timeline.hpp) of `frames` video frames at `fps`: the intro
/// card, then the simulation with the captions of `lesson`.
[[nodiscard]] Timeline lesson_timeline(const LessonPlan& lesson, int fps, std::int64_t frames);

/// Seconds of the intro card: about 2 s, at most a quarter of a short video.
inline constexpr double intro_seconds = 2.0;

/// The captions a video shows, each with where it was written (for an error naming it): the
/// caption line a whole frame wide must hold every one of them.
struct CaptionSource {
    std::string text;
    std::string file;  ///< "" when not read from a file
    int line = 0;
    std::string field;  ///< "render.caption", "render.captions.text" or the caption's file:line
};
/// `scene_caption_at`: the scene's RenderHints::caption_at ("file:line: render.caption"), if any.
[[nodiscard]] std::vector<CaptionSource> captions_shown(const LessonPlan& lesson,
                                                        const std::string& scene_caption_at);

/// The colour key's words for a colour mode: the speed or mass range (the video's fixed colour
/// scale) under the full level's bar, "slow".."fast" or "light".."heavy" at the lesson's, and
/// "tagged" beside the tag key. Scene colours need no key (all empty).
[[nodiscard]] ColorKeyWords color_key(ColorMode mode, double speed_min, double speed_max,
                                      double mass_min, double mass_max);

/// The queue picture's budget (`--queue K`): what fits in a strip under the boxes with its text at
/// the lesson's size (capitals 2.8 % of the frame height). A heap's tree down to the deepest level
/// with at most 8 nodes and at most 2 levels, an array queue's first 6 slots, and the next
/// `next_events` collisions in the box.
inline constexpr std::size_t queue_tree_level_nodes = 8;
inline constexpr unsigned queue_tree_levels = 2;
inline constexpr std::size_t queue_array_slots = 6;
[[nodiscard]] QueueViewLimits queue_picture(std::size_t next_events) noexcept;

/// The event-driven panel's next collision as the lesson draws it: `next` (what the engine
/// resolves next, sim::CollisionLookahead; next.t after snapshot.time) seen in `snapshot` (the
/// panel's state now): the line between the discs' centres, to the image of the partner it will
/// meet in a periodic box, or to the wall point it will touch, and its time to go with the
/// lesson clock's decimals ("next hit in 0.42", "next hit in < 0.01"). Empty for a 3D panel or
/// a record naming a disc the snapshot lacks.
[[nodiscard]] NextCollisionView next_collision_view(const CollisionRecord& next,
                                                    const Snapshot& snapshot,
                                                    const FrameClock& clock);
/// The words of the next collision's label for a time to go of `to_go`, with the decimals of the
/// lesson clock (clock_text) of `clock`.
/// `short_form`: "in 0.42", for a box too narrow for the whole line.
[[nodiscard]] std::string next_collision_words(double to_go, const FrameClock& clock,
                                               bool short_form = false);

/// The queue strip's words for `queue` at simulation time `now` (the snapshot's): the fast engine
/// (one event per disc) re-predicts a stale event, the classic engine throws it away; each event
/// shown gets its label ("3-7", "5 wall") and its time to go from `now`.
[[nodiscard]] QueueWords queue_words(const QueueView& queue, double now);

}  // namespace collide::show
