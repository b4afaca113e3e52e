#pragma once
/// \file
/// SIGINT, SIGTERM, SIGHUP, SIGQUIT and SIGPIPE turned into a flag the frame pipeline polls: the
/// pipeline then throws, stack unwinding runs the writers' destructors (which delete their
/// temporary outputs), and `main` exits 1 with "interrupted by SIGINT; nothing was written".
/// Nothing half-written ever lands at the destination path (docs/outputs.md).

#include <array>
#include <atomic>
#include <csignal>
#include <string>

namespace collide::app {

/// Installs handlers for SIGINT, SIGTERM, SIGHUP, SIGQUIT and SIGPIPE for its lifetime
/// (restoring the previous ones after, unless a signal arrived: then they stay until the program
/// exits, so a late second signal is still harmless). The first signal sets the flag; a second one
/// is ignored
/// (the clean stop is already removing the temporaries); a third (SIGPIPE aside) ends the process
/// at once with the signal's default action, for a clean stop that hangs.
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
    /// True once one of the signals arrived.
    [[nodiscard]] bool requested() const noexcept;
    /// The first signal that arrived, or 0.
    [[nodiscard]] int signal_number() const noexcept;
    /// The one wording of an interrupt: "interrupted by SIGINT; nothing was written".
    [[nodiscard]] std::string message() const;
    /// Throws Error(runtime, message()) when a signal arrived.
    void throw_if_requested() const;

  private:
    std::array<struct sigaction, 5> previous_{};
};

}  // namespace collide::app
