#include "interrupt.hpp"

#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include "collide/error.hpp"
#include "collide/io/file.hpp"

namespace collide::app {
namespace {

// Signal handlers may only touch lock-free atomics of static storage duration; this is why these
// are namespace-scope variables rather than members.
std::atomic<bool> interrupt_requested{false};
std::atomic<int> interrupt_signal{0};
std::atomic<int> interrupt_count{0};
/// io::outputs_committed() when the last guard was created: more since then means this run put
/// outputs in place.
std::atomic<std::uint64_t> commits_before_run{0};
std::atomic<bool> guard_alive{false};
std::atomic<bool> stop_at_once{false};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "signal handlers need lock-free atomics");

/// The signals that ask for a clean stop: Ctrl-C, kill, a closed terminal, Ctrl-\, a reader of
/// our output (a `| head`) gone away, a CPU-time limit (`ulimit -t`), the two user signals and
/// the timers (`timeout -s ALRM`). Every one of them would otherwise kill the process by default
/// and leave a named temporary behind.
constexpr std::array<int, handled_signal_count> handled_signals{
    SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGXCPU, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM};

/// From this signal on (SIGPIPE aside) the user insists on stopping at once.
constexpr int signals_to_force = 3;

/// Signals the system repeats by itself (every write to a closed pipe; every second past a CPU
/// limit): never a sign that the user insists.
bool repeats_by_itself(int signal_number) {
    return signal_number == SIGPIPE || signal_number == SIGXCPU;
}

const char* signal_name(int number);

/// write(2) of a whole string, in a signal handler (async-signal-safe).
void write_raw(const char* text) {
    std::size_t size = 0;
    while (text[size] != '\0') ++size;
    while (size > 0) {
        const ssize_t written = ::write(STDERR_FILENO, text, size);
        if (written <= 0) return;
        text += written;
        size -= static_cast<std::size_t>(written);
    }
}

/// Ends the process from the handler: the message, then the signal's default (or 128 + the
/// number for those that would dump core). The signal is blocked while its handler runs, so
/// the raised one is delivered, with SIG_DFL, as the handler returns.
void end_from_handler(int signal_number) {
    write_raw("collide: error: interrupted by ");
    write_raw(signal_name(signal_number));
    write_raw("; nothing was written\n");
    if (signal_number == SIGQUIT || signal_number == SIGXCPU) _exit(128 + signal_number);
    signal(signal_number, SIG_DFL);
    raise(signal_number);
}

extern "C" void on_interrupt(int signal_number) {
    if (stop_at_once.load()) {
        end_from_handler(signal_number);
        return;
    }
    if (!interrupt_requested.exchange(true)) interrupt_signal.store(signal_number);
    if (repeats_by_itself(signal_number)) return;
    // The second signal (two Ctrl-C in a row) is harmless: the clean stop is already under way
    // and removes the temporaries. The third ends the process now, as the signal's default
    // would, for a clean stop that hangs (an unresponsive network filesystem, say).
    if (interrupt_count.fetch_add(1) + 1 >= signals_to_force) {
        signal(signal_number, SIG_DFL);
        raise(signal_number);
    }
}

extern "C" void on_message_timeout(int /*signal_number*/) {}

/// Installs the handler for `signal_number`, unless the signal was ignored when collide started
/// (`nohup`, a shell's `trap '' HUP`): that choice was the user's, and it stays. Returns whether
/// it installed one; `previous` receives the action it replaced.
bool install(int signal_number, struct sigaction* previous) {
    if (sigaction(signal_number, nullptr, previous) != 0) {
        throw_runtime_error(std::string("cannot read a signal's action: ") + std::strerror(errno));
    }
    if (previous->sa_handler == SIG_IGN) return false;
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    // Every handled signal is blocked while the handler runs, so two arriving together count
    // one after the other. No SA_RESETHAND (a second signal must not kill the process halfway
    // through removing its temporaries) and no SA_RESTART (blocking calls return EINTR, so a
    // write to a reader that stalled ends as soon as a signal arrives).
    sigemptyset(&action.sa_mask);
    for (const int other : handled_signals) sigaddset(&action.sa_mask, other);
    action.sa_flags = 0;
    if (sigaction(signal_number, &action, nullptr) != 0) {
        throw_runtime_error(std::string("cannot install signal handler: ") + std::strerror(errno));
    }
    return true;
}

const char* signal_name(int number) {
    switch (number) {
        case SIGINT:
            return "SIGINT";
        case SIGTERM:
            return "SIGTERM";
        case SIGHUP:
            return "SIGHUP";
        case SIGQUIT:
            return "SIGQUIT";
        case SIGPIPE:
            return "SIGPIPE";
        case SIGXCPU:
            return "SIGXCPU (CPU time limit)";
        case SIGUSR1:
            return "SIGUSR1";
        case SIGUSR2:
            return "SIGUSR2";
        case SIGALRM:
            return "SIGALRM";
        case SIGVTALRM:
            return "SIGVTALRM";
        default:
            return "a signal";
    }
}

}  // namespace

