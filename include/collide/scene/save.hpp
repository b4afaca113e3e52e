#pragma once
/// \file
/// Writing scenes back out (library collide_scene): TOML with every disc explicit (generated
/// discs frozen), or algs4 text. Reading what was written gives the same scene bit for bit.

#include <atomic>
#include <filesystem>
#include <iosfwd>

#include "collide/scene.hpp"

namespace collide {

/// Writes `scene` as a TOML scene: title, [box], the [render] hints that are set, then one
/// [[disc]] per disc with 17 significant digits. O(N).
void write_toml_scene(std::ostream& out, const Scene& scene);

/// Writes `scene` to `path`: `.toml` => write_toml_scene, `.txt` => algs4 (unit box with walls
/// only), through an io::OutputFile (collide/io/file.hpp): an exclusive temporary beside `path`
/// renamed onto it, so `path` holds its old content or the whole new scene, and concurrent saves
/// to one path each produce a whole file. When `cancel` is set by then (a signal), nothing is
/// written. Throws Error(input) for another extension, a box algs4 cannot express, or a path
/// that cannot be created (with the system's reason, e.g. "Read-only file system");
/// Error(runtime) when writing fails (e.g. "No space left on device") or on `cancel`.
void save_scene(const Scene& scene, const std::filesystem::path& path,
                const std::atomic<bool>* cancel = nullptr);

}  // namespace collide
