// `collide check` names each character of a scene's on-screen text that no installed font has (the
// font nor a fallback: file, line, the character); Greek, Polish and mathematics are in DejaVu
// Sans and pass quietly, Japanese too where a fallback font (fonts-droid-fallback) is installed.
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

/// Debian's fallback font (fonts-droid-fallback), which has Chinese, Japanese and Korean.
bool droid_fallback_installed() {
    return fs::is_regular_file("/usr/share/fonts/truetype/droid/DroidSansFallbackFull.ttf");
}

TEST_CASE("check: a character no installed font has is named with file, line and the character") {
    TempDir dir("check_glyphs");
    const fs::path scene = dir.path / "scene.toml";
    std::string text = scene_text;
    // U+E000 is a private-use character and U+0378 an unassigned one: no font has them.
    text += "\n[[render.captions]]\nat = 3\ntext = \"\uE000 and \u0378 and ≈\"\n";
    collide::test::write_file(scene, text);
    const auto r = run_collide("check " + scene.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);  // a warning, not an error
    if (r.output.find("not checked") != std::string::npos) {
        COLLIDE_SKIP_TEST("no DejaVu Sans: " << r.output);
    }
    // Line 22 is the second caption's "at" (the cue's line), as every caption message names it.
    CHECK(r.output.find("scene.toml:22: render.captions[1].text: '\uE000' (U+E000) is not in ") !=
          std::string::npos);
    const bool unassigned_named =
        r.output.find("scene.toml:22: render.captions[1].text: '\u0378' (U+0378) is not in ") !=
        std::string::npos;
    CHECK(unassigned_named);
    CHECK(r.output.find("DejaVu Sans") != std::string::npos);
    CHECK(r.output.find("it is drawn as '?'") != std::string::npos);
    if (droid_fallback_installed()) {
        CHECK(r.output.find("is not in any installed font (DejaVu Sans (") != std::string::npos);
        CHECK(r.output.find("Droid Sans Fallback (") != std::string::npos);
    }
    // Greek, Polish and mathematics are in DejaVu: no warning about the title or the others.
    CHECK(r.output.find(": title:") == std::string::npos);
    CHECK(r.output.find("U+2248") == std::string::npos);  // ≈
    CHECK(r.output.find("ok: ") != std::string::npos);
}

TEST_CASE("check: Japanese passes where a fallback font has it, a private-use title is named") {
    TempDir dir("check_title");
    const fs::path scene = dir.path / "s.toml";
    std::string text = scene_text;
    text.replace(text.find("Zderzenia"), 9, "気体の衝突 \uE001");
    text.replace(text.find("Kule się zderzają"), 17, "漢字の説明");
    collide::test::write_file(scene, text);
    const auto r = run_collide("check " + scene.string() + " --json");
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    if (r.output.find("not checked") != std::string::npos) COLLIDE_SKIP_TEST(r.output);
    CHECK(r.output.find("s.toml:1: title: '\uE001' (U+E001) is not in ") != std::string::npos);
    if (droid_fallback_installed()) {
        CHECK(r.output.find("U+6C17") == std::string::npos);  // 気
        CHECK(r.output.find("U+6F22") == std::string::npos);  // 漢
        CHECK(r.output.find("render.caption:") == std::string::npos);
    } else {
        CHECK(r.output.find("s.toml:1: title: '気' (U+6C17) is not in the font DejaVu Sans") !=
              std::string::npos);
    }
}
