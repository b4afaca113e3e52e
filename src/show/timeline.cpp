// The lesson timeline: a script in seconds of video (card, captions with holds, epilogue) turned
// into segments on whole video frames, each showing one simulation frame or a run of them.
#include "collide/show/timeline.hpp"

#include <algorithm>
#include <cmath>

#include "collide/assert.hpp"
#include "collide/show/still_timeline.hpp"

namespace collide::show {

std::string_view segment_kind_name(SegmentKind kind) noexcept {
    switch (kind) {
        case SegmentKind::card:
            return "card";
        case SegmentKind::run:
            return "run";
        case SegmentKind::hold:
            return "hold";
        case SegmentKind::replay:
            return "replay";
        case SegmentKind::epilogue:
            return "epilogue";
        case SegmentKind::question:
            return "question";
        case SegmentKind::reveal:
            return "reveal";
    }
    return "run";
}

double caption_reading_seconds(std::string_view caption) noexcept {
    std::size_t words = 0;
    bool in_word = false;
    for (const char c : caption) {
        const bool space = c == ' ' || c == '\n' || c == '\t';
        if (!space && !in_word) ++words;
        in_word = !space;
    }
    return std::clamp(0.5 + 0.3 * static_cast<double>(words), 1.5, 4.0);
}

std::int64_t Timeline::frame_count() const noexcept {
    return segments.empty() ? 0 : segments.back().end_frame;
}

const Segment& Timeline::segment_at(std::int64_t k) const {
    COLLIDE_ASSERT(!segments.empty() && k >= 0 && k < frame_count(), "a frame of the video");
    const auto after =
        std::upper_bound(segments.begin(), segments.end(), k,
                         [](std::int64_t f, const Segment& s) { return f < s.first_frame; });
    return *std::prev(after);
}

std::int64_t Timeline::last_sim_frame() const noexcept {
    return segments.empty() ? 0 : segments.back().last_sim_frame();
}

namespace {

/// What one video frame is, before frames of the same kind merge into segments.
struct FrameLabel {
    SegmentKind kind = SegmentKind::run;
    bool moves = true;
    int caption = -1;   ///< index into the cues; -1: the script's caption (or the kind's own)
    int replay = -1;    ///< index into the replays (a replay frame)
    int question = -1;  ///< index into the questions (a question or reveal frame)
};

std::int64_t whole_frames(double seconds, int fps) {
    if (!(seconds > 0.0)) return 0;
    return std::llround(seconds * static_cast<double>(fps));
}

/// The first video frame whose time k / fps is at or after `seconds`: where a caption timed at
/// `seconds` appears, and how many frames lie before it.
std::int64_t first_frame_at(double seconds, int fps) {
    if (!(seconds > 0.0)) return 0;
    const auto rate = static_cast<double>(fps);
    auto k = static_cast<std::int64_t>(std::ceil(seconds * rate));
    while (k > 0 && static_cast<double>(k - 1) / rate >= seconds) --k;
    while (static_cast<double>(k) / rate < seconds) ++k;
    return k;
}

std::string caption_of(const TimelineScript& script, const FrameLabel& label) {
    if (label.kind == SegmentKind::card) return script.card_title;
    if (label.kind == SegmentKind::epilogue) return script.epilogue_caption;
    if (label.kind == SegmentKind::replay)
        return script.replays[static_cast<std::size_t>(label.replay)].caption;
    if (label.kind == SegmentKind::question)
        return script.questions[static_cast<std::size_t>(label.question)].question;
    if (label.kind == SegmentKind::reveal)
        return script.questions[static_cast<std::size_t>(label.question)].answer;
    if (label.caption < 0) return script.caption;
    return script.cues[static_cast<std::size_t>(label.caption)].text;
}

/// How many frames up to and including frame k have shown the caption frame k shows (runs and
/// holds: a card or a replay before it is not reading time).
std::int64_t frames_read(const std::vector<FrameLabel>& labels, std::int64_t k) {
    const int caption = labels[static_cast<std::size_t>(k)].caption;
    std::int64_t first = k;
    while (first > 0) {
        const FrameLabel& before = labels[static_cast<std::size_t>(first - 1)];
        if (before.caption != caption ||
            (before.kind != SegmentKind::run && before.kind != SegmentKind::hold))
            break;
        --first;
    }
    return k + 1 - first;
}

/// Each replay over the frames after the running frame that first shows its simulation frame:
/// the simulation frames shown are counted as the labels go, so holds before it delay it. When
/// the caption on screen appeared too recently to be read, the picture first holds on it (its
/// reading time, caption_reading_seconds), then the replay begins.
void place_replays(const TimelineScript& script, std::int64_t epilogue_start,
                   std::vector<FrameLabel>& labels) {
    std::size_t next = 0;
    std::int64_t shown = -1;
    std::int64_t replayed = -1;  // the failure a question's reveal replayed (its frame)
    for (std::int64_t k = 0; k < epilogue_start && next < script.replays.size(); ++k) {
        const FrameLabel label = labels[static_cast<std::size_t>(k)];
        shown = label.moves ? shown + 1 : std::max<std::int64_t>(shown, 0);
        if (label.question >= 0 &&
            script.questions[static_cast<std::size_t>(label.question)].reveal_replays)
            replayed = shown + 1;
        while (next < script.replays.size() && (script.replays[next].after_sim_frame < shown ||
                                                script.replays[next].after_sim_frame == replayed))
            ++next;
        if (next == script.replays.size()) break;
        const TimelineReplay& replay = script.replays[next];
        if (label.kind != SegmentKind::run || !label.moves || replay.after_sim_frame != shown)
            continue;
        const std::int64_t length = whole_frames(replay.seconds, script.fps);
        const std::int64_t lead = std::max<std::int64_t>(
            0, whole_frames(caption_reading_seconds(caption_of(script, label)), script.fps) -
                   frames_read(labels, k));
        // A question keeps its frames: a replay that would fall on them is left out.
        const auto asks = [&](std::int64_t f) {
            return labels[static_cast<std::size_t>(f)].question >= 0;
        };
        bool free = k + 1 + lead + length <= epilogue_start;
        for (std::int64_t f = k + 1; free && f <= k + lead + length; ++f) free = !asks(f);
        if (length > 0 && free) {
            for (std::int64_t f = k + 1; f <= k + lead; ++f)
                labels[static_cast<std::size_t>(f)] = {SegmentKind::hold, false, label.caption};
            for (std::int64_t f = k + lead + 1; f <= k + lead + length; ++f) {
                labels[static_cast<std::size_t>(f)] = {SegmentKind::replay, false, -1,
                                                       static_cast<int>(next)};
            }
            k += lead + length;
        }
        ++next;
    }
}

/// Each question over the first stretch of its length from its time on in which every frame
/// runs (a card, a hold or an earlier question pushes it later); a question that does not end
/// before the epilogue is left out.
void place_questions(const TimelineScript& script, std::int64_t epilogue_start,
                     std::vector<FrameLabel>& labels) {
    const auto runs = [&](std::int64_t k) {
        const FrameLabel& label = labels[static_cast<std::size_t>(k)];
        return label.kind == SegmentKind::run && label.moves;
    };
    for (std::size_t i = 0; i < script.questions.size(); ++i) {
        const TimelineQuestion& question = script.questions[i];
        const std::int64_t think =
            std::max<std::int64_t>(1, whole_frames(question.think, script.fps));
        const std::int64_t reveal =
            std::max<std::int64_t>(1, whole_frames(question.reveal, script.fps));
        std::int64_t from = first_frame_at(question.at, script.fps);
        // The first run of think + reveal frames that only runs, from `from` on.
        std::int64_t free = 0;
        std::int64_t k = from;
        for (; k < epilogue_start && free < think + reveal; ++k) {
            free = runs(k) ? free + 1 : 0;
        }
        if (free < think + reveal) continue;
        from = k - think - reveal;
        for (std::int64_t f = from; f < from + think; ++f)
            labels[static_cast<std::size_t>(f)].kind = SegmentKind::question;
        for (std::int64_t f = from + think; f < from + think + reveal; ++f)
            labels[static_cast<std::size_t>(f)].kind = SegmentKind::reveal;
        for (std::int64_t f = from; f < from + think + reveal; ++f) {
            labels[static_cast<std::size_t>(f)].moves = false;
            labels[static_cast<std::size_t>(f)].question = static_cast<int>(i);
        }
    }
}

/// Every frame's label: captions by video time, then the frozen stretches over them.
std::vector<FrameLabel> label_frames(const TimelineScript& script) {
    const std::int64_t frames = std::max<std::int64_t>(1, script.frames);
    std::vector<FrameLabel> labels(static_cast<std::size_t>(frames));
    const auto at = [&](std::int64_t k) -> FrameLabel& {
        return labels[static_cast<std::size_t>(k)];
    };
    // Frozen stretches leave at least one running frame, taken from the epilogue first.
    // A card beneath which the simulation runs is no frozen stretch: it may cover every frame.
    const std::int64_t card = std::min(first_frame_at(script.card_seconds, script.fps),
                                       script.card_waits ? frames - 1 : frames);
    const std::int64_t epilogue =
        std::clamp<std::int64_t>(whole_frames(script.epilogue_seconds, script.fps), 0,
                                 frames - 1 - std::min(card, frames - 1));
    const std::int64_t epilogue_start = frames - epilogue;

    for (std::size_t i = 0; i < script.cues.size(); ++i) {
        const std::int64_t from =
            std::clamp<std::int64_t>(first_frame_at(script.cues[i].at, script.fps), 0, frames);
        for (std::int64_t k = from; k < frames; ++k) at(k).caption = static_cast<int>(i);
    }
    std::int64_t frozen_until = card;  // holds never overlap the card or each other
    for (std::size_t i = 0; i < script.cues.size(); ++i) {
        const std::int64_t length = whole_frames(script.cues[i].hold, script.fps);
        if (length == 0) continue;
        const std::int64_t from =
            std::max(frozen_until, first_frame_at(script.cues[i].at, script.fps));
        const std::int64_t to = std::min(from + length, epilogue_start);
        for (std::int64_t k = from; k < to; ++k)
            at(k) = {SegmentKind::hold, false, static_cast<int>(i)};
        frozen_until = std::max(frozen_until, to);
    }
    for (std::int64_t k = 0; k < card; ++k) at(k) = {SegmentKind::card, !script.card_waits, -1};
    for (std::int64_t k = epilogue_start; k < frames; ++k)
        at(k) = {SegmentKind::epilogue, false, -1};
    place_questions(script, epilogue_start, labels);
    place_replays(script, epilogue_start, labels);
    return labels;
}

}  // namespace

Timeline build_timeline(const TimelineScript& script) {
    Timeline timeline;
    timeline.fps = std::max(1, script.fps);
    const std::vector<FrameLabel> labels = label_frames(script);
    std::int64_t last_shown = -1;  // the simulation frame shown by the previous video frame
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const FrameLabel& label = labels[i];
        const auto k = static_cast<std::int64_t>(i);
        const std::int64_t shown =
            label.moves ? last_shown + 1 : std::max<std::int64_t>(last_shown, 0);
        const bool same =
            i > 0 && labels[i - 1].kind == label.kind && labels[i - 1].moves == label.moves &&
            // A question's caption is its own words: a scripted caption changing beneath it
            // does not split it.
            (labels[i - 1].caption == label.caption || label.question >= 0) &&
            labels[i - 1].replay == label.replay && labels[i - 1].question == label.question;
        if (!same) {
            Segment segment;
            segment.kind = label.kind;
            segment.first_frame = k;
            segment.sim_frame = shown;
            segment.moves = label.moves;
            segment.caption = caption_of(script, label);
            segment.question = label.question;
            timeline.segments.push_back(std::move(segment));
        }
        timeline.segments.back().end_frame = k + 1;
        last_shown = shown;
    }
    const auto fps = static_cast<double>(timeline.fps);
    for (Segment& segment : timeline.segments) {
        segment.start = static_cast<double>(segment.first_frame) / fps;
        segment.end = static_cast<double>(segment.end_frame) / fps;
    }
    return timeline;
}

