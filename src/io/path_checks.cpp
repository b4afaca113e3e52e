// The path rules every output shares (include/collide/io/file.hpp, docs/outputs.md): links
// followed as the kernel would (protected_symlinks), names checked, the parent opened, and the
// errors quoted the one way.

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

constexpr int max_symlink_hops = 40;  // Linux's own limit (ELOOP)

/// Creation failures that say something about the path the user gave (exit 2), as opposed to
/// the machine's state (a full disk, an I/O error: exit 1).
bool is_path_problem(int error) {
    return error != ENOSPC && error != EDQUOT && error != EIO && error != ENOMEM &&
           error != EMFILE && error != ENFILE;
}

}  // namespace

namespace internal {

std::string quote_path(const fs::path& path) {
    std::string text;
    text.reserve(path.native().size() + 2);
    text.append(1, '\'').append(path.native()).append(1, '\'');
    return text;
}

std::string errno_text(int error) {
    return std::strerror(error);
}

[[noreturn]] void throw_create_error(const std::string& what, int error) {
    if (is_path_problem(error)) throw_input_error(what + ": " + errno_text(error));
    throw_runtime_error(what + ": " + errno_text(error));
}

fs::path directory_of(const fs::path& path) {
    const fs::path parent = path.parent_path();
    return parent.empty() ? fs::path(".") : parent;
}

/// The process umask, read without changing it (umask(2) can only be read by setting it, which
/// races with other threads creating files). Linux >= 4.7 reports it in /proc; 022 otherwise.
mode_t current_umask() {
    const File status(::open("/proc/self/status", O_RDONLY | O_CLOEXEC));
    std::array<char, 4096> text{};
    const ssize_t size = status ? ::read(status.get(), text.data(), text.size() - 1) : -1;
    if (size <= 0) return 022;
    const char* line = std::strstr(text.data(), "\nUmask:");
    unsigned int mask = 022;
    if (line == nullptr || std::sscanf(line, "\nUmask: %o", &mask) != 1) return 022;
    return static_cast<mode_t>(mask);
}

bool proc_fd_available() {
    static const bool available = ::access("/proc/self/fd", X_OK) == 0;
    return available;
}

std::string proc_fd_path(int fd) {
    return "/proc/self/fd/" + std::to_string(fd);
}

/// The descriptor a name like /dev/stdout or /proc/self/fd/3 stands for, or -1. Such names are
/// the process's own open files: written through a duplicate (reopening the name would start a
/// redirected file over at offset 0, and renaming onto it is meaningless).
int standard_stream_fd(const fs::path& path) {
    const std::string& name = path.native();
    if (name == "-" || name == "/dev/stdout") return STDOUT_FILENO;
    if (name == "/dev/stderr") return STDERR_FILENO;
    for (const std::string_view prefix : {"/dev/fd/", "/proc/self/fd/"}) {
        if (name.rfind(prefix, 0) != 0 || name.size() == prefix.size()) continue;
        int fd = 0;
        for (const char c : name.substr(prefix.size())) {
            if (c < '0' || c > '9' || fd > 100000) return -1;
            fd = fd * 10 + (c - '0');
        }
        return fd;
    }
    return -1;
}

bool same_file(const struct stat& a, const struct stat& b) {
    return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

}  // namespace internal

namespace {

/// The kernel's protected_symlinks rule: in a sticky world-writable directory (/tmp), a link is
/// only followed when it belongs to us or to the directory's owner.
bool link_is_protected(const fs::path& link, const struct stat& link_status) {
    struct stat directory {};
    if (::stat(directory_of(link).c_str(), &directory) != 0) return false;
    const bool shared = (directory.st_mode & S_ISVTX) != 0 && (directory.st_mode & S_IWOTH) != 0;
    return shared && link_status.st_uid != ::geteuid() && link_status.st_uid != directory.st_uid;
}

/// Applies link_is_protected to every directory component of `path` that is a link (and to the
/// links their targets pass through), as the kernel's path walk does when protected_symlinks is
/// on: `/tmp/dirlink/notes.csv`, with `dirlink` another user's link to a directory, must not
/// let a run replace a file in that directory. Throws Error(input).
void check_directory_links(const fs::path& path, const fs::path& destination,
                           const std::string& label) {
    std::vector<fs::path> pending;  // components still to walk, the next one last
    // Puts the components of `p` before those still pending, its first to be walked next.
    const auto walk_first = [&pending](const fs::path& p) {
        const fs::path relative = p.relative_path();
        const std::vector<fs::path> parts(relative.begin(), relative.end());
        for (auto it = parts.rbegin(); it != parts.rend(); ++it) pending.push_back(*it);
    };
    const fs::path directory = directory_of(path);
    walk_first(directory);
    fs::path walked = directory.has_root_path() ? directory.root_path() : fs::path(".");
    for (int hops = 0; !pending.empty();) {
        const fs::path part = pending.back();
        pending.pop_back();
        if (part.empty() || part == ".") continue;
        const fs::path next = walked / part;
        struct stat status {};
        if (::lstat(next.c_str(), &status) != 0 || !S_ISLNK(status.st_mode) ||
            next.native().rfind("/proc/", 0) == 0) {
            walked = next;
            continue;
        }
        if (link_is_protected(next, status)) {
            throw_input_error(label + " " + quote_path(destination) +
                              ": refusing to follow the link " + quote_path(next) +
                              ", which another user owns in a shared (sticky) directory");
        }
        if (++hops > max_symlink_hops) return;  // a loop: open() reports it
        std::error_code error;
        const fs::path target = fs::read_symlink(next, error);
        if (error) return;
        if (target.is_absolute()) walked = target.root_path();
        // The target's components replace the link's, walked from the link's directory (or the
        // root), before the rest of the path.
        walk_first(target);
    }
}

}  // namespace

namespace internal {

/// `destination` with symbolic links followed to the file they name (which need not exist).
fs::path follow_links(const fs::path& destination, const std::string& label) {
    fs::path path = destination;
    for (int hop = 0; hop < max_symlink_hops; ++hop) {
        struct stat status {};
        if (::lstat(path.c_str(), &status) != 0 || !S_ISLNK(status.st_mode)) {
            check_directory_links(path, destination, label);
            return path;
        }
        // /proc's links (/dev/stdout leads there) are not paths; open() follows them itself.
        if (path.native().rfind("/proc/", 0) == 0) return path;
        if (link_is_protected(path, status)) {
            throw_input_error(label + " " + quote_path(destination) +
                              ": refusing to follow the link " + quote_path(path) +
                              ", which another user owns in a shared (sticky) directory");
        }
        std::error_code error;
        const fs::path target = fs::read_symlink(path, error);
        if (error) return path;
        path = target.is_absolute() ? target : directory_of(path) / target;
    }
    throw_input_error(label + " " + quote_path(destination) +
                      ": too many levels of symbolic links");
}

/// Opens the directory `path` lives in, with the checks and messages every output shares.
File open_parent(const fs::path& path, const fs::path& shown, const std::string& label) {
    const fs::path directory = directory_of(path);
    const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) return File(fd);
    const int error = errno;
    const std::string what = label + " " + quote_path(shown);
    if (error == ENOENT)
        throw_input_error(what + ": directory " + quote_path(directory) + " does not exist");
    if (error == ENOTDIR)
        throw_input_error(what + ": " + quote_path(directory) + " is not a directory");
    throw_create_error(what + ": cannot open its directory " + quote_path(directory), error);
}

/// A name the link `link` led to that names no file: its target ended in '/', '/.' or '/..'
/// (the destination's own spelling is checked before links are followed).
void check_link_target(const fs::path& destination, const fs::path& target,
                       const std::string& label) {
    if (target == destination) return;
    if (!target.has_filename() || target.filename() == "." || target.filename() == "..") {
        throw_input_error(label + " " + quote_path(destination) + ": its link leads to " +
                          quote_path(target) +
                          ", which names no file (it ends with '/', '.' or '..')");
    }
}

/// Refuses a name longer than the directory's filesystem allows (pathconf NAME_MAX), which
/// would otherwise only fail when the finished output is renamed onto it.
void check_name_length(int directory, const std::string& name, const fs::path& shown,
                       const std::string& label) {
    errno = 0;
    const long limit = ::fpathconf(directory, _PC_NAME_MAX);
    if (limit <= 0 || name.size() <= static_cast<std::size_t>(limit)) return;
    throw_input_error(label + " " + quote_path(shown) + ": its name is " +
                      std::to_string(name.size()) + " bytes long; this filesystem allows " +
                      std::to_string(limit) + " (a shorter name)");
}

/// True when `name` in `directory` is the root of a mount (a bind mount of a file or directory
/// included, even on the same filesystem): the kernel refuses to rename anything onto it.
bool is_mount_root(int directory, const std::string& name) {
    struct statx status {};
    if (::statx(directory, name.c_str(), AT_SYMLINK_NOFOLLOW, STATX_BASIC_STATS, &status) != 0)
        return false;
    if ((status.stx_attributes_mask & STATX_ATTR_MOUNT_ROOT) != 0)
        return (status.stx_attributes & STATX_ATTR_MOUNT_ROOT) != 0;
    // Kernels before 5.8: a different device than the directory's.
    struct stat above {};
    return ::fstat(directory, &above) == 0 && (status.stx_dev_major != major(above.st_dev) ||
                                               status.stx_dev_minor != minor(above.st_dev));
}

[[noreturn]] void throw_mount_point(const fs::path& shown, const std::string& label) {
    throw_input_error(label + " " + quote_path(shown) +
                      " is a mount point (a bind mount?): an output is put in place by renaming "
                      "onto it, which the system refuses for a mount point; give another path");
}

}  // namespace internal

std::string file_type_name(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

}  // namespace collide::io
