// Temporary names (a marker, the owner's pid, random letters), and the sweep of temporaries
// provably abandoned by a process that is gone (include/collide/io/file.hpp, docs/outputs.md).

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "file_internal.hpp"

namespace collide::io {
namespace fs = std::filesystem;
using namespace internal;  // the shared helpers of file_internal.hpp

namespace {

constexpr std::string_view marker = ".collide-";
constexpr std::size_t random_length = 6;

std::string random_suffix() {
    static constexpr std::string_view alphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    std::array<unsigned char, random_length> bytes{};
    ssize_t got = ::getrandom(bytes.data(), bytes.size(), 0);
    if (got != static_cast<ssize_t>(bytes.size())) {
        // getrandom cannot fail for 6 bytes once the pool is up; exclusivity does not depend on
        // randomness anyway (O_EXCL retries), only the number of attempts does.
        for (unsigned char& b : bytes) b = static_cast<unsigned char>(std::rand());
    }
    std::string suffix;
    for (const unsigned char b : bytes) suffix += alphabet[b % alphabet.size()];
    return suffix;
}

bool process_alive(pid_t pid) {
    return ::kill(pid, 0) == 0 || errno == EPERM;
}

/// Calls `visit(name)` for every entry of the open directory `fd` but "." and "..".
template <typename Visit>
void for_each_entry(int fd, Visit visit) {
    const int copy = ::dup(fd);
    if (copy < 0) return;
    DIR* listing = ::fdopendir(copy);
    if (listing == nullptr) {
        ::close(copy);
        return;
    }
    ::rewinddir(listing);
    while (const dirent* entry = ::readdir(listing)) {
        const std::string_view name = entry->d_name;
        if (name == "." || name == "..") continue;
        visit(std::string(name));
    }
    ::closedir(listing);
}

}  // namespace

namespace internal {

/// A fresh temporary name for `name` (the template with its XXXXXX filled in).
std::string fresh_temporary_name(std::string_view name) {
    std::string candidate = detail::temporary_template(name, ::getpid());
    candidate.replace(candidate.size() - random_length, random_length, random_suffix());
    return candidate;
}

void lock_exclusively(int fd) {
    // Cannot fail on a file we just created (nobody else knows it); a filesystem without locks
    // (some FUSE mounts) only loses the sweep's proof of life, and the sweep then keeps the file.
    (void)::flock(fd, LOCK_EX | LOCK_NB);
}

/// True when every entry of the open directory `fd` is a regular file satisfying `accept`;
/// the first other entry goes to `offender`.
bool holds_only(int fd, const OutputDirectory::NamePredicate& accept, std::string* offender) {
    bool only = true;
    for_each_entry(fd, [&](const std::string& name) {
        struct stat status {};
        const bool ok = ::fstatat(fd, name.c_str(), &status, AT_SYMLINK_NOFOLLOW) == 0 &&
                        S_ISREG(status.st_mode) && accept && accept(name);
        if (!ok && only && offender != nullptr) *offender = name;
        only = only && ok;
    });
    return only;
}

/// Removes the regular files in the open directory `fd` that satisfy `accept` (all regular files
/// when it is null), then the directory `name` itself from `parent` if it is now empty.
void remove_directory_files(int parent, const std::string& name, int fd,
                            const OutputDirectory::NamePredicate& accept) {
    std::vector<std::string> doomed;
    for_each_entry(fd, [&](const std::string& entry) {
        struct stat status {};
        if (::fstatat(fd, entry.c_str(), &status, AT_SYMLINK_NOFOLLOW) == 0 &&
            S_ISREG(status.st_mode) && (!accept || accept(entry))) {
            doomed.push_back(entry);
        }
    });
    for (const std::string& entry : doomed) ::unlinkat(fd, entry.c_str(), 0);
    ::unlinkat(parent, name.c_str(), AT_REMOVEDIR);  // fails, harmlessly, if anything else is left
}

/// The sweep (see the header): `directory` is an open directory.
std::size_t sweep(int directory, const OutputDirectory::NamePredicate& directory_entries) {
    std::vector<std::string> candidates;
    for_each_entry(directory, [&](const std::string& name) {
        const std::optional<pid_t> owner = detail::temporary_owner(name);
        if (owner && *owner != ::getpid() && !process_alive(*owner)) candidates.push_back(name);
    });
    std::size_t removed = 0;
    for (const std::string& name : candidates) {
        // Never open anything but plain files and directories (a device's open can act).
        struct stat kind {};
        if (::fstatat(directory, name.c_str(), &kind, AT_SYMLINK_NOFOLLOW) != 0 ||
            !(S_ISREG(kind.st_mode) || S_ISDIR(kind.st_mode))) {
            continue;
        }
        // Files are opened for writing: NFS emulates flock with POSIX locks, which need it.
        File file(::openat(directory, name.c_str(),
                           O_RDWR | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
        if (!file && errno == EISDIR) {
            file = File(
                ::openat(directory, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
        }
        struct stat status {};
        if (!file || ::fstat(file.get(), &status) != 0 || status.st_uid != ::geteuid()) continue;
        // A live writer anywhere (another host on NFS, another pid namespace) holds the lock.
        if (::flock(file.get(), LOCK_EX | LOCK_NB) != 0) continue;
        struct stat named {};
        if (::fstatat(directory, name.c_str(), &named, AT_SYMLINK_NOFOLLOW) != 0 ||
            !same_file(status, named)) {
            continue;
        }
        if (S_ISREG(status.st_mode)) {
            if (::unlinkat(directory, name.c_str(), 0) == 0) ++removed;
        } else if (S_ISDIR(status.st_mode) && directory_entries &&
                   holds_only(file.get(), directory_entries)) {
            remove_directory_files(directory, name, file.get(), directory_entries);
            struct stat after {};
            if (::fstatat(directory, name.c_str(), &after, AT_SYMLINK_NOFOLLOW) != 0) ++removed;
        }
    }
    return removed;
}

}  // namespace internal

// ------------------------------------------------------------------------------------------------
// detail

namespace detail {

std::string temporary_template(std::string_view name, pid_t pid, std::size_t name_max) {
    const std::string tail =
        std::string(marker) + std::to_string(pid) + "-" + std::string(random_length, 'X');
    const std::size_t room = name_max > tail.size() + 1 ? name_max - tail.size() - 1 : 0;
    std::size_t keep = std::min(name.size(), room);
    // Do not cut a UTF-8 character in two (continuation bytes are 10xxxxxx).
    while (keep > 0 && keep < name.size() &&
           (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80) {
        --keep;
    }
    return "." + std::string(name.substr(0, keep)) + tail;
}

std::optional<pid_t> temporary_owner(std::string_view name) {
    if (name.size() < 2 || name.front() != '.') return std::nullopt;
    const std::size_t at = name.rfind(marker);
    if (at == std::string_view::npos || at == 0) return std::nullopt;
    std::string_view rest = name.substr(at + marker.size());
    const std::size_t dash = rest.find('-');
    if (dash == 0 || dash == std::string_view::npos || dash > 10) return std::nullopt;
    const std::string_view digits = rest.substr(0, dash);
    const std::string_view random = rest.substr(dash + 1);
    if (random.size() != random_length) return std::nullopt;
    long long pid = 0;
    for (const char c : digits) {
        if (c < '0' || c > '9') return std::nullopt;
        pid = pid * 10 + (c - '0');
    }
    for (const char c : random) {
        const bool alnum =
            (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
        if (!alnum) return std::nullopt;
    }
    if (pid <= 0 || pid > 0x7fffffff) return std::nullopt;
    return static_cast<pid_t>(pid);
}

std::size_t sweep_stale_temporaries(const fs::path& directory,
                                    const OutputDirectory::NamePredicate& directory_entries) {
    const File fd(::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (!fd) return 0;
    return sweep(fd.get(), directory_entries);
}

}  // namespace detail

}  // namespace collide::io
