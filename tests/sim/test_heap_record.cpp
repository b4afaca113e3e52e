// The record behind `collide heap` (heap_record.hpp): parsing, the steps replayed from the queues'
// records by kind, and the final state of every implementation against `collide pq`'s trace
// (run_trace) for the same operations. Its words and timing are tested with collide_show.
#include <doctest/doctest.h>

#include <algorithm>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "../support/input_error.hpp"
#include "collide/sim/pq/heap_record.hpp"
#include "collide/sim/pq/trace.hpp"

using namespace collide::pq;

namespace {

using collide::test::contains;
using collide::test::input_error_message;

/// Checks that `expr` throws an input error whose message contains `part`.
#define CHECK_INPUT_ERROR(expr, part) \
    CHECK(contains(input_error_message([&] { (void)(expr); }), part))

std::vector<QueueKind> every_kind() {
    return {{QueueFamily::unordered, 0}, {QueueFamily::ordered, 0}, {QueueFamily::binary, 2},
            {QueueFamily::dary, 3},      {QueueFamily::dary, 4},    {QueueFamily::dary, 5},
            {QueueFamily::indexed, 2},   {QueueFamily::indexed, 3}, {QueueFamily::indexed, 4}};
}

/// The last state of each panel.
std::vector<std::vector<std::string>> final_arrays(const HeapRecord& record) {
    std::vector<std::vector<std::string>> out;
    for (const HeapPanel& p : record.panels()) out.push_back(p.ops.back().end.keys);
    return out;
}

void check_against_pq_trace(const std::string& ops_text, Orientation orientation) {
    CAPTURE(ops_text);
    const std::vector<QueueKind> kinds = every_kind();
    const Trace trace = run_trace(parse_trace_ops(ops_text), orientation, kinds);
    const HeapRecord timeline =
        HeapRecord::operations(parse_heap_ops(ops_text), kinds, orientation);
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

/// The kinds of an operation's steps.
std::vector<HeapStep::Kind> kinds_of(const PanelOp& op) {
    std::vector<HeapStep::Kind> out;
    for (const HeapStep& s : op.steps) out.push_back(s.kind);
    return out;
}

}  // namespace

TEST_CASE("heap lesson: operations parse like collide pq's, plus KEY^NEW") {
    const auto ops = parse_heap_ops("5  * 3^12", "--ops");
    REQUIRE(ops.size() == 3);
    CHECK(ops[0].kind == HeapOp::Kind::insert);
    CHECK(ops[1].kind == HeapOp::Kind::remove);
    CHECK(ops[2].kind == HeapOp::Kind::increase);
    CHECK(ops[2].token == 3);
    CHECK(ops[2].spelling == "3^12");
    CHECK(parse_heap_ops("5 9 3^12")[2].new_key.number == 12);
    CHECK(parse_heap_ops("E^Z")[0].new_key.word == "Z");
}

TEST_CASE("heap lesson: bad tokens are input errors naming the token and its position") {
    CHECK_INPUT_ERROR(parse_heap_ops("P Q ? *"), "ops: token 3 '?'");
    CHECK_INPUT_ERROR(parse_heap_ops("P Q ? *", "--ops"), "--ops: token 3 '?'");
    CHECK_INPUT_ERROR(parse_heap_ops("5 9 3^"), "token 3 '3^': increase-key is KEY^NEW");
    CHECK_INPUT_ERROR(parse_heap_ops("5 9 ^4"), "token 3 '^4'");
    CHECK_INPUT_ERROR(parse_heap_ops("5 X"), "token 2 'X': is a word but the first key '5'");
    CHECK_INPUT_ERROR(parse_heap_ops("5 9 3^Z"), "token 3 '3^Z': is a word");
    CHECK_INPUT_ERROR(parse_heap_ops("   "), "ops: no operations given");
    CHECK_INPUT_ERROR(parse_heap_ops("99999999999999999999"), "integer out of range");
    CHECK_INPUT_ERROR(parse_sort_keys("S O * T"), "sort: token 3 '*'");
    CHECK_INPUT_ERROR(parse_sort_keys("", "--sort"), "--sort: no keys given");
}

TEST_CASE("heap lesson: operations a queue cannot do are input errors naming the token") {
    const std::vector<QueueKind> binary{{QueueFamily::binary, 2}};
    const std::vector<QueueKind> indexed{{QueueFamily::indexed, 2}};
    const auto run = [](const char* ops, const std::vector<QueueKind>& kinds) {
        return HeapRecord::operations(parse_heap_ops(ops), kinds, Orientation::max);
    };
    CHECK_INPUT_ERROR(run("P * *", binary), "ops: token 3 '*': removes from an empty queue");
    CHECK_INPUT_ERROR(run("5 3 3^12", binary), "token 3 '3^12': increase-key needs impl indexed");
    // The caller names the fields as its user knows them.
    CHECK_INPUT_ERROR(HeapRecord::operations(parse_heap_ops("5 3 3^12"), binary, Orientation::max,
                                             "--ops", "--impl"),
                      "--ops: token 3 '3^12': increase-key needs --impl indexed");
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

TEST_CASE("heap lesson: the lecture's insert of S into a binary heap, step by step") {
    const std::vector<QueueKind> binary{{QueueFamily::binary, 2}};
    const HeapRecord t =
        HeapRecord::operations(parse_heap_ops("T P R N H O A E I G S"), binary, Orientation::max);
    const HeapPanel& panel = t.panels().front();
    // The heap T P R N H O A E I G, then S swims up past H and P and stops under T.
    CHECK(panel.ops[9].end.keys ==
          std::vector<std::string>{"T", "P", "R", "N", "H", "O", "A", "E", "I", "G"});
    const PanelOp& insert_s = panel.ops[10];
    using K = HeapStep::Kind;
    CHECK(kinds_of(insert_s) ==
          std::vector<K>{K::appear, K::compare, K::exchange, K::compare, K::exchange, K::compare});
    CHECK(insert_s.steps[0].i == 10);
    CHECK(insert_s.steps[0].state.keys.back() == "S");  // already in the array
    CHECK(insert_s.steps[1].i == 10);
    CHECK(insert_s.steps[1].j == 4);
    CHECK(insert_s.steps[1].order > 0);  // S > H
    CHECK(insert_s.steps[2].i == 10);
    CHECK(insert_s.steps[2].j == 4);
    CHECK(insert_s.steps[2].state.keys[10] == "S");  // the state before the exchange
    CHECK(insert_s.steps[5].order < 0);              // S < T: stop
    CHECK(insert_s.end.keys ==
          std::vector<std::string>{"T", "S", "R", "N", "P", "O", "A", "E", "I", "G", "H"});
    CHECK(insert_s.end.compares - panel.ops[9].end.compares == 3);
    CHECK(insert_s.end.exchanges - panel.ops[9].end.exchanges == 2);
    CHECK(insert_s.removed.empty());
    CHECK(t.ops().size() == 11);
    CHECK(!t.heapsort());
}

TEST_CASE("heap lesson: remove-max exchanges root and last, removes, then sinks") {
    const std::vector<QueueKind> binary{{QueueFamily::binary, 2}};
    const HeapRecord t =
        HeapRecord::operations(parse_heap_ops("P Q E X A *"), binary, Orientation::max);
    const PanelOp& remove = t.panels().front().ops.back();
    REQUIRE(remove.steps.size() >= 3);
    CHECK(remove.steps[0].kind == HeapStep::Kind::exchange);
    CHECK(remove.steps[0].i == 0);
    CHECK(remove.steps[1].kind == HeapStep::Kind::remove);
    CHECK(remove.steps[1].i == 4);
    CHECK(remove.steps[1].state.keys[4] == "X");  // the state before it leaves
    CHECK(remove.steps[2].kind == HeapStep::Kind::compare);
    CHECK(remove.removed == "X");
}

TEST_CASE("heap lesson: the arrays record their scan and their shifts") {
    const std::vector<QueueKind> arrays{{QueueFamily::unordered, 0}, {QueueFamily::ordered, 0}};
    const HeapRecord t =
        HeapRecord::operations(parse_heap_ops("P Q E A *"), arrays, Orientation::max);
    const HeapPanel& unordered = t.panels()[0];
    const HeapPanel& ordered = t.panels()[1];
    // remove max: the scan compares each slot with the max so far, then exchanges it with the last.
    const PanelOp& scan = unordered.ops.back();
    REQUIRE(scan.steps.size() >= 2);
    CHECK(scan.steps.front().kind == HeapStep::Kind::compare);
    CHECK(scan.steps.front().best == std::optional<std::size_t>(0));
    CHECK(scan.steps.front().order > 0);  // Q > P: the new max
    CHECK(scan.steps[1].best == std::optional<std::size_t>(1));
    CHECK(ordered.shifts);
    // insert E into P Q (kept ascending: P, Q): E is compared with Q, Q shifts right, ...
    const PanelOp& insert_e = ordered.ops[2];
    CHECK(std::count_if(insert_e.steps.begin(), insert_e.steps.end(),
                        [](const HeapStep& s) { return s.kind == HeapStep::Kind::shift; }) == 2);
    CHECK(std::none_of(insert_e.steps.begin(), insert_e.steps.end(),
                       [](const HeapStep& s) { return s.kind == HeapStep::Kind::exchange; }));
    CHECK(ordered.ops.back().steps.size() == 1);  // remove max: the last slot leaves
    CHECK(!unordered.tree);
    CHECK(t.panels().size() == 2);
}

TEST_CASE("heap lesson: increase-key through the indexed heap's map") {
    const std::vector<QueueKind> indexed{{QueueFamily::indexed, 2}};
    const HeapRecord t =
        HeapRecord::operations(parse_heap_ops("5 9 3 7 * 3^12"), indexed, Orientation::max);
    const HeapPanel& panel = t.panels().front();
    const PanelOp& increase = panel.ops.back();
    REQUIRE(increase.steps.size() >= 2);
    CHECK(increase.steps[0].kind == HeapStep::Kind::change);
    CHECK(increase.steps[0].from == "3");
    CHECK(increase.steps[0].state.keys[increase.steps[0].i] == "12");
    // Then the new key against the old one, in its own slot.
    CHECK(increase.steps[1].kind == HeapStep::Kind::compare);
    CHECK(increase.steps[1].i == increase.steps[1].j);
    CHECK(increase.steps[1].order > 0);  // 12 > 3
    CHECK(increase.end.keys.front() == "12");
    // The handles follow their keys: handle 2 (the third insert, key 3) is now 12 at the root.
    CHECK(increase.end.handles.front() == 2);
    CHECK(increase.end.handles.size() == increase.end.keys.size());
    CHECK(panel.tree);
}

TEST_CASE("heap lesson: heapsort builds the heap, then sorts down with the sorted part apart") {
    const std::vector<TraceKey> keys = parse_sort_keys("S O R T E X A M P L E");
    const HeapRecord t = HeapRecord::heapsort(keys, Orientation::max);
    CHECK(t.heapsort());
    REQUIRE(t.ops().size() == 2);
    CHECK(t.ops()[0].kind == HeapOp::Kind::build);
    CHECK(t.ops()[1].kind == HeapOp::Kind::sortdown);
    const HeapPanel& panel = t.panels().front();
    CHECK(panel.ops[0].end.keys ==
          std::vector<std::string>{"X", "T", "S", "P", "L", "R", "A", "M", "O", "E", "E"});
    CHECK(panel.ops[0].steps.front().kind == HeapStep::Kind::sink);
    CHECK(panel.ops[0].steps.front().i == 4);   // E at a[5]: the last node with a child
    CHECK(panel.ops[0].steps.front().j == 11);  // in the whole array
    CHECK(panel.ops[1].end.keys ==
          std::vector<std::string>{"A", "E", "E", "L", "M", "O", "P", "R", "S", "T", "X"});
    CHECK(panel.ops[1].end.heap_size == 0);
    // The sortdown starts by exchanging the max with the last, then sinks in a smaller heap.
    const HeapStep& first = panel.ops[1].steps.front();
    CHECK(first.kind == HeapStep::Kind::exchange);
    CHECK(first.i == 0);
    CHECK(first.j == 10);
    CHECK(panel.ops[1].steps[1].kind == HeapStep::Kind::sink);
    CHECK(panel.ops[1].steps[1].j == 10);
    CHECK(panel.ops[1].steps[1].state.heap_size == 10);
    const HeapRecord down = HeapRecord::heapsort(keys, Orientation::min);
    CHECK(down.panels().front().ops[1].end.keys ==
          std::vector<std::string>{"X", "T", "S", "R", "P", "O", "M", "L", "E", "E", "A"});
}

TEST_CASE("heap lesson: the record holds the most items any panel holds at once") {
    const std::vector<QueueKind> kinds{{QueueFamily::unordered, 0}, {QueueFamily::binary, 2}};
    const HeapRecord t =
        HeapRecord::operations(parse_heap_ops("P Q E * A"), kinds, Orientation::min);
    CHECK(t.capacity() == 3);
    CHECK(t.orientation() == Orientation::min);
    REQUIRE(t.ops().size() == 5);
    CHECK(t.ops()[3].spelling == "*");
    for (const HeapPanel& p : t.panels()) CHECK(p.ops[3].removed == "E");
}
