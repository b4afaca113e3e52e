// Ctrl-C (SIGINT) and SIGTERM stop `collide render` and `collide simulate` even in the middle of
// one endless simulation step (an absurd --speed or --until): exit 1 with a message, and nothing
// left behind: no output, no temporary file.

#include <doctest/doctest.h>
#include <sys/wait.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../support/signal_child.hpp"
#include "../support/temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using collide::test::run_and_signal;
using collide::test::SignalledRun;
using collide::test::TempDir;

std::vector<std::string> entries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
    return names;
}

std::string read_all(const fs::path& file) {
    std::ifstream in(file);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool has_hidden_entry(const fs::path& dir) {
    for (const std::string& name : entries(dir))
        if (name.front() == '.') return true;
    return false;
}

bool has_entry_containing(const fs::path& dir, const std::string& part) {
    for (const std::string& name : entries(dir))
        if (name.find(part) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("render: a signal during an endless simulation step exits 1 and leaves nothing") {
    for (const int signal_number : {SIGINT, SIGTERM}) {
        CAPTURE(signal_number);
        TempDir out("interrupt_render");
        TempDir logs("interrupt_render_log");
        const fs::path log = logs.path / "log.txt";
        // --speed 1e300: the first frame lies 10^298 time units ahead, an endless advance_to()
        // (--no-limits: without it, the work estimate refuses to start such a run).
        SignalledRun run;
        run.argv = {
            COLLIDE_EXE, "render",     "gas",  "-o",         (out.path / "out.mp4").string(),
            "--speed",   "1e300",      "-q",   "l",          "--duration",
            "1",         "--progress", "none", "--no-limits"};
        run.log = log;
        run.started = [&] { return has_hidden_entry(out.path); };
        // The default settle (500 ms) takes it deep into the simulation, where only the
        // engines' polling sees a signal.
        const int status = run_and_signal(run, signal_number);
        REQUIRE(WIFEXITED(status));  // handled, not killed by the signal
        CHECK(WEXITSTATUS(status) == 1);
        CHECK(read_all(log).find(signal_number == SIGINT
                                     ? "interrupted by SIGINT"
                                     : "interrupted by SIGTERM") != std::string::npos);
        CHECK(entries(out.path).empty());  // neither the video nor its temporary
    }
}

TEST_CASE("simulate: a signal during an endless run exits 1 and removes the events log") {
    TempDir out("interrupt_simulate");
    TempDir logs("interrupt_simulate_log");
    const fs::path log = logs.path / "log.txt";
    SignalledRun run;
    run.argv = {COLLIDE_EXE,
                "simulate",
                "gas",
                "--until",
                "1e300",
                "--events-log",
                (out.path / "ev.csv").string(),
                "--no-limits"};
    run.log = log;
    run.started = [&] { return has_entry_containing(out.path, "ev.csv.tmp"); };
    const int status = run_and_signal(run, SIGINT);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 1);
    CHECK(read_all(log).find("interrupted by SIGINT") != std::string::npos);
    CHECK(entries(out.path).empty());
}
