// The teaching trace behind `collide pq`: parsing the operations and the lecture's table.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "collide/error.hpp"
#include "collide/sim/pq/trace.hpp"

using namespace collide::pq;

namespace {

std::string trace_error(std::string_view ops) {
    try {
        (void)parse_trace_ops(ops);
    } catch (const collide::Error& e) {
        CHECK(e.kind() == collide::ErrorKind::input);
        return e.what();
    }
    return "(no error)";
}

std::vector<std::string> letters(const char* spaced) {
    std::vector<std::string> out;
    for (const TraceOp& op : parse_trace_ops(spaced)) out.push_back(op.key.text());
    return out;
}

/// The column of one queue kind in a trace.
std::size_t column_of(const Trace& trace, const char* kind) {
    for (std::size_t c = 0; c < trace.queues.size(); ++c) {
        if (to_string(trace.queues[c]) == kind) return c;
    }
    FAIL("no column " << kind);
    return 0;
}

}  // namespace

TEST_CASE(
    "the lecture's sequence: removals return Q, X, P and the ordered array ends A E E L M P") {
    const auto ops = parse_trace_ops("P Q E * X A M * P L E *");
    const auto kinds = default_trace_queues();
    const Trace trace = run_trace(ops, Orientation::max, kinds);
    REQUIRE(trace.rows.size() == 12);
    std::vector<std::string> removed;
    for (const TraceRow& row : trace.rows) {
        if (row.operation == "remove max") removed.push_back(row.returned);
        CHECK(row.contents.size() == kinds.size());
        for (const auto& array : row.contents) CHECK(array.size() == row.size);
    }
    CHECK(removed == std::vector<std::string>{"Q", "X", "P"});
    CHECK(trace.rows.back().size == 6);
    CHECK(trace.rows.back().contents[column_of(trace, "ordered")] == letters("A E E L M P"));
    CHECK(trace.rows[0].operation == "insert");
    CHECK(trace.rows[0].argument == "P");
    CHECK(trace.rows[0].returned.empty());
    CHECK(trace.rows[3].argument.empty());
}

TEST_CASE("the arrays follow the lecture's rules step by step") {
    const auto ops = parse_trace_ops("P Q E * X A M * P L E *");
    const QueueKind kinds[] = {parse_queue_kind("unordered"), parse_queue_kind("binary")};
    const Trace trace = run_trace(ops, Orientation::max, kinds);
    // Unordered: the max is swapped with the last item, then the array shrinks.
    CHECK(trace.rows[2].contents[0] == letters("P Q E"));
    CHECK(trace.rows[3].contents[0] == letters("P E"));
    // Binary heap: P Q swims Q to the root; E goes under it; remove max sinks E.
    CHECK(trace.rows[1].contents[1] == letters("Q P"));
    CHECK(trace.rows[2].contents[1] == letters("Q P E"));
    CHECK(trace.rows[3].contents[1] == letters("P E"));
    CHECK(trace.rows[4].contents[1] == letters("X E P"));
}

TEST_CASE("a min-queue removes the smallest and its ordered array is descending") {
    const auto ops = parse_trace_ops("5 -3 12 * 007 *");
    const QueueKind kinds[] = {parse_queue_kind("ordered"), parse_queue_kind("dary:4")};
    const Trace trace = run_trace(ops, Orientation::min, kinds);
    CHECK(trace.rows[3].operation == "remove min");
    CHECK(trace.rows[3].returned == "-3");
    CHECK(trace.rows[4].argument == "7");  // numbers print in canonical form
    CHECK(trace.rows[5].returned == "5");
    CHECK(trace.rows[4].contents[0] == std::vector<std::string>{"12", "7", "5"});
}

TEST_CASE("numbers compare as numbers, words byte by byte") {
    const auto numbers = parse_trace_ops("9 10 100 * *");
    const QueueKind kinds[] = {parse_queue_kind("binary")};
    const Trace trace = run_trace(numbers, Orientation::max, kinds);
    CHECK(trace.rows[3].returned == "100");
    CHECK(trace.rows[4].returned == "10");
    const Trace words = run_trace(parse_trace_ops("apple Pear pear *"), Orientation::max, kinds);
    CHECK(words.rows[3].returned == "pear");
}

