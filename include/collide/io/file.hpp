#pragma once
/// \file
/// The one place where collide's safe-output rules live (library collide_io, std + POSIX only;
/// used by collide_scene, collide_video and the app, never by collide_sim). docs/outputs.md says
/// what they promise to users:
///
/// - Nothing appears at a destination until the whole output is written: writers write into a
///   temporary that `commit()` puts in place with one atomic rename; dropped uncommitted (error,
///   interrupt), the temporary goes and the old destination is untouched.
/// - Temporaries are created exclusively, in the destination's directory (rename is atomic only
///   within one filesystem): an unnamed O_TMPFILE file where the filesystem supports it (then
///   not even SIGKILL or a power cut leaves anything behind), else a hidden
///   `.NAME.collide-PID-XXXXXX` made by mkostemp/mkdtemp, never a fixed or guessable name. The
///   temporary's name is kept within NAME_MAX (the NAME part is shortened), so any legal
///   destination name works.
/// - Every writer holds an exclusive flock(2) on its temporary. A later run removes hidden
///   temporaries of that exact pattern, in the directory it writes to, only when they are
///   provably abandoned: owned by the same user, the process PID in the name gone, and nobody
///   holding the lock.
/// - A destination that is a symbolic link is written through: the link stays and its target is
///   replaced (except, as the kernel's protected_symlinks rule does, a link in a sticky
///   world-writable directory such as /tmp owned by someone else: refused).
/// - Errors: a destination that cannot be created (no such directory, permissions, read-only
///   filesystem) is Error(input) with the system's reason; a write that fails (full disk, I/O
///   error) is Error(runtime).

#include <sys/types.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace collide::io {

/// An owned file descriptor, closed by the destructor (fmt's `file`): copy deleted, noexcept
/// move that empties the source.
class File {
  public:
    File() = default;
    explicit File(int fd) noexcept : fd_(fd) {}
    ~File();
    File(File&& other) noexcept;
    File& operator=(File&& other) noexcept;
    File(const File&) = delete;
    File& operator=(const File&) = delete;

    [[nodiscard]] int get() const noexcept { return fd_; }
    [[nodiscard]] explicit operator bool() const noexcept { return fd_ >= 0; }

    /// Writes all `size` bytes (retrying short writes, and EINTR unless a stop was requested:
    /// see set_stop_flag). Throws Error(runtime) "cannot write 'SHOWN': REASON" (e.g. "No space
    /// left on device", "interrupted").
    void write_all(const void* data, std::size_t size, const std::filesystem::path& shown) const;
    /// close(2), checked (NFS reports delayed write errors here). Throws Error(runtime).
    void close(const std::filesystem::path& shown);

  private:
    int fd_ = -1;
};

/// Registers the process's stop request (the app's signal handlers set it; null: none). A write
/// that blocks (a reader of a pipe or FIFO that stopped reading) returns EINTR when a signal
/// arrives; File::write_all then gives up instead of retrying when the flag is set, so a signal
/// ends a run whatever its output. The flag must outlive its registration.
void set_stop_flag(const std::atomic<bool>* flag) noexcept;

/// How many outputs this process has put in place so far (renames of OutputFile and
/// OutputDirectory): a run that saw it grow must not say, interrupted, that nothing was written.
[[nodiscard]] std::uint64_t outputs_committed() noexcept;

/// How an OutputFile may treat its destination.
struct OutputOptions {
    /// Names the output in messages: "LABEL 'PATH': reason" ("output", "--events-log", ...).
    std::string label = "output";
    /// Streams (a text log, raw frames) may go to standard output ("-") or to an existing
    /// device, FIFO or socket (/dev/stdout, /dev/null), written in place: there is nothing to
    /// replace atomically. Without this, such destinations are refused (Error(input)).
    bool allow_stream = false;
    /// Use an unnamed O_TMPFILE temporary where the filesystem supports it. Only tests turn this
    /// off, to exercise the hidden named temporary that other filesystems get.
    bool unnamed_temporary = true;
    /// Abandoned temporary directories beside the destination (a PNG sequence whose run was
    /// killed) are swept when every entry satisfies this (see sweep_stale_temporaries); unset:
    /// they are kept.
    std::function<bool(std::string_view)> stale_directory_entries{};
};

