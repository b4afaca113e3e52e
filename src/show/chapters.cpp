// A video's chapters: the timeline's stretches (card, each caption, replay, question, answer,
// epilogue) or the step captions of a heap or puzzle video, with the titles players list.
#include "collide/show/chapters.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "collide/show/replay.hpp"

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

/// The last frame at or before `seconds` of video, kept within [start, still].
double frame_before(double seconds, double fps, double start, double still) {
    return std::clamp(std::floor(seconds * fps + 1e-9) / fps, start, still);
}

/// Whether `segment` shows a replay: a replay, or a question's reveal that replays its step.
bool shows_replay(const Segment& segment, const std::vector<bool>& replaying_reveals) {
    if (segment.kind == SegmentKind::replay) return true;
    return segment.kind == SegmentKind::reveal && segment.question >= 0 &&
           static_cast<std::size_t>(segment.question) < replaying_reveals.size() &&
           replaying_reveals[static_cast<std::size_t>(segment.question)];
}

/// Chapters of `parts`: a caption back for a moment (shorter than min_run_chapter_seconds, a
/// caption an earlier chapter of the run showed, between a replay or an answer and what comes
/// next) is no stop of its own: it joins the chapter after it, which starts there (its title,
/// its still). A caption's first showing stays a chapter however short; the last chapter has
/// none after it and stays.
void join_captions_back(Chapters& chapters, std::vector<Part>& parts) {
    std::set<std::string> shown;
    for (std::size_t i = 0; i + 1 < chapters.size();) {
        const bool body = parts[i] == Part::body;
        const bool back = body && shown.count(chapters[i].title) > 0;
        if (back && chapters[i].end - chapters[i].start < min_run_chapter_seconds) {
            chapters[i + 1].start = chapters[i].start;
            chapters.erase(chapters.begin() + static_cast<std::ptrdiff_t>(i));
            parts.erase(parts.begin() + static_cast<std::ptrdiff_t>(i));
            continue;
        }
        if (body) shown.insert(chapters[i].title);
        ++i;
    }
}

}  // namespace

Chapters timeline_chapters(const Timeline& timeline, double card_fade,
                           const std::vector<bool>& replaying_reveals) {
    Chapters chapters;
    std::vector<Part> parts;
    const auto fps = static_cast<double>(std::max(1, timeline.fps));
    Part last_part = Part::card;
    const std::string* last_caption = nullptr;
    for (const Segment& segment : timeline.segments) {
        const Part part = part_of(segment.kind);
        const bool same = last_caption != nullptr && part == last_part &&
                          (part == Part::replay || *last_caption == segment.caption);
        if (!same) {
            chapters.push_back({segment.start, segment.end, chapter_title(part, segment.caption)});
            parts.push_back(part);
        }
        Chapter& chapter = chapters.back();
        chapter.end = segment.end;
        chapter.still = static_cast<double>(segment.end_frame - 1) / fps;
        if (part == Part::card && card_fade > 0.0) {
            // The last frame at or before the fade begins: the title at full strength.
            chapter.still =
                frame_before(segment.end - card_fade, fps, chapter.start, chapter.still);
        } else if (shows_replay(segment, replaying_reveals)) {
            // The replay's whole picture stands until replay_hold_end, then fades out.
            chapter.still = frame_before(segment.start + replay_hold_end - 1.0 / fps, fps,
                                         segment.start, chapter.still);
        }
        last_part = part;
        last_caption = &segment.caption;
    }
    join_captions_back(chapters, parts);
    return chapters;
}

