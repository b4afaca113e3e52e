// The animation model of `collide heap` (heap_lesson.hpp): parsing, the steps replayed from the
// queues' records, captions, lock-step timing, and the final state of every implementation
// against `collide pq`'s trace (run_trace) for the same operations.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "../support/input_error.hpp"
#include "collide/sim/pq/heap_lesson.hpp"
#include "collide/sim/pq/trace.hpp"

using namespace collide::pq;

namespace {

using collide::test::contains;
using collide::test::input_error_message;

/// Checks that `expr` throws an input error whose message contains `part`.
#define CHECK_INPUT_ERROR(expr, part) \
    CHECK(contains(input_error_message([&] { (void)(expr); }), part))

const LessonPacing pacing{0.5, 0.25, 1.0, 2.0};

std::vector<QueueKind> every_kind() {
    return {{QueueFamily::unordered, 0}, {QueueFamily::ordered, 0}, {QueueFamily::binary, 2},
            {QueueFamily::dary, 3},      {QueueFamily::dary, 4},    {QueueFamily::dary, 5},
            {QueueFamily::indexed, 2},   {QueueFamily::indexed, 3}, {QueueFamily::indexed, 4}};
}

/// The last state the animation shows for each panel.
std::vector<std::vector<std::string>> final_arrays(const LessonTimeline& timeline) {
    const LessonFrame last = timeline.frame_at(timeline.duration());
    std::vector<std::vector<std::string>> out;
    for (const LessonPanelFrame& p : last.panels) out.push_back(p.state->keys);
    return out;
}

void check_against_pq_trace(const std::string& ops_text, Orientation orientation) {
    CAPTURE(ops_text);
    const std::vector<QueueKind> kinds = every_kind();
    const Trace trace = run_trace(parse_trace_ops(ops_text), orientation, kinds);
    const LessonTimeline timeline =
        LessonTimeline::operations(parse_lesson_ops(ops_text), kinds, orientation, 1, pacing);
    const auto arrays = final_arrays(timeline);
    REQUIRE(arrays.size() == kinds.size());
    for (std::size_t k = 0; k < kinds.size(); ++k) {
        CAPTURE(to_string(kinds[k]));
        CHECK(arrays[k] == trace.rows.back().contents[k]);
        // ... and after every operation, not only the last.
        for (std::size_t op = 0; op < trace.rows.size(); ++op) {
            CHECK(timeline.panels()[k].ops[op].end.keys == trace.rows[op].contents[k]);
        }
    }
}

std::string random_ops(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::string out;
    int size = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (size > 0 && rng() % 3 == 0) {
            out += "* ";
            --size;
        } else {
            out += std::string(1, static_cast<char>('A' + rng() % 26)) + " ";
            ++size;
        }
    }
    return out;
}

bool has_caption(const LessonPanel& panel, const std::string& text) {
    for (const LessonPanelOp& op : panel.ops) {
        for (const LessonStep& s : op.steps) {
            if (s.state.caption == text) return true;
        }
    }
    return false;
}

}  // namespace

TEST_CASE("heap lesson: operations parse like collide pq's, plus KEY^NEW") {
    const auto ops = parse_lesson_ops("5  * 3^12", "--ops");
    REQUIRE(ops.size() == 3);
    CHECK(ops[0].kind == LessonOp::Kind::insert);
    CHECK(ops[1].kind == LessonOp::Kind::remove);
    CHECK(ops[2].kind == LessonOp::Kind::increase);
    CHECK(ops[2].token == 3);
    CHECK(ops[2].spelling == "3^12");
    CHECK(parse_lesson_ops("5 9 3^12")[2].new_key.number == 12);
    CHECK(parse_lesson_ops("E^Z")[0].new_key.word == "Z");
}

TEST_CASE("heap lesson: bad tokens are input errors naming the token and its position") {
    CHECK_INPUT_ERROR(parse_lesson_ops("P Q ? *"), "--ops: token 3 '?'");
    CHECK_INPUT_ERROR(parse_lesson_ops("5 9 3^"), "token 3 '3^': increase-key is KEY^NEW");
    CHECK_INPUT_ERROR(parse_lesson_ops("5 9 ^4"), "token 3 '^4'");
    CHECK_INPUT_ERROR(parse_lesson_ops("5 X"), "token 2 'X': is a word but the first key '5'");
    CHECK_INPUT_ERROR(parse_lesson_ops("5 9 3^Z"), "token 3 '3^Z': is a word");
    CHECK_INPUT_ERROR(parse_lesson_ops("   "), "--ops: no operations given");
    CHECK_INPUT_ERROR(parse_lesson_ops("99999999999999999999"), "integer out of range");
    CHECK_INPUT_ERROR(parse_sort_keys("S O * T", "--sort"), "--sort: token 3 '*'");
    CHECK_INPUT_ERROR(parse_sort_keys("", "--sort"), "--sort: no keys given");
}

