// `collide check` names each character of a scene's on-screen text that the font lacks (file,
// line, the character); Greek, Polish and mathematics are in DejaVu Sans and pass quietly.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "../support/files.hpp"
#include "../support/skip.hpp"
#include "../support/temp_dir.hpp"
#include "multilingual_scene.hpp"
#include "run_collide.hpp"

namespace fs = std::filesystem;
using collide::test::run_collide;
using collide::test::TempDir;

namespace {

constexpr const char* scene_text = collide::test::multilingual_scene;

}  // namespace

TEST_CASE("check: a character the font lacks is named with file, line and the character") {
    TempDir dir("check_glyphs");
    const fs::path scene = dir.path / "scene.toml";
    std::string text = scene_text;
    text += "\n[[render.captions]]\nat = 3\ntext = \"漢字 and ≈\"\n";
    collide::test::write_file(scene, text);
    const auto r = run_collide("check " + scene.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);  // a warning, not an error
    if (r.output.find("not checked") != std::string::npos) {
        COLLIDE_SKIP_TEST("no DejaVu Sans: " << r.output);
    }
    // Line 22 is the second caption's "at" (the cue's line), as every caption message names it.
    CHECK(r.output.find("scene.toml:22: render.captions[1].text: '漢' (U+6F22) is not in the "
                        "font DejaVu Sans") != std::string::npos);
    CHECK(r.output.find("'字' (U+5B57)") != std::string::npos);
    // Greek, Polish and mathematics are in DejaVu: no warning about the title or the others.
    CHECK(r.output.find(": title:") == std::string::npos);
    CHECK(r.output.find("U+2248") == std::string::npos);  // ≈
    CHECK(r.output.find("ok: ") != std::string::npos);
}

TEST_CASE("check: a title the font cannot draw is named with its line") {
    TempDir dir("check_title");
    const fs::path scene = dir.path / "s.toml";
    std::string text = scene_text;
    text.replace(text.find("Zderzenia"), 9, "\u4E2D");
    collide::test::write_file(scene, text);
    const auto r = run_collide("check " + scene.string() + " --json");
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    if (r.output.find("not checked") != std::string::npos) COLLIDE_SKIP_TEST(r.output);
    CHECK(r.output.find("s.toml:1: title: '\u4E2D' (U+4E2D) is not in the font") !=
          std::string::npos);
}
