#include "pipeline.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <thread>
#include <utility>

#include "bounded_queue.hpp"
#include "collide/error.hpp"
#include "collide/show/chapters.hpp"
#include "collide/show/collision_summary.hpp"
#include "collide/show/event_loop_code.hpp"
#include "collide/show/plot_words.hpp"
#include "collide/show/replay.hpp"
#include "collide/show/subtitles.hpp"

namespace collide::app {

namespace {

/// SimFrames in flight between the simulation and render threads: enough to ride out an uneven
/// frame (a burst of collisions) without holding many snapshots in memory.
constexpr std::size_t sim_queue_frames = 4;

/// How far past the last frame the next collision line looks (seconds of video): a thumbnail's
/// last frame shows its line too; a collision further away is no "next" a class waits for.
constexpr double lookahead_seconds = 10.0;

double relative_drift(double energy, double initial) {
    return initial > 0.0 ? (energy - initial) / initial : 0.0;
}

/// The simulation thread and the queue it fills. The destructor closes the queue (so a producer
/// blocked on a full queue wakes up) and joins, so no path out of a run leaves a thread behind.
class SimulationThread {
  public:
    SimulationThread(const Scene& scene, const RenderPlan& plan, const std::atomic<bool>* cancel,
                     const SphereScene* spheres)
        : queue_(sim_queue_frames),
          thread_([this, &scene, &plan, cancel, spheres] { run(scene, plan, cancel, spheres); }) {}
    ~SimulationThread() {
        queue_.close();
        if (thread_.joinable()) thread_.join();
    }
    SimulationThread(const SimulationThread&) = delete;
    SimulationThread& operator=(const SimulationThread&) = delete;

    /// The next frame, or nullopt when all are done (or the simulation failed or was cancelled).
    std::optional<SimFrame> next() { return queue_.pop(); }

    /// After next() returned nullopt: rethrows the simulation's error, if any, and hands out the
    /// engines' final measurements.
    std::vector<Measurements> finish() {
        thread_.join();
        if (error_) std::rethrow_exception(error_);
        return final_measurements_;
    }

  private:
    void run(const Scene& scene, const RenderPlan& plan, const std::atomic<bool>* cancel,
             const SphereScene* spheres) {
        try {
            FrameSource source(scene, plan, cancel, spheres);
            for (std::int64_t k = 0; k < plan.timeline.frame_count(); ++k) {
                if (cancel != nullptr && cancel->load()) break;
                if (!queue_.push(source.frame(k))) break;
            }
            final_measurements_ = source.measurements();
        } catch (...) {
            error_ = std::current_exception();
        }
        queue_.close();
    }

