#pragma once
/// \file
/// The frame pipeline of `collide render`: simulate -> render -> encode, overlapped on threads.
///
///   simulation thread    FrameSource: advances the engines to each frame time, takes snapshots,
///                        measurements and counter lines          -> BoundedQueue<SimFrame>
///   calling thread       owns the GL context: FrameComposer + Renderer draw the frame
///                        (and show it in the --preview window)   -> VideoWriter::write
///   encoder thread(s)    inside VideoWriter (RGBA -> yuv420p, libx264 and its own threads)
///
/// Every stage sees frames strictly in order and nothing depends on wall time, so the output is
/// byte-identical whatever the thread timing (same scene, options -> same file).

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "collide/io/file.hpp"
#include "collide/render/renderer.hpp"
#include "collide/scene.hpp"
#include "collide/scene3.hpp"
#include "collide/show/collision.hpp"
#include "collide/show/failure_marks.hpp"
#include "collide/show/sphere_camera.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/lookahead.hpp"
#include "collide/snapshot.hpp"
#include "interrupt.hpp"
#include "progress.hpp"
#include "render_plan.hpp"
#include "video_job.hpp"

namespace collide::app {

/// One simulation's state at a frame time, with its on-screen figures.
struct PanelFrame {
    /// The engine's discs; for a 3D scene the discs standing in for its spheres on the screen
    /// (show::project), and `view` the spheres themselves.
    Snapshot snapshot;
    bool spheres = false;  ///< a 3D scene: `view` is drawn
    SphereView view;
    std::string title;
    std::string short_title;   ///< drawn where `title` does not fit (empty: none)
    render::DriftPoint drift;  ///< (KE - KE0) / KE0 at this frame
    bool time_driven = false;
    /// A --dt list (RenderPlan::time_steps): this time-driven panel's step, for the epilogue's
    /// column; 0 otherwise.
    double compared_dt = 0.0;
    std::string note;           ///< time-driven: its step note (show::step_note; empty: none)
    int frames_per_step = 1;    ///< time-driven: its step indicator's period
    show::PanelWords words;     ///< counters, figures, compact line, cost (collide/show)
    Measurements measurements;  ///< the engine's, at this frame (the epilogue's card)
    QueueWords queue_words;     ///< the queue strip's (snapshot.queue set)
    /// Lesson level, event-driven panel without the queue: the collision it resolves next.
    NextCollisionView next_collision;
};

/// What the simulation thread hands to the render thread for one frame.
struct SimFrame {
    std::int64_t index = 0;          ///< the video frame
    std::int64_t sim_frame = 0;      ///< the simulation frame it shows (plan.timeline)
    double time = 0.0;               ///< the simulation time it shows
    bool moved = true;               ///< a new state: not a repeat of the previous frame's
    std::vector<PanelFrame> panels;  ///< time-driven first, then event-driven (as the plan says)
};

/// Owns the engines of a plan and produces its frames in order. Deterministic: the same scene
/// and plan give the same frames (on-screen figures are counts, never wall-clock times).
class FrameSource {
  public:
    /// Builds the engines (time-driven and/or event-driven per plan.mode). Throws Error(input)
    /// for engine options make_engine rejects. Once `stop` is set (nullptr: never), frame()
    /// throws Error(runtime) within a few thousand events, however far its frame time is.
    /// `spheres` (nullptr: none): a 3D scene, run instead of `scene` (which then only stands in
    /// for it: show::stand_in_scene) and seen through plan.camera.
    FrameSource(const Scene& scene, const RenderPlan& plan, const std::atomic<bool>* stop = nullptr,
                const SphereScene* spheres = nullptr);
    /// Advances every engine to the simulation time video frame k shows (plan.timeline; k = 0,
    /// 1, 2, ... each once, in order: the next collision line runs an engine a frame early) and
    /// describes the frame.
    [[nodiscard]] SimFrame frame(std::int64_t k);
    /// Measurements of each engine now, in panel order.
    [[nodiscard]] std::vector<Measurements> measurements() const;

