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
#include "json_output.hpp"
#include "work_limits.hpp"

namespace collide::app {

void add_check_command(CLI::App& root) {
    struct CheckOptions {
        std::string scene;
        std::string export_path;
        bool json = false;
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
    cmd->add_flag("--json", options->json,
                  "Print the summary as JSON (scene, name, discs, summary, exported)");
    cmd->callback([options] {
        // A signal while a large scene loads ends with the one interrupt message (main), and
        // one while the export is written leaves nothing at the destination, not even a
        // temporary: the guard turns it into a flag save_scene checks before the rename.
        InterruptGuard interrupts;
        AnyScene any = [&] {
            const StopAtOnce nothing_written_yet(interrupts);
            return load_any_scene(options->scene);  // validates; throws Error(input) -> exit 2
        }();
        interrupts.throw_if_requested();
        if (const auto* spheres = std::get_if<SphereScene>(&any)) {
            if (!options->export_path.empty())
                throw_option_error("--export",
                                   "writes 2D scenes only (exporting spheres is not built yet)");
            const std::string summary = sphere_scene_summary(*spheres);
            if (options->json) {
                const Json document{{"scene", options->scene},
                                    {"name", spheres->name},
                                    {"spheres", spheres->spheres.size()},
                                    {"summary", summary},
                                    {"exported", nullptr}};
                std::fputs(json_text(document).c_str(), stdout);
                return;
            }
            std::printf("ok: %s: %s\n", options->scene.c_str(), summary.c_str());
            return;
        }
        const Scene scene = std::move(std::get<Scene>(any));
        check_scene_hints(scene);  // what `collide render SCENE` would refuse in the hints
        if (!options->export_path.empty()) {
            try {
                save_scene(scene, options->export_path, &interrupts.flag());
            } catch (const Error&) {
                interrupts.throw_if_requested();
                throw;
            }
        }
        if (options->json) {
            Json document{{"scene", options->scene},
                          {"name", scene.name},
                          {"discs", scene.discs.size()},
                          {"summary", scene_summary(scene)},
                          {"exported", nullptr}};
            if (!options->export_path.empty()) document["exported"] = options->export_path;
            std::fputs(json_text(document).c_str(), stdout);
            return;
        }
        std::printf("ok: %s: %s\n", options->scene.c_str(), scene_summary(scene).c_str());
        if (!options->export_path.empty()) std::printf("wrote %s\n", options->export_path.c_str());
    });
}

}  // namespace collide::app
