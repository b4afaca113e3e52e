// Standard output that cannot take what a command prints (a full disk, a closed descriptor) is a
// failure like any other write: exit 1 with a message, never a silent exit 0 (#48 item 10). The
// real program, run through the shell with its standard output on /dev/full or closed (>&-).

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/temp_dir.hpp"
#include "run_collide.hpp"

using collide::test::run_collide;
using collide::test::run_collide_shell;
using collide::test::TempDir;

namespace {

namespace fs = std::filesystem;

/// `collide ARGS` with standard output redirected by `redirect` (the shell's words), its
/// standard error captured.
collide::test::RunResult run_redirected(const std::string& args, const std::string& redirect) {
    return run_collide_shell(std::string("\"") + COLLIDE_EXE + "\" " + args + " " + redirect);
}

}  // namespace

TEST_CASE("every command that prints on standard output fails (exit 1) when it cannot") {
    if (!fs::exists("/dev/full")) return;
    TempDir dir("stdout_lost");
    const auto path = [&](const char* name) { return "'" + (dir.path / name).string() + "'"; };
    REQUIRE(run_collide("thumbnail gas --at 1 --size 160x90 -o " + path("a.png")).exit_code == 0);
    const std::vector<std::string> commands{
        "pq --ops '3 1 2 * *'",
        "simulate gas --until 0.5 --json",
        "simulate billiards --until 0.5",
        "check gas",
        "check gas --json",
        "scenes",
        "scenes --json",
        "puzzle '1 2 3 4 5 6 0 7 8' --solve",
        "puzzle '1 2 3 4 5 6 0 7 8' --json",
        "render gas -q l --size 160x90 --duration 0.5 --no-intro --no-epilogue --json -o " +
            path("g.mp4"),
        "render gas -q l --size 160x90 --duration 0.5 --no-intro --no-epilogue -o " +
            path("g2.mp4"),
        "thumbnail gas --size 160x90 --json -o " + path("t.png"),
        "compare " + path("a.png") + " " + path("a.png"),
        "--help",
        "render --help",
        "--version",
    };
    for (const std::string& args : commands) {
        CAPTURE(args);
        const auto full = run_redirected(args, "> /dev/full");
        CHECK(full.exit_code == 1);
        CHECK(full.output.find("collide: error: cannot write to standard output: No space left "
                               "on device") != std::string::npos);
        const auto closed = run_redirected(args, ">&-");
        CHECK(closed.exit_code == 1);
        CHECK(closed.output.find("collide: error: cannot write to standard output: Bad file "
                                 "descriptor") != std::string::npos);
    }
}

TEST_CASE("a closed standard output is never handed to a file the run opens") {
    // With descriptor 1 closed, the first file opened would get it: what is printed would land in
    // the video. The summary must fail instead, and the files hold only their own bytes.
    TempDir dir("stdout_closed");
    const fs::path layout = dir.path / "layout.json";
    const auto r =
        run_redirected("thumbnail gas --size 160x90 --json --layout-json '" + layout.string() +
                           "' -o '" + (dir.path / "t.png").string() + "'",
                       ">&-");
    CHECK(r.exit_code == 1);
    REQUIRE(fs::exists(layout));
    std::ifstream in(layout);
    CHECK(nlohmann::json::accept(in));
}

TEST_CASE("a reader that leaves ends the run quietly, by SIGPIPE, as any filter") {
    // `collide scenes | true`: no message about standard output (the reader chose to stop).
    const auto r = run_collide_shell(std::string("\"") + COLLIDE_EXE + "\" scenes --json | true");
    CHECK(r.output.find("cannot write to standard output") == std::string::npos);
}

TEST_CASE("output that arrived whole still exits 0") {
    const auto r = run_redirected("scenes", "> /dev/null");
    CHECK(r.exit_code == 0);
    CHECK(r.output.empty());
}
