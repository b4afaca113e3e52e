#pragma once
/// \file
/// Loading scenes for the CLI (library collide_scene: links collide_sim and toml++).
/// Implemented with the scenes issue.

#include <filesystem>
#include <string>
#include <vector>

#include "collide/scene.hpp"

namespace collide {

/// Loads and validates a scene: an algs4 `.txt` file, a `.toml` scene, or the name of a built-in
/// scene (assets/scenes/<name>.toml). Throws Error(input) naming file:line (or TOML key) and field.
[[nodiscard]] Scene load_scene(const std::string& path_or_name);

/// Names of the built-in scenes, sorted.
[[nodiscard]] std::vector<std::string> builtin_scene_names();

}  // namespace collide
