// "Which board does A* expand next?" (`collide puzzle --questions on`, issue #45): for many
// random boards and queues the revealed board is the one the recorded search expands next, the
// other is not (and the picture decides: its priority is higher), and the video holds still on
// the question with its letters, countdown and words, then goes on where it stopped.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "collide/show/puzzle_program.hpp"
#include "collide/show/questions.hpp"
#include "collide/show/subtitles.hpp"

using namespace collide;
using puzzle::Board;
using show::PuzzleProgram;
using show::PuzzleQuestion;

namespace {

/// What the search itself did next after `step` expansions: the board it expanded, read from the
/// expansion order (not from the question).
std::uint64_t expanded_board(const puzzle::SearchResult& r, std::size_t step) {
    return r.nodes[r.expansions.at(step)].board;
}

}  // namespace

TEST_CASE(
    "puzzle questions: the revealed board is A*'s next expansion, over many boards and "
    "queues") {
    const std::vector<pq::QueueKind> queues = {
        {pq::QueueFamily::binary, 2}, {pq::QueueFamily::dary, 4}, {pq::QueueFamily::unordered, 1}};
    std::size_t asked = 0;
    std::size_t answer_b = 0;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        const Board start = puzzle::random_board(3, 8 + static_cast<int>(seed % 16), seed);
        if (start == Board::goal(3)) continue;
        for (const pq::QueueKind& queue : queues) {
            for (const auto heuristic :
                 {puzzle::Heuristic::manhattan, puzzle::Heuristic::hamming}) {
                const std::vector<puzzle::SearchResult> results = {
                    puzzle::breadth_first(start), puzzle::a_star(start, heuristic, queue)};
                PuzzleProgram lesson(start, results);
                lesson.ask_questions(true);
                CAPTURE(seed);
                // BFS (panel 0) is never asked about; A* (panel 1) at most once.
                REQUIRE(lesson.questions().size() <= 1);
                for (const PuzzleQuestion& q : lesson.questions()) {
                    const puzzle::SearchResult& r = results[q.panel];
                    REQUIRE(r.method == puzzle::Method::astar);
                    REQUIRE(q.candidates.size() == 2);
                    REQUIRE(q.answer < 2);
                    REQUIRE(q.step < r.expansions.size());
                    const std::uint32_t shown = q.candidates[q.answer];
                    const std::uint32_t other = q.candidates[1 - q.answer];
                    CHECK(r.nodes[shown].board == expanded_board(r, q.step));
                    CHECK(r.nodes[other].board != expanded_board(r, q.step));
                    // The class decides by the labels: the other board's priority is higher.
                    CHECK(r.nodes[other].priority > r.nodes[shown].priority);
                    // Both boards were waiting in the queue when it asks.
                    for (const std::uint32_t id : q.candidates) {
                        CHECK(r.enqueued_at(id) <= q.step);
                        CHECK((r.nodes[id].popped == puzzle::no_node ||
                               r.nodes[id].popped >= q.step));
                    }
                    CHECK(q.think >= show::min_think_seconds);
                    ++asked;
                    answer_b += q.answer;
                }
            }
        }
    }
    CHECK(asked > 150);
    // The answer is not always the same letter.
    CHECK(answer_b > 0);
    CHECK(answer_b < asked);
}

TEST_CASE("puzzle questions: the video holds on the question, then reveals it, then goes on") {
    const Board start = Board::parse("8 1 3 4 0 2 7 6 5");
    const std::vector<puzzle::SearchResult> results = {
        puzzle::breadth_first(start),
        puzzle::a_star(start, puzzle::Heuristic::manhattan, {pq::QueueFamily::binary, 2})};
    PuzzleProgram quiet(start, results);
    PuzzleProgram lesson(start, results);
    lesson.ask_questions(true);
    REQUIRE(lesson.questions().size() == 1);
    const PuzzleQuestion& q = lesson.questions().front();
    CHECK(lesson.duration() == doctest::Approx(quiet.duration() + q.seconds()));
    const double start_s = lesson.question_start(0);
    const view::PuzzleFrameView asked = lesson.frame_at(start_s + 0.1);
    const view::PuzzleFrameView late = lesson.frame_at(start_s + q.think - 0.1);
    const view::PuzzlePanelView& p = asked.panels[q.panel];
    REQUIRE(p.queue.size() == 2);
    CHECK(p.queue[0].label.rfind("A: ", 0) == 0);
    CHECK(p.queue[1].label.rfind("B: ", 0) == 0);
    CHECK(p.caption == q.question);
    CHECK(p.queue_more == show::countdown_words(q.think - 0.1));
    // Frozen: the tree is the same throughout the think time, and shows q.step expansions.
    CHECK(p.counters == late.panels[q.panel].counters);
    CHECK(p.counters.front() == "expanded " + std::to_string(q.step));
    const view::PuzzleFrameView shown = lesson.frame_at(start_s + q.think + 0.1);
    CHECK(shown.panels[q.panel].caption == q.answer_words);
    CHECK(shown.panels[q.panel].queue[q.answer].mark == view::PuzzleMark::current);
    // Before and after, the frames are the quiet lesson's, shifted by the question.
    const double after = start_s + q.seconds() + 0.5;
    CHECK(lesson.frame_at(after).panels[q.panel].counters ==
          quiet.frame_at(after - q.seconds()).panels[q.panel].counters);
    CHECK(lesson.frame_at(start_s - 0.2).panels[q.panel].counters ==
          quiet.frame_at(start_s - 0.2).panels[q.panel].counters);
    // The subtitles carry both.
    const Cues cues = show::puzzle_subtitle_cues(lesson, 30);
    const auto has = [&](const std::string& words) {
        return std::any_of(cues.begin(), cues.end(),
                           [&](const Cue& c) { return c.text.find(words) != std::string::npos; });
    };
    CHECK(has(q.question));
    CHECK(has(q.answer_words));
    const Cues none = show::puzzle_subtitle_cues(quiet, 30);
    CHECK_FALSE(std::any_of(none.begin(), none.end(), [](const Cue& c) {
        return c.text.find("expand next") != std::string::npos;
    }));
}

TEST_CASE("puzzle questions: with the code beside A*, the question still holds on the search") {
    const Board start = Board::parse("8 1 3 4 0 2 7 6 5");
    const std::vector<puzzle::SearchResult> results = {
        puzzle::a_star(start, puzzle::Heuristic::manhattan, {pq::QueueFamily::binary, 2})};
    PuzzleProgram lesson(start, results, true);
    lesson.ask_questions(true);
    REQUIRE(lesson.questions().size() == 1);
    const PuzzleQuestion& q = lesson.questions().front();
    const view::PuzzleFrameView asked = lesson.frame_at(lesson.question_start(0) + 0.5);
    CHECK(asked.panels[0].caption == q.question);
    CHECK(asked.panels[0].counters.front() == "expanded " + std::to_string(q.step));
    CHECK(results[0].nodes[q.candidates[q.answer]].board == expanded_board(results[0], q.step));
}
