#include "collide/video/subtitles.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

#include "collide/error.hpp"
#include "iso639.hpp"

namespace collide::video {
namespace {

std::string lowercase(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

/// "HH:MM:SS" then `separator` and milliseconds ('.' for WebVTT, ',' for SubRip).
std::string timestamp(double seconds, char separator) {
    const long long ms = std::llround(std::max(0.0, seconds) * 1000.0);
    char text[40];
    std::snprintf(text, sizeof text, "%02lld:%02lld:%02lld%c%03lld", ms / 3600000, ms / 60000 % 60,
                  ms / 1000 % 60, separator, ms % 1000);
    return text;
}

std::string replaced(std::string text, std::string_view from, std::string_view to) {
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size())) {
        text.replace(at, from.size(), to);
    }
    return text;
}

/// A character that is no text: a C0 control (tab and line ends aside, handled by the caller),
/// DEL, or (as the UTF-8 bytes C2 80..C2 9F) a C1 control such as U+0085 NEXT LINE.
bool is_control_byte(unsigned char c) {
    return (c < 0x20 && c != '\t') || c == 0x7f;
}

/// One line of a cue: control characters dropped (C1 ones too), tabs made spaces.
std::string clean_line(std::string_view line) {
    std::string out;
    out.reserve(line.size());
    for (std::size_t i = 0; i < line.size(); ++i) {
        const auto c = static_cast<unsigned char>(line[i]);
        if (c == 0xC2 && i + 1 < line.size() && static_cast<unsigned char>(line[i + 1]) >= 0x80 &&
            static_cast<unsigned char>(line[i + 1]) <= 0x9F) {
            ++i;  // U+0080..U+009F
            continue;
        }
        if (is_control_byte(c)) continue;
        out += c == '\t' ? ' ' : static_cast<char>(c);
    }
    return out;
}

}  // namespace

std::string plain_cue_text(std::string_view text) {
    std::string out;
    std::size_t start = 0;
    while (start <= text.size()) {
        // '\r' alone ends a line for some readers (FFmpeg's among them): a line end here too.
        const std::size_t end = std::min(text.find_first_of("\r\n", start), text.size());
        const std::string line = clean_line(text.substr(start, end - start));
        if (line.find_first_not_of(' ') != std::string::npos) {
            if (!out.empty()) out += '\n';
            out += line;
        }
        start = end + 1;
    }
    // Until none is left: "--->" is "-->" again once its first arrow is shortened.
    while (out.find("-->") != std::string::npos) out = replaced(std::move(out), "-->", "->");
    return out;
}

std::string subtitle_language(std::string_view tag, std::string_view field) {
    const std::string code = lowercase(tag);
    for (const detail::Iso639& entry : detail::iso639_codes) {
        if (code.size() == 2 && code == entry.two_letter) return entry.terminology;
        if (code.size() == 3 && (code == entry.terminology || code == entry.bibliographic))
            return entry.terminology;
    }
    throw_input_error(std::string(field) + ": '" + std::string(tag) +
                      "' is not an ISO 639 language code (two letters such as en, pl, cs, de, "
                      "el, ru, or three such as eng, pol; und: undetermined)");
}

SubtitleFormat subtitle_format_of(const std::filesystem::path& path, std::string_view field) {
    const std::string extension = lowercase(path.extension().string());
    if (extension == ".vtt") return SubtitleFormat::webvtt;
    if (extension == ".srt") return SubtitleFormat::srt;
    throw_input_error(std::string(field) + ": '" + path.string() +
                      "' must end in .vtt (WebVTT) or .srt (SubRip)");
}

std::string webvtt_text(const Cues& cues) {
    std::string out = "WEBVTT\n";
    for (const Cue& cue : cues) {
        std::string text = plain_cue_text(cue.text);
        if (text.empty()) continue;
        text = replaced(replaced(replaced(text, "&", "&amp;"), "<", "&lt;"), ">", "&gt;");
        out += '\n' + timestamp(cue.start, '.') + " --> " + timestamp(cue.end, '.') + '\n' + text +
               '\n';
    }
    return out;
}

std::string srt_text(const Cues& cues) {
    std::string out;
    int number = 0;
    for (const Cue& cue : cues) {
        const std::string text = plain_cue_text(cue.text);
        if (text.empty()) continue;
        if (number > 0) out += '\n';
        out += std::to_string(++number) + '\n' + timestamp(cue.start, ',') + " --> " +
               timestamp(cue.end, ',') + '\n' + text + '\n';
    }
    return out;
}

std::string webvtt_chapters_text(const Chapters& chapters) {
    Cues cues;
    cues.reserve(chapters.size());
    for (const Chapter& chapter : chapters)
        cues.push_back({chapter.start, chapter.end, chapter.title});
    return webvtt_text(cues);
}

std::string subtitle_file_text(const Cues& cues, SubtitleFormat format) {
    return format == SubtitleFormat::webvtt ? webvtt_text(cues) : srt_text(cues);
}

}  // namespace collide::video
