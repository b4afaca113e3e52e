// The checks across a run's outputs (two outputs naming one file, an output inside a directory
// output, an output naming an input), CommitGroup's all-or-nothing commit, and scratch files
// (include/collide/io/file.hpp, docs/outputs.md).

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

}  // namespace collide::io
