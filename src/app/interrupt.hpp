#pragma once
/// \file
/// SIGINT/SIGTERM turned into a flag the frame pipeline polls: the pipeline then throws, stack
/// unwinding runs the writers' destructors (which delete their temporary outputs), and `main`
/// exits non-zero with a message. Nothing half-written ever lands at the destination path.

#include <atomic>
#include <csignal>

namespace collide::app {

/// Installs SIGINT and SIGTERM handlers for its lifetime (restoring the previous ones after).
/// Each handler fires once: a second Ctrl-C gets the default action and ends the process at once.
/// Only one may be alive at a time (a second one throws Error(runtime)): a signal handler can only
/// reach static storage, so the flag behind it is the one process-wide variable of the program.
class InterruptGuard {
  public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    /// The flag the handlers set; hand it to VideoOptions::cancel and poll it in loops.
    [[nodiscard]] const std::atomic<bool>& flag() const noexcept;
    /// True once SIGINT or SIGTERM arrived.
    [[nodiscard]] bool requested() const noexcept;
    /// The signal that arrived (SIGINT, SIGTERM) or 0.
    [[nodiscard]] int signal_number() const noexcept;
    /// Throws Error(runtime, "interrupted by SIGINT") when a signal arrived.
    void throw_if_requested() const;

  private:
    struct sigaction previous_int_ {};
    struct sigaction previous_term_ {};
};

}  // namespace collide::app
