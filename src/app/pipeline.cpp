#include "pipeline.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <optional>
#include <thread>
#include <utility>

#include "bounded_queue.hpp"
#include "collide/error.hpp"
#include "collide/show/chapters.hpp"
#include "collide/show/subtitles.hpp"

namespace collide::app {

namespace {

/// Frame states in flight between the simulation and render threads: enough to ride out an uneven
/// frame (a burst of collisions) without holding many snapshots in memory.
constexpr std::size_t sim_queue_frames = 4;

/// The simulation thread and the queue it fills. The destructor closes the queue (so a producer
/// blocked on a full queue wakes up) and joins, so no path out of a run leaves a thread behind.
class SimulationThread {
  public:
    SimulationThread(show::SceneView scene, const show::CollisionSettings& settings,
                     const std::atomic<bool>* cancel)
        : queue_(sim_queue_frames),
          thread_([this, scene, &settings, cancel] { run(scene, settings, cancel); }) {}
    ~SimulationThread() {
        queue_.close();
        if (thread_.joinable()) thread_.join();
    }
    SimulationThread(const SimulationThread&) = delete;
    SimulationThread& operator=(const SimulationThread&) = delete;

    /// The next frame, or nullopt when all are done (or the simulation failed or was cancelled).
    std::optional<show::CollisionState> next() { return queue_.pop(); }

    /// After next() returned nullopt: rethrows the simulation's error, if any, and hands out the
    /// engines' final measurements.
    std::vector<Measurements> finish() {
        thread_.join();
        if (error_) std::rethrow_exception(error_);
        return final_measurements_;
    }

  private:
    void run(show::SceneView scene, const show::CollisionSettings& settings,
             const std::atomic<bool>* cancel) {
        try {
            show::CollisionSimulation source(scene, settings, cancel);
            for (std::int64_t k = 0; k < settings.timeline.frame_count(); ++k) {
                if (cancel != nullptr && cancel->load()) break;
                if (!queue_.push(source.state(k))) break;
            }
            final_measurements_ = source.measurements();
        } catch (...) {
            error_ = std::current_exception();
        }
        queue_.close();
    }

    BoundedQueue<show::CollisionState> queue_;
    std::exception_ptr error_;
    std::vector<Measurements> final_measurements_;
    std::thread thread_;  // last: started once everything it uses exists
};

std::string title_of(const RenderPlan& plan) {
    return plan.mode == RenderMode::both ? "collide: time-driven vs event-driven" : "collide";
}

/// Every caption of the video fits the caption line of this frame size, or the render stops
/// before anything is written, naming the caption and how much of it fits.
void check_captions_fit(const Scene& scene, const RenderPlan& plan) {
    const auto check = [&](const std::string& text, const std::string& file, int line,
                           const std::string& field) {
        if (text.empty()) return;
        const render::CaptionFit fit = render::fit_caption(plan.render, text);
        if (fit.fits) return;
        throw_scene_error(
            file, line, field,
            fmt::format("too long for the caption line of a {}x{} frame: {} of its characters "
                        "fit (a wider --size, or a shorter caption)",
                        plan.width, plan.height, fit.max_characters));
    };
    for (const show::CaptionSource& caption :
         show::captions_shown(plan.lesson, scene.render.caption_at)) {
        check(caption.text, caption.file, caption.line, caption.field);
    }
}

}  // namespace

namespace {

/// The frames of a render for the video job: simulated on their own thread (SimulationThread),
/// filled by the collision program and painted here, on the thread that owns the GL context.
class CollisionJobFrames final : public FrameProgram {
  public:
    CollisionJobFrames(show::SceneView scene, const RenderPlan& plan, render::Backend backend,
                       const JobHooks& hooks, PipelineResult& result)
        : plan_(plan),
          settings_(collision_settings(plan)),
          interrupts_(hooks.interrupts),
          result_(result),
          renderer_(plan.render, backend, hooks.notice),
          program_(settings_),
          simulation_(scene, settings_,
                      hooks.interrupts != nullptr ? &hooks.interrupts->flag() : nullptr) {}

    double frame(std::int64_t /*k*/, FrameUse use, Image& image) override {
        std::optional<show::CollisionState> frame = simulation_.next();
        if (!frame) stopped_early();
        // A frame is phases (text layout, drawing, read-back) that each take a while at a large
        // --size: the renderer knows nothing of interrupts, so the flag is polled between them.
        check_interrupt();
        const render::FrameContent& content = program_.frame(*frame);
        const bool last = frame->index + 1 == plan_.timeline.frame_count();
        check_interrupt();
        switch (use) {
            case FrameUse::output:
                output(*frame, content, image);
                break;
            case FrameUse::warm:
                renderer_.draw(content);
                break;
            case FrameUse::skip:
                break;
        }
        check_interrupt();
        if (!plan_.layout_json.empty() && last)
            result_.layout_json = renderer_.layout_json(content);
        result_.sim_time = frame->time;
        return frame->time;
    }

