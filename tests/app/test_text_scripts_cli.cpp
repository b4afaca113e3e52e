// Every language through the real program: a scene captioned in Japanese draws its glyphs from the
// fallback font (not '?'), and a character no font has is drawn exactly as '?' would be.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "../support/files.hpp"
#include "../support/skip.hpp"
#include "../support/temp_dir.hpp"
#include "collide/video/png.hpp"
#include "run_collide.hpp"

namespace fs = std::filesystem;
using collide::test::run_collide;
using collide::test::TempDir;

namespace {

/// A two-disc scene titled and captioned with `words`.
std::string scene_with(const std::string& words) {
    return "title = \"" + words + "\"\n" + R"(disc = [
  { position = [0.3, 0.5], velocity = [0.5, 0], radius = 0.05, mass = 1 },
  { position = [0.7, 0.5], velocity = [-0.5, 0], radius = 0.05, mass = 1 },
]

[box]
width = 1.0
height = 1.0
boundary = "walls"

[render]
duration = 4.0
caption = ")" +
           words + "\"\n";
}

/// The thumbnail at t = 2 (the caption on screen) of the scene captioned `words`.
collide::Image thumbnail(const TempDir& dir, const std::string& name, const std::string& words) {
    const fs::path scene = dir.path / (name + ".toml");
    const fs::path png = dir.path / (name + ".png");
    collide::test::write_file(scene, scene_with(words));
    const auto r = run_collide("thumbnail " + scene.string() + " -q l --at 2 --progress none -o " +
                               png.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    return collide::video::read_png(png);
}

/// Pixels in the bottom fifth of the frame (where the caption is) that differ.
int differing_caption_pixels(const collide::Image& a, const collide::Image& b) {
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);
    int count = 0;
    for (int y = a.height * 4 / 5; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const std::uint8_t* p = a.pixel(x, y);
            const std::uint8_t* q = b.pixel(x, y);
            count += (p[0] != q[0] || p[1] != q[1] || p[2] != q[2]) ? 1 : 0;
        }
    }
    return count;
}

}  // namespace

TEST_CASE("thumbnail: a Japanese caption is drawn from the fallback font, not as '?'") {
    if (!fs::is_regular_file("/usr/share/fonts/truetype/droid/DroidSansFallbackFull.ttf"))
        COLLIDE_SKIP_TEST("no fallback font (fonts-droid-fallback)");
    TempDir dir("text_scripts");
    // Five characters each: the captions are as wide when each is drawn as '?'.
    const collide::Image japanese = thumbnail(dir, "japanese", "気体の衝突");
    const collide::Image asked = thumbnail(dir, "asked", "?????");
    const collide::Image unknown = thumbnail(dir, "unknown", "\uE000\uE001\uE002\uE003\uE004");
    // Japanese has ink of its own where '?' was drawn...
    CHECK(differing_caption_pixels(japanese, asked) > 200);
    // ... and characters no installed font has (private use) are drawn exactly as '?'.
    CHECK(differing_caption_pixels(unknown, asked) == 0);
    CHECK(unknown.rgba == asked.rgba);
}
