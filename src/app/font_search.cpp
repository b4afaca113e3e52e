#include "font_search.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string_view>

#include "collide/error.hpp"
#include "collide/text/font_face.hpp"
#include "interrupt.hpp"

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

/// How long fontconfig may take to name a font: it answers in milliseconds from its cache, in
/// seconds when it builds the cache first; one that hangs must not hold the run.
constexpr int fontconfig_timeout_ms = 10'000;

/// Ends the child `pid` (a SIGKILL: it may be stuck) and reaps it.
void kill_and_reap(pid_t pid) {
    kill(pid, SIGKILL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
}

/// What `fc-match -f '%{file}' 'DejaVu Sans:style=Book'` prints, or "" (no fc-match, no answer
/// within fontconfig_timeout_ms). Run without a shell; its standard error is left alone. A signal
/// that asks the run to stop (interrupt.hpp) ends the wait at once and throws the interrupt.
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
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::milliseconds(fontconfig_timeout_ms);
    std::string text;
    char buffer[4096];
    for (;;) {
        if (const int signal_number = interrupt_received(); signal_number != 0) {
            kill_and_reap(pid);
            throw_runtime_error(interrupt_message(signal_number));
        }
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            kill_and_reap(pid);
            return {};
        }
        // A signal interrupts the wait (the handlers have no SA_RESTART): the flag is looked at
        // again at once.
        pollfd ready{out.fd[0], POLLIN, 0};
        const int polled =
            poll(&ready, 1, static_cast<int>(std::min<long long>(left.count(), 200)));
        if (polled < 0 && errno != EINTR) break;
        if (polled <= 0) continue;
        const ssize_t n = read(out.fd[0], buffer, sizeof buffer);
        if (n > 0) {
            if (text.size() < 65536) text.append(buffer, static_cast<std::size_t>(n));
        } else if (n == 0 || errno != EINTR) {
            break;
        }
    }
    // Its output is closed: it is about to exit (or has); the deadline still holds.
    int status = 0;
    for (;;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) return {};
        if (interrupt_received() != 0 || std::chrono::steady_clock::now() >= deadline) {
            kill_and_reap(pid);
            if (const int signal_number = interrupt_received(); signal_number != 0)
                throw_runtime_error(interrupt_message(signal_number));
            return {};
        }
        usleep(10'000);
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return {};
    return text;
}

/// `path`, which the user chose with `chosen_by` (--font, $COLLIDE_FONT), once it is known to be a
/// font: one that is not is the user's mistake (exit 2, naming the file and the option), not a
/// broken installation (the renderer's advice to reinstall fonts-dejavu-core).
std::string users_font(const std::string& path, std::string_view chosen_by) {
    if (!is_regular_file(path))
        throw_option_error(chosen_by, path, "a TrueType font file (.ttf) that exists");
    (void)text::FontFace(path, chosen_by);
    return path;
}

}  // namespace

std::string find_font(const std::string& requested) {
    if (!requested.empty()) return users_font(requested, "--font");
    if (const char* env = std::getenv("COLLIDE_FONT"); env != nullptr && *env != '\0') {
        return users_font(env, "$COLLIDE_FONT");
    }
    for (const std::string_view path : dejavu_paths) {
        if (is_regular_file(std::string(path))) return std::string(path);
    }
    const std::string matched = fontconfig_match();
    if (!matched.empty() && is_regular_file(matched)) return matched;
    return std::string(dejavu_paths.front());
}

}  // namespace collide::app
