#pragma once
/// \file
/// Loading scenes for the CLI (library collide_scene: links collide_sim and toml++).
/// Every loader validates (collide/sim/scene_check.hpp) before it returns: a scene that comes out
/// of here is safe to hand to any engine.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "collide/scene.hpp"
#include "collide/scene3.hpp"

namespace collide {

/// Loads and validates a scene: an algs4 `.txt` file, a `.toml` scene, or the name of a built-in
/// scene (assets/scenes/<name>.toml). Throws Error(input) naming file:line (or TOML key) and field.
[[nodiscard]] Scene load_scene(const std::string& path_or_name);

/// How a scene is loaded, beyond its file.
struct SceneOptions {
    /// Replaces the seed of every `[[generate]]` block (block i gets seed + i, so blocks still
    /// differ): the CLI's `--seed`. Unset = the scene's own seeds. No effect on algs4 files.
    std::optional<std::uint64_t> seed;
};

/// Same, looking built-in names up in `assets_dir`/scenes instead of scene_assets_dir().
[[nodiscard]] Scene load_scene(const std::string& path_or_name,
                               const std::filesystem::path& assets_dir,
                               const SceneOptions& options = {});

/// Names of the built-in scenes, sorted.
[[nodiscard]] std::vector<std::string> builtin_scene_names();

/// A built-in scene and its one-line description (the TOML `description` key).
struct BuiltinScene {
    std::string name;
    std::string description;
};

/// The built-in scenes of `assets_dir`/scenes, sorted by name. Throws Error(input) if a
/// scene file cannot be read.
[[nodiscard]] std::vector<BuiltinScene> builtin_scenes(const std::filesystem::path& assets_dir);

/// Where the built-in data (scenes/) is, and how it was found (for messages and --version).
struct DataDir {
    std::filesystem::path path;
    std::string found_by;  ///< "$COLLIDE_DATA_DIR", "next to the program", ...
};

/// The data directory, first of: $COLLIDE_DATA_DIR (or the older $COLLIDE_ASSETS_DIR) when set
/// and not empty; PREFIX/share/collide when the running program is PREFIX/bin/collide or
/// PREFIX/libexec/collide/collide-draw (found
/// through /proc/self/exe, so a moved prefix still works); and, for a program that runs from
/// inside its own build tree only, the source tree's assets/ (the development fallback). When
/// nothing is found, the path next to the program (which does not exist; messages name it).
[[nodiscard]] DataDir data_dir();

/// data_dir().path: where built-in scene names are looked up (its scenes/ folder).
[[nodiscard]] std::filesystem::path scene_assets_dir();

/// Parses and validates a TOML scene given as text. `file_label` names it in messages;
/// `include` paths are resolved against `base_dir`. Throws Error(input) "file:line: key: reason".
[[nodiscard]] Scene parse_toml_scene(std::string_view text, const std::string& file_label,
                                     const std::filesystem::path& base_dir,
                                     const SceneOptions& options = {});

/// A scene of either dimension: discs (Scene) or spheres (SphereScene, `dimension = 3`).
using AnyScene = std::variant<Scene, SphereScene>;

/// Like parse_toml_scene, but a `dimension = 3` scene comes back as spheres instead of being
/// refused. 3D scenes are checked as they are read (file:line: field): explicit spheres inside a
/// walled box and not overlapping, [[fcc]] and [[generate]] not too dense to generate, no 2D key.
[[nodiscard]] AnyScene parse_any_toml_scene(std::string_view text, const std::string& file_label,
                                            const std::filesystem::path& base_dir,
                                            const SceneOptions& options = {});

/// load_scene for commands that also run spheres (check, simulate): a 3D TOML scene (file or
/// built-in) comes back as a SphereScene; anything else as load_scene gives it.
[[nodiscard]] AnyScene load_any_scene(const std::string& path_or_name,
                                      const SceneOptions& options = {});

/// Reads, parses and validates a TOML scene file (named after its stem).
[[nodiscard]] Scene load_toml_scene(const std::filesystem::path& path,
                                    const SceneOptions& options = {});

/// Reads a whole scene file (a scene or an include), safely: refuses anything that is not a
/// regular file (a FIFO, a device such as /dev/zero, a directory, through symlinks too) without
/// blocking in open(), and any file larger than max_scene_file_bytes (collide/sim/algs4.hpp,
/// 512 MiB). Throws Error(input) naming the file.
[[nodiscard]] std::string read_scene_file(const std::filesystem::path& path);

/// The candidate closest to `word` by edit distance, or "" when none is close enough to be a
/// plausible typo ("radus" -> "radius"). Used for "unknown key ... (did you mean ...?)".
[[nodiscard]] std::string nearest_name(std::string_view word,
                                       const std::vector<std::string>& candidates);

}  // namespace collide