    void finish() override { result_.engines = simulation_.finish(); }

  private:
    void check_interrupt() const {
        if (interrupts_ != nullptr) interrupts_->throw_if_requested();
    }

    /// Draws the frame, except inside a hold or a question's reveal: there every frame after
    /// the first is the first one again (the states, the clock, the caption and the markers all
    /// stand still), and drawing it again would only lengthen the trails by points that stand
    /// still too. A will-see question's reveal is a replay: it moves.
    void output(const show::CollisionState& frame, const render::FrameContent& content,
                Image& image) {
        const show::Segment& segment = plan_.timeline.segment_at(frame.index);
        const bool replays = segment.question >= 0 &&
                             static_cast<std::size_t>(segment.question) < plan_.questions.size() &&
                             plan_.questions[static_cast<std::size_t>(segment.question)].kind ==
                                 QuestionKind::will_see;
        const bool hold = segment.kind == show::SegmentKind::hold ||
                          (segment.kind == show::SegmentKind::reveal && !replays);
        if (hold && frame.index > segment.first_frame && !held_.rgba.empty()) {
            image = held_;
            return;
        }
        renderer_.render(content, image);
        if (hold) held_ = image;
    }

    /// The simulation ended before the last frame: an interrupt (say so, rather than the
    /// "simulation stopped" the engines threw on seeing it), its error, or neither.
    [[noreturn]] void stopped_early() {
        if (interrupts_ != nullptr) interrupts_->throw_if_requested();
        (void)simulation_.finish();
        throw_runtime_error("rendering stopped before the last frame");
    }

    const RenderPlan& plan_;
    const show::CollisionSettings settings_;  ///< the program's and the simulation's
    const InterruptGuard* interrupts_;
    PipelineResult& result_;
    render::Renderer renderer_;
    show::CollisionProgram program_;
    Image held_;                   ///< the first frame of the hold under way
    SimulationThread simulation_;  // last: its thread starts once everything else exists
};

}  // namespace

PipelineResult run_render(show::SceneView scene, const RenderPlan& plan, const JobHooks& hooks,
                          io::OutputFile* layout_file, const SubtitleOutput& subtitles,
                          const ChapterOutput& chapters) {
    check_captions_fit(scene.discs(), plan);
    VideoJob job;
    job.output.path = plan.output;
    job.output.format = plan.format;
    job.output.still = plan.kind == OutputKind::still;
    job.width = plan.width;
    job.height = plan.height;
    job.fps = plan.fps;
    job.frames = plan.timeline.frame_count();
    // Only the frames whose positions appear in the trails need drawing before a still's frame.
    job.warm_frames = (plan.render.trails ? plan.render.trail_length : 1) - 1;
    job.title = title_of(plan);
    if (!job.output.still) {
        job.output.subtitles = subtitles;
        job.output.cues = show::subtitle_cues(plan.timeline, plan.lesson);
        // The lesson level draws the captions; full and none leave them to the track.
        job.output.cues_in_picture = show::level_shows(plan.render.overlays).captions;
        job.output.chapter_output = chapters;
        std::vector<bool> replaying_reveals;
        for (const show::QuestionAnswer& question : plan.questions)
            replaying_reveals.push_back(question.kind == QuestionKind::will_see);
        job.output.chapters = show::timeline_chapters(
            plan.timeline, plan.lesson.intro_fade_seconds(), replaying_reveals);
    }

    PipelineResult result;
    JobHooks job_hooks = hooks;
    job_hooks.before_commit = [&] {
        if (layout_file != nullptr) layout_file->write(result.layout_json);
    };
    if (layout_file != nullptr) job_hooks.commit_with.push_back(layout_file);
    const JobResult written = run_video_job(
        job,
        [&](render::Backend backend) {
            return std::make_unique<CollisionJobFrames>(scene, plan, backend, hooks, result);
        },
        job_hooks);
    result.frames = written.frames;
    result.notices = written.notices;
    result.output_width = written.output_width;
    result.output_height = written.output_height;
    result.output_fps = written.output_fps;
    return result;
}

}  // namespace collide::app
