#pragma once
/// \file
/// Text for a terminal: what collide prints to people (errors, warnings, notices, the scene
/// listing) may quote a scene's or the command line's words, which are anyone's bytes. An escape
/// sequence among them (ESC, the 8-bit CSI U+009B, BEL, a carriage return) would act on the
/// terminal instead of being read: clear the screen, retitle the window, overwrite the line.

#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

namespace collide {

namespace detail {

/// The length of the valid UTF-8 sequence starting at text[at] (1 to 4), or 0 when the bytes
/// there are not one (a stray continuation byte, an overlong form, a surrogate, beyond U+10FFFF,
/// cut short).
[[nodiscard]] inline std::size_t utf8_sequence_length(std::string_view text, std::size_t at) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(at);
    if (lead < 0x80) return 1;
    std::size_t length = 0;
    unsigned char low = 0x80;  // the range of the second byte (overlongs and surrogates out)
    unsigned char high = 0xBF;
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        if (lead == 0xE0) low = 0xA0;
        if (lead == 0xED) high = 0x9F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        if (lead == 0xF0) low = 0x90;
        if (lead == 0xF4) high = 0x8F;
    } else {
        return 0;
    }
    if (at + length > text.size()) return 0;
    if (byte(at + 1) < low || byte(at + 1) > high) return 0;
    for (std::size_t i = 2; i < length; ++i) {
        if (byte(at + i) < 0x80 || byte(at + i) > 0xBF) return 0;
    }
    return length;
}

/// JSON's short escape of a control character ('n' for a line feed), or '\0' for none.
[[nodiscard]] inline char json_short_escape(unsigned char c) {
    switch (c) {
        case '\b':
            return 'b';
        case '\f':
            return 'f';
        case '\n':
            return 'n';
        case '\r':
            return 'r';
        case '\t':
            return 't';
        default:
            return '\0';
    }
}

}  // namespace detail

/// `text` safe to print: control characters (C0, DEL, and the C1 range U+0080..U+009F, which
/// terminals read as ESC sequences) written as JSON writes them (`\u001b`, `\r`), and bytes that
/// are no UTF-8 as `\xff`; everything else, any language's letters included, unchanged. Line breaks
/// and tabs stay when `keep_line_breaks` (a message of several lines), else they are escaped too
/// (`\n`, `\t`), so that a quoted word is one line. Backslashes are left as they are.
[[nodiscard]] inline std::string printable_text(std::string_view text,
                                                bool keep_line_breaks = true) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t length = detail::utf8_sequence_length(text, at);
        const auto c = static_cast<unsigned char>(text[at]);
        char escaped[8];
        if (length == 0) {
            std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
            out += escaped;
            ++at;
            continue;
        }
        const bool c1 = length == 2 && c == 0xC2 && static_cast<unsigned char>(text[at + 1]) < 0xA0;
        const bool control = (length == 1 && (c < 0x20 || c == 0x7F)) || c1;
        if (control && keep_line_breaks && (c == '\n' || c == '\t')) {
            out += static_cast<char>(c);
        } else if (control && detail::json_short_escape(c) != '\0') {
            out += '\\';
            out += detail::json_short_escape(c);
        } else if (control) {
            const unsigned code = c1 ? static_cast<unsigned char>(text[at + 1]) : c;
            std::snprintf(escaped, sizeof escaped, "\\u%04x", code);
            out += escaped;
        } else {
            out.append(text.substr(at, length));
        }
        at += length;
    }
    return out;
}

}  // namespace collide