/// One output file: a temporary beside the destination (see the file comment), moved onto it by
/// commit(), removed by discard() or the destructor. Move-only.
class OutputFile {
  public:
    /// Owns nothing.
    OutputFile() = default;
    /// Checks `destination` (its directory exists, it is not a directory, not a non-regular file
    /// unless options.allow_stream; symbolic links are followed), removes provably abandoned
    /// temporaries beside it, and creates this output's temporary. Throws Error(input) naming
    /// the label, the path and the system's reason when the destination cannot be written.
    explicit OutputFile(const std::filesystem::path& destination, OutputOptions options = {});
    ~OutputFile();
    OutputFile(OutputFile&& other) noexcept;
    OutputFile& operator=(OutputFile&& other) noexcept;
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    /// The open temporary (or stream), for writing.
    [[nodiscard]] int fd() const noexcept { return file_.get(); }
    /// A name that opens this very file, for libraries that insist on a path (libav):
    /// /proc/self/fd/N, so that nothing planted under the temporary's name is ever opened.
    [[nodiscard]] std::filesystem::path reopen_path() const;
    /// The destination as given (for messages).
    [[nodiscard]] const std::filesystem::path& destination() const noexcept { return destination_; }
    /// True when writing straight to standard output or a device/FIFO (see OutputOptions).
    [[nodiscard]] bool is_stream() const noexcept { return stream_; }
    /// True when this stream is the very file standard output writes to ("-", /dev/stdout, a
    /// name of the file stdout is redirected to), so that nothing else may go to stdout.
    /// False once committed or discarded.
    [[nodiscard]] bool is_standard_output() const noexcept;
    /// The temporary's name in the destination's directory, when it has one (tests).
    [[nodiscard]] const std::string& temporary_name() const noexcept { return temporary_name_; }

    /// Appends bytes. Throws Error(runtime) naming the destination and the reason.
    void write(const void* data, std::size_t size) const;
    void write(std::string_view text) const { write(text.data(), text.size()); }

    /// Everything of commit() that can fail for want of space or I/O, without touching the
    /// destination: flushes the data to disk (fsync), gives the file the mode an ordinary
    /// creation would (or the replaced file's), gives an unnamed temporary its hidden name, and
    /// checks again that the destination is no input of the run (see note_input_file). Throws
    /// Error (runtime; input for an input); the destructor then removes the temporary.
    /// Idempotent.
    void prepare_commit();
    /// prepare_commit() (if not done yet), then renames the temporary onto the destination
    /// atomically. Streams: nothing to move. Throws Error(runtime) on failure; the old
    /// destination is then untouched and the temporary is removed by the destructor.
    void commit();
    /// Removes the temporary now (idempotent, never throws).
    void discard() noexcept;

  private:
    /// An O_TMPFILE in directory_ (when `unnamed` and the filesystem has it), else a hidden
    /// exclusive file named after target_name_. Throws Error naming `what`.
    void create_temporary(bool unnamed, const std::string& what);

    std::filesystem::path destination_;
    std::string label_;
    File directory_;              ///< the (resolved) destination's directory
    std::string target_name_;     ///< the destination's name in directory_
    File file_;                   ///< the temporary, locked with flock(LOCK_EX)
    std::string temporary_name_;  ///< its name in directory_; empty while it is an O_TMPFILE
    bool stream_ = false;
    bool active_ = false;    ///< true while there is a temporary (or stream) to commit or discard
    bool prepared_ = false;  ///< prepare_commit() is done: only the rename is left
};

/// A directory output (a PNG sequence): a hidden temporary directory beside the destination,
/// filled with create_file(), that commit() puts in the destination's place.
///
/// An existing destination directory is only ever replaced when everything in it is a regular
/// file whose name satisfies `replaceable` (an earlier sequence of the same name); anything else
/// in it, or a destination that is the current directory or one of its ancestors (`.`, `..`,
/// `/`) or a mount point, is Error(input) up front. The replaced directory's files that satisfy
/// `replaceable` are removed after the commit; anything that appeared meanwhile is left in place.
class OutputDirectory {
  public:
    using NamePredicate = std::function<bool(std::string_view)>;

    OutputDirectory() = default;
    /// Throws Error(input) naming the path and the reason when the destination is unsuitable.
    /// Abandoned temporary directories beside it are swept when all their entries satisfy
    /// `stale_entries` (unset: `replaceable`): a sequence of any name killed earlier.
    OutputDirectory(const std::filesystem::path& destination, NamePredicate replaceable,
                    std::string label = "output", const NamePredicate& stale_entries = {});
    ~OutputDirectory();
    OutputDirectory(OutputDirectory&& other) noexcept;
    OutputDirectory& operator=(OutputDirectory&& other) noexcept;
    OutputDirectory(const OutputDirectory&) = delete;
    OutputDirectory& operator=(const OutputDirectory&) = delete;

    /// Creates `name` (a plain file name) exclusively inside the temporary directory.
    /// Throws Error(runtime).
    [[nodiscard]] File create_file(const std::string& name) const;
    /// Everything of commit() that can fail before the rename: the directory's mode, and the
    /// check that the destination still holds only what it may replace. Throws Error(runtime);
    /// the old destination is then untouched. May be repeated.
    void prepare_commit();
    /// prepare_commit(), then moves the directory into place (atomically exchanging it with an
    /// existing one where the filesystem can). Throws Error(runtime); the old destination is
    /// then untouched.
    void commit();
    /// Removes the temporary directory and the files this object created in it. Never throws.
    void discard() noexcept;

  private:
    std::filesystem::path destination_;
    std::string label_;
    NamePredicate replaceable_;
    File parent_;  ///< the destination's parent directory
    std::string target_name_;
    File temporary_;  ///< the temporary directory, locked with flock(LOCK_EX)
    std::string temporary_name_;
    bool active_ = false;
};

