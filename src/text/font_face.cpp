#include "collide/text/font_face.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <utility>

#include "collide/error.hpp"

namespace collide::text {
namespace {

/// The file a FontFace reads, and who chose it: the messages about it differ. A font the search
/// found (DejaVu) is the installation's fault: a runtime error, with the advice to reinstall it.
/// One the user named (`chosen_by` "--font" or "$COLLIDE_FONT") is bad input, named as such.
struct FontSource {
    const std::string& path;
    std::string_view chosen_by;
    std::string_view package = "fonts-dejavu-core";  // the one a runtime error advises
};

[[noreturn]] void unusable(const FontSource& font, const std::string& why) {
    if (!font.chosen_by.empty()) {
        throw_input_error(std::string(font.chosen_by) + ": '" + font.path +
                          "' is not a usable font file (" + why +
                          "); give a TrueType or OpenType font (.ttf, .otf, .ttc)");
    }
    throw_runtime_error("font: '" + font.path + "' is not a usable TrueType font (" + why +
                        "); reinstall " + std::string(font.package));
}

/// The whole file, read only once its size is known to be within max_font_file_bytes (a font is
/// read whole before any check: a huge file would cost its size in memory and seconds).
std::vector<unsigned char> read_font_file(const FontSource& font) {
    std::FILE* file = std::fopen(font.path.c_str(), "rb");
    if (file == nullptr) {
        const std::string reason = std::strerror(errno);
        if (!font.chosen_by.empty()) {
            throw_input_error(std::string(font.chosen_by) + ": cannot open '" + font.path +
                              "': " + reason);
        }
        throw_runtime_error(
            "font: cannot open '" + font.path + "': " + reason +
            " (install fonts-dejavu-core, or give a TrueType font with --font FILE or "
            "$COLLIDE_FONT)");
    }
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> owner(file, &std::fclose);
    struct stat status {};
    if (fstat(fileno(file), &status) != 0 || !S_ISREG(status.st_mode)) {
        unusable(font, "not a regular file");
    }
    const auto size = static_cast<std::uint64_t>(status.st_size);
    if (size > max_font_file_bytes) {
        unusable(font, std::to_string(size / (1024 * 1024)) + " MB, more than the " +
                           std::to_string(max_font_file_bytes / (1024 * 1024)) +
                           " MB a font file may have");
    }
    std::vector<unsigned char> data(static_cast<std::size_t>(size));
    const std::size_t read = std::fread(data.data(), 1, data.size(), file);
    if (std::ferror(file) != 0)
        unusable(font, std::string("cannot read it: ") + std::strerror(errno));
    data.resize(read);  // a file that shrank meanwhile is checked as it was read
    return data;
}

std::uint32_t big_endian(const std::vector<unsigned char>& data, std::size_t at, int bytes) {
    std::uint32_t value = 0;
    for (int i = 0; i < bytes; ++i) value = (value << 8) | data[at + static_cast<std::size_t>(i)];
    return value;
}

constexpr std::uint32_t tag(const char (&name)[5]) {
    std::uint32_t value = 0;
    for (int i = 0; i < 4; ++i) value = (value << 8) | static_cast<unsigned char>(name[i]);
    return value;
}

std::uint32_t table_checksum(const std::vector<unsigned char>& data, std::uint64_t start,
                             std::uint64_t length) {
    std::uint32_t sum = 0;
    for (std::uint64_t at = start; at < start + length; at += 4) {
        std::uint32_t word = 0;
        for (std::uint64_t b = at; b < at + 4; ++b) {
            word = (word << 8) | (b < start + length ? data[static_cast<std::size_t>(b)] : 0U);
        }
        sum += word;
    }
    return sum;
}

/// FreeType survives damaged fonts, but draws what the damage says: missing or wrong glyphs in
/// a lecture video, found by a student. So before it sees the file: the table directory must
/// lie within it, every table too, the tables a glyph needs must be there (TrueType outlines or
/// CFF ones), and each table (but 'head', which holds the whole file's adjustment) must match
/// its checksum, which catches damage inside a table as well.
void check_sfnt(const std::vector<unsigned char>& data, const FontSource& font) {
    constexpr std::size_t directory_header = 12;
    constexpr std::size_t record_size = 16;
    if (data.size() < directory_header + 4) unusable(font, "too short");
    std::size_t offset = 0;
    if (big_endian(data, 0, 4) == tag("ttcf")) offset = big_endian(data, 12, 4);  // its first font
    if (offset > data.size() || data.size() - offset < directory_header)
        unusable(font, "truncated");
    const std::size_t tables = big_endian(data, offset + 4, 2);
    if (data.size() - offset - directory_header < tables * record_size) unusable(font, "truncated");
    std::vector<std::uint32_t> present;
    for (std::size_t t = 0; t < tables; ++t) {
        const std::size_t record = offset + directory_header + t * record_size;
        const std::uint32_t name = big_endian(data, record, 4);
        const std::uint64_t start = big_endian(data, record + 8, 4);
        const std::uint64_t length = big_endian(data, record + 12, 4);
        if (start + length > data.size()) unusable(font, "truncated");
        present.push_back(name);
        if (name == tag("head")) continue;
        if (table_checksum(data, start, length) != big_endian(data, record + 4, 4))
            unusable(font, "damaged: a table's checksum does not match");
    }
    const auto has = [&present](std::uint32_t name) {
        return std::find(present.begin(), present.end(), name) != present.end();
    };
    const bool outlines =
        (has(tag("glyf")) && has(tag("loca"))) || has(tag("CFF ")) || has(tag("CFF2"));
    for (const std::uint32_t name :
         {tag("cmap"), tag("head"), tag("hhea"), tag("hmtx"), tag("maxp")}) {
        if (!has(name)) unusable(font, "tables missing");
    }
    if (!outlines) unusable(font, "tables missing");
}

/// A fallback font where a distribution installs it, and the package that does (Debian's name
/// where Debian has it: the messages of this build speak Debian).
struct FallbackFont {
    std::string_view path;
    std::string_view package;
};

/// Droid Sans Fallback first: it covers Chinese, Japanese and Korean in one face of 4 MB, where
/// Noto Sans CJK's collection is 20-90 MB, read whole by every atlas that needs it.
constexpr std::array<FallbackFont, 5> fallback_fonts = {{
    {"/usr/share/fonts/truetype/droid/DroidSansFallbackFull.ttf", "fonts-droid-fallback"},
    {"/usr/share/fonts/google-droid-sans-fonts/DroidSansFallbackFull.ttf", "fonts-droid-fallback"},
    {"/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc", "fonts-noto-cjk"},
    {"/usr/share/fonts/google-noto-cjk/NotoSansCJK-Regular.ttc", "fonts-noto-cjk"},
    {"/usr/share/fonts/noto-cjk/NotoSansCJK-Regular.ttc", "fonts-noto-cjk"},
}};

std::string encode_utf8(std::uint32_t cp) {
    std::string out;
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
    return out;
}

}  // namespace

FontFace::FontFace(const std::string& path, std::string_view chosen_by, std::string_view package)
    : path_(path), data_(read_font_file(FontSource{path, chosen_by, package})) {
    const FontSource source{path_, chosen_by, package};
    check_sfnt(data_, source);
    if (const FT_Error error = FT_Init_FreeType(&library_); error != 0) {
        library_ = nullptr;
        if (error == FT_Err_Out_Of_Memory) throw std::bad_alloc();
        throw_runtime_error("font: FreeType could not start (error " + std::to_string(error) + ")");
    }
    if (const FT_Error error = FT_New_Memory_Face(library_, data_.data(),
                                                  static_cast<FT_Long>(data_.size()), 0, &face_);
        error != 0) {
        face_ = nullptr;
        release();
        // Memory is main's to report, as every other allocation that fails (out of memory).
        if (error == FT_Err_Out_Of_Memory) throw std::bad_alloc();
        unusable(source, "FreeType cannot read it");
    }
    if (face_->charmap == nullptr || face_->charmap->encoding != FT_ENCODING_UNICODE ||
        !FT_IS_SCALABLE(face_)) {
        release();
        unusable(source, "no Unicode outlines");
    }
}

FontFace::~FontFace() {
    release();
}

FontFace::FontFace(FontFace&& other) noexcept
    : path_(std::move(other.path_)),
      data_(std::move(other.data_)),  // the buffer moves with its pointer: the face stays valid
      library_(std::exchange(other.library_, nullptr)),
      face_(std::exchange(other.face_, nullptr)) {}

FontFace& FontFace::operator=(FontFace&& other) noexcept {
    if (this != &other) {
        release();
        path_ = std::move(other.path_);
        data_ = std::move(other.data_);
        library_ = std::exchange(other.library_, nullptr);
        face_ = std::exchange(other.face_, nullptr);
    }
    return *this;
}

void FontFace::release() noexcept {
    if (face_ != nullptr) FT_Done_Face(face_);
    if (library_ != nullptr) FT_Done_FreeType(library_);
    face_ = nullptr;
    library_ = nullptr;
}

bool FontFace::has_character(std::uint32_t code_point) const {
    return FT_Get_Char_Index(face_, code_point) != 0;
}

std::string FontFace::name() const {
    std::string out = face_->family_name != nullptr ? face_->family_name : "";
    if (face_->style_name != nullptr && std::string_view(face_->style_name) != "Book" &&
        std::string_view(face_->style_name) != "Regular") {
        out += std::string(" ") + face_->style_name;
    }
    return out;
}

std::vector<std::string> installed_fallback_fonts() {
    std::vector<std::string> out;
    for (const FallbackFont& font : fallback_fonts) {
        struct stat status {};
        const std::string path(font.path);
        if (stat(path.c_str(), &status) == 0 && S_ISREG(status.st_mode)) out.push_back(path);
    }
    return out;
}

std::string_view fallback_font_package(std::string_view path) {
    for (const FallbackFont& font : fallback_fonts) {
        if (font.path == path) return font.package;
    }
    return "the package that installed it";
}

bool needs_no_glyph(std::uint32_t cp) {
    return cp < 0x20 || (cp >= 0x7F && cp <= 0x9F) || cp == 0xAD || cp == 0x34F ||
           (cp >= 0x200B && cp <= 0x200F) || (cp >= 0x2028 && cp <= 0x202E) ||
           (cp >= 0x2060 && cp <= 0x206F) || (cp >= 0xFE00 && cp <= 0xFE0F) || cp == 0xFEFF ||
           (cp >= 0xE0000 && cp <= 0xE0FFF);
}

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

std::vector<std::uint32_t> missing_characters(const FontFace& font, std::string_view text) {
    return missing_characters(std::vector<const FontFace*>{&font}, text);
}

std::vector<std::uint32_t> missing_characters(const std::vector<const FontFace*>& fonts,
                                              std::string_view text) {
    std::vector<std::uint32_t> missing;
    for (const std::uint32_t cp : decode_utf8(text)) {
        if (needs_no_glyph(cp)) continue;
        if (std::any_of(fonts.begin(), fonts.end(),
                        [cp](const FontFace* font) { return font->has_character(cp); })) {
            continue;
        }
        if (std::find(missing.begin(), missing.end(), cp) == missing.end()) missing.push_back(cp);
    }
    return missing;
}

std::string describe_character(std::uint32_t code_point) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "U+%04X", static_cast<unsigned>(code_point));
    if (needs_no_glyph(code_point) || code_point > 0x10FFFF ||
        (code_point >= 0xD800 && code_point <= 0xDFFF)) {
        return hex;
    }
    return "'" + encode_utf8(code_point) + "' (" + hex + ")";
}

}  // namespace collide::text
