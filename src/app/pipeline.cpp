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
#include "collide/io/file.hpp"
#include "collide/render/preview.hpp"
#include "collide/video/png.hpp"
#include "collide/video/video_writer.hpp"

namespace collide::app {

namespace {

/// SimFrames in flight between the simulation and render threads: enough to ride out an uneven
/// frame (a burst of collisions) without holding many snapshots in memory.
constexpr std::size_t sim_queue_frames = 4;

double relative_drift(double energy, double initial) {
    return initial > 0.0 ? (energy - initial) / initial : 0.0;
}

void check_interrupt(const PipelineHooks& hooks) {
    if (hooks.interrupts != nullptr) hooks.interrupts->throw_if_requested();
}

/// The simulation thread and the queue it fills. The destructor closes the queue (so a producer
/// blocked on a full queue wakes up) and joins, so no path out of a run leaves a thread behind.
class SimulationThread {
  public:
    SimulationThread(const Scene& scene, const RenderPlan& plan, const std::atomic<bool>* cancel)
        : queue_(sim_queue_frames),
          thread_([this, &scene, &plan, cancel] { run(scene, plan, cancel); }) {}
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
    void run(const Scene& scene, const RenderPlan& plan, const std::atomic<bool>* cancel) {
        try {
            FrameSource source(scene, plan, cancel);
            for (std::int64_t k = 0; k < plan.clock.count; ++k) {
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

/// Raw RGBA frames appended to a file (benchmarks only), through io::OutputFile like every
/// output: in place once the video is finished, or a stream ("-", a FIFO, /dev/null).
class RawDump {
  public:
    explicit RawDump(const std::filesystem::path& path) {
        if (!path.empty()) file_.emplace(path, io::OutputOptions{"--dump-rgba", true});
    }

    void write(const Image& image) {
        if (file_) file_->write(image.rgba.data(), image.rgba.size());
    }
    void finish() {
        if (file_) file_->commit();
    }

  private:
    std::optional<io::OutputFile> file_;
};

std::string_view title_of(const RenderPlan& plan) {
    return plan.mode == RenderMode::both ? "collide: time-driven vs event-driven" : "collide";
}

/// The --preview window: null when not asked for or when there is no display (after a notice).
std::unique_ptr<render::PreviewWindow> open_preview_if_asked(const RenderPlan& plan,
                                                             const PipelineHooks& hooks) {
    if (!hooks.preview) return nullptr;
    return render::open_preview(plan.width, plan.height, std::string(title_of(plan)).c_str(),
                                hooks.notice);
}

/// The backend that renders the frames. With a preview window open it is GLFW, so that one GL
/// implementation (Mesa's GLX driver) serves both: libOSMesa and the GLX driver share Mesa's
/// per-thread current context (libglapi), while glvnd skips a glXMakeCurrent that its own records
/// say changes nothing; after an OSMesa frame the preview then drew and swapped with OSMesa's
/// context and crashed (issue 22; docs/renderer.md, "Preview").
render::Backend render_backend(const render::PreviewWindow* preview, const PipelineHooks& hooks) {
    return preview != nullptr ? render::Backend::glfw : hooks.backend;
}

/// Every caption of the video fits the caption line of this frame size, or the render stops
/// before anything is written, naming the caption and how much of it fits.
void check_captions_fit(const Scene& scene, const RenderPlan& plan) {
    const auto check = [&](const std::string& text, const std::string& file, int line,
                           const std::string& field) {
        if (text.empty()) return;
        const render::CaptionFit fit = render::fit_caption(plan.render, text);
        if (fit.fits) return;
        throw_input_error(
            file, line, field,
            fmt::format("too long for the caption line of a {}x{} frame: {} of its characters "
                        "fit (a wider --size, or a shorter caption)",
                        plan.width, plan.height, fit.max_characters));
    };
    if (!plan.lesson.caption.empty()) {
        // caption_at is "file:line: render.caption" (empty for a caption not read from a file).
        const std::string& at = scene.render.caption_at;
        check(plan.lesson.caption, "", 0, at.empty() ? "render.caption" : at);
    }
    for (const CaptionCue& cue : plan.lesson.captions) {
        check(cue.text, cue.file, cue.line, "render.captions.text");
    }
}

}  // namespace

// ------------------------------------------------------------------------------------------------
// Simulation side

std::vector<std::string> time_driven_counters(const Measurements& m, double energy_drift) {
    // Short "label  value" pairs: the renderer lays them out in a grid of narrow columns.
    return {
        fmt::format("steps  {}", short_count(static_cast<double>(m.steps))),
        fmt::format("checks  {}", short_count(static_cast<double>(m.overlap_checks))),
        fmt::format("collisions  {}",
                    short_count(static_cast<double>(m.collisions_pair + m.collisions_wall))),
        fmt::format("overlaps now  {}", m.overlapping_pairs),
        fmt::format("deepest  {:.2g}", m.max_overlap),
        fmt::format("missed  {}", m.missed_collisions),
        fmt::format("escaped  {}", m.escaped),
        fmt::format("energy drift  {:+.1e}", energy_drift),
        fmt::format("checks/time  {}",
                    m.t > 0.0 ? short_count(static_cast<double>(m.overlap_checks) / m.t) : "-"),
    };
}

std::vector<std::string> event_driven_counters(const Measurements& m, double energy_drift) {
    const std::uint64_t queue_ops = m.queue.pushes + m.queue.pops;
    const double stale_share = m.queue.pops > 0 ? 100.0 * static_cast<double>(m.queue.stale_pops) /
                                                      static_cast<double>(m.queue.pops)
                                                : 0.0;
    const double work = static_cast<double>(m.predictions + queue_ops);
    return {
        fmt::format("events  {}", short_count(static_cast<double>(m.events))),
        fmt::format("collisions  {}",
                    short_count(static_cast<double>(m.collisions_pair + m.collisions_wall))),
        fmt::format("predictions  {}", short_count(static_cast<double>(m.predictions))),
        fmt::format("queue ops  {}", short_count(static_cast<double>(queue_ops))),
        fmt::format("queue max  {}", m.queue.max_size),
        fmt::format("stale pops  {:.0f}%", stale_share),
        fmt::format("overlaps now  {}", m.max_overlap > 0.0 ? "yes" : "0"),
        fmt::format("energy drift  {:+.1e}", energy_drift),
        fmt::format("ops/time  {}", m.t > 0.0 ? short_count(work / m.t) : "-"),
    };
}

std::vector<std::string> comparison_notes(RenderMode /*mode*/) {
    // The chaos remark belongs to the scenes that need it (their own captions), not every video.
    return {};
}

namespace {
std::string count_text(std::uint64_t n) {
    return render::with_separators(static_cast<long long>(n));
}
}  // namespace

std::vector<render::Figure> time_driven_figures(const Measurements& m, bool walls) {
    std::vector<render::Figure> out = {
        {count_text(m.missed_collisions), "missed", true},
        {count_text(m.overlapping_pairs), "overlapping", true},
    };
    if (walls && m.escaped > 0) out.push_back({count_text(m.escaped), "left the box", true});
    out.push_back({count_text(m.collisions_pair + m.collisions_wall), "collisions", false});
    return out;
}

std::vector<render::Figure> event_driven_figures(const Measurements& m) {
    return {
        {count_text(m.collisions_pair + m.collisions_wall), "collisions", false},
        {"0", "missed", true},
    };
}

FrameSource::FrameSource(const Scene& scene, const RenderPlan& plan, const std::atomic<bool>* stop)
    : plan_(plan) {
    const auto add = [&](const EngineOptions& options, bool time_driven, std::string title) {
        Panel panel;
        panel.engine = make_engine(scene, options);
        panel.engine->set_stop_flag(stop);
        if (!time_driven && plan.queue_events > 0 && !panel.engine->watch_queue(plan.queue_events))
            throw_option_error("--queue", "the " + std::string(to_string(options.engine)) +
                                              " engine has no event queue");
        panel.time_driven = time_driven;
        panel.title = std::move(title);
        panel.initial_energy = panel.engine->measurements().kinetic_energy;
        panels_.push_back(std::move(panel));
    };
    const bool lesson = plan.render.overlays == render::OverlayLevel::lesson;
    if (plan.mode != RenderMode::event)
        add(plan.time_engine, true,
            lesson ? time_lesson_title(plan.time_engine.dt)
                   : time_panel_title(plan.time_engine.dt));
    if (plan.mode != RenderMode::time)
        add(plan.event_engine, false,
            lesson ? event_lesson_title(plan.event_engine) : event_panel_title(plan.event_engine));
}

SimFrame FrameSource::frame(std::int64_t k) {
    SimFrame out;
    out.index = k;
    out.time = plan_.clock.time(k);
    out.panels.reserve(panels_.size());
    for (Panel& panel : panels_) {
        // The time-driven engine takes the whole steps of dt up to the frame time and shows the
        // latest (TimeEngine::advance_to): every caller gets the same state at the same step.
        panel.engine->advance_to(std::max(out.time, panel.engine->time()));
        out.panels.push_back(describe(panel));
    }
    return out;
}

PanelFrame FrameSource::describe(const Panel& panel) const {
    PanelFrame out;
    out.snapshot = panel.engine->snapshot();
    const Measurements m = panel.engine->measurements();
    const double drift = relative_drift(m.kinetic_energy, panel.initial_energy);
    out.title = panel.title;
    out.counters =
        panel.time_driven ? time_driven_counters(m, drift) : event_driven_counters(m, drift);
    out.drift = {out.snapshot.time, drift};
    out.time_driven = panel.time_driven;
    if (panel.time_driven) {
        out.figures = time_driven_figures(m, out.snapshot.box.boundary == Boundary::walls);
        out.compact_line = fmt::format("{} missed", count_text(m.missed_collisions));
        out.cost_label = "pair tests";
        out.cost = static_cast<double>(m.overlap_checks);
    } else {
        out.figures = event_driven_figures(m);
        out.compact_line =
            fmt::format("{} collisions", count_text(m.collisions_pair + m.collisions_wall));
        out.cost_label = "queue steps";
        out.cost = static_cast<double>(m.queue.pushes + m.queue.pops);
    }
    return out;
}

std::vector<Measurements> FrameSource::measurements() const {
    std::vector<Measurements> out;
    for (const Panel& panel : panels_) out.push_back(panel.engine->measurements());
    return out;
}

// ------------------------------------------------------------------------------------------------
// Render side

FrameComposer::FrameComposer(const RenderPlan& plan) : plan_(plan) {
    content_.notes = comparison_notes(plan.mode);
}

const render::FrameContent& FrameComposer::compose(const SimFrame& frame) {
    const LessonPlan& lesson = plan_.lesson;
    const double video_time = static_cast<double>(frame.index) / plan_.fps;
    content_.panels.resize(frame.panels.size());
    content_.energy_drift.resize(frame.panels.size());
    for (std::size_t i = 0; i < frame.panels.size(); ++i) {
        const PanelFrame& panel = frame.panels[i];
        render::PanelContent& out = content_.panels[i];
        out.snapshot = &panel.snapshot;
        out.title = panel.title;
        out.counters = panel.counters;
        out.figures = panel.figures;
        out.compact_line = panel.compact_line;
        out.cost_label = panel.cost_label;
        out.cost = panel.cost;
        out.accent = render::panel_accent(panel.time_driven);
        out.note.clear();
        out.step_period = 1;
        out.step_phase = 0;
        if (panel.time_driven && lesson.frames_per_step > 1) {
            // Which frame of the held step this is: a new state restarts the count.
            if (panel.snapshot.time != last_step_time_) {
                last_step_time_ = panel.snapshot.time;
                step_phase_ = 0;
            } else {
                ++step_phase_;
            }
            out.note = step_note(plan_.time_engine.dt, plan_.clock.interval);
            out.step_period = lesson.frames_per_step;
            out.step_phase = std::min(step_phase_, lesson.frames_per_step - 1);
        }
        content_.energy_drift[i].push_back(panel.drift);
        if (std::isfinite(panel.drift.drift))
            largest_drift_ = std::max(largest_drift_, std::abs(panel.drift.drift));
    }
    content_.time_text = clock_label(frame.time, plan_.clock, plan_.speed.speed);
    if (plan_.render.overlays == render::OverlayLevel::lesson) {
        // Just the time: the column is narrow and the playback rate is no lesson.
        content_.time_text = content_.time_text.substr(0, content_.time_text.find("   ("));
    }
    content_.video_time = video_time;
    content_.speed = plan_.speed.speed;
    content_.caption = lesson.caption_at(video_time);
    content_.histogram = lesson.histogram;
    const bool conserved = largest_drift_ <= round_off_drift;
    content_.energy_line = conserved ? "Energy conserved" : "Energy not conserved";
    content_.energy_plot = !conserved;
    content_.intro_title = lesson.title;
    content_.intro_text = lesson.description;
    content_.intro_opacity = lesson.intro_opacity(video_time);
    return content_;
}

PipelineResult render_video(const Scene& scene, const RenderPlan& plan,
                            const PipelineHooks& hooks) {
    const std::atomic<bool>* cancel =
        hooks.interrupts != nullptr ? &hooks.interrupts->flag() : nullptr;
    video::VideoOptions options;
    options.path = plan.output;
    options.format = plan.format;
    options.width = plan.width;
    options.height = plan.height;
    options.fps = plan.fps;
    options.cancel = cancel;
    check_captions_fit(scene, plan);
    video::VideoWriter writer(options);  // validates, checks the path, creates the temporary
    std::unique_ptr<render::PreviewWindow> preview = open_preview_if_asked(plan, hooks);
    render::Renderer renderer(plan.render, render_backend(preview.get(), hooks), hooks.notice);
    RawDump dump(hooks.dump_rgba);

    PipelineResult result;
    FrameComposer composer(plan);
    SimulationThread simulation(scene, plan, cancel);
    while (std::optional<SimFrame> frame = simulation.next()) {
        check_interrupt(hooks);
        Image image = writer.spare_frame();
        const render::FrameContent& content = composer.compose(*frame);
        renderer.render(content, image);
        if (!plan.layout_json.empty() && frame->index + 1 == plan.clock.count) {
            result.layout_json = renderer.layout_json(content);
        }
        // Closing the window stops the preview only: the video is encoded to the end.
        if (preview && !preview->show(image)) preview.reset();
        dump.write(image);
        writer.write(std::move(image));
        result.frames += 1;
        result.sim_time = frame->time;
        if (hooks.progress != nullptr) hooks.progress->frame_done(frame->time);
    }
    // Interrupted: say so, rather than the "simulation stopped" the engines threw on seeing it.
    check_interrupt(hooks);
    result.engines = simulation.finish();
    if (result.frames != plan.clock.count)
        throw_runtime_error("rendering stopped before the last frame");
    writer.finish();
    dump.finish();
    result.notices = writer.notices();
    result.output_width = writer.output_width();
    result.output_height = writer.output_height();
    result.output_fps = writer.output_fps();
    return result;
}

PipelineResult render_still(const Scene& scene, const RenderPlan& plan,
                            const PipelineHooks& hooks) {
    const std::atomic<bool>* cancel =
        hooks.interrupts != nullptr ? &hooks.interrupts->flag() : nullptr;
    check_captions_fit(scene, plan);
    // Opened first (it stays hidden until it has the image) so the renderer can share its GL.
    std::unique_ptr<render::PreviewWindow> preview = open_preview_if_asked(plan, hooks);
    render::Renderer renderer(plan.render, render_backend(preview.get(), hooks), hooks.notice);
    // Only the frames whose positions appear in the trails need drawing before the last one.
    const std::int64_t history = plan.render.trails ? plan.render.trail_length : 1;
    const std::int64_t first_drawn = std::max<std::int64_t>(0, plan.clock.count - history);

    PipelineResult result;
    FrameComposer composer(plan);
    Image image;
    SimulationThread simulation(scene, plan, cancel);
    while (std::optional<SimFrame> frame = simulation.next()) {
        check_interrupt(hooks);
        const render::FrameContent& content = composer.compose(*frame);
        if (frame->index + 1 == plan.clock.count) {
            renderer.render(content, image);
            if (!plan.layout_json.empty()) result.layout_json = renderer.layout_json(content);
        } else if (frame->index >= first_drawn) {
            renderer.draw(content);
        }
        result.frames += 1;
        result.sim_time = frame->time;
        if (hooks.progress != nullptr) hooks.progress->frame_done(frame->time);
    }
    // Interrupted: say so, rather than the "simulation stopped" the engines threw on seeing it.
    check_interrupt(hooks);
    result.engines = simulation.finish();
    if (result.frames != plan.clock.count)
        throw_runtime_error("rendering stopped before the last frame");
    if (preview) preview->show(image);
    video::write_png(image, plan.output);
    result.output_width = image.width;
    result.output_height = image.height;
    return result;
}

}  // namespace collide::app