/// Checks up front (before any work) that `destination` can be written as a directory output,
/// by the rules of OutputDirectory, without creating anything. Throws Error(input).
void check_output_directory(const std::filesystem::path& destination,
                            const OutputDirectory::NamePredicate& replaceable,
                            const std::string& label = "output");

/// One output of a run (for check_distinct_outputs): its label in messages ("-o",
/// "--layout-json"), its path, and whether it is a directory output (a PNG sequence).
struct NamedOutput {
    std::string label;
    std::filesystem::path path;
    bool directory = false;
};

/// Refuses, before anything is written, two outputs of one run that are the same file: after
/// symbolic links, hard links included, standard output twice ("-" and /dev/stdout) - or a file
/// inside a directory output, which replaces its directory as a whole. Throws Error(input)
/// naming both. Creates nothing.
void check_distinct_outputs(const std::vector<NamedOutput>& outputs);

/// One input of a run, for check_outputs_not_inputs: its label in messages ("EXPECTED", "the
/// scene") and its path.
struct NamedInput {
    std::string label;
    std::filesystem::path path;
};

/// Refuses, before anything is written, an output that is one of the run's inputs (an output
/// would replace what the run reads: `compare A.png B.png --diff A.png`): the same file after
/// symbolic links, hard links included (same device and inode), or, for a file that does not
/// exist yet, the same path once resolved. Throws Error(input) naming both. Creates nothing.
void check_outputs_not_inputs(const std::vector<NamedOutput>& outputs,
                              const std::vector<NamedInput>& inputs);

/// Records that this process read the open file `fd` (named `path`) as an input (a scene, an
/// algs4 file a scene includes): from then on no OutputFile of the process may replace it, nor
/// write into it as a stream. An OutputFile checks its destination against every input noted
/// when it is created and again in prepare_commit(), and refuses one with Error(input) naming
/// the option, the path and the input ("--layout-json 's.toml' is the scene file 's.toml'
/// this run reads"). The record keeps a duplicate of `fd` open, so that the file's inode is not
/// reused for another file while the process runs. Thread-safe; a process-wide record, like
/// the stop flag, since inputs are read deep in libraries (a scene's includes) that know
/// nothing of the outputs.
void note_input_file(int fd, const std::filesystem::path& path);

/// The outputs of one run, put in place together (docs/outputs.md, "Several outputs of one
/// run"): commit() first prepares every output (the video's data flushed, the sidecars, the
/// slide folder checked again: everything that can fail for want of space, I/O or a changed
/// destination), and only when all of them are ready, and no stop was requested (set_stop_flag),
/// renames them into place one after the other. A failure or a stop before the renames leaves
/// every destination as it was (the outputs' owners remove their temporaries). Holds
/// references: the outputs must outlive commit().
class CommitGroup {
  public:
    /// Adds an output (null: nothing).
    void add(OutputFile* file);
    void add(OutputDirectory* directory);
    /// Adds any output by its two steps (a video writer's): `prepare` may throw, `rename` puts
    /// it in place.
    void add(std::function<void()> prepare, std::function<void()> rename);
    /// Prepares every output, then renames each into place in the order added. Throws Error:
    /// runtime ("interrupted" for a stop), or whatever a preparation threw. Once the renames have
    /// begun, a stop request waits for them to end.
    void commit();

  private:
    struct Step {
        std::function<void()> prepare;
        std::function<void()> rename;
    };
    std::vector<Step> steps_;
};

/// An unnamed scratch file in `directory` (O_TMPFILE, or mkostemp + unlink at once), for data
/// that must never outlive the process (the GIF writer's frame store). Throws Error(runtime).
[[nodiscard]] File open_scratch_file(const std::filesystem::path& directory);

/// What a file that is not a regular one is, for messages: "a directory", "a FIFO (named pipe)",
/// "a character device", "a block device", "a socket", or "not a regular file".
[[nodiscard]] std::string file_type_name(mode_t mode);

namespace detail {

/// The mkstemp template of a temporary for the file `name`, for process `pid`:
/// ".NAME.collide-PID-XXXXXX", with NAME shortened (at a UTF-8 character boundary) so that the
/// whole stays within `name_max` bytes.
[[nodiscard]] std::string temporary_template(std::string_view name, pid_t pid,
                                             std::size_t name_max = 255);
/// The process id in a name made from temporary_template(), or nothing for any other name.
[[nodiscard]] std::optional<pid_t> temporary_owner(std::string_view name);
/// Forgets every input noted by note_input_file (tests: a test's files are deleted, and their
/// inodes may be reused by the next test's).
void forget_input_files() noexcept;
/// Removes the abandoned temporaries in `directory` (see the file comment): files, and
/// directories whose entries all satisfy `directory_entries` (null: directories are kept).
/// Returns how many were removed. Never throws.
std::size_t sweep_stale_temporaries(const std::filesystem::path& directory,
                                    const OutputDirectory::NamePredicate& directory_entries = {});

}  // namespace detail

}  // namespace collide::io
