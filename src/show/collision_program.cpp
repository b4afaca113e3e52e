// The collision video's frames: the engines' state at frame k -> the view the painter paints.
#include "collide/show/collision_program.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "collide/show/collision_summary.hpp"
#include "collide/show/event_loop_code.hpp"
#include "collide/show/plot_words.hpp"

namespace collide::show {

CollisionProgram::CollisionProgram(const CollisionSettings& settings) : settings_(settings) {
    // The colour scale is fixed for the whole video, and so are its words.
    content_.color_key = color_key(settings.color_mode, settings.speed_min, settings.speed_max,
                                   settings.mass_min, settings.mass_max);
    content_.speed_plot = speed_plot_words(settings.speed_max);
}

void CollisionProgram::advance_step_phase(std::size_t i, double state_time) {
    if (state_time != last_step_time_[i]) {
        last_step_time_[i] = state_time;
        step_phase_[i] = 0;
    } else {
        ++step_phase_[i];
    }
}

const ReplayView& CollisionProgram::question_picture(const Segment& segment,
                                                     const Snapshot& snapshot,
                                                     double seconds_left) {
    const QuestionAnswer& answer = settings_.questions[static_cast<std::size_t>(segment.question)];
    const bool reveal = segment.kind == SegmentKind::reveal;
    if (question_segment_ != &segment) {
        // The letters' places are searched once a segment: the picture is frozen.
        question_segment_ = &segment;
        question_view_ = question_view(answer, snapshot, settings_.clock, seconds_left, reveal);
    } else if (!reveal) {
        // Only the countdown changes.
        if (!question_view_.heading.empty()) question_view_.heading = countdown_words(seconds_left);
    }
    return question_view_;
}

const FrameContent& CollisionProgram::frame(const CollisionState& state) {
    const LessonPlan& lesson = settings_.lesson;
    const LevelShows shows = level_shows(settings_.level);
    const Segment& segment = settings_.timeline.segment_at(state.index);
    const double video_time = static_cast<double>(state.index) / settings_.fps;
    content_.panels.resize(state.panels.size());
    if (marks_.size() != state.panels.size()) {
        // The wrap note of a periodic box is said once, by the first panel: its legend line
        // takes the frame's width when the other panel (event-driven: no failures) has none.
        marks_.clear();
        for (std::size_t i = 0; i < state.panels.size(); ++i)
            marks_.emplace_back(mark_budget, i == 0);
    }
    content_.energy_drift.resize(state.panels.size());
    last_step_time_.resize(state.panels.size(), -1.0);
    step_phase_.resize(state.panels.size(), 0);
    // A question or its answer: the event-driven panel marks the candidates (its own next
    // collision line would give the answer away) and counts down, or shows the answer.
    const bool asking =
        (segment.kind == SegmentKind::question || segment.kind == SegmentKind::reveal) &&
        segment.question >= 0 &&
        static_cast<std::size_t>(segment.question) < settings_.questions.size();
    const QuestionAnswer* asked =
        asking ? &settings_.questions[static_cast<std::size_t>(segment.question)] : nullptr;
    // A will-see question is the time-driven panel's: its answer is the replay of the step.
    const bool will_see = asked != nullptr && asked->kind == QuestionKind::will_see;
    // A replay: both panels zoom onto the failure's spot, each with its own marks.
    const ReplayFailure* replay =
        segment.kind == SegmentKind::replay ? replay_at(settings_.replays, segment.sim_frame)
        : will_see && segment.kind == SegmentKind::reveal && asked->failure ? &*asked->failure
                                                                            : nullptr;
    std::optional<ReplayViews> replayed;
    if (replay != nullptr && !state.panels.empty()) {
        replayed =
            replay_views(*replay, state.panels[0].snapshot.box,
                         static_cast<double>(state.index - segment.first_frame) / settings_.fps);
    }
    content_.code.reset();
    for (std::size_t i = 0; i < state.panels.size(); ++i) {
        const PanelState& panel = state.panels[i];
        PanelContent& out = content_.panels[i];
        if (settings_.code && panel.snapshot.queue && !content_.code) {
            // --code: the loop's line under way, from the queue's latest pop.
            content_.code =
                event_loop_view(*panel.snapshot.queue, panel.snapshot.time, settings_.speed);
        }
        out.snapshot = &panel.snapshot;
        out.spheres = panel.spheres ? &panel.view : nullptr;
        out.title = panel.title;
        out.short_title = panel.short_title;
        out.counters = panel.words.counters;
        out.figures = panel.words.figures;
        out.compact_line = panel.words.compact_line;
        out.cost_label = panel.compared_dt > 0.0 ? compared_cost_label(panel.compared_dt)
                                                 : panel.words.cost_label;
        out.cost = panel.words.cost;
        out.cost_text = panel.words.cost_text;
        out.cost_words = panel.words.cost_words;
        out.how = state.panels.size() == 2 ? panel.words.how : std::string();
        out.queue_words = panel.queue_words;
        out.time_driven = panel.time_driven;
        out.note = panel.note;
        out.step_period = 1;
        out.step_phase = 0;
        if (panel.time_driven && panel.frames_per_step > 1) {
            // Which frame of the held step this is: a new state restarts the count (a frozen
            // frame, a card's or a hold's, is no frame of the step).
            if (state.moved) advance_step_phase(i, panel.snapshot.time);
            out.step_period = panel.frames_per_step;
            out.step_phase = std::min(step_phase_[i], panel.frames_per_step - 1);
        }
        if (shows.text) {
            // The failure marks and their legend. They fade with the moving picture (a card or
            // a hold keeps them as they are).
            marks_[i].update(panel.snapshot, static_cast<double>(state.sim_frame) / settings_.fps);
            out.marks = marks_[i].marks();
            out.mark_words = marks_[i].words();
            out.mark_line = mark_line(panel.time_driven, i == 0, panel.snapshot.box);
        }
        // A replay draws the collision the event-driven panel predicted itself: no second line.
        out.next_collision = replayed ? NextCollisionView{} : panel.next_collision;
        out.zoom = replayed ? replayed->zoom : BoxZoom{};
        out.replay = !replayed           ? ReplayView{}
                     : panel.time_driven ? replayed->time_driven
                                         : replayed->event_driven;
        out.queue_in_box = true;
        if (asking && !will_see && !panel.time_driven && !replayed) {
            out.next_collision = {};
            out.queue_in_box = false;
            out.replay = question_picture(segment, panel.snapshot, segment.end - video_time);
        }
        if (will_see && panel.time_driven && !replayed && asked->failure) {
            // The replay's zoom from the start: the two discs are a few pixels in the whole box.
            out.replay = will_see_view(*asked, segment.end - video_time);
            out.zoom = replay_target(*asked->failure, panel.snapshot.box);
        }
        if (state.moved || content_.energy_drift[i].empty())
            content_.energy_drift[i].push_back(panel.drift);
        drifts_.resize(state.panels.size());
        drifts_[i].time_driven = panel.time_driven;
        if (std::isfinite(panel.drift.drift))
            drifts_[i].largest = std::max(drifts_[i].largest, std::abs(panel.drift.drift));
    }
    // The ratio compares the two engines (time-driven first, as the settings order them).
    content_.cost_ratio = state.panels.size() == 2
                              ? work_ratio(state.panels[0].words.cost, state.panels[1].words.cost)
                              : std::string();
    content_.time_text = clock_text(state.time, settings_.clock, settings_.speed, settings_.level);
    content_.time_unit = shows.time_unit ? time_unit : std::string();
    content_.cost_heading = cost_heading;
    // Failure markers fade with the moving picture: a card or a hold keeps them as they are.
    content_.video_time = static_cast<double>(state.sim_frame) / settings_.fps;
    content_.speed = settings_.speed;
    content_.pop_highlight = {pop_highlight_seconds(false, settings_.code),
                              pop_highlight_seconds(true, settings_.code)};
    // The card's words are its title (the timeline's caption); beneath it, the scene's caption.
    content_.caption =
        segment.kind == SegmentKind::card ? lesson.caption_at(video_time) : segment.caption;
    content_.histogram = lesson.histogram;
    content_.energy_line = energy_line(drifts_);
    content_.energy_plot = std::any_of(drifts_.begin(), drifts_.end(), [](const EngineDrift& d) {
        return d.largest > round_off_drift;
    });
    content_.drift_plot = drift_plot_words(content_.energy_drift);
    content_.intro_title = lesson.title;
    content_.intro_text = lesson.description;
    content_.intro_opacity = lesson.intro_opacity(video_time);
    content_.summary = {};
    if (segment.kind == SegmentKind::epilogue) {
        std::vector<SummaryPanel> panels;
        for (const PanelState& panel : state.panels)
            panels.push_back({panel.measurements, panel.time_driven, panel.compared_dt});
        const bool walls =
            !state.panels.empty() && state.panels[0].snapshot.box.boundary == Boundary::walls;
        // The card is the lesson's: its clock is the lesson column's, whatever the level.
        const bool spheres = !state.panels.empty() && state.panels[0].spheres;
        content_.summary = summary_card(
            panels, walls,
            clock_text(state.time, settings_.clock, settings_.speed, OverlayLevel::lesson),
            spheres);
        content_.summary.opacity = summary_opacity(video_time - segment.start);
        // The caption over the card says what the figures mean: the timeline's (the subtitles')
        // was written before the run, without them.
        content_.caption = epilogue_caption(panels);
    }
    return content_;
}

}  // namespace collide::show