  private:
    struct Panel {
        std::unique_ptr<Engine> engine;               ///< discs
        std::unique_ptr<SphereEngine> sphere_engine;  ///< or spheres
        [[nodiscard]] EngineBase& base() const {
            return engine ? static_cast<EngineBase&>(*engine) : *sphere_engine;
        }
        bool time_driven = false;
        double compared_dt = 0.0;  ///< PanelFrame::compared_dt
        std::string title;
        std::string short_title;
        std::string note;
        int frames_per_step = 1;
        double initial_energy = 0.0;
        /// What the event-driven engine resolves next, for the next collision line (lesson
        /// level, no queue strip, discs). nullptr: none drawn. After `engine`, which it watches:
        /// destroyed first.
        std::unique_ptr<sim::CollisionLookahead> lookahead;
    };
    [[nodiscard]] PanelFrame describe(const Panel& panel, double video_seconds) const;
    /// The collision `panel` resolves after video frame k's `snapshot` (looked for at the times
    /// the panel's engine will be advanced to, at most lookahead_seconds of video past the last
    /// frame), as the lesson draws it; empty when none is found. May advance the engine to
    /// frame k + 1's time.
    [[nodiscard]] NextCollisionView next_collision(Panel& panel, const Snapshot& snapshot,
                                                   std::int64_t k);
    /// The simulation time the engines are advanced to at video frame `k` (beyond the last
    /// frame: one frame interval per frame, for the next collision's look ahead).
    [[nodiscard]] double schedule_time(std::int64_t k) const;

    const RenderPlan& plan_;
    std::vector<Panel> panels_;
    std::int64_t last_sim_frame_ = -1;
};

/// Turns SimFrames into the renderer's FrameContent (render thread), keeping each panel's energy
/// drift series across frames. The content points into the SimFrame, which must outlive its use.
class FrameComposer {
  public:
    explicit FrameComposer(const RenderPlan& plan);
    [[nodiscard]] const render::FrameContent& compose(const SimFrame& frame);

  private:
    /// Time-driven panel `i`'s state is at `state_time`: a new step restarts its count.
    void advance_step_phase(std::size_t i, double state_time);

    const RenderPlan& plan_;
    render::FrameContent content_;
    std::vector<show::EngineDrift> drifts_;  ///< per panel: the largest drift so far
    std::vector<show::FailureMarks> marks_;  ///< per panel (lesson level)
    std::vector<double> last_step_time_;     ///< per panel: the state time of its latest step
    std::vector<int> step_phase_;            ///< per panel: frames shown of that step
};

/// What happened, for the summary line.
struct PipelineResult {
    std::int64_t frames = 0;
    double sim_time = 0.0;              ///< simulation time of the last frame
    std::vector<Measurements> engines;  ///< in panel order
    std::vector<std::string> notices;   ///< from the encoder (size rounded, GIF rate reduced)
    int output_width = 0;
    int output_height = 0;
    double output_fps = 0.0;
    std::string layout_json;  ///< the last frame's rectangles (when plan.layout_json is set)
};

/// Renders plan.clock's frames into plan.output through the video job (video_job.hpp): a video
/// (MP4, GIF or PNG sequence), or for a still (thumbnail, --last-frame) only the last frame as a
/// PNG, every earlier frame time still simulated (so the time-driven engine takes the video's
/// steps) and the frames that feed the trails drawn, so the image equals the video's frame.
/// Nothing appears at plan.output unless every frame was produced and the file finished.
/// `layout_file` (may be null: no --layout-json) receives the last frame's rectangles once the
/// output is complete, before either is put in place: a failure to write one leaves both
/// destinations untouched. Throws Error: input for bad options, runtime for GL/encoder failures
/// or an interrupt.
/// `subtitles`: the video's cues (show::subtitle_cues of the timeline) go into the MP4 and/or a
/// sidecar as it says; the sidecar too appears only with the video.
/// `chapters`: the timeline's chapters (show::timeline_chapters) go into the MP4, a chapters
/// file and/or a slide folder as it says, likewise only with the video.
/// `spheres` (nullptr: none): a 3D scene drawn as spheres, `scene` its stand-in
/// (show::stand_in_scene).
PipelineResult run_render(const Scene& scene, const RenderPlan& plan, const JobHooks& hooks,
                          io::OutputFile* layout_file = nullptr,
                          const SubtitleOutput& subtitles = {}, const ChapterOutput& chapters = {},
                          const SphereScene* spheres = nullptr);

}  // namespace collide::app
