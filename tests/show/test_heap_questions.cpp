// "Where does K end up?" (`collide heap --questions on`, issue #45): for many random lessons the
// revealed slot is where the operation actually leaves the key (read here from the array the
// operation ends with, keys all different), the distractors are other slots of the heap, and the
// lesson holds still on the question with the letters, the countdown and the words on screen.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "collide/show/chapters.hpp"
#include "collide/show/drawn_timeline.hpp"
#include "collide/show/heap_program.hpp"
#include "collide/show/questions.hpp"
#include "collide/show/subtitles.hpp"

using namespace collide;
using collide::show::HeapProgram;
using collide::show::HeapQuestion;

namespace {

const show::HeapPacing questions_pacing{0.8, 0.5, 1.0, 2.5};

/// Random operations on distinct integer keys: inserts, removes ('*') and, for an indexed heap,
/// increase-keys of keys still in the queue.
std::string random_ops(std::uint64_t seed, bool increases) {
    std::mt19937_64 rng(seed);
    std::vector<int> in_queue;
    std::set<int> used;  // every key ever given: all different, so a key names one slot
    std::string ops;
    int next = 10;
    const int n = 6 + static_cast<int>(rng() % 14);
    for (int i = 0; i < n; ++i) {
        const std::uint64_t roll = rng() % 10;
        std::string op;
        if (roll < 3 && !in_queue.empty()) {
            op = "*";
            in_queue.clear();  // which key leaves is the heap's business: no increase after it
        } else if (roll < 5 && increases && !in_queue.empty()) {
            // A key raised (increase-key only raises) to one no other key has.
            const int key = in_queue[rng() % in_queue.size()];
            int raised = key + 1 + static_cast<int>(rng() % 400);
            while (used.count(raised) != 0) ++raised;
            used.insert(raised);
            op = std::to_string(key) + "^" + std::to_string(raised);
            std::replace(in_queue.begin(), in_queue.end(), key, raised);
        } else {
            next += 1 + static_cast<int>(rng() % 7);
            // Keys rise and fall: some swim far, some not at all.
            int key = rng() % 2 == 0 ? next : 1000 - next;
            while (used.count(key) != 0) ++key;
            used.insert(key);
            op = std::to_string(key);
            in_queue.push_back(key);
        }
        ops += (ops.empty() ? "" : " ") + op;
    }
    return ops;
}

HeapProgram asking(const std::string& ops, std::vector<pq::QueueKind> kinds,
                   pq::Orientation orientation) {
    HeapProgram lesson(pq::HeapRecord::operations(pq::parse_heap_ops(ops), kinds, orientation),
                       questions_pacing, 1);
    lesson.ask_questions(true);
    return lesson;
}

/// The slot the operation leaves `key` in, from the array it ends with (keys are distinct).
std::size_t slot_of(const pq::PanelOp& done, const std::string& key) {
    const auto& keys = done.end.keys;
    const auto it = std::find(keys.begin(), keys.end(), key);
    REQUIRE(it != keys.end());
    return static_cast<std::size_t>(it - keys.begin());
}

void check_answers(const HeapProgram& lesson) {
    const pq::HeapRecord& record = lesson.record();
    for (const HeapQuestion& q : lesson.questions()) {
        const pq::HeapOp& op = record.ops()[q.op];
        const pq::PanelOp& done = record.panels()[q.panel].ops[q.op];
        CAPTURE(q.op);
        CAPTURE(q.question);
        REQUIRE(q.candidates.size() >= show::min_candidates);
        REQUIRE(q.candidates.size() <= show::max_candidates);
        REQUIRE(q.answer < q.candidates.size());
        // The key asked about is the operation's: the inserted or raised key, or for a remove
        // the last key, moved to the root.
        if (op.kind == pq::HeapOp::Kind::insert) CHECK(q.key == op.key.text());
        if (op.kind == pq::HeapOp::Kind::increase) CHECK(q.key == op.new_key.text());
        if (op.kind == pq::HeapOp::Kind::remove) {
            const pq::ArrayState& before = q.op == 0 ? record.panels()[q.panel].start
                                                     : record.panels()[q.panel].ops[q.op - 1].end;
            CHECK(q.key == before.keys.back());
            CHECK(q.from == 0);
        }
        // The revealed slot is where the key really is once the operation is done.
        const std::size_t actual = slot_of(done, q.key);
        CHECK(q.candidates[q.answer] == actual);
        // The distractors: other slots of the heap, each once, none the answer.
        const std::set<std::size_t> distinct(q.candidates.begin(), q.candidates.end());
        CHECK(distinct.size() == q.candidates.size());
        for (std::size_t i = 0; i < q.candidates.size(); ++i) {
            CHECK(q.candidates[i] < done.end.keys.size());
            if (i != q.answer) CHECK(q.candidates[i] != actual);
        }
        CHECK(q.think >= show::min_think_seconds);
        CHECK(q.answer_words.find("Answer: " + show::candidate_letter(q.answer)) == 0);
    }
}

}  // namespace

