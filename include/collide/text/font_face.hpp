#pragma once
/// \file
/// A font file opened with FreeType, without GL: which characters it has (for `collide check`)
/// and the face the renderer rasterises glyphs from. collide_text links FreeType only, so the
/// program `collide` may use it (no GL, no libav among its NEEDED entries).

#include <ft2build.h>
#include FT_FREETYPE_H

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace collide::text {

/// The largest font file read (256 MiB): the largest fonts in use (CJK collections) are a tenth
/// of it; a file beyond it is refused before it is read (docs/limits.md).
inline constexpr std::uint64_t max_font_file_bytes = 256ULL * 1024 * 1024;

/// One font file (TrueType, OpenType or the first font of a collection) opened with FreeType:
/// the library instance and the face, owned together. Move-only; not shared between threads.
class FontFace {
  public:
    /// Reads and checks the file (at most max_font_file_bytes; every table within the file and
    /// matching its checksum: a damaged font is refused here, not met as wrong glyphs later).
    /// Throws collide::Error naming `path` when it cannot be read or is not a usable font:
    /// with `chosen_by` empty (a font the search found), a runtime error advising to reinstall
    /// fonts-dejavu-core; else an input error that names `chosen_by`, the option or variable the
    /// user gave the file with ("--font", "$COLLIDE_FONT"). `package` is the Debian package the
    /// runtime error advises to reinstall (a fallback font's is not DejaVu's).
    explicit FontFace(const std::string& path, std::string_view chosen_by = {},
                      std::string_view package = "fonts-dejavu-core");
    ~FontFace();
    FontFace(FontFace&& other) noexcept;
    FontFace& operator=(FontFace&& other) noexcept;
    FontFace(const FontFace&) = delete;
    FontFace& operator=(const FontFace&) = delete;

    /// True when the font maps `code_point` to a glyph of its own (not the "missing" box).
    [[nodiscard]] bool has_character(std::uint32_t code_point) const;
    /// "DejaVu Sans"-like: the family and style names the file gives.
    [[nodiscard]] std::string name() const;
    [[nodiscard]] const std::string& path() const noexcept { return path_; }
    /// The FreeType face, for the renderer's rasteriser; owned by this object.
    [[nodiscard]] FT_Face face() const noexcept { return face_; }

  private:
    void release() noexcept;

    std::string path_;
    std::vector<unsigned char> data_;  // FreeType reads the face from here: lives as long
    FT_Library library_ = nullptr;
    FT_Face face_ = nullptr;
};

/// The fallback fonts installed here, in the order they are asked for a character the main font
/// lacks (CJK, above all): Droid Sans Fallback (Debian's fonts-droid-fallback, Fedora's
/// google-droid-sans-fonts), then Noto Sans CJK (fonts-noto-cjk; Fedora, Arch). Only paths that
/// are regular files; none opened or checked here.
[[nodiscard]] std::vector<std::string> installed_fallback_fonts();

/// The Debian package that installs the fallback font at `path` (for a message that advises to
/// reinstall it).
[[nodiscard]] std::string_view fallback_font_package(std::string_view path);

/// True for the characters a shaper draws as nothing (Unicode's default ignorables: joiners,
/// variation selectors, spaces of zero width; and the C0/C1 controls): no font needs a glyph.
[[nodiscard]] bool needs_no_glyph(std::uint32_t code_point);

/// Decodes UTF-8 into code points; malformed bytes become U+FFFD.
[[nodiscard]] std::vector<std::uint32_t> decode_utf8(std::string_view text);

/// The characters of `text` (UTF-8) that `font` has no glyph for, each once, in the order they
/// first appear. Characters drawn as nothing need no glyph (controls, spaces of zero width,
/// joiners, variation selectors) and are never reported.
[[nodiscard]] std::vector<std::uint32_t> missing_characters(const FontFace& font,
                                                            std::string_view text);

/// The characters of `text` (UTF-8) that none of `fonts` has (the main font and its fallbacks:
/// what the renderer draws as '?'), each once, in the order they first appear; as above.
[[nodiscard]] std::vector<std::uint32_t> missing_characters(
    const std::vector<const FontFace*>& fonts, std::string_view text);

/// A character for a message: "'Δ' (U+0394)", or "U+0007" alone for one that cannot be shown.
[[nodiscard]] std::string describe_character(std::uint32_t code_point);

}  // namespace collide::text
