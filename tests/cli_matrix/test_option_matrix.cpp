// The command-line option matrix: the real `collide` over many bad and extreme option sets. Each
// bad set must end with exit 2 and a "collide: error: <option>" message before any work starts;
// each extreme but valid set must succeed. Built in every tree, this suite also runs against the
// sanitizer build's executable (scripts/test.sh, step 2, label `cli-matrix`), where UBSan's
// -fno-sanitize-recover turns any undefined behaviour (an unchecked double -> integer
// conversion, a signed overflow) into a failed run, and LeakSanitizer any leak on these paths.

#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "../app/run_collide.hpp"
#include "../support/input_error.hpp"
#include "bad_draw_options.hpp"

using collide::test::Bad;
using collide::test::bad_heap_options;
using collide::test::bad_render_options;
using collide::test::bad_thumbnail_options;
using collide::test::contains;
using collide::test::never;
using collide::test::run_collide;

namespace {

/// Runs every case; each must be refused with exit 2, with a message that names `option` first
/// (and says `detail`), without a sanitizer report.
void expect_refused(const std::string& command, const std::vector<Bad>& cases) {
    for (const Bad& c : cases) {
        const std::string args = command + " " + c.args;
        CAPTURE(args);
        const auto r = run_collide(args);
        CHECK(r.exit_code == 2);
        CHECK(contains(r.output, c.usage ? "collide: error: " : "collide: error: " + c.option));
        CHECK(contains(r.output, c.option));
        CHECK(contains(r.output, c.detail));
        CHECK_FALSE(contains(r.output, "runtime error"));  // UBSan
        CHECK_FALSE(contains(r.output, "Sanitizer"));      // ASan, LSan
    }
}

/// Every case must succeed (exit 0) without a sanitizer report.
void expect_ok(const std::vector<std::string>& cases) {
    for (const std::string& args : cases) {
        CAPTURE(args);
        const auto r = run_collide(args);
        CHECK(r.exit_code == 0);
        CHECK_FALSE(contains(r.output, "runtime error"));
        CHECK_FALSE(contains(r.output, "Sanitizer"));
    }
}

}  // namespace

TEST_CASE("option matrix: render's numbers, sizes and names") {
    expect_refused("render", bad_render_options());
}

TEST_CASE("option matrix: thumbnail --at at every extreme") {
    expect_refused("thumbnail", bad_thumbnail_options());
}

TEST_CASE("option matrix: simulate's --until, --dt and engines") {
    std::vector<Bad> cases;
    for (const char* v : {"-1", "nan", "inf", "1e300", "1e308", "abc"})
        cases.push_back({std::string("gas --until ") + v, "--until", "", v == std::string("abc")});
    for (const char* v : {"0", "-1", "nan", "inf", "1e-300", "1e-9"})
        cases.push_back({std::string("gas --until 10 --engine time --dt ") + v, "--dt"});
    cases.push_back({"gas --until 10 --engine time --dt 1e-300 --no-limits", "--dt"});
    cases.push_back(
        {"gas --until 1 --engine warp", "--engine", "fast, classic or time, got 'warp'"});
    cases.push_back({"gas --until 1 --engine classic --pq dary:0", "--pq", "from 2 to 64"});
    cases.push_back({"gas --until 1 --pq heap", "--pq", "got 'heap'"});
    cases.push_back({"gas --until 1 --engine time --td-detect magic", "--td-detect"});
    cases.push_back({"gas --until -1", "--until", "got '-1'"});
    cases.push_back({"/dev/null --until 1", "/dev/null"});
    cases.push_back({"/ --until 1", "/"});
    expect_refused("simulate", cases);
}

TEST_CASE("option matrix: bench engine's counts") {
    std::vector<Bad> cases;
    for (const char* v : {"0", "1", "1.5", "1e10", "-1", "nan", "inf"})
        cases.push_back({std::string("--n ") + v, "--n"});
    for (const char* v : {"0", "1", "-1", "nan"})
        cases.push_back({std::string("--eta ") + v, "--eta"});
    for (const char* v : {"0", "1e30", "nan", "inf", "2e10"})
        cases.push_back({std::string("--collisions ") + v, "--collisions"});
    for (const char* v : {"nan", "inf", "1e300"})
        cases.push_back({std::string("--warmup ") + v, "--warmup"});
    for (const char* v : {"-1", "18446744073709551616", "1e23"})
        cases.push_back({std::string("--seed ") + v, "--seed"});
    cases.push_back({"--engine time", "--engine", "event-driven engine (fast or classic)"});
    cases.push_back({"--engine classic --pq heap", "--pq", "got 'heap'"});
    cases.push_back({"--eta 2", "--eta", "(0, 0.85], got '2'"});
    expect_refused("bench engine", cases);
}