TEST_CASE(
    "heap questions: the revealed slot is where the operation leaves the key, over many "
    "random lessons") {
    const std::vector<std::vector<pq::QueueKind>> heaps = {
        {{pq::QueueFamily::binary, 2}},
        {{pq::QueueFamily::dary, 3}},
        {{pq::QueueFamily::dary, 4}},
        {{pq::QueueFamily::unordered, 1}, {pq::QueueFamily::binary, 2}},
    };
    std::size_t asked = 0;
    std::set<std::size_t> answer_letters;
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        for (const auto& kinds : heaps) {
            for (const auto orientation : {pq::Orientation::max, pq::Orientation::min}) {
                const std::string ops = random_ops(seed, false);
                CAPTURE(ops);
                const HeapProgram lesson = asking(ops, kinds, orientation);
                check_answers(lesson);
                asked += lesson.questions().size();
                for (const HeapQuestion& q : lesson.questions()) answer_letters.insert(q.answer);
            }
        }
    }
    CHECK(asked > 500);
    // The answer's letter varies: A is not always right.
    CHECK(answer_letters.size() >= 3);
}

TEST_CASE(
    "heap questions: the indexed heap's increase-key asks too, and its answer is the "
    "record's") {
    std::size_t increases = 0;
    for (std::uint64_t seed = 1; seed <= 80; ++seed) {
        for (const auto orientation : {pq::Orientation::max, pq::Orientation::min}) {
            const std::string ops = random_ops(seed, true);
            CAPTURE(ops);
            const HeapProgram lesson = asking(ops, {{pq::QueueFamily::indexed, 2}}, orientation);
            check_answers(lesson);
            for (const HeapQuestion& q : lesson.questions())
                increases += lesson.record().ops()[q.op].kind == pq::HeapOp::Kind::increase;
        }
    }
    CHECK(increases > 20);
}

TEST_CASE(
    "heap questions: the lecture's trace asks before each swim and sink with room for two "
    "answers") {
    const HeapProgram lesson =
        asking("P Q E * X A M * P L E *", {{pq::QueueFamily::binary, 2}}, pq::Orientation::max);
    // Every operation but the first insert (one slot: nothing to choose) and the removes that
    // leave fewer than two keys.
    REQUIRE(lesson.questions().size() == 11);
    const HeapQuestion& q = lesson.questions()[0];  // insert Q under P: Q swims to the root
    CHECK(q.op == 1);
    CHECK(q.key == "Q");
    CHECK(q.candidates.size() == 2);
    CHECK(q.candidates[q.answer] == 0);
    CHECK(q.question == "Where does Q end up: A or B?");
    CHECK(q.answer_words == "Answer: " + show::candidate_letter(q.answer) + ", Q ends up at a[1]");
    // Asking lengthens the video by the questions' seconds, no more.
    HeapProgram quiet(lesson.record(), questions_pacing, 1);
    double extra = 0.0;
    for (const HeapQuestion& each : lesson.questions()) extra += each.seconds();
    CHECK(lesson.duration() == doctest::Approx(quiet.duration() + extra));
    quiet.ask_questions(false);
    CHECK(quiet.questions().empty());
}