TEST_CASE("heap lesson: operations a queue cannot do are input errors naming the token") {
    const std::vector<QueueKind> binary{{QueueFamily::binary, 2}};
    const std::vector<QueueKind> indexed{{QueueFamily::indexed, 2}};
    const auto run = [](const char* ops, const std::vector<QueueKind>& kinds) {
        return LessonTimeline::operations(parse_lesson_ops(ops), kinds, Orientation::max, 1,
                                          pacing);
    };
    CHECK_INPUT_ERROR(run("P * *", binary), "--ops: token 3 '*': removes from an empty queue");
    CHECK_INPUT_ERROR(run("5 3 3^12", binary), "token 3 '3^12': increase-key needs --impl indexed");
    CHECK_INPUT_ERROR(run("5 3 4^12", indexed), "token 3 '4^12': key 4 is not in the queue");
    CHECK_INPUT_ERROR(run("5 3 3^1", indexed), "token 3 '3^1': increase-key to a smaller key");
    CHECK_INPUT_ERROR(run("5 3 * 5^9", indexed), "key 5 is not in the queue");
}

TEST_CASE("heap lesson: every implementation ends where collide pq's trace ends (max and min)") {
    check_against_pq_trace("P Q E * X A M * P L E *", Orientation::max);
    check_against_pq_trace("P Q E * X A M * P L E *", Orientation::min);
    check_against_pq_trace("5 -3 12 007 * 4 4 4 * *", Orientation::max);
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        check_against_pq_trace(random_ops(40, seed),
                               seed % 2 ? Orientation::max : Orientation::min);
    }
}

TEST_CASE("heap lesson: the lecture's insert of S into a binary heap, in words") {
    const std::vector<QueueKind> binary{{QueueFamily::binary, 2}};
    const LessonTimeline t = LessonTimeline::operations(parse_lesson_ops("T P R N H O A E I G S"),
                                                        binary, Orientation::max, 1, pacing);
    const LessonPanel& panel = t.panels().front();
    // The heap T P R N H O A E I G, then S swims up past H and P and stops under T.
    CHECK(panel.ops[9].end.keys ==
          std::vector<std::string>{"T", "P", "R", "N", "H", "O", "A", "E", "I", "G"});
    const LessonPanelOp& insert_s = panel.ops[10];
    REQUIRE(insert_s.steps.size() == 6);  // appear, (compare, exchange) x 2, compare
    CHECK(insert_s.steps[0].kind == LessonStep::Kind::appear);
    CHECK(insert_s.steps[0].state.caption == "insert S at a[11]");
    CHECK(insert_s.steps[1].state.caption == "insert S at a[11]; S > H: exchange");
    CHECK(insert_s.steps[2].kind == LessonStep::Kind::exchange);
    CHECK(insert_s.steps[2].i == 10);
    CHECK(insert_s.steps[2].j == 4);
    CHECK(insert_s.steps[3].state.caption == "insert S at a[11]; S > P: exchange");
    CHECK(insert_s.steps[5].state.caption == "insert S at a[11]; S < T: stop");
    CHECK(insert_s.end.keys ==
          std::vector<std::string>{"T", "S", "R", "N", "P", "O", "A", "E", "I", "G", "H"});
    CHECK(insert_s.end.caption == "insert S: 3 compares, 2 exchanges");
    CHECK(insert_s.end.compares - panel.ops[9].end.compares == 3);
}

TEST_CASE("heap lesson: remove-max exchanges root and last, removes, then sinks (0-based names)") {
    const std::vector<QueueKind> binary{{QueueFamily::binary, 2}};
    const LessonTimeline t = LessonTimeline::operations(parse_lesson_ops("P Q E X A *"), binary,
                                                        Orientation::max, 0, pacing);
    const LessonPanelOp& remove = t.panels().front().ops.back();
    REQUIRE(remove.steps.size() >= 3);
    CHECK(remove.steps[0].kind == LessonStep::Kind::exchange);
    CHECK(remove.steps[0].i == 0);
    CHECK(remove.steps[1].kind == LessonStep::Kind::remove);
    CHECK(remove.steps[1].state.caption == "remove max: X leaves a[4]");
    CHECK(remove.steps[2].kind == LessonStep::Kind::compare);
    CHECK(remove.end.caption.rfind("remove max X: ", 0) == 0);
}

