// The collision video's lesson timeline: the intro card and the captions over the video.
#include <algorithm>

#include "collide/show/collision.hpp"

namespace collide::show {

const std::string& LessonPlan::caption_at(double video_seconds) const noexcept {
    const std::string* current = &caption;
    for (const CaptionCue& cue : captions) {
        if (cue.at > video_seconds) break;
        current = &cue.text;
    }
    return *current;
}

double LessonPlan::intro_fade_seconds() const noexcept {
    return intro_seconds > 0.0 ? std::min(0.5, 0.5 * intro_seconds) : 0.0;
}

float LessonPlan::intro_opacity(double video_seconds) const noexcept {
    if (!(intro_seconds > 0.0) || video_seconds >= intro_seconds) return 0.0F;
    const double fade = intro_fade_seconds();
    return static_cast<float>(std::clamp((intro_seconds - video_seconds) / fade, 0.0, 1.0));
}

Timeline lesson_timeline(const LessonPlan& lesson, int fps, std::int64_t frames) {
    TimelineScript script;
    script.fps = fps;
    script.frames = frames;
    script.card_seconds = lesson.intro_seconds;
    script.card_waits = true;
    script.card_title = lesson.title;
    script.caption = lesson.caption;
    for (const CaptionCue& cue : lesson.captions)
        script.cues.push_back({cue.at, cue.text, cue.hold});
    script.replays = lesson.replays;
    script.questions = lesson.questions;
    script.epilogue_seconds = lesson.epilogue_seconds;
    script.epilogue_caption = lesson.epilogue_caption;
    return build_timeline(script);
}

std::vector<CaptionSource> captions_shown(const LessonPlan& lesson,
                                          const std::string& scene_caption_at) {
    std::vector<CaptionSource> out;
    if (!lesson.caption.empty()) {
        // caption_at is "file:line: render.caption" (empty for a caption not read from a file).
        out.push_back({lesson.caption, "", 0,
                       scene_caption_at.empty() ? "render.caption" : scene_caption_at});
    }
    for (const CaptionCue& cue : lesson.captions) {
        out.push_back({cue.text, cue.file, cue.line, "render.captions.text"});
    }
    for (const QuestionCue& cue : lesson.question_cues) {
        if (!cue.text.empty())
            out.push_back({cue.text, cue.file, cue.line, "render.questions.text"});
    }
    return out;
}

}  // namespace collide::show
