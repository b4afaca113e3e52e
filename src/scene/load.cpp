// load_scene: decide what the argument names (algs4 file, TOML file, built-in scene), load it,
// and let the loader validate it.

#include "collide/scene/load.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cstdlib>
#include <system_error>

#include "collide/error.hpp"
#include "collide/sim/algs4.hpp"
#include "toml_limits.hpp"

namespace collide {

namespace {

std::filesystem::path scenes_dir(const std::filesystem::path& assets_dir) {
    return assets_dir / "scenes";
}

bool has_extension(const std::filesystem::path& p, const char* ext) {
    return p.extension() == ext;
}

// A bare word ("brownian") that is not an existing file names a built-in scene.
bool looks_like_name(const std::string& s) {
    return !s.empty() && s.find('/') == std::string::npos &&
           !std::filesystem::path(s).has_extension();
}

std::vector<std::string> scene_names_in(const std::filesystem::path& assets_dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(scenes_dir(assets_dir), ec)) {
        if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

/// A built-in scene whose file is a symbolic link that leads nowhere (a broken one, or one in a
/// loop) is there, by name, but cannot be read: said as such, not as an unknown name.
void refuse_broken_link(const std::string& name, const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_symlink(std::filesystem::symlink_status(file, ec))) return;
    std::error_code followed;
    (void)std::filesystem::status(file, followed);
    if (!followed) return;  // it leads to something; reading it says what, if it is not a scene
    const std::filesystem::path target = std::filesystem::read_symlink(file, ec);
    const std::string why = followed == std::errc::too_many_symbolic_link_levels
                                ? "a symbolic link in a loop"
                                : "a broken symbolic link (to '" + target.string() + "')";
    throw_scene_error("'" + name + "'", 0, "",
                      "the built-in scene's file " + file.string() + " is " + why +
                          "; reinstall collide's data directory, or set COLLIDE_DATA_DIR");
}

Scene load_builtin(const std::string& name, const std::filesystem::path& assets_dir,
                   const SceneOptions& options) {
    const std::filesystem::path file = scenes_dir(assets_dir) / (name + ".toml");
    std::error_code ec;
    refuse_broken_link(name, file);
    // Anything there that is not a regular file is refused by name when it is read.
    if (!std::filesystem::exists(file, ec)) {
        std::string reason = "not a scene file and not a built-in scene";
        if (!std::filesystem::is_directory(scenes_dir(assets_dir), ec)) {
            throw_scene_error("'" + name + "'", 0, "",
                              reason + " (no built-in scenes: " + scenes_dir(assets_dir).string() +
                                  " is not a directory; set COLLIDE_DATA_DIR to collide's data "
                                  "directory, the one holding scenes/)");
        }
        const std::string guess = nearest_name(name, scene_names_in(assets_dir));
        reason +=
            guess.empty() ? " (`collide scenes` lists them)" : " (did you mean '" + guess + "'?)";
        throw_scene_error("'" + name + "'", 0, "", reason);
    }
    Scene scene = load_toml_scene(file, options);
    scene.name = name;
    return scene;
}

std::filesystem::path running_executable() {
    std::error_code ec;
    std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    return exe;
}

DataDir find_data_dir() {
    for (const char* variable : {"COLLIDE_DATA_DIR", "COLLIDE_ASSETS_DIR"}) {
        const char* env = std::getenv(variable);
        if (env != nullptr && *env != '\0') return {env, std::string("$") + variable};
    }
    const std::filesystem::path exe = running_executable();
    if (exe.empty()) return {{}, "nowhere: /proc/self/exe cannot be read"};
    // Installed: PREFIX/bin/collide next to PREFIX/share/collide (the prefix may have moved),
    // or PREFIX/libexec/collide/collide-draw, one level further down.
    const std::filesystem::path installed = exe.parent_path().parent_path() / "share" / "collide";
    std::error_code ec;
    if (std::filesystem::is_directory(installed / "scenes", ec))
        return {installed, "next to the program"};
    const std::filesystem::path from_libexec =
        exe.parent_path().parent_path().parent_path() / "share" / "collide";
    if (exe.parent_path().parent_path().filename() == "libexec" &&
        std::filesystem::is_directory(from_libexec / "scenes", ec))
        return {from_libexec, "next to the program"};
#ifdef COLLIDE_BUILD_TREE
    // Development only: a program that runs from inside its own build tree reads the source
    // tree's assets, so a fresh build works without installing. An installed or moved copy never
    // gets here (its path is not under the build tree).
    const std::filesystem::path build_tree = COLLIDE_BUILD_TREE;
    const auto end =
        std::mismatch(build_tree.begin(), build_tree.end(), exe.begin(), exe.end()).first;
    if (end == build_tree.end())
        return {COLLIDE_SOURCE_ASSETS_DIR, "the source tree: a run from the build tree"};
#endif
    return {installed, "next to the program"};
}

}  // namespace

DataDir data_dir() {
    return find_data_dir();
}

std::filesystem::path scene_assets_dir() {
    return find_data_dir().path;
}

Scene load_scene(const std::string& path_or_name) {
    return load_scene(path_or_name, scene_assets_dir());
}

Scene load_scene(const std::string& path_or_name, const std::filesystem::path& assets_dir,
                 const SceneOptions& options) {
    if (path_or_name.empty())
        throw_scene_error("", 0, "", "empty scene path (give a file or a built-in scene name)");
    const std::filesystem::path path(path_or_name);
    std::error_code ec;
    const bool exists = std::filesystem::exists(path, ec);
    if (!exists && looks_like_name(path_or_name))
        return load_builtin(path_or_name, assets_dir, options);
    if (exists && std::filesystem::is_directory(path, ec))
        throw_scene_error(path_or_name, 0, "", "is a directory, not a scene file");
    if (has_extension(path, ".txt")) return read_algs4_text(read_scene_file(path), path).scene;
    if (has_extension(path, ".toml")) return load_toml_scene(path, options);
    if (!exists) throw_scene_error(path_or_name, 0, "", "no such file");
    throw_scene_error(path_or_name, 0, "",
                      "unknown scene format '" + path.extension().string() +
                          "' (expected an algs4 .txt file or a .toml scene)");
}

AnyScene load_any_scene(const std::string& path_or_name, const SceneOptions& options) {
    const std::filesystem::path path(path_or_name);
    std::error_code ec;
    const bool exists = !path_or_name.empty() && std::filesystem::exists(path, ec);
    std::filesystem::path file;
    std::string name;
    if (!path_or_name.empty() && !exists && looks_like_name(path_or_name)) {
        file = scenes_dir(scene_assets_dir()) / (path_or_name + ".toml");
        name = path_or_name;
        if (!std::filesystem::exists(file, ec))
            return load_scene(path_or_name, scene_assets_dir(), options);
    } else if (exists && !std::filesystem::is_directory(path, ec) && has_extension(path, ".toml")) {
        file = path;
        name = path.stem().string();
    } else {
        return load_scene(path_or_name, scene_assets_dir(), options);
    }
    AnyScene any =
        parse_any_toml_scene(read_scene_file(file), file.string(), file.parent_path(), options);
    std::visit(
        [&](auto& scene) {
            scene.name = name;
            if (scene.title.empty()) scene.title = valid_utf8(name);
        },
        any);
    return any;
}

std::vector<std::string> builtin_scene_names() {
    return scene_names_in(scene_assets_dir());
}

std::vector<BuiltinScene> builtin_scenes(const std::filesystem::path& assets_dir) {
    std::vector<BuiltinScene> scenes;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(scenes_dir(assets_dir), ec)) {
        if (entry.path().extension() != ".toml") continue;
        BuiltinScene s;
        s.name = entry.path().stem().string();
        try {
            const std::string text = read_scene_file(entry.path());
            check_toml_limits(text, entry.path().string());
            const toml::table doc = toml::parse(text, entry.path().string());
            s.description = doc["description"].value_or(std::string());
        } catch (const toml::parse_error& e) {
            throw_scene_error(entry.path().string(), static_cast<int>(e.source().begin.line), "",
                              "TOML syntax error: " + std::string(e.description()));
        }
        scenes.push_back(std::move(s));
    }
    std::sort(scenes.begin(), scenes.end(),
              [](const BuiltinScene& a, const BuiltinScene& b) { return a.name < b.name; });
    return scenes;
}

}  // namespace collide
