// `collide heap --code` (collide/show/heap_code.hpp): the listing beside the tree names the
// operation under way, and its marked line is the one the animated step carries out. Checked
// frame by frame against the record's own steps (their kinds, the slots they touch, the steps
// around them), not against a list of frame numbers.
#include <doctest/doctest.h>

#include <optional>
#include <string>
#include <vector>

#include "../support/input_error.hpp"
#include "collide/show/heap_code.hpp"
#include "collide/show/heap_program.hpp"

using namespace collide;
using collide::show::HeapProgram;
using collide::test::contains;
using collide::test::input_error_message;
using pq::HeapOp;
using pq::HeapStep;

namespace {

const show::HeapPacing code_pacing{1.0, 0.5, 1.0, 2.0};

HeapProgram with_code(pq::HeapRecord record) {
    HeapProgram lesson(std::move(record), code_pacing, 1);
    lesson.show_code(true);
    return lesson;
}

HeapProgram ops_lesson(const char* ops, pq::QueueKind kind, pq::Orientation orientation) {
    const std::vector<pq::QueueKind> kinds{kind};
    return with_code(pq::HeapRecord::operations(pq::parse_heap_ops(ops), kinds, orientation));
}

HeapProgram sort_lesson(const char* keys, pq::Orientation orientation) {
    return with_code(pq::HeapRecord::heapsort(pq::parse_sort_keys(keys), orientation));
}

/// What the first line of an operation's listing must name.
std::string header_of(HeapOp::Kind op, pq::Orientation orientation) {
    switch (op) {
        case HeapOp::Kind::insert:
            return "insert(";
        case HeapOp::Kind::remove:
            return orientation == pq::Orientation::max ? "remove_max(" : "remove_min(";
        case HeapOp::Kind::increase:
            return "increase_key(";
        default:
            return "heapsort(";
    }
}

/// The words the marked line must hold for step `s` of `done`, derived from the step itself:
/// what it does, and to which slots.
std::vector<std::string> expected_words(const HeapProgram& lesson, std::size_t op,
                                        const pq::PanelOp& done, std::size_t s) {
    const pq::HeapRecord& record = lesson.record();
    const HeapStep& step = done.steps[s];
    const HeapOp::Kind kind = record.ops()[op].kind;
    const bool max = record.orientation() == pq::Orientation::max;
    const unsigned d = record.panels().front().arity;
    const auto parent = [d](std::size_t i) { return (i - 1) / d; };
    switch (step.kind) {
        case HeapStep::Kind::appear:
            return {"a[last] = key"};
        case HeapStep::Kind::change:
            return {"a[k] = key"};
        case HeapStep::Kind::remove:
            return {"take out a[last]"};
        case HeapStep::Kind::sink:
            return {"sink(k)"};
        case HeapStep::Kind::compare:
            if (step.i == step.j) return {"key < old"};
            if (step.i > 0 && step.j > 0 && parent(step.i) == parent(step.j))
                return {max ? "larger child" : "smaller child"};
            // A key against its parent (swim) or against its child (sink).
            if (step.i > 0 && parent(step.i) == step.j)
                return {max ? "a[p] >= a[k]" : "a[p] <= a[k]", "stop"};
            REQUIRE(parent(step.j) == step.i);
            return {max ? "a[k] >= a[j]" : "a[k] <= a[j]", "stop"};
        case HeapStep::Kind::exchange: {
            const bool root_with_last = step.i == 0 && step.j + 1 == step.state.heap_size;
            const bool sortdown_round = kind == HeapOp::Kind::sortdown &&
                                        s + 1 < done.steps.size() &&
                                        done.steps[s + 1].kind == HeapStep::Kind::sink;
            const bool removal_next = kind == HeapOp::Kind::remove && s + 1 < done.steps.size() &&
                                      done.steps[s + 1].kind == HeapStep::Kind::remove;
            if (sortdown_round || removal_next) {
                REQUIRE(root_with_last);
                return {"exchange a[root], a[last]"};
            }
            if (step.i > 0 && parent(step.i) == step.j) return {"exchange a[k], a[p]"};
            REQUIRE(parent(step.j) == step.i);
            return {"exchange a[k], a[j]"};
        }
        case HeapStep::Kind::shift:
            break;
    }
    FAIL("a heap's record holds no shift");
    return {};
}

/// Walks the lesson at 25 frames a second and checks every frame's listing against the record.
/// Returns how many frames had a marked line.
std::size_t check_frames(const HeapProgram& lesson) {
    const pq::HeapRecord& record = lesson.record();
    std::size_t marked = 0;
    for (double t = 0.0; t <= lesson.duration(); t += 0.04) {
        const show::HeapMoment moment = lesson.moment_at(t);
        const view::HeapFrameView frame = lesson.frame_at(t);
        REQUIRE(frame.code.has_value());
        const view::CodeView& code = *frame.code;
        REQUIRE_FALSE(code.lines.empty());
        const std::size_t op = moment.started ? moment.op : 0;
        REQUIRE(op < record.ops().size());
        CAPTURE(t);
        CHECK(contains(code.lines.front().text,
                       header_of(record.ops()[op].kind, record.orientation())));
        const HeapStep* step = moment.panels.front().step;
        if (step == nullptr) {
            CHECK_FALSE(code.current.has_value());  // intro, pauses and outro: no line under way
            continue;
        }
        const pq::PanelOp& done = record.panels().front().ops[op];
        const auto s = static_cast<std::size_t>(step - done.steps.data());
        REQUIRE(code.current.has_value());
        REQUIRE(*code.current < code.lines.size());
        const std::string& line = code.lines[*code.current].text;
        for (const std::string& word : expected_words(lesson, op, done, s)) {
            CAPTURE(line);
            CHECK(contains(line, word));
        }
        ++marked;
    }
    return marked;
}

}  // namespace

