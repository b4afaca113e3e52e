#include "interrupt.hpp"

#include <unistd.h>

#include <array>
#include <cstring>
#include <string>

#include "collide/error.hpp"

namespace collide::app {
namespace {

// Signal handlers may only touch lock-free atomics of static storage duration; this is why these
// are namespace-scope variables rather than members.
std::atomic<bool> interrupt_requested{false};
std::atomic<int> interrupt_signal{0};
std::atomic<int> interrupt_count{0};
std::atomic<bool> guard_alive{false};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "signal handlers need lock-free atomics");

/// The signals that ask for a clean stop: Ctrl-C, kill, a closed terminal, Ctrl-\, and a reader
/// of our output (a `| head`) gone away.
constexpr std::array<int, 5> handled_signals{SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE};

/// From this signal on (SIGPIPE aside) the user insists on stopping at once.
constexpr int signals_to_force = 3;

extern "C" void on_interrupt(int signal_number) {
    if (!interrupt_requested.exchange(true)) interrupt_signal.store(signal_number);
    // SIGPIPE repeats by itself (every write to the closed pipe), so it never counts as the
    // user insisting.
    if (signal_number == SIGPIPE) return;
    // The second signal (two Ctrl-C in a row) is harmless: the clean stop is already under way
    // and removes the temporaries. The third ends the process now, as the signal's default
    // would, for a clean stop that hangs (an unresponsive network filesystem, say).
    if (interrupt_count.fetch_add(1) + 1 >= signals_to_force) {
        signal(signal_number, SIG_DFL);
        raise(signal_number);
    }
}

void install(int signal_number, struct sigaction* previous) {
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    // Every handled signal is blocked while the handler runs, so two arriving together count
    // one after the other. No SA_RESETHAND (a second signal must not kill the process halfway
    // through removing its temporaries) and no SA_RESTART (blocking calls return EINTR).
    sigemptyset(&action.sa_mask);
    for (const int other : handled_signals) sigaddset(&action.sa_mask, other);
    action.sa_flags = 0;
    if (sigaction(signal_number, &action, previous) != 0) {
        throw_runtime_error(std::string("cannot install signal handler: ") + std::strerror(errno));
    }
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
    std::size_t installed = 0;
    try {
        for (; installed < handled_signals.size(); ++installed) {
            install(handled_signals[installed], &previous_[installed]);
        }
    } catch (...) {
        for (std::size_t i = 0; i < installed; ++i) {
            sigaction(handled_signals[i], &previous_[i], nullptr);
        }
        guard_alive.store(false);
        throw;
    }
}

InterruptGuard::~InterruptGuard() {
    // Once a signal asked for a stop, the handlers stay: the program is on its way out, and a
    // second Ctrl-C arriving between this destructor and exit() must stay harmless rather than
    // meet the default action (killed by the signal instead of exit 1). The third still kills.
    if (!interrupt_requested.load()) {
        for (std::size_t i = 0; i < handled_signals.size(); ++i) {
            sigaction(handled_signals[i], &previous_[i], nullptr);
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
    return std::string("interrupted by ") + signal_name(signal_number()) + "; nothing was written";
}

void InterruptGuard::throw_if_requested() const {
    if (requested()) throw_runtime_error(message());
}

}  // namespace collide::app
