// A video's subtitle cues: the title card, then the captions, as plain timed text.
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

Cues subtitle_cues(const LessonPlan& lesson, double video_seconds) {
    if (!(video_seconds > 0.0)) return {};
    const double title_end = lesson.intro_seconds > 0.0
                                 ? std::min(lesson.intro_seconds, video_seconds)
                             : lesson.title.empty() ? 0.0
                                                    : std::min(intro_seconds, 0.25 * video_seconds);
    std::vector<TimedText> steps;
    std::string title = lesson.title;
    if (lesson.intro_seconds > 0.0 && !lesson.description.empty()) {
        title += title.empty() ? lesson.description : "\n" + lesson.description;
    }
    steps.push_back({0.0, title});
    // The caption on screen when the title's cue ends, then each scripted change after it.
    steps.push_back({title_end, lesson.caption_at(title_end)});
    for (const CaptionCue& cue : lesson.captions) {
        if (cue.at > title_end) steps.push_back({cue.at, cue.text});
    }
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

Cues heap_subtitle_cues(const HeapLesson& lesson, int fps) {
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

Cues puzzle_subtitle_cues(const PuzzleLesson& lesson, int fps) {
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