TEST_CASE("heap lesson: the arrays show their scan and their shifts") {
    const std::vector<QueueKind> arrays{{QueueFamily::unordered, 0}, {QueueFamily::ordered, 0}};
    const LessonTimeline t = LessonTimeline::operations(parse_lesson_ops("P Q E A *"), arrays,
                                                        Orientation::max, 1, pacing);
    const LessonPanel& unordered = t.panels()[0];
    const LessonPanel& ordered = t.panels()[1];
    CHECK(has_caption(unordered, "scan for the max: Q > P, new max Q"));
    CHECK(has_caption(unordered, "remove max: exchange Q with the last, A"));
    CHECK(unordered.ops.back().steps.front().kind == LessonStep::Kind::compare);
    CHECK(ordered.shifts);
    CHECK(has_caption(ordered, "insert E at a[3]; P > E: shift P right"));
    CHECK(ordered.ops.back().steps.size() == 1);  // remove max: the last slot leaves
    CHECK(!unordered.tree);
    CHECK(t.panels().size() == 2);
}

TEST_CASE("heap lesson: increase-key through the indexed heap's map") {
    const std::vector<QueueKind> indexed{{QueueFamily::indexed, 2}};
    const LessonTimeline t = LessonTimeline::operations(parse_lesson_ops("5 9 3 7 * 3^12"), indexed,
                                                        Orientation::max, 1, pacing);
    const LessonPanel& panel = t.panels().front();
    const LessonPanelOp& increase = panel.ops.back();
    REQUIRE(!increase.steps.empty());
    CHECK(increase.steps[0].kind == LessonStep::Kind::change);
    CHECK(increase.end.keys.front() == "12");
    // The handles follow their keys: handle 2 (the third insert, key 3) is now 12 at the root.
    CHECK(increase.end.handles.front() == 2);
    CHECK(increase.end.handles.size() == increase.end.keys.size());
    CHECK(panel.tree);
}

TEST_CASE("heap lesson: heapsort builds the heap, then sorts down with the sorted part apart") {
    const std::vector<TraceKey> keys = parse_sort_keys("S O R T E X A M P L E");
    const LessonTimeline t = LessonTimeline::heapsort(keys, Orientation::max, 1, pacing);
    REQUIRE(t.op_labels().size() == 2);
    const LessonPanel& panel = t.panels().front();
    CHECK(panel.ops[0].end.keys ==
          std::vector<std::string>{"X", "T", "S", "P", "L", "R", "A", "M", "O", "E", "E"});
    CHECK(panel.ops[0].steps.front().kind == LessonStep::Kind::sink);
    CHECK(panel.ops[0].steps.front().state.caption == "build the heap: sink E at a[5]");
    CHECK(panel.ops[1].end.keys ==
          std::vector<std::string>{"A", "E", "E", "L", "M", "O", "P", "R", "S", "T", "X"});
    CHECK(panel.ops[1].end.heap_size == 0);
    CHECK(panel.ops[1].steps.front().state.caption ==
          "sortdown: exchange max X with E at a[11]; X is in place");
    const LessonTimeline down = LessonTimeline::heapsort(keys, Orientation::min, 0, pacing);
    CHECK(down.panels().front().ops[1].end.keys ==
          std::vector<std::string>{"X", "T", "S", "R", "P", "O", "M", "L", "E", "E", "A"});
}

TEST_CASE("heap lesson: panels move in lock-step, each operation paced by its longest panel") {
    const std::vector<QueueKind> kinds{{QueueFamily::unordered, 0}, {QueueFamily::binary, 2}};
    const LessonTimeline t =
        LessonTimeline::operations(parse_lesson_ops("P Q E *"), kinds, Orientation::max, 1, pacing);
    double expected = pacing.intro + pacing.outro;
    for (std::size_t op = 0; op < 4; ++op) {
        std::size_t steps = 0;
        for (const LessonPanel& p : t.panels()) steps = std::max(steps, p.ops[op].steps.size());
        expected += static_cast<double>(steps) * pacing.pace + pacing.pause;
    }
    CHECK(t.duration() == doctest::Approx(expected));
    CHECK(!t.frame_at(0.0).started);
    CHECK(t.frame_at(0.0).panels[0].state->keys.empty());
    // The first step of the first operation: both panels show P appearing.
    const LessonFrame f = t.frame_at(pacing.intro + 0.1);
    CHECK(f.started);
    CHECK(f.op == 0);
    for (const LessonPanelFrame& p : f.panels) {
        REQUIRE(p.step != nullptr);
        CHECK(p.step->kind == LessonStep::Kind::appear);
        CHECK(p.progress == doctest::Approx(0.2));
    }
    // Counters never go down.
    std::uint64_t last = 0;
    for (double s = 0.0; s <= t.duration(); s += 0.05) {
        const std::uint64_t c = t.frame_at(s).panels[1].state->compares;
        CHECK(c >= last);
        last = c;
    }
    CHECK(t.capacity() == 3);
}

TEST_CASE("heap lesson: a pace of zero is refused") {
    const std::vector<QueueKind> binary{{QueueFamily::binary, 2}};
    CHECK_INPUT_ERROR(LessonTimeline::operations(parse_lesson_ops("P"), binary, Orientation::max, 1,
                                                 {0.0, 0.1, 0.0, 0.0}),
                      "--pace");
}
