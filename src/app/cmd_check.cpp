/// `collide check SCENE`: load and validate a scene, print a one-line summary (exit 0) or the
/// first problem with file:line and field (exit 2, via main).

#include <cstdio>
#include <memory>
#include <string>

#include "collide/scene/load.hpp"
#include "collide/sim/scene_check.hpp"
#include "commands.hpp"

namespace collide::app {

void add_check_command(CLI::App& root) {
    auto scene_arg = std::make_shared<std::string>();
    CLI::App* cmd = root.add_subcommand(
        "check", "Validate a scene (algs4 .txt, .toml or a built-in name) and summarise it");
    cmd->add_option("scene", *scene_arg, "Scene file or built-in scene name (see `collide scenes`)")
        ->required();
    cmd->callback([scene_arg] {
        const Scene scene = load_scene(*scene_arg);  // validates; throws Error(input) -> exit 2
        std::printf("ok: %s: %s\n", scene_arg->c_str(), scene_summary(scene).c_str());
    });
}

}  // namespace collide::app
