#include "standard_streams.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace collide::app {

void reserve_standard_descriptors() noexcept {
    for (const int descriptor : {STDIN_FILENO, STDOUT_FILENO, STDERR_FILENO}) {
        if (fcntl(descriptor, F_GETFD) != -1 || errno != EBADF) continue;
        // The lowest free descriptor is this one (the lower ones are open by now): standard
        // input gets a write-only placeholder, the two outputs read-only ones.
        // It stays across collide's exec of collide-draw (no O_CLOEXEC).
        const int placeholder =
            open("/dev/null", descriptor == STDIN_FILENO ? O_WRONLY : O_RDONLY);  // NOLINT
        if (placeholder < 0 || placeholder == descriptor) continue;
        dup2(placeholder, descriptor);
        close(placeholder);
    }
}

std::optional<std::string> standard_output_failure(bool& broken_pipe) noexcept {
    broken_pipe = false;
    errno = 0;
    int reason = 0;
    if (std::fflush(stdout) != 0) {
        reason = errno;
    } else if (std::ferror(stdout) != 0) {
        // The failure came with an earlier write whose errno is long gone: an empty write to the
        // descriptor tells again (EBADF for a closed one, ENOSPC for /dev/full).
        errno = 0;
        reason = ::write(STDOUT_FILENO, "", 0) < 0 ? errno : 0;
    } else {
        return std::nullopt;
    }
    broken_pipe = reason == EPIPE;
    std::string message = "cannot write to standard output";
    if (reason != 0) message += std::string(": ") + std::strerror(reason);
    return message;
}

}  // namespace collide::app
