// `collide pq`: the lecture's trace table end to end (exit codes, table contents, formats, errors).
#include <doctest/doctest.h>

#include <sstream>
#include <string>
#include <vector>

#include "run_collide.hpp"

using collide::test::run_collide;

namespace {

const char* lecture_ops = "--ops \"P Q E * X A M * P L E *\"";

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

}  // namespace

TEST_CASE(
    "collide pq prints the lecture's table: removals Q, X, P, ordered array ends A E E L M P") {
    const auto r = run_collide(std::string("pq ") + lecture_ops + " --impl ordered --format csv");
    REQUIRE(r.exit_code == 0);
    const auto lines = lines_of(r.output);
    REQUIRE(lines.size() == 13);  // header + 12 operations
    CHECK(lines[0] == "operation,argument,return,size,ordered");
    CHECK(lines[1] == "insert,P,,1,P");
    CHECK(lines[4] == "remove max,,Q,2,E P");
    CHECK(lines[8] == "remove max,,X,4,A E M P");
    CHECK(lines[12] == "remove max,,P,6,A E E L M P");
}

TEST_CASE("by default every implementation gets a column in a plain text table") {
    const auto r = run_collide(std::string("pq ") + lecture_ops);
    REQUIRE(r.exit_code == 0);
    const auto lines = lines_of(r.output);
    REQUIRE(lines.size() == 14);  // header, rule, 12 operations
    for (const char* column : {"operation", "argument", "return", "size", "unordered", "ordered",
                               "binary", "dary:3", "indexed:4"}) {
        CHECK(contains(lines[0], column));
    }
    CHECK(lines[1].find_first_not_of("- ") == std::string::npos);
    CHECK(contains(lines[13], "A E E L M P"));
    CHECK(lines[13].rfind("remove max", 0) == 0);
}

TEST_CASE("--format markdown makes a pipe table for slides, --min removes the smallest") {
    const auto r =
        run_collide("pq --ops \"3 1 2 * *\" --min --impl binary,unordered --format markdown");
    REQUIRE(r.exit_code == 0);
    const auto lines = lines_of(r.output);
    REQUIRE(lines.size() == 7);
    CHECK(lines[0] == "| operation | argument | return | size | binary | unordered |");
    CHECK(lines[1] == "| --- | --- | --- | --- | --- | --- |");
    CHECK(lines[5] == "| remove min |  | 1 | 2 | 2 3 | 3 2 |");
    CHECK(lines[6] == "| remove min |  | 2 | 1 | 3 | 3 |");
}

TEST_CASE("a bad token is an input error naming it (exit 2)") {
    const auto r = run_collide("pq --ops \"P Q ? *\"");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "--ops: token 3 '?'"));
}

TEST_CASE("mixing numbers and letters is refused, naming the token (exit 2)") {
    const auto r = run_collide("pq --ops \"P 4 *\"");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "token 2 '4': is a number but the first key 'P' is a word"));
}

TEST_CASE("removing from an empty queue, an unknown --impl or --format are errors (exit 2)") {
    const auto empty = run_collide("pq --ops \"A * *\"");
    CHECK(empty.exit_code == 2);
    CHECK(contains(empty.output, "token 3 '*': removes from an empty queue"));
    const auto impl = run_collide("pq --ops A --impl heap");
    CHECK(impl.exit_code == 2);
    CHECK(contains(
        impl.output,
        "--impl: expected a queue: unordered, ordered, binary, dary:D or indexed[:D], got 'heap'"));
    const auto format = run_collide("pq --ops A --format pdf");
    CHECK(format.exit_code == 2);
    CHECK(contains(format.output, "pdf"));
    const auto missing = run_collide("pq");
    CHECK(missing.exit_code == 2);
    CHECK(contains(missing.output, "--ops"));
}

TEST_CASE("the text table's layout is unchanged: padded columns, a rule, no trailing blanks") {
    const auto r = run_collide("pq --ops \"P Q E * X\" --impl ordered,binary");
    REQUIRE(r.exit_code == 0);
    CHECK(r.output ==
          "operation   argument  return  size  ordered  binary\n"
          "----------  --------  ------  ----  -------  ------\n"
          "insert      P                 1     P        P\n"
          "insert      Q                 2     P Q      Q P\n"
          "insert      E                 3     E P Q    Q P E\n"
          "remove max            Q       2     E P      P E\n"
          "insert      X                 3     E P X    X E P\n");
}

namespace {

/// "1 2 ... count": the longest trace allowed when count is 10,000.
std::string ascending_ops(int count) {
    std::string ops;
    for (int key = 1; key <= count; ++key) ops += std::to_string(key) + " ";
    return ops;
}

}  // namespace

TEST_CASE("10,000 operations stream in bounded memory, arrays show 32 entries and say so") {
    // The table used to be built whole, every row with every array in full: memory and output
    // grew with the square of the input (1,500 operations: 8 MB of output; 10,000 would need
    // ~8 GB). The address-space cap makes such a regression fail instead of swapping.
    for (const char* format : {"text", "csv", "markdown"}) {
        CAPTURE(format);
        const auto big = collide::test::run_collide_measured(
            "pq --ops \"" + ascending_ops(10000) + "\" --format " + format, 2048);
        REQUIRE_MESSAGE(big.exit_code == 0, big.output.substr(0, 500));
        const auto small = collide::test::run_collide_measured(
            std::string("pq --ops \"P Q E * X\" --format ") + format);
        REQUIRE(small.exit_code == 0);
        MESSAGE("peak resident size: " << small.peak_rss_kib / 1024 << " MiB for 5 operations, "
                                       << big.peak_rss_kib / 1024 << " MiB for 10,000");
        CHECK(big.peak_rss_kib <= small.peak_rss_kib + 32 * 1024);
        // 10,000 rows of at most 5 arrays x 32 keys of 6 characters, plus the other columns.
        CHECK(big.output.size() < 10001u * 1100u);
        const auto lines = lines_of(big.output);
        REQUIRE(lines.size() == (std::string(format) == "csv" ? 10001u : 10002u));
        CHECK(contains(lines[0], "binary (first 32)"));
        // After the last insert the unordered and the ordered array both hold 1 ... 10000: they
        // show the first 32 and count the other 9,968.
        CHECK(contains(lines.back(),
                       "1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 "
                       "23 24 25 26 27 28 29 30 31 32 ... (+9968 more)"));
    }
}

TEST_CASE("over the limits: 10,001 operations, a 33-letter word, 17 implementations (exit 2)") {
    // Capped like the test above: a trace that ran anyway would need gigabytes.
    const auto many =
        collide::test::run_collide_measured("pq --ops \"" + ascending_ops(10001) + "\"", 2048);
    CHECK(many.exit_code == 2);
    CHECK(contains(many.output, "--ops: 10001 operations; at most 10000"));
    const auto word = run_collide("pq --ops \"A abcdefghijklmnopqrstuvwxyzabcdefg\"");
    CHECK(word.exit_code == 2);
    CHECK(contains(word.output,
                   "token 2 'abcdefghijklmnopqrstuvwxyzabcdef...': a word of 33 "
                   "letters; at most 32"));
    std::string impls = "binary";
    for (int i = 0; i < 16; ++i) impls += ",binary";
    const auto columns = run_collide("pq --ops A --impl " + impls);
    CHECK(columns.exit_code == 2);
    CHECK(contains(columns.output, "--impl: 17 implementations; at most 16"));
}
