#pragma once
/// \file
/// The collision video's program (`collide render` / `collide thumbnail`), the way HeapProgram
/// and PuzzleProgram are the heap's and the puzzle's: what a class sees in frame k, decided here.
///
///   CollisionSimulation   owns the engines (time-driven and/or event-driven), advances them to
///                         the time frame k shows and describes their state: snapshots, figures,
///                         titles, the next collision (runs on the app's simulation thread)
///   CollisionProgram      turns that state into the frame's view (FrameContent): which card,
///                         caption, replay, marks, histogram, code column, clock and summary
///                         the frame carries (runs on the thread that paints)
///
/// The choices made once for the whole video (the intro and summary cards, the captions and
/// their holds, the histogram, the trails, the replays; what each overlay level shows) are the
/// functions at the end. Deterministic: the same scene and settings give the same frames
/// (on-screen figures are counts, never wall-clock times). No GL, no CLI: src/app resolves the
/// options into CollisionSettings and runs the job.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "collide/render_options.hpp"
#include "collide/scene.hpp"
#include "collide/scene3.hpp"
#include "collide/show/collision.hpp"
#include "collide/show/failure_marks.hpp"
#include "collide/show/questions.hpp"
#include "collide/show/replay.hpp"
#include "collide/show/scene_view.hpp"
#include "collide/show/sphere_camera.hpp"
#include "collide/show/timeline.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/lookahead.hpp"
#include "collide/snapshot.hpp"
#include "collide/view/collision.hpp"

namespace collide::show {

/// What each overlay level shows of the lesson, in one place (the app checks options against
/// it; the program and the cards follow it).
struct LevelShows {
    bool text = false;            ///< any words or figures at all (none: the discs alone)
    bool cards = false;           ///< the intro card and the summary card at the end
    bool caption_holds = false;   ///< captions shown, so a hold may freeze the picture for them
    bool captions = false;        ///< captions drawn in the picture: a subtitle track starts off
    bool queue = false;           ///< --queue's strip (and --code's column beside it)
    bool replays = false;         ///< a replay of the time-driven panel's failures
    bool next_collision = false;  ///< the event-driven panel's next collision line (2D)
    bool time_unit = false;       ///< the clock's unit under it, the clock without its rate
};
[[nodiscard]] LevelShows level_shows(OverlayLevel level) noexcept;

/// The video's options as the collision program needs them, resolved once (src/app's
/// RenderPlan). Every field is valid once filled by the app.
struct CollisionSettings {
    OverlayLevel level = OverlayLevel::lesson;
    bool time_panels = true;     ///< time-driven panel(s): --mode both or time
    bool event_panel = true;     ///< the event-driven panel: --mode both or event
    EngineOptions event_engine;  ///< engine fast or classic
    EngineOptions time_engine;   ///< engine time, with its dt
    /// A --dt list: one time-driven panel per step, in the order given; empty: one, time_engine.
    std::vector<double> time_steps;
    std::size_t queue_events = 0;  ///< --queue: upcoming events shown (0: no strip)
    bool code = false;             ///< --code: the event-driven loop beside the queue
    int fps = 30;
    double speed = 1.0;  ///< simulation time per second of video
    FrameClock clock;    ///< the simulation frames
    Timeline timeline;   ///< the video frames: which simulation frame each shows, and why
    LessonPlan lesson;   ///< the lesson's cards, captions, histogram, step note
    std::vector<ReplayFailure> replays;  ///< the failures replayed, in the video's order
    /// The questions' answers, indexed like lesson.questions (show/questions.hpp).
    std::vector<QuestionAnswer> questions;
    /// The colour scale (fixed for the whole video) and its words.
    ColorMode color_mode = ColorMode::scene;
    double speed_min = 0.0;
    double speed_max = 1.0;
    double mass_min = 1.0;
    double mass_max = 1.0;
    /// A 3D scene's camera.
    CameraMotion camera = CameraMotion::fixed;
    Projection projection = Projection::orthographic;
    double slab = 0.0;
};

/// One simulation's state at a frame time, with its on-screen figures.
struct PanelState {
    /// The engine's discs; for a 3D scene the discs standing in for its spheres on the screen
    /// (show::project), and `view` the spheres themselves.
    Snapshot snapshot;
    bool spheres = false;  ///< a 3D scene: `view` is drawn
    SphereView view;
    std::string title;
    std::string short_title;  ///< drawn where `title` does not fit (empty: none)
    DriftPoint drift;         ///< (KE - KE0) / KE0 at this frame
    bool time_driven = false;
    /// A --dt list: this time-driven panel's step, for the epilogue's column; 0 otherwise.
    double compared_dt = 0.0;
    std::string note;           ///< time-driven: its step note (step_note; empty: none)
    int frames_per_step = 1;    ///< time-driven: its step indicator's period
    PanelWords words;           ///< counters, figures, compact line, cost
    Measurements measurements;  ///< the engine's, at this frame (the epilogue's card)
    QueueWords queue_words;     ///< the queue strip's (snapshot.queue set)
    /// Lesson level, event-driven panel without the queue: the collision it resolves next.
    NextCollisionView next_collision;
};

/// The engines' state at one video frame: what the simulation thread hands to the painting one.
struct CollisionState {
    std::int64_t index = 0;          ///< the video frame
    std::int64_t sim_frame = 0;      ///< the simulation frame it shows (settings.timeline)
    double time = 0.0;               ///< the simulation time it shows
    bool moved = true;               ///< a new state: not a repeat of the previous frame's
    std::vector<PanelState> panels;  ///< time-driven first, then event-driven
};

/// Owns the engines of a video and describes their state at each frame, in order.
class CollisionSimulation {
  public:
    /// Builds the engines (time-driven and/or event-driven per the settings). Throws
    /// Error(input) for engine options make_engine rejects. Once `stop` is set (nullptr: never),
    /// state() throws Error(runtime) within a few thousand events, however far its frame time.
    /// `settings` must outlive the simulation.
    CollisionSimulation(SceneView scene, const CollisionSettings& settings,
                        const std::atomic<bool>* stop = nullptr);
    ~CollisionSimulation();
    CollisionSimulation(const CollisionSimulation&) = delete;
    CollisionSimulation& operator=(const CollisionSimulation&) = delete;