namespace {

/// What a chapter of one heap operation is called: its summary's head ("insert S", "remove the
/// max X"), heapsort's two phases by what they do.
std::string heap_op_title(const HeapProgram& lesson, std::size_t k) {
    const pq::HeapOp& op = lesson.record().ops()[k];
    if (op.kind == pq::HeapOp::Kind::build) return "build the heap";
    if (op.kind == pq::HeapOp::Kind::sortdown) return "sortdown";
    if (lesson.text().empty()) return lesson.op_labels()[k];
    const std::string& summary = lesson.text().front().ops[k].summary;
    return summary.substr(0, summary.find(':'));
}

/// The title of operations first..last (inclusive) in one chapter.
std::string heap_group_title(const HeapProgram& lesson, std::size_t first, std::size_t last) {
    if (last - first >= 3) {
        return heap_op_title(lesson, first) + " ... " + heap_op_title(lesson, last) + " (" +
               std::to_string(last - first + 1) + " operations)";
    }
    std::string title;
    for (std::size_t k = first; k <= last; ++k)
        title += (title.empty() ? "" : ", ") + heap_op_title(lesson, k);
    return title;
}

}  // namespace

Chapters heap_chapters(const HeapProgram& lesson, double video_seconds, int fps) {
    const std::vector<double>& starts = lesson.op_starts();
    const std::size_t ops = lesson.record().ops().size();
    if (!(video_seconds > 0.0)) return {};
    if (ops == 0) return {{0.0, video_seconds, one_line(lesson.name()), 0.0}};
    // Groups of operations [first, last], each from its first operation's start (the first
    // from 0: the intro) to the next group's; a group closes once it lasts long enough. A
    // question (--questions on) closes its group where its reveal starts, so that the slide
    // player stops on the question; the reveal starts the next group, titled by the answer.
    struct Group {
        std::size_t first = 0;
        std::size_t last = 0;
        double start = 0.0;
        const HeapQuestion* asks = nullptr;     ///< the question it ends on
        const HeapQuestion* answers = nullptr;  ///< the question whose reveal starts it
    };
    const auto question_of = [&lesson](std::size_t k) -> std::optional<std::size_t> {
        const std::vector<HeapQuestion>& qs = lesson.questions();
        for (std::size_t q = 0; q < qs.size(); ++q)
            if (qs[q].op == k) return q;
        return std::nullopt;
    };
    std::vector<Group> groups{{0, 0, 0.0}};
    for (std::size_t k = 0; k < ops; ++k) {
        if (k > 0) {
            if (groups.back().asks == nullptr &&
                starts[k] - groups.back().start < min_heap_chapter_seconds) {
                groups.back().last = k;
            } else {
                groups.push_back({k, k, starts[k]});
            }
        }
        if (const std::optional<std::size_t> q = question_of(k)) {
            const HeapQuestion& question = lesson.questions()[*q];
            groups.back().asks = &question;
            groups.push_back({k, k, lesson.question_start(*q) + question.think});
            groups.back().answers = &question;
        }
    }
    // The last group runs to the end (the outro): too short, it joins the one before (unless
    // that one ends on a question: the reveal and the outro last longer than a chapter needs).
    if (groups.size() > 1 && groups[groups.size() - 2].asks == nullptr &&
        video_seconds - groups.back().start < min_heap_chapter_seconds) {
        const std::size_t last = groups.back().last;
        groups.pop_back();
        groups.back().last = last;
    }
    Chapters chapters;
    const double frame = 1.0 / static_cast<double>(std::max(1, fps));
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const double end = g + 1 < groups.size() ? groups[g + 1].start : video_seconds;
        std::string title;
        if (groups[g].answers != nullptr) {
            title = groups[g].answers->answer_words;
            if (groups[g].last > groups[g].first)
                title += "; " + heap_group_title(lesson, groups[g].first + 1, groups[g].last);
        } else {
            title = heap_group_title(lesson, groups[g].first, groups[g].last);
        }
        // A group that ends on a question (after a reveal too short for a chapter of its own,
        // the next operation's) is named by it too: the player stops on those words.
        if (groups[g].asks != nullptr) title += ": " + groups[g].asks->question;
        Chapter c{groups[g].start, end, one_line(title), 0.0};
        c.still = std::max(c.start, std::ceil(c.end / frame - 1e-9) * frame - frame);
        chapters.push_back(std::move(c));
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