TEST_CASE("heap code: inserts swim and removals sink, line by line (the lecture's trace)") {
    const HeapProgram lesson =
        ops_lesson("P Q E * X A M * P L E *", {pq::QueueFamily::binary, 2}, pq::Orientation::max);
    CHECK(check_frames(lesson) > 100);
}

TEST_CASE("heap code: a min-oriented 3-heap turns the words around") {
    const HeapProgram lesson =
        ops_lesson("T P R N H O A E I G S * * *", {pq::QueueFamily::dary, 3}, pq::Orientation::min);
    CHECK(check_frames(lesson) > 100);
    const view::HeapFrameView last = lesson.frame_at(lesson.duration());
    REQUIRE(last.code);
    CHECK(last.code->lines.front().text == "remove_min():");
}

TEST_CASE("heap code: increase-key swims in a max-queue, sinks in a min-queue") {
    const HeapProgram up =
        ops_lesson("5 9 3 7 * 3^12", {pq::QueueFamily::indexed, 2}, pq::Orientation::max);
    CHECK(check_frames(up) > 30);
    const HeapProgram down =
        ops_lesson("1 5 3 9 7 1^8", {pq::QueueFamily::indexed, 2}, pq::Orientation::min);
    CHECK(check_frames(down) > 30);
    const auto calls = [](const HeapProgram& l, const char* line) {
        for (const view::CodeLineView& c : l.code_at(l.moment_at(l.duration())).lines) {
            if (c.text == line) return true;
        }
        return false;
    };
    CHECK(calls(up, "swim(k)"));
    CHECK_FALSE(calls(up, "sink(k)"));
    CHECK(calls(down, "sink(k)"));
    CHECK_FALSE(calls(down, "swim(k)"));
}

TEST_CASE("heap code: heapsort's two passes, construction then sortdown, in one listing") {
    for (const pq::Orientation o : {pq::Orientation::max, pq::Orientation::min}) {
        const HeapProgram lesson = sort_lesson("S O R T E X A M P L E", o);
        CHECK(check_frames(lesson) > 50);
        // Both passes mark lines of their own: the construction's sinks, the sortdown's rounds.
        std::vector<bool> marked_in_build;
        std::vector<bool> marked_in_sortdown;
        for (double t = 0.0; t <= lesson.duration(); t += 0.04) {
            const show::HeapMoment m = lesson.moment_at(t);
            const view::HeapFrameView f = lesson.frame_at(t);
            if (!f.code->current) continue;
            std::vector<bool>& marks = m.op == 0 ? marked_in_build : marked_in_sortdown;
            marks.resize(f.code->lines.size());
            marks[*f.code->current] = true;
        }
        const std::vector<view::CodeLineView> lines = show::heap_code(HeapOp::Kind::build, o);
        const auto line_of = [&](const std::string& text) {
            for (std::size_t k = 0; k < lines.size(); ++k) {
                if (lines[k].text == text) return k;
            }
            FAIL("no line " << text);
            return std::size_t{0};
        };
        REQUIRE(marked_in_build.size() == lines.size());
        REQUIRE(marked_in_sortdown.size() == lines.size());
        CHECK(marked_in_build[line_of("sink(k)")]);
        CHECK_FALSE(marked_in_build[line_of("exchange a[root], a[last]")]);
        CHECK(marked_in_sortdown[line_of("exchange a[root], a[last]")]);
        CHECK_FALSE(marked_in_sortdown[line_of("sink(k)")]);
    }
}

TEST_CASE("heap code: only one heap panel can show its code") {
    const std::vector<pq::QueueKind> two{{pq::QueueFamily::unordered, 1},
                                         {pq::QueueFamily::binary, 2}};
    HeapProgram lesson(
        pq::HeapRecord::operations(pq::parse_heap_ops("P Q *"), two, pq::Orientation::max),
        code_pacing, 1);
    CHECK_FALSE(show::heap_code_fits(lesson.record()));
    CHECK(contains(input_error_message([&] { lesson.show_code(true); }), "code:"));
    CHECK_FALSE(lesson.frame_at(1.5).code.has_value());  // without --code: no listing
    const std::vector<pq::QueueKind> array{{pq::QueueFamily::ordered, 1}};
    CHECK_FALSE(show::heap_code_fits(
        pq::HeapRecord::operations(pq::parse_heap_ops("P Q *"), array, pq::Orientation::max)));
}
