#pragma once
// Internal: text shaped with HarfBuzz and rasterised with FreeType at one size, glyph by glyph as
// text first needs them, into a coverage atlas; and text layout into overlay quads.

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "overlay_geometry.hpp"

namespace collide::render {

/// One font at one pixel size, with the installed fallback fonts (text::installed_fallback_fonts:
/// CJK) for the characters it lacks. A line is split into runs by direction (Unicode's bidi
/// algorithm, FriBidi: Arabic and Hebrew right to left, the Latin words and numbers inside them
/// left to right) and by face (each character from the font when it has it, else the first
/// fallback that does), each run shaped by HarfBuzz (Arabic joined, ligatures, marks, kerning)
/// and the runs put in visual order. A character no face has is drawn as '?' (`collide check`
/// warns about those). Glyphs are rasterised once, when text first uses them, and shaped lines
/// are cached, so a frame's text costs lookups. Move-only; one thread at a time (the caches are
/// filled by the const calls).
class FontAtlas {
  public:
    /// Opens the font (TrueType or OpenType). Throws collide::Error (runtime) naming `path`
    /// when the file is missing or is not a usable font.
    FontAtlas(const std::string& path, float pixel_height);
    ~FontAtlas();
    FontAtlas(FontAtlas&& other) noexcept;
    FontAtlas& operator=(FontAtlas&& other) noexcept;
    FontAtlas(const FontAtlas&) = delete;
    FontAtlas& operator=(const FontAtlas&) = delete;

    /// Appends `text` (UTF-8) with its baseline at `baseline_y` starting at `x`. Returns the x
    /// after the last glyph.
    float add_text(OverlayBatch& batch, float x, float baseline_y, std::string_view text,
                   Rgba8 color) const;
    /// The advance width of `text` in pixels.
    [[nodiscard]] float text_width(std::string_view text) const;

    /// One glyph of a line as add_text draws it.
    struct ShapedGlyph {
        std::size_t face;  ///< 0 the font, 1... the installed fallbacks in order
        unsigned glyph;    ///< the glyph's index in that face ('?' of the font: no face had it)
        std::size_t character;  ///< the first code point it draws: an index into the text's
        float pen_x;            ///< pixels from the line's start to the glyph's pen position
    };
    /// `text` (UTF-8, one line) shaped: its glyphs left to right, as drawn.
    [[nodiscard]] std::vector<ShapedGlyph> shaped(std::string_view text) const;

    /// The height stb_truetype's ScaleForPixelHeight meant: ascender to descender, in pixels.
    [[nodiscard]] float pixel_height() const noexcept { return pixel_height_; }
    [[nodiscard]] float ascent() const noexcept { return ascent_; }
    [[nodiscard]] float line_height() const noexcept { return pixel_height_ * 1.2F; }

    /// The single-channel atlas, atlas_size() bytes a row, holding every glyph drawn so far.
    /// It grows by rows as text needs new glyphs, so take it after the last add_text.
    [[nodiscard]] const std::vector<std::uint8_t>& bitmap() const noexcept;
    [[nodiscard]] int atlas_size() const noexcept;

  private:
    struct Cache;  // the face, the shaper and the caches (font.cpp)
    float pixel_height_ = 0.0F;
    float ascent_ = 0.0F;
    std::unique_ptr<Cache> cache_;
};

/// Greedy word wrap: the words of `text` (split at spaces) in lines no wider than `width` pixels
/// in `font` (a word wider than that gets a line of its own).
[[nodiscard]] std::vector<std::string> wrap_words(const FontAtlas& font, const std::string& text,
                                                  float width);

/// Decodes UTF-8 into code points; malformed bytes become U+FFFD.
[[nodiscard]] std::vector<std::uint32_t> decode_utf8(std::string_view text);

}  // namespace collide::render