    BoundedQueue<SimFrame> queue_;
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

/// Engine::watch_queue, its errors about the field `queue` said as the option `--queue`.
bool watch_queue(EngineBase& engine, const QueueViewLimits& limits) {
    try {
        return engine.watch_queue(limits);
    } catch (const Error& e) {
        const std::string_view field = "queue: ";
        const std::string_view message = e.what();
        if (e.kind() != ErrorKind::input || !message.starts_with(field)) throw;
        throw_option_error("--queue", message.substr(field.size()));
    }
}

}  // namespace

// ------------------------------------------------------------------------------------------------
// Simulation side

FrameSource::FrameSource(const Scene& scene, const RenderPlan& plan, const std::atomic<bool>* stop,
                         const SphereScene* spheres)
    : plan_(plan) {
    const OverlayLevel level = plan.render.overlays;
    const auto add = [&](const EngineOptions& options, bool time_driven,
                         std::string title) -> Panel& {
        Panel panel;
        if (spheres != nullptr) {
            panel.sphere_engine = make_engine(*spheres, options);
        } else {
            panel.engine = make_engine(scene, options);
        }
        panel.base().set_stop_flag(stop);
        if (!time_driven && plan.queue_events > 0 &&
            !watch_queue(panel.base(), show::queue_picture(plan.queue_events)))
            throw_option_error("--queue", "the " + std::string(to_string(options.engine)) +
                                              " engine has no event queue");
        if (!time_driven && spheres == nullptr && level == OverlayLevel::lesson &&
            plan.queue_events == 0) {
            // The next collision line: the engine, run a frame early, says what comes next.
            panel.lookahead = std::make_unique<sim::CollisionLookahead>(*panel.engine);
        }
        panel.time_driven = time_driven;
        panel.title = std::move(title);
        panel.initial_energy = panel.base().measurements().kinetic_energy;
        panels_.push_back(std::move(panel));
        return panels_.back();
    };
    // --code: the panels share what the listing leaves, so their titles are short (one panel
    // alone too: its text stops at the column beside it).
    const bool narrow = plan.code;
    if (plan.mode != RenderMode::event && plan.time_steps.empty()) {
        Panel& panel =
            add(plan.time_engine, true, show::panel_title(true, level, plan.time_engine, narrow));
        panel.note = plan.lesson.step_note;
        panel.frames_per_step = plan.lesson.frames_per_step;
    }
    if (plan.mode != RenderMode::event) {
        // A --dt list: one time-driven panel per step.
        for (const double dt : plan.time_steps) {
            EngineOptions options = plan.time_engine;
            options.dt = dt;
            Panel& panel = add(options, true, show::compared_step_title(dt, level));
            panel.short_title = show::compared_step_short_title(dt);
            // No step note: beside the others its line would not fit, and the titles say
            // which steps are long.
            panel.compared_dt = dt;
        }
    }
    if (plan.mode != RenderMode::time) {
        Panel& panel = add(plan.event_engine, false,
                           show::panel_title(false, level, plan.event_engine, narrow));
        // Beside a --dt list's panels the cells are narrower: a short title where it must.
        if (!plan.time_steps.empty()) panel.short_title = show::event_short_title;
    }
}

SimFrame FrameSource::frame(std::int64_t k) {
    SimFrame out;
    out.index = k;
    out.sim_frame = plan_.timeline.sim_frame(k);
    out.time = plan_.clock.time(out.sim_frame);
    out.moved = out.sim_frame != last_sim_frame_;
    last_sim_frame_ = out.sim_frame;
    out.panels.reserve(panels_.size());
    // The camera turns with the moving picture (a card or a hold keeps it where it is).
    const double video_seconds = static_cast<double>(out.sim_frame) / plan_.fps;
    for (Panel& panel : panels_) {
        // The time-driven engine takes the whole steps of dt up to the frame time and shows the
        // latest (TimeEngine::advance_to): every caller gets the same state at the same step.
        EngineBase& engine = panel.base();
        engine.advance_to(std::max(out.time, engine.time()));
        out.panels.push_back(describe(panel, video_seconds));
        if (panel.lookahead)
            out.panels.back().next_collision = next_collision(panel, out.panels.back().snapshot, k);
    }
    return out;
}

double FrameSource::schedule_time(std::int64_t k) const {
    const std::int64_t count = plan_.timeline.frame_count();
    if (k < count) return plan_.clock.time(plan_.timeline.sim_frame(k));
    return plan_.clock.time(plan_.timeline.sim_frame(count - 1)) +
           static_cast<double>(k - count + 1) * plan_.clock.interval;
}

NextCollisionView FrameSource::next_collision(Panel& panel, const Snapshot& snapshot,
                                              std::int64_t k) {
    // After describe(): the engine may be advanced to frame k + 1's time here, and the frame's
    // figures must be those of frame k.
    const std::int64_t count = plan_.timeline.frame_count();
    const auto last = count + static_cast<std::int64_t>(std::ceil(lookahead_seconds * plan_.fps));
    const sim::FramesAhead frames{[this, k](std::int64_t i) { return schedule_time(k + i); },
                                  count - 1 - k, last - 1 - k};
    const std::optional<CollisionRecord> next = panel.lookahead->next(frames);
    if (!next) return {};
    return show::next_collision_view(*next, snapshot, plan_.clock);
}

PanelFrame FrameSource::describe(const Panel& panel, double video_seconds) const {
    PanelFrame out;
    if (panel.sphere_engine) {
        show::ProjectedPanel projected = show::project(
            panel.sphere_engine->snapshot(),
            show::camera_at(plan_.camera, video_seconds, plan_.slab, plan_.projection));
        out.snapshot = std::move(projected.screen);
        out.view = std::move(projected.view);
        out.spheres = true;
    } else {
        out.snapshot = panel.engine->snapshot();
    }
    const Measurements m = panel.base().measurements();
    const double drift = relative_drift(m.kinetic_energy, panel.initial_energy);
    out.title = panel.title;
    out.short_title = panel.short_title;
    out.drift = {out.snapshot.time, drift};
    out.time_driven = panel.time_driven;
    out.compared_dt = panel.compared_dt;
    out.note = panel.note;
    out.frames_per_step = panel.frames_per_step;
    out.measurements = m;
    out.words =
        show::panel_words(m, panel.time_driven, out.snapshot.box.boundary == Boundary::walls, drift,
                          plan_.event_engine.engine);
    if (out.snapshot.queue)
        out.queue_words = show::queue_words(*out.snapshot.queue, out.snapshot.time);
    return out;
}

std::vector<Measurements> FrameSource::measurements() const {
    std::vector<Measurements> out;
    for (const Panel& panel : panels_) out.push_back(panel.base().measurements());
    return out;
}

// ------------------------------------------------------------------------------------------------
// Render side

FrameComposer::FrameComposer(const RenderPlan& plan) : plan_(plan) {
    // The colour scale is fixed for the whole video, and so are its words.
    const render::RenderConfig& r = plan.render;
    content_.color_key =
        show::color_key(r.color_mode, r.speed_min, r.speed_max, r.mass_min, r.mass_max);
    content_.speed_plot = show::speed_plot_words(r.speed_max);
}

void FrameComposer::advance_step_phase(std::size_t i, double state_time) {
    if (state_time != last_step_time_[i]) {
        last_step_time_[i] = state_time;
        step_phase_[i] = 0;
    } else {
        ++step_phase_[i];
    }
}

const render::FrameContent& FrameComposer::compose(const SimFrame& frame) {
    const LessonPlan& lesson = plan_.lesson;
    const show::Segment& segment = plan_.timeline.segment_at(frame.index);
    const double video_time = static_cast<double>(frame.index) / plan_.fps;
    content_.panels.resize(frame.panels.size());
    if (marks_.size() != frame.panels.size()) {
        // The wrap note of a periodic box is said once, by the first panel: its legend line
        // takes the frame's width when the other panel (event-driven: no failures) has none.
        marks_.clear();
        for (std::size_t i = 0; i < frame.panels.size(); ++i)
            marks_.emplace_back(show::mark_budget, i == 0);
    }
    content_.energy_drift.resize(frame.panels.size());
    last_step_time_.resize(frame.panels.size(), -1.0);
    step_phase_.resize(frame.panels.size(), 0);
    // A replay: both panels zoom onto the failure's spot, each with its own marks (collide/show).
    const show::ReplayFailure* replay = segment.kind == show::SegmentKind::replay
                                            ? show::replay_at(plan_.replays, segment.sim_frame)
                                            : nullptr;
    std::optional<show::ReplayFrame> replay_frame;
    if (replay != nullptr && !frame.panels.empty()) {
        replay_frame =
            show::replay_frame(*replay, frame.panels[0].snapshot.box,
                               static_cast<double>(frame.index - segment.first_frame) / plan_.fps);
    }
    content_.code.reset();
    for (std::size_t i = 0; i < frame.panels.size(); ++i) {
        const PanelFrame& panel = frame.panels[i];
        render::PanelContent& out = content_.panels[i];
        if (plan_.code && panel.snapshot.queue && !content_.code) {
            // --code: the loop's line under way, from the queue's latest pop.
            content_.code = show::event_loop_view(*panel.snapshot.queue, panel.snapshot.time,
                                                  plan_.speed.speed);
        }
        out.snapshot = &panel.snapshot;
        out.spheres = panel.spheres ? &panel.view : nullptr;
        out.title = panel.title;
        out.short_title = panel.short_title;
        out.counters = panel.words.counters;
        out.figures = panel.words.figures;
        out.compact_line = panel.words.compact_line;
        out.cost_label = panel.compared_dt > 0.0 ? show::compared_cost_label(panel.compared_dt)
                                                 : panel.words.cost_label;
        out.cost = panel.words.cost;
        out.cost_text = panel.words.cost_text;
        out.cost_words = panel.words.cost_words;
        out.how = frame.panels.size() == 2 ? panel.words.how : std::string();
        out.queue_words = panel.queue_words;
        out.accent = render::panel_accent(panel.time_driven, plan_.render.theme);
        out.note = panel.note;
        out.step_period = 1;
        out.step_phase = 0;
        if (panel.time_driven && panel.frames_per_step > 1) {
            // Which frame of the held step this is: a new state restarts the count (a frozen
            // frame, a card's or a hold's, is no frame of the step).
            if (frame.moved) advance_step_phase(i, panel.snapshot.time);
            out.step_period = panel.frames_per_step;
            out.step_phase = std::min(step_phase_[i], panel.frames_per_step - 1);
        }
        if (plan_.render.overlays != OverlayLevel::none) {
            // The failure marks and their legend: which failures get a mark is decided in show.
            // They fade with the moving picture (a card or a hold keeps them as they are).
            marks_[i].update(panel.snapshot, static_cast<double>(frame.sim_frame) / plan_.fps);
            out.marks = marks_[i].marks();
            out.mark_words = marks_[i].words();
            out.mark_line = show::mark_line(panel.time_driven, i == 0, panel.snapshot.box);
        }
        // A replay draws the collision the event-driven panel predicted itself: no second line.
        out.next_collision = replay_frame ? NextCollisionView{} : panel.next_collision;
        out.zoom = replay_frame ? replay_frame->zoom : BoxZoom{};
        out.replay = !replay_frame       ? ReplayView{}
                     : panel.time_driven ? replay_frame->time_driven
                                         : replay_frame->event_driven;
        if (frame.moved || content_.energy_drift[i].empty())
            content_.energy_drift[i].push_back(panel.drift);
        drifts_.resize(frame.panels.size());
        drifts_[i].time_driven = panel.time_driven;
        if (std::isfinite(panel.drift.drift))
            drifts_[i].largest = std::max(drifts_[i].largest, std::abs(panel.drift.drift));
    }
    // The ratio compares the two engines (time-driven first, as the plan orders them).
    content_.cost_ratio = frame.panels.size() == 2 ? show::work_ratio(frame.panels[0].words.cost,
                                                                      frame.panels[1].words.cost)
                                                   : std::string();
    content_.time_text =
        show::clock_text(frame.time, plan_.clock, plan_.speed.speed, plan_.render.overlays);
    content_.time_unit =
        plan_.render.overlays == OverlayLevel::lesson ? show::time_unit : std::string();
    content_.cost_heading = show::cost_heading;
    // Failure markers fade with the moving picture: a card or a hold keeps them as they are.
    content_.video_time = static_cast<double>(frame.sim_frame) / plan_.fps;
    content_.speed = plan_.speed.speed;
    content_.pop_highlight = {show::pop_highlight_seconds(false, plan_.code),
                              show::pop_highlight_seconds(true, plan_.code)};
    // The card's words are its title (the timeline's caption); beneath it, the scene's caption.
    content_.caption =
        segment.kind == show::SegmentKind::card ? lesson.caption_at(video_time) : segment.caption;
    content_.histogram = lesson.histogram;
    content_.energy_line = show::energy_line(drifts_);
    content_.energy_plot =
        std::any_of(drifts_.begin(), drifts_.end(),
                    [](const show::EngineDrift& d) { return d.largest > show::round_off_drift; });
    content_.drift_plot = show::drift_plot_words(content_.energy_drift);
    content_.intro_title = lesson.title;
    content_.intro_text = lesson.description;
    content_.intro_opacity = lesson.intro_opacity(video_time);
    content_.summary = {};
    if (segment.kind == show::SegmentKind::epilogue) {
        std::vector<show::SummaryPanel> panels;
        for (const PanelFrame& panel : frame.panels)
            panels.push_back({panel.measurements, panel.time_driven, panel.compared_dt});
        const bool walls =
            !frame.panels.empty() && frame.panels[0].snapshot.box.boundary == Boundary::walls;
        content_.summary = show::summary_card(
            panels, walls,
            show::clock_text(frame.time, plan_.clock, plan_.speed.speed, OverlayLevel::lesson));
        content_.summary.opacity = show::summary_opacity(video_time - segment.start);
    }
    return content_;
}

namespace {

/// The frames of a render for the video job: simulated on their own thread (SimulationThread),
/// composed and drawn here, on the thread that owns the GL context.
class CollisionProgram final : public FrameProgram {
  public:
    CollisionProgram(const Scene& scene, const RenderPlan& plan, render::Backend backend,
                     const JobHooks& hooks, PipelineResult& result, const SphereScene* spheres)
        : plan_(plan),
          interrupts_(hooks.interrupts),
          result_(result),
          renderer_(plan.render, backend, hooks.notice),
          composer_(plan),
          simulation_(scene, plan,
                      hooks.interrupts != nullptr ? &hooks.interrupts->flag() : nullptr, spheres) {}