InterruptGuard::InterruptGuard() {
    if (guard_alive.exchange(true)) {
        throw_runtime_error("InterruptGuard: only one may be alive at a time");
    }
    interrupt_requested.store(false);
    interrupt_signal.store(0);
    interrupt_count.store(0);
    commits_before_run.store(io::outputs_committed());
    std::size_t tried = 0;
    try {
        for (; tried < handled_signals.size(); ++tried) {
            installed_[tried] = install(handled_signals[tried], &previous_[tried]);
        }
    } catch (...) {
        for (std::size_t i = 0; i < tried; ++i) {
            if (installed_[i]) sigaction(handled_signals[i], &previous_[i], nullptr);
        }
        guard_alive.store(false);
        throw;
    }
    io::set_stop_flag(&interrupt_requested);
}

StopAtOnce::StopAtOnce(const InterruptGuard& /*guard*/) noexcept {
    stop_at_once.store(true);
}

StopAtOnce::~StopAtOnce() {
    stop_at_once.store(false);
}

InterruptGuard::~InterruptGuard() {
    stop_at_once.store(false);
    // Once a signal asked for a stop, the handlers stay: the program is on its way out, and a
    // second Ctrl-C arriving between this destructor and exit() must stay harmless rather than
    // meet the default action (killed by the signal instead of exit 1). The third still kills.
    if (!interrupt_requested.load()) {
        io::set_stop_flag(nullptr);
        for (std::size_t i = 0; i < handled_signals.size(); ++i) {
            if (installed_[i]) sigaction(handled_signals[i], &previous_[i], nullptr);
        }
    }
    guard_alive.store(false);
}

const std::atomic<bool>& InterruptGuard::flag() const noexcept {
    return interrupt_requested;
}

bool InterruptGuard::requested() const noexcept {
    return interrupt_requested.load();
}

int InterruptGuard::signal_number() const noexcept {
    return interrupt_signal.load();
}

std::string InterruptGuard::message() const {
    return interrupt_message(signal_number());
}

void InterruptGuard::throw_if_requested() const {
    if (requested()) throw_runtime_error(message());
}

}  // namespace collide::app

namespace collide::app {

int interrupt_received() noexcept {
    return interrupt_requested.load() ? interrupt_signal.load() : 0;
}

std::string interrupt_message(int signal_number) {
    // All outputs go in place together (io::CommitGroup): once they have, the stop came too late.
    if (io::outputs_committed() > commits_before_run.load())
        return std::string("interrupted by ") + signal_name(signal_number) +
               " once the outputs were in place";
    return std::string("interrupted by ") + signal_name(signal_number) + "; nothing was written";
}

void ignore_file_size_signal() noexcept {
    // Past `ulimit -f`, write() then fails with EFBIG ("File too large"): an ordinary write
    // error, which removes the temporary and exits 1 with a message, where SIGXFSZ's default
    // would kill the process and leave a named temporary (a PNG sequence's directory) behind.
    signal(SIGXFSZ, SIG_IGN);
}

void end_by_signal(int signal_number, const std::string& message) noexcept {
    // The message must not hang on a reader of standard error that stalled (`2>&1 | sleep`):
    // a one-second alarm interrupts the write (no SA_RESTART).
    struct sigaction timeout {};
    timeout.sa_handler = on_message_timeout;
    sigemptyset(&timeout.sa_mask);
    sigaction(SIGALRM, &timeout, nullptr);
    alarm(1);
    std::fprintf(stderr, "collide: error: %s\n", message.c_str());
    alarm(0);
    // Signals whose default dumps core (Ctrl-\\, a CPU limit) end with the shell's code for
    // them instead: nothing failed that a core file would help with. The others end the process
    // as their default does, so that the caller sees "killed by SIGINT" (the shell's $? is 130)
    // and a shell loop or script stops, as it would for any program.
    if (signal_number == SIGQUIT || signal_number == SIGXCPU) _exit(128 + signal_number);
    signal(signal_number, SIG_DFL);
    sigset_t only{};
    sigemptyset(&only);
    sigaddset(&only, signal_number);
    sigprocmask(SIG_UNBLOCK, &only, nullptr);
    raise(signal_number);
    _exit(128 + signal_number);  // not reached: the default action of these signals terminates
}

}  // namespace collide::app