TEST_CASE("option matrix: heap's numbers and names") {
    expect_refused("heap", bad_heap_options());
}

TEST_CASE("option matrix: pq's implementations") {
    std::vector<Bad> cases;
    for (const char* v : {"heap", "dary:1", "dary:65", "indexed:5", "indexed:x", "dary:"})
        cases.push_back({std::string("--ops A --impl ") + v, "--impl", std::string("got '") + v});
    expect_refused("pq", cases);
}

TEST_CASE("option matrix: extreme but valid values run to the end") {
    expect_ok({"simulate gas --until 0", "simulate gas --until 1e-300",
               "simulate gas --until 5e-324", "simulate gas --until 1e3",
               "simulate gas --until 1 --engine time --dt 1e-4",
               "simulate gas --until 1 --engine classic --pq dary:2", "check gas",
               "bench engine --n 2 --eta 0.01 --collisions 1 --warmup 0",
               "bench engine --n 64 --collisions 100 --seed 18446744073709551615 --json"});
}

TEST_CASE("option matrix: puzzle's boards and options") {
    std::vector<Bad> cases;
    const std::string out = never + ".mp4";
    // The board is the positional argument: its errors begin "board".
    cases.push_back({"\"1 2 3 4 x 6 7 5 8\"" + out, "board", "'x' (token 5)"});
    cases.push_back({"\"1 2 3 4 9 6 7 5 0\"" + out, "board", "'9' (token 5)"});
    cases.push_back({"\"1 2 3 4 0 6 7 5 99999999999999999999\"" + out, "board", "(token 9)"});
    cases.push_back({"\"1 2 3 4 0 6 7 5 5\"" + out, "board", "'5' (token 9)"});
    cases.push_back({"\"1 2 3\"" + out, "board", "board: 3 tokens"});
    cases.push_back({"\"\"" + out, "board", "board: 0 tokens"});
    cases.push_back({"\"1 2 3 4 5 6 8 7 0\"" + out, "board", "cannot be solved"});
    cases.push_back({"\"2 1 3 0\"" + out, "board", "cannot be solved"});
    for (const char* v : {"-1", "1001", "1e3", "x"})
        cases.push_back({std::string("random --moves ") + v + out, "--moves"});
    for (const char* v : {"1", "5", "-3"})
        cases.push_back({std::string("random --side ") + v + out, "--side"});
    for (const char* v : {"-1", "1e23", "0x10"})
        cases.push_back({std::string("random --seed ") + v + out, "--seed"});
    cases.push_back({"\"1 2 3 4 0 6 7 5 8\" --seed 3" + out, "--seed"});
    cases.push_back({"random --heuristic euclid" + out, "--heuristic"});
    for (const char* v : {"heap", "dary:0", "indexed:5"})
        cases.push_back({std::string("random --pq ") + v + out, "--pq"});
    cases.push_back({"random --method dfs" + out, "--method"});
    for (const char* v : {"0", "-1", "20000001", "1e6"})
        cases.push_back({std::string("random --max-nodes ") + v + out, "--max-nodes"});
    cases.push_back({"random --solve -o x.mp4", "--output"});
    cases.push_back({"random --json --size 854x480", "--size"});
    cases.push_back({"random --size 320x180" + out, "--size"});
    cases.push_back({"random -q z" + out, "-q"});
    cases.push_back({"random --fps 0" + out, "--fps"});
    cases.push_back({"random --format avi" + out, "--format"});
    cases.push_back({"random --last-frame" + out, "-o"});
    cases.push_back({"random --progress loud" + out, "--progress"});
    cases.push_back(
        {"random --side 4 --moves 60 --seed 5 --max-nodes 10000 --solve", "--max-nodes"});
    expect_refused("puzzle", cases);
}
