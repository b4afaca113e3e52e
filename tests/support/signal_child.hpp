#pragma once
// Shared by the test suites: runs a program in a child process, signals it once it is under way,
// and hands back how it ended (the interrupt tests of the video writer and of the CLI).

#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace collide::test {

struct SignalledRun {
    std::vector<std::string> argv;  ///< argv[0] is the executable's path
    std::filesystem::path log;      ///< stdout and stderr go here; empty: inherited
    std::function<bool()> started;  ///< polled every 10 ms: true once the run is under way
    /// Used instead of `started` when set: the same, given the child's process id.
    std::function<bool(pid_t)> started_child;
    std::chrono::milliseconds start_timeout{30000};  ///< sanitizer builds start slowly
    std::chrono::milliseconds settle{500};           ///< run time between started() and the signal
    int repeats = 1;                                 ///< how many times the signal is sent
    std::chrono::milliseconds repeat_gap{0};         ///< between two of them
    std::vector<int> ignored;  ///< signals the child starts with ignored (as under `nohup`)
    /// The child leads a process group of its own and the signal goes to the whole group, as a
    /// terminal's Ctrl-C does (for a shell running a loop of commands).
    bool process_group = false;
    /// How long the child may take to end after the signal before the test fails.
    std::chrono::milliseconds end_timeout{30000};
};

/// How a run that a signal stopped ends (docs/outputs.md): by that very signal, after its clean
/// stop (the shell's $? is 128 + its number), or, for SIGQUIT and SIGXCPU, whose default would
/// dump core, with exit status 128 + its number.
inline bool ended_by(int status, int signal_number) {
    if (signal_number == SIGQUIT || signal_number == SIGXCPU)
        return WIFEXITED(status) && WEXITSTATUS(status) == 128 + signal_number;
    return WIFSIGNALED(status) && WTERMSIG(status) == signal_number;
}

/// True when process `pid` has a file open in `directory` (an unnamed O_TMPFILE temporary shows
/// as "DIR/#INODE (deleted)" in /proc): the way to see that a writer has begun when its
/// temporary has no name.
inline bool has_open_file_in(pid_t pid, const std::filesystem::path& directory) {
    std::error_code error;
    const std::string prefix = std::filesystem::canonical(directory, error).string() + "/";
    const std::filesystem::path fds = "/proc/" + std::to_string(pid) + "/fd";
    for (const auto& entry : std::filesystem::directory_iterator(fds, error)) {
        const std::string target = std::filesystem::read_symlink(entry.path(), error).string();
        if (!error && target.rfind(prefix, 0) == 0) return true;
    }
    return false;
}

/// Starts run.argv, waits until run.started() holds (checked: a run that never starts fails the
/// test), lets it run run.settle longer, sends `signal_number` and returns the wait status once
/// the child has ended. A child still running 30 s after the signal ignored it: it is killed and
/// the test fails, rather than hanging.
/// The CPU time (user + system, every thread) process `pid` has used so far, in seconds.
inline double cpu_seconds_of(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
    // After the command's name in parentheses (which may hold spaces): fields 3 on; utime and
    // stime are fields 14 and 15.
    const std::size_t close = text.rfind(')');
    if (close == std::string::npos) return 0.0;
    std::istringstream fields(text.substr(close + 2));
    std::string field;
    unsigned long long ticks = 0;
    for (int number = 3; number <= 15 && (fields >> field); ++number) {
        if (number >= 14) ticks += std::stoull(field);
    }
    return static_cast<double>(ticks) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

/// `cpu_after_signal` (optional): set to the CPU time the child used from the signal to its
/// end, in seconds: unlike the wall time, it does not grow when the machine is busy, so a test
/// can bound the work a stop takes whatever the load.
inline int run_and_signal(const SignalledRun& run, int signal_number,
                          double* cpu_after_signal = nullptr) {
    // Emptied here, before the child exists: a log left by an earlier run in the same file must
    // not satisfy run.started() before this child has even truncated it (the signal then came
    // before collide had its handlers, under load).
    if (!run.log.empty()) {
        const int fd = open(run.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        REQUIRE(fd >= 0);
        close(fd);
    }
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        for (const int ignored : run.ignored) signal(ignored, SIG_IGN);
        if (run.process_group) setpgid(0, 0);
        if (!run.log.empty()) {
            const int fd = open(run.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            if (fd < 0) _exit(126);
            dup2(fd, STDOUT_FILENO);
            dup2(fd, STDERR_FILENO);
        }
        std::vector<char*> argv;
        for (const std::string& a : run.argv) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
    constexpr std::chrono::milliseconds poll{10};
    bool ready = false;
    for (auto waited = std::chrono::milliseconds{0}; waited < run.start_timeout && !ready;
         waited += poll) {
        ready = run.started_child ? run.started_child(child) : run.started();
        if (!ready) std::this_thread::sleep_for(poll);
    }
    CHECK(ready);
    std::this_thread::sleep_for(run.settle);
    const double cpu_before_signal = cpu_seconds_of(child);
    for (int sent = 0; sent < run.repeats; ++sent) {
        if (sent > 0) std::this_thread::sleep_for(run.repeat_gap);
        kill(run.process_group ? -child : child, signal_number);
    }
    int status = 0;
    for (auto waited = std::chrono::milliseconds{0}; waited < run.end_timeout; waited += poll) {
        rusage usage{};
        if (wait4(child, &status, WNOHANG, &usage) == child) {
            const auto seconds = [](const timeval& t) {
                return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) / 1e6;
            };
            if (cpu_after_signal != nullptr) {
                *cpu_after_signal =
                    seconds(usage.ru_utime) + seconds(usage.ru_stime) - cpu_before_signal;
            }
            return status;
        }
        std::this_thread::sleep_for(poll);
    }
    kill(run.process_group ? -child : child, SIGKILL);
    waitpid(child, &status, 0);
    FAIL("the child did not stop within " << run.end_timeout.count() << " ms of the signal");
    return status;
}

}  // namespace collide::test
