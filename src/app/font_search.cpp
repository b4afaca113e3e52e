#include "font_search.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <string_view>

#include "collide/error.hpp"

extern char** environ;

namespace collide::app {

namespace {

constexpr std::array<std::string_view, 3> dejavu_paths = {
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",    // Debian, Ubuntu (fonts-dejavu-core)
    "/usr/share/fonts/dejavu-sans-fonts/DejaVuSans.ttf",  // Fedora
    "/usr/share/fonts/TTF/DejaVuSans.ttf",                // Arch
};

bool is_regular_file(const std::string& path) {
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

/// Owns a pipe's file descriptors.
struct Pipe {
    int fd[2] = {-1, -1};
    Pipe() {
        if (pipe2(fd, O_CLOEXEC) != 0) fd[0] = fd[1] = -1;
    }
    Pipe(const Pipe&) = delete;
    Pipe& operator=(const Pipe&) = delete;
    ~Pipe() {
        for (int f : fd) {
            if (f >= 0) close(f);
        }
    }
    void close_write() {
        if (fd[1] >= 0) close(fd[1]);
        fd[1] = -1;
    }
};

/// What `fc-match -f '%{file}' 'DejaVu Sans:style=Book'` prints, or "" (no fc-match, no answer).
/// Run without a shell; its standard error is left alone.
std::string fontconfig_match() {
    Pipe out;
    if (out.fd[0] < 0) return {};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out.fd[1], STDOUT_FILENO);
    char program[] = "fc-match";
    char format_flag[] = "-f";
    char format[] = "%{file}";
    char pattern[] = "DejaVu Sans:style=Book";
    char* argv[] = {program, format_flag, format, pattern, nullptr};
    pid_t pid = -1;
    const int spawned = posix_spawnp(&pid, program, &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    out.close_write();
    if (spawned != 0) return {};
    std::string text;
    char buffer[4096];
    for (;;) {
        const ssize_t n = read(out.fd[0], buffer, sizeof buffer);
        if (n > 0) {
            if (text.size() < 65536) text.append(buffer, static_cast<std::size_t>(n));
        } else if (n == 0 || errno != EINTR) {
            break;
        }
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return {};
    return text;
}

}  // namespace

std::string find_font(const std::string& requested) {
    if (!requested.empty()) {
        if (!is_regular_file(requested))
            throw_option_error("--font", requested, "a TrueType font file (.ttf) that exists");
        return requested;
    }
    if (const char* env = std::getenv("COLLIDE_FONT"); env != nullptr && *env != '\0') {
        if (!is_regular_file(env))
            throw_option_error("$COLLIDE_FONT", env, "a TrueType font file (.ttf) that exists");
        return env;
    }
    for (const std::string_view path : dejavu_paths) {
        if (is_regular_file(std::string(path))) return std::string(path);
    }
    const std::string matched = fontconfig_match();
    if (!matched.empty() && is_regular_file(matched)) return matched;
    return std::string(dejavu_paths.front());
}

}  // namespace collide::app
