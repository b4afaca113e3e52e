#include "collide/video/output.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "collide/error.hpp"

namespace collide::video {
namespace fs = std::filesystem;

namespace {

fs::path directory_of(const fs::path& path) {
    const fs::path parent = path.parent_path();
    return parent.empty() ? fs::path(".") : parent;
}

// Built with append(): GCC 12 at -O3 warns (-Wrestrict, a known false positive) about
// `"literal" + std::string` here.
std::string quoted(const fs::path& path) {
    std::string text;
    text.reserve(path.native().size() + 2);
    text.append(1, '\'').append(path.native()).append(1, '\'');
    return text;
}

/// mkstemp/mkdtemp template beside `destination`: hidden, recognisable, unique.
std::vector<char> temporary_template(const fs::path& destination) {
    std::string hidden_name(1, '.');
    hidden_name.append(destination.filename().native()).append(".XXXXXX");
    const std::string name = (directory_of(destination) / hidden_name).string();
    return std::vector<char>(name.begin(), name.end());
}

/// The process umask, read without changing it (umask(2) can only be read by setting it, which
/// would race with other threads creating files). Linux >= 4.7 reports it in /proc; 022 otherwise.
mode_t current_umask() {
    std::FILE* status = std::fopen("/proc/self/status", "r");
    if (status == nullptr) return 022;
    char line[256];
    unsigned int mask = 022;
    while (std::fgets(line, sizeof line, status) != nullptr) {
        if (std::sscanf(line, "Umask: %o", &mask) == 1) break;
    }
    std::fclose(status);
    return static_cast<mode_t>(mask);
}

/// mkstemp/mkdtemp create 0600/0700 (private while being written); the finished output gets the
/// permissions an ordinary open/mkdir would have given it, so a video can be served or shared.
void give_ordinary_permissions(const fs::path& path, bool directory) {
    const mode_t mode = (directory ? 0777 : 0666) & ~current_umask();
    ::chmod(path.c_str(), mode);  // best effort: a failure only leaves the file private
}

}  // namespace

void check_output_writable(const fs::path& path, bool directory_output) {
    if (path.empty()) throw_input_error("output path is empty");
    if (!path.has_filename()) {
        throw_input_error("output path " + quoted(path) + " names no file (it ends with a '/')");
    }
    const fs::path directory = directory_of(path);
    std::error_code error;
    const fs::file_status status = fs::status(directory, error);
    if (!fs::exists(status)) {
        throw_input_error("output path " + quoted(path) + ": directory " + quoted(directory) +
                          " does not exist");
    }
    if (!fs::is_directory(status)) {
        throw_input_error("output path " + quoted(path) + ": " + quoted(directory) +
                          " is not a directory");
    }
    if (!directory_output && fs::is_directory(fs::status(path, error))) {
        throw_input_error("output path " + quoted(path) + " is an existing directory");
    }
    if (directory_output && fs::exists(fs::status(path, error)) &&
        !fs::is_directory(fs::status(path, error))) {
        throw_input_error("output path " + quoted(path) + " exists and is not a directory");
    }
    // Probe by creating a file: access(W_OK) is wrong for root and read-only mounts.
    TemporaryOutput probe(path, TemporaryOutput::Kind::file);
    probe.discard();
}

TemporaryOutput::TemporaryOutput(const fs::path& destination, Kind kind)
    : destination_(destination), kind_(kind) {
    std::vector<char> name = temporary_template(destination);
    name.push_back('\0');
    if (kind == Kind::file) {
        const int fd = ::mkstemp(name.data());
        if (fd < 0) {
            throw_input_error("output path " + quoted(destination) + ": cannot create a file in " +
                              quoted(directory_of(destination)) + ": " + std::strerror(errno));
        }
        ::close(fd);
    } else if (::mkdtemp(name.data()) == nullptr) {
        throw_input_error("output path " + quoted(destination) + ": cannot create a directory in " +
                          quoted(directory_of(destination)) + ": " + std::strerror(errno));
    }
    temporary_ = fs::path(name.data());
    owned_ = true;
}

TemporaryOutput::~TemporaryOutput() {
    discard();
}

TemporaryOutput::TemporaryOutput(TemporaryOutput&& other) noexcept
    : destination_(std::move(other.destination_)),
      temporary_(std::move(other.temporary_)),
      kind_(other.kind_),
      owned_(std::exchange(other.owned_, false)) {}

TemporaryOutput& TemporaryOutput::operator=(TemporaryOutput&& other) noexcept {
    if (this != &other) {
        discard();
        destination_ = std::move(other.destination_);
        temporary_ = std::move(other.temporary_);
        kind_ = other.kind_;
        owned_ = std::exchange(other.owned_, false);
    }
    return *this;
}

void TemporaryOutput::commit() {
    if (!owned_) throw_runtime_error("output " + quoted(destination_) + ": nothing to commit");
    std::error_code error;
    give_ordinary_permissions(temporary_, kind_ == Kind::directory);
    if (kind_ == Kind::file) {
        fs::rename(temporary_, destination_, error);
        if (error) {
            throw_runtime_error("cannot rename " + quoted(temporary_) + " to " +
                                quoted(destination_) + ": " + error.message());
        }
        owned_ = false;
        return;
    }
    // Directories cannot be renamed over non-empty ones: move the old one aside first, and put
    // it back if the second rename fails.
    fs::path aside;
    if (fs::exists(destination_, error)) {
        aside = temporary_;
        aside += ".old";
        fs::rename(destination_, aside, error);
        if (error) {
            throw_runtime_error("cannot move the old " + quoted(destination_) +
                                " aside: " + error.message());
        }
    }
    fs::rename(temporary_, destination_, error);
    if (error) {
        std::error_code ignored;
        if (!aside.empty()) fs::rename(aside, destination_, ignored);
        throw_runtime_error("cannot rename " + quoted(temporary_) + " to " + quoted(destination_) +
                            ": " + error.message());
    }
    owned_ = false;
    if (!aside.empty()) fs::remove_all(aside, error);  // best effort: the new output is in place
}

void TemporaryOutput::discard() noexcept {
    if (!owned_) return;
    owned_ = false;
    std::error_code ignored;
    fs::remove_all(temporary_, ignored);
}

}  // namespace collide::video
