#pragma once
// Runs the `collide` executable built by this tree and captures its exit code and output.

#include <doctest/doctest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace collide::test {

struct RunResult {
    int exit_code = -1;
    std::string output;  ///< stdout and stderr, interleaved
};

/// Runs `cmd` through popen, capturing its stdout, and its exit code.
inline RunResult run_command(const std::string& cmd) {
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

/// `text` as one word for sh: in single quotes, each ' in it written '\'' (close, an escaped
/// quote, reopen), so that a path with spaces, $, `, ", \, ' or a newline reaches the program as
/// it is. Double quotes would not do: sh expands $ and ` inside them (a TMPDIR may hold either).
inline std::string shell_quoted(const std::string& text) {
    // Appended, not "'" + ...: GCC 12 -O2 warns falsely there (-Wrestrict, PR 105329).
    std::string out(1, '\'');
    for (const char c : text) {
        if (c == '\'')
            out += "'\\''";
        else
            out += c;
    }
    out += '\'';
    return out;
}

/// Runs a shell command line (`sh -c`), capturing its exit code and its stdout and stderr.
inline RunResult run_collide_shell(const std::string& command) {
    return run_command("sh -c " + shell_quoted(command) + " 2>&1");
}

/// Runs `collide <args>` through the shell (args are pasted verbatim: quote them yourself).
inline RunResult run_collide(const std::string& args) {
    return run_command(std::string("\"") + COLLIDE_EXE + "\" " + args + " 2>&1");
}

/// Runs `collide <args>` through the shell with `env` before it: environment assignments
/// ("NAME='value'"), a wrapper ("timeout 60") or a shell command ("ulimit -v 1000000;"), or
/// nothing (env and args are pasted verbatim: quote them yourself).
inline RunResult run_collide_env(const std::string& env, const std::string& args) {
    return run_command(env + " \"" + COLLIDE_EXE + "\" " + args + " 2>&1");
}

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool address_sanitizer = true;
#else
inline constexpr bool address_sanitizer = false;
#endif

struct MeasuredRun : RunResult {
    long peak_rss_kib = 0;  ///< the process's peak resident set size (ru_maxrss from wait4)
};

/// Runs `collide <args>` like run_collide and also reports its peak resident size. Under
/// AddressSanitizer, freed blocks wait in a quarantine (256 MB by default) that would show as
/// growth: the child runs without one, so the figure measures what the program holds.
/// `address_space_mib` > 0 caps the child's address space (RLIMIT_AS) so that a regression fails
/// with an allocation error instead of taking a shared machine's memory; ignored under
/// AddressSanitizer, which reserves terabytes of address space for its shadow memory.
inline MeasuredRun run_collide_measured(const std::string& args, long address_space_mib = 0) {
    const std::string cmd = std::string("exec \"") + COLLIDE_EXE + "\" " + args + " 2>&1";
    std::array<int, 2> out{};
    if (pipe(out.data()) != 0) throw std::runtime_error("pipe failed");
    const pid_t child = fork();
    if (child < 0) throw std::runtime_error("fork failed");
    if (child == 0) {
        const char* asan = std::getenv("ASAN_OPTIONS");
        const std::string options =
            std::string(asan != nullptr ? asan : "") + ":quarantine_size_mb=0";
        setenv("ASAN_OPTIONS", options.c_str(), 1);
        if (!address_sanitizer && address_space_mib > 0) {
            const auto bytes = static_cast<rlim_t>(address_space_mib) * 1024 * 1024;
            const rlimit limit{bytes, bytes};
            setrlimit(RLIMIT_AS, &limit);
        }
        dup2(out[1], STDOUT_FILENO);
        close(out[0]);
        close(out[1]);
        execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    close(out[1]);
    MeasuredRun r;
    std::array<char, 4096> buf{};
    for (ssize_t n = 0; (n = read(out[0], buf.data(), buf.size())) != 0;) {
        if (n > 0)
            r.output.append(buf.data(), static_cast<std::size_t>(n));
        else if (errno != EINTR)
            break;
    }
    close(out[0]);
    int status = 0;
    rusage usage{};
    while (wait4(child, &status, 0, &usage) < 0) {
        if (errno != EINTR) throw std::runtime_error("wait4 failed");
    }
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.peak_rss_kib = usage.ru_maxrss;
    return r;
}

/// Runs `collide <args>` expecting bad input (exit code 2, checked); returns its output.
inline std::string run_collide_bad_input(const std::string& args) {
    const RunResult r = run_collide(args);
    CHECK_MESSAGE(r.exit_code == 2, args);
    return r.output;
}

}  // namespace collide::test
