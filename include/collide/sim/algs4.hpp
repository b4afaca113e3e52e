#pragma once
/// \file
/// The algs4 `CollisionSystem` text format (std-only): first token N, then N lines
/// "rx ry vx vy radius mass r g b" (Java doubles such as 1.9E-4, integer colours 0..255) in the
/// unit box with walls. Read leniently about layout (leading spaces, blank lines, CRLF, no final
/// newline), strictly about content (column count, numbers, N).

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>

#include "collide/scene.hpp"
#include "collide/sim/scene_check.hpp"

namespace collide {

/// A scene together with where each disc came from (for validation messages).
struct ParsedScene {
    Scene scene;
    SceneOrigin origin;
};

/// Parses algs4 text. `file_label` names the source in messages. Does NOT validate the physics
/// (call validate_scene); throws Error(input) "file:line: field: reason" for a missing or bad N,
/// a line without exactly 9 columns, a value that is not a number, a colour outside 0..255, or N
/// disagreeing with the number of disc lines. O(N).
/// A leading UTF-8 byte order mark is skipped; a number too small for a double ("1e-400") reads
/// as 0 with its sign, as in TOML scenes and on the command line; one too large ("1e400") is an
/// error saying so.
[[nodiscard]] ParsedScene parse_algs4(std::string_view text, const std::string& file_label);
/// The same, reading the stream to its end first.
[[nodiscard]] ParsedScene parse_algs4(std::istream& in, const std::string& file_label);

/// The UTF-8 byte order mark that some editors put at the start of a text file.
inline constexpr std::string_view utf8_bom = "\xEF\xBB\xBF";

/// `text` as valid UTF-8: every byte that does not belong to a well-formed sequence (overlong
/// forms, surrogates and code points past U+10FFFF included) becomes U+FFFD. A title taken from a
/// file name is display text, so a scene holds it this way from the moment it is loaded, and an
/// exported scene reads back to the same title. O(size).
[[nodiscard]] std::string valid_utf8(std::string_view text);

/// The largest scene file (or include) collide reads: 512 MiB. An algs4 file with 10^6 discs
/// written at full precision (write_algs4) is about 150 MB; the cap keeps a mistaken argument
/// (a disk image, /dev/zero behind a symlink) from being read until memory runs out.
inline constexpr std::uintmax_t max_scene_file_bytes = std::uintmax_t{512} << 20;

/// Parses algs4 text read from `path` (the scene is named after the file stem; its title is the
/// stem through valid_utf8), then validates it.
[[nodiscard]] ParsedScene read_algs4_text(std::string_view text, const std::filesystem::path& path);

/// Reads an algs4 file (the scene is named after the file stem), then validates it.
/// Throws Error(input) when the file cannot be read, is not a regular file, is larger than
/// max_scene_file_bytes, or is invalid. Checks the file type before opening, with std::filesystem
/// only (racy); the CLI reads through collide::read_scene_file, which cannot block.
[[nodiscard]] ParsedScene read_algs4_file(const std::filesystem::path& path);

/// Writes a scene in algs4 format with round-trip precision (17 significant digits). Box size,
/// boundary, tags and render hints are not representable and are dropped.
void write_algs4(std::ostream& out, const Scene& scene);

}  // namespace collide
