// The collision video's engines: advanced to each frame's time and described as a class sees
// them (snapshots, figures, titles, the next collision).
#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>
#include <utility>

#include "collide/error.hpp"
#include "collide/show/collision_program.hpp"

namespace collide::show {

namespace {

/// How far past the last frame the next collision line looks (seconds of video): a thumbnail's
/// last frame shows its line too; a collision further away is no "next" a class waits for.
constexpr double lookahead_seconds = 10.0;

double relative_drift(double energy, double initial) {
    return initial > 0.0 ? (energy - initial) / initial : 0.0;
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

struct CollisionSimulation::Panel {
    std::unique_ptr<Engine> engine;               ///< discs
    std::unique_ptr<SphereEngine> sphere_engine;  ///< or spheres
    [[nodiscard]] EngineBase& base() const {
        return engine ? static_cast<EngineBase&>(*engine) : *sphere_engine;
    }
    bool time_driven = false;
    double compared_dt = 0.0;  ///< PanelState::compared_dt
    std::string title;
    std::string short_title;
    std::string note;
    int frames_per_step = 1;
    double initial_energy = 0.0;
    /// What the event-driven engine resolves next, for the next collision line (lesson level,
    /// no queue strip, discs). nullptr: none drawn. After `engine`, which it watches: destroyed
    /// first.
    std::unique_ptr<sim::CollisionLookahead> lookahead;
};

CollisionSimulation::CollisionSimulation(SceneView scene, const CollisionSettings& settings,
                                         const std::atomic<bool>* stop)
    : settings_(settings) {
    const OverlayLevel level = settings.level;
    const auto add = [&](EngineOptions options, bool time_driven, std::string title) -> Panel& {
        Panel panel;
        options.stop = stop;  // building 4 M spheres' engine takes seconds
        if (scene.three_d()) {
            panel.sphere_engine = make_engine(scene.spheres(), options);
        } else {
            panel.engine = make_engine(scene.discs(), options);
        }
        panel.base().set_stop_flag(stop);
        if (!time_driven && settings.queue_events > 0 &&
            !watch_queue(panel.base(), queue_picture(settings.queue_events)))
            throw_option_error("--queue", "the " + std::string(to_string(options.engine)) +
                                              " engine has no event queue");
        if (!time_driven && !scene.three_d() && level_shows(level).next_collision &&
            settings.queue_events == 0) {
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
    const bool narrow = settings.code;
    if (settings.time_panels && settings.time_steps.empty()) {
        Panel& panel =
            add(settings.time_engine, true, panel_title(true, level, settings.time_engine, narrow));
        panel.note = settings.lesson.step_note;
        panel.frames_per_step = settings.lesson.frames_per_step;
    }
    if (settings.time_panels) {
        // A --dt list: one time-driven panel per step.
        for (const double dt : settings.time_steps) {
            EngineOptions options = settings.time_engine;
            options.dt = dt;
            Panel& panel = add(options, true, compared_step_title(dt, level));
            panel.short_title = compared_step_short_title(dt);
            // No step note: beside the others its line would not fit, and the titles say
            // which steps are long.
            panel.compared_dt = dt;
        }
    }
    if (settings.event_panel) {
        Panel& panel = add(settings.event_engine, false,
                           panel_title(false, level, settings.event_engine, narrow));
        // Beside a --dt list's panels the cells are narrower: a short title where it must.
        if (!settings.time_steps.empty()) panel.short_title = event_short_title;
    }
}

CollisionSimulation::~CollisionSimulation() = default;

CollisionState CollisionSimulation::state(std::int64_t k) {
    CollisionState out;
    out.index = k;
    out.sim_frame = settings_.timeline.sim_frame(k);
    out.time = settings_.clock.time(out.sim_frame);
    out.moved = out.sim_frame != last_sim_frame_;
    last_sim_frame_ = out.sim_frame;
    out.panels.reserve(panels_.size());
    // The camera turns with the moving picture (a card or a hold keeps it where it is).
    const double video_seconds = static_cast<double>(out.sim_frame) / settings_.fps;
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

double CollisionSimulation::schedule_time(std::int64_t k) const {
    const std::int64_t count = settings_.timeline.frame_count();
    if (k < count) return settings_.clock.time(settings_.timeline.sim_frame(k));
    return settings_.clock.time(settings_.timeline.sim_frame(count - 1)) +
           static_cast<double>(k - count + 1) * settings_.clock.interval;
}

NextCollisionView CollisionSimulation::next_collision(Panel& panel, const Snapshot& snapshot,
                                                      std::int64_t k) {
    // After describe(): the engine may be advanced to frame k + 1's time here, and the frame's
    // figures must be those of frame k.
    const std::int64_t count = settings_.timeline.frame_count();
    const auto last =
        count + static_cast<std::int64_t>(std::ceil(lookahead_seconds * settings_.fps));
    const sim::FramesAhead frames{[this, k](std::int64_t i) { return schedule_time(k + i); },
                                  count - 1 - k, last - 1 - k};
    const std::optional<CollisionRecord> next = panel.lookahead->next(frames);
    if (!next) return {};
    return next_collision_view(*next, snapshot, settings_.clock);
}

PanelState CollisionSimulation::describe(const Panel& panel, double video_seconds) const {
    PanelState out;
    if (panel.sphere_engine) {
        ProjectedPanel projected = project(
            panel.sphere_engine->snapshot(),
            camera_at(settings_.camera, video_seconds, settings_.slab, settings_.projection));
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
    out.words = panel_words(m, panel.time_driven, out.snapshot.box.boundary == Boundary::walls,
                            drift, settings_.event_engine.engine);
    if (out.snapshot.queue) out.queue_words = queue_words(*out.snapshot.queue, out.snapshot.time);
    return out;
}

std::vector<Measurements> CollisionSimulation::measurements() const {
    std::vector<Measurements> out;
    for (const Panel& panel : panels_) out.push_back(panel.base().measurements());
    return out;
}

}  // namespace collide::show
