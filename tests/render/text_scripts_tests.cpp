// Text in every language: Greek, Polish, Czech, German, Cyrillic and mathematical characters are
// drawn glyph for glyph as FreeType draws them (not '?', not the font's missing-glyph box), and a
// frame's title card shows them.
#include <doctest/doctest.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "../support/skip.hpp"
#include "collide/render/renderer.hpp"
#include "collide/text/font_face.hpp"
#include "font.hpp"
#include "glyph_blit.hpp"
#include "render_fixtures.hpp"

namespace collide::render {
namespace {

/// Each character of the test, one UTF-8 string each.
const std::vector<std::string> characters = {"Δ", "σ", "η", "π", "≈", "×", "→", "±",
                                             "√", "²",  // Greek and mathematics
                                             "ą", "ę", "ł", "ń", "ś", "ź", "ż", "Ł",  // Polish
                                             "č", "ř", "š", "ž", "ů", "ě",            // Czech
                                             "ß", "ä", "ö", "ü",                      // German
                                             "Д", "ж", "Я", "ы"};                     // Cyrillic

/// FreeType opened directly, at the size FontAtlas promises for `pixel_height` (ascender to
/// descender), rasterising as the renderer documents (light hinting, outlines only).
class Reference {
  public:
    Reference(const std::string& path, float pixel_height) {
        REQUIRE(FT_Init_FreeType(&library_) == 0);
        REQUIRE(FT_New_Face(library_, path.c_str(), 0, &face_) == 0);
        const double em = pixel_height * face_->units_per_EM /
                          (static_cast<double>(face_->ascender) - face_->descender);
        const auto size = static_cast<FT_F26Dot6>(std::lround(em * 64.0));
        REQUIRE(FT_Set_Char_Size(face_, size, size, 72, 72) == 0);
    }
    ~Reference() {
        FT_Done_Face(face_);
        FT_Done_FreeType(library_);
    }
    Reference(const Reference&) = delete;
    Reference& operator=(const Reference&) = delete;

    [[nodiscard]] bool has(std::uint32_t cp) const { return FT_Get_Char_Index(face_, cp) != 0; }

    /// The coverage of `cp` drawn with its origin at (x, baseline) into a black image.
    [[nodiscard]] Image draw(std::uint32_t cp, int x, int baseline, int width, int height) const {
        Image image(width, height);
        REQUIRE(FT_Load_Char(face_, cp,
                             FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT | FT_LOAD_NO_BITMAP) == 0);
        const FT_GlyphSlot g = face_->glyph;
        for (unsigned row = 0; row < g->bitmap.rows; ++row) {
            for (unsigned col = 0; col < g->bitmap.width; ++col) {
                const int px = x + g->bitmap_left + static_cast<int>(col);
                const int py = baseline - g->bitmap_top + static_cast<int>(row);
                if (px < 0 || py < 0 || px >= width || py >= height) continue;
                const std::uint8_t c = g->bitmap.buffer[row * g->bitmap.pitch + col];
                std::uint8_t* p = image.pixel(px, py);
                p[0] = p[1] = p[2] = p[3] = c;
            }
        }
        return image;
    }

  private:
    FT_Library library_ = nullptr;
    FT_Face face_ = nullptr;
};

/// `text` in opaque white on black through the renderer's text path (atlas, then the CPU blend).
Image drawn(const FontAtlas& font, const std::string& text, int x, int baseline, int width,
            int height) {
    Image image(width, height);
    OverlayBatch batch;
    font.add_text(batch, static_cast<float>(x), static_cast<float>(baseline), text,
                  {255, 255, 255, 255});
    blend_glyphs(image, batch.glyphs(), font.bitmap(), font.atlas_size());
    return image;
}

int differing_pixels(const Image& a, const Image& b) {
    int count = 0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) count += a.rgba[i] != b.rgba[i] ? 1 : 0;
    return count;
}

int inked_pixels(const Image& a) {
    int count = 0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) count += a.rgba[i] != 0 ? 1 : 0;
    return count;
}

