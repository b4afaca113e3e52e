#include "interrupt.hpp"

#include <cstring>
#include <string>

#include "collide/error.hpp"

namespace collide::app {
namespace {

// Signal handlers may only touch lock-free atomics / sig_atomic_t of static storage duration;
// this is why these two are namespace-scope variables rather than members.
std::atomic<bool> interrupt_requested{false};
std::atomic<int> interrupt_signal{0};
std::atomic<bool> guard_alive{false};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "signal handlers need lock-free atomics");

extern "C" void on_interrupt(int signal_number) {
    interrupt_signal.store(signal_number);
    interrupt_requested.store(true);
}

void install(int signal_number, struct sigaction* previous) {
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    // SA_RESETHAND: the first Ctrl-C asks for a clean stop, a second one kills at once (the default
    // action) should the clean stop hang. No SA_RESTART: blocking calls return EINTR.
    action.sa_flags = SA_RESETHAND;
    if (sigaction(signal_number, &action, previous) != 0) {
        throw_runtime_error(std::string("cannot install signal handler: ") + std::strerror(errno));
    }
}

}  // namespace

InterruptGuard::InterruptGuard() {
    if (guard_alive.exchange(true)) {
        throw_runtime_error("InterruptGuard: only one may be alive at a time");
    }
    interrupt_requested.store(false);
    interrupt_signal.store(0);
    try {
        install(SIGINT, &previous_int_);
        install(SIGTERM, &previous_term_);
    } catch (...) {
        sigaction(SIGINT, &previous_int_, nullptr);
        guard_alive.store(false);
        throw;
    }
}

InterruptGuard::~InterruptGuard() {
    sigaction(SIGINT, &previous_int_, nullptr);
    sigaction(SIGTERM, &previous_term_, nullptr);
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

void InterruptGuard::throw_if_requested() const {
    if (!requested()) return;
    const int number = signal_number();
    const char* name = number == SIGINT ? "SIGINT" : number == SIGTERM ? "SIGTERM" : "a signal";
    throw_runtime_error(std::string("interrupted by ") + name + "; partial output removed");
}

}  // namespace collide::app
