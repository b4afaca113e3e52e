#include "font.hpp"

#include <fribidi.h>
#include <hb-ft.h>
#include <hb.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
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

/// One glyph of a shaped run: which atlas glyph, where relative to the pen, how far it moves;
/// and, for FontAtlas::shaped, which face and glyph it is and the character it starts from.
struct PlacedGlyph {
    std::uint32_t atlas_glyph;
    float x_offset, y_offset;  // pixels; y up, as the shaper gives them
    float advance;
    std::size_t face;
    FT_UInt glyph;
    std::size_t character;  // index into the text's code points
};

/// A face the atlas draws from (the font, or a fallback) with its shaper, at the atlas's size.
struct ShapingFace {
    text::FontFace face;
    std::unique_ptr<hb_font_t, HbFontDeleter> shaper;

    /// Sets `face` to the em size `em_26_6` (26.6 pixels); `shaper` stays null when FreeType
    /// cannot.
    ShapingFace(text::FontFace opened, FT_F26Dot6 em_26_6) : face(std::move(opened)) {
        if (FT_Set_Char_Size(face.face(), em_26_6, em_26_6, 72, 72) != 0) return;
        shaper.reset(hb_ft_font_create_referenced(face.face()));
        // Unhinted advances: widths scale with the size, as a layout measured them.
        hb_ft_font_set_load_flags(shaper.get(), FT_LOAD_DEFAULT | FT_LOAD_NO_HINTING);
    }
};

/// A stretch of a line's characters drawn in one direction with one face.
struct Run {
    std::size_t start = 0, length = 0;  // code points
    int level = 0;                      // the bidi embedding level: odd is right to left
    std::size_t face = 0;
};

/// The characters' embedding levels (Unicode's bidi algorithm through FriBidi), the paragraph's
/// direction taken from its first strong character: an Arabic or Hebrew line reads right to
/// left, numbers and Latin words inside it left to right. All 0 when FriBidi fails (out of
/// memory): the line is drawn in logical order rather than not at all.
std::vector<int> bidi_levels(const std::vector<std::uint32_t>& text) {
    if (text.empty()) return {};
    const auto n = static_cast<FriBidiStrIndex>(text.size());
    std::vector<FriBidiCharType> types(text.size());
    std::vector<FriBidiBracketType> brackets(text.size());
    std::vector<FriBidiLevel> levels(text.size(), 0);
    fribidi_get_bidi_types(text.data(), n, types.data());
    fribidi_get_bracket_types(text.data(), n, types.data(), brackets.data());
    FriBidiParType direction = FRIBIDI_PAR_ON;
    if (fribidi_get_par_embedding_levels_ex(types.data(), brackets.data(), n, &direction,
                                            levels.data()) == 0) {
        std::fill(levels.begin(), levels.end(), 0);
    }
    return {levels.begin(), levels.end()};
}

/// Puts `runs` (in logical order) in visual order, left to right: from the highest level down
/// to the lowest odd one, every stretch of runs at that level or above is reversed (rule L2).
void to_visual_order(std::vector<Run>& runs) {
    int highest = 0, lowest_odd = std::numeric_limits<int>::max();
    for (const Run& r : runs) {
        highest = std::max(highest, r.level);
        if (r.level % 2 == 1) lowest_odd = std::min(lowest_odd, r.level);
    }
    for (int level = highest; level >= lowest_odd; --level) {
        for (std::size_t i = 0; i < runs.size();) {
            if (runs[i].level < level) {
                ++i;
                continue;
            }
            std::size_t end = i;
            while (end < runs.size() && runs[end].level >= level) ++end;
            std::reverse(runs.begin() + static_cast<std::ptrdiff_t>(i),
                         runs.begin() + static_cast<std::ptrdiff_t>(end));
            i = end;
        }
    }
}

/// A combining mark (of no script of its own: it takes its base's).
bool is_combining(std::uint32_t cp) {
    return hb_unicode_script(hb_unicode_funcs_get_default(), cp) == HB_SCRIPT_INHERITED;
}

}  // namespace

struct FontAtlas::Cache {
    ShapingFace main;
    // Fallback faces, opened the first time a character the main face lacks is met (most text
    // never needs them); one that cannot be opened stays null, and its characters draw as '?'.
    std::vector<std::string> fallback_paths = text::installed_fallback_fonts();
    std::vector<std::unique_ptr<ShapingFace>> fallbacks;
    std::size_t fallbacks_opened = 0;
    FT_F26Dot6 em_26_6 = 0;

