#pragma once
// Internal: a glyph atlas baked from a TrueType file with stb_truetype (Latin-1, one size), and
// text layout into overlay quads.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "overlay_geometry.hpp"

namespace collide::render {

class FontAtlas {
  public:
    /// Bakes code points 32..255 of the font at `pixel_height`. Throws collide::Error (runtime)
    /// when the file is missing or is not a usable TrueType font.
    FontAtlas(const std::string& path, float pixel_height);

    /// Appends `text` (UTF-8; unknown characters become '?') with its baseline at `baseline_y`
    /// starting at `x`. Returns the x after the last glyph.
    float add_text(OverlayBatch& batch, float x, float baseline_y, std::string_view text,
                   Rgba8 color) const;
    /// The advance width of `text` in pixels.
    [[nodiscard]] float text_width(std::string_view text) const;

    [[nodiscard]] float pixel_height() const noexcept { return pixel_height_; }
    [[nodiscard]] float ascent() const noexcept { return ascent_; }
    [[nodiscard]] float line_height() const noexcept { return pixel_height_ * 1.2F; }

    /// The single-channel atlas (atlas_size x atlas_size bytes) to upload as a texture.
    [[nodiscard]] const std::vector<std::uint8_t>& bitmap() const noexcept { return bitmap_; }
    [[nodiscard]] int atlas_size() const noexcept { return atlas_size_; }

  private:
    struct Glyph {
        float x_offset, y_offset;  // top-left pixel relative to the pen (whole pixels, y down)
        std::uint16_t u, v, width, height;  // texels in the atlas
        float advance;
    };
    [[nodiscard]] const Glyph& glyph(std::uint32_t code_point) const noexcept;

    float pixel_height_ = 0.0F;
    float ascent_ = 0.0F;
    int atlas_size_ = 0;
    std::vector<std::uint8_t> bitmap_;
    std::vector<Glyph> glyphs_;  // code points 32..255
};

/// Greedy word wrap: the words of `text` (split at spaces) in lines no wider than `width` pixels
/// in `font` (a word wider than that gets a line of its own).
[[nodiscard]] std::vector<std::string> wrap_words(const FontAtlas& font, const std::string& text,
                                                  float width);

/// Decodes UTF-8 into code points; malformed bytes become U+FFFD.
[[nodiscard]] std::vector<std::uint32_t> decode_utf8(std::string_view text);

}  // namespace collide::render