std::vector<int> questions_asked(const Timeline& timeline) {
    std::vector<int> asked;
    for (const Segment& segment : timeline.segments) {
        if (segment.kind == SegmentKind::question) asked.push_back(segment.question);
    }
    return asked;
}

Timeline running_timeline(int fps, std::int64_t frames, std::string caption) {
    TimelineScript script;
    script.fps = fps;
    script.frames = frames;
    script.caption = std::move(caption);
    return build_timeline(script);
}

}  // namespace collide::show

namespace collide::show {

Timeline still_timeline(const Timeline& video, std::int64_t frames, const std::string& caption) {
    // Where each run of the video starts showing its caption, in simulation frames: the state
    // first shown in a run is read with that run's caption.
    std::vector<std::pair<std::int64_t, const std::string*>> from;
    for (const Segment& segment : video.segments) {
        if (segment.kind != SegmentKind::run) continue;
        if (from.empty() && segment.sim_frame > 0) from.emplace_back(0, &caption);
        from.emplace_back(segment.sim_frame, &segment.caption);
    }
    Timeline timeline;
    timeline.fps = video.fps;
    const std::int64_t count = std::max<std::int64_t>(1, frames);
    for (std::size_t i = 0; i < std::max<std::size_t>(1, from.size()); ++i) {
        const std::int64_t first = from.empty() ? 0 : std::min(from[i].first, count);
        const std::int64_t end = i + 1 < from.size() ? std::min(from[i + 1].first, count) : count;
        if (end <= first) continue;
        const std::string& words = from.empty() ? caption : *from[i].second;
        if (!timeline.segments.empty() && timeline.segments.back().caption == words) {
            timeline.segments.back().end_frame = end;
            continue;
        }
        Segment segment;
        segment.first_frame = first;
        segment.end_frame = end;
        segment.sim_frame = first;
        segment.caption = words;
        timeline.segments.push_back(std::move(segment));
    }
    const auto fps = static_cast<double>(timeline.fps);
    for (Segment& segment : timeline.segments) {
        segment.start = static_cast<double>(segment.first_frame) / fps;
        segment.end = static_cast<double>(segment.end_frame) / fps;
    }
    return timeline;
}

}  // namespace collide::show