TEST_CASE(
    "Greek, Polish, Czech, German, Cyrillic and math glyphs are FreeType's, pixel for pixel") {
    const std::string path = RenderConfig{}.font_path;
    if (!std::filesystem::exists(path)) COLLIDE_SKIP_TEST("no DejaVu Sans at " << path);
    constexpr int width = 96, height = 96, x = 24, baseline = 64;
    for (const float pixel_height : {11.0F, 24.0F, 40.0F}) {
        CAPTURE(pixel_height);
        const FontAtlas font(path, pixel_height);
        const Reference reference(path, pixel_height);
        const Image question = drawn(font, "?", x, baseline, width, height);
        for (const std::string& ch : characters) {
            CAPTURE(ch);
            const std::vector<std::uint32_t> cps = text::decode_utf8(ch);
            REQUIRE(cps.size() == 1);
            REQUIRE(reference.has(cps[0]));  // a glyph of its own in DejaVu: not the box
            const Image ours = drawn(font, ch, x, baseline, width, height);
            CHECK(inked_pixels(ours) > 0);
            CHECK(differing_pixels(ours, reference.draw(cps[0], x, baseline, width, height)) == 0);
            CHECK(differing_pixels(ours, question) > 0);  // not '?'
        }
    }
}

TEST_CASE("a character the font lacks is drawn as '?' and reported by missing_characters") {
    const std::string path = RenderConfig{}.font_path;
    if (!std::filesystem::exists(path)) COLLIDE_SKIP_TEST("no DejaVu Sans at " << path);
    const FontAtlas font(path, 24.0F);
    // U+4E2D (CJK) is not in DejaVu Sans.
    const Image cjk = drawn(font, "\u4E2D", 24, 64, 96, 96);
    CHECK(differing_pixels(cjk, drawn(font, "?", 24, 64, 96, 96)) == 0);
    CHECK(font.text_width("\u4E2D") == doctest::Approx(font.text_width("?")));

    const text::FontFace face(path);
    const std::vector<std::uint32_t> missing =
        text::missing_characters(face, "Δt \u4E2D \u2060 \u4E2D ≈ \u3042");
    REQUIRE(missing.size() == 2);  // each once; the word joiner U+2060 needs no glyph
    CHECK(missing[0] == 0x4E2D);
    CHECK(missing[1] == 0x3042);  // Hiragana: not in DejaVu either
    CHECK(text::describe_character(0x394) == "'Δ' (U+0394)");
    CHECK(text::describe_character(0x7) == "U+0007");
    CHECK(face.name() == "DejaVu Sans");
}

TEST_CASE("the title card shows Greek and mathematical text, not '?'") {
    RenderConfig config = test::small_config(true);
    config.overlays = OverlayLevel::lesson;  // the level that shows the title card
    if (!std::filesystem::exists(config.font_path)) {
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << config.font_path);
    }
    Renderer renderer(config, test::test_backend());
    const Snapshot s = test::gas_snapshot(0, 0.05, {1.0, 1.0, Boundary::walls}, 1);
    const auto card = [&](const std::string& title, const std::string& text) {
        FrameContent frame;
        frame.panels = {{&s, "", {""}}};
        frame.intro_title = title;
        frame.intro_text = text;
        frame.intro_opacity = 1.0F;
        return renderer.render(frame);
    };
    const Image greek = card("Δt ≈ 0.01 s, σ → η", "Zażółć gęślą jaźń; příliš žluťoučký");
    const Image asked = card("?t ? 0.01 s, ? ? ?", "Za???? g??l? ja??; p??li? ?lu?ou?k?");
    test::dump_if_requested(greek, "text_scripts_card");
    CHECK(differing_pixels(greek, asked) > 50);
}

}  // namespace
}  // namespace collide::render
