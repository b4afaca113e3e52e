/// `collide scenes`: list the built-in scenes (usable anywhere a scene path is) with a
/// one-line description each.

#include <algorithm>
#include <cstdio>
#include <string>

#include "collide/error.hpp"
#include "collide/scene/load.hpp"
#include "commands.hpp"

namespace collide::app {

void add_scenes_command(CLI::App& root) {
    CLI::App* cmd = root.add_subcommand(
        "scenes", "List the built-in scenes (use a name wherever a scene path goes)");
    cmd->callback([] {
        const std::filesystem::path assets = scene_assets_dir();
        const std::vector<BuiltinScene> scenes = builtin_scenes(assets);
        if (scenes.empty()) {
            throw_input_error("no built-in scenes found in " + (assets / "scenes").string() +
                              " (set COLLIDE_ASSETS_DIR to the assets directory)");
        }
        std::size_t width = 0;
        for (const BuiltinScene& s : scenes) width = std::max(width, s.name.size());
        for (const BuiltinScene& s : scenes) {
            std::printf("%-*s  %s\n", static_cast<int>(width), s.name.c_str(),
                        s.description.c_str());
        }
    });
}

}  // namespace collide::app
