#include "font.hpp"

#include <stb_truetype.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

#include "collide/error.hpp"

namespace collide::render {
namespace {

constexpr std::uint32_t first_code_point = 32;
constexpr std::uint32_t code_point_count = 224;  // 32..255: ASCII and Latin-1 (×, ², ±, ·)

std::vector<unsigned char> read_font_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw_runtime_error(
            "font: cannot open '" + path +
            "' (install fonts-dejavu-core, or give a TrueType font with --font FILE or "
            "$COLLIDE_FONT)");
    }
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::uint32_t big_endian(const std::vector<unsigned char>& data, std::size_t at, int bytes) {
    std::uint32_t value = 0;
    for (int i = 0; i < bytes; ++i) value = (value << 8) | data[at + static_cast<std::size_t>(i)];
    return value;
}

/// stb_truetype trusts every offset in the file: a truncated or corrupt font makes it read far
/// beyond the data (SIGSEGV). So before it sees the file: the table directory must lie within
/// it, every table too, the tables stb_truetype needs must be there, and each table (but
/// 'head', which holds the whole file's adjustment) must match its checksum, which catches
/// damage inside a table as well.
void check_truetype(const std::vector<unsigned char>& data, const std::string& path) {
    const auto unusable = [&path](const std::string& why) {
        throw_runtime_error("font: '" + path + "' is not a usable TrueType font (" + why +
                            "); reinstall fonts-dejavu-core");
    };
    constexpr std::size_t directory_header = 12;
    constexpr std::size_t record_size = 16;
    if (data.size() < directory_header + 4) unusable("too short");
    std::size_t offset = 0;
    if (big_endian(data, 0, 4) == 0x74746366U) {  // 'ttcf': a collection; its first font
        offset = big_endian(data, 12, 4);
    }
    if (offset > data.size() || data.size() - offset < directory_header) unusable("truncated");
    const std::size_t tables = big_endian(data, offset + 4, 2);
    if (data.size() - offset - directory_header < tables * record_size) unusable("truncated");
    int needed = 0;
    for (std::size_t t = 0; t < tables; ++t) {
        const std::size_t record = offset + directory_header + t * record_size;
        const std::uint32_t tag = big_endian(data, record, 4);
        const std::uint32_t checksum = big_endian(data, record + 4, 4);
        const std::uint64_t start = big_endian(data, record + 8, 4);
        const std::uint64_t length = big_endian(data, record + 12, 4);
        if (start + length > data.size()) unusable("truncated");
        for (const char* name : {"cmap", "head", "hhea", "hmtx", "loca", "glyf", "maxp"}) {
            std::uint32_t wanted = 0;
            for (int i = 0; i < 4; ++i)
                wanted = (wanted << 8) | static_cast<unsigned char>(name[i]);
            if (tag == wanted) ++needed;
        }
        if (tag == 0x68656164U) continue;  // 'head'
        std::uint32_t sum = 0;
        for (std::uint64_t at = start; at < start + length; at += 4) {
            std::uint32_t word = 0;
            for (std::uint64_t b = at; b < at + 4; ++b) {
                word = (word << 8) | (b < start + length ? data[static_cast<std::size_t>(b)] : 0U);
            }
            sum += word;
        }
        if (sum != checksum) unusable("damaged: a table's checksum does not match");
    }
    if (needed < 7) unusable("tables missing");
}

}  // namespace

std::vector<std::uint32_t> decode_utf8(std::string_view text) {
    std::vector<std::uint32_t> out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto byte = static_cast<unsigned char>(text[i]);
        int extra = 0;
        std::uint32_t cp = 0;
        if (byte < 0x80) {
            cp = byte;
        } else if ((byte & 0xE0) == 0xC0) {
            cp = byte & 0x1F;
            extra = 1;
        } else if ((byte & 0xF0) == 0xE0) {
            cp = byte & 0x0F;
            extra = 2;
        } else if ((byte & 0xF8) == 0xF0) {
            cp = byte & 0x07;
            extra = 3;
        } else {
            out.push_back(0xFFFD);
            ++i;
            continue;
        }
        if (i + static_cast<std::size_t>(extra) >= text.size() && extra > 0) {
            out.push_back(0xFFFD);  // truncated sequence at the end
            break;
        }
        bool valid = true;
        for (int k = 1; k <= extra; ++k) {
            const auto next = static_cast<unsigned char>(text[i + static_cast<std::size_t>(k)]);
            if ((next & 0xC0) != 0x80) {
                valid = false;
                break;
            }
            cp = (cp << 6) | (next & 0x3F);
        }
        if (!valid) {
            out.push_back(0xFFFD);
            ++i;
            continue;
        }
        out.push_back(cp);
        i += static_cast<std::size_t>(extra) + 1;
    }
    return out;
}

