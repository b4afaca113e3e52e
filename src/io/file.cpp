// The one RAII file type, the run's record of its inputs, and OutputFile: an exclusive
// temporary beside the destination, committed atomically (include/collide/io/file.hpp,
// docs/outputs.md).

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
#include "file_internal.hpp"

namespace collide::io {
namespace fs = std::filesystem;
using namespace internal;  // the shared helpers of file_internal.hpp

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
}  // namespace

namespace internal {

bool stop_requested() noexcept {
    const std::atomic<bool>* flag = stop_flag.load();
    return flag != nullptr && flag->load();
}

std::atomic<std::uint64_t> committed_count{0};  ///< outputs_committed()

}  // namespace internal

void set_stop_flag(const std::atomic<bool>* flag) noexcept {
    stop_flag.store(flag);
}

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

namespace detail {

void forget_input_files() noexcept {
    const std::lock_guard lock(inputs_mutex);
    noted_inputs().clear();
}

}  // namespace detail

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

}  // namespace collide::io
