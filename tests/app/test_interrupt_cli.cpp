// Ctrl-C (SIGINT) and SIGTERM stop `collide render` and `collide simulate` even in the middle of
// one endless simulation step (an absurd --speed or --until): exit 1 with a message, and nothing
// left behind: no output, no temporary file.

#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "../support/temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using collide::test::TempDir;

std::vector<std::string> entries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
    return names;
}

/// Starts `collide args...` (output to `log`), waits until `started()` holds (up to 30 s:
/// sanitizer builds start slowly) and a little more, sends `signal_number` and returns the wait
/// status once the process has ended.
int run_and_signal(const std::vector<std::string>& args, const fs::path& log, int signal_number,
                   const std::function<bool()>& started) {
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd < 0) _exit(126);
        dup2(fd, STDOUT_FILENO);
        dup2(fd, STDERR_FILENO);
        std::vector<char*> argv;
        argv.push_back(const_cast<char*>(COLLIDE_EXE));
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(COLLIDE_EXE, argv.data());
        _exit(127);
    }
    bool ready = false;
    for (int attempt = 0; attempt < 3000 && !ready; ++attempt) {
        ready = started();
        if (!ready) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    CHECK(ready);
    // Let it get deep into the simulation, where only the engines' polling can notice a signal.
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    kill(child, signal_number);
    // A run that ignores the signal would never end: give it 30 s, then kill it (and fail).
    int status = 0;
    for (int attempt = 0; attempt < 3000; ++attempt) {
        if (waitpid(child, &status, WNOHANG) == child) return status;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    kill(child, SIGKILL);
    waitpid(child, &status, 0);
    FAIL("collide did not stop within 30 s of the signal");
    return status;
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
        // --speed 1e300: the first frame lies 10^298 time units ahead, an endless advance_to().
        const int status =
            run_and_signal({"render", "gas", "-o", (out.path / "out.mp4").string(), "--speed",
                            "1e300", "-q", "l", "--duration", "1", "--progress", "none"},
                           log, signal_number, [&] { return has_hidden_entry(out.path); });
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
    const int status = run_and_signal(
        {"simulate", "gas", "--until", "1e300", "--events-log", (out.path / "ev.csv").string()},
        log, SIGINT, [&] { return has_entry_containing(out.path, "ev.csv.tmp"); });
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 1);
    CHECK(read_all(log).find("interrupted by SIGINT") != std::string::npos);
    CHECK(entries(out.path).empty());
}
