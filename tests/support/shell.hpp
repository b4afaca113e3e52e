#pragma once
// Shell helpers for the end-to-end tests: run a command for its standard output, and ask whether
// ffprobe is installed (the tests that read a file back with it skip without it).
#include <cstdio>
#include <cstdlib>
#include <string>

namespace collide::test {

/// Runs a shell command and returns its standard output ("" when it cannot start).
inline std::string capture(const std::string& cmd) {
    std::string out;
    FILE* pipe = popen(cmd.c_str(), "r");
    if (pipe == nullptr) return out;
    char buf[512];
    while (std::fgets(buf, sizeof buf, pipe) != nullptr) out += buf;
    pclose(pipe);
    return out;
}

inline bool have_ffprobe() {
    return std::system("ffprobe -version >/dev/null 2>&1") == 0;
}

}  // namespace collide::test
