#pragma once
// Shared by the test suites: runs code that must fail a COLLIDE_ASSERT (a programmer error, see
// collide/assert.hpp) in a child process, and hands back what the assertion printed.

#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <string>

namespace collide::test {

/// Runs f in a forked child with its stderr read through a pipe. Returns what the child printed
/// when it died of SIGABRT (a failed COLLIDE_ASSERT prints "file:line: assertion failed: ..."),
/// or "" when it ended otherwise (f returned or threw, or hung for a minute). The child touches
/// nothing the parent owns on the way out (_exit), so f may use objects built in the parent, as
/// long as it fails before it needs other threads: a renderer's frame checks come before any GL
/// call, and GL in the child would wait forever for the driver's threads, which fork() leaves
/// behind.
template <class F>
std::string assertion_failure(F&& f) {
    int pipe_fds[2];
    REQUIRE(pipe(pipe_fds) == 0);
    std::fflush(stderr);
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        close(pipe_fds[0]);
        dup2(pipe_fds[1], STDERR_FILENO);
        alarm(60);  // a child stuck (e.g. waiting for a thread fork() left behind) fails the test
        try {
            f();
        } catch (...) {
        }
        _exit(0);
    }
    close(pipe_fds[1]);
    std::string text;
    char buffer[512];
    for (ssize_t got = 0; (got = read(pipe_fds[0], buffer, sizeof buffer)) > 0;)
        text.append(buffer, static_cast<std::size_t>(got));
    close(pipe_fds[0]);
    int status = 0;
    REQUIRE(waitpid(child, &status, 0) == child);
    if (!WIFSIGNALED(status) || WTERMSIG(status) != SIGABRT) return "";
    return text;
}

}  // namespace collide::test
