#pragma once
/// \file
/// The checks the app runs on a video's destination before rendering anything. The rules
/// themselves (exclusive temporaries beside the destination, atomic commit, symbolic links,
/// directories of frames) live in collide/io/file.hpp; docs/outputs.md says what they promise.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace collide::video {

/// Checks, before any frame is rendered, that `path` can be written: its directory exists, is a
/// directory, and a file can actually be created in it (probed with a temporary that is removed
/// again; permission bits alone lie for root and read-only mounts), and `path` itself is not an
/// existing directory or device. With `directory_output` (PNG sequences) `path` is a directory
/// that is written whole: it must be new, empty, or hold only an earlier sequence of the same
/// stem; `.`, `..`, `/`, the current directory and its parents are refused.
/// Throws Error(input) naming the path and the reason.
void check_output_writable(const std::filesystem::path& path, bool directory_output = false);

/// Throws Error(input) when the frames of a sequence written to the directory `path` would have
/// names longer than the filesystem allows (255 bytes).
void check_sequence_name(const std::filesystem::path& path);

/// The name of frame `index` in a PNG sequence: "<stem>_00042.png" (at least five digits).
[[nodiscard]] std::string sequence_frame_name(std::string_view stem, std::int64_t index);
/// True for names sequence_frame_name(stem, i) gives for some i: the files a new sequence of
/// `stem` may replace.
[[nodiscard]] bool is_sequence_frame_name(std::string_view stem, std::string_view name);
/// True for the frame names of a sequence of any stem ("<stem>_<5 or more digits>.png"): what an
/// abandoned sequence's temporary directory holds, swept by the next writer in that directory.
[[nodiscard]] bool is_any_sequence_frame_name(std::string_view name);
/// The stem of the frames in the directory `path` ("frames/" and "frames" give "frames").
[[nodiscard]] std::string sequence_stem(const std::filesystem::path& path);

}  // namespace collide::video
