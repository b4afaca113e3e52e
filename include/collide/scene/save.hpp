#pragma once
/// \file
/// Writing scenes back out (library collide_scene): TOML with every disc explicit (generated
/// discs frozen), or algs4 text. Reading what was written gives the same scene bit for bit.

#include <filesystem>
#include <iosfwd>

#include "collide/scene.hpp"

namespace collide {

/// Writes `scene` as a TOML scene: title, [box], the [render] hints that are set, then one
/// [[disc]] per disc with 17 significant digits. O(N).
void write_toml_scene(std::ostream& out, const Scene& scene);

/// Writes `scene` to `path`: `.toml` => write_toml_scene, `.txt` => algs4 (unit box with walls
/// only). Writes a temporary file next to `path` and renames it, so `path` is never left
/// half-written. Throws Error(input) for another extension, a box algs4 cannot express, or an
/// unwritable path.
void save_scene(const Scene& scene, const std::filesystem::path& path);

}  // namespace collide