    std::unique_ptr<hb_buffer_t, HbBufferDeleter> buffer{hb_buffer_create()};
    FT_UInt question_mark = 0;  // drawn for a character no face has

    std::unordered_map<std::uint64_t, std::uint32_t> glyph_of;  // (face, glyph) -> in glyphs
    std::vector<AtlasGlyph> glyphs;
    std::unordered_map<std::string, std::vector<PlacedGlyph>, StringHash, std::equal_to<>> runs;

    // The atlas: rows of `width` bytes, filled shelf by shelf (left to right, then a new shelf
    // below the tallest glyph of the last one).
    std::vector<std::uint8_t> bitmap;
    int width = 256;
    int shelf_x = 0, shelf_y = 0, shelf_height = 0;

    Cache(text::FontFace font, FT_F26Dot6 em) : main(std::move(font), em), em_26_6(em) {}

    const ShapingFace* face(std::size_t index);
    std::size_t face_for(std::uint32_t cp, const std::size_t* previous);
    std::vector<Run> runs_of(const std::vector<std::uint32_t>& text);
    void shape_run(const std::vector<std::uint32_t>& text, const Run& run,
                   std::vector<PlacedGlyph>& out);
    std::uint32_t atlas_glyph(std::size_t face_index, FT_UInt glyph);
    const std::vector<PlacedGlyph>& shape(std::string_view text);
};

/// Face 0 is the font; 1... the installed fallbacks in order (null when unusable).
const ShapingFace* FontAtlas::Cache::face(std::size_t index) {
    if (index == 0) return &main;
    while (fallbacks_opened < index && fallbacks_opened < fallback_paths.size()) {
        const std::string& path = fallback_paths[fallbacks_opened++];
        std::unique_ptr<ShapingFace> opened;
        try {
            opened = std::make_unique<ShapingFace>(
                text::FontFace(path, {}, text::fallback_font_package(path)), em_26_6);
            if (!opened->shaper) opened.reset();
        } catch (const Error&) {
            // `collide check` names a fallback that cannot be opened; here its characters are
            // drawn as '?', as if it were not installed.
        }
        fallbacks.push_back(std::move(opened));
    }
    return index <= fallbacks.size() ? fallbacks[index - 1].get() : nullptr;
}

/// The face that draws `cp`: the font when it has it, else the first fallback that does, else
/// the font ('?'). Joiners and combining marks stay in the face of the character before them
/// (when it has the mark), so that they are shaped with it; spaces, digits and punctuation come
/// from the font when it has them, as in every other line.
std::size_t FontAtlas::Cache::face_for(std::uint32_t cp, const std::size_t* previous) {
    if (previous != nullptr) {
        if (text::needs_no_glyph(cp)) return *previous;
        if (is_combining(cp) && face(*previous)->face.has_character(cp)) return *previous;
    }
    if (main.face.has_character(cp)) return 0;
    for (std::size_t k = 1; k <= fallback_paths.size(); ++k) {
        const ShapingFace* f = face(k);
        if (f != nullptr && f->face.has_character(cp)) return k;
    }
    return 0;
}

/// The runs of `text` (one line) in visual order: split where the embedding level or the face
/// changes.
std::vector<Run> FontAtlas::Cache::runs_of(const std::vector<std::uint32_t>& text) {
    const std::vector<int> levels = bidi_levels(text);
    std::vector<Run> out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const std::size_t* previous = out.empty() ? nullptr : &out.back().face;
        const std::size_t f = face_for(text[i], previous);
        if (out.empty() || out.back().level != levels[i] || out.back().face != f) {
            out.push_back({i, 0, levels[i], f});
        }
        ++out.back().length;
    }
    to_visual_order(out);
    return out;
}

