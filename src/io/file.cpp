// The safe-output rules (include/collide/io/file.hpp, docs/outputs.md): exclusive temporaries
// beside the destination, atomic commit, and the sweep of provably abandoned temporaries.

#include "collide/io/file.hpp"

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

namespace collide::io {
namespace fs = std::filesystem;

namespace {

constexpr std::string_view marker = ".collide-";
constexpr std::size_t random_length = 6;
constexpr int max_symlink_hops = 40;  // Linux's own limit (ELOOP)
constexpr int max_name_attempts = 100;

std::string quote_path(const fs::path& path) {
    std::string text;
    text.reserve(path.native().size() + 2);
    text.append(1, '\'').append(path.native()).append(1, '\'');
    return text;
}

std::string errno_text(int error) {
    return std::strerror(error);
}

/// Creation failures that say something about the path the user gave (exit 2), as opposed to
/// the machine's state (a full disk, an I/O error: exit 1).
bool is_path_problem(int error) {
    return error != ENOSPC && error != EDQUOT && error != EIO && error != ENOMEM &&
           error != EMFILE && error != ENFILE;
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

/// A fresh temporary name for `name` (the template with its XXXXXX filled in).
std::string fresh_temporary_name(std::string_view name) {
    std::string candidate = detail::temporary_template(name, ::getpid());
    candidate.replace(candidate.size() - random_length, random_length, random_suffix());
    return candidate;
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

bool process_alive(pid_t pid) {
    return ::kill(pid, 0) == 0 || errno == EPERM;
}

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

void lock_exclusively(int fd) {
    // Cannot fail on a file we just created (nobody else knows it); a filesystem without locks
    // (some FUSE mounts) only loses the sweep's proof of life, and the sweep then keeps the file.
    (void)::flock(fd, LOCK_EX | LOCK_NB);
}

bool same_file(const struct stat& a, const struct stat& b) {
    return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
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

/// True when every entry of the open directory `fd` is a regular file satisfying `accept`;
/// the first other entry goes to `offender`.
bool holds_only(int fd, const OutputDirectory::NamePredicate& accept,
                std::string* offender = nullptr) {
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

}  // namespace

// ------------------------------------------------------------------------------------------------
// File

File::~File() {
    if (fd_ >= 0) ::close(fd_);
}

File::File(File&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}

File& File::operator=(File&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0) ::close(fd_);
        fd_ = std::exchange(other.fd_, -1);
    }
    return *this;
}

namespace {
/// The registered stop request (set_stop_flag): signal handlers can only reach static storage.
std::atomic<const std::atomic<bool>*> stop_flag{nullptr};

bool stop_requested() noexcept {
    const std::atomic<bool>* flag = stop_flag.load();
    return flag != nullptr && flag->load();
}
}  // namespace

void set_stop_flag(const std::atomic<bool>* flag) noexcept {
    stop_flag.store(flag);
}

namespace {
std::atomic<std::uint64_t> committed_count{0};  ///< outputs_committed()
}  // namespace

std::uint64_t outputs_committed() noexcept {
    return committed_count.load();
}

void File::write_all(const void* data, std::size_t size, const fs::path& shown) const {
    const auto* bytes = static_cast<const char*>(data);
    while (size > 0) {
        // Checked before every write, and again after a write a signal interrupted: a reader
        // that never reads would otherwise keep this loop (and the process) waiting forever.
        if (stop_requested())
            throw_runtime_error("cannot write " + quote_path(shown) + ": interrupted");
        const ssize_t written = ::write(fd_, bytes, size);
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) {
            throw_runtime_error("cannot write " + quote_path(shown) + ": " +
                                errno_text(written < 0 ? errno : ENOSPC));
        }
        bytes += written;
        size -= static_cast<std::size_t>(written);
    }
}

void File::close(const fs::path& shown) {
    const int fd = std::exchange(fd_, -1);
    if (fd >= 0 && ::close(fd) != 0 && errno != EINTR) {
        const int error = errno;
        throw_runtime_error("cannot write " + quote_path(shown) + ": " + errno_text(error));
    }
}

// ------------------------------------------------------------------------------------------------
// The run's inputs

namespace {

struct NotedInput {
    dev_t device = 0;
    ino_t inode = 0;
    fs::path path;
    /// The file kept open, so that its inode cannot be freed and given to another file while it
    /// is recorded (a deleted input's number would otherwise refuse an unrelated output).
    File pin;
};

std::mutex inputs_mutex;

std::vector<NotedInput>& noted_inputs() {
    static std::vector<NotedInput> inputs;  // a process-wide record (see note_input_file)
    return inputs;
}

/// Refuses the regular file `status` (the destination of `what`) when the run read it.
void refuse_input(const struct stat& status, const std::string& what) {
    if (!S_ISREG(status.st_mode)) return;
    const std::lock_guard lock(inputs_mutex);
    for (const NotedInput& input : noted_inputs()) {
        if (input.device == status.st_dev && input.inode == status.st_ino) {
            throw_input_error(what + " is " + quote_path(input.path) +
                              ", which this run reads: an output never replaces one of its "
                              "inputs; give it another path");
        }
    }
}

}  // namespace

void note_input_file(int fd, const fs::path& path) {
    struct stat status {};
    if (::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode)) return;
    const std::lock_guard lock(inputs_mutex);
    for (const NotedInput& input : noted_inputs()) {
        if (input.device == status.st_dev && input.inode == status.st_ino) return;
    }
    // Without a descriptor to spare (EMFILE) the input is still recorded, only not pinned.
    noted_inputs().push_back(
        {status.st_dev, status.st_ino, path, File(::fcntl(fd, F_DUPFD_CLOEXEC, 3))});
}

// ------------------------------------------------------------------------------------------------
// OutputFile

OutputFile::OutputFile(const fs::path& destination, OutputOptions options)
    : destination_(destination), label_(std::move(options.label)) {
    const std::string what = label_ + " " + quote_path(destination);
    if (destination.empty()) throw_input_error(label_ + ": the path is empty");
    if (const int stream = standard_stream_fd(destination); stream >= 0) {
        if (!options.allow_stream) {
            throw_input_error(what + " is one of this process's open streams; give a file name");
        }
        file_ = File(::fcntl(stream, F_DUPFD_CLOEXEC, 3));
        const int error = errno;
        if (!file_) throw_input_error(what + ": " + errno_text(error));
        // Standard output redirected into an input (`>> scene.toml`) would write into it.
        struct stat status {};
        if (::fstat(file_.get(), &status) == 0) refuse_input(status, what);
        stream_ = active_ = true;
        return;
    }
    if (!destination.has_filename() || destination.filename() == "." ||
        destination.filename() == "..") {
        throw_input_error(what + " names no file (it ends with '/', '.' or '..')");
    }
    const fs::path target = follow_links(destination, label_);
    check_link_target(destination, target, label_);
    directory_ = open_parent(target, destination, label_);
    target_name_ = target.filename().native();
    check_name_length(directory_.get(), target_name_, destination, label_);

    struct stat existing {};
    if (::fstatat(directory_.get(), target_name_.c_str(), &existing, AT_SYMLINK_NOFOLLOW) == 0) {
        if (S_ISDIR(existing.st_mode)) throw_input_error(what + " is an existing directory");
        refuse_input(existing, what);
        if (S_ISREG(existing.st_mode) && is_mount_root(directory_.get(), target_name_))
            throw_mount_point(destination, label_);
        if (!S_ISREG(existing.st_mode)) {
            if (!options.allow_stream) {
                throw_input_error(what + " is not a regular file (a device, FIFO or socket)");
            }
            // O_NONBLOCK: a FIFO nobody reads fails (ENXIO) instead of blocking forever.
            file_ = File(::openat(directory_.get(), target_name_.c_str(),
                                  O_WRONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
            if (!file_) {
                const int error = errno;
                throw_create_error(what + (error == ENXIO ? ": nobody reads this FIFO" : ""),
                                   error);
            }
            ::fcntl(file_.get(), F_SETFL, ::fcntl(file_.get(), F_GETFL) & ~O_NONBLOCK);
            stream_ = active_ = true;
            return;
        }
    }

    sweep(directory_.get(), options.stale_directory_entries);
    create_temporary(options.unnamed_temporary,
                     what + ": cannot create a file in " + quote_path(directory_of(target)));
    lock_exclusively(file_.get());
    active_ = true;
}

void OutputFile::create_temporary(bool unnamed, const std::string& what) {
    if (unnamed && proc_fd_available()) {
        file_ = File(::openat(directory_.get(), ".", O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666));
        const int error = errno;
        // Filesystems without O_TMPFILE say so in several ways; those get a named temporary.
        if (file_) return;
        if (error != EOPNOTSUPP && error != EISDIR && error != EINVAL && error != ENOENT) {
            throw_create_error(what, error);
        }
    }
    for (int attempt = 0; attempt < max_name_attempts; ++attempt) {
        temporary_name_ = fresh_temporary_name(target_name_);
        file_ = File(::openat(directory_.get(), temporary_name_.c_str(),
                              O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600));
        if (file_) return;
        const int error = errno;
        temporary_name_.clear();
        if (error != EEXIST) throw_create_error(what, error);
    }
    throw_runtime_error(what + ": no free temporary name");
}

OutputFile::~OutputFile() {
    discard();
}

OutputFile::OutputFile(OutputFile&& other) noexcept
    : destination_(std::move(other.destination_)),
      label_(std::move(other.label_)),
      directory_(std::move(other.directory_)),
      target_name_(std::move(other.target_name_)),
      file_(std::move(other.file_)),
      temporary_name_(std::move(other.temporary_name_)),
      stream_(other.stream_),
      active_(std::exchange(other.active_, false)),
      prepared_(std::exchange(other.prepared_, false)) {}

OutputFile& OutputFile::operator=(OutputFile&& other) noexcept {
    if (this != &other) {
        discard();
        destination_ = std::move(other.destination_);
        label_ = std::move(other.label_);
        directory_ = std::move(other.directory_);
        target_name_ = std::move(other.target_name_);
        file_ = std::move(other.file_);
        temporary_name_ = std::move(other.temporary_name_);
        stream_ = other.stream_;
        active_ = std::exchange(other.active_, false);
        prepared_ = std::exchange(other.prepared_, false);
    }
    return *this;
}

bool OutputFile::is_standard_output() const noexcept {
    if (!stream_ || !file_) return false;
    struct stat mine {};
    struct stat out {};
    return ::fstat(file_.get(), &mine) == 0 && ::fstat(STDOUT_FILENO, &out) == 0 &&
           mine.st_dev == out.st_dev && mine.st_ino == out.st_ino;
}

fs::path OutputFile::reopen_path() const {
    if (proc_fd_available() || temporary_name_.empty()) return proc_fd_path(file_.get());
    return directory_of(follow_links(destination_, label_)) / temporary_name_;
}

void OutputFile::write(const void* data, std::size_t size) const {
    if (!active_) throw_runtime_error(label_ + " " + quote_path(destination_) + ": not open");
    file_.write_all(data, size, destination_);
}

void OutputFile::prepare_commit() {
    const std::string what = label_ + " " + quote_path(destination_);
    if (!active_) throw_runtime_error(what + ": nothing to commit");
    if (stream_ || prepared_) return;
    if (::fsync(file_.get()) != 0) {
        const int error = errno;  // NFS and full disks report delayed write errors here
        throw_runtime_error("cannot write " + quote_path(destination_) + ": " + errno_text(error));
    }
    // The finished file gets the replaced file's permissions, or those of an ordinary creation.
    struct stat old {};
    const bool replacing =
        ::fstatat(directory_.get(), target_name_.c_str(), &old, AT_SYMLINK_NOFOLLOW) == 0 &&
        S_ISREG(old.st_mode);
    if (replacing) refuse_input(old, what);  // an input read after the output was created
    ::fchmod(file_.get(), replacing ? (old.st_mode & 0777) : (0666 & ~current_umask()));
    if (temporary_name_.empty()) {
        // An O_TMPFILE gets a (temporary, exclusive) name first: linkat cannot replace a file.
        const std::string source = proc_fd_path(file_.get());
        for (int attempt = 0; attempt < max_name_attempts && temporary_name_.empty(); ++attempt) {
            const std::string name = fresh_temporary_name(target_name_);
            if (::linkat(AT_FDCWD, source.c_str(), directory_.get(), name.c_str(),
                         AT_SYMLINK_FOLLOW) == 0) {
                temporary_name_ = name;
            } else if (errno != EEXIST) {
                const int error = errno;
                throw_runtime_error("cannot put " + quote_path(destination_) +
                                    " in place: " + errno_text(error));
            }
        }
        if (temporary_name_.empty()) throw_runtime_error(what + ": no free temporary name");
    }
    prepared_ = true;
}

void OutputFile::commit() {
    const std::string what = label_ + " " + quote_path(destination_);
    if (!active_) throw_runtime_error(what + ": nothing to commit");
    if (stream_) {
        active_ = false;
        file_.close(destination_);
        return;
    }
    prepare_commit();
    if (::renameat(directory_.get(), temporary_name_.c_str(), directory_.get(),
                   target_name_.c_str()) != 0) {
        const int error = errno;
        throw_runtime_error("cannot put " + quote_path(destination_) +
                            " in place: " + errno_text(error));
    }
    committed_count.fetch_add(1);
    temporary_name_.clear();
    active_ = false;
    prepared_ = false;
    file_.close(destination_);
}

void OutputFile::discard() noexcept {
    if (!active_) return;
    active_ = false;
    prepared_ = false;
    if (!temporary_name_.empty()) {
        // Only our own file: a name that now holds something else stays.
        struct stat ours {};
        struct stat named {};
        if (::fstat(file_.get(), &ours) == 0 &&
            ::fstatat(directory_.get(), temporary_name_.c_str(), &named, AT_SYMLINK_NOFOLLOW) ==
                0 &&
            same_file(ours, named)) {
            ::unlinkat(directory_.get(), temporary_name_.c_str(), 0);
        }
        temporary_name_.clear();
    }
    file_ = File();
}

// ------------------------------------------------------------------------------------------------
// OutputDirectory

namespace {

/// The destination of a directory output with trailing '/' removed, refused if it names "."
/// or ".." (which would be the current directory or its parent).
fs::path directory_destination(const fs::path& destination, const std::string& label) {
    fs::path path = destination;
    while (!path.empty() && !path.has_filename() && path != path.root_path()) {
        path = path.parent_path();
    }
    const std::string what = label + " " + quote_path(destination);
    if (path.empty()) throw_input_error(label + ": the path is empty");
    if (path == path.root_path() || path.filename() == "." || path.filename() == "..") {
        throw_input_error(what +
                          ": a directory output is written as a new directory of its own; give "
                          "it a name (e.g. frames), not '.', '..' or '/'");
    }
    return path;
}

/// True when `directory` is the current directory or one of its ancestors.
bool contains_working_directory(const fs::path& directory) {
    std::error_code error;
    const fs::path here = fs::current_path(error);
    const fs::path there = fs::canonical(directory, error);
    if (error) return false;
    for (fs::path p = here; !p.empty(); p = p.parent_path()) {
        if (fs::equivalent(p, there, error)) return true;
        if (p == p.root_path()) break;
    }
    return false;
}

/// Checks an existing destination directory (open as `fd`, named `path`) by the class's rules.
void check_replaceable(int parent, int fd, const fs::path& path, const fs::path& shown,
                       const OutputDirectory::NamePredicate& replaceable,
                       const std::string& label) {
    const std::string what = label + " " + quote_path(shown);
    struct stat status {};
    struct stat above {};
    if ((::fstat(fd, &status) == 0 && ::fstat(parent, &above) == 0 &&
         status.st_dev != above.st_dev) ||
        is_mount_root(parent, path.filename().native())) {
        throw_input_error(what +
                          " is a mount point; a directory output replaces its "
                          "directory, so give a new directory inside it");
    }
    if (contains_working_directory(path)) {
        throw_input_error(what +
                          " is the current directory or one of its parents; give a new "
                          "directory for the output (e.g. frames)");
    }
    std::string offender;
    if (!holds_only(fd, replaceable, &offender)) {
        throw_input_error(what + " holds other files (" + quote_path(offender) +
                          "): a directory output replaces the whole directory, so it must be "
                          "new, empty, or hold only an earlier output of the same kind; give a "
                          "new directory, e.g. " +
                          quote_path(shown / "frames"));
    }
}

}  // namespace

OutputDirectory::OutputDirectory(const fs::path& destination, NamePredicate replaceable,
                                 std::string label, const NamePredicate& stale_entries)
    : destination_(destination), label_(std::move(label)), replaceable_(std::move(replaceable)) {
    const fs::path named = directory_destination(destination, label_);
    const fs::path target = directory_destination(follow_links(named, label_), label_);
    parent_ = open_parent(target, destination, label_);
    target_name_ = target.filename().native();
    check_name_length(parent_.get(), target_name_, destination, label_);
    const std::string what = label_ + " " + quote_path(destination);

    struct stat existing {};
    if (::fstatat(parent_.get(), target_name_.c_str(), &existing, AT_SYMLINK_NOFOLLOW) == 0) {
        if (!S_ISDIR(existing.st_mode)) throw_input_error(what + " exists and is not a directory");
        const File old(::openat(parent_.get(), target_name_.c_str(),
                                O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
        const int error = errno;
        if (!old) throw_create_error(what, error);
        check_replaceable(parent_.get(), old.get(), target, destination, replaceable_, label_);
    }

    sweep(parent_.get(), stale_entries ? stale_entries : replaceable_);
    for (int attempt = 0; attempt < max_name_attempts && !temporary_; ++attempt) {
        temporary_name_ = fresh_temporary_name(target_name_);
        if (::mkdirat(parent_.get(), temporary_name_.c_str(), 0700) != 0) {
            if (errno == EEXIST) continue;
            const int error = errno;
            throw_create_error(
                what + ": cannot create a directory in " + quote_path(directory_of(target)), error);
        }
        temporary_ = File(::openat(parent_.get(), temporary_name_.c_str(),
                                   O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
        if (!temporary_) {
            const int error = errno;
            ::unlinkat(parent_.get(), temporary_name_.c_str(), AT_REMOVEDIR);
            throw_create_error(what + ": cannot open the temporary directory", error);
        }
    }
    if (!temporary_) throw_runtime_error(what + ": no free temporary name");
    lock_exclusively(temporary_.get());
    active_ = true;
}

OutputDirectory::~OutputDirectory() {
    discard();
}

OutputDirectory::OutputDirectory(OutputDirectory&& other) noexcept
    : destination_(std::move(other.destination_)),
      label_(std::move(other.label_)),
      replaceable_(std::move(other.replaceable_)),
      parent_(std::move(other.parent_)),
      target_name_(std::move(other.target_name_)),
      temporary_(std::move(other.temporary_)),
      temporary_name_(std::move(other.temporary_name_)),
      active_(std::exchange(other.active_, false)) {}

OutputDirectory& OutputDirectory::operator=(OutputDirectory&& other) noexcept {
    if (this != &other) {
        discard();
        destination_ = std::move(other.destination_);
        label_ = std::move(other.label_);
        replaceable_ = std::move(other.replaceable_);
        parent_ = std::move(other.parent_);
        target_name_ = std::move(other.target_name_);
        temporary_ = std::move(other.temporary_);
        temporary_name_ = std::move(other.temporary_name_);
        active_ = std::exchange(other.active_, false);
    }
    return *this;
}

File OutputDirectory::create_file(const std::string& name) const {
    File file(::openat(temporary_.get(), name.c_str(),
                       O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666));
    if (!file) {
        const int error = errno;
        throw_runtime_error("cannot write " + quote_path(destination_ / name) + ": " +
                            errno_text(error));
    }
    return file;
}

void OutputDirectory::prepare_commit() {
    const std::string what = label_ + " " + quote_path(destination_);
    if (!active_) throw_runtime_error(what + ": nothing to commit");
    struct stat old {};
    const bool exists =
        ::fstatat(parent_.get(), target_name_.c_str(), &old, AT_SYMLINK_NOFOLLOW) == 0;
    ::fchmod(temporary_.get(),
             exists && S_ISDIR(old.st_mode) ? (old.st_mode & 07777) : (0777 & ~current_umask()));
    if (!exists) return;
    // Checked again: the destination may have changed while the frames were rendered.
    const File current(::openat(parent_.get(), target_name_.c_str(),
                                O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
    std::string offender;
    if (!current || !holds_only(current.get(), replaceable_, &offender)) {
        throw_runtime_error(what + " changed while the frames were written (it now holds " +
                            quote_path(offender) + "); left as it is");
    }
}

void OutputDirectory::commit() {
    prepare_commit();
    std::string replaced;  // where the old destination ends up, emptied below
    struct stat old {};
    const bool exists =
        ::fstatat(parent_.get(), target_name_.c_str(), &old, AT_SYMLINK_NOFOLLOW) == 0;
    if (exists) {
        if (::renameat2(parent_.get(), temporary_name_.c_str(), parent_.get(), target_name_.c_str(),
                        RENAME_EXCHANGE) == 0) {
            replaced = temporary_name_;
        } else if (errno == EINVAL || errno == ENOSYS) {
            // No atomic exchange here: move the old one aside (onto a fresh empty directory of
            // ours), then the new one in; put the old one back if that fails.
            std::string aside = fresh_temporary_name(target_name_);
            if (::mkdirat(parent_.get(), aside.c_str(), 0700) != 0 ||
                ::renameat(parent_.get(), target_name_.c_str(), parent_.get(), aside.c_str()) !=
                    0) {
                const int error = errno;
                ::unlinkat(parent_.get(), aside.c_str(), AT_REMOVEDIR);
                throw_runtime_error("cannot replace " + quote_path(destination_) + ": " +
                                    errno_text(error));
            }
            if (::renameat(parent_.get(), temporary_name_.c_str(), parent_.get(),
                           target_name_.c_str()) != 0) {
                const int error = errno;
                ::renameat(parent_.get(), aside.c_str(), parent_.get(), target_name_.c_str());
                throw_runtime_error("cannot replace " + quote_path(destination_) + ": " +
                                    errno_text(error));
            }
            replaced = aside;
        } else {
            const int error = errno;
            throw_runtime_error("cannot replace " + quote_path(destination_) + ": " +
                                errno_text(error));
        }
    } else if (::renameat(parent_.get(), temporary_name_.c_str(), parent_.get(),
                          target_name_.c_str()) != 0) {
        const int error = errno;
        throw_runtime_error("cannot put " + quote_path(destination_) +
                            " in place: " + errno_text(error));
    }
    committed_count.fetch_add(1);
    active_ = false;
    temporary_ = File();
    temporary_name_.clear();
    if (!replaced.empty()) {
        // The old sequence: only the files the rules allowed replacing go (nothing else was
        // there a moment ago; anything that appeared since keeps the directory).
        const File old_directory(::openat(parent_.get(), replaced.c_str(),
                                          O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
        if (old_directory) {
            remove_directory_files(parent_.get(), replaced, old_directory.get(), replaceable_);
        }
    }
}

void OutputDirectory::discard() noexcept {
    if (!active_) return;
    active_ = false;
    // Our own private (0700) directory: every regular file in it is a frame we wrote.
    remove_directory_files(parent_.get(), temporary_name_, temporary_.get(), {});
    temporary_ = File();
    temporary_name_.clear();
}

void check_output_directory(const fs::path& destination,
                            const OutputDirectory::NamePredicate& replaceable,
                            const std::string& label) {
    OutputDirectory probe(destination, replaceable, label);
    probe.discard();
}

namespace {

/// What an output path stands for, to compare two outputs of a run: an open stream's file, an
/// existing file's identity, or (not yet existing) its path with every link resolved.
struct OutputIdentity {
    bool exists = false;
    dev_t device = 0;
    ino_t inode = 0;
    fs::path resolved;
};

OutputIdentity identity_of(const NamedOutput& output) {
    OutputIdentity id;
    struct stat status {};
    if (const int stream = standard_stream_fd(output.path); stream >= 0) {
        if (::fstat(stream, &status) == 0) {
            id.exists = true;
            id.device = status.st_dev;
            id.inode = status.st_ino;
        }
        return id;
    }
    fs::path path = follow_links(output.path, output.label);
    if (output.directory) path = directory_destination(path, output.label);
    std::error_code error;
    id.resolved = fs::weakly_canonical(fs::absolute(path, error), error);
    if (error) id.resolved = fs::absolute(path).lexically_normal();
    if (::stat(path.c_str(), &status) == 0) {
        id.exists = true;
        id.device = status.st_dev;
        id.inode = status.st_ino;
    }
    return id;
}

bool same_output(const OutputIdentity& a, const OutputIdentity& b) {
    if (a.exists && b.exists) return a.device == b.device && a.inode == b.inode;
    return !a.resolved.empty() && a.resolved == b.resolved;
}

/// True when `inner` lies inside the directory `outer` (both resolved).
bool lies_inside(const fs::path& inner, const fs::path& outer) {
    if (inner.empty() || outer.empty()) return false;
    const fs::path relative = inner.lexically_relative(outer);
    return !relative.empty() && *relative.begin() != ".." && relative != ".";
}

}  // namespace

void check_distinct_outputs(const std::vector<NamedOutput>& outputs) {
    std::vector<OutputIdentity> ids;
    ids.reserve(outputs.size());
    for (const NamedOutput& output : outputs) ids.push_back(identity_of(output));
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        for (std::size_t j = i + 1; j < outputs.size(); ++j) {
            const NamedOutput& a = outputs[i];
            const NamedOutput& b = outputs[j];
            if (same_output(ids[i], ids[j])) {
                throw_input_error(b.label + " " + quote_path(b.path) + " is the same file as " +
                                  a.label + " " + quote_path(a.path) +
                                  ": each output of a run needs a file of its own");
            }
            const auto inside = [&](const NamedOutput& dir, const OutputIdentity& dir_id,
                                    const NamedOutput& file, const OutputIdentity& file_id) {
                if (!dir.directory || !lies_inside(file_id.resolved, dir_id.resolved)) return;
                throw_input_error(file.label + " " + quote_path(file.path) + " lies inside " +
                                  dir.label + " " + quote_path(dir.path) +
                                  ", which is replaced as a whole; give it a path outside");
            };
            inside(a, ids[i], b, ids[j]);
            inside(b, ids[j], a, ids[i]);
        }
    }
}

void check_outputs_not_inputs(const std::vector<NamedOutput>& outputs,
                              const std::vector<NamedInput>& inputs) {
    for (const NamedOutput& output : outputs) {
        const OutputIdentity out = identity_of(output);
        for (const NamedInput& input : inputs) {
            if (!same_output(out, identity_of({input.label, input.path, false}))) continue;
            throw_input_error(output.label + " " + quote_path(output.path) + " is " + input.label +
                              " " + quote_path(input.path) +
                              ", which this run reads: an output never replaces one of its "
                              "inputs; give it another path");
        }
    }
}

// ------------------------------------------------------------------------------------------------
// CommitGroup

void CommitGroup::add(OutputFile* file) {
    if (file == nullptr) return;
    add([file] { file->prepare_commit(); }, [file] { file->commit(); });
}

void CommitGroup::add(OutputDirectory* directory) {
    if (directory == nullptr) return;
    add([directory] { directory->prepare_commit(); }, [directory] { directory->commit(); });
}

void CommitGroup::add(std::function<void()> prepare, std::function<void()> rename) {
    steps_.push_back({std::move(prepare), std::move(rename)});
}

void CommitGroup::commit() {
    for (const Step& step : steps_) step.prepare();
    // The last moment a stop leaves every destination as it was; the renames then take
    // microseconds, and stopping among them would leave some outputs old and some new.
    if (stop_requested()) throw_runtime_error("interrupted before the outputs were put in place");
    for (const Step& step : steps_) step.rename();
    steps_.clear();
}

File open_scratch_file(const fs::path& directory) {
    File file(::open(directory.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600));
    if (file) return file;
    std::string name = (directory / ".collide-scratch.XXXXXX").native();
    file = File(::mkostemp(name.data(), O_CLOEXEC));
    if (!file) {
        const int error = errno;
        throw_runtime_error("cannot create a scratch file in " + quote_path(directory) + ": " +
                            errno_text(error));
    }
    ::unlink(name.c_str());  // unnamed from now on: the kernel frees it when the file closes
    return file;
}

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

void forget_input_files() noexcept {
    const std::lock_guard lock(inputs_mutex);
    noted_inputs().clear();
}

std::size_t sweep_stale_temporaries(const fs::path& directory,
                                    const OutputDirectory::NamePredicate& directory_entries) {
    const File fd(::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (!fd) return 0;
    return sweep(fd.get(), directory_entries);
}

}  // namespace detail

}  // namespace collide::io
