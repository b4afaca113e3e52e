#pragma once
/// \file
/// Standard output as a promise: what a command printed there either arrived, or the program
/// says so and exits 1 (`collide scenes > /dev/full`, a closed standard output). Both programs
/// (`collide`, `collide-draw`) call these from main.

#include <optional>
#include <string>

namespace collide::app {

/// Gives each of the standard descriptors (0, 1, 2) that is closed at start a placeholder that
/// fails every transfer in its direction (/dev/null opened the other way): a write to a closed
/// standard output then fails with EBADF, as it would have, instead of landing in whichever file
/// the run opened next and received descriptor 1. Call first thing in main.
void reserve_standard_descriptors() noexcept;

/// Flushes standard output and returns, when anything printed there was lost (a full disk, a
/// closed descriptor, a reader gone), "cannot write to standard output: REASON"; nullopt when
/// everything arrived. `broken_pipe` is set when the reason is a reader that left (EPIPE).
[[nodiscard]] std::optional<std::string> standard_output_failure(bool& broken_pipe) noexcept;

}  // namespace collide::app
