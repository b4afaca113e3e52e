#pragma once
/// \file
/// Output-path safety shared by every writer: the checks the app runs before rendering anything,
/// and the temporary-file-then-rename discipline that keeps a destination whole.

#include <filesystem>
#include <string>

namespace collide::video {

/// Checks, before any frame is rendered, that `path` can be written: its directory (the current
/// directory when `path` has none) exists, is a directory, and a file can actually be created in
/// it (probed with a temporary file that is removed again; permission bits alone lie for root and
/// read-only mounts), and `path` itself is not an existing directory (unless `directory_output`:
/// PNG sequences write a directory). Throws Error(input) naming the path and the reason.
void check_output_writable(const std::filesystem::path& path, bool directory_output = false);

/// A uniquely named temporary file or directory created beside a destination, removed by the
/// destructor unless `commit()` renamed it onto the destination. Move-only.
/// Beside, not in /tmp: rename(2) is only atomic within one filesystem.
class TemporaryOutput {
  public:
    enum class Kind { file, directory };

    /// An empty placeholder owning nothing (assign a real one later).
    TemporaryOutput() = default;
    /// Creates a hidden `.<name>.XXXXXX` temporary next to `destination`.
    /// Throws Error(input) naming `destination` if it cannot be created there.
    TemporaryOutput(const std::filesystem::path& destination, Kind kind);
    ~TemporaryOutput();
    TemporaryOutput(TemporaryOutput&& other) noexcept;
    TemporaryOutput& operator=(TemporaryOutput&& other) noexcept;
    TemporaryOutput(const TemporaryOutput&) = delete;
    TemporaryOutput& operator=(const TemporaryOutput&) = delete;

    /// Where to write (the temporary).
    [[nodiscard]] const std::filesystem::path& path() const noexcept { return temporary_; }
    /// Where `commit()` puts it.
    [[nodiscard]] const std::filesystem::path& destination() const noexcept { return destination_; }

    /// Renames the temporary onto the destination, replacing what was there (for a directory the
    /// old one is moved aside first and removed after). Throws Error(runtime) on failure, in which
    /// case the temporary is still removed by the destructor and the old destination is kept.
    void commit();

    /// Removes the temporary now (idempotent, never throws).
    void discard() noexcept;

  private:
    std::filesystem::path destination_;
    std::filesystem::path temporary_;
    Kind kind_ = Kind::file;
    bool owned_ = false;  ///< true while the temporary exists and is ours to remove
};

}  // namespace collide::video
