#pragma once
/// \file
/// COLLIDE_ASSERT, the cheap check for programmer errors: a broken promise between collide's own
/// modules (a frame handed to a painter with 0 or 3 panels, an exchange of slots that do not
/// exist), never bad user input, which is an Error naming its field (error.hpp) whatever the
/// build. On in Debug and RelWithDebInfo builds (CMake defines COLLIDE_ASSERTS for them), off in
/// Release, where the condition is not even evaluated. A failed assertion prints where and what
/// to stderr and aborts: it is a bug to fix, not a message for the user. The heavy O(N)
/// validators (heaps, engines) sit behind the COLLIDE_VALIDATE build option instead.

#include <cstdio>
#include <cstdlib>

namespace collide {

/// True in builds where COLLIDE_ASSERT checks its condition (for tests of the assertions).
#if defined(COLLIDE_ASSERTS)
inline constexpr bool asserts_enabled = true;
#else
inline constexpr bool asserts_enabled = false;
#endif

namespace detail {

/// Reports a failed COLLIDE_ASSERT ("file:line: assertion failed: condition (why)") and aborts.
[[noreturn]] inline void assertion_failed(const char* condition, const char* why, const char* file,
                                          int line) noexcept {
    std::fprintf(stderr, "%s:%d: assertion failed: %s (%s)\n", file, line, condition, why);
    std::fflush(stderr);
    std::abort();
}

}  // namespace detail
}  // namespace collide

/// COLLIDE_ASSERT(condition, why): aborts with `why` (a string literal saying what the caller
/// broke) when `condition` is false, in builds with assertions on; see the file comment.
#if defined(COLLIDE_ASSERTS)
#define COLLIDE_ASSERT(condition, why) \
    ((condition) ? void(0)             \
                 : ::collide::detail::assertion_failed(#condition, why, __FILE__, __LINE__))
#else
#define COLLIDE_ASSERT(condition, why) ((void)sizeof(!(condition)))
#endif
