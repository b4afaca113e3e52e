#include "font.hpp"

#include <hb-ft.h>
#include <hb.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <unordered_map>
#include <utility>

#include "collide/error.hpp"
#include "collide/text/font_face.hpp"

namespace collide::render {
namespace {

/// Rasterising: light hinting (vertical only, so glyph widths and the shaper's advances agree)
/// keeps stems and the baseline on whole pixels, crisp at the 10 px of a 320x180 thumbnail; the
/// outlines always, never a font's embedded bitmaps (those exist at some sizes only).
constexpr FT_Int32 raster_flags = FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT | FT_LOAD_NO_BITMAP;

/// Shaped runs kept: every distinct string of a few hundred frames (titles, labels, counters
/// that tick); past that the cache starts over rather than grow with a long video's counters.
constexpr std::size_t max_cached_runs = 4096;

struct HbFontDeleter {
    void operator()(hb_font_t* f) const noexcept { hb_font_destroy(f); }
};
struct HbBufferDeleter {
    void operator()(hb_buffer_t* b) const noexcept { hb_buffer_destroy(b); }
};

struct StringHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const noexcept {
        return std::hash<std::string_view>{}(s);
    }
};

/// The atlas width: a power of two holding a row of about a dozen glyphs of the size, so that
/// shelves are few; tall text gets wide rows, never a glyph wider than the atlas.
int atlas_width_for(float pixel_height) {
    int width = 256;
    while (static_cast<float>(width) < 12.0F * pixel_height && width < 16384) width *= 2;
    return width;
}

/// A glyph rasterised into the atlas.
struct AtlasGlyph {
    int left = 0;  // pixels from the pen to the bitmap's left column
    int top = 0;   // pixels from the baseline up to the bitmap's top row
    std::uint16_t u = 0, v = 0, width = 0, height = 0;
};

/// One glyph of a shaped run: which atlas glyph, where relative to the pen, how far it moves.
struct PlacedGlyph {
    std::uint32_t atlas_glyph;
    float x_offset, y_offset;  // pixels; y up, as the shaper gives them
    float advance;
};

}  // namespace

struct FontAtlas::Cache {
    text::FontFace face;
    std::unique_ptr<hb_font_t, HbFontDeleter> shaper;
    std::unique_ptr<hb_buffer_t, HbBufferDeleter> buffer{hb_buffer_create()};
    FT_UInt question_mark = 0;  // drawn for a character the font lacks

    std::unordered_map<FT_UInt, std::uint32_t> glyph_of;  // font glyph -> index in glyphs
    std::vector<AtlasGlyph> glyphs;
    std::unordered_map<std::string, std::vector<PlacedGlyph>, StringHash, std::equal_to<>> runs;

    // The atlas: rows of `width` bytes, filled shelf by shelf (left to right, then a new shelf
    // below the tallest glyph of the last one).
    std::vector<std::uint8_t> bitmap;
    int width = 256;
    int shelf_x = 0, shelf_y = 0, shelf_height = 0;

    explicit Cache(const std::string& path) : face(path) {}

    std::uint32_t atlas_glyph(FT_UInt index);
    const std::vector<PlacedGlyph>& shape(std::string_view text);
};

std::uint32_t FontAtlas::Cache::atlas_glyph(FT_UInt index) {
    if (const auto it = glyph_of.find(index); it != glyph_of.end()) return it->second;
    AtlasGlyph g;
    const FT_Face f = face.face();
    // A glyph FreeType cannot load (a damaged outline the table checks let through) is blank.
    if (FT_Load_Glyph(f, index, raster_flags) == 0 &&
        f->glyph->bitmap.pixel_mode == FT_PIXEL_MODE_GRAY) {
        const FT_Bitmap& b = f->glyph->bitmap;
        const int w = std::min(static_cast<int>(b.width), width);
        const int h = static_cast<int>(b.rows);
        if (shelf_x + w > width) {
            shelf_y += shelf_height;
            shelf_x = 0;
            shelf_height = 0;
        }
        const std::size_t rows_needed = static_cast<std::size_t>(shelf_y + h);
        if (bitmap.size() < rows_needed * static_cast<std::size_t>(width))
            bitmap.resize(rows_needed * static_cast<std::size_t>(width), 0);
        for (int y = 0; y < h; ++y) {
            const unsigned char* src = b.buffer + static_cast<std::ptrdiff_t>(y) * b.pitch;
            std::memcpy(bitmap.data() + static_cast<std::size_t>(shelf_y + y) * width + shelf_x,
                        src, static_cast<std::size_t>(w));
        }
        g = {f->glyph->bitmap_left,
             f->glyph->bitmap_top,
             static_cast<std::uint16_t>(shelf_x),
             static_cast<std::uint16_t>(shelf_y),
             static_cast<std::uint16_t>(w),
             static_cast<std::uint16_t>(h)};
        shelf_x += w;
        shelf_height = std::max(shelf_height, h);
        // Texel coordinates are 16 bits: past that, glyphs draw blank rather than wrong.
        if (shelf_y + h > 65535) g.width = g.height = 0;
    }
    glyphs.push_back(g);
    const auto slot = static_cast<std::uint32_t>(glyphs.size() - 1);
    glyph_of.emplace(index, slot);
    return slot;
}

