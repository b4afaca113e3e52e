// The helpers the files of collide_io share (path checks, temporary names, the sweep, the stop
// request); private to src/io. The public rules are in include/collide/io/file.hpp.
#pragma once

#include <sys/stat.h>
#include <sys/types.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "collide/io/file.hpp"

namespace collide::io::internal {

namespace fs = std::filesystem;

constexpr int max_name_attempts = 100;

// path_checks.cpp

std::string quote_path(const fs::path& path);
std::string errno_text(int error);
/// Throws Error(input) for a failure that says something about the path, Error(runtime) else.
[[noreturn]] void throw_create_error(const std::string& what, int error);
fs::path directory_of(const fs::path& path);
mode_t current_umask();
bool proc_fd_available();
std::string proc_fd_path(int fd);
int standard_stream_fd(const fs::path& path);
bool same_file(const struct stat& a, const struct stat& b);
fs::path follow_links(const fs::path& destination, const std::string& label);
File open_parent(const fs::path& path, const fs::path& shown, const std::string& label);
void check_link_target(const fs::path& destination, const fs::path& target,
                       const std::string& label);
void check_name_length(int directory, const std::string& name, const fs::path& shown,
                       const std::string& label);
bool is_mount_root(int directory, const std::string& name);
[[noreturn]] void throw_mount_point(const fs::path& shown, const std::string& label);

// temporaries.cpp

std::string fresh_temporary_name(std::string_view name);
void lock_exclusively(int fd);
bool holds_only(int fd, const OutputDirectory::NamePredicate& accept,
                std::string* offender = nullptr);
void remove_directory_files(int parent, const std::string& name, int fd,
                            const OutputDirectory::NamePredicate& accept);
std::size_t sweep(int directory, const OutputDirectory::NamePredicate& directory_entries);

// file.cpp

bool stop_requested() noexcept;
extern std::atomic<std::uint64_t> committed_count;  ///< outputs_committed()

// output_directory.cpp

fs::path directory_destination(const fs::path& destination, const std::string& label);

}  // namespace collide::io::internal