FontAtlas::FontAtlas(const std::string& path, float pixel_height) : pixel_height_(pixel_height) {
    const std::vector<unsigned char> data = read_font_file(path);
    check_truetype(data, path);
    stbtt_fontinfo info;
    if (data.empty() ||
        stbtt_InitFont(&info, data.data(), stbtt_GetFontOffsetForIndex(data.data(), 0)) == 0) {
        throw_runtime_error("font: '" + path + "' is not a usable TrueType font");
    }
    int ascent = 0, descent = 0, gap = 0;
    stbtt_GetFontVMetrics(&info, &ascent, &descent, &gap);
    ascent_ = static_cast<float>(ascent) * stbtt_ScaleForPixelHeight(&info, pixel_height);

    // 224 glyphs fit 256x256 up to ~20 px, 512x512 up to ~48 px, 1024 up to ~90 px (4K lesson
    // text); larger text (frames beyond 4K) gets the next size that holds them all.
    atlas_size_ = pixel_height <= 20.0F   ? 256
                  : pixel_height <= 48.0F ? 512
                  : pixel_height <= 88.0F ? 1024
                                          : 2048;
    constexpr int largest_atlas = 8192;
    std::vector<stbtt_bakedchar> baked(code_point_count);
    for (;; atlas_size_ *= 2) {
        bitmap_.assign(static_cast<std::size_t>(atlas_size_) * atlas_size_, 0);
        const int rows_used = stbtt_BakeFontBitmap(
            data.data(), static_cast<int>(stbtt_GetFontOffsetForIndex(data.data(), 0)),
            pixel_height, bitmap_.data(), atlas_size_, atlas_size_,
            static_cast<int>(first_code_point), static_cast<int>(code_point_count), baked.data());
        if (rows_used > 0) break;
        if (atlas_size_ >= largest_atlas) {
            throw_runtime_error("font: glyphs of '" + path + "' do not fit the atlas at this size");
        }
    }
    glyphs_.reserve(code_point_count);
    for (const stbtt_bakedchar& b : baked) {
        // stbtt bakes each glyph box at whole-pixel offsets; the atlas is at most 1024 texels.
        glyphs_.push_back({b.xoff, b.yoff, b.x0, b.y0, static_cast<std::uint16_t>(b.x1 - b.x0),
                           static_cast<std::uint16_t>(b.y1 - b.y0), b.xadvance});
    }
}

const FontAtlas::Glyph& FontAtlas::glyph(std::uint32_t code_point) const noexcept {
    if (code_point < first_code_point || code_point >= first_code_point + code_point_count) {
        code_point = '?';
    }
    return glyphs_[code_point - first_code_point];
}

float FontAtlas::add_text(OverlayBatch& batch, float x, float baseline_y, std::string_view text,
                          Rgba8 color) const {
    // Glyphs were rasterised on the pixel grid, so each one lands on whole pixels. The pen
    // advances by fractional widths; a glyph goes to the pixel column whose centre its left edge
    // reaches (ceil(edge - 1/2)), the column a rasteriser fills first for a quad there.
    float pen = std::round(x);
    const float base = std::round(baseline_y);
    for (const std::uint32_t cp : decode_utf8(text)) {
        const Glyph& g = glyph(cp);
        if (g.width > 0 && g.height > 0) {
            batch.add_glyph({static_cast<int>(std::ceil(pen + g.x_offset - 0.5F)),
                             static_cast<int>(base + g.y_offset), g.u, g.v, g.width, g.height,
                             color});
        }
        pen += g.advance;
    }
    return pen;
}

float FontAtlas::text_width(std::string_view text) const {
    float width = 0.0F;
    for (const std::uint32_t cp : decode_utf8(text)) width += glyph(cp).advance;
    return width;
}

std::vector<std::string> wrap_words(const FontAtlas& font, const std::string& text, float width) {
    // Widths add up (glyph advances, no kerning), so each word is measured once and the line's
    // width kept as a sum: linear in the text, however long its lines.
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

}  // namespace collide::render