const std::vector<PlacedGlyph>& FontAtlas::Cache::shape(std::string_view text) {
    if (const auto it = runs.find(text); it != runs.end()) return it->second;
    if (runs.size() >= max_cached_runs) runs.clear();
    hb_buffer_t* b = buffer.get();
    hb_buffer_clear_contents(b);
    hb_buffer_add_utf8(b, text.data(), static_cast<int>(text.size()), 0,
                       static_cast<int>(text.size()));
    hb_buffer_guess_segment_properties(b);
    hb_shape(shaper.get(), b, nullptr, 0);
    unsigned count = 0;
    const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(b, &count);
    const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(b, &count);
    std::vector<PlacedGlyph> run;
    run.reserve(count);
    constexpr float from_26_6 = 1.0F / 64.0F;
    for (unsigned i = 0; i < count; ++i) {
        FT_UInt index = info[i].codepoint;
        float advance = static_cast<float>(pos[i].x_advance) * from_26_6;
        if (index == 0) {  // the font lacks the character: '?' as before, never a box
            index = question_mark;
            advance =
                static_cast<float>(hb_font_get_glyph_h_advance(shaper.get(), index)) * from_26_6;
        }
        run.push_back({atlas_glyph(index), static_cast<float>(pos[i].x_offset) * from_26_6,
                       static_cast<float>(pos[i].y_offset) * from_26_6, advance});
    }
    return runs.emplace(std::string(text), std::move(run)).first->second;
}

FontAtlas::FontAtlas(const std::string& path, float pixel_height)
    : pixel_height_(pixel_height), cache_(std::make_unique<Cache>(path)) {
    const FT_Face f = cache_->face.face();
    // `pixel_height` is the ascender-to-descender height (what stb_truetype's
    // ScaleForPixelHeight meant, so sizes and layouts stay those of before); FreeType wants
    // the em, in 26.6 pixels.
    const double units = static_cast<double>(f->ascender) - static_cast<double>(f->descender);
    const double em = static_cast<double>(pixel_height) * f->units_per_EM / units;
    const auto em_26_6 = static_cast<FT_F26Dot6>(std::lround(em * 64.0));
    if (!(units > 0.0) || em_26_6 <= 0 || FT_Set_Char_Size(f, em_26_6, em_26_6, 72, 72) != 0) {
        throw_runtime_error("font: '" + path + "' cannot be drawn at " +
                            std::to_string(pixel_height) + " pixels");
    }
    ascent_ = static_cast<float>(static_cast<double>(f->ascender) * em / f->units_per_EM);
    cache_->shaper.reset(hb_ft_font_create_referenced(f));
    // Unhinted advances: widths scale with the size, as a layout measured them.
    hb_ft_font_set_load_flags(cache_->shaper.get(), FT_LOAD_DEFAULT | FT_LOAD_NO_HINTING);
    cache_->question_mark = FT_Get_Char_Index(f, '?');
    cache_->width = atlas_width_for(pixel_height);
}

FontAtlas::~FontAtlas() = default;
FontAtlas::FontAtlas(FontAtlas&& other) noexcept = default;
FontAtlas& FontAtlas::operator=(FontAtlas&& other) noexcept = default;

const std::vector<std::uint8_t>& FontAtlas::bitmap() const noexcept {
    return cache_->bitmap;
}
int FontAtlas::atlas_size() const noexcept {
    return cache_->width;
}

float FontAtlas::add_text(OverlayBatch& batch, float x, float baseline_y, std::string_view text,
                          Rgba8 color) const {
    // Glyphs were rasterised on the pixel grid, so each one lands on whole pixels. The pen
    // advances by fractional widths; a glyph goes to the pixel column whose centre its left edge
    // reaches (ceil(edge - 1/2)), the column a rasteriser fills first for a quad there.
    float pen = std::round(x);
    const float base = std::round(baseline_y);
    for (const PlacedGlyph& p : cache_->shape(text)) {
        const AtlasGlyph& g = cache_->glyphs[p.atlas_glyph];
        if (g.width > 0 && g.height > 0) {
            batch.add_glyph({static_cast<int>(std::ceil(pen + p.x_offset - 0.5F)) + g.left,
                             static_cast<int>(base - std::round(p.y_offset)) - g.top, g.u, g.v,
                             g.width, g.height, color});
        }
        pen += p.advance;
    }
    return pen;
}

float FontAtlas::text_width(std::string_view text) const {
    float width = 0.0F;
    for (const PlacedGlyph& p : cache_->shape(text)) width += p.advance;
    return width;
}

std::vector<std::string> wrap_words(const FontAtlas& font, const std::string& text, float width) {
    // Each word is measured once and the line's width kept as a sum (kerning across a space is
    // left out: a fraction of a pixel): linear in the text, however long its lines.
    const float space = font.text_width(" ");
    std::vector<std::string> lines;
    std::string line;
    float line_width = 0.0F;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find(' ', start), text.size());
        const std::string_view word(text.data() + start, end - start);
        const float word_width = font.text_width(word);
        if (!line.empty() && line_width + space + word_width > width) {
            lines.push_back(std::move(line));
            line.assign(word);
            line_width = word_width;
        } else {
            if (!line.empty()) {
                line += ' ';
                line_width += space;
            }
            line += word;
            line_width += word_width;
        }
        start = end + 1;
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

std::vector<std::uint32_t> decode_utf8(std::string_view text) {
    return text::decode_utf8(text);
}

}  // namespace collide::render