TEST_CASE("bad operation strings name the offending token") {
    CHECK(trace_error("P Q ! *") ==
          "ops: token 3 '!': not a key (a word of letters or an integer) nor '*' (remove)");
    CHECK(trace_error("P Q1").find("token 2 'Q1'") != std::string::npos);
    CHECK(trace_error("P 3 Q").rfind(
              "ops: token 2 '3': is a number but the first key 'P' is a word", 0) == 0);
    CHECK(trace_error("* 4 x").find("token 3 'x': is a word but the first key '4' is a number") !=
          std::string::npos);
    CHECK(trace_error("99999999999999999999")
              .find("token 1 '99999999999999999999': integer out of range") != std::string::npos);
    CHECK(trace_error("   ").find("no operations") != std::string::npos);
    CHECK(trace_error("- +").find("token 1 '-'") != std::string::npos);
}

TEST_CASE("removing from an empty queue is an input error naming the token") {
    const auto ops = parse_trace_ops("A * *");
    const QueueKind kinds[] = {parse_queue_kind("binary")};
    try {
        (void)run_trace(ops, Orientation::max, kinds);
        FAIL("no error");
    } catch (const collide::Error& e) {
        CHECK(e.kind() == collide::ErrorKind::input);
        CHECK(std::string(e.what()) == "ops: token 3 '*': removes from an empty queue");
    }
}

TEST_CASE("white space of any kind separates tokens, '*' needs no neighbours") {
    const auto ops = parse_trace_ops("\tP\nQ  *  ");
    REQUIRE(ops.size() == 3);
    CHECK(ops[2].remove);
    CHECK(ops[2].token == 3);
    CHECK(ops[1].spelling == "Q");
}

TEST_CASE("for_each_trace_row streams run_trace's rows, each array cut to its first entries") {
    // Four inserts, one removal, 40 times: the queue grows to 121 items, arrays beyond 5 are cut.
    std::string spaced;
    for (int i = 0; i < 200; ++i)
        spaced += i % 5 == 4 ? "* " : std::string(1, char('A' + (i * 7) % 26)) + " ";
    const auto ops = parse_trace_ops(spaced);
    const std::vector<QueueKind> kinds = default_trace_queues();
    const Trace full = run_trace(ops, Orientation::max, kinds);
    std::size_t seen = 0;
    for_each_trace_row(ops, Orientation::max, kinds, 5, [&](const TraceRow& row) {
        REQUIRE(seen < full.rows.size());
        const TraceRow& expected = full.rows[seen++];
        CHECK(row.operation == expected.operation);
        CHECK(row.argument == expected.argument);
        CHECK(row.returned == expected.returned);
        CHECK(row.size == expected.size);
        REQUIRE(row.contents.size() == kinds.size());
        for (std::size_t q = 0; q < kinds.size(); ++q) {
            const auto& all = expected.contents[q];
            REQUIRE(all.size() == row.size);
            const std::size_t shown = std::min<std::size_t>(5, all.size());
            CHECK(row.contents[q] == std::vector<std::string>(all.begin(), all.begin() + shown));
        }
    });
    CHECK(seen == ops.size());
    CHECK(peak_trace_size(ops) == 121);
}

TEST_CASE("an input error in the trace comes before the first row") {
    const auto ops = parse_trace_ops("A B * * *");
    const std::vector<QueueKind> kinds = default_trace_queues();
    std::size_t rows = 0;
    try {
        for_each_trace_row(ops, Orientation::min, kinds, all_trace_entries,
                           [&rows](const TraceRow&) { ++rows; });
        FAIL("no error");
    } catch (const collide::Error& e) {
        CHECK(e.kind() == collide::ErrorKind::input);
        CHECK(std::string(e.what()) == "ops: token 5 '*': removes from an empty queue");
    }
    CHECK(rows == 0);
}

TEST_CASE("a trace is at most max_trace_operations operations with words of bounded length") {
    std::string at_limit;
    for (std::size_t i = 0; i < max_trace_operations; ++i) at_limit += "A ";
    CHECK(parse_trace_ops(at_limit).size() == max_trace_operations);
    CHECK(trace_error(at_limit + "*") ==
          "ops: 10001 operations; at most 10000 (a trace is a table to read, one row per "
          "operation)");
    const std::string longest(max_trace_key_length, 'x');
    CHECK(parse_trace_ops("A " + longest).back().key.word == longest);
    CHECK(trace_error("A " + longest + "y") ==
          "ops: token 2 '" + longest + "...': a word of 33 letters; at most 32");
}
