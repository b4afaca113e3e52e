// A video's chapters: the timeline's stretches (card, each caption, replay, question, answer,
// epilogue) or the step captions of a heap or puzzle video, with the titles players list.
#include "collide/show/chapters.hpp"

#include <algorithm>
#include <cmath>

namespace collide::show {

std::string one_line(const std::string& text, std::string_view separator) {
    std::string out;
    std::string line;
    const auto flush = [&] {
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos) return;
        const std::size_t last = line.find_last_not_of(" \t\r");
        if (!out.empty()) out += separator;
        out += line.substr(first, last - first + 1);
    };
    for (const char c : text) {
        if (c == '\n') {
            flush();
            line.clear();
        } else if (!(c == ' ' && !line.empty() && line.back() == ' ')) {
            line += c;
        }
    }
    flush();
    return out;
}

namespace {

/// Which chapter a segment belongs to: runs and holds showing one caption are one chapter.
enum class Part { card, body, replay, epilogue, question, reveal };

Part part_of(SegmentKind kind) {
    switch (kind) {
        case SegmentKind::card:
            return Part::card;
        case SegmentKind::run:
        case SegmentKind::hold:
            return Part::body;
        case SegmentKind::replay:
            return Part::replay;
        case SegmentKind::epilogue:
            return Part::epilogue;
        case SegmentKind::question:
            return Part::question;
        case SegmentKind::reveal:
            return Part::reveal;
    }
    return Part::body;
}

/// The title players list for a chapter of `part` whose segments show `caption`.
std::string chapter_title(Part part, const std::string& caption) {
    const std::string words = one_line(caption);
    switch (part) {
        case Part::card:
            return words.empty() ? "Title" : words;
        case Part::body:
            return words.empty() ? "The simulation runs" : words;
        case Part::replay:
            return words.empty() ? "Replay" : "Replay: " + words;
        case Part::epilogue:
            return words.empty() ? "The final figures" : words;
        case Part::question:
            return words.empty() ? "Question" : words;
        case Part::reveal:
            return words.empty() ? "Answer" : words;
    }
    return words;
}

}  // namespace

Chapters timeline_chapters(const Timeline& timeline, double card_fade) {
    Chapters chapters;
    const auto fps = static_cast<double>(std::max(1, timeline.fps));
    Part last_part = Part::card;
    const std::string* last_caption = nullptr;
    for (const Segment& segment : timeline.segments) {
        const Part part = part_of(segment.kind);
        const bool same = last_caption != nullptr && part == last_part &&
                          (part == Part::replay || *last_caption == segment.caption);
        if (!same)
            chapters.push_back({segment.start, segment.end, chapter_title(part, segment.caption)});
        chapters.back().end = segment.end;
        chapters.back().still = static_cast<double>(segment.end_frame - 1) / fps;
        if (part == Part::card && card_fade > 0.0) {
            // The last frame at or before the fade begins: the title at full strength.
            const double faded = std::floor((segment.end - card_fade) * fps + 1e-9) / fps;
            chapters.back().still = std::clamp(faded, chapters.back().start, chapters.back().still);
        }
        last_part = part;
        last_caption = &segment.caption;
    }
    return chapters;
}

Chapters chapters_from_cues(const Cues& cues, double video_seconds, int fps) {
    Chapters chapters;
    const double frame = 1.0 / static_cast<double>(std::max(1, fps));
    const auto last_frame = [frame](const Chapter& c) {
        return std::max(c.start, std::ceil(c.end / frame - 1e-9) * frame - frame);
    };
    for (const Cue& cue : cues) {
        if (!(cue.start < video_seconds)) break;
        std::string title = one_line(cue.text, " / ");
        if (title.empty()) continue;
        if (!chapters.empty() && chapters.back().title == title) continue;
        const double start = chapters.empty() ? 0.0 : cue.start;
        if (!chapters.empty()) chapters.back().end = start;
        chapters.push_back({start, video_seconds, std::move(title), 0.0});
    }
    for (Chapter& chapter : chapters) chapter.still = last_frame(chapter);
    return chapters;
}

}  // namespace collide::show
