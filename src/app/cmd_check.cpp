/// `collide check SCENE [--export FILE]`: load and validate a scene, print a one-line summary
/// (exit 0) or the first problem with file:line and field (exit 2, via main). --export writes the
/// scene back out with every disc explicit (generated discs frozen; algs4 <-> TOML conversion).

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "collide/error.hpp"
#include "collide/printable.hpp"
#include "collide/scene/load.hpp"
#include "collide/scene/save.hpp"
#include "collide/sim/scene_check.hpp"
#include "collide/sim/sphere_check.hpp"
#include "collide/text/font_face.hpp"
#include "commands.hpp"
#include "font_search.hpp"
#include "interrupt.hpp"
#include "json_output.hpp"
#include "work_limits.hpp"

namespace collide::app {
namespace {

/// One text of the scene a student reads, and where it was written ("file:line: field").
struct ScreenText {
    std::string where;
    const std::string* text;
};

/// The line of a top-level `key = ...` in a TOML scene file (top-level keys come before the
/// first [table] header), or 0 when the file has none or is not TOML (a built-in name, algs4).
int top_level_key_line(const std::string& scene_arg, std::string_view key) {
    if (std::filesystem::path(scene_arg).extension() != ".toml") return 0;
    std::ifstream in(scene_arg);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::size_t start = line.find_first_not_of(" \t");
        if (start == std::string::npos) continue;
        if (line[start] == '[') return 0;
        if (line.compare(start, key.size(), key) != 0) continue;
        const std::size_t after = line.find_first_not_of(" \t", start + key.size());
        if (after != std::string::npos && line[after] == '=') return number;
    }
    return 0;
}

/// The scene's on-screen texts: the title (the intro card, the header), the description, the
/// caption line and each scripted caption.
std::vector<ScreenText> screen_texts(const Scene& scene, const std::string& scene_arg) {
    const auto top_level = [&scene_arg](const char* key) {
        const int line = top_level_key_line(scene_arg, key);
        return line > 0 ? scene_arg + ":" + std::to_string(line) + ": " + key
                        : scene_arg + ": " + key;
    };
    std::vector<ScreenText> out{{top_level("title"), &scene.title},
                                {top_level("description"), &scene.description}};
    if (scene.render.caption) {
        const std::string& at = scene.render.caption_at;
        out.push_back({at.empty() ? scene_arg + ": render.caption" : at, &*scene.render.caption});
    }
    for (std::size_t i = 0; i < scene.render.captions.size(); ++i) {
        const CaptionCue& cue = scene.render.captions[i];
        const std::string field = "render.captions[" + std::to_string(i) + "].";
        const std::string where =
            (cue.file.empty() ? scene_arg : cue.file + ":" + std::to_string(cue.line)) + ": " +
            field;
        out.push_back({where + "text", &cue.text});
        if (cue.event_text) out.push_back({where + "event", &*cue.event_text});
        if (cue.time_text) out.push_back({where + "time", &*cue.time_text});
    }
    return out;
}

/// The installed fallback fonts that open (text::installed_fallback_fonts); a warning for each
/// that does not: the renderer draws its characters as '?'.
std::vector<text::FontFace> usable_fallback_fonts() {
    std::vector<text::FontFace> out;
    for (const std::string& path : text::installed_fallback_fonts()) {
        try {
            out.emplace_back(path, std::string_view{}, text::fallback_font_package(path));
        } catch (const Error& e) {
            std::fprintf(stderr, "warning: the fallback font is not used: %s\n",
                         printable_text(e.what()).c_str());
        }
    }
    return out;
}

/// "the font DejaVu Sans (PATH)", or with fallbacks "any installed font (DejaVu Sans (PATH),
/// Droid Sans Fallback (PATH))": where a character was looked for.
std::string fonts_looked_in(const std::vector<const text::FontFace*>& fonts) {
    const auto one = [](const text::FontFace* f) { return f->name() + " (" + f->path() + ")"; };
    if (fonts.size() == 1) return "the font " + one(fonts.front());
    std::string out = "any installed font (";
    for (std::size_t i = 0; i < fonts.size(); ++i) out += (i > 0 ? ", " : "") + one(fonts[i]);
    return out + ")";
}

/// Warns (stderr) about each character of the scene's on-screen text that neither the font the
/// drawing commands would use nor any installed fallback font has: it would be drawn as '?'. A
/// font that cannot be opened is a warning too: checking a scene needs no font, drawing it does.
void warn_missing_characters(const Scene& scene, const std::string& scene_arg,
                             const std::string& font_option) {
    std::optional<text::FontFace> font;
    try {
        font.emplace(find_font(font_option));
    } catch (const Error& e) {
        std::fprintf(stderr, "warning: the scene's characters were not checked: %s\n",
                     printable_text(e.what()).c_str());
        return;
    }
    const std::vector<ScreenText> texts = screen_texts(scene, scene_arg);
    // The fallbacks (megabytes, checked whole) are read only when the font lacks something.
    if (std::all_of(texts.begin(), texts.end(), [&font](const ScreenText& t) {
            return text::missing_characters(*font, *t.text).empty();
        })) {
        return;
    }
    const std::vector<text::FontFace> fallbacks = usable_fallback_fonts();
    std::vector<const text::FontFace*> fonts{&*font};
    for (const text::FontFace& f : fallbacks) fonts.push_back(&f);
    const std::string looked_in = printable_text(fonts_looked_in(fonts));
    for (const ScreenText& t : texts) {
        for (const std::uint32_t cp : text::missing_characters(fonts, *t.text)) {
            std::fprintf(stderr, "warning: %s: %s is not in %s: it is drawn as '?'\n",
                         printable_text(t.where).c_str(),
                         printable_text(text::describe_character(cp)).c_str(), looked_in.c_str());
        }
    }
}

}  // namespace

void add_check_command(CLI::App& root) {
    struct CheckOptions {
        std::string scene;
        std::string export_path;
        std::string font;
        bool json = false;
    };
    auto options = std::make_shared<CheckOptions>();
    CLI::App* cmd = root.add_subcommand(
        "check", "Validate a scene (algs4 .txt, .toml or a built-in name) and summarise it");
    cmd->add_option("scene", options->scene,
                    "Scene file or built-in scene name (see `collide scenes`)")
        ->required()
        ->type_name("SCENE");
    cmd->add_option("--export", options->export_path,
                    "Also write the scene with every disc explicit: .toml, or .txt (algs4, unit "
                    "box with walls only)")
        ->type_name("PATH");
    cmd->add_option(
           "--font", options->font,
           std::string(font_option_help) + "; the scene's text is checked for characters it lacks")
        ->type_name("FILE");
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
            std::printf("ok: %s: %s\n", printable_text(options->scene).c_str(),
                        printable_text(summary).c_str());
            return;
        }
        const Scene scene = std::move(std::get<Scene>(any));
        check_scene_hints(scene);  // what `collide render SCENE` would refuse in the hints
        warn_missing_characters(scene, options->scene, options->font);
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
        std::printf("ok: %s: %s\n", printable_text(options->scene).c_str(),
                    printable_text(scene_summary(scene)).c_str());
        if (!options->export_path.empty())
            std::printf("wrote %s\n", printable_text(options->export_path).c_str());
    });
}

}  // namespace collide::app
