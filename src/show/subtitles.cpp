// A video's subtitle cues: the words on screen segment by segment, as plain timed text.
#include "collide/show/subtitles.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace collide::show {

Cues cues_from_steps(const std::vector<TimedText>& steps, double video_seconds) {
    Cues cues;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const double start = std::max(0.0, steps[i].start);
        const double end =
            i + 1 < steps.size() ? std::min(steps[i + 1].start, video_seconds) : video_seconds;
        if (steps[i].text.empty() || !(end > start)) continue;
        if (!cues.empty() && cues.back().text == steps[i].text && cues.back().end >= start) {
            cues.back().end = end;  // the same words on screen: one cue
            continue;
        }
        cues.push_back({start, end, steps[i].text});
    }
    return cues;
}

namespace {

/// The words on screen during `segment`: a card shows the title and the description.
std::string segment_words(const Segment& segment, const LessonPlan& lesson) {
    if (segment.kind != SegmentKind::card) return segment.caption;
    std::string words = lesson.title;
    if (!lesson.description.empty())
        words += words.empty() ? lesson.description : "\n" + lesson.description;
    return words;
}

/// Without a card the title is named first, briefly: the steps before `title_end` give way to
/// it, and the words on screen at `title_end` follow.
std::vector<TimedText> title_first(std::vector<TimedText> steps, const std::string& title,
                                   double title_end) {
    std::vector<TimedText> out{{0.0, title}};
    std::string at_end;
    for (TimedText& step : steps) {
        if (step.start <= title_end) {
            at_end = std::move(step.text);
        } else {
            if (out.size() == 1) out.push_back({title_end, std::move(at_end)});
            out.push_back(std::move(step));
        }
    }
    if (out.size() == 1) out.push_back({title_end, std::move(at_end)});
    return out;
}

}  // namespace

Cues subtitle_cues(const Timeline& timeline, const LessonPlan& lesson) {
    const double video_seconds =
        static_cast<double>(timeline.frame_count()) / std::max(1, timeline.fps);
    if (!(video_seconds > 0.0)) return {};
    std::vector<TimedText> steps;
    bool card = false;
    for (const Segment& segment : timeline.segments) {
        card = card || segment.kind == SegmentKind::card;
        steps.push_back({segment.start, segment_words(segment, lesson)});
    }
    if (!card && !lesson.title.empty())
        steps = title_first(std::move(steps), lesson.title,
                            std::min(intro_seconds, 0.25 * video_seconds));
    return cues_from_steps(steps, video_seconds);
}

namespace {

/// The words on screen sampled at each frame time k / fps of a `duration`-second video.
Cues sampled_cues(double duration, int fps, const std::function<std::string(double)>& words) {
    const auto frames = std::max<long long>(1, std::llround(duration * fps));
    std::vector<TimedText> steps;
    for (long long k = 0; k < frames; ++k) {
        const double t = static_cast<double>(k) / fps;
        std::string text = words(t);
        if (steps.empty() || steps.back().text != text) steps.push_back({t, std::move(text)});
    }
    return cues_from_steps(steps, static_cast<double>(frames) / fps);
}

/// One line per panel; with several panels each says whose it is.
std::string panel_lines(const std::vector<std::pair<std::string, std::string>>& panels) {
    std::string out;
    for (const auto& [title, caption] : panels) {
        if (caption.empty()) continue;
        if (!out.empty()) out += '\n';
        const bool named = panels.size() > 1 && !title.empty() && caption.rfind(title, 0) != 0;
        out += named ? title + ": " + caption : caption;
    }
    return out;
}

}  // namespace

Cues heap_subtitle_cues(const HeapProgram& lesson, int fps) {
    return sampled_cues(lesson.duration(), fps, [&lesson](double t) {
        const HeapMoment moment = lesson.moment_at(t);
        std::vector<std::pair<std::string, std::string>> panels;
        for (std::size_t i = 0; i < moment.panels.size(); ++i) {
            const std::string title = i < lesson.text().size() ? lesson.text()[i].title : "";
            panels.emplace_back(title, *moment.panels[i].caption);
        }
        return panel_lines(panels);
    });
}

Cues puzzle_subtitle_cues(const PuzzleProgram& lesson, int fps) {
    return sampled_cues(lesson.duration(), fps, [&lesson](double t) {
        const view::PuzzleFrameView frame = lesson.frame_at(t);
        std::vector<std::pair<std::string, std::string>> panels;
        for (const view::PuzzlePanelView& panel : frame.panels) {
            panels.emplace_back(panel.title, panel.caption);
        }
        return panel_lines(panels);
    });
}

}  // namespace collide::show
