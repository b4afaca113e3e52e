#pragma once
// Runs the `collide` executable built by this tree and captures its exit code and output.

#include <doctest/doctest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace collide::test {

struct RunResult {
    int exit_code = -1;
    std::string output;  ///< stdout and stderr, interleaved
};

/// Runs `collide <args>` through the shell with environment assignments `env` ("NAME='value'",
/// or empty) before it (args and env are pasted verbatim: quote them yourself).
inline RunResult run_collide_env(const std::string& env, const std::string& args) {
    const std::string cmd = env + " \"" + COLLIDE_EXE + "\" " + args + " 2>&1";
    RunResult r;
    FILE* pipe = popen(cmd.c_str(), "r");
    if (pipe == nullptr) return r;
    std::array<char, 4096> buf{};
    std::size_t n = 0;
    while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
    const int status = pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

/// Runs `collide <args>` through the shell (args are pasted verbatim: quote them yourself).
inline RunResult run_collide(const std::string& args) {
    return run_collide_env("", args);
}

/// Runs `collide <args>` expecting bad input (exit code 2, checked); returns its output.
inline std::string run_collide_bad_input(const std::string& args) {
    const RunResult r = run_collide(args);
    CHECK_MESSAGE(r.exit_code == 2, args);
    return r.output;
}

}  // namespace collide::test