TEST_CASE("heap questions: the frames hold still on the question, then show the answer") {
    const HeapProgram lesson =
        asking("P Q E * X A M *", {{pq::QueueFamily::binary, 2}}, pq::Orientation::max);
    REQUIRE(!lesson.questions().empty());
    for (std::size_t n = 0; n < lesson.questions().size(); ++n) {
        const HeapQuestion& q = lesson.questions()[n];
        const double start = lesson.question_start(n);
        CAPTURE(q.question);
        const show::HeapMoment early = lesson.moment_at(start + 0.1);
        const show::HeapMoment late = lesson.moment_at(start + q.think - 0.1);
        REQUIRE(early.question == static_cast<int>(n));
        CHECK_FALSE(early.reveal);
        // Frozen: the same state and step throughout the think time.
        CHECK(early.panels[0].state == late.panels[0].state);
        CHECK(early.panels[0].step == late.panels[0].step);
        CHECK(*early.panels[0].caption == q.question);
        const view::HeapFrameView asked = lesson.frame_at(start + 0.1);
        const view::HeapPanelView& panel = asked.panels[q.panel];
        REQUIRE(panel.letters.size() == q.candidates.size());
        CHECK(panel.letters[0].letter == "A");
        CHECK(panel.countdown == show::countdown_words(q.think - 0.1));
        CHECK_FALSE(panel.reveal);
        // The key asked about is on the slot it starts from while the class thinks.
        const auto& keys = early.panels[0].state->keys;
        REQUIRE(q.from < keys.size());
        const view::HeapFrameView shown = lesson.frame_at(start + q.think + 0.1);
        CHECK(shown.panels[q.panel].reveal);
        CHECK(shown.panels[q.panel].countdown.empty());
        CHECK(shown.panels[q.panel].letters[q.answer].answer);
        CHECK(shown.panels[q.panel].caption == q.answer_words);
        // After the reveal the operation goes on: no question.
        CHECK(lesson.moment_at(start + q.seconds() + 0.05).question == -1);
        CHECK(lesson.moment_at(start - 0.05).question == -1);
    }
}

TEST_CASE(
    "heap questions: subtitles carry the question and the answer, and a chapter ends on each "
    "question, none shorter than 4 s") {
    const HeapProgram lesson =
        asking("P Q E * X A M * P L E *", {{pq::QueueFamily::binary, 2}}, pq::Orientation::max);
    const int fps = 30;
    const Cues cues = show::heap_subtitle_cues(lesson, fps);
    const Chapters chapters = show::heap_chapters(lesson, lesson.duration(), fps);
    for (std::size_t n = 0; n < lesson.questions().size(); ++n) {
        const HeapQuestion& q = lesson.questions()[n];
        CAPTURE(q.question);
        CHECK(std::any_of(cues.begin(), cues.end(),
                          [&](const Cue& c) { return c.text == q.question; }));
        CHECK(std::any_of(cues.begin(), cues.end(),
                          [&](const Cue& c) { return c.text == q.answer_words; }));
        const double reveal = lesson.question_start(n) + q.think;
        CHECK(std::any_of(chapters.begin(), chapters.end(), [&](const Chapter& c) {
            return std::abs(c.end - reveal) < 1e-9 && c.title.find(q.question) != std::string::npos;
        }));
    }
    for (const Chapter& c : chapters) {
        CAPTURE(c.title);
        CHECK(c.end - c.start >= show::min_heap_chapter_seconds - 1e-9);
    }
}

TEST_CASE(
    "heap questions: the timeline holds a question and its reveal where the lesson asks, "
    "back to back with the runs") {
    const HeapProgram lesson =
        asking("P Q E * X A M *", {{pq::QueueFamily::binary, 2}}, pq::Orientation::max);
    const int fps = 30;
    const show::Timeline timeline =
        show::drawn_lesson_timeline(lesson.duration(), fps, show::asked_stretches(lesson));
    std::int64_t frame = 0;
    std::size_t questions = 0;
    for (std::size_t i = 0; i < timeline.segments.size(); ++i) {
        const show::Segment& s = timeline.segments[i];
        CHECK(s.first_frame == frame);
        CHECK(s.end_frame > s.first_frame);
        frame = s.end_frame;
        if (s.kind != show::SegmentKind::question) continue;
        const HeapQuestion& q = lesson.questions().at(static_cast<std::size_t>(s.question));
        CHECK(s.caption == q.question);
        CHECK(std::abs(s.start - lesson.question_start(questions)) < 1.0 / fps);
        CHECK(s.end - s.start >= show::min_think_seconds);
        REQUIRE(i + 1 < timeline.segments.size());
        CHECK(timeline.segments[i + 1].kind == show::SegmentKind::reveal);
        CHECK(timeline.segments[i + 1].caption == q.answer_words);
        // The lesson's own frames agree: frozen on the question, then on the answer.
        CHECK(lesson.moment_at(s.start + 0.5 / fps).question == s.question);
        CHECK(lesson.moment_at(timeline.segments[i + 1].start + 0.5 / fps).reveal);
        ++questions;
    }
    CHECK(questions == lesson.questions().size());
    CHECK(frame == std::llround(lesson.duration() * fps));
    // Without questions: one run.
    const show::Timeline quiet = show::drawn_lesson_timeline(lesson.duration(), fps, {});
    REQUIRE(quiet.segments.size() == 1);
    CHECK(quiet.segments[0].kind == show::SegmentKind::run);
}
