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
    "collide pq prints the lecture's table: removals Q, X, P; ordered array ends A E E L M P") {
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

TEST_CASE("--format markdown makes a pipe table for slides; --min removes the smallest") {
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
    CHECK(contains(impl.output, "--impl: unknown queue 'heap'"));
    const auto format = run_collide("pq --ops A --format pdf");
    CHECK(format.exit_code == 2);
    CHECK(contains(format.output, "pdf"));
    const auto missing = run_collide("pq");
    CHECK(missing.exit_code == 2);
    CHECK(contains(missing.output, "--ops"));
}
