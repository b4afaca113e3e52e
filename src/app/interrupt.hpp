#pragma once
/// \file
/// SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGXCPU, SIGUSR1/2, SIGALRM and SIGVTALRM turned
/// into a flag the frame pipeline polls: the pipeline then throws, stack unwinding runs the
/// writers' destructors (which delete their temporary outputs), and `main` says "interrupted by
/// SIGINT; nothing was written" and ends the process by the same signal (end_by_signal), so that
/// the shell sees 130 and a loop stops. Nothing half-written ever lands at the destination path
/// (docs/outputs.md).

#include <array>
#include <atomic>
#include <csignal>
#include <cstddef>
#include <string>

namespace collide::app {

/// How many signals an InterruptGuard handles.
inline constexpr std::size_t handled_signal_count = 10;

/// Installs handlers for the signals above for its lifetime, except those that were ignored
/// when the program started (`nohup` stays in force)
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
    std::array<struct sigaction, handled_signal_count> previous_{};
    std::array<bool, handled_signal_count> installed_{};
};

/// While alive, a signal ends the process at once, from the handler, with the same message and
/// the same end as a clean stop (end_by_signal): for phases that have nothing to clean up and no
/// loop that polls the flag, such as loading a large scene. A signal that arrived before it was
/// created is left to the guard's flag.
class StopAtOnce {
  public:
    explicit StopAtOnce(const InterruptGuard& guard) noexcept;
    ~StopAtOnce();
    StopAtOnce(const StopAtOnce&) = delete;
    StopAtOnce& operator=(const StopAtOnce&) = delete;
};

/// The signal that asked for a stop since the last InterruptGuard was created, or 0; it stays
/// readable after the guard is gone (main reads it once the command has unwound).
[[nodiscard]] int interrupt_received() noexcept;

/// "interrupted by SIGINT; nothing was written", or "interrupted by SIGINT once the outputs were
/// in place" when the run (since the last InterruptGuard was created) put outputs in place.
[[nodiscard]] std::string interrupt_message(int signal_number);

/// Makes a file-size limit (`ulimit -f`) an ordinary write error (EFBIG) instead of SIGXFSZ's
/// default (killed, temporaries left behind). Called once at the start of main.
void ignore_file_size_signal() noexcept;

/// The end of an interrupted run, after the clean stop: prints "collide: error: MESSAGE" (giving
/// up after a second if standard error does not take it) and ends the process by
/// `signal_number`'s default action, so the caller sees it killed by that signal (the shell's $?
/// is 128 + the number: 130 for SIGINT). SIGQUIT and SIGXCPU, whose default dumps core, exit
/// with 128 + the number instead.
[[noreturn]] void end_by_signal(int signal_number, const std::string& message) noexcept;

}  // namespace collide::app
