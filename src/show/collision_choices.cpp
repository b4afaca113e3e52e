// The collision lesson's choices made once for the whole video: what each overlay level shows,
// the cards and captions, the histogram, the trails and the replays.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "collide/error.hpp"
#include "collide/show/collision_program.hpp"
#include "collide/show/collision_summary.hpp"
#include "collide/show/questions.hpp"
#include "collide/show/timeline.hpp"

namespace collide::show {

namespace {

/// Captions beyond the video: an error when the video is as long as the scene says (the scene
/// is wrong), a notice when --duration shortened it (a preview).
std::vector<CaptionCue> captions_within(const std::vector<CaptionCue>& captions, double duration,
                                        bool cli_duration, std::vector<std::string>& notices) {
    std::vector<CaptionCue> kept;
    for (CaptionCue cue : captions) {
        if (cue.at < duration && cue.at + cue.hold > duration) {
            if (!cli_duration) {
                throw_scene_error(cue.file, cue.line, "render.captions.hold",
                                  fmt::format("beyond the video: held from {:g} s for {:g} s, "
                                              "the video lasts {:g} s (set [render] duration)",
                                              cue.at, cue.hold, duration));
            }
            notices.push_back(
                fmt::format("the hold at {:g} s is cut short at the end of this "
                            "{:g} s video",
                            cue.at, duration));
            cue.hold = duration - cue.at;
        }
        if (cue.at < duration) {
            kept.push_back(cue);
            continue;
        }
        if (!cli_duration) {
            throw_scene_error(cue.file, cue.line, "render.captions.at",
                              fmt::format("beyond the video: {:g} s, the video lasts {:g} s "
                                          "(set [render] duration)",
                                          cue.at, duration));
        }
        notices.push_back(
            fmt::format("the caption at {:g} s is after the end of this {:g} s "
                        "video: not shown",
                        cue.at, duration));
    }
    return kept;
}

/// The cue's words for the panels the video shows: its `event` or `time` form in a video of
/// that panel alone, else its text.
std::string caption_for_panels(const CaptionCue& cue, const LessonRequest& request) {
    if (request.event_panel && !request.time_panel && cue.event_text) return *cue.event_text;
    if (request.time_panel && !request.event_panel && cue.time_text) return *cue.time_text;
    return cue.text;
}

/// A stretch of video in which the simulation stands still (a caption's hold, a question).
struct Freeze {
    double at = 0.0;
    double seconds = 0.0;
};

/// Seconds of simulation running before `at` seconds of video, frozen by `intro` seconds of
/// card and by `freezes`.
double running_before(double at, double intro, const std::vector<Freeze>& freezes) {
    double frozen = std::min(intro, at);
    for (const Freeze& f : freezes) {
        if (f.at < at) frozen += std::min(f.seconds, at - f.at);
    }
    return std::max(0.0, at - frozen);
}

/// The second of video at which `running` seconds of simulation (at this video's pace) have run
/// after `intro` seconds of card and `freezes`: each freeze starting before it delays it.
double video_second_after(double running, double intro, const std::vector<Freeze>& freezes) {
    double at = intro + running;
    // Each pass adds the freezes that start before the moment found; it only moves later, and
    // settles once no further freeze starts before it.
    for (std::size_t pass = 0; pass <= freezes.size(); ++pass) {
        double frozen = 0.0;
        for (const Freeze& f : freezes) {
            if (f.at < at) frozen += f.seconds;
        }
        const double next = intro + running + frozen;
        if (next == at) break;
        at = next;
    }
    return at;
}

/// The captions of a video whose simulation runs `request.slower` times slower than the scene's
/// own pace (--code's slow motion, --slow-motion, --speed): each caption written for the moment
/// the scene's video shows at its `at` moves to where this video shows that moment (the same
/// simulation time; the cards, holds and questions stay seconds of video). Without this, a
/// slowed video would say "the pictures drift apart" long before they do. The replays' holds are
/// not known here: they only make a slowed caption later.
/// A caption so moved past `run_end` (the summary card or the end) is left out with a notice in
/// `notices`.
std::vector<CaptionCue> paced_captions(const Scene& scene, const LessonRequest& request,
                                       const LessonPlan& lesson, double run_end,
                                       const LevelShows& shows, std::vector<std::string>& notices) {
    // A faster video shows a moment after its caption's: late, but not yet untrue.
    if (!(request.slower > 1.0)) return scene.render.captions;
    const bool scene_intro = !scene.description.empty() && shows.cards;
    const double written_intro =
        scene_intro ? std::min(intro_seconds, 0.25 * request.scene_duration) : 0.0;
    std::vector<Freeze> written;  // the scene's own video
    for (const QuestionCue& cue : scene.render.questions)
        written.push_back({cue.at, cue.think + reveal_seconds_of(cue.kind)});
    for (const CaptionCue& cue : scene.render.captions) {
        if (shows.caption_holds && cue.hold > 0.0) written.push_back({cue.at, cue.hold});
    }
    std::vector<Freeze> here;  // this video's: its questions, then the moved captions' holds
    for (const TimelineQuestion& q : lesson.questions) here.push_back({q.at, q.think + q.reveal});
    std::vector<CaptionCue> captions;
    for (CaptionCue cue : scene.render.captions) {
        const double running = running_before(cue.at, written_intro, written) * request.slower;
        double at = video_second_after(running, lesson.intro_seconds, here);
        // Moved together, a caption waits until the one before it has been read.
        if (!captions.empty()) {
            const CaptionCue& before = captions.back();
            at = std::max(
                at, before.at + std::max(before.hold, caption_reading_seconds(
                                                          caption_for_panels(before, request))));
        }
        // A caption the run ends before it can be read is left out as one it never reaches.
        if (at + caption_reading_seconds(caption_for_panels(cue, request)) > run_end) {
            const std::string place = cue.file.empty() ? std::string("the scene")
                                                       : fmt::format("{}:{}", cue.file, cue.line);
            notices.push_back(fmt::format(
                "{}: render.captions: the caption at {:g} s describes a moment this video, {:.3g}x "
                "slower than the scene's pace, reaches at {:.1f} s, too late to be read before "
                "its run ends at {:.1f} s: not shown",
                place, cue.at, request.slower, at, run_end));
            continue;
        }
        cue.at = at;
        if (shows.caption_holds && cue.hold > 0.0) here.push_back({cue.at, cue.hold});
        captions.push_back(cue);
    }
    return captions;
}

}  // namespace

LevelShows level_shows(OverlayLevel level) noexcept {
    LevelShows shows;
    switch (level) {
        case OverlayLevel::none:
            break;
        case OverlayLevel::full:
            shows.text = true;
            break;
        case OverlayLevel::lesson:
            shows.text = true;
            shows.cards = true;
            shows.caption_holds = true;
            shows.captions = true;
            shows.queue = true;
            shows.replays = true;
            shows.next_collision = true;
            shows.time_unit = true;
            break;
    }
    return shows;
}

LessonPlan lesson_plan(const Scene& scene, const LessonRequest& request,
                       std::vector<std::string>& notices) {
    const LevelShows shows = level_shows(request.level);
    LessonPlan lesson;
    lesson.title = scene.title;
    lesson.description = scene.description;
    // The card as the video has it (a still drops it once the video's timeline is known): only
    // at the level that draws it, where the simulation waits for it.
    if (request.intro && !scene.description.empty() && shows.cards)
        lesson.intro_seconds = std::min(intro_seconds, 0.25 * request.duration);
    // The summary card at the end, where the lesson's figures are shown.
    if (request.epilogue && shows.cards)
        lesson.epilogue_seconds = std::min(epilogue_seconds, 0.2 * request.duration);
    // Questions: where the lesson's captions and words are drawn, by the panel that answers
    // them (will-see: the time-driven one; the others: the event-driven one). Planned before the
    // captions: a slowed video's captions move around them.
    std::vector<std::string> question_notices;
    if (request.questions && shows.replays && !request.step_list) {
        for (const QuestionCue& cue : scene.render.questions) {
            const bool event = needs_event_panel(cue.kind);
            if (event ? !request.event_panel : needs_time_panel(cue.kind) && !request.time_panel) {
                question_notices.push_back(question_place(cue) + ": render.questions: a " +
                                           std::string(question_kind_name(cue.kind)) +
                                           " question needs the " + (event ? "event" : "time") +
                                           "-driven panel; not asked");
                continue;
            }
            lesson.questions.push_back({cue.at,
                                        cue.think,
                                        reveal_seconds_of(cue.kind),
                                        {},
                                        {},
                                        cue.kind == QuestionKind::will_see});
            lesson.question_cues.push_back(cue);
        }
    }
    lesson.caption = scene.render.caption.value_or("");
    // A caption moved past the end by the command line's pace is the command line's doing: a
    // notice, as past a --duration's end.
    lesson.captions = captions_within(
        paced_captions(scene, request, lesson, request.duration - lesson.epilogue_seconds, shows,
                       notices),
        request.duration, request.duration_from_cli || request.slower > 1.0, notices);
    // One panel: the words written for it, never a word of the absent one ("Left tests...").
    for (CaptionCue& cue : lesson.captions) cue.text = caption_for_panels(cue, request);
    lesson.epilogue_caption = request.time_panel && request.event_panel
                                  ? "In the end: what each method counted"
                                  : "In the end: the final figures";
    if (request.step_list) {
        // A --dt list: the scene's captions speak of two panels ("Left: ..."); the video's one
        // caption says what the panels side by side show.
        lesson.caption = step_list_caption;
        lesson.captions.clear();
    }
    // A hold freezes the picture for its caption to be read: only where captions are shown.
    if (!shows.caption_holds) {
        for (CaptionCue& cue : lesson.captions) cue.hold = 0.0;
    }
    // The questions' notices where they always came: after the captions'.
    notices.insert(notices.end(), question_notices.begin(), question_notices.end());
    lesson.histogram = histogram_size(scene);
    // A --dt list: each panel's note and step indicator are its own (CollisionSimulation).
    if (request.step_list) return lesson;
    lesson.frames_per_step = whole_frames_per_step(request.dt, request.frame_interval);
    lesson.step_note = step_note(request.dt, request.frame_interval);
    return lesson;
}

std::size_t moving_disc_count(const Scene& scene) {
    if (scene.discs.empty()) return 0;
    double lightest = std::numeric_limits<double>::infinity();
    for (const Disc& d : scene.discs) lightest = std::min(lightest, d.mass);
    const double heavy = immovable_mass_ratio * lightest;
    return static_cast<std::size_t>(
        std::count_if(scene.discs.begin(), scene.discs.end(),
                      [&](const Disc& d) { return std::isfinite(d.mass) && d.mass < heavy; }));
}

PlotSize histogram_size(const Scene& scene) {
    // A distribution needs discs: below this many moving ones a histogram is noise.
    constexpr std::size_t enough_for_a_distribution = 200;
    // "auto": only where it teaches, i.e. where there are enough moving discs; a scene may ask
    // for one anyway ("small"), or make it the subject ("large", e.g. maxwell-boltzmann).
    if (scene.render.histogram) return *scene.render.histogram;
    if (moving_disc_count(scene) >= enough_for_a_distribution) return PlotSize::small;
    return PlotSize::none;
}

bool few_tagged_discs(const Scene& scene) {
    constexpr std::size_t few_tagged = 8;
    const auto tagged = static_cast<std::size_t>(std::count_if(
        scene.discs.begin(), scene.discs.end(), [](const Disc& d) { return !d.tag.empty(); }));
    return tagged > 0 && tagged <= few_tagged;
}

int trail_length(const Scene& scene, std::int64_t frames) {
    constexpr std::int64_t default_length = 48;
    constexpr std::int64_t longest = 1024;
    if (!few_tagged_discs(scene)) return static_cast<int>(default_length);
    return static_cast<int>(std::clamp(frames, default_length, longest));
}

ReplayChoice shown_replays(ReplayChoice asked, bool time_panels, OverlayLevel level) {
    // The replay's words and marks are the lesson's: a level without them replays nothing.
    if (!time_panels || !level_shows(level).replays) return ReplayChoice::none;
    return asked;
}

}  // namespace collide::show
