// Reading a scene file whole, safely: open without blocking (a FIFO would wait for a writer
// forever), then check what was opened (fstat on the descriptor: no race with a stat before
// open), refuse anything but a regular file, and read no more than max_scene_file_bytes.

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "collide/scene/load.hpp"
#include "collide/sim/algs4.hpp"

namespace collide {

namespace {

/// Owns a file descriptor; closes it on every way out.
class FileDescriptor {
  public:
    explicit FileDescriptor(int fd) noexcept : fd_(fd) {}
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    [[nodiscard]] int get() const noexcept { return fd_; }

  private:
    int fd_;
};

std::string mebibytes(std::uintmax_t bytes) {
    return std::to_string(bytes >> 20) + " MiB";
}

[[noreturn]] void too_large(const std::string& name) {
    throw_scene_error(name, 0, "",
                      "larger than " + mebibytes(max_scene_file_bytes) +
                          ", the most a scene file may have (docs/scenes.md, \"Limits\")");
}

}  // namespace

std::string read_scene_file(const std::filesystem::path& path) {
    const std::string name = path.string();
    // O_NONBLOCK: opening a FIFO returns at once instead of waiting for a writer.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        throw_scene_error(name, 0, "",
                          "cannot open the scene file: " +
                              std::error_code(errno, std::generic_category()).message());
    }
    const FileDescriptor file(fd);
    struct stat info {};
    if (::fstat(file.get(), &info) != 0) {
        throw_runtime_error(name + ": cannot read the file's status: " +
                            std::error_code(errno, std::generic_category()).message());
    }
    if (!S_ISREG(info.st_mode)) {
        throw_scene_error(name, 0, "",
                          io::file_type_name(info.st_mode) +
                              ", not a regular file: scenes are read from "
                              "regular files only");
    }
    // No output of this run may replace it (`--layout-json scene.toml`, an included file).
    io::note_input_file(file.get(), path);
    const auto size = static_cast<std::uintmax_t>(info.st_size);
    if (size > max_scene_file_bytes) too_large(name);
    // Read to the end rather than `size` bytes (the file may change meanwhile), but never beyond
    // the cap.
    std::string text(static_cast<std::size_t>(size) + 1, '\0');
    std::size_t used = 0;
    for (;;) {
        if (used == text.size()) {
            if (used > max_scene_file_bytes) too_large(name);
            text.resize(std::min<std::size_t>(2 * used + 4096, max_scene_file_bytes + 1));
        }
        const ssize_t got = ::read(file.get(), text.data() + used, text.size() - used);
        if (got < 0) {
            if (errno == EINTR) continue;
            throw_scene_error(
                name, 0, "",
                "read error: " + std::error_code(errno, std::generic_category()).message());
        }
        if (got == 0) break;
        used += static_cast<std::size_t>(got);
    }
    if (used > max_scene_file_bytes) too_large(name);
    text.resize(used);
    return text;
}

}  // namespace collide
