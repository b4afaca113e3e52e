// Text in every language: Greek, Polish, Czech, German, Cyrillic and mathematical characters are
// drawn glyph for glyph as FreeType draws them (not '?', not the font's missing-glyph box), and a
// frame's title card shows them; Japanese comes from the fallback font; Arabic is joined and,
// with Hebrew, drawn right to left, in mixed lines too.
#include <doctest/doctest.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
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
    /// `path` at the em of `sized_as` (the main font, whose ascender-to-descender height is
    /// `pixel_height`): a fallback face is drawn at the main font's em.
    Reference(const std::string& path, float pixel_height, const std::string& sized_as = {}) {
        REQUIRE(FT_Init_FreeType(&library_) == 0);
        FT_Face metrics = nullptr;
        REQUIRE(FT_New_Face(library_, (sized_as.empty() ? path : sized_as).c_str(), 0, &metrics) ==
                0);
        const double em = pixel_height * metrics->units_per_EM /
                          (static_cast<double>(metrics->ascender) - metrics->descender);
        FT_Done_Face(metrics);
        REQUIRE(FT_New_Face(library_, path.c_str(), 0, &face_) == 0);
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

TEST_CASE("a character no font has is drawn as '?' and reported by missing_characters") {
    const std::string path = RenderConfig{}.font_path;
    if (!std::filesystem::exists(path)) COLLIDE_SKIP_TEST("no DejaVu Sans at " << path);
    const FontAtlas font(path, 24.0F);
    // U+E000 (private use) is in no font installed: not DejaVu, not a fallback.
    const Image unknown = drawn(font, "\uE000", 24, 64, 96, 96);
    CHECK(differing_pixels(unknown, drawn(font, "?", 24, 64, 96, 96)) == 0);
    CHECK(font.text_width("\uE000") == doctest::Approx(font.text_width("?")));

    const text::FontFace face(path);
    const std::vector<std::uint32_t> missing =
        text::missing_characters(face, "Δt \u4E2D \u2060 \u4E2D ≈ \u3042");
    REQUIRE(missing.size() == 2);  // each once; the word joiner U+2060 needs no glyph
    CHECK(missing[0] == 0x4E2D);   // CJK: not in DejaVu Sans
    CHECK(missing[1] == 0x3042);   // Hiragana: not in DejaVu either
    CHECK(text::describe_character(0x394) == "'Δ' (U+0394)");
    CHECK(text::describe_character(0x7) == "U+0007");
    CHECK(face.name() == "DejaVu Sans");
}

/// The first installed fallback font, or "" (the tests that need one skip).
std::string first_fallback() {
    const std::vector<std::string> fallbacks = text::installed_fallback_fonts();
    return fallbacks.empty() ? std::string() : fallbacks.front();
}

TEST_CASE("missing_characters over the font and its fallbacks names only what no font has") {
    const std::string path = RenderConfig{}.font_path;
    const std::string fallback = first_fallback();
    if (!std::filesystem::exists(path) || fallback.empty())
        COLLIDE_SKIP_TEST("no DejaVu Sans or no fallback font (fonts-droid-fallback)");
    const text::FontFace main(path);
    const text::FontFace extra(fallback);
    const std::vector<std::uint32_t> missing =
        text::missing_characters({&main, &extra}, "気体の衝突 \uE000 Δt \u0378 \uE000 \u4E2D");
    REQUIRE(missing.size() == 2);  // private use and unassigned; the Japanese is in the fallback
    CHECK(missing[0] == 0xE000);
    CHECK(missing[1] == 0x0378);
}

TEST_CASE("Japanese is drawn from the fallback font, glyph for glyph, beside the font's Latin") {
    const std::string path = RenderConfig{}.font_path;
    const std::string fallback = first_fallback();
    if (!std::filesystem::exists(path) || fallback.empty())
        COLLIDE_SKIP_TEST("no DejaVu Sans or no fallback font (fonts-droid-fallback)");
    constexpr int width = 96, height = 96, x = 24, baseline = 64;
    for (const float pixel_height : {11.0F, 24.0F, 40.0F}) {
        CAPTURE(pixel_height);
        const FontAtlas font(path, pixel_height);
        const Reference reference(fallback, pixel_height, path);
        const Image question = drawn(font, "?", x, baseline, width, height);
        for (const std::string ch : {"気", "体", "の", "衝", "突", "ア", "。"}) {
            CAPTURE(ch);
            const std::vector<std::uint32_t> cps = text::decode_utf8(ch);
            REQUIRE(reference.has(cps[0]));
            const Image ours = drawn(font, ch, x, baseline, width, height);
            CHECK(inked_pixels(ours) > 0);
            CHECK(differing_pixels(ours, question) > 0);  // not '?'
            CHECK(differing_pixels(ours, reference.draw(cps[0], x, baseline, width, height)) == 0);
        }
        // A mixed line: Latin from the font, the Japanese from the fallback, left to right.
        const std::vector<FontAtlas::ShapedGlyph> line = font.shaped("Gas 気体 2");
        REQUIRE(line.size() == 8);
        for (std::size_t i = 0; i < line.size(); ++i) {
            CAPTURE(i);
            CHECK(line[i].character == i);
            CHECK(line[i].glyph != 0);
            if (i > 0) CHECK(line[i].pen_x > line[i - 1].pen_x);
        }
        CHECK(line[0].face == 0);
        CHECK(line[4].face == 1);
        CHECK(line[5].face == 1);
        CHECK(line[7].face == 0);
    }
}

/// The glyph of `cp` shaped alone (its isolated form).
unsigned isolated_glyph(const FontAtlas& font, const std::string& cp) {
    const std::vector<FontAtlas::ShapedGlyph> alone = font.shaped(cp);
    REQUIRE(alone.size() == 1);
    return alone[0].glyph;
}

/// The glyph drawing the `index`th character of `line`.
const FontAtlas::ShapedGlyph& glyph_of(const std::vector<FontAtlas::ShapedGlyph>& line,
                                       std::size_t index) {
    const auto it = std::find_if(line.begin(), line.end(),
                                 [index](const auto& g) { return g.character == index; });
    REQUIRE(it != line.end());
    return *it;
}

TEST_CASE("Arabic is joined and drawn right to left, alone and inside a Latin line") {
    const std::string path = RenderConfig{}.font_path;
    if (!std::filesystem::exists(path)) COLLIDE_SKIP_TEST("no DejaVu Sans at " << path);
    for (const float pixel_height : {11.0F, 24.0F}) {
        CAPTURE(pixel_height);
        const FontAtlas font(path, pixel_height);
        // بيت: beh, yeh, teh: initial, medial and final forms, none the isolated one.
        const std::vector<FontAtlas::ShapedGlyph> word = font.shaped("بيت");
        REQUIRE(word.size() == 3);
        CHECK(glyph_of(word, 0).glyph != isolated_glyph(font, "ب"));
        CHECK(glyph_of(word, 1).glyph != isolated_glyph(font, "ي"));
        CHECK(glyph_of(word, 2).glyph != isolated_glyph(font, "ت"));
        // The first logical character is drawn rightmost.
        CHECK(glyph_of(word, 0).pen_x > glyph_of(word, 1).pen_x);
        CHECK(glyph_of(word, 1).pen_x > glyph_of(word, 2).pen_x);

        // In a Latin line the Latin reads left to right and the Arabic word right to left, still
        // joined: "Gas " then the word's last letter leftmost, then " ok".
        const std::vector<FontAtlas::ShapedGlyph> mixed = font.shaped("Gas بيت ok");
        REQUIRE(mixed.size() == 10);
        CHECK(glyph_of(mixed, 0).pen_x < glyph_of(mixed, 1).pen_x);
        CHECK(glyph_of(mixed, 2).pen_x < glyph_of(mixed, 6).pen_x);
        CHECK(glyph_of(mixed, 6).pen_x < glyph_of(mixed, 5).pen_x);
        CHECK(glyph_of(mixed, 5).pen_x < glyph_of(mixed, 4).pen_x);
        CHECK(glyph_of(mixed, 4).pen_x < glyph_of(mixed, 8).pen_x);
        CHECK(glyph_of(mixed, 8).pen_x < glyph_of(mixed, 9).pen_x);
        CHECK(glyph_of(mixed, 4).glyph == glyph_of(word, 0).glyph);  // joined as alone
        CHECK(glyph_of(mixed, 6).glyph == glyph_of(word, 2).glyph);
    }
}

TEST_CASE("Hebrew is drawn right to left, and a Latin word inside it left to right") {
    const std::string path = RenderConfig{}.font_path;
    if (!std::filesystem::exists(path)) COLLIDE_SKIP_TEST("no DejaVu Sans at " << path);
    const FontAtlas font(path, 24.0F);
    // "שלום abc": a right-to-left line (its first strong character is Hebrew), so "abc" stands
    // at the left, read left to right, and שלום to its right, its first letter rightmost.
    const std::vector<FontAtlas::ShapedGlyph> line = font.shaped("שלום abc");
    REQUIRE(line.size() == 8);
    CHECK(glyph_of(line, 5).pen_x < glyph_of(line, 6).pen_x);
    CHECK(glyph_of(line, 6).pen_x < glyph_of(line, 7).pen_x);
    CHECK(glyph_of(line, 7).pen_x < glyph_of(line, 3).pen_x);
    for (std::size_t i = 0; i < 3; ++i) {
        CAPTURE(i);
        CHECK(glyph_of(line, i).pen_x > glyph_of(line, i + 1).pen_x);
    }
    CHECK(line.front().character == 5);  // 'a' leftmost
    CHECK(line.back().character == 0);   // 'ש' rightmost
    // Its width is that of its parts: the order changes, not the advances.
    CHECK(font.text_width("שלום abc") ==
          doctest::Approx(font.text_width("שלום") + font.text_width(" abc")).epsilon(0.02));
}

TEST_CASE("the title card shows Greek and mathematical text, not '?'") {
    const RenderConfig config = test::lesson_config(320, 180);  // the level of the title card
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

    if (first_fallback().empty()) return;  // Japanese needs the fallback font
    const Image japanese = card("気体の衝突", "分子は箱の中で衝突する");
    const Image japanese_asked = card("?????", "???????????");
    test::dump_if_requested(japanese, "text_scripts_card_japanese");
    CHECK(differing_pixels(japanese, japanese_asked) > 50);
}

}  // namespace
}  // namespace collide::render
