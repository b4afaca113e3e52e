/// `collide check SCENE [--export FILE]`: load and validate a scene, print a one-line summary
/// (exit 0) or the first problem with file:line and field (exit 2, via main). --export writes the
/// scene back out with every disc explicit (generated discs frozen; algs4 <-> TOML conversion).

#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <variant>

#include "collide/error.hpp"
#include "collide/scene/load.hpp"
#include "collide/scene/save.hpp"
#include "collide/sim/scene_check.hpp"
#include "collide/sim/sphere_check.hpp"
#include "commands.hpp"
#include "interrupt.hpp"
#include "work_limits.hpp"

namespace collide::app {

void add_check_command(CLI::App& root) {
    struct CheckOptions {
        std::string scene;
        std::string export_path;
    };
    auto options = std::make_shared<CheckOptions>();
    CLI::App* cmd = root.add_subcommand(
        "check", "Validate a scene (algs4 .txt, .toml or a built-in name) and summarise it");
    cmd->add_option("scene", options->scene,
                    "Scene file or built-in scene name (see `collide scenes`)")
        ->required();
    cmd->add_option("--export", options->export_path,
                    "Also write the scene with every disc explicit: .toml, or .txt (algs4, unit "
                    "box with walls only)");
    cmd->callback([options] {
        // Validates; throws Error(input) -> exit 2.
        AnyScene any = load_any_scene(options->scene);
        if (const auto* spheres = std::get_if<SphereScene>(&any)) {
            if (!options->export_path.empty())
                throw_option_error("--export",
                                   "writes 2D scenes only (exporting spheres is not built yet)");
            std::printf("ok: %s: %s\n", options->scene.c_str(),
                        sphere_scene_summary(*spheres).c_str());
            return;
        }
        const Scene scene = std::move(std::get<Scene>(any));
        check_scene_hints(scene);  // what `collide render SCENE` would refuse in the hints
        if (!options->export_path.empty()) {
            // A signal while the file is written leaves nothing at the destination, not even a
            // temporary: the guard turns it into a flag save_scene checks before the rename.
            InterruptGuard interrupts;
            try {
                save_scene(scene, options->export_path, &interrupts.flag());
            } catch (const Error&) {
                interrupts.throw_if_requested();
                throw;
            }
        }
        std::printf("ok: %s: %s\n", options->scene.c_str(), scene_summary(scene).c_str());
        if (!options->export_path.empty()) std::printf("wrote %s\n", options->export_path.c_str());
    });
}

}  // namespace collide::app
