#pragma once
/// \file
/// The algs4 `CollisionSystem` text format (std-only): first token N, then N lines
/// "rx ry vx vy radius mass r g b" (Java doubles such as 1.9E-4, integer colours 0..255) in the
/// unit box with walls. Read leniently about layout (leading spaces, blank lines, CRLF, no final
/// newline), strictly about content (column count, numbers, N).

#include <filesystem>
#include <iosfwd>
#include <string>

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
[[nodiscard]] ParsedScene parse_algs4(std::istream& in, const std::string& file_label);

/// Reads an algs4 file (the scene is named after the file stem), then validates it.
/// Throws Error(input) when the file cannot be read or is invalid.
[[nodiscard]] ParsedScene read_algs4_file(const std::filesystem::path& path);

/// Writes a scene in algs4 format with round-trip precision (17 significant digits). Box size,
/// boundary, tags and render hints are not representable and are dropped.
void write_algs4(std::ostream& out, const Scene& scene);

}  // namespace collide