void FontAtlas::Cache::shape_run(const std::vector<std::uint32_t>& text, const Run& run,
                                 std::vector<PlacedGlyph>& out) {
    const ShapingFace& shaping = *face(run.face);
    hb_buffer_t* b = buffer.get();
    hb_buffer_clear_contents(b);
    // The whole line as context: Arabic letters join across a change of face.
    // (UTF-32 checked: a value beyond Unicode, from a malformed UTF-8 sequence, becomes U+FFFD.)
    hb_buffer_add_utf32(b, text.data(), static_cast<int>(text.size()),
                        static_cast<unsigned>(run.start), static_cast<int>(run.length));
    hb_buffer_set_direction(b, run.level % 2 == 1 ? HB_DIRECTION_RTL : HB_DIRECTION_LTR);
    hb_buffer_guess_segment_properties(b);  // the script and language
    hb_shape(shaping.shaper.get(), b, nullptr, 0);
    unsigned count = 0;
    const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(b, &count);
    const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(b, &count);
    constexpr float from_26_6 = 1.0F / 64.0F;
    for (unsigned i = 0; i < count; ++i) {
        std::size_t face_index = run.face;
        FT_UInt index = info[i].codepoint;
        float advance = static_cast<float>(pos[i].x_advance) * from_26_6;
        if (index == 0) {  // no face has the character: '?' as before, never a box
            face_index = 0;
            index = question_mark;
            advance = static_cast<float>(hb_font_get_glyph_h_advance(main.shaper.get(), index)) *
                      from_26_6;
        }
        out.push_back({atlas_glyph(face_index, index),
                       static_cast<float>(pos[i].x_offset) * from_26_6,
                       static_cast<float>(pos[i].y_offset) * from_26_6, advance, face_index, index,
                       info[i].cluster});
    }
}

std::uint32_t FontAtlas::Cache::atlas_glyph(std::size_t face_index, FT_UInt index) {
    const std::uint64_t key = (static_cast<std::uint64_t>(face_index) << 32) | index;
    if (const auto it = glyph_of.find(key); it != glyph_of.end()) return it->second;
    AtlasGlyph g;
    const FT_Face f = face(face_index)->face.face();
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
    glyph_of.emplace(key, slot);
    return slot;
}

/// `text` (one line) as glyphs in visual order, left to right: each run shaped with its face and
/// direction (HarfBuzz gives a right-to-left run's glyphs already reversed).
const std::vector<PlacedGlyph>& FontAtlas::Cache::shape(std::string_view text) {
    if (const auto it = runs.find(text); it != runs.end()) return it->second;
    if (runs.size() >= max_cached_runs) runs.clear();
    const std::vector<std::uint32_t> characters = text::decode_utf8(text);
    std::vector<PlacedGlyph> placed;
    placed.reserve(characters.size());
    for (const Run& run : runs_of(characters)) shape_run(characters, run, placed);
    return runs.emplace(std::string(text), std::move(placed)).first->second;
}

namespace {

/// FreeType's em in pixels for `pixel_height`, the ascender-to-descender height (what
/// stb_truetype's ScaleForPixelHeight meant, so sizes and layouts stay those of before); 0 when
/// the font has no such height.
double em_for(const text::FontFace& font, float pixel_height) {
    const FT_Face f = font.face();
    const double units = static_cast<double>(f->ascender) - static_cast<double>(f->descender);
    if (!(units > 0.0)) return 0.0;
    return static_cast<double>(pixel_height) * f->units_per_EM / units;
}

}  // namespace

FontAtlas::FontAtlas(const std::string& path, float pixel_height) : pixel_height_(pixel_height) {
    text::FontFace font(path);
    const double em = em_for(font, pixel_height);
    const auto em_26_6 = static_cast<FT_F26Dot6>(std::lround(em * 64.0));
    if (em_26_6 > 0) cache_ = std::make_unique<Cache>(std::move(font), em_26_6);
    if (em_26_6 <= 0 || !cache_->main.shaper) {
        throw_runtime_error("font: '" + path + "' cannot be drawn at " +
                            std::to_string(pixel_height) + " pixels");
    }
    const FT_Face f = cache_->main.face.face();
    ascent_ = static_cast<float>(static_cast<double>(f->ascender) * em / f->units_per_EM);
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

std::vector<FontAtlas::ShapedGlyph> FontAtlas::shaped(std::string_view text) const {
    std::vector<ShapedGlyph> out;
    float pen = 0.0F;
    for (const PlacedGlyph& p : cache_->shape(text)) {
        out.push_back({p.face, p.glyph, p.character, pen + p.x_offset});
        pen += p.advance;
    }
    return out;
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