    double frame(std::int64_t /*k*/, FrameUse use, Image& image) override {
        std::optional<SimFrame> frame = simulation_.next();
        if (!frame) stopped_early();
        // A frame is phases (text layout, drawing, read-back) that each take a while at a large
        // --size: the renderer knows nothing of interrupts, so the flag is polled between them.
        check_interrupt();
        const render::FrameContent& content = composer_.compose(*frame);
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

    /// Draws the frame, except inside a hold: there every frame after the first is the first
    /// one again (the states, the clock, the caption and the markers all stand still), and
    /// drawing it again would only lengthen the trails by points that stand still too.
    void output(const SimFrame& frame, const render::FrameContent& content, Image& image) {
        const show::Segment& segment = plan_.timeline.segment_at(frame.index);
        const bool hold = segment.kind == show::SegmentKind::hold;
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
    const InterruptGuard* interrupts_;
    PipelineResult& result_;
    render::Renderer renderer_;
    FrameComposer composer_;
    Image held_;                   ///< the first frame of the hold under way
    SimulationThread simulation_;  // last: its thread starts once everything else exists
};

}  // namespace

PipelineResult run_render(const Scene& scene, const RenderPlan& plan, const JobHooks& hooks,
                          io::OutputFile* layout_file, const SubtitleOutput& subtitles,
                          const ChapterOutput& chapters, const SphereScene* spheres) {
    check_captions_fit(scene, plan);
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
        job.output.chapter_output = chapters;
        job.output.chapters =
            show::timeline_chapters(plan.timeline, plan.lesson.intro_fade_seconds());
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
            return std::make_unique<CollisionProgram>(scene, plan, backend, hooks, result, spheres);
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
