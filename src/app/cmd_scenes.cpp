/// `collide scenes`: list the built-in scenes (usable anywhere a scene path is) with a
/// one-line description each.

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "collide/error.hpp"
#include "collide/printable.hpp"
#include "collide/scene/load.hpp"
#include "commands.hpp"
#include "json_output.hpp"

namespace collide::app {

void add_scenes_command(CLI::App& root) {
    CLI::App* cmd = root.add_subcommand(
        "scenes", "List the built-in scenes (use a name wherever a scene path goes)");
    auto json = std::make_shared<bool>(false);
    cmd->add_flag("--json", *json, "Print the list as JSON: [{\"name\", \"description\"}, ...]");
    cmd->callback([json] {
        const std::filesystem::path assets = scene_assets_dir();
        const std::vector<BuiltinScene> scenes = builtin_scenes(assets);
        if (scenes.empty()) {
            throw_input_error(
                "no built-in scenes found in " + (assets / "scenes").string() +
                " (set COLLIDE_DATA_DIR to collide's data directory, the one holding scenes/)");
        }
        if (*json) {
            Json list = Json::array();
            for (const BuiltinScene& s : scenes) {
                list.push_back(Json{{"name", s.name}, {"description", s.description}});
            }
            std::fputs(json_text(list).c_str(), stdout);
            return;
        }
        std::size_t width = 0;
        for (const BuiltinScene& s : scenes) width = std::max(width, s.name.size());
        for (const BuiltinScene& s : scenes) {
            // A description is anyone's text: escape sequences in it are shown, not obeyed.
            std::printf("%-*s  %s\n", static_cast<int>(width), printable_text(s.name).c_str(),
                        printable_text(s.description, false).c_str());
        }
    });
}

}  // namespace collide::app
