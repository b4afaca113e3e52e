// OutputDirectory: a directory output (frames, a slide deck) built as a private temporary
// directory beside the destination and swapped in whole (include/collide/io/file.hpp,
// docs/outputs.md).

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

namespace internal {

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

}  // namespace internal

namespace {

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

}  // namespace collide::io
