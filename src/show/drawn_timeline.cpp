#include "collide/show/drawn_timeline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace collide::show {

Timeline drawn_lesson_timeline(double duration, int fps, const std::vector<AskedStretch>& asked) {
    Timeline timeline;
    timeline.fps = std::max(1, fps);
    const double rate = static_cast<double>(timeline.fps);
    const std::int64_t frames = std::max<std::int64_t>(1, std::llround(duration * rate));
    // The first frame showing time t or later (frame k shows k / fps).
    const auto frame_of = [&](double t) {
        return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::ceil(t * rate - 1e-9)), 0,
                                        frames);
    };
    const auto add = [&](SegmentKind kind, std::int64_t first, std::int64_t end,
                         const std::string& caption, int question) {
        if (end <= first) return;
        Segment s;
        s.kind = kind;
        s.first_frame = first;
        s.end_frame = end;
        s.start = static_cast<double>(first) / rate;
        s.end = static_cast<double>(end) / rate;
        s.moves = kind == SegmentKind::run;
        s.caption = caption;
        s.question = question;
        timeline.segments.push_back(std::move(s));
    };
    std::int64_t at = 0;
    for (std::size_t q = 0; q < asked.size(); ++q) {
        const AskedStretch& a = asked[q];
        const std::int64_t ask = std::max(at, frame_of(a.start));
        const std::int64_t reveal = std::max(ask, frame_of(a.start + a.think));
        const std::int64_t end = std::max(reveal, frame_of(a.start + a.think + a.reveal));
        add(SegmentKind::run, at, ask, "", -1);
        add(SegmentKind::question, ask, reveal, a.question, static_cast<int>(q));
        add(SegmentKind::reveal, reveal, end, a.answer, static_cast<int>(q));
        at = end;
    }
    add(SegmentKind::run, at, frames, "", -1);
    return timeline;
}

std::vector<AskedStretch> asked_stretches(const HeapProgram& lesson) {
    std::vector<AskedStretch> out;
    for (std::size_t q = 0; q < lesson.questions().size(); ++q) {
        const HeapQuestion& asked = lesson.questions()[q];
        out.push_back({lesson.question_start(q), asked.think, asked.reveal, asked.question,
                       asked.answer_words});
    }
    return out;
}

std::vector<AskedStretch> asked_stretches(const PuzzleProgram& lesson) {
    std::vector<AskedStretch> out;
    for (std::size_t q = 0; q < lesson.questions().size(); ++q) {
        const PuzzleQuestion& asked = lesson.questions()[q];
        out.push_back({lesson.question_start(q), asked.think, asked.reveal, asked.question,
                       asked.answer_words});
    }
    return out;
}

}  // namespace collide::show