    /// Advances every engine to the simulation time video frame k shows (settings.timeline;
    /// k = 0, 1, 2, ... each once, in order: the next collision line runs an engine a frame
    /// early) and describes the frame.
    [[nodiscard]] CollisionState state(std::int64_t k);
    /// Measurements of each engine now, in panel order.
    [[nodiscard]] std::vector<Measurements> measurements() const;

  private:
    struct Panel;
    [[nodiscard]] PanelState describe(const Panel& panel, double video_seconds) const;
    /// The collision `panel` resolves after video frame k's `snapshot`, as the lesson draws it;
    /// empty when none is found. May advance the engine to frame k + 1's time.
    [[nodiscard]] NextCollisionView next_collision(Panel& panel, const Snapshot& snapshot,
                                                   std::int64_t k);
    /// The simulation time the engines are advanced to at video frame `k` (beyond the last
    /// frame: one frame interval per frame, for the next collision's look ahead).
    [[nodiscard]] double schedule_time(std::int64_t k) const;

    const CollisionSettings& settings_;
    std::vector<Panel> panels_;
    std::int64_t last_sim_frame_ = -1;
};

/// The collision video's frames: turns the engines' state at frame k into the view the painter
/// paints, keeping what spans frames (each panel's energy drift series, its failure marks, the
/// time-driven step indicator's phase). The view points into the state, which must outlive its
/// use.
class CollisionProgram {
  public:
    /// `settings` must outlive the program.
    explicit CollisionProgram(const CollisionSettings& settings);
    [[nodiscard]] const FrameContent& frame(const CollisionState& state);

  private:
    /// Time-driven panel `i`'s state is at `state_time`: a new step restarts its count.
    void advance_step_phase(std::size_t i, double state_time);
    /// What the event-driven panel draws during a question or reveal `segment` (its question
    /// answered in settings), `seconds_left` of it to go.
    [[nodiscard]] const ReplayView& question_picture(const Segment& segment,
                                                     const Snapshot& snapshot, double seconds_left);

    const CollisionSettings& settings_;
    FrameContent content_;
    std::vector<EngineDrift> drifts_;     ///< per panel: the largest drift so far
    std::vector<FailureMarks> marks_;     ///< per panel (lesson level)
    std::vector<double> last_step_time_;  ///< per panel: the state time of its latest step
    std::vector<int> step_phase_;         ///< per panel: frames shown of that step
    /// The question's picture of the segment shown last (its letters' places are searched once).
    const Segment* question_segment_ = nullptr;
    ReplayView question_view_;
};

// ------------------------------------------------------------------------------------------------
// The choices made once for the whole video

/// What the lesson plan is made of, besides the scene (src/app resolves the options).
struct LessonRequest {
    OverlayLevel level = OverlayLevel::lesson;
    double duration = 10.0;          ///< seconds of video
    bool duration_from_cli = false;  ///< --duration given: captions beyond it are a notice
    bool intro = true;               ///< no --no-intro
    bool epilogue = true;            ///< no --no-epilogue
    bool step_list = false;          ///< a --dt list
    double dt = 0.0;                 ///< the time-driven step (one step)
    double frame_interval = 1.0;     ///< simulation time between frames
    bool questions = true;           ///< no --questions none: the scene's questions are asked
    bool time_panel = true;          ///< the video shows a time-driven panel (not --mode event)
    bool event_panel = true;         ///< the video shows the event-driven panel (not --mode time)
    /// How many times slower the simulation runs than at the scene's own pace (--code's slow
    /// motion, --slow-motion, --speed): a caption moves to the moment it was written for.
    double slower = 1.0;
    double scene_duration = 10.0;  ///< seconds of the video as the scene says (its intro card)
};

/// The lesson's cards, captions, histogram and step note for `scene`. Captions beyond the video
/// are an error naming them where the video is as long as the scene says, a notice in `notices`
/// where --duration shortened it. Throws Error(input).
[[nodiscard]] LessonPlan lesson_plan(const Scene& scene, const LessonRequest& request,
                                     std::vector<std::string>& notices);

/// How many of the scene's discs can move (mass below 1000 x the lightest).
[[nodiscard]] std::size_t moving_disc_count(const Scene& scene);

/// The speed histogram: the scene's hint, else a small one where there are enough moving discs
/// for a distribution.
[[nodiscard]] PlotSize histogram_size(const Scene& scene);

/// A few tagged discs whose path is the lesson (a Brownian tracer): their whole path stays on
/// screen (each trail point costs a segment per frame, so not for many).
[[nodiscard]] bool few_tagged_discs(const Scene& scene);

/// Trails long enough to see a path: the whole video of `frames` for a few tagged discs
/// (thinned past 1024 points), 48 frames otherwise.
[[nodiscard]] int trail_length(const Scene& scene, std::int64_t frames);

/// Which failures are replayed given the choice asked for (--replay, the scene's hint, else
/// first): none where the video cannot show one (no time-driven panel, or a level without
/// replays).
[[nodiscard]] ReplayChoice shown_replays(ReplayChoice asked, bool time_panels, OverlayLevel level);

}  // namespace collide::show
